/* SPDX-License-Identifier: Apache-2.0 */
/*
 * Sub-pixel position of line points across the line: see subpixel.h.
 *
 * Only the points of reported pieces are refined, each from the gray values
 * of its grid around it across the line (E at the point and its two
 * neighbours, recomputed from the frame, or from the pass's grid rows where
 * they are cached: the pass keeps no energies, and no buffer keeps the stack
 * short), so the cost follows the number of points, not
 * the frame size. Integer only: E values, then one 32-bit division.
 */
#include "subpixel.h"

/* 255^2: the squared difference counted for a pair that leaves the grid (docs/algorithm.md). */
#define SL_SUB_DMAX2 65025u

/* Gray value of the grid pixel whose block starts at src: the rounded box mean
 * of 2^level x 2^level frame pixels that symline_i_grid_row() gives. */
static uint32_t grid_px(const uint8_t *src, size_t stride, uint32_t level)
{
    const uint32_t s = 1u << level;
    uint32_t sum = 0u, i, j;
    /* Levels 0 and 1 (most points) on their own only save time (SL_FOR_SPEED). */
    if (SL_FOR_SPEED && level == 0u) {
        return *src;
    }
    if (SL_FOR_SPEED && level == 1u) { /* the most common coarse scale, unrolled */
        return ((uint32_t)src[0] + src[1] + src[stride] + src[stride + 1u] + 2u) >> 2;
    }
    for (j = 0; j < s; j++, src += stride) {
        for (i = 0; i < s; i++) {
            sum += src[i];
        }
    }
    /* Half the divisor rounds (0 at level 0). */
    return (sum + ((s * s) >> 1)) >> (2u * level);
}

/* Where the energies of one point are taken: the block of grid pixel i across
 * the line, the step to the next grid pixel across, n grid pixels across. */
typedef struct symline_i_across {
    const uint8_t *at; /* block of index i */
    size_t step;       /* bytes from one grid pixel to the next across the line */
    size_t stride;     /* frame stride */
    uint32_t level, i, n, m;
    uint32_t lag; /* a marked run ends at most lag past its marked index */
} symline_i_across;

/* Gray value at index i + k across the line, or SL_SUB_OUT outside the grid. */
#define SL_SUB_OUT 0x100u
static uint32_t gray_at(const symline_i_across *a, int32_t k)
{
    /* A negative index wraps to beyond n. */
    return a->i + (uint32_t)k < a->n
               ? grid_px(a->at + (ptrdiff_t)k * (ptrdiff_t)a->step, a->stride, a->level)
               : SL_SUB_OUT;
}

/* The squared difference of a pair, SL_SUB_DMAX2 for one that leaves the grid. */
static uint32_t diff2(uint32_t l, uint32_t r)
{
    const int32_t d = (int32_t)l - (int32_t)r;
    return ((l | r) & SL_SUB_OUT) != 0u ? SL_SUB_DMAX2 : (uint32_t)(d * d);
}

/* E (docs/algorithm.md) at i+k-1, i+k and i+k+1, anywhere in the grid, in
 * one sweep out from i+k that reads each gray value once (2m+3 of them, no
 * buffer): l0, l1, l2 hold the values at i+k-(j-1), i+k-j, i+k-(j+1), r0, r1,
 * r2 those at i+k+(j-1), i+k+j, i+k+(j+1). The weights m+1-j come from
 * running sums: term j is added once for every t = j..m. */
static void energies3_checked(const symline_i_across *a, int32_t k, uint32_t e[3])
{
    uint32_t l0 = gray_at(a, k), l1 = gray_at(a, k - 1), r0 = l0, r1 = gray_at(a, k + 1);
    uint32_t s0 = 0u, s1 = 0u, s2 = 0u, e0 = 0u, e1 = 0u, e2 = 0u;
    int32_t j;
    for (j = 1; j <= (int32_t)a->m; j++) {
        const uint32_t l2 = gray_at(a, k - 1 - j), r2 = gray_at(a, k + 1 + j);
        s0 += diff2(l2, r0); /* centre i+k-1: i+k-1-j, i+k-1+j */
        s1 += diff2(l1, r1); /* centre i+k:   i+k-j,   i+k+j */
        s2 += diff2(l0, r2); /* centre i+k+1: i+k+1-j, i+k+1+j */
        e0 += s0;
        e1 += s1;
        e2 += s2;
        l0 = l1;
        l1 = l2;
        r0 = r1;
        r1 = r2;
    }
    e[0] = e0;
    e[1] = e1;
    e[2] = e2;
}

/* E at index i + k alone (the rare walk along a run of equal E): where the
 * build optimises for size, the middle one of the sweep's three; else term
 * by term, which keeps the frames under the stack budget at -O3. */
static uint32_t energy_at(const symline_i_across *a, int32_t k)
{
    uint32_t e[3];
    if (SL_FOR_SPEED) {
        int32_t j;
        e[1] = 0u;
        for (j = 1; j <= (int32_t)a->m; j++) {
            e[1] += (a->m + 1u - (uint32_t)j) * diff2(gray_at(a, k - j), gray_at(a, k + j));
        }
    } else {
        energies3_checked(a, k, e);
    }
    return e[1];
}

/* The same sweep away from the border, without the bounds checks, by
 * pointers. Inline with a constant level 0 (most points, one byte per gray
 * value) and with the pass's level. */
static inline void sweep(const symline_i_across *a, uint32_t level, uint32_t e[3])
{
    /* Pointers walk out from i: pl to i-(j+1), pr to i+(j+1). */
    const uint8_t *pl = a->at - a->step, *pr = a->at + a->step;
    uint32_t l0 = grid_px(a->at, a->stride, level), l1 = grid_px(pl, a->stride, level);
    uint32_t r0 = l0, r1 = grid_px(pr, a->stride, level), j;
    uint32_t s0 = 0u, s1 = 0u, s2 = 0u, e0 = 0u, e1 = 0u, e2 = 0u;
    for (j = a->m; j > 0u; j--) {
        uint32_t l2, r2;
        int32_t d0, d1, d2;
        pl -= a->step;
        pr += a->step;
        l2 = grid_px(pl, a->stride, level);
        r2 = grid_px(pr, a->stride, level);
        d0 = (int32_t)l2 - (int32_t)r0; /* centre i-1: i-1-j, i-1+j */
        d1 = (int32_t)l1 - (int32_t)r1; /* centre i:   i-j,   i+j */
        d2 = (int32_t)l0 - (int32_t)r2; /* centre i+1: i+1-j, i+1+j */
        s0 += (uint32_t)(d0 * d0);
        s1 += (uint32_t)(d1 * d1);
        s2 += (uint32_t)(d2 * d2);
        e0 += s0;
        e1 += s1;
        e2 += s2;
        l0 = l1;
        l1 = l2;
        r0 = r1;
        r1 = r2;
    }
    e[0] = e0;
    e[1] = e1;
    e[2] = e2;
}

/* E at i-1, i and i+1. The bounds-checked sweep serves every point where
 * the build optimises for size; else the unchecked inline sweeps away from
 * the border, and near it term by term. */
static void energies3(const symline_i_across *a, uint32_t e[3])
{
    if (!SL_FOR_SPEED) {
        energies3_checked(a, 0, e);
    } else if (a->i < a->m + 1u || a->i + a->m + 1u >= a->n) {
        e[0] = energy_at(a, -1);
        e[1] = energy_at(a, 0);
        e[2] = energy_at(a, 1);
    } else if (a->level == 0u) {
        sweep(a, 0u, e);
    } else {
        sweep(a, a->level, e);
    }
}

/* Offset (1/128 grid px) of the parabola's vertex through E at i-1, i and
 * i+1 (e: no two neighbours equal); 0 where E has no minimum at i. */
static inline int32_t vertex(const uint32_t e[3])
{
    int32_t num, den;
    if (e[0] < e[1] || e[2] < e[1]) {
        return 0; /* not a minimum of E (not an S point) */
    }
    /* Parabola vertex: (E(i-1) - E(i+1)) / (2 (E(i-1) - 2 E(i) + E(i+1))) px,
     * |num| < den; both halved until num * 64 fits 32 bits. den >= 2^23 or
     * unhalved, and then at least 2: neither neighbour equals E(i). */
    {
        uint32_t de = e[0] + e[2] - 2u * e[1];
        uint32_t dn = e[0] > e[2] ? e[0] - e[2] : e[2] - e[0];
        while (de >= (1u << 24)) {
            de >>= 1;
            dn >>= 1;
        }
        den = (int32_t)de;
        num = e[0] > e[2] ? (int32_t)dn : -(int32_t)dn;
    }
    return num * 64 / den;
}

/* Offset (1/128 grid px) of the ridge's middle from index i across the line. */
static int32_t offset_at(const symline_i_across *a)
{
    uint32_t e[3];
    if (a->i == 0u || a->i + 1u >= a->n) {
        return 0;
    }
    energies3(a, e);
    if (e[0] == e[1] || e[2] == e[1]) {
        /* A run of equal E: its exact middle (the S point is its lower middle). */
        const int32_t longest = 2 * (int32_t)a->lag + 1, last = (int32_t)a->n - 1 - (int32_t)a->i;
        int32_t lo = 0, hi = 0;
        while ((int32_t)a->i + lo > 1 && hi - lo + 1 < longest && energy_at(a, lo - 1) == e[1]) {
            lo--;
        }
        while (hi + 1 < last && hi - lo + 1 < longest && energy_at(a, hi + 1) == e[1]) {
            hi++;
        }
        /* i is the run's (a+b) div 2, so this is 0 or half a pixel. */
        return lo + hi > 0 ? 64 : 0;
    }
    return vertex(e);
}

/* The squared difference of two gray values. */
static inline uint32_t sq(uint32_t l, uint32_t r)
{
    const int32_t d = (int32_t)l - (int32_t)r;
    return (uint32_t)(d * d);
}

/* Marks a point for offset_at() (fx; no offset is this far). */
#define SL_SUB_LATER INT8_MIN

/* The offsets of points q[0, n) with m = 3 (the default radius) at level 0
 * or 1 (most points; at every level where the grid rows are cached,
 * offsets_cached()), to save time (SL_FOR_SPEED): away from the border, E
 * at i-1, i and i+1 from the nine gray values around i in straight-line
 * code; vert and level constants. A point with i below lo, near the far
 * border or on a run of equal E is marked SL_SUB_LATER. Returns how many
 * were. img: the frame, or a pass's grid itself at level 0. */
static inline uint32_t offsets_m3(const symline_image *img, uint32_t lo, uint32_t n_across,
                                  int vert, uint32_t level, symline_point *q, uint32_t n)
{
    const ptrdiff_t st = vert ? (ptrdiff_t)1 << level : (ptrdiff_t)img->stride << level;
    const size_t sd = img->stride;
    uint32_t k, later = 0u;
    for (k = 0; k < n; k++) {
        /* g + j * st: the block of index i + j. */
        const uint8_t *g = img->data + ((size_t)q[k].y << level) * sd + ((size_t)q[k].x << level);
        const uint32_t i = vert ? q[k].x : q[k].y;
        if (i >= lo && i + 4u < n_across) {
            const uint32_t m4 = grid_px(g - 4 * st, sd, level), m3 = grid_px(g - 3 * st, sd, level);
            const uint32_t m2 = grid_px(g - 2 * st, sd, level), m1 = grid_px(g - st, sd, level);
            const uint32_t c0 = grid_px(g, sd, level), p1 = grid_px(g + st, sd, level);
            const uint32_t p2 = grid_px(g + 2 * st, sd, level), p3 = grid_px(g + 3 * st, sd, level);
            const uint32_t p4 = grid_px(g + 4 * st, sd, level);
            uint32_t e[3];
            /* E(c) = 3 d(c-1, c+1)^2 + 2 d(c-2, c+2)^2 + d(c-3, c+3)^2. */
            e[0] = 3u * sq(m2, c0) + 2u * sq(m3, p1) + sq(m4, p2);
            e[1] = 3u * sq(m1, p1) + 2u * sq(m2, p2) + sq(m3, p3);
            e[2] = 3u * sq(c0, p2) + 2u * sq(m1, p3) + sq(m2, p4);
            if (e[0] != e[1] && e[2] != e[1]) {
                const int32_t off = vertex(e);
                q[k].fx = (int8_t)(vert ? off : 0);
                q[k].fy = (int8_t)(vert ? 0 : off);
                continue;
            }
        }
        q[k].fx = SL_SUB_LATER;
        q[k].fy = 0;
        later++;
    }
    return later;
}

#if SL_FOR_SPEED_DEEP
/* offsets_m3() at a coarse scale from its rows in the grid row cache
 * (linepoints.h), the pass's grid as a frame of its own: they hold the box
 * means the frame would give, so a point reads nine bytes instead of nine
 * blocks of the frame. The cache holds the rows from head[level] on (those
 * the pass decided its points in, and the rows across the line it read
 * there); a point whose rows across the line start above them is left for
 * offset_at(). */
static uint32_t offsets_cached(const symline_image *img, const symline_i_pass *p, symline_point *q,
                               uint32_t n)
{
    const uint32_t from = symline_i_cache_head(p->cache_end)[p->level];
    symline_image grid;
    grid.data = symline_i_cache_rows(p->cache_end, img->width, img->height, p->level,
                                     SL_CACHE_TOP(p->cache));
    grid.width = p->w;
    grid.height = p->h;
    grid.stride = p->w;
    if (p->axis == SYMLINE_AXIS_VERTICAL) {
        return offsets_m3(&grid, 4u, p->w, 1, 0u, q, n);
    }
    return offsets_m3(&grid, from + 4u, p->h, 0, 0u, q, n);
}
#endif

/* offsets_m3() with the pass's axis and level as constants: at level 0 or
 * 1 from the frame, at coarser ones (and at level 1) from the cached grid
 * rows where the pass has them. Out of line: its frame is gone when
 * offset_at() runs (the stack budget). */
SL_NOINLINE static uint32_t offsets_fast(const symline_image *img, const symline_i_pass *p,
                                         symline_point *q, uint32_t n)
{
#if SL_FOR_SPEED_DEEP
    if (p->level > 0u && p->cache != SL_CACHE_OFF) {
        return offsets_cached(img, p, q, n);
    }
#endif
    if (p->axis == SYMLINE_AXIS_VERTICAL) {
        return p->level == 0u ? offsets_m3(img, 4u, p->w, 1, 0u, q, n)
                              : offsets_m3(img, 4u, p->w, 1, 1u, q, n);
    }
    return p->level == 0u ? offsets_m3(img, 4u, p->h, 0, 0u, q, n)
                          : offsets_m3(img, 4u, p->h, 0, 1u, q, n);
}

/* Whether offsets_fast() serves the pass: m = 3 at level 0 or 1, or at any
 * level from the grid row cache (SL_FOR_SPEED_DEEP). */
static bool offsets_fast_serves(const symline_i_pass *p)
{
#if SL_FOR_SPEED_DEEP
    if (p->m == 3u && p->cache != SL_CACHE_OFF) {
        return true;
    }
#endif
    return SL_FOR_SPEED && p->level <= 1u && p->m == 3u;
}

void symline_i_subpixel(const symline_image *img, const symline_i_pass *p, symline_point *q,
                        uint32_t n)
{
    const int vert = p->axis == SYMLINE_AXIS_VERTICAL;
    symline_i_across a;
    uint32_t k = 0u;
    if (offsets_fast_serves(p)) {
        /* Only the points marked SL_SUB_LATER are left: from the first of
         * them on, every point as below (the same offsets again; a second
         * test per point would make the frame larger). */
        if (offsets_fast(img, p, q, n) == 0u) {
            return;
        }
        while (q[k].fx != SL_SUB_LATER) {
            k++;
        }
    }
    a.stride = img->stride;
    a.step = vert ? ((size_t)1u << p->level) : (size_t)img->stride << p->level;
    a.level = p->level;
    a.n = vert ? p->w : p->h;
    a.m = p->m;
    a.lag = p->lag;
    for (; k < n; k++) {
        int32_t off;
        a.i = vert ? q[k].x : q[k].y;
        a.at =
            img->data + ((size_t)q[k].y << p->level) * img->stride + ((size_t)q[k].x << p->level);
        off = offset_at(&a);
        q[k].fx = (int8_t)(vert ? off : 0);
        q[k].fy = (int8_t)(vert ? 0 : off);
    }
}

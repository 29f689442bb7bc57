/* SPDX-License-Identifier: Apache-2.0 */
/*
 * Extrema of symmetry on the exact energies, with the plateau rule.
 *
 * Both directions compare each energy with its two neighbours over whole
 * rows in 32-bit lanes (along a row: the row shifted by one; down the
 * columns: three rows of energies), which decides every entry that is not
 * part of a plateau, and marks where runs of equal energies begin and end.
 * Plateaus are rare and take a slow path at those marks only; down the
 * columns a small per-column state (where the run began, how it was entered)
 * follows them, so a frame is processed row by row holding three rows of
 * energies.
 */
#include "extrema.h"

#include "symmetry.h"

/* The entries of the plateau mask where a neighbour is equal: bit x - x0
 * (x0 <= x < x1 <= x0 + 32) where eq_up[x] != eq_dn[x]. */
#define SL_PLATEAU_BITS(bits, x0, x1, eq_up, eq_dn)                                                \
    do {                                                                                           \
        uint32_t x_;                                                                               \
        for (x_ = (x0); x_ < (x1); x_++) {                                                         \
            (bits) |= (uint32_t)((eq_up) != (eq_dn)) << (x_ - (x0));                               \
        }                                                                                          \
    } while (0)

/* The references in whole-row lane loops where the compiler has vector
 * lanes (SSE2, NEON) and the build optimises for speed; else one entry at a
 * time (kinds_small()), which is shorter, needs less stack and is faster on
 * scalar cores. */
#if defined(__SSE2__) || defined(__ARM_NEON) || defined(__ARM_NEON__)
#define SL_KINDS_LANES SL_FOR_SPEED
#else
#define SL_KINDS_LANES 0
#endif

/* The sign -1, 0, +1 of a - b. */
static inline int32_t sign_of(uint32_t a, uint32_t b)
{
    return (int32_t)(a > b) - (int32_t)(a < b);
}

/* The kind of an entry by v = r - l + 2 (kinds_small()). */
static const uint8_t kind_of[5] = {SYMLINE_MAP_A, SYMLINE_MAP_NONE, SYMLINE_MAP_NONE,
                                   SYMLINE_MAP_NONE, SYMLINE_MAP_S};

/*
 * The references one entry at a time, branch-free: the n <= 32 entries
 * of mid with the signs l of mid - up and r of dn - mid. Down the
 * columns (sg not NULL) l comes from sg, which takes r for the next row;
 * along a row (sg NULL, dn = mid + 1) l is the previous entry's r. With
 * v = r - l: an S point where v = 2 (l = -1, r = +1), an A point where
 * v = -2; exactly one of l, r is zero where v is odd. Returns the plateau
 * bits.
 */
static uint32_t kinds_small(const uint32_t *mid, const uint32_t *dn, int8_t *sg, uint32_t n,
                            uint8_t *map)
{
    uint32_t x, bits = 0u;
    int32_t l = (sg == NULL) ? sign_of(mid[0], *(mid - 1)) : 0;
    for (x = 0; x < n; x++) {
        const int32_t r = sign_of(dn[x], mid[x]);
        int32_t v;
        if (sg != NULL) {
            l = (int32_t)sg[x];
            sg[x] = (int8_t)r;
        }
        v = r - l;
        map[x] = kind_of[v + 2];
        bits |= ((uint32_t)v & 1u) << x;
        l = r;
    }
    return bits;
}

uint32_t symline_i_extrema_along_c(const uint32_t *E, uint32_t n, uint8_t *restrict map,
                                   uint32_t *restrict ev)
{
    const uint32_t *const L = E - 1, *const R = E + 1; /* the neighbours */
    uint32_t x0, x, any = 0u;
    if (!SL_KINDS_LANES && SL_KINDS_MAX == 32u) { /* one word */
        return *ev = kinds_small(E, R, NULL, n, map);
    }
    for (x0 = 0; x0 < n; x0 += 32u) {
        const uint32_t x1 = (n - x0 > 32u) ? x0 + 32u : n;
        uint32_t flat = 0u, bits = 0u;
        if (!SL_KINDS_LANES) {
            ev[x0 / 32u] = bits = kinds_small(E + x0, R + x0, NULL, x1 - x0, map + x0);
            any |= bits;
            continue;
        }
        /* E < 2^31 for every radius (symline_emax(255) < 2^31), so the sign
         * of a difference is its top bit: an S point when both E[x-1] - E[x]
         * and E[x+1] - E[x] are positive (E[x] - E[x-1] and E[x] - E[x+1]
         * negative), an A point when both are negative. Subtractions and
         * shifts only: the loop vectorises without unsigned compares. */
        for (x = x0; x < x1; x++) {
            const uint32_t a = L[x], b = E[x], c = R[x];
            const uint32_t s = ((b - a) & (b - c)) >> 31;
            const uint32_t l = ((a - b) & (c - b)) >> 31;
            map[x] = (uint8_t)((0u - s) | (l << 7));
            flat |= (uint32_t)(a == b) | (uint32_t)(b == c);
        }
        /* The plateau mask only where some energy equals a neighbour. */
        if (flat != 0u) {
            SL_PLATEAU_BITS(bits, x0, x1, L[x_] == E[x_], E[x_] == R[x_]);
        }
        ev[x0 / 32u] = bits;
        any |= bits;
    }
    return any;
}

uint32_t symline_i_extrema_across_c(const uint32_t *restrict mid, const uint32_t *restrict dn,
                                    int8_t *restrict sg, uint32_t n, uint8_t *restrict map,
                                    uint32_t *restrict ev)
{
    uint32_t x0, x, any = 0u;
    if (!SL_KINDS_LANES && SL_KINDS_MAX == 32u) { /* one word */
        return *ev = kinds_small(mid, dn, sg, n, map);
    }
    for (x0 = 0; x0 < n; x0 += 32u) {
        const uint32_t x1 = (n - x0 > 32u) ? x0 + 32u : n;
        uint32_t flat = 0u, bits = 0u;
        if (!SL_KINDS_LANES) {
            ev[x0 / 32u] = bits = kinds_small(mid + x0, dn + x0, sg + x0, x1 - x0, map + x0);
            any |= bits;
            continue;
        }
        for (x = x0; x < x1; x++) {
            const int8_t u = sg[x]; /* sign of mid - up */
            const uint32_t b = mid[x], c = dn[x];
            map[x] = (uint8_t)((u < 0 && c > b)   ? SYMLINE_MAP_S
                               : (u > 0 && c < b) ? SYMLINE_MAP_A
                                                  : SYMLINE_MAP_NONE);
            flat |= (uint32_t)(u == 0) | (uint32_t)(b == c);
        }
        if (flat != 0u) {
            SL_PLATEAU_BITS(bits, x0, x1, sg[x_] == 0, mid[x_] == dn[x_]);
        }
        /* The next row's signs, once this row's are read. */
        for (x = x0; x < x1; x++) {
            sg[x] = (int8_t)sign_of(dn[x], mid[x]);
        }
        ev[x0 / 32u] = bits;
        any |= bits;
    }
    return any;
}

/* The plateau mask words of n <= SL_KINDS_MAX entries (one where the blocks
 * are 32 entries: the loops over words fold away). */
#define SL_WORDS(n) (SL_KINDS_WORDS == 1u ? 1u : ((n) + 31u) / 32u)

/* Index of the lowest set bit of v != 0: one instruction where the target
 * has it, a multiply and a table lookup elsewhere (no library call). */
static inline uint32_t lowest_bit(uint32_t v)
{
#if defined(__GNUC__) && (defined(__x86_64__) || defined(__i386__) || defined(__aarch64__) ||      \
                          (defined(__ARM_FEATURE_CLZ) && defined(__ARM_ARCH) && __ARM_ARCH >= 7))
    return (uint32_t)__builtin_ctz(v);
#else
    static const uint8_t debruijn[32] = {0,  1,  28, 2,  29, 14, 24, 3,  30, 22, 20,
                                         15, 25, 17, 4,  8,  31, 27, 13, 23, 21, 19,
                                         16, 7,  26, 12, 18, 6,  11, 5,  10, 9};
    return debruijn[((v & (0u - v)) * 0x077CB531u) >> 27];
#endif
}

/*
 * The run rule over a row. Every entry with unequal neighbours is decided in
 * blocks by symline_i_extrema_along(), which also marks the entries where a
 * run of two or more equal energies begins (differs from its left neighbour)
 * or ends (differs from its right one). A run is decided at its end i: it
 * began at a, the last begin mark (runs touching entry 0 have none: a stays
 * 0), and is marked at its middle, which no later block overwrites, unless
 * it touches either end or is longer than the plateau limit allows.
 */
/* Entry i (0 < i < n-1 of row E) where a run of equal energies begins (a
 * becomes i) or ends: then the run [a, i] is marked at its middle, unless
 * it touches entry 0 (a = 0) or is longer than the plateau limit allows. */
static inline void run_mark(const uint32_t *E, uint32_t i, uint32_t lag, uint8_t *map, uint32_t *a)
{
    const uint32_t v = E[i];
    if (v != E[i - 1u]) {
        *a = i; /* a run begins */
    } else if (*a >= 1u && i - (*a + i) / 2u <= lag) {
        /* Neither neighbour equals v: larger on both sides S, smaller A. */
        const bool left_up = E[*a - 1u] > v, right_up = E[i + 1u] > v;
        map[(*a + i) / 2u] = left_up != right_up ? (uint8_t)SYMLINE_MAP_NONE
                             : left_up           ? (uint8_t)SYMLINE_MAP_S
                                                 : (uint8_t)SYMLINE_MAP_A;
    }
}

void symline_i_extrema_runs(const uint32_t *E, uint32_t n, uint32_t lag, uint8_t *map)
{
    uint32_t x0, x1, a = 0u;
    map[0] = SYMLINE_MAP_NONE;
    map[n - 1u] = SYMLINE_MAP_NONE;
    uint32_t k, ev[SL_KINDS_WORDS];
    for (x0 = 1u; x0 + 1u < n; x0 = x1) {
        x1 = x0 + ((n - 1u - x0 > SL_KINDS_MAX) ? SL_KINDS_MAX : n - 1u - x0);
        if (symline_i_extrema_along(E + x0, x1 - x0, map + x0, ev) == 0u) {
            continue;
        }
        for (k = 0; k < SL_WORDS(x1 - x0); k++) {
            uint32_t bits;
            for (bits = ev[k]; bits != 0u; bits &= bits - 1u) {
                run_mark(E, x0 + 32u * k + lowest_bit(bits), lag, map, &a); /* i + 1 < n */
            }
        }
    }
}

/* Column x, where a run of equal energies begins or ends at row t-1 >= 1. A
 * run begins when mid == dn != up; left says whether the row above it is
 * larger (+1) or smaller (-1). It ends when up == mid != dn, and is an
 * extremum at its middle row when the row below is on the same side. */
static void plateau_down(const symline_i_coldown *cd, const uint32_t *up, const uint32_t *mid,
                         const uint32_t *dn, uint32_t t, uint32_t x)
{
    if (mid[x] == dn[x]) {
        cd->run_start[x] = (uint16_t)(t - 1u);
        cd->sg[cd->width + x] = (int8_t)((up[x] > mid[x]) ? 1 : -1);
    } else {
        const int8_t right = (int8_t)((dn[x] > mid[x]) ? 1 : -1);
        const uint32_t y = ((uint32_t)cd->run_start[x] + t - 1u) / 2u;
        if (cd->sg[cd->width + x] == right && t - 1u - y <= cd->lag) {
            cd->map[(size_t)(y % cd->ring) * cd->stride + x] =
                (uint8_t)((right > 0) ? SYMLINE_MAP_S : SYMLINE_MAP_A);
        }
    }
}

void symline_i_extrema_down(const symline_i_coldown *cd, const uint32_t *E, uint32_t t)
{
    /* Row t-2 is row t-1 itself at t = 1: row 0 has no row above, so it is
     * never marked, and every run starts there without a side. */
    const uint32_t w = cd->width;
    const uint32_t *up = cd->E3 + (size_t)((t + 1u) % 3u) * w; /* row t-2's slot */
    const uint32_t *mid = up == cd->E3 + 2u * (size_t)w ? cd->E3 : up + w;
    up = (t >= 2u) ? up : mid;
    uint8_t *mr = cd->map + (size_t)((t - 1u) % cd->ring) * cd->stride;
    uint32_t i, nb;
    if (t == 1u) {
        /* No sign to the row above, and no side for the runs that start at
         * row 0 (so they are never marked: their run_start is not needed). */
        for (i = 0; i < 2u * w; i++) {
            cd->sg[i] = 0;
        }
    }
    uint32_t k, ev[SL_KINDS_WORDS];
    for (i = 0; i < w; i += nb) {
        nb = (w - i > SL_KINDS_MAX) ? SL_KINDS_MAX : w - i;
        if (symline_i_extrema_across(mid + i, E + i, cd->sg + i, nb, mr + i, ev) == 0u) {
            continue;
        }
        for (k = 0; k < SL_WORDS(nb); k++) {
            uint32_t bits;
            for (bits = ev[k]; bits != 0u; bits &= bits - 1u) {
                plateau_down(cd, up, mid, E, t, i + 32u * k + lowest_bit(bits));
            }
        }
    }
}

symline_status symline_extrema_row(const uint32_t *E, uint32_t n, uint8_t *map)
{
    if (E == NULL || map == NULL) {
        return SYMLINE_ERR_NULL;
    }
    if (n == 0u || n > SYMLINE_MAX_DIM) {
        return SYMLINE_ERR_SIZE;
    }
    symline_i_extrema_runs(E, n, SL_RUN_ANY_LENGTH, map);
    return SYMLINE_OK;
}

size_t symline_extrema_workspace_size(uint32_t width, uint32_t height, symline_axis axis,
                                      uint32_t m)
{
    size_t n;
    if (!symline_i_query_ok(width, height, axis, m)) {
        return 0u;
    }
    n = symline_i_align_up((size_t)width * sizeof(uint32_t)) + SL_ALIGN;
    if (axis == SYMLINE_AXIS_HORIZONTAL) {
        /* three rows of energies and where the plateaus began (symline_i_coldown) */
        n += symline_i_align_up((size_t)3u * width * sizeof(uint32_t)) +
             symline_i_align_up((size_t)width * sizeof(uint16_t)) + (size_t)2u * SL_ALIGN;
    }
    return n;
}

symline_status symline_extrema(const symline_image *img, symline_axis axis, uint32_t m,
                               uint8_t *map, uint32_t map_stride, size_t map_len, void *ws,
                               size_t ws_size)
{
    uint8_t *cur, *end;
    uint32_t *E, y, x;
    symline_i_coldown cd;
    symline_status st =
        symline_i_frame_begin(img, axis, m, map, map_stride, map_len, ws, ws_size, &cur, &end, &E);
    if (st != SYMLINE_OK) {
        return st;
    }
    cd.width = img->width;
    cd.lag = SL_RUN_ANY_LENGTH;
    cd.map = map;
    cd.stride = map_stride;
    cd.ring = img->height;
    if (axis != SYMLINE_AXIS_VERTICAL) {
        /* The row of energies along rows (4 B per column) is not needed
         * here: it holds the signs and plateau sides (2 B per column). */
        cd.sg = (int8_t *)(void *)E;
        cd.E3 = (uint32_t *)symline_i_carve(&cur, end, (size_t)3u * img->width * sizeof(uint32_t));
        cd.run_start =
            (uint16_t *)symline_i_carve(&cur, end, (size_t)img->width * sizeof(uint16_t));
        if (cd.E3 == NULL || cd.run_start == NULL) {
            return SYMLINE_ERR_BUFFER;
        }
    }
    for (y = 0; y < img->height; y++) {
        if (axis == SYMLINE_AXIS_VERTICAL) { /* along the rows */
            (void)symline_energy_row(img->data + (size_t)y * img->stride, img->width, m, E);
            (void)symline_extrema_row(E, img->width, map + (size_t)y * map_stride);
            continue;
        }
        /* down the columns: three rows of energies */
        E = cd.E3 + (size_t)(y % 3u) * img->width;
        (void)symline_energy_across_image(img, y, m, E);
        if (y >= 1u) {
            symline_i_extrema_down(&cd, E, y);
        }
    }
    if (axis == SYMLINE_AXIS_VERTICAL) {
        return SYMLINE_OK;
    }
    /* The last row touches the bottom: never marked. */
    map += (size_t)(img->height - 1u) * map_stride;
    for (x = 0; x < img->width; x++) {
        map[x] = SYMLINE_MAP_NONE;
    }
    return SYMLINE_OK;
}

/* SPDX-License-Identifier: Apache-2.0 */
/*
 * Line points of one pass, streamed over a ring of rows.
 *
 * Vertical axis (symmetry along rows): every grid row is complete on its own:
 * energies, extrema and the filter run row by row.
 *
 * Horizontal axis (symmetry along columns): energies of grid row t need rows
 * t-m .. t+m. Three rows of energies decide the extrema of the middle one
 * with row-wise comparisons; a run of equal energies [a, b] down a column (a
 * plateau, rare) is followed on a slow path and reported when row b+1
 * arrives, at row (a+b) div 2. Extrema of plateaus longer than
 * 2*lag+1 rows are not line points (no thin line has them), so every
 * extremum of row y is known once row y+lag+1 has been pushed, and the
 * decision for row y (which looks a_distance rows of extrema and k rows of gray
 * values up and down) is taken delta = a_distance+lag+1 rows later. The ring holds
 * just those rows: working memory grows with width * radius, not with height.
 *
 * Output: points appended in raster order, so the list is its own spatial
 * index together with row_start.
 */
#include "linepoints.h"

#include "extrema.h"
#include "stagemark.h"
#include "symmetry.h"

void symline_i_grid_row(const symline_image *img, const symline_i_pass *p, uint32_t y,
                        uint16_t *acc, uint8_t *out)
{
    const uint32_t s = 1u << p->level;
    const uint32_t shift = 2u * p->level;
    /* The width in a local: out (bytes) might alias *p, and a bound read
     * through p after every store keeps the loops from vectorising. */
    const uint32_t w = p->w;
    const uint32_t span = w * s;
    uint32_t x, d;
    const uint8_t *src = img->data + (size_t)(y * s) * img->stride;
    if (p->level == 0u) {
        for (x = 0; x < w; x++) {
            out[x] = src[x];
        }
        return;
    }
    for (x = 0; x < span; x++) {
        acc[x] = src[x];
    }
    for (d = 1u; d < s; d++) {
        const uint8_t *r = src + (size_t)d * img->stride;
        for (x = 0; x < span; x++) {
            acc[x] = (uint16_t)(acc[x] + r[x]);
        }
    }
    if (s == 2u) { /* the common first step, as a plain lane loop */
        for (x = 0; x < w; x++) {
            const uint16_t *pair = acc + (size_t)2u * x;
            out[x] = (uint8_t)(((uint32_t)pair[0] + pair[1] + 2u) >> 2);
        }
        return;
    }
    for (x = 0; x < w; x++) {
        uint32_t sum = 0u;
        for (d = 0; d < s; d++) {
            sum += acc[x * s + d];
        }
        out[x] = (uint8_t)((sum + (1u << (shift - 1u))) >> shift);
    }
}

/* Rows of the horizontal-axis rings. */
static uint32_t h_delta(const symline_i_pass *p)
{
    return p->filter.a_distance + p->lag + 1u;
}
static uint32_t h_map_rows(const symline_i_pass *p)
{
    return h_delta(p) + p->filter.a_distance;
}
static uint32_t h_gray_rows(const symline_i_pass *p)
{
    return h_delta(p) + p->k + p->m + 1u;
}

/* State of the horizontal-axis rings (kept in the workspace). */
typedef struct hring {
    const symline_image *img;
    const symline_i_pass *p;
    uint8_t *gray; /* gray_rows rows of w (levels > 0) */
    uint32_t gray_rows;
    symline_i_coldown cd; /* extrema down the columns into the map ring (cd.ring rows of w) */
} hring;

/* SYMLINE_DETECT_WORKSPACE_SIZE() (detect.h) counts 6 bytes per extremum and 8 per
 * row pointer, and the ring state within its fixed part (see pass.c). */
typedef char
    symline_i_ring_state_fits_ws_budget[(sizeof(hring) <= 80u && sizeof(symline_extremum) <= 6u &&
                                         sizeof(const uint8_t *) <= 8u)
                                            ? 1
                                            : -1];

size_t symline_i_collect_ws_size(const symline_i_pass *p, uint32_t img_width)
{
    size_t n = (size_t)6u * SL_ALIGN;
    const size_t w = p->w;
    n += symline_i_align_up(w * sizeof(uint32_t)); /* energies */
    if (p->level > 0u) {
        n += symline_i_align_up((size_t)img_width * sizeof(uint16_t)); /* box accumulator */
    }
    if (p->axis == SYMLINE_AXIS_VERTICAL) {
        n += symline_i_align_up(w); /* extrema of the row */
        if (p->level > 0u) {
            n += symline_i_align_up(w); /* the grid row */
        }
        return n;
    }
    n += symline_i_align_up(sizeof(hring));
    n += symline_i_align_up(2u * w * sizeof(uint32_t)); /* two more rows of energies */
    n += symline_i_align_up(w * sizeof(uint16_t)) + symline_i_align_up(w); /* plateau state */
    /* 2 B per column unused since the column extrema need no event list; kept
     * until SYMLINE_DETECT_WORKSPACE_SIZE (detect.h) and its sizing test drop
     * them together. */
    n += symline_i_align_up(2u * w) + (size_t)2u * SL_ALIGN;
    n += symline_i_align_up(w * (size_t)h_map_rows(p));
    if (p->level > 0u) {
        n += symline_i_align_up(w * (size_t)h_gray_rows(p));
    }
    n += symline_i_align_up((2u * (size_t)p->m + 1u) * sizeof(const uint8_t *));
    return n;
}

static void push_point(symline_point *pts, uint32_t cap, uint32_t *n, uint32_t x, uint32_t y,
                       uint32_t *dropped)
{
    if (*n >= cap) {
        (*dropped)++; /* counted, so the result can say how much storage was needed */
        return;
    }
    pts[*n].x = (uint16_t)x;
    pts[*n].y = (uint16_t)y;
    (*n)++;
}

/* The byte-lane pre-filter below pays where the compiler has vector lanes for
 * it (16 bytes per instruction); on scalar cores (Cortex-M) it would cost about
 * what it saves, in code size too, so it is left out there. */
#if defined(__SSE2__) || defined(__ARM_NEON) || defined(__ARM_NEON__)
#define SL_ROW_PREFILTER 1
#endif

#ifdef SL_ROW_PREFILTER
/*
 * Drops from map[0 .. n-1] the S points that the line filter's first tests
 * reject (symline_i_linefilter_gray() repeats them on what is left): gray c
 * below the illumination minimum and, for the contrast filter, a ridge not
 * above its sides lo, hi by ridge_min or sides brighter than side_max. Byte
 * lanes, whole rows; A points stay. Limits above 255 are clamped, which only
 * keeps more points for the exact test.
 */
SL_NOINLINE static void drop_dim_s(const symline_i_linefilter *f, const uint8_t *c,
                                   const uint8_t *lo, const uint8_t *hi, uint32_t n, uint8_t *map)
{
    const uint8_t mg = (uint8_t)(f->min_gray < 255u ? f->min_gray : 255u);
    uint8_t sm = 255u, rm = 0u;
    uint32_t x;
    if (f->kind != SYMLINE_FILTER_PAPER) {
        sm = (uint8_t)(f->side_max < 255u ? f->side_max : 255u);
        rm = (uint8_t)(f->ridge_min < 1u ? 1u : f->ridge_min < 255u ? f->ridge_min : 255u);
    } else {
        lo = c; /* the paper's filter: gray only (side c, ridge 0 >= rm = 0) */
        hi = c;
    }
    for (x = 0; x < n; x++) {
        const uint8_t side = lo[x] > hi[x] ? lo[x] : hi[x];
        const uint8_t d = (uint8_t)(c[x] > side ? (uint32_t)c[x] - side : 0u);
        const unsigned keep = (unsigned)(c[x] >= mg) & (unsigned)(side <= sm) & (unsigned)(d >= rm);
        map[x] = (uint8_t)((map[x] == SYMLINE_MAP_S && keep == 0u) ? SYMLINE_MAP_NONE : map[x]);
    }
}
#endif

/* ---- vertical axis: along rows ---- */

SL_NOINLINE static symline_status collect_vertical(const symline_image *img,
                                                   const symline_i_pass *p, uint8_t *cur,
                                                   uint8_t *end, symline_point *pts, uint32_t cap,
                                                   uint32_t *n, uint32_t *row_start,
                                                   uint32_t *dropped)
{
    uint32_t *E = (uint32_t *)symline_i_carve(&cur, end, (size_t)p->w * sizeof(uint32_t));
    uint8_t *map = (uint8_t *)symline_i_carve(&cur, end, p->w);
    uint16_t *acc = NULL;
    uint8_t *grow = NULL;
    uint32_t y, x;
    /* The level read once: the scratch rows exist exactly when it is above 0
     * (GCC's -fanalyzer cannot tell that p->level stays put across the
     * stores below, and reported a NULL row otherwise). */
    const uint32_t w = p->w, k = p->k, level = p->level;
    if (level > 0u) {
        acc = (uint16_t *)symline_i_carve(&cur, end, (size_t)img->width * sizeof(uint16_t));
        grow = (uint8_t *)symline_i_carve(&cur, end, p->w);
        if (acc == NULL || grow == NULL) {
            return SYMLINE_ERR_BUFFER;
        }
    }
    if (E == NULL || map == NULL) {
        return SYMLINE_ERR_BUFFER;
    }
    for (y = 0; y < p->h; y++) {
        const uint8_t *row;
        row_start[y] = *n;
        if (level == 0u) {
            row = img->data + (size_t)y * img->stride;
        } else {
            SL_STAGE(GRID);
            symline_i_grid_row(img, p, y, acc, grow);
            row = grow;
        }
        SL_STAGE(OPERATOR);
        (void)symline_energy_row(row, w, p->m, E);
        SL_STAGE(EXTREMA);
        symline_i_extrema_runs(E, w, p->lag, map);
        SL_STAGE(FILTER);
#ifdef SL_ROW_PREFILTER
        if (w > 2u * k) { /* the interior, where both sides lie in the row */
            drop_dim_s(&p->filter, row + k, row, row + (size_t)2u * k, w - 2u * k, map + k);
        }
#endif
        for (x = 0; x < w; x = SL_NEXT_S(map, x, w)) {
            if (map[x] != SYMLINE_MAP_S) {
                continue;
            }
            if (!symline_i_linefilter_gray(&p->filter, row[x], row[x >= k ? x - k : 0u],
                                           row[x + k < w ? x + k : w - 1u])) {
                continue;
            }
            if (p->filter.a_distance != 0u &&
                !symline_i_linefilter_a_near(&p->filter, map, w, 1u, w, x)) {
                continue;
            }
            push_point(pts, cap, n, x, y, dropped);
        }
    }
    row_start[p->h] = *n;
    return SYMLINE_OK;
}

/* ---- horizontal axis: down the columns, over rings ---- */

static const uint8_t *h_row(const hring *r, uint32_t y)
{
    if (r->p->level == 0u) {
        return r->img->data + (size_t)y * r->img->stride;
    }
    return r->gray + (size_t)(y % r->gray_rows) * r->p->w;
}

static uint8_t *h_map(const hring *r, uint32_t y)
{
    return r->cd.map + (size_t)(y % r->cd.ring) * r->p->w;
}

static void h_decide(const hring *r, uint32_t y, symline_point *pts, uint32_t cap, uint32_t *n,
                     uint32_t *row_start, uint32_t *dropped)
{
    const symline_i_pass *p = r->p;
    uint8_t *map = h_map(r, y);
    const uint8_t *c = h_row(r, y);
    const uint8_t *lo = h_row(r, y >= p->k ? y - p->k : 0u);
    const uint8_t *hi = h_row(r, y + p->k < p->h ? y + p->k : p->h - 1u);
    uint32_t x;
    row_start[y] = *n;
#ifdef SL_ROW_PREFILTER
    drop_dim_s(&p->filter, c, lo, hi, p->w, map);
#endif
    for (x = 0; x < p->w; x = SL_NEXT_S(map, x, p->w)) {
        if (map[x] != SYMLINE_MAP_S) {
            continue;
        }
        if (!symline_i_linefilter_gray(&p->filter, c[x], lo[x], hi[x])) {
            continue;
        }
        if (p->filter.a_distance != 0u &&
            !symline_i_linefilter_a_near(&p->filter, r->cd.map + x, r->cd.ring, p->w, p->h, y)) {
            continue;
        }
        push_point(pts, cap, n, x, y, dropped);
    }
}

SL_NOINLINE static symline_status collect_horizontal(const symline_image *img,
                                                     const symline_i_pass *p, uint8_t *cur,
                                                     uint8_t *end, symline_point *pts, uint32_t cap,
                                                     uint32_t *n, uint32_t *row_start,
                                                     uint32_t *dropped)
{
    hring *rp = (hring *)symline_i_carve(&cur, end, sizeof(hring));
    const uint32_t w = p->w, h = p->h, m = p->m;
    const uint32_t delta = h_delta(p);
    /* Energies of rows t-2, t-1, t in turn (E3 + w * (row % 3)). */
    uint32_t *E3 = (uint32_t *)symline_i_carve(&cur, end, (size_t)3u * w * sizeof(uint32_t));
    symline_i_coldown *cd;
    const uint8_t **rows;
    uint16_t *acc = NULL;
    uint32_t t, y, produced = 0u;
    if (rp == NULL) {
        return SYMLINE_ERR_BUFFER;
    }
    cd = &rp->cd;
    rp->img = img;
    rp->p = p;
    rp->gray_rows = h_gray_rows(p);
    cd->E3 = E3;
    cd->stride = w;
    cd->width = w;
    cd->ring = h_map_rows(p);
    cd->lag = p->lag;
    cd->map = (uint8_t *)symline_i_carve(&cur, end, (size_t)w * cd->ring);
    cd->run_start = (uint16_t *)symline_i_carve(&cur, end, (size_t)w * sizeof(uint16_t));
    cd->left = (int8_t *)symline_i_carve(&cur, end, w);
    rp->gray = NULL;
    if (p->level > 0u) {
        rp->gray = (uint8_t *)symline_i_carve(&cur, end, (size_t)w * rp->gray_rows);
        acc = (uint16_t *)symline_i_carve(&cur, end, (size_t)img->width * sizeof(uint16_t));
        if (rp->gray == NULL || acc == NULL) {
            return SYMLINE_ERR_BUFFER;
        }
    }
    rows = (const uint8_t **)symline_i_carve(&cur, end,
                                             (2u * (size_t)m + 1u) * sizeof(const uint8_t *));
    if (E3 == NULL || cd->run_start == NULL || cd->left == NULL || cd->map == NULL ||
        rows == NULL) {
        return SYMLINE_ERR_BUFFER;
    }
    for (t = 0; t < h; t++) {
        uint32_t j;
        uint32_t *E = E3 + (size_t)(t % 3u) * w;
        if (p->level > 0u) {
            const uint32_t need = (t + m < h) ? t + m : h - 1u;
            SL_STAGE(GRID);
            while (produced <= need) {
                symline_i_grid_row(img, p, produced, acc,
                                   rp->gray + (size_t)(produced % rp->gray_rows) * w);
                produced++;
            }
        }
        for (j = 0; j <= 2u * m; j++) {
            const uint32_t yy = t + j; /* row t - m + j, offset by m to stay unsigned */
            rows[j] = (yy >= m && yy - m < h) ? h_row(rp, yy - m) : NULL;
        }
        SL_STAGE(OPERATOR);
        (void)symline_energy_across(rows, m, w, E);
        SL_STAGE(EXTREMA);
        if (t >= 1u) {
            symline_i_extrema_down(cd, E, t);
        }
        if (t >= delta) {
            SL_STAGE(FILTER);
            h_decide(rp, t - delta, pts, cap, n, row_start, dropped);
        }
    }
    SL_STAGE(FILTER);
    {
        uint8_t *mr = h_map(rp, h - 1u);
        uint32_t i;
        for (i = 0; i < w; i++) {
            mr[i] = SYMLINE_MAP_NONE;
        }
    }
    for (y = (h > delta) ? h - delta : 0u; y < h; y++) {
        h_decide(rp, y, pts, cap, n, row_start, dropped);
    }
    row_start[h] = *n;
    return SYMLINE_OK;
}

symline_status symline_i_collect(const symline_image *img, const symline_i_pass *p, void *ws,
                                 size_t ws_size, symline_point *pts, uint32_t cap, uint32_t *n,
                                 uint32_t *row_start, uint32_t *dropped)
{
    uint8_t *cur = (uint8_t *)ws;
    uint8_t *end = cur + ws_size;
    *n = 0u;
    if (p->w == 0u || p->h == 0u) {
        return SYMLINE_ERR_SIZE;
    }
    if (p->axis == SYMLINE_AXIS_VERTICAL) {
        return collect_vertical(img, p, cur, end, pts, cap, n, row_start, dropped);
    }
    return collect_horizontal(img, p, cur, end, pts, cap, n, row_start, dropped);
}

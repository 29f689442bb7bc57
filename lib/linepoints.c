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

/* The pass's grid rows (grid.c). A port's version (SYMLINE_PORT_GRID)
 * replaces this call, which is then its reference. */
#ifdef SYMLINE_PORT_GRID
#define SL_GRID_ROW symline_i_grid_row_c
#else
#define SL_GRID_ROW symline_i_grid_row
#endif
void SL_GRID_ROW(const symline_image *img, const symline_i_pass *p, uint32_t y, uint16_t *acc,
                 uint8_t *out)
{
    symline_i_grid_level_row(img, p->level, y, acc, out);
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

/* State of the rings (kept in the workspace). Along rows (vertical axis)
 * every ring holds one row: a grid row is decided as soon as it is in. */
typedef struct hring {
    const symline_image *img;
    const symline_i_pass *p;
    uint8_t *gray; /* gray_rows rows of w (levels > 0) */
    uint32_t gray_rows;
    symline_i_coldown cd; /* extrema (down the columns) into the map ring (cd.ring rows of w) */
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
    size_t n = (size_t)6u * SL_ALIGN + symline_i_align_up(sizeof(hring));
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
    n += symline_i_align_up(2u * w * sizeof(uint32_t)); /* two more rows of energies */
    n += symline_i_align_up(w * sizeof(uint16_t));      /* where the plateaus began */
    /* the signs of the differences between rows and the plateaus' sides (cd.sg) */
    n += symline_i_align_up(2u * w);
    /* 1 B per column unused since the column extrema need no event list, kept
     * until SYMLINE_DETECT_WORKSPACE_SIZE (detect.h) and its sizing test drop
     * it together. */
    n += symline_i_align_up(w) + (size_t)2u * SL_ALIGN;
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
 * what it saves, in code size too, so it is left out there, unless a port has
 * byte lanes for it (Cortex-M4/M7: SYMLINE_PORT_DROP_DIM_S, port/armv7em/).
 * Where a port searches the row with the byte test itself
 * (SYMLINE_PORT_LINE_S: x86-64, AArch64), the row decision uses that instead. */
#if !defined(SYMLINE_PORT_LINE_S) && (defined(__SSE2__) || defined(__ARM_NEON) ||                  \
                                      defined(__ARM_NEON__) || defined(SYMLINE_PORT_DROP_DIM_S))
#define SL_ROW_PREFILTER 1
#endif
/* A port's version (SYMLINE_PORT_DROP_DIM_S: where the core has byte lanes of
 * its own, linepoints.h) replaces it; this one is then the reference. */
#ifdef SYMLINE_PORT_DROP_DIM_S
#define SL_DROP_DIM_S_REF void symline_i_drop_dim_s_c
#define drop_dim_s symline_i_drop_dim_s
#else
#define SL_DROP_DIM_S_REF SL_NOINLINE static void drop_dim_s
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
SL_DROP_DIM_S_REF(const symline_i_linefilter *f, const uint8_t *c, const uint8_t *lo,
                  const uint8_t *hi, uint32_t n, uint8_t *map)
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

static const uint8_t *ring_row(const hring *r, uint32_t y)
{
    if (r->p->level == 0u) {
        return r->img->data + (size_t)y * r->img->stride;
    }
    return r->gray + (size_t)(y % r->gray_rows) * r->p->w;
}

static uint8_t *ring_map(const hring *r, uint32_t y)
{
    return r->cd.map + (size_t)(y % r->cd.ring) * r->p->w;
}

/* What the decision of one row reads (built in decide_row()). */
typedef struct row_view {
    uint8_t *map; /* written only by the pre-filter (SL_ROW_PREFILTER) */
    const uint8_t *c, *lo, *hi;
    const uint8_t *amap; /* the A points near: the map row, or the map ring */
    uint32_t w, dk;      /* dk: across the line along the row (vertical axis), else 0 */
    uint32_t aring, alen;
    size_t astep;
} row_view;

/* S point x of row y, its sides' gray values lo and hi: added to the points
 * when the line filter takes it. */
static SL_ALWAYS_INLINE void decide_s(const symline_i_linefilter *f, const row_view *v, uint32_t x,
                                      uint32_t y, uint32_t lo, uint32_t hi, bool along,
                                      symline_point *pts, uint32_t cap, uint32_t *n,
                                      uint32_t *dropped)
{
    if (!symline_i_linefilter_gray(f, v->c[x], lo, hi)) {
        return;
    }
    if (f->a_distance != 0u && !symline_i_linefilter_a_near(f, v->amap + (along ? 0u : x), v->aring,
                                                            v->astep, v->alen, along ? x : y)) {
        return;
    }
    push_point(pts, cap, n, x, y, dropped);
}

/* decide_s() where the sides may lie beyond the row's ends (clamped). */
static SL_ALWAYS_INLINE void decide_s_edge(const symline_i_linefilter *f, const row_view *v,
                                           uint32_t x, uint32_t y, bool along, symline_point *pts,
                                           uint32_t cap, uint32_t *n, uint32_t *dropped)
{
    const uint32_t w = v->w, dk = v->dk;
    decide_s(f, v, x, y, v->lo[x >= dk ? x - dk : 0u], v->hi[x + dk < w ? x + dk : w - 1u], along,
             pts, cap, n, dropped);
}

/* The line points of grid row y from its map row: S points whose gray
 * values pass the line filter, with an A point near when it asks for one.
 * Across the line: k entries either side along a row (vertical axis),
 * k rows up and down a column (horizontal axis). */
static SL_ALWAYS_INLINE void decide_row(const hring *r, uint32_t y, symline_point *pts,
                                        uint32_t cap, uint32_t *n, uint32_t *row_start,
                                        uint32_t *dropped, bool along)
{
    const symline_i_pass *p = r->p;
    /* A copy in locals: the stores of points cannot change it (to save time). */
    const symline_i_linefilter fcopy = p->filter;
    const symline_i_linefilter *f = SL_FOR_SPEED ? &fcopy : &p->filter;
    const uint32_t w = p->w;
    const uint32_t dk = along ? p->k : 0u, ky = along ? 0u : p->k;
    uint32_t x = 0u;
    row_view v;
    v.map = ring_map(r, y);
    v.c = ring_row(r, y);
    v.lo = ring_row(r, y >= ky ? y - ky : 0u);
    v.hi = ring_row(r, y + ky < p->h ? y + ky : p->h - 1u);
    v.amap = along ? v.map : r->cd.map;
    v.w = w;
    v.dk = dk;
    v.aring = along ? w : r->cd.ring;
    v.alen = along ? w : p->h;
    v.astep = along ? 1u : w;
    row_start[y] = *n;
#ifdef SYMLINE_PORT_LINE_S
    if (w > 2u * dk) {
        /* The interior, where both sides lie in the row (along a row; the
         * whole row down columns): one pass of the byte test over it gives
         * the few S points the exact filter has to look at. */
        const uint32_t len = w - 2u * dk;
        const bool paper = f->kind == SYMLINE_FILTER_PAPER; /* gray only */
        const uint8_t *ic = v.c + dk, *ilo = paper ? ic : v.lo, *ihi = paper ? ic : v.hi + 2u * dk;
        symline_i_prefilter pf;
        uint16_t cand[SL_LINE_S_MAX];
        uint32_t at = 0u, i;
        symline_i_prefilter_setup(f, &pf);
        for (; x < dk; x++) { /* the left border */
            if (v.map[x] == SYMLINE_MAP_S) {
                decide_s_edge(f, &v, x, y, along, pts, cap, n, dropped);
            }
        }
        while (at < len) {
            const uint32_t k = symline_i_line_s(&pf, v.map + dk, ic, ilo, ihi, at, len, cand, &at);
            for (i = 0; i < k; i++) {
                const uint32_t j = cand[i];
                decide_s(f, &v, dk + j, y, v.lo[j], v.hi[j + 2u * dk], along, pts, cap, n, dropped);
            }
        }
        for (x = w - dk; x < w; x++) { /* the right border */
            if (v.map[x] == SYMLINE_MAP_S) {
                decide_s_edge(f, &v, x, y, along, pts, cap, n, dropped);
            }
        }
    }
#elif defined(SL_ROW_PREFILTER)
    if (w > 2u * dk) { /* along a row: the interior, where both sides lie in the row */
        drop_dim_s(f, v.c + dk, v.lo, v.hi + (size_t)2u * dk, w - 2u * dk, v.map + dk);
    }
#endif
    for (; x < w; x = SL_NEXT_S(v.map, x, w)) {
        if (v.map[x] == SYMLINE_MAP_S) {
            decide_s_edge(f, &v, x, y, along, pts, cap, n, dropped);
        }
    }
}

/* The row decision; to save time (SL_FOR_SPEED), one copy per axis. */
SL_NOINLINE static void decide(const hring *r, uint32_t y, symline_point *pts, uint32_t cap,
                               uint32_t *n, uint32_t *row_start, uint32_t *dropped)
{
    const bool along = r->p->axis == SYMLINE_AXIS_VERTICAL;
    if (SL_FOR_SPEED && along) {
        decide_row(r, y, pts, cap, n, row_start, dropped, true);
    } else if (SL_FOR_SPEED) {
        decide_row(r, y, pts, cap, n, row_start, dropped, false);
    } else {
        decide_row(r, y, pts, cap, n, row_start, dropped, along);
    }
}

symline_status symline_i_collect(const symline_image *img, const symline_i_pass *p, void *ws,
                                 size_t ws_size, symline_point *pts, uint32_t cap, uint32_t *n,
                                 uint32_t *row_start, uint32_t *dropped)
{
    uint8_t *cur = (uint8_t *)ws;
    uint8_t *const end = cur + ws_size;
    hring *rp = (hring *)symline_i_carve(&cur, end, sizeof(hring));
    const uint32_t w = p->w, h = p->h, m = p->m;
    const bool along = p->axis == SYMLINE_AXIS_VERTICAL;
    /* Down the columns, row t's extrema are known once row t + lag + 1 is in,
     * and its decision waits for a_distance more rows of extrema. */
    const uint32_t delta = along ? 0u : h_delta(p);
    /* Energies of rows t-2, t-1, t in turn (E3 + w * (row % 3)); one row along rows. */
    const uint32_t erows = along ? 1u : 3u;
    uint32_t *E3 = (uint32_t *)symline_i_carve(&cur, end, (size_t)erows * w * sizeof(uint32_t));
    symline_i_coldown *cd;
    const uint8_t **rows = NULL;
    uint16_t *acc = NULL;
    uint32_t t, produced = 0u;
    *n = 0u;
    if (w == 0u || h == 0u) {
        return SYMLINE_ERR_SIZE;
    }
    if (rp == NULL) {
        return SYMLINE_ERR_BUFFER;
    }
    cd = &rp->cd;
    rp->img = img;
    rp->p = p;
    rp->gray_rows = along ? 1u : h_gray_rows(p);
    cd->E3 = E3;
    cd->stride = w;
    cd->width = w;
    cd->ring = along ? 1u : h_map_rows(p);
    cd->lag = p->lag;
    cd->map = (uint8_t *)symline_i_carve(&cur, end, (size_t)w * cd->ring);
    if (p->level > 0u) { /* else the frame's rows are read (ring_row()) */
        rp->gray = (uint8_t *)symline_i_carve(&cur, end, (size_t)w * rp->gray_rows);
        /* The box accumulator serves the lane loops alone (SL_FOR_SPEED); its
         * room stays in the workspace size either way. */
        if (SL_FOR_SPEED) {
            acc = (uint16_t *)symline_i_carve(&cur, end, (size_t)img->width * sizeof(uint16_t));
        }
        if (rp->gray == NULL || (SL_FOR_SPEED && acc == NULL)) {
            return SYMLINE_ERR_BUFFER;
        }
    }
    if (!along) {
        cd->run_start = (uint16_t *)symline_i_carve(&cur, end, (size_t)w * sizeof(uint16_t));
        cd->sg = (int8_t *)symline_i_carve(&cur, end, 2u * (size_t)w);
        rows = (const uint8_t **)symline_i_carve(&cur, end,
                                                 (2u * (size_t)m + 1u) * sizeof(const uint8_t *));
        if (cd->run_start == NULL || cd->sg == NULL || rows == NULL) {
            return SYMLINE_ERR_BUFFER;
        }
    }
    if (E3 == NULL || cd->map == NULL) {
        return SYMLINE_ERR_BUFFER;
    }
    /* Rows t >= h only decide the last delta rows. */
    for (t = 0; t < h + delta; t++) {
        uint32_t *E = E3 + (size_t)(t % erows) * w;
        if (t >= h) {
            if (t == h) {
                /* The last row touches the bottom: never marked. */
                uint8_t *mr = ring_map(rp, h - 1u);
                uint32_t x;
                for (x = 0; x < w; x++) {
                    mr[x] = SYMLINE_MAP_NONE;
                }
            }
        } else {
            if (p->level > 0u) {
                const uint32_t need = along ? t : (t + m < h) ? t + m : h - 1u;
                SL_STAGE(GRID);
                while (produced <= need) {
                    symline_i_grid_row(img, p, produced, acc,
                                       rp->gray + (size_t)(produced % rp->gray_rows) * w);
                    produced++;
                }
            }
            SL_STAGE(OPERATOR);
            if (along) {
                (void)symline_energy_row(ring_row(rp, t), w, m, E);
                SL_STAGE(EXTREMA);
                symline_i_extrema_runs(E, w, p->lag, cd->map);
            } else {
                uint32_t j;
                for (j = 0; j <= 2u * m; j++) {
                    const uint32_t yy = t + j; /* row t - m + j, offset by m to stay unsigned */
                    rows[j] = (yy >= m && yy - m < h) ? ring_row(rp, yy - m) : NULL;
                }
                (void)symline_energy_across(rows, m, w, E);
                SL_STAGE(EXTREMA);
                if (t >= 1u) {
                    symline_i_extrema_down(cd, E, t);
                }
            }
        }
        if (t >= delta) {
            SL_STAGE(FILTER);
            decide(rp, t - delta, pts, cap, n, row_start, dropped);
        }
    }
    row_start[h] = *n;
    return SYMLINE_OK;
}

/* SPDX-License-Identifier: Apache-2.0 */
/*
 * Line points of one pass, streamed row by row.
 *
 * A line point is an S point (a symmetry maximum, with the plateau limit)
 * that passes the line filter. The filter's gray-value tests need no
 * energies, and on field frames only 1 to 5 grid pixels in 100 pass them,
 * so each grid row is first searched with the byte test (whole rows, byte
 * lanes) and energies are computed at those candidates alone, where the
 * extremum is decided exactly by the run rule of docs/algorithm.md: the
 * points are those the whole energy and extrema images would give
 * (tests/detect/test_linepoints.c compares them).
 *
 * Vertical axis (symmetry along rows): every grid row is complete on its own.
 * Horizontal axis (symmetry down the columns): a candidate of row y reads
 * energies of rows y - a_distance - lag - 1 .. y + a_distance + lag + 1
 * (plateaus longer than 2*lag+1 rows are not line points: no thin line has
 * them; the paper's filter looks a_distance rows for an A point), each m
 * rows more. At full resolution those are the frame's rows; at coarser
 * scales a ring holds just those grid rows: working memory grows with
 * width * radius, not with height.
 *
 * Output: points appended in raster order, so the list is its own spatial
 * index together with row_start.
 */
#include "linepoints.h"

#include "stagemark.h"

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

/* How far from a decided row a candidate's work reaches down the columns
 * (horizontal axis), in grid rows: energies of rows y - a_distance - lag - 1
 * .. y + a_distance + lag + 1 (the plateau limit and the A point search),
 * each reading m rows more, and the contrast sides k = m + 1 <= that. */
static uint32_t reach(const symline_i_pass *p)
{
    return p->filter.a_distance + p->lag + 1u + p->m;
}

/* Grid rows held down the columns at coarse levels: the decided row and
 * reach() rows to either side. */
static uint32_t ring_rows(const symline_i_pass *p)
{
    return 2u * reach(p) + 1u;
}

size_t symline_i_collect_ws_size(const symline_i_pass *p, uint32_t img_width)
{
    size_t n = (size_t)2u * SL_ALIGN;
    if (p->level > 0u) {
        n += symline_i_align_up((size_t)img_width * sizeof(uint16_t)); /* box accumulator */
        /* the grid row, or the ring of them down the columns */
        n += symline_i_align_up((size_t)p->w *
                                (p->axis == SYMLINE_AXIS_VERTICAL ? 1u : 2u * ring_rows(p)));
    }
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

/* The line through a candidate: entry i of it is c0[(i - i0) * step] (a
 * grid row along it, vertical axis; a column down, horizontal axis), n
 * entries. */
typedef struct line_view {
    const uint8_t *c0;
    ptrdiff_t step;
    uint32_t i0, n, m, lag;
} line_view;

/* The contribution of m - j pairs that leave the line to the sums of
 * energy_at(): each adds 255^2 to the partial sum, which the energy adds. */
static uint32_t outside_pairs(uint32_t j, uint32_t m, uint32_t sum, uint32_t e)
{
    for (; j <= m; j++) {
        sum += 255u * 255u;
        e += sum;
    }
    return e;
}

/*
 * The symmetry energy E(i) of entry i of the line (docs/algorithm.md),
 * exactly: sum over j = 1..m of (m + 1 - j) d_j^2, as the sum over
 * k = 1..m of the partial sums d_1^2 + .. + d_k^2 (one product per pair),
 * d_j = 255 where the pair leaves the line. At most 255^2 m (m + 1) / 2 <
 * 2^31.
 */
static uint32_t energy_at(const line_view *l, uint32_t i)
{
    const uint32_t m = l->m, in = i < l->n - 1u - i ? i : l->n - 1u - i;
    const uint32_t inner = in < m ? in : m; /* pairs inside the line */
    const ptrdiff_t step = l->step;
    const uint8_t *a = l->c0 + ((ptrdiff_t)i - (ptrdiff_t)l->i0) * step, *b = a;
    uint32_t j, sum = 0u, e = 0u;
    for (j = 1u; j <= inner; j++) {
        int32_t d;
        a -= step;
        b += step;
        d = (int32_t)*a - (int32_t)*b;
        sum += (uint32_t)(d * d);
        e += sum;
    }
    return outside_pairs(j, m, sum, e);
}

/* E(i-1), E(i) and E(i+1) of an entry at least m + 1 entries inside the
 * line, in one loop over the pairs; m a constant where that pays (below). */
static SL_ALWAYS_INLINE void energies3_in(const line_view *l, uint32_t i, uint32_t m, uint32_t *up,
                                          uint32_t *e, uint32_t *dn)
{
    const ptrdiff_t step = l->step;
    const uint8_t *lo = l->c0 + ((ptrdiff_t)i - (ptrdiff_t)l->i0) * step, *hi = lo;
    uint32_t j, su = 0u, sc = 0u, sd = 0u, eu = 0u, ec = 0u, ed = 0u;
    for (j = 1u; j <= m; j++) {
        int32_t du, dc, dd;
        lo -= step;
        hi += step;
        du = (int32_t)lo[-step] - (int32_t)hi[-step];
        dc = (int32_t)lo[0] - (int32_t)hi[0];
        dd = (int32_t)lo[step] - (int32_t)hi[step];
        su += (uint32_t)(du * du);
        sc += (uint32_t)(dc * dc);
        sd += (uint32_t)(dd * dd);
        eu += su;
        ec += sc;
        ed += sd;
    }
    *up = eu;
    *e = ec;
    *dn = ed;
}

/* E(i-1), E(i) and E(i+1) of entry 0 < i < n-1 of the line. */
static SL_ALWAYS_INLINE void energies3(const line_view *l, uint32_t i, uint32_t *up, uint32_t *e,
                                       uint32_t *dn)
{
    if (SL_FOR_SPEED && i > l->m && i + l->m + 1u < l->n) {
        if (l->m == 3u) { /* the default radius: unrolled, constant offsets */
            energies3_in(l, i, 3u, up, e, dn);
        } else {
            energies3_in(l, i, l->m, up, e, dn);
        }
    } else {
        *up = energy_at(l, i - 1u);
        *e = energy_at(l, i);
        *dn = energy_at(l, i + 1u);
    }
}

/*
 * Whether entry i of the line is an S point (s) or an A point (!s) by the run
 * rule of docs/algorithm.md with the plateau limit: the middle of a run
 * [a, b] of equal energies, a >= 1, b <= n - 2, b - i <= lag, whose
 * neighbours E(a-1), E(b+1) are both larger (S) or both smaller (A). Most
 * runs are single entries: three energies decide; a run is followed at most
 * lag + 1 entries each way (a longer one is not marked).
 */
static bool extremum_at(const line_view *l, uint32_t i, bool s)
{
    uint32_t e, up, dn, a = i, b = i;
    if (i == 0u || i + 1u >= l->n) {
        return false;
    }
    SL_STAGE(OPERATOR);
    energies3(l, i, &up, &e, &dn);
    SL_STAGE(EXTREMA);
    /* The run of equal energies through i, followed on the slow path. */
    while (up == e) {
        if (--a == 0u || i - a > l->lag) {
            return false;
        }
        up = energy_at(l, a - 1u);
    }
    while (dn == e) {
        if (++b + 1u >= l->n || b - i > l->lag) {
            return false;
        }
        dn = energy_at(l, b + 1u);
    }
    return (up > e) == s && (dn > e) == s && (a + b) / 2u == i;
}

/* Whether an A point lies within a_distance entries of entry i (the paper's filter). */
static bool a_near(const line_view *l, uint32_t i, uint32_t d)
{
    uint32_t j = i >= d ? i - d : 0u;
    const uint32_t last = i + d < l->n ? i + d : l->n - 1u;
    for (; j <= last; j++) {
        if (extremum_at(l, j, false)) {
            return true;
        }
    }
    return false;
}

/* Grid row y's gray values (rows[r] = grid row y0 + r, the decided row at
 * `mid`) and the line filter's candidates in it. */
typedef struct row_view {
    const uint8_t *c, *lo, *hi; /* the row, and its sides across the line (down: rows y -+ k) */
    uint32_t y, w, dk;          /* dk: across the line along the row (vertical axis), else 0 */
} row_view;

/* Candidate x of row v (its sides lo, hi): a line point when the exact gray
 * test passes, it is an S point along the line l, and, for the paper's
 * filter, an A point lies near it across the line. */
static SL_ALWAYS_INLINE void decide_at(const symline_i_linefilter *f, line_view *l,
                                       const row_view *v, uint32_t x, uint32_t lo, uint32_t hi,
                                       bool along, symline_point *pts, uint32_t cap, uint32_t *n,
                                       uint32_t *dropped)
{
    const uint32_t i = along ? x : v->y;
    if (!symline_i_linefilter_gray(f, v->c[x], lo, hi)) {
        return;
    }
    if (!along) {
        l->c0 = v->c + x; /* down column x from row y */
    }
    if (!extremum_at(l, i, true) || (f->a_distance != 0u && !a_near(l, i, f->a_distance))) {
        SL_STAGE(FILTER);
        return;
    }
    SL_STAGE(FILTER);
    push_point(pts, cap, n, x, v->y, dropped);
}

/* decide_at() where the sides may lie beyond the row's ends (clamped). */
static SL_ALWAYS_INLINE void decide_edge(const symline_i_linefilter *f, line_view *l,
                                         const row_view *v, uint32_t x, bool along,
                                         symline_point *pts, uint32_t cap, uint32_t *n,
                                         uint32_t *dropped)
{
    const uint32_t w = v->w, dk = v->dk;
    decide_at(f, l, v, x, v->lo[x >= dk ? x - dk : 0u], v->hi[x + dk < w ? x + dk : w - 1u], along,
              pts, cap, n, dropped);
}

/* symline_i_linefilter_gray() as one expression, for the batches below: its
 * early returns would be branches that go either way. */
static SL_ALWAYS_INLINE uint32_t gray_ok(const symline_i_linefilter *f, uint32_t c, uint32_t lo,
                                         uint32_t hi)
{
    const uint32_t side = lo > hi ? lo : hi, diff = lo > hi ? lo - hi : hi - lo;
    const uint32_t ridge = f->ridge_pct == 0u ? 0u : (c * f->ridge_pct + 99u) / 100u;
    const uint32_t asym = (diff * f->asym_pct + 99u) / 100u;
    uint32_t need = ridge > f->ridge_min ? ridge : f->ridge_min;
    need = asym > need ? asym : need;
    if (f->kind == SYMLINE_FILTER_PAPER) {
        return (uint32_t)(c >= f->min_gray);
    }
    return (uint32_t)(c >= f->min_gray) & (uint32_t)(c > side) & (uint32_t)(side <= f->side_max) &
           (uint32_t)(c - side >= need);
}

/* The candidates cand[0..k-1] of row v (interior entries: x = dk + cand[i])
 * in three steps over the batch: the exact gray test, then the energies and
 * the S decision (a plateau on extremum_at()'s slow path), then the points.
 * A candidate passes each test about as often as it fails: one branch per
 * test and candidate would be mispredicted half the time, the batches
 * compact their lists without branches. */
static SL_ALWAYS_INLINE void decide_batch(const symline_i_linefilter *f, line_view *l,
                                          const row_view *v, uint16_t *cand, uint32_t k, bool along,
                                          symline_point *pts, uint32_t cap, uint32_t *n,
                                          uint32_t *dropped)
{
    const uint32_t dk = v->dk;
    uint32_t i, kg = 0u, ks = 0u;
    for (i = 0; i < k; i++) {
        const uint32_t j = cand[i];
        cand[kg] = (uint16_t)(dk + j);
        kg += gray_ok(f, v->c[dk + j], v->lo[j], v->hi[j + 2u * dk]);
    }
    SL_STAGE(OPERATOR);
    for (i = 0; i < kg; i++) {
        const uint32_t x = cand[i], at = along ? x : v->y;
        uint32_t up = 0u, e = 0u, dn = 0u, s;
        if (!along) {
            l->c0 = v->c + x; /* down column x from row y */
        }
        if (at != 0u && at + 1u < l->n) {
            energies3(l, at, &up, &e, &dn);
        }
        s = (uint32_t)(up > e) & (uint32_t)(dn > e);
        if (up == e || dn == e) {
            s = (uint32_t)extremum_at(l, at, true);
        }
        cand[ks] = (uint16_t)x;
        ks += s;
    }
    SL_STAGE(FILTER);
    for (i = 0; i < ks; i++) {
        const uint32_t x = cand[i];
        if (f->a_distance != 0u) {
            if (!along) {
                l->c0 = v->c + x;
            }
            if (!a_near(l, along ? x : v->y, f->a_distance)) {
                continue;
            }
        }
        push_point(pts, cap, n, x, v->y, dropped);
    }
}

/* The line points of grid row v->y: the byte test over the row's interior
 * (where both sides lie in the row; the whole row down the columns) gives
 * the few candidates, the exact tests follow at those alone. */
static SL_ALWAYS_INLINE void decide_row(const symline_i_linefilter *f, line_view *l,
                                        const row_view *v, symline_point *pts, uint32_t cap,
                                        uint32_t *n, uint32_t *dropped, bool along)
{
    const uint32_t w = v->w, dk = v->dk;
    uint32_t x;
    SL_STAGE(FILTER);
    for (x = 0u; x < dk && x < w; x++) { /* the left border */
        decide_edge(f, l, v, x, along, pts, cap, n, dropped);
    }
    if (w > 2u * dk) {
        const uint32_t len = w - 2u * dk;
        const bool paper = f->kind == SYMLINE_FILTER_PAPER; /* gray only */
        const uint8_t *ic = v->c + dk, *ilo = paper ? ic : v->lo,
                      *ihi = paper ? ic : v->hi + 2u * dk;
        symline_i_prefilter pf;
        uint16_t cand[SL_LINE_CAND_MAX];
        uint32_t at = 0u, k, i;
        symline_i_prefilter_setup(f, &pf);
        while (at < len) {
            k = symline_i_line_cand(&pf, ic, ilo, ihi, at, len, cand, &at);
            if (SL_FOR_SPEED) {
                decide_batch(f, l, v, cand, k, along, pts, cap, n, dropped);
                continue;
            }
            for (i = 0; i < k; i++) {
                const uint32_t j = cand[i];
                decide_at(f, l, v, dk + j, v->lo[j], v->hi[j + 2u * dk], along, pts, cap, n,
                          dropped);
            }
        }
        x = w - dk;
    }
    for (; x < w; x++) { /* the right border */
        decide_edge(f, l, v, x, along, pts, cap, n, dropped);
    }
}

/* The row decision; to save time (SL_FOR_SPEED), one copy per axis. */
SL_NOINLINE static void decide(const symline_i_linefilter *f, line_view *l, const row_view *v,
                               symline_point *pts, uint32_t cap, uint32_t *n, uint32_t *dropped)
{
    const bool along = l->step == 1;
    if (SL_FOR_SPEED && along) {
        decide_row(f, l, v, pts, cap, n, dropped, true);
    } else if (SL_FOR_SPEED) {
        decide_row(f, l, v, pts, cap, n, dropped, false);
    } else {
        decide_row(f, l, v, pts, cap, n, dropped, along);
    }
}

symline_status symline_i_collect(const symline_image *img, const symline_i_pass *p, void *ws,
                                 size_t ws_size, symline_point *pts, uint32_t cap, uint32_t *n,
                                 uint32_t *row_start, uint32_t *dropped)
{
    uint8_t *cur = (uint8_t *)ws;
    uint8_t *const end = cur + ws_size;
    const uint32_t w = p->w, h = p->h;
    const bool along = p->axis == SYMLINE_AXIS_VERTICAL;
    /* Down the columns at coarse levels, row y is decided once row y + R is in. */
    const uint32_t R = along ? 0u : reach(p), held = along ? 1u : ring_rows(p);
    /* A copy in locals: the stores of points cannot change it (to save time). */
    const symline_i_linefilter fcopy = p->filter;
    const symline_i_linefilter *f = SL_FOR_SPEED ? &fcopy : &p->filter;
    uint16_t *acc = NULL;
    uint8_t *gray = NULL;
    uint32_t y, produced = 0u;
    line_view l;
    row_view v;
    *n = 0u;
    if (w == 0u || h == 0u) {
        return SYMLINE_ERR_SIZE;
    }
    if (p->level > 0u) { /* else the frame's rows are read */
        /* The box accumulator serves the lane loops alone (SL_FOR_SPEED); its
         * room stays in the workspace size either way. */
        if (SL_FOR_SPEED) {
            acc = (uint16_t *)symline_i_carve(&cur, end, (size_t)img->width * sizeof(uint16_t));
        }
        /* Down the columns each grid row twice, in slots r % held and
         * r % held + held: any held rows in a row lie one after the other. */
        gray = (uint8_t *)symline_i_carve(&cur, end, (size_t)w * (along ? 1u : 2u * held));
        if (gray == NULL || (SL_FOR_SPEED && acc == NULL)) {
            return SYMLINE_ERR_BUFFER;
        }
    }
    l.n = along ? w : h;
    l.m = p->m;
    l.lag = p->lag;
    l.i0 = 0u;
    l.step = along ? 1 : (ptrdiff_t)(p->level == 0u ? img->stride : w);
    v.w = w;
    v.dk = along ? p->k : 0u;
    for (y = 0; y < h; y++) {
        if (p->level == 0u) {
            v.c = img->data + (size_t)y * img->stride;
        } else if (along) {
            SL_STAGE(GRID);
            symline_i_grid_row(img, p, y, acc, gray);
            v.c = gray;
        } else {
            const uint32_t need = y + R < h ? y + R : h - 1u, first = y > R ? y - R : 0u;
            SL_STAGE(GRID);
            for (; produced <= need; produced++) {
                uint8_t *g = gray + (size_t)(produced % held) * w, *g2 = g + (size_t)held * w;
                uint32_t x;
                symline_i_grid_row(img, p, produced, acc, g);
                for (x = 0; x < w; x++) {
                    g2[x] = g[x];
                }
            }
            /* Rows first .. need from the slot of row first on. */
            v.c = gray + (size_t)(first % held + (y - first)) * w;
        }
        if (along) {
            v.lo = v.c;
            v.hi = v.c;
            l.c0 = v.c;
        } else {
            const ptrdiff_t st = l.step;
            v.lo = v.c - (ptrdiff_t)(y >= p->k ? p->k : y) * st;
            v.hi = v.c + (ptrdiff_t)(y + p->k < h ? p->k : h - 1u - y) * st;
            l.i0 = y;
        }
        v.y = y;
        row_start[y] = *n;
        decide(f, &l, &v, pts, cap, n, dropped);
    }
    row_start[h] = *n;
    return SYMLINE_OK;
}

/* SPDX-License-Identifier: Apache-2.0 */
/*
 * Line points of one pass, streamed row by row.
 *
 * A line point is an S point (a symmetry maximum, with the plateau limit)
 * that passes the line filter. The filter's gray-value tests need no
 * energies, and on field frames only 1 to 5 grid pixels in 100 pass them,
 * so each grid row is first searched with the byte test (whole rows, byte
 * lanes) and energies are computed at those candidates alone (down the
 * columns, in the speed builds, for blocks of neighbouring candidates at
 * once), where the extremum is decided exactly by the run rule of
 * docs/algorithm.md: the points are those the whole energy and extrema
 * images would give (tests/detect/test_linepoints.c compares them).
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
                 uint8_t *out, uint8_t *twin)
{
    symline_i_grid_level_row(img, p->level, y, acc, out, twin);
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
 * line, in one loop over the pairs; m and the step constants where that
 * pays (below): along a row (step 1) the 18 loads of m = 3 are 9 bytes. */
static SL_ALWAYS_INLINE void energies3_in(const line_view *l, uint32_t i, uint32_t m,
                                          ptrdiff_t step, uint32_t *up, uint32_t *e, uint32_t *dn)
{
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

/* E(i-1), E(i) and E(i+1) of entry 0 < i < n-1 of the line; unrolled at
 * the default radius (along a row at m = 3 s_point() calls energies3_in()
 * with step 1 itself). */
static SL_ALWAYS_INLINE void energies3(const line_view *l, uint32_t i, uint32_t *up, uint32_t *e,
                                       uint32_t *dn)
{
    if (SL_FOR_SPEED && i > l->m && i + l->m + 1u < l->n) {
        if (l->m == 3u) { /* constant offsets */
            energies3_in(l, i, 3u, l->step, up, e, dn);
        } else {
            energies3_in(l, i, l->m, l->step, up, e, dn);
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

/*
 * The decision in vector lanes, where the compiler has them (SSE2, NEON)
 * and the build optimises for speed, at the default radius m = 3: down the
 * columns a line across them gives runs of consecutive candidates in a
 * row, so a block of SL_LP_LANES neighbouring entries gets the rest of the
 * exact gray test, E(y-1), E(y), E(y+1) and the S decision at once
 * (symline_i_lanes_down_c(), linepoints.h: a loop over the entries the
 * compiler vectorises; a port's symline_i_cand_down() decides from the
 * byte test's masks instead), instead of one candidate at a time with
 * strided loads. Along the rows the runs are a line's width, a
 * few entries: blocks there saved nothing (callgrind), the candidate-wise
 * batch stays. Scalar cores (Cortex-M) keep it too: there the lanes would
 * be work on entries that are no candidates.
 */
#if SL_FOR_SPEED && (defined(__SSE2__) || defined(__ARM_NEON) || defined(__ARM_NEON__))
#define SL_LP_LANES SL_LANES_DOWN
#else
#define SL_LP_LANES 0u
#endif
/* A port's byte test and decision down the columns in one pass (speed
 * builds; the size builds have no byte test). */
#if SL_LP_LANES && defined(SYMLINE_PORT_CAND_DOWN)
#define SL_LP_CAND_DOWN 1
#else
#define SL_LP_CAND_DOWN 0
#endif

#if SL_LP_LANES
/* Whether the lanes can take the filter: the byte test exact on min_gray,
 * and 100 (c - side), c * ridge_pct and |lo - hi| * asym_pct within 16 bits
 * (ridge_pct <= 100, the checked range; asym_pct <= 257, the default 150). */
static bool lane_gray_setup(const symline_i_linefilter *f, symline_i_lane_gray *g)
{
    g->ridge_min = (int16_t)(f->ridge_min < 1u ? 1u : (f->ridge_min < 256u ? f->ridge_min : 256u));
    g->ridge_pct = (uint16_t)f->ridge_pct;
    g->asym_pct = (uint16_t)f->asym_pct;
    g->paper = (uint16_t)(f->kind == SYMLINE_FILTER_PAPER);
    return f->min_gray <= 255u && f->ridge_pct <= 100u && f->asym_pct <= 257u;
}
#endif

/* The state of one pass's collection, in the workspace (not on the stack:
 * the deepest call chain of the detector runs through here). */
typedef struct lp_ctx {
    const symline_i_linefilter *f; /* the pass's filter */
    line_view l;                   /* the line through the candidate at hand */
    const uint8_t *c, *lo, *hi;    /* row y, and its sides across the line (down: rows y -+ k) */
    symline_point *pts;
    uint32_t *n, *dropped;
    uint32_t cap, y, w, dk; /* dk: across the line along the row (vertical axis), else 0 */
    uint32_t x0, x1;        /* the columns of row y decided: x0 .. x1-1 */
    uint32_t at, len;       /* speed builds, w > 2 dk: the interior entries among
                               them, dk + at .. dk + len-1 */
    uint32_t top, full;     /* speed builds, below the field boundary: the rows no
                               column keeps are those above top, every column keeps
                               those from full on (field_spans()) */
    const symline_image *img;
    const symline_i_pass *p;
    uint16_t *acc;     /* box sums of the coarse grids' rows (speed builds) */
    uint8_t *gray;     /* the coarse grid's row, or ring of rows */
    uint32_t produced; /* grid rows in the ring (or the cache) so far */
#if SL_FOR_SPEED_DEEP
    uint32_t built; /* the first row this pass built into the grid row cache; h: none */
#endif
    uint16_t cand[SL_LINE_CAND_MAX];
    symline_i_prefilter pf; /* the byte test of this pass's filter */
#if SL_LP_LANES
    symline_i_lane_gray lg; /* the exact gray test after the byte test */
    bool gray_rest;         /* lg holds this pass's filter */
    bool lanes;             /* the lanes decide this pass's interior candidates (m = 3) */
    bool lanes_row;         /* ... and those of the row at hand */
#endif
} lp_ctx;

/* In the speed builds each decision is copied into its callers (one copy per
 * axis); the size builds keep one of each. */
#if SL_FOR_SPEED
#define SL_LP_INLINE SL_ALWAYS_INLINE
#else
#define SL_LP_INLINE
#endif

static void push_point(lp_ctx *c, uint32_t x)
{
    if (*c->n >= c->cap) {
        (*c->dropped)++; /* counted, so the result can say how much storage was needed */
        return;
    }
    c->pts[*c->n].x = (uint16_t)x;
    c->pts[*c->n].y = (uint16_t)c->y;
    (*c->n)++;
}

/* Entry x of row y with sides lo, hi: a line point when the exact gray test
 * passes, it is an S point along the line through it, and, for the paper's
 * filter, an A point lies near it across the line. */
static SL_LP_INLINE void decide_at(lp_ctx *c, uint32_t x, uint32_t lo, uint32_t hi, bool along)
{
    const uint32_t i = along ? x : c->y;
    if (!symline_i_linefilter_gray(c->f, c->c[x], lo, hi)) {
        return;
    }
    if (!along) {
        c->l.c0 = c->c + x; /* down column x from row y */
    }
    if (!extremum_at(&c->l, i, true) ||
        (c->f->a_distance != 0u && !a_near(&c->l, i, c->f->a_distance))) {
        SL_STAGE(FILTER);
        return;
    }
    SL_STAGE(FILTER);
    push_point(c, x);
}

/* decide_at() for entries x0 .. x1-1, where the sides may lie beyond the
 * row's ends (clamped): the row's first and last dk entries (all of it in
 * the size builds). */
static SL_LP_INLINE void decide_edge(lp_ctx *c, uint32_t x0, uint32_t x1, bool along)
{
    const uint32_t w = c->w, dk = c->dk;
    uint32_t x;
    for (x = x0; x < x1; x++) {
        decide_at(c, x, c->lo[x >= dk ? x - dk : 0u], c->hi[x + dk < w ? x + dk : w - 1u], along);
    }
}

/* decide_edge() for a row's left or right border along the row (speed
 * builds, w > 2 dk), behind the byte test (for the paper's filter its
 * gray value alone): the clamped side is the row's
 * first or last entry, the other lies in the row; most border entries fail
 * at c >= min_gray, bright ones mostly at the contrast (callgrind). */
static SL_ALWAYS_INLINE void decide_border(lp_ctx *c, const symline_i_prefilter *pf, bool left,
                                           bool along)
{
    const uint32_t w = c->w, dk = c->dk;
    const uint8_t *const r = c->c;
    const uint32_t fixed = left ? r[0] : r[w - 1u];
    const bool paper = c->f->kind == SYMLINE_FILTER_PAPER; /* gray only */
    /* the border's entries among columns c->x0 .. c->x1-1 */
    const uint32_t x1 = left ? (dk < c->x1 ? dk : c->x1) : c->x1;
    uint32_t x = left ? c->x0 : (w - dk > c->x0 ? w - dk : c->x0);
    for (; x < x1; x++) {
        const uint32_t v = r[x];
        if (v >= pf->min_gray) {
            const uint32_t other = left ? r[x + dk] : r[x - dk];
            const uint32_t side = fixed > other ? fixed : other;
            if (paper || ((v >= side + pf->ridge_min || v == 255u) && side <= pf->side_max)) {
                decide_at(c, x, left ? fixed : other, left ? other : fixed, along);
            }
        }
    }
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

/* Whether candidate x of row y, which passed the exact gray test, is an S
 * point along the line through it (a plateau on extremum_at()'s slow
 * path): 1 or 0. */
static SL_ALWAYS_INLINE uint32_t s_point(lp_ctx *c, uint32_t x, bool along)
{
    const uint32_t at = along ? x : c->y;
    uint32_t up = 0u, e = 0u, dn = 0u, s;
    if (!along) {
        c->l.c0 = c->c + x; /* down column x from row y */
    }
    if (along && c->l.m == 3u && c->dk > 3u) {
        /* along a row the batch's candidates lie dk > m entries inside it */
        energies3_in(&c->l, at, 3u, 1, &up, &e, &dn);
    } else if (at != 0u && at + 1u < c->l.n) {
        energies3(&c->l, at, &up, &e, &dn);
    }
    s = (uint32_t)(up > e) & (uint32_t)(dn > e);
    if (up == e || dn == e) {
        s = (uint32_t)extremum_at(&c->l, at, true);
    }
    return s;
}

#if defined(SYMLINE_PORT_S_ALONG3) || SL_LP_CAND_DOWN
/* Of the ks candidates cand[0 ..] that a port's decision kept
 * (symline_i_s_along3_keep() along a row, symline_i_cand_down() down the
 * columns), those of the set bits of plateau lie beside a run of equal
 * energies: the run rule decides them (extremum_at()). Keeps the S points
 * in cand[0 ..], returns how many. Rare: apart from the batch's loop. */
SL_NOINLINE static uint32_t plateaus(lp_ctx *c, uint32_t ks, uint64_t plateau, bool along)
{
    uint32_t i, kept = 0u;
    for (i = 0; i < ks; i++) {
        const uint32_t x = c->cand[i];
        c->cand[kept] = (uint16_t)x;
        if (((plateau >> i) & 1u) == 0u) {
            kept++;
            continue;
        }
        if (!along) {
            c->l.c0 = c->c + x; /* down column x from row y */
        }
        kept += (uint32_t)extremum_at(&c->l, along ? x : c->y, true);
    }
    return kept;
}
#endif

#if SL_LP_LANES && !SL_LP_CAND_DOWN
/* s_point() down the columns, for the few candidates decided one at a time:
 * apart, so that the blocks' loop keeps its state in registers. */
SL_NOINLINE static uint32_t s_point_down(lp_ctx *c, uint32_t x)
{
    return s_point(c, x, false);
}
/* symline_i_s3_down() (linepoints.h), for the candidates decided one at a
 * time: apart, so that the blocks' loop keeps its state in registers. */
SL_NOINLINE static uint32_t s3_down(const uint8_t *p, ptrdiff_t st)
{
    return symline_i_s3_down(p, st);
}

/* Candidates within one block of lanes that make it worth its cost, about
 * that of this many candidates decided one at a time (callgrind, ex01 and
 * field frames down the columns, the portable block of 16). */
#define SL_LP_BLOCK_MIN 4u

/* The exact gray test and the S decision of candidates cand[0..k-1] of a
 * row down the columns (x = cand[i]): the S points' x to cand[0 ..],
 * returns how many. A candidate with SL_LP_BLOCK_MIN - 1 more within
 * SL_LP_LANES entries starts a block of lanes, which they share; the others
 * are decided one at a time. */
static SL_ALWAYS_INLINE uint32_t decide_batch_lanes(lp_ctx *c, uint32_t k)
{
    const uint32_t lanes = SL_LP_LANES, last = c->w - lanes; /* the last block start */
    uint16_t *cand = c->cand;
    uint8_t code[SL_LP_LANES];
    uint32_t i, ks = 0u, x0 = 0u, end = 0u;
    for (i = 0; i < k; i++) {
        const uint32_t x = cand[i];
        uint32_t s;
        if (x < end) {
            s = code[x - x0];
        } else if (i + SL_LP_BLOCK_MIN - 1u < k && cand[i + SL_LP_BLOCK_MIN - 1u] < x + lanes) {
            x0 = x < last ? x : last;
            end = x0 + lanes;
            symline_i_lanes_down_c(c->c + x0, c->l.step, &c->lg, code);
            s = code[x - x0];
        } else {
            /* alone */
            s = symline_i_lane_gray_ok(&c->lg, c->c[x], c->lo[x], c->hi[x]) != 0u
                    ? s3_down(c->c + x, c->l.step)
                    : 0u;
        }
        if (s > 1u) {
            s = s_point_down(c, x);
        }
        cand[ks] = (uint16_t)x;
        ks += s;
    }
    return ks;
}
#elif SL_LP_LANES
/* With a port's symline_i_cand_down() decide_row() has decided them: the
 * k S points are cand[0..k-1]. */
static SL_ALWAYS_INLINE uint32_t decide_batch_lanes(lp_ctx *c, uint32_t k)
{
    (void)c;
    return k;
}
#endif

/* The candidates cand[0..k-1] of row y (interior entries: x = dk + cand[i])
 * in three steps over the batch: the exact gray test, then the energies and
 * the S decision (a plateau on extremum_at()'s slow path), then the points.
 * A candidate passes each test about as often as it fails: one branch per
 * test and candidate would be mispredicted half the time, the batches
 * compact their lists without branches. Speed builds only. */
static SL_ALWAYS_INLINE void decide_batch(lp_ctx *c, uint32_t k, bool along)
{
    const uint32_t dk = c->dk;
    uint16_t *cand = c->cand;
    uint32_t i, kg = 0u, ks = 0u;
#if SL_LP_LANES
    if (c->lanes_row) {
        SL_STAGE(OPERATOR);
        ks = decide_batch_lanes(c, k);
    } else
#endif
    {
#if SL_LP_LANES
        if (c->gray_rest) { /* what the byte test left open */
            /* held in registers across the list's stores (along a row its
             * sides are the row itself) */
            const symline_i_lane_gray lg = c->lg;
            const uint8_t *const r = c->c + dk, *const lo = along ? c->c : c->lo;
            const uint8_t *const hi = (along ? c->c : c->hi) + (size_t)2u * dk;
            for (i = 0; i < k; i++) {
                const uint32_t j = cand[i];
                cand[kg] = (uint16_t)(dk + j);
                kg += symline_i_lane_gray_ok(&lg, r[j], lo[j], hi[j]);
            }
        } else
#endif
        {
            for (i = 0; i < k; i++) {
                const uint32_t j = cand[i];
                cand[kg] = (uint16_t)(dk + j);
                kg += gray_ok(c->f, c->c[dk + j], c->lo[j], c->hi[j + 2u * dk]);
            }
        }
        SL_STAGE(OPERATOR);
#ifdef SYMLINE_PORT_S_ALONG3
        if (along && c->l.m == 3u && c->dk > 3u) {
            /* along a row the batch's candidates lie dk > m entries inside
             * it: the port's lanes keep the S points and the plateaus */
            uint64_t plateau;
            ks = symline_i_s_along3_keep(c->c, cand, kg, &plateau);
            if (plateau != 0u) {
                ks = plateaus(c, ks, plateau, true);
            }
        } else
#endif
        {
            for (i = 0; i < kg; i++) {
                const uint32_t x = cand[i];
                cand[ks] = (uint16_t)x;
                ks += s_point(c, x, along);
            }
        }
    }
    SL_STAGE(FILTER);
    if (c->f->a_distance == 0u && ks != 0u && *c->n + ks <= c->cap) {
        /* the contrast filter, room for all: the S points are the points
         * (ks != 0: storage of capacity 0 may be NULL, and NULL + 0 is
         * undefined) */
        symline_point *const q = c->pts + *c->n;
        for (i = 0; i < ks; i++) {
            q[i].x = cand[i];
            q[i].y = (uint16_t)c->y;
        }
        *c->n += ks;
        return;
    }
    for (i = 0; i < ks; i++) {
        const uint32_t x = cand[i];
        if (c->f->a_distance != 0u) {
            if (!along) {
                c->l.c0 = c->c + x;
            }
            if (!a_near(&c->l, along ? x : c->y, c->f->a_distance)) {
                continue;
            }
        }
        push_point(c, x);
    }
}

/* The line points of grid row y: the byte test over the row's interior
 * (where both sides lie in the row; the whole row down the columns) gives
 * the few candidates, the exact tests follow at those alone. */
static SL_LP_INLINE void decide_row(lp_ctx *c, bool along)
{
    const uint32_t w = c->w, dk = c->dk;
    SL_STAGE(FILTER);
    if (!SL_FOR_SPEED || w <= 2u * dk) {
        /* Every entry with clamped sides: on scalar cores the byte test
         * costs what the exact test's first compares cost, and code. */
        decide_edge(c, c->x0, c->x1, along);
        return;
    }
    {
        /* the interior entries dk + j, j = at .. len-1, of columns x0 .. x1-1 */
        const uint32_t len = c->len;
        const bool paper = c->f->kind == SYMLINE_FILTER_PAPER; /* gray only */
        const uint8_t *ic = c->c + dk, *ilo = paper ? ic : c->lo,
                      *ihi = paper ? ic : c->hi + (size_t)2u * dk;
        const symline_i_prefilter *const pf = &c->pf;
        uint32_t at = c->at;
        /* the left border (down the columns dk = 0: none); the border keeps
         * to columns x0 .. x1-1 itself (asking here would hold two more
         * values across the row: the stack's budget on Cortex-M4) */
        if (along) {
            decide_border(c, pf, true, true);
        }
#if SL_LP_LANES
        /* down the columns: rows y - 4 .. y + 4 held */
        c->lanes_row = c->lanes && !along && c->y >= 4u && c->y + 4u < c->l.n;
#endif
        while (at < len) {
#if SL_LP_CAND_DOWN
            if (c->lanes_row) {
                /* the byte test and the decision in one pass; the rare
                 * plateaus by the run rule */
                uint64_t pl;
                uint32_t k = symline_i_cand_down(pf, &c->lg, ic, ilo, ihi, c->l.step, at, len,
                                                 c->cand, &pl, &at);
                if (pl != 0u) {
                    k = plateaus(c, k, pl, false);
                }
                decide_batch(c, k, along);
                continue;
            }
#endif
            decide_batch(c, symline_i_line_cand(pf, ic, ilo, ihi, at, len, c->cand, &at), along);
        }
        if (along) { /* the right border */
            decide_border(c, pf, false, true);
        }
    }
}

/* The row decision; to save time (SL_FOR_SPEED), one copy per axis. */
SL_NOINLINE static void decide(lp_ctx *c)
{
    const bool along = c->l.step == 1;
    if (SL_FOR_SPEED && along) {
        decide_row(c, true);
    } else if (SL_FOR_SPEED) {
        decide_row(c, false);
    } else {
        decide_row(c, along);
    }
}

/* The columns of each row that keep it below the field boundary, from the
 * first kept rows rows[0 .. w-1] of the pass's grid (c->p: field, w <=
 * 65535, h), where the build optimises for speed: no column keeps a row
 * above c->top, the first and the last column (and so the span between
 * them) those from c->full on, and for the rows between span[y] becomes x0 |
 * x1 << 16, columns x0 .. x1-1 from the first to the last one that keeps
 * row y. The first such column changes only where the minimum of the rows
 * from the left drops, the last one where that from the right drops: each
 * row is written at most twice, in time w + (c->full - c->top);
 * field_columns() reads them. Apart from the collection's loop: its frame
 * is on the deepest call chain. */
SL_NOINLINE static void field_spans(lp_ctx *c, uint32_t *span)
{
    const uint16_t *const rows = c->p->field;
    const uint32_t w = c->p->w, h = c->p->h;
    const uint32_t l0 = rows[0] < h ? rows[0] : h, r0 = rows[w - 1u] < h ? rows[w - 1u] : h;
    uint32_t x, y, m = l0;
    for (x = 1u; x < w; x++) { /* x0 of the rows above l0 (x1 = 0 for now) */
        while (rows[x] < m) {
            span[--m] = x;
        }
    }
    c->top = m;
    c->full = l0 > r0 ? l0 : r0;
    for (m = r0, x = w - 1u; x-- > 0u;) { /* x1 of the rows above r0 */
        while (rows[x] < m) {
            m--;
            span[m] = (m < l0 ? span[m] : 0u) | (x + 1u) << 16;
        }
    }
    for (y = r0; y < l0; y++) { /* from r0 on the last column keeps them */
        span[y] |= w << 16;
    }
}

/* The columns of row y to decide, c->x0 .. c->x1-1: all, or from the first
 * to the last one that keeps row y below the field boundary; from the row's
 * span (field_spans()), or where the build optimises for size by looking for
 * them from either end (in time of the columns left out). Where the build
 * optimises for speed, also the interior entries among them (c->at, c->len:
 * decide_row()). */
static void field_columns(lp_ctx *c, uint32_t y, const uint32_t *span)
{
    const uint16_t *const rows = c->p->field;
    const uint32_t w = c->w, dk = c->dk;
    uint32_t x0 = 0u, x1 = w;
    if (SL_FOR_SPEED && rows != NULL && y < c->full) {
        x0 = y < c->top ? 1u : span[y] & 0xFFFFu;
        x1 = y < c->top ? 0u : span[y] >> 16;
    } else if (!SL_FOR_SPEED && rows != NULL) {
        while (x0 < x1 && rows[x0] > y) {
            x0++;
        }
        while (x1 > x0 && rows[x1 - 1u] > y) {
            x1--;
        }
    }
    c->x0 = x0;
    c->x1 = x1;
    if (SL_FOR_SPEED && w > 2u * dk) {
        c->at = x0 > dk ? x0 - dk : 0u;
        c->len = x1 <= dk ? 0u : x1 < w - dk ? x1 - dk : w - 2u * dk;
    }
}

#if SL_FOR_SPEED_DEEP
/* Row r of the pass's scale into its place in the grid row cache
 * (linepoints.h), c->gray pointing at the scale's rows: from the frame's
 * blocks, or where the pass folds (level 1), with its sums, which make the
 * coarser scales' rows: a level's sums of an even row start a row of the
 * next level, those of the odd row after it finish that row, which then
 * goes on to the level after. acc holds level 2's sums, then each coarser
 * level's. Apart from the row's lookup: its frame stays small. */
SL_NOINLINE static void cache_build(lp_ctx *c, uint32_t r)
{
    const symline_i_pass *p = c->p;
    const uint32_t fold = SL_CACHE_FOLD(p->cache), W = c->img->width, H = c->img->height;
    const size_t stride = c->img->stride;
    uint8_t *const out = c->gray + (size_t)r * p->w;
    const uint16_t *head;
    uint16_t *s;
    uint8_t *rows;
    uint32_t l, j = r >> 1;
    if (fold == 0u) {
        symline_i_grid_row(c->img, p, r, c->acc, out, NULL);
        return;
    }
    head = symline_i_cache_head(c->pts + c->cap);
    rows = c->gray + (size_t)p->w * p->h; /* level 2's */
    if (j >= (H >> 2) || j < head[2]) {   /* below the last row, or its first row was not built */
        symline_i_grid_sums1(c->img->data + (size_t)(2u * r) * stride, stride, p->w, out, NULL,
                             NULL);
        return;
    }
    symline_i_grid_sums1(c->img->data + (size_t)(2u * r) * stride, stride, p->w, out, c->acc,
                         (r & 1u) != 0u ? rows + (size_t)j * (W >> 2) : NULL);
    if ((r & 1u) == 0u) {
        return;
    }
    s = c->acc;
    for (l = 3u; l <= fold; l++) {
        const uint32_t wl = W >> l, i = j >> 1;
        rows += (size_t)(W >> (l - 1u)) * (H >> (l - 1u));
        if (i >= (H >> l) || i < head[l]) {
            break;
        }
        symline_i_grid_fold(s, wl, l, s + (W >> (l - 1u)),
                            (j & 1u) != 0u ? rows + (size_t)i * wl : NULL);
        if ((j & 1u) == 0u) {
            break;
        }
        s += W >> (l - 1u);
        j = i;
    }
}

/* Row y from the grid row cache, the rows up to what the pass reads with it
 * (down the columns: y + reach) built where the cache holds them not yet.
 * The pass's first row built makes the first rows of the coarser scales it
 * folds into: those whose rows below it are all built. */
static const uint8_t *cache_row_at(lp_ctx *c, uint32_t y)
{
    const symline_i_pass *p = c->p;
    const uint32_t h = p->h, R = p->axis == SYMLINE_AXIS_VERTICAL ? 0u : reach(p);
    const uint32_t need = y + R < h ? y + R : h - 1u, first = y > R ? y - R : 0u;
    uint16_t *const head = symline_i_cache_head(c->pts + c->cap);
    const uint32_t held = head[p->level];
    uint32_t r = c->produced > first ? c->produced : first;
    if (r < held && r < c->built) {
        uint32_t l, f = r;
        c->built = r;
        for (l = 2u; l <= SL_CACHE_FOLD(p->cache); l++) {
            f = (f + 1u) / 2u;
            head[l] = (uint16_t)f;
        }
    }
    for (; r <= need && r < held; r++) {
        cache_build(c, r);
    }
    c->produced = need + 1u;
    return c->gray + (size_t)y * p->w;
}
#endif

/* Grid row y of the pass (c->y): the frame's row at full resolution; at a
 * coarse level the grid row, from the grid row cache where the pass has it
 * (linepoints.h), and down the columns the ring's rows up to y + R produced
 * (each written twice, see symline_i_collect()), with rows y - R .. y + R at
 * the ring's stride around the row returned. Apart from the collection's
 * loop: its frame is not on the deepest call chain. */
SL_NOINLINE static const uint8_t *grid_row_at(lp_ctx *c, uint32_t y)
{
    const symline_i_pass *p = c->p;
    const uint32_t w = p->w, h = p->h;
    if (p->level == 0u) {
        return c->img->data + (size_t)y * c->img->stride;
    }
    SL_STAGE(GRID);
#if SL_FOR_SPEED_DEEP
    if (p->cache != SL_CACHE_OFF) {
        return cache_row_at(c, y);
    }
#endif
    if (p->axis == SYMLINE_AXIS_VERTICAL) {
        symline_i_grid_row(c->img, p, y, c->acc, c->gray, NULL);
        return c->gray;
    } else {
        const uint32_t R = reach(p), held = ring_rows(p);
        const uint32_t need = y + R < h ? y + R : h - 1u, first = y > R ? y - R : 0u;
        /* (the first row decided may lie below the first row: symline_i_collect()) */
        for (c->produced = c->produced > first ? c->produced : first; c->produced <= need;
             c->produced++) {
            uint8_t *g = c->gray + (size_t)(c->produced % held) * w;
            symline_i_grid_row(c->img, p, c->produced, c->acc, g, g + (size_t)held * w);
        }
        /* Rows first .. need from the slot of row first on. */
        return c->gray + (size_t)(first % held + (y - first)) * w;
    }
}

size_t symline_i_collect_ws_size(const symline_i_pass *p, uint32_t img_width)
{
    size_t n = (size_t)3u * SL_ALIGN + symline_i_align_up(sizeof(lp_ctx));
    if (p->level > 0u) {
        n += symline_i_align_up((size_t)img_width * sizeof(uint16_t)); /* box accumulator */
        /* the grid row, or the ring of them down the columns */
        n += symline_i_align_up((size_t)p->w *
                                (p->axis == SYMLINE_AXIS_VERTICAL ? 1u : 2u * ring_rows(p)));
    }
    return n;
}

symline_status symline_i_collect(const symline_image *img, const symline_i_pass *p, void *ws,
                                 size_t ws_size, symline_point *pts, uint32_t cap, uint32_t *n,
                                 uint32_t *row_start, uint32_t *dropped)
{
    uint8_t *cur = (uint8_t *)ws;
    uint8_t *const end = cur + ws_size;
    const uint32_t h = p->h;
    const bool along = p->axis == SYMLINE_AXIS_VERTICAL;
    lp_ctx *c = (lp_ctx *)symline_i_carve(&cur, end, sizeof(lp_ctx));
    uint32_t y, full;
    bool none;
    *n = 0u;
    if (p->w == 0u || h == 0u) {
        return SYMLINE_ERR_SIZE;
    }
    if (c == NULL) {
        return SYMLINE_ERR_BUFFER;
    }
    c->acc = NULL;
    c->gray = NULL;
    if (p->level > 0u) { /* else the frame's rows are read */
        /* The box accumulator serves the lane loops alone (SL_FOR_SPEED); its
         * room stays in the workspace size either way. */
        if (SL_FOR_SPEED) {
            c->acc = (uint16_t *)symline_i_carve(&cur, end, (size_t)img->width * sizeof(uint16_t));
        }
        /* Down the columns each grid row twice, in slots r % held and
         * r % held + held: any held rows in a row lie one after the other. */
        c->gray =
            (uint8_t *)symline_i_carve(&cur, end, (size_t)p->w * (along ? 1u : 2u * ring_rows(p)));
        if (c->gray == NULL || (SL_FOR_SPEED && c->acc == NULL)) {
            return SYMLINE_ERR_BUFFER;
        }
    }
    c->img = img;
    c->p = p;
    c->produced = 0u;
#if SL_FOR_SPEED_DEEP
    c->built = h;
    if (p->cache != SL_CACHE_OFF) { /* the scale's rows in the cache instead of the ring */
        c->gray = symline_i_cache_rows(pts + cap, img->width, img->height, p->level,
                                       SL_CACHE_TOP(p->cache));
    }
#endif
    c->f = &p->filter;
    c->pts = pts;
    c->n = n;
    c->dropped = dropped;
    c->cap = cap;
    c->w = p->w;
    c->dk = along ? p->k : 0u;
    c->l.n = along ? p->w : h;
    c->l.m = p->m;
    c->l.lag = p->lag;
    c->l.i0 = 0u;
    c->l.step = along ? 1 : (ptrdiff_t)(p->level == 0u ? img->stride : p->w);
    if (SL_FOR_SPEED) { /* the size builds have no byte test */
        symline_i_prefilter_setup(c->f, &c->pf);
    }
#if SL_LP_LANES
    /* the byte test and the rest of the gray test; the blocks of lanes at
     * m = 3 (k = 4), in a row that holds one */
    c->gray_rest = lane_gray_setup(c->f, &c->lg);
    c->lanes = c->gray_rest && p->m == 3u && p->k == 4u && c->w >= 2u * c->dk + SL_LP_LANES;
#endif
    if (SL_FOR_SPEED) {
        c->top = 0u;
        c->full = 0u;
        if (p->field != NULL) {
            field_spans(c, row_start);
        }
    }
    full = SL_FOR_SPEED ? c->full : 0u;
    for (y = 0, none = false; y < h; y++) {
        const uint8_t *row;
        /* (where the build optimises for speed the columns stay all of them
         * from the row below the spans on) */
        if (!SL_FOR_SPEED || y <= full) {
            field_columns(c, y, row_start);
            none = c->x0 >= c->x1;
        }
        row_start[y] = *n;
        if (none) {
            continue; /* above the field in every column */
        }
        /* (the frame's rows without a call on 64-bit speed builds: on the
         * firmware's the call keeps this frame smaller) */
        row = SL_FOR_SPEED_DEEP && p->level == 0u ? img->data + (size_t)y * img->stride
                                                  : grid_row_at(c, y);
        c->c = row;
        c->lo = row;
        c->hi = row;
        c->l.c0 = row;
        if (!along) {
            const ptrdiff_t st = c->l.step;
            c->lo = row - (ptrdiff_t)(y >= p->k ? p->k : y) * st;
            c->hi = row + (ptrdiff_t)(y + p->k < h ? p->k : h - 1u - y) * st;
            c->l.i0 = y;
        }
        c->y = y;
        decide(c);
    }
    row_start[h] = *n;
#if SL_FOR_SPEED_DEEP
    if (c->built < h) { /* rows built .. h-1 are held now */
        symline_i_cache_head(pts + cap)[p->level] = (uint16_t)c->built;
    }
#endif
    return SYMLINE_OK;
}

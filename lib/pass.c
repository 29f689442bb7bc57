/* SPDX-License-Identifier: Apache-2.0 */
/*
 * One pass (an axis at one scale) of the detector. It collects its line
 * points into the caller's point storage (raster order, strip processing),
 * traces them from the storage's free tail, turns the chains into segments
 * (cut at corners, the line filter's whole-piece side test, fit) and
 * compacts the points it keeps down to where the pass began. Parts of a
 * chain that an earlier pass (finer scale, or the horizontal axis at the same
 * scale) already reported are left out, so one physical line is reported once.
 */
#include "pass.h"

#include "fieldboundary.h"

#include "fixed.h"
#include "segments.h"
#include "stagemark.h"
#include "subpixel.h"
#include "tracer.h"
#include "linecheck.h"
#include "passplan.h"

/* The bend test (symline_i_bend_check) runs on pieces at least this long (px) at
 * the finest scales only: coarser grids step by 4 px and more. */
#define SL_BEND_MIN_PX 16u
#define SL_BEND_MAX_LEVEL 1u
/* Fewest points of a reported piece at any scale: three coarse blocks in a row
 * are a blob's rim as often as a line. */
#define SL_MIN_PIECE_POINTS 4u

/* The fixed part of SYMLINE_DETECT_WORKSPACE_SIZE() (detect.h) holds, besides
 * alignment and the collection's bookkeeping (linepoints.c), a pass's state
 * and the tracer's: they must stay within these budgets on every target. */
typedef char symline_i_pass_state_fits_ws_budget
    [(sizeof(symline_i_pass) <= 96u && sizeof(symline_i_tracer) <= 64u) ? 1 : -1];

void symline_i_pass_setup(symline_i_pass *p, const symline_config *cfg, symline_axis axis,
                          uint32_t level, uint32_t width, uint32_t height)
{
    p->axis = axis;
    p->level = level;
    p->w = width >> level;
    p->h = height >> level;
    p->m = cfg->radius;
    p->k = cfg->radius + 1u;
    p->lag = cfg->radius;
    if (SL_FOR_SPEED_DEEP) { /* read nowhere else (no code in the firmware) */
        p->cache = SL_CACHE_OFF;
    }
    p->field = NULL;
    symline_i_linefilter_setup(&p->filter, cfg);
}

/* Point i of the storage; NULL for storage that is NULL (capacity 0, which
 * detect.h allows): NULL + 0 is undefined behaviour in C. */
static symline_point *point_at(const symline_result *r, uint32_t i)
{
    return r->points != NULL ? r->points + i : NULL;
}

/* Asks the grid of earlier segments (segindex.h), which tests the few
 * segments near the point instead of every one. */
static bool covered(const symline_i_run *d, symline_i_segindex *ix, const symline_point *q,
                    uint32_t level)
{
    const int32_t x = symline_i_q8(q->x, level), y = symline_i_q8(q->y, level);
    return symline_i_segindex_near(ix, d->r, d->prev_seg, x, y, symline_i_cover_tol_q8(level));
}

/* Whether a piece of n points at the pass's level is long enough to report. */
static bool piece_long_enough(const symline_i_run *d, const symline_i_pass *p, uint32_t n)
{
    return (n << p->level) >= d->cfg->min_length && n >= SL_MIN_PIECE_POINTS;
}

/* One piece of a chain (grid coordinates, absolute storage index `at`). */
static void emit(symline_i_run *d, const symline_i_pass *p, uint32_t at, uint32_t n)
{
    symline_point *q = d->r->points + at;
    symline_segment *s;
    if (!piece_long_enough(d, p, n)) {
        return;
    }
    if (d->field_rows != NULL &&
        symline_i_linecheck_too_wide(d->field_rows, p->level, p->h, q, n)) {
        return;
    }
    if (p->filter.kind == SYMLINE_FILTER_CONTRAST && p->filter.asym_pct != 0u &&
        symline_i_linefilter_piece_fails(&p->filter, d->img, p->axis, p->level, p->k, q, n)) {
        return;
    }
    if (d->nseg >= d->r->segment_cap) {
        d->truncated = true;
        return;
    }
    s = &d->r->segments[d->nseg++];
    SL_STAGE(SUBPIXEL);
    symline_i_subpixel(d->img, p, q, n);
    SL_STAGE(SEGMENTS);
    symline_i_fit(q, n, p->level, d->cfg->curve_dev_q8, s);
    /* A flat arc stays under the deviation threshold but bends: a curve too. */
    if (s->kind == SYMLINE_KIND_LINE && d->cfg->curve_bend_q8 != 0u &&
        p->level <= SL_BEND_MAX_LEVEL && (n << p->level) >= SL_BEND_MIN_PX) {
        symline_i_bend_check(q, n, p->level, d->cfg->curve_bend_q8, s);
    }
    s->axis = (uint8_t)p->axis;
    s->first = at;
    s->count = n;
}

/* The first of the chain's points q[0..e-q-1] that an earlier segment
 * covers (cov true) or does not (false); e if none. A point in a cell the
 * grid lists nothing in is not covered, without asking: a cell's points have
 * grid coordinates (x >> sh, y >> sh) (inside the frame, at levels up to
 * SL_CELL_SHIFT: a block never straddles a cell), and the last such cell is
 * remembered, as a chain steps a grid pixel at a time (in one call of the
 * grid's own, symline_i_segindex_scan()). The first pass has no earlier
 * segment at all. Only where the build optimises for speed
 * (chain()); apart from it so that its frame is not under the fit's. */
SL_NOINLINE static const symline_point *next_point(const symline_i_run *d, uint32_t level,
                                                   symline_i_segindex *ix, const symline_point *q,
                                                   const symline_point *e, bool cov)
{
    if (ix == NULL || ix->cols == 0u || ix->indexed != d->prev_seg || level > SL_CELL_SHIFT) {
        while (q < e && covered(d, ix, q, level) != cov) {
            q++;
        }
        return q;
    }
    if (d->prev_seg == 0u) {
        return cov ? e : q;
    }
    return symline_i_segindex_scan(ix, d->r, d->prev_seg, q, e, level,
                                   symline_i_cover_tol_q8(level), cov);
}

/* The earlier passes' segments on a grid, so that testing a chain point
 * against them looks at one cell instead of all of them (time linear in the
 * frame, not quadratic, on cluttered frames). The ids go to the workspace
 * or, when larger, to the point storage beyond what the tracing can write
 * (at most n points after the raster list). */
static SL_ALWAYS_INLINE void index_fill(const symline_i_run *d, const symline_i_pass *p,
                                        symline_i_segindex *ix, uint8_t *ws, size_t ws_bytes,
                                        uint32_t n)
{
    const uint64_t used = (uint64_t)d->npts + 2u * (uint64_t)n;
    symline_point *spare = used < d->r->point_cap ? d->r->points + (size_t)used : NULL;
    size_t spare_bytes =
        spare != NULL ? (size_t)(d->r->point_cap - used) * sizeof(symline_point) : 0u;
    if (SL_FOR_SPEED_DEEP && p->cache != SL_CACHE_OFF) {
        /* not into the grid row cache: it lies above twice the pass's grid
         * in points (n <= w h) */
        spare_bytes -= (size_t)symline_i_cache_bytes(d->img->width, d->img->height, p->level,
                                                     SL_CACHE_TOP(p->cache));
    }
    SL_STAGE(SEGMENTS); /* it serves the overlap test with earlier passes */
    if (ix != NULL) {
        symline_i_segindex_build(ix, ws, ws_bytes, spare, spare_bytes, d->img->width,
                                 d->img->height, d->r, d->prev_seg,
                                 symline_i_cover_tol_q8(p->level));
    }
}

/* An index not built yet (SL_FOR_SPEED_DEEP, symline_i_segindex.hit): it is
 * built at the pass's first chain long enough to report (chain()), so a
 * pass without one (on several field frames the vertical axis at full
 * resolution) never builds it. Until then its cols hold the pass's points n
 * and its rows the bytes of its workspace, which follows it. */
#define SL_INDEX_PENDING 0xFFFFFFFEu

/* A traced chain at storage index `at`: drop covered parts, cut at corners, emit pieces. */
static void chain(symline_i_run *d, const symline_i_pass *p, symline_i_segindex *ix, uint32_t at,
                  uint32_t n)
{
    const symline_point *c = d->r->points + at;
    uint32_t i, s, from = 0u;
    /* Every piece is part of the chain: a chain too short to be emitted
     * (most of them: two or three points of turf) needs no per-point test. */
    if (!piece_long_enough(d, p, n)) {
        return;
    }
    if (SL_FOR_SPEED_DEEP && ix != NULL && ix->hit == SL_INDEX_PENDING) {
        /* the first chain of the pass that may report: the index now */
        index_fill(d, p, ix, (uint8_t *)(ix + 1), ix->rows, ix->cols);
    }
    if (SL_FOR_SPEED && ix != NULL) {
        ix->hit = SL_NO_HIT; /* another chain: the last one's entry is not a better guess */
    }
    for (i = 0; i <= n; i++) {
        /* The uncovered runs [from, i), each cut at its corners. Where the
         * build optimises for speed, a run's first point and its end found
         * by next_point(). */
        if (SL_FOR_SPEED) {
            from = (uint32_t)(next_point(d, p->level, ix, c + from, c + n, false) - c);
            i = (uint32_t)(next_point(d, p->level, ix, c + from, c + n, true) - c);
        } else if (i < n && !covered(d, ix, &c[i], p->level)) {
            continue;
        }
        for (s = from; s < i;) {
            const uint32_t len = symline_i_corner_cut(c + s, i - s);
            emit(d, p, at + s, len);
            s += len;
        }
        from = i + 1u;
    }
}

/* a + b, at most UINT32_MAX (32-bit only: cheap on a Cortex-M0). */
static uint32_t sat_add(uint32_t a, uint32_t b)
{
    return a > 0xFFFFFFFFu - b ? 0xFFFFFFFFu : a + b;
}

/* symline_result.points_needed grows to at least need. */
SL_NOINLINE static void note_need(symline_result *r, uint32_t need)
{
    if (need > r->points_needed) {
        r->points_needed = need;
    }
}

/* The raster list of n stored and `dropped` lost points after the kept ones.
 * A call of its own keeps the collection's frame as small as it was. */
SL_NOINLINE static void note_listed(symline_i_run *d, uint32_t n, uint32_t dropped)
{
    note_need(d->r, sat_add(sat_add(d->npts, n), dropped));
}

/* Keeps only the points segments [first_seg, nseg) use, right after the
 * earlier ones (from index w), as full-resolution points; returns the end.
 * Apart from trace() so that its frame is not under the fit's. */
SL_NOINLINE static uint32_t keep_points(symline_result *r, uint32_t first_seg, uint32_t nseg,
                                        uint32_t w, uint32_t level)
{
    /* Where the build optimises for speed, each point is converted as it is
     * copied: its Q7 full-resolution coordinate u 2^level + (2^level - 1) 64
     * (u = 128 x + fx, fixed.h) plus 64 is never negative (fx >= -64) and
     * below 2^32, so 32-bit unsigned arithmetic gives it exactly; its pixel
     * is that over 128, its remainder the low 7 bits less 64 (as
     * symline_i_pt_to_full() rounds). */
    const uint32_t add = (((1u << level) - 1u) << 6) + 64u;
    uint32_t k;
    for (k = first_seg; k < nseg; k++) {
        symline_segment *s = &r->segments[k];
        /* w <= s->first: a forward copy. */
        if (SL_FOR_SPEED) {
            /* Walked by pointer: no index arithmetic per point. */
            const symline_point *q = r->points + s->first, *const e = q + s->count;
            symline_point *o = r->points + w;
            for (; q != e; q++, o++) {
                const uint32_t vx =
                    ((((uint32_t)q->x << 7) + (uint32_t)(int32_t)q->fx) << level) + add;
                const uint32_t vy =
                    ((((uint32_t)q->y << 7) + (uint32_t)(int32_t)q->fy) << level) + add;
                o->x = (uint16_t)(vx >> 7);
                o->y = (uint16_t)(vy >> 7);
                o->fx = (int8_t)((int32_t)(vx & 127u) - 64);
                o->fy = (int8_t)((int32_t)(vy & 127u) - 64);
            }
        } else {
            symline_point *const q = r->points + s->first, *const o = r->points + w;
            uint32_t i;
            for (i = 0; i < s->count; i++) {
                /* Converted in place (read only once), then copied field by
                 * field: a struct copy may become a libc memcpy call. */
                symline_i_pt_to_full(&q[i], level);
                o[i].x = q[i].x;
                o[i].y = q[i].y;
                o[i].fx = q[i].fx;
                o[i].fy = q[i].fy;
            }
        }
        s->first = w;
        w += s->count;
    }
    return w;
}

/* Traces the pass's raster list (n points at d->npts) and keeps its
 * segments' points right after the earlier passes' ones. t: the tracer's
 * state, in the pass workspace. Apart from symline_i_pass_run() so that its frame
 * and the line point collection's are never on the stack together. */
SL_NOINLINE static void trace(symline_i_run *d, const symline_i_pass *p, const uint32_t *row_start,
                              uint32_t n, symline_i_tracer *t, symline_i_segindex *ix)
{
    symline_result *r = d->r;
    const uint32_t base = d->npts;
    const uint32_t first_seg = d->nseg;
    uint32_t tail = base + n, cnt;
    bool cut = false;
    /* Chains go to the storage's free tail after the raster list (storage
     * with room is not NULL). */
    symline_i_tracer_init(t, point_at(r, base), n, row_start, p->h);
    SL_STAGE(TRACE);
    while (tail < r->point_cap &&
           symline_i_tracer_next(t, r->points + tail, r->point_cap - tail, &cnt, &cut)) {
        SL_STAGE(SEGMENTS);
        chain(d, p, ix, tail, cnt);
        tail += cnt;
        SL_STAGE(TRACE);
    }
    SL_STAGE(SEGMENTS);
    if (cut || (tail >= r->point_cap && n > 0u)) {
        cut = true; /* or the storage ran out */
        d->truncated = true;
    }
    /* Storage this pass needed: the raster list and the chains after the kept
     * points, plus one free entry that shows the tracer nothing is left
     * (tail < point_cap then). When it ran out, at most every line point is
     * in a chain: base + 2 * all. */
    if (row_start[p->h + 1u] != 0u || cut) {
        const uint32_t all = sat_add(n, row_start[p->h + 1u]);
        note_need(r, sat_add(sat_add(base, sat_add(all, all)), 1u));
    } else {
        note_need(r, n == 0u ? base : tail + 1u);
    }
    d->npts = keep_points(r, first_seg, d->nseg, base, p->level);
    d->prev_seg = d->nseg;
}

/* Whether the field boundary lies more than the margin below the frame's
 * top anywhere; else every grid row lies below it in every column (between
 * two vertices the boundary lies no lower than the lower one). */
static bool field_below_top(const symline_i_run *d)
{
    const symline_field_boundary *const b = &d->r->field;
    uint32_t i;
    for (i = 0; i < b->count; i++) {
        if (b->v[i].y > (int32_t)d->cfg->field_margin) {
            return true;
        }
    }
    return false;
}

/* Whether `bytes` fit above the first n points of a storage of cap points
 * (SL_FOR_SPEED_DEEP: 64-bit sizes). */
static bool cache_fits(uint64_t n, uint64_t cap, uint64_t bytes)
{
    return n * sizeof(symline_point) + bytes <= cap * sizeof(symline_point);
}

/* The grid row cache for a pass (linepoints.h), SL_FOR_SPEED_DEEP: where
 * the storage has the room for the pass's points and the cache of its scale
 * and the coarser ones, the cache that earlier passes filled, or, at the
 * first axis of a scale, a new one (its head: no rows held yet), which the
 * pass at level 1 fills for the coarser scales as well. Where the room is
 * short the cache ends: the rows it held may be overwritten. */
static uint32_t cache_plan(symline_i_run *d, const symline_i_pass *p)
{
    const uint32_t W = d->img->width, H = d->img->height;
    const uint32_t top = symline_i_level_count(d->cfg, W, H) - 1u;
    uint16_t *head;
    uint32_t l;
    if (p->level == 0u ||
        !cache_fits((uint64_t)d->npts + 2u * (uint64_t)p->w * p->h, d->r->point_cap,
                    symline_i_cache_bytes(W, H, p->level, top))) {
        d->cache_top = 0u;
        return SL_CACHE_OFF;
    }
    if (d->cache_top != 0u) {
        return top;
    }
    if (p->axis != symline_i_axis_of(d->cfg, 0u)) {
        return SL_CACHE_OFF; /* the scale's first pass had no cache: rows unknown */
    }
    d->cache_top = (uint8_t)top;
    head = symline_i_cache_head(d->r->points + d->r->point_cap);
    for (l = p->level; l <= top; l++) {
        head[l] = (uint16_t)(H >> l);
    }
    return p->level == 1u && top >= 2u
               ? top | (top < SL_CACHE_FOLD_MAX ? top : SL_CACHE_FOLD_MAX) << 4
               : top;
}

/* The pass's raster list into the free part of the point storage (after
 * d->npts), *n points; row_start[p->h + 1] counts those that did not fit. Apart from
 * symline_i_pass_run() so that the collection's call and the tracing's are never on
 * the stack together. */
SL_NOINLINE static symline_status collect(symline_i_run *d, symline_i_pass *p, uint8_t *ws,
                                          const uint8_t *end, uint32_t *row_start, uint32_t *n)
{
    symline_point *const pts = point_at(d->r, d->npts);
    symline_status st;
    if (d->field_rows != NULL) {
        /* Above the field: nothing to trace, and in each row only the
         * columns from the first to the last one whose field has begun are
         * decided. */
        SL_STAGE(FIELD);
        if (!SL_FOR_SPEED || p->axis == SYMLINE_AXIS_HORIZONTAL ||
            d->cfg->axes != SYMLINE_AXES_BOTH) {
            /* The rows depend on the level alone: to save time (SL_FOR_SPEED),
             * once per level (horizontal first). */
            symline_i_field_rows(&d->r->field, p->level, p->w, d->img->width, d->cfg->field_margin,
                                 d->field_rows);
        }
        /* (where the build optimises for speed, not where every column keeps
         * every row) */
        p->field = (!SL_FOR_SPEED || field_below_top(d)) ? d->field_rows : NULL;
    }
    if (SL_FOR_SPEED_DEEP) {
        p->cache = cache_plan(d, p);
    }
#if SL_FOR_SPEED_DEEP
    p->cache_end = point_at(d->r, d->r->point_cap); /* (read only with a cache) */
#endif
    st = symline_i_collect(d->img, p, ws, (size_t)(end - ws), pts, d->r->point_cap - d->npts, n,
                           row_start, &row_start[p->h + 1u]);
    if (row_start[p->h + 1u] != 0u) {
        d->truncated = true;
    }
    /* The raster list needs its room (all of it, stored or not) before the
     * field boundary thins it. */
    note_listed(d, *n, row_start[p->h + 1u]);
    if (st == SYMLINE_OK && d->field_rows != NULL) {
        SL_STAGE(FIELD);
        *n = symline_i_field_drop(d->field_rows, p->w, pts, row_start, p->h);
    }
    return st;
}

/* The grid's place after the tracer's state, and its build or (where the
 * build optimises for speed on a 64-bit core) what the build needs. */
SL_NOINLINE static symline_i_segindex *index_earlier(const symline_i_run *d,
                                                     const symline_i_pass *p, uint8_t *ws,
                                                     uint8_t *end, uint32_t n)
{
    symline_i_segindex *ix =
        (symline_i_segindex *)symline_i_carve(&ws, end, sizeof(symline_i_segindex));
    if (SL_FOR_SPEED_DEEP && ix != NULL) {
        /* (the index takes far less than 4 GiB: no more is said) */
        const size_t bytes = (size_t)(end - ws);
        ix->hit = SL_INDEX_PENDING;
        ix->cols = n;
        ix->rows = bytes < 0xFFFFFFFFu ? (uint32_t)bytes : 0xFFFFFFFFu;
        return ix;
    }
    index_fill(d, p, ix, ws, (size_t)(end - ws), n);
    return ix;
}

symline_status symline_i_pass_run(symline_i_run *d, symline_i_pass *p, uint8_t *ws, uint8_t *end)
{
    uint8_t *rest = ws;
    /* The row index (h + 1 entries), then the count of line points that did not fit. */
    uint32_t *row_start =
        (uint32_t *)symline_i_carve(&rest, end, ((size_t)p->h + 2u) * sizeof(uint32_t));
    uint32_t n = 0u;
    symline_i_tracer *t;
    symline_status st;
    if (row_start == NULL) {
        return SYMLINE_ERR_BUFFER;
    }
    row_start[p->h + 1u] = 0u;
    st = collect(d, p, rest, end, row_start, &n);
    if (st != SYMLINE_OK) {
        return st;
    }
    /* The collection's rings are free again: the tracer's state and the grid
     * of earlier segments take their place. */
    t = (symline_i_tracer *)symline_i_carve(&rest, end, sizeof(symline_i_tracer));
    if (t == NULL) {
        return SYMLINE_ERR_BUFFER;
    }
    /* A grid that does not fit (not reached: the workspace size was
     * checked) is NULL: every earlier segment is then tested. */
    trace(d, p, row_start, n, t, index_earlier(d, p, rest, end, n));
    return SYMLINE_OK;
}

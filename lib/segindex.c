/* SPDX-License-Identifier: Apache-2.0 */
/*
 * The grid of earlier segments (segindex.h). Built once per pass in two
 * sweeps over the segments: count the cells each one touches, then enter its
 * id (a line) or its runs of pieces (a curve); cells hold their entries in
 * one array (compressed rows), so the grid needs 4 bytes per cell and 4 per
 * entry (8 per curve run) and nothing else. A cell the previous piece of the
 * same line touched is skipped. Where the build optimises for speed on
 * 64-bit targets, the count keeps the cells it visits in the unused end of
 * the id area, and the fill enters the ids from that list instead of walking
 * the segments again (as far as the list stays clear of the ids).
 *
 * A point near a chord lies within tol of one of the chord's pieces of at
 * most one cell's length, hence inside that piece's bounding box grown by
 * tol; every cell such a box touches lists the segment. symline_i_near_segment()
 * coarsens long chords before its exact test (up to about length / 4096 of
 * slack), so the boxes grow by length / 1024 + 1 px more than tol.
 */
#include "segindex.h"

#include "common.h"
#include "fixed.h"
#include "segments.h"

uint32_t symline_i_grid_dims(uint32_t width, uint32_t height, uint32_t *cols, uint32_t *rows)
{
    *cols = ((width - 1u) >> SL_CELL_SHIFT) + 1u;
    *rows = ((height - 1u) >> SL_CELL_SHIFT) + 1u;
    return *cols * *rows;
}

size_t symline_i_segindex_ws_size(uint32_t width, uint32_t height)
{
    uint32_t cols, rows;
    const size_t cells = symline_i_grid_dims(width, height, &cols, &rows);
    return symline_i_align_up(cells * sizeof(uint32_t)) + SL_ALIGN +
           symline_i_align_up(cells * SL_IDS_PER_CELL * sizeof(uint32_t));
}

/* The cell (column or row) of a Q8 coordinate, clamped to 0 .. n-1. */
static uint32_t cell_of(int32_t v_q8, uint32_t n)
{
    uint32_t c;
    if (v_q8 < 0) {
        return 0u;
    }
    c = ((uint32_t)v_q8 >> 8) >> SL_CELL_SHIFT;
    return c < n ? c : n - 1u;
}

static void visit_cell(symline_i_cellwalk *w, uint32_t c)
{
    uint32_t node;
    /* if/else rather than a switch: no jump table helper on small cores. */
    if (w->mode == SL_WALK_COUNT) {
        w->end[c] += w->width * w->sign;
        w->added += w->width;
#if SL_FOR_SPEED_DEEP
        if (w->sign == 1u) {
            if (w->kept < w->cell_cap) {
                w->cells[-1 - (ptrdiff_t)w->kept++] = c;
            } else {
                w->full = true;
            }
        }
#endif
    } else if (w->mode == SL_WALK_FILL) {
        w->ids[w->end[c]++] = w->seg;
        if (w->width == 2u) {
            w->ids[w->end[c]++] = w->piece_end;
        }
    } else {
        for (node = w->head[c]; node != 0xFFFFFFFFu && w->n <= w->cand_cap; node = w->next[node]) {
            if (w->n < w->cand_cap) {
                w->cand[w->n] = node >> 1;
            }
            w->n++;
        }
    }
}

uint32_t symline_i_cell_at(uint32_t cols, uint32_t rows, int32_t x_q8, int32_t y_q8)
{
    return cell_of(y_q8, rows) * cols + cell_of(x_q8, cols);
}

/* The cells c[0] .. c[1] (of n) within margin of the span from p to q. */
static void cell_span(int32_t p, int32_t q, int32_t margin, uint32_t n, uint32_t c[2])
{
    c[0] = cell_of((p < q ? p : q) - margin, n);
    c[1] = cell_of((p > q ? p : q) + margin, n);
}

/* a + d k / 2^sh, d's magnitude rounded down, in 32 bits: |d| < 2^26 and
 * k <= 2^sh <= 2^13 keep both products below 2^26. k = 2^sh: exactly a + d. */
SL_NOINLINE static int32_t split_at(int32_t a, int32_t d, uint32_t k, uint32_t sh)
{
    const uint32_t u = (uint32_t)(d < 0 ? -d : d);
    const int32_t o = (int32_t)((u >> sh) * k + (((u & ((1u << sh) - 1u)) * k) >> sh));
    return d < 0 ? a - o : a + o;
}

void symline_i_cellwalk_chord(symline_i_cellwalk *w, int32_t ax, int32_t ay, int32_t bx, int32_t by,
                              int32_t margin)
{
    const int32_t dx = bx - ax, dy = by - ay;
    const uint32_t ux = (uint32_t)(dx < 0 ? -dx : dx), uy = (uint32_t)(dy < 0 ? -dy : dy);
    const uint32_t len = ux > uy ? ux : uy;
    /* The previous piece's cells: none before the first. */
    uint32_t sh = 0u, k, px0 = 1u, px1 = 0u, py0 = 0u, py1 = 0u;
    int32_t px = ax, py = ay;
    margin += (int32_t)((len + (uint32_t)margin) >> 10) + (int32_t)SL_PX_Q8(1u);
    while ((len >> sh) > (SL_PX_Q8(1u) << SL_CELL_SHIFT)) {
        sh++;
    }
    /* 2^sh pieces of at most a cell; any split of the chord covers it. */
    for (k = 1u; k <= (1u << sh); k++) {
        /* The last piece ends at b (a short chord is one piece): split_at()
         * puts it there, where speed counts without the calls. */
        const bool last = SL_FOR_SPEED && k == 1u << sh;
        const int32_t qx = last ? bx : split_at(ax, dx, k, sh);
        const int32_t qy = last ? by : split_at(ay, dy, k, sh);
        uint32_t cx[2], cy[2], x, y;
        cell_span(px, qx, margin, w->cols, cx);
        cell_span(py, qy, margin, w->rows, cy);
        for (y = cy[0]; y <= cy[1]; y++) {
            for (x = cx[0]; x <= cx[1]; x++) {
                if (x < px0 || x > px1 || y < py0 || y > py1) {
                    visit_cell(w, y * w->cols + x);
                }
            }
        }
        px0 = cx[0];
        px1 = cx[1];
        py0 = cy[0];
        py1 = cy[1];
        px = qx;
        py = qy;
    }
}

#if SL_FOR_SPEED_DEEP
/* The count's end of an entry whose cells are kept from item `from` on: its
 * last cell marked or, when they did not all fit, none of them kept and no
 * later entry's either (the fill walks those). */
static void entry_counted(symline_i_cellwalk *w, uint32_t from)
{
    if (w->mode != SL_WALK_COUNT || w->sign != 1u) {
        return;
    }
    if (w->full) {
        w->kept = from;
        w->cell_cap = from;
    } else if (w->kept > from) {
        w->cells[-(ptrdiff_t)w->kept] |= SL_PIECE;
    }
}

/* The fill of the next entry from the cells the count kept, in the order
 * the count visited them (the fill visits the same entries in the same
 * order); false when they were not kept. */
static bool entry_filled(symline_i_cellwalk *w)
{
    uint32_t c;
    if (w->mode != SL_WALK_FILL || w->used >= w->kept) {
        return false;
    }
    do {
        uint32_t *e;
        c = w->cells[-1 - (ptrdiff_t)w->used++];
        /* visit_cell()'s fill, here without its mode tests. */
        e = &w->end[c & ~SL_PIECE];
        w->ids[(*e)++] = w->seg;
        if (w->width == 2u) {
            w->ids[(*e)++] = w->piece_end;
        }
    } while ((c & SL_PIECE) == 0u);
    return true;
}
#endif

/* Points of a curve's polyline in one grid entry (a run): where the build
 * optimises for speed, four of its pieces, which makes fewer entries to
 * enter and to list while a cell still asks only the runs near it; else
 * one piece (the smaller code). */
#define SL_RUN_POINTS (SL_FOR_SPEED ? SL_POLY_STEP * 4u : SL_POLY_STEP)

/* Every cell within margin of the box x0..x1, y0..y1 (whole pixels), plus
 * the rounding slack of symline_i_cellwalk_chord() for a chord as long as
 * the box is wide: a run's cells (speed builds). */
static void visit_box(symline_i_cellwalk *w, uint32_t x0, uint32_t y0, uint32_t x1, uint32_t y1)
{
    const uint32_t ext = (x1 - x0 > y1 - y0 ? x1 - x0 : y1 - y0) << 8;
    const int32_t margin =
        w->margin + (int32_t)((ext + (uint32_t)w->margin) >> 10) + (int32_t)SL_PX_Q8(1u);
    uint32_t cx[2], cy[2], x, y;
    cell_span((int32_t)(x0 << 8), (int32_t)(x1 << 8), margin, w->cols, cx);
    cell_span((int32_t)(y0 << 8), (int32_t)(y1 << 8), margin, w->rows, cy);
    for (y = cy[0]; y <= cy[1]; y++) {
        for (x = cx[0]; x <= cx[1]; x++) {
            visit_cell(w, y * w->cols + x);
        }
    }
}

/* Every piece symline_i_near_segment() tests for segment id: a line as its
 * id, a curve run by run (the pieces of its polyline from an entry's first
 * point to its last; a cell then asks only the runs near it, not a long
 * curve along its whole length), each run in every cell it touches: a
 * piece's by its chord, a longer run's by the box of its pieces' ends (which
 * holds its pieces). Point indices from 2^31 on (16 GiB of points) list
 * the curve whole. */
static void visit_segment(symline_i_cellwalk *v, const symline_result *r, uint32_t id)
{
    const symline_segment *s = &r->segments[id];
    const symline_point *p = r->points + s->first;
    uint32_t i;
    v->seg = id;
    v->width = 1u;
    if (s->kind == SYMLINE_KIND_LINE || s->count < 2u || s->first + s->count >= SL_PIECE) {
#if SL_FOR_SPEED_DEEP
        const uint32_t from = v->kept;
        if (entry_filled(v)) {
            return;
        }
#endif
        symline_i_cellwalk_chord(v, s->x0, s->y0, s->x1, s->y1, v->margin);
#if SL_FOR_SPEED_DEEP
        entry_counted(v, from);
#endif
        return;
    }
    v->width = 2u;
    for (i = 0; i + 1u < s->count; i += SL_RUN_POINTS) {
        const uint32_t j = (i + SL_RUN_POINTS < s->count) ? i + SL_RUN_POINTS : s->count - 1u;
        v->seg = SL_PIECE | (s->first + i);
        v->piece_end = s->first + j;
        if (SL_FOR_SPEED) {
            /* The box of the run's pieces: of their ends alone (every
             * SL_POLY_STEP-th point and the run's last, in whole pixels, as
             * near_entry() tests them), walked by pointer. */
            const symline_point *q = p + i, *const e = p + j;
            uint32_t x0 = q->x, y0 = q->y, x1 = x0, y1 = y0;
#if SL_FOR_SPEED_DEEP
            const uint32_t from = v->kept;
            if (entry_filled(v)) {
                continue;
            }
#endif
            while (q != e) {
                uint32_t x, y;
                q = e - q > (ptrdiff_t)SL_POLY_STEP ? q + SL_POLY_STEP : e;
                x = q->x;
                y = q->y;
                x0 = x < x0 ? x : x0;
                x1 = x > x1 ? x : x1;
                y0 = y < y0 ? y : y0;
                y1 = y > y1 ? y : y1;
            }
            visit_box(v, x0, y0, x1, y1);
#if SL_FOR_SPEED_DEEP
            entry_counted(v, from);
#endif
        } else {
            symline_i_cellwalk_chord(v, (int32_t)p[i].x << 8, (int32_t)p[i].y << 8,
                                     (int32_t)p[j].x << 8, (int32_t)p[j].y << 8, v->margin);
        }
    }
}

/* The start of an area, aligned for uint32_t ids, and how many it holds. */
SL_NOINLINE static uint32_t *id_area(void *mem, size_t bytes, uint32_t *n)
{
    uint8_t *cur = (uint8_t *)mem;
    const size_t skip = (SL_ALIGN - ((uintptr_t)cur & (SL_ALIGN - 1u))) & (SL_ALIGN - 1u);
    *n = 0u;
    if (mem == NULL || bytes <= skip) {
        return NULL;
    }
    bytes = (bytes - skip) / sizeof(uint32_t);
    *n = bytes > 0xFFFFFFFFu ? 0xFFFFFFFFu : (uint32_t)bytes;
    return (uint32_t *)(void *)(cur + skip);
}

void symline_i_segindex_build(symline_i_segindex *ix, void *mem, size_t bytes, void *spare,
                              size_t spare_bytes, uint32_t width, uint32_t height,
                              const symline_result *r, uint32_t nseg, int32_t tol_q8)
{
    uint8_t *cur = (uint8_t *)mem, *const lim = (uint8_t *)mem + bytes;
    const uint32_t cells = symline_i_grid_dims(width, height, &ix->cols, &ix->rows);
    uint32_t c, s, cap, cap2, total = 0u, sum = 0u;
    uint32_t *ids2;
    symline_i_cellwalk v;
    ix->end = (uint32_t *)symline_i_carve(&cur, lim, (size_t)cells * sizeof(uint32_t));
    ix->indexed = 0u;
    ix->hit = SL_NO_HIT;
    if (ix->end == NULL) {
        ix->cols = 0u; /* not reached: the workspace size was checked */
        return;
    }
    ix->ids = id_area(cur, (size_t)(lim - cur), &cap);
    ids2 = id_area(spare, spare_bytes, &cap2);
    if (cap2 > cap) {
        ix->ids = ids2;
        cap = cap2;
    }
    v.cols = ix->cols;
    v.rows = ix->rows;
    v.end = ix->end;
    v.ids = ix->ids;
    for (c = 0; c < cells; c++) {
        ix->end[c] = 0u;
    }
    /* Count, segment by segment, while the ids fit. */
    v.margin = tol_q8;
    v.mode = SL_WALK_COUNT;
    v.sign = 1u;
#if SL_FOR_SPEED_DEEP
    /* The cells the count visits go to the far end of the id area while it
     * is unused; the fill reads those the ids it writes (from the start)
     * leave alone instead of walking the segments again. */
    v.cells = cap != 0u ? ix->ids + cap : NULL;
    v.cell_cap = cap;
    v.kept = v.used = 0u;
    v.full = false;
#endif
    for (s = 0; s < nseg && s < SL_PIECE; s++) {
#if SL_FOR_SPEED_DEEP
        const uint32_t kept = v.kept;
#endif
        v.added = 0u;
        visit_segment(&v, r, s);
        if (v.added > cap - total) {
            /* Does not fit: take its counts back; it and later ones stay out. */
            v.sign = UINT32_MAX;
            visit_segment(&v, r, s);
#if SL_FOR_SPEED_DEEP
            v.kept = kept;
#endif
            break;
        }
        total += v.added;
    }
    ix->indexed = s;
    /* Counts to start offsets, then enter the ids (each cell's offset runs to its end). */
    for (c = 0; c < cells; c++) {
        const uint32_t n = ix->end[c];
        ix->end[c] = sum;
        sum += n;
    }
    v.mode = SL_WALK_FILL;
#if SL_FOR_SPEED_DEEP
    if (v.kept > cap - sum) {
        /* Ids [0, sum) would overwrite the rest: the whole entries before. */
        uint32_t t = cap - sum;
        while (t > 0u && (v.cells[-(ptrdiff_t)t] & SL_PIECE) == 0u) {
            t--;
        }
        v.kept = t;
    }
#endif
    for (s = 0; s < ix->indexed; s++) {
        visit_segment(&v, r, s);
    }
}

/* Where the build optimises for speed on a 64-bit core, near_entry() is
 * copied into both its callers in symline_i_segindex_near() (a chain asks
 * once per point; the call cost a fifth of the test). */
#if SL_FOR_SPEED_DEEP
#define SL_NEAR_INLINE SL_ALWAYS_INLINE
#else
#define SL_NEAR_INLINE
#endif

/* Whether q lies near grid entry k (a line's id, or a curve's run: the
 * pieces of its polyline in it). */
static SL_NEAR_INLINE bool near_entry(const symline_i_segindex *ix, const symline_result *r,
                                      uint32_t k, const symline_i_near *q)
{
    const uint32_t e = ix->ids[k];
    uint32_t a;
    if ((e & SL_PIECE) == 0u) {
        const symline_segment *s = &r->segments[e];
        /* A line's test here, inline (SL_FOR_SPEED_DEEP, segments.h). */
        if (SL_FOR_SPEED_DEEP && (s->kind == SYMLINE_KIND_LINE || s->count < 2u)) {
            return symline_i_near_chord(s->x0, s->y0, s->x1, s->y1, q);
        }
        return symline_i_near_segment(s, r->points, q);
    }
    if (SL_FOR_SPEED_DEEP) {
        /* The same pieces, walked by pointer: each ends where the next
         * starts, the last at the run's last point. */
        const symline_point *pa = r->points + (e - SL_PIECE), *const pl =
                                                                  r->points + ix->ids[k + 1u];
        while (pa < pl) {
            const symline_point *pb = pl - pa > (ptrdiff_t)SL_POLY_STEP ? pa + SL_POLY_STEP : pl;
            if (symline_i_near_chord((int32_t)pa->x << SL_Q8_SHIFT, (int32_t)pa->y << SL_Q8_SHIFT,
                                     (int32_t)pb->x << SL_Q8_SHIFT, (int32_t)pb->y << SL_Q8_SHIFT,
                                     q)) {
                return true;
            }
            pa = pb;
        }
        return false;
    }
    a = e - SL_PIECE; /* the run's first point, before its last (visit_segment()) */
    return symline_i_near_run(r->points + a, ix->ids[k + 1u] - a, q);
}

/* The line entry a chain's scan tried first, prepared (SL_FOR_SPEED_DEEP):
 * k the entry, SL_NO_HIT: none yet. Elsewhere each point tests the chord. */
#if SL_FOR_SPEED_DEEP
typedef struct hit_prep {
    uint32_t k;
    symline_i_chord_prep c;
} hit_prep;
#else
typedef struct hit_prep hit_prep;
#endif

/* near_entry() of the entry tried first (ix->hit); within a scan (hp not
 * NULL) a line's chord prepared once for the points of the chain that runs
 * along it. */
static SL_ALWAYS_INLINE bool near_hit(const symline_i_segindex *ix, const symline_result *r,
                                      const symline_i_near *q, hit_prep *hp)
{
#if SL_FOR_SPEED_DEEP
    const uint32_t e = ix->ids[ix->hit];
    if (hp != NULL && (e & SL_PIECE) == 0u) {
        const symline_segment *s = &r->segments[e];
        if (s->kind == SYMLINE_KIND_LINE || s->count < 2u) {
            if (hp->k != ix->hit) {
                symline_i_chord_prepare(&hp->c, s->x0, s->y0, s->x1, s->y1, q->tol);
                hp->k = ix->hit;
            }
            return symline_i_near_prepared(&hp->c, q);
        }
    }
#else
    (void)hp;
#endif
    return near_entry(ix, r, ix->hit, q);
}

/* symline_i_segindex_near(), inline in both its callers. */
static SL_ALWAYS_INLINE bool near_at(symline_i_segindex *ix, const symline_result *r, uint32_t nseg,
                                     int32_t x, int32_t y, int32_t tol_q8, hit_prep *hp,
                                     bool hit_tried)
{
    symline_i_near q;
    uint32_t i = 0u;
    q.x = x;
    q.y = y;
    q.tol = tol_q8;
    if (ix != NULL && ix->cols != 0u) {
        uint32_t c, k;
        if (SL_FOR_SPEED && !hit_tried && ix->hit != SL_NO_HIT && near_hit(ix, r, &q, hp)) {
            return true; /* (most points of a chain along an earlier segment: no cell needed) */
        }
        c = symline_i_cell_at(ix->cols, ix->rows, x, y);
        for (k = c == 0u ? 0u : ix->end[c - 1u]; k < ix->end[c];
             k += (ix->ids[k] & SL_PIECE) != 0u ? 2u : 1u) {
            /* The entry just tried first is not near: not again. */
            if (SL_FOR_SPEED && k == ix->hit) {
                continue;
            }
            if (near_entry(ix, r, k, &q)) {
                ix->hit = k;
                return true;
            }
        }
        if (SL_FOR_SPEED) {
            /* Near none: the chain has left the entry, which would only be
             * tried again in vain at its next points. */
            ix->hit = SL_NO_HIT;
        }
        i = ix->indexed;
    }
    for (; i < nseg; i++) {
        if (symline_i_near_segment(&r->segments[i], r->points, &q)) {
            return true;
        }
    }
    return false;
}

bool symline_i_segindex_near(symline_i_segindex *ix, const symline_result *r, uint32_t nseg,
                             int32_t x, int32_t y, int32_t tol_q8)
{
    return near_at(ix, r, nseg, x, y, tol_q8, NULL, false);
}

#if SL_FOR_SPEED /* (chain() in pass.c asks in speed builds only) */
const symline_point *symline_i_segindex_scan(symline_i_segindex *ix, const symline_result *r,
                                             uint32_t nseg, const symline_point *q,
                                             const symline_point *e, uint32_t level, int32_t tol_q8,
                                             bool near)
{
    const uint32_t sh = SL_CELL_SHIFT - level;
    uint32_t cell = UINT32_MAX; /* the last cell found empty */
#if SL_FOR_SPEED_DEEP
    /* (all of it set: no compiler sees k guard the rest) */
    hit_prep prep = {SL_NO_HIT, {0}}, *const hp = &prep;
#else
    hit_prep *const hp = NULL;
#endif
    for (; q < e; q++) {
        const int32_t x = symline_i_q8(q->x, level), y = symline_i_q8(q->y, level);
        uint32_t at;
        bool tried = false;
        if (SL_FOR_SPEED_DEEP && ix->hit != SL_NO_HIT) {
            /* The entry the last point was near, before the point's cell:
             * a point near it lies in a cell that lists it. */
            symline_i_near qn;
            qn.x = x;
            qn.y = y;
            qn.tol = tol_q8;
            if (near_hit(ix, r, &qn, hp)) {
                if (near) {
                    break;
                }
                continue;
            }
            tried = true;
        }
        at = ((uint32_t)q->y >> sh) * ix->cols + ((uint32_t)q->x >> sh);
        if (at == cell || symline_i_segindex_cell_empty(ix, at)) {
            cell = at;
            ix->hit = tried ? SL_NO_HIT : ix->hit; /* left behind */
            if (!near) {
                break;
            }
        } else if (near_at(ix, r, nseg, x, y, tol_q8, hp, tried) == near) {
            break;
        }
    }
    return q;
}
#endif

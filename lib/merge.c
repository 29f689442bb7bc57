/*
 * The merge of collinear line pieces that an occluder (a robot, a ball) or a
 * junction split: close ends, each piece on the other's line, and the joined
 * piece still straight. The joined piece's points are made contiguous in the
 * point storage by rotating the points in between (three reversals), so a
 * segment is always one range of points.
 */
#include "merge.h"

#include "endgrid.h"

#include "fixed.h"
#include "segments.h"
#include "tracer.h"

/* The coarsest scale a segment can come from (its half block widens the
 * merge's tolerance across the line). */
#define SL_MAX_LEVEL_SLACK 5u

/* What joined_dev() returns for a pair whose joined piece would be a curve. */
#define SL_JOINED_IS_CURVE UINT32_MAX

static uint64_t dist2(int32_t ax, int32_t ay, int32_t bx, int32_t by)
{
    const int64_t dx = (int64_t)ax - bx, dy = (int64_t)ay - by;
    return (uint64_t)(dx * dx + dy * dy);
}

/* End i (0..3: a's two, then b's two) of the pair; x in *x, y in *y. */
static void end_of(const symline_segment *a, const symline_segment *b, uint32_t i, int32_t *x,
                   int32_t *y)
{
    const symline_segment *s = i < 2u ? a : b;
    *x = (i & 1u) ? s->x1 : s->x0;
    *y = (i & 1u) ? s->y1 : s->y0;
}

/* Whether line b may join line a: close ends, each piece on the other's line.
 * Sets the joined ends (the extreme ends along the longer piece). */
SL_NOINLINE static bool mergeable(const symline_segment *a, const symline_segment *b, uint64_t gap2,
                                  uint32_t dev_q8, int32_t ends[4])
{
    const int32_t adx = a->x1 - a->x0, ady = a->y1 - a->y0;
    const int32_t bdx = b->x1 - b->x0, bdy = b->y1 - b->y0;
    /* The longer piece by the larger of |dx|, |dy| (within 30 % of its length). */
    const int32_t aax = adx < 0 ? -adx : adx, aay = ady < 0 ? -ady : ady;
    const int32_t abx = bdx < 0 ? -bdx : bdx, aby = bdy < 0 ? -bdy : bdy;
    const int32_t al = aax > aay ? aax : aay, bl = abx > aby ? abx : aby;
    const bool a_longer = al >= bl;
    const int32_t dx = a_longer ? adx : bdx;
    const int32_t dy = a_longer ? ady : bdy;
    int64_t lo = 0, hi = 0;
    uint64_t g = ~(uint64_t)0;
    uint32_t i;
    /* Each end on the other piece's line; the gap: the closest pair of ends. */
    for (i = 0; i < 4u; i++) {
        const symline_segment *o = i < 2u ? b : a;
        int32_t x, y, ox, oy;
        uint64_t t;
        end_of(a, b, i, &x, &y);
        if (sl_line_dist_q8(o->x0, o->y0, o->x1 - o->x0, o->y1 - o->y0, x, y) > dev_q8) {
            return false;
        }
        end_of(a, b, (i ^ 2u) & 2u, &ox, &oy);
        t = dist2(x, y, ox, oy);
        g = t < g ? t : g;
        end_of(a, b, ((i ^ 2u) & 2u) | 1u, &ox, &oy);
        t = dist2(x, y, ox, oy);
        g = t < g ? t : g;
    }
    if (g > gap2) {
        return false;
    }
    /* New ends: the extreme end points along the longer piece. */
    for (i = 0; i < 4u; i++) {
        int32_t x, y;
        int64_t proj;
        end_of(a, b, i, &x, &y);
        proj = (int64_t)x * dx + (int64_t)y * dy;
        if (i == 0u || proj < lo) {
            lo = proj;
            ends[0] = x;
            ends[1] = y;
        }
        if (i == 0u || proj > hi) {
            hi = proj;
            ends[2] = x;
            ends[3] = y;
        }
    }
    return true;
}

/*
 * Where the points of the merged lines are. Eagerly, every join rotates the
 * absorbed line's points next to its new owner's (pieces == NULL): what the
 * result needs, but a join then moves all the points stored between the two.
 * With room in the free end of the point storage, the joins only chain the
 * slots (own, next, last) and the points are laid out once at the end, in
 * the very order the rotations would have given.
 */
typedef struct sl_pieces {
    uint32_t *own;          /* per slot: points of its own run, from segments[slot].first */
    uint32_t *next;         /* per slot: the slot whose points follow in its line, or SL_NO_SLOT */
    uint32_t *last;         /* per slot: the last slot of the chain it starts */
    symline_point *scratch; /* room for point_count points */
} sl_pieces;

#define SL_NO_SLOT 0xFFFFFFFFu

/* The largest cross product of slot s's points (all its runs) to the chord. */
static uint64_t chain_cross(const symline_result *r, const sl_pieces *pc, uint32_t s,
                            const int32_t ends[4], uint64_t best)
{
    const symline_segment *seg = &r->segments[s];
    if (pc == NULL) {
        return sl_max_cross(r->points + seg->first, seg->count, 0u, ends[0], ends[1], ends[2],
                            ends[3], best);
    }
    for (; s != SL_NO_SLOT; s = pc->next[s]) {
        best = sl_max_cross(r->points + r->segments[s].first, pc->own[s], 0u, ends[0], ends[1],
                            ends[2], ends[3], best);
    }
    return best;
}

/* The joined piece's max_dev, or SL_JOINED_IS_CURVE when it would be a curve. Kept
 * apart from mergeable() so their frames are never on the stack together. */
SL_NOINLINE static uint32_t joined_dev(const symline_result *r, const sl_pieces *pc, uint32_t i,
                                       uint32_t j, const int32_t ends[4], uint32_t curve_q8)
{
    const uint64_t best = chain_cross(r, pc, j, ends, chain_cross(r, pc, i, ends, 0u));
    const uint32_t d = sl_cross_dev(best, ends[0], ends[1], ends[2], ends[3]);
    return sl_is_curve(ends[0], ends[1], ends[2], ends[3], d, curve_q8) ? SL_JOINED_IS_CURVE : d;
}

/* A segment's ends, Q8. */
static void set_ends(symline_segment *s, int32_t x0, int32_t y0, int32_t x1, int32_t y1)
{
    s->x0 = x0;
    s->y0 = y0;
    s->x1 = x1;
    s->y1 = y1;
}

/* Field-by-field copy (a struct assignment may become a libc memcpy call). */
static void copy_segment(symline_segment *d, const symline_segment *s)
{
    set_ends(d, s->x0, s->y0, s->x1, s->y1);
    d->max_dev = s->max_dev;
    d->first = s->first;
    d->count = s->count;
    d->kind = s->kind;
    d->axis = s->axis;
    d->level = s->level;
    d->merged = s->merged;
}

/* A slot whose segment was absorbed (kind is a symline_kind otherwise);
 * the slots are compacted once the merge is done, so that slot numbers stay
 * those of the grid of ends meanwhile. */
#define SL_GONE 0xFFu

/* Segment j joins segment i (i < j) and slot j is marked gone. Eagerly: j's
 * points move right behind i's (three reversals rotate the points between). */
static void absorb(symline_result *r, sl_pieces *pc, uint32_t i, uint32_t j)
{
    symline_segment *a = &r->segments[i];
    const uint32_t b_first = r->segments[j].first, b_count = r->segments[j].count;
    if (pc != NULL) {
        pc->next[pc->last[i]] = j;
        pc->last[i] = pc->last[j];
    } else {
        const uint32_t mid0 = a->first + a->count;
        const uint32_t midn = b_first - mid0;
        uint32_t k;
        sl_reverse_points(r->points + mid0, midn);
        sl_reverse_points(r->points + b_first, b_count);
        sl_reverse_points(r->points + mid0, midn + b_count);
        for (k = i + 1u; k < j; k++) {
            r->segments[k].first += b_count;
        }
    }
    a->count += b_count;
    r->segments[j].kind = SL_GONE;
}

/* Joins line j into line i when the pair passes the merge's tests. */
static bool try_join(symline_result *r, sl_pieces *pc, uint32_t i, uint32_t j, uint64_t gap2,
                     uint32_t dev_q8, uint32_t curve_dev_q8, sl_endgrid *g)
{
    int32_t ends[4];
    uint32_t dev;
    symline_segment *a = &r->segments[i];
    const symline_segment *b = &r->segments[j];
    const uint32_t level = a->level > b->level ? a->level : b->level;
    const uint32_t thr = curve_dev_q8 + sl_block_half_q8(level);
    if (b->kind != SYMLINE_KIND_LINE) {
        return false;
    }
    if (!mergeable(a, b, gap2, dev_q8 + sl_block_half_q8(level), ends)) {
        return false;
    }
    dev = joined_dev(r, pc, i, j, ends, thr);
    if (dev == SL_JOINED_IS_CURVE) {
        return false;
    }
    if (g != NULL) {
        sl_endgrid_remove(g, a, i);
        sl_endgrid_remove(g, b, j);
    }
    set_ends(a, ends[0], ends[1], ends[2], ends[3]);
    a->max_dev = dev;
    a->level = (uint8_t)level;
    a->merged = true; /* points piece after piece (curvejoin.c) */
    absorb(r, pc, i, j);
    if (g != NULL) {
        sl_endgrid_add(g, a, i);
    }
    return true;
}

/*
 * Line i against the lines after it, in slot order, until one joins it
 * (true) or none does: from the grid, the lines with an end near i's line
 * and within the gap of its ends; without a grid (or too many of them),
 * every later line.
 */
static bool join_first(symline_result *r, sl_pieces *pc, uint32_t i, uint64_t gap2, uint32_t gap_px,
                       uint32_t dev_q8, uint32_t curve_dev_q8, sl_endgrid *g, int64_t ext_max)
{
    uint32_t j;
    if (g != NULL) {
        /* A joining line's end lies within dev (plus the coarsest scale's
         * half block, plus rounding) of i's line, and within the gap of one
         * of i's ends along it. */
        const int64_t gap_q8 = (int64_t)gap_px << SL_Q8_SHIFT;
        const uint32_t ext = (uint32_t)(gap_q8 < ext_max ? gap_q8 : ext_max);
        const int32_t margin =
            (int32_t)(dev_q8 + sl_block_half_q8(SL_MAX_LEVEL_SLACK) + SL_PX_Q8(1u));
        const int32_t n = sl_endgrid_query(g, &r->segments[i], ext, margin);
        if (n >= 0) {
            int32_t k;
            for (k = 0; k < n; k++) {
                j = g->cand[k];
                if (j > i && try_join(r, pc, i, j, gap2, dev_q8, curve_dev_q8, g)) {
                    return true;
                }
            }
            return false;
        }
    }
    for (j = i + 1u; j < r->segment_count; j++) {
        if (try_join(r, pc, i, j, gap2, dev_q8, curve_dev_q8, g)) {
            return true;
        }
    }
    return false;
}

/* The deferred layout, carved from the free end of the point storage; *rest
 * and *rest_bytes say what is left of that (all of it when NULL is returned:
 * no room). */
static sl_pieces *pieces_init(const symline_result *r, uint8_t **rest, size_t *rest_bytes)
{
    uint8_t *cur, *end;
    sl_pieces *pc;
    uint32_t s;
    if (r->points == NULL || r->point_count >= r->point_cap) {
        return NULL;
    }
    cur = (uint8_t *)(r->points + r->point_count);
    end = cur + (size_t)(r->point_cap - r->point_count) * sizeof(symline_point);
    *rest = cur;
    *rest_bytes = (size_t)(end - cur);
    pc = (sl_pieces *)sl_carve(&cur, end, sizeof(sl_pieces));
    if (pc == NULL) {
        return NULL;
    }
    pc->own = (uint32_t *)sl_carve(&cur, end, (size_t)r->segment_count * sizeof(uint32_t));
    pc->next = (uint32_t *)sl_carve(&cur, end, (size_t)r->segment_count * sizeof(uint32_t));
    pc->last = (uint32_t *)sl_carve(&cur, end, (size_t)r->segment_count * sizeof(uint32_t));
    pc->scratch =
        (symline_point *)sl_carve(&cur, end, (size_t)r->point_count * sizeof(symline_point));
    if (pc->own == NULL || pc->next == NULL || pc->last == NULL || pc->scratch == NULL) {
        return NULL;
    }
    for (s = 0; s < r->segment_count; s++) {
        pc->own[s] = r->segments[s].count;
        pc->next[s] = SL_NO_SLOT;
        pc->last[s] = s;
    }
    *rest = cur;
    *rest_bytes = (size_t)(end - cur);
    return pc;
}

/* The deferred layout: each line's runs one after the other, lines in slot
 * order (what the rotations give), through the scratch area. */
static void pieces_layout(symline_result *r, const sl_pieces *pc)
{
    uint32_t i, s, k, w = 0u;
    for (i = 0; i < r->segment_count; i++) {
        const uint32_t first = w;
        if (r->segments[i].kind == SL_GONE) {
            continue;
        }
        for (s = i; s != SL_NO_SLOT; s = pc->next[s]) {
            const symline_point *src = r->points + r->segments[s].first;
            for (k = 0; k < pc->own[s]; k++) {
                pc->scratch[w + k].x = src[k].x;
                pc->scratch[w + k].y = src[k].y;
                pc->scratch[w + k].fx = src[k].fx;
                pc->scratch[w + k].fy = src[k].fy;
            }
            w += pc->own[s];
        }
        r->segments[i].first = first;
    }
    for (k = 0; k < w; k++) {
        r->points[k].x = pc->scratch[k].x;
        r->points[k].y = pc->scratch[k].y;
        r->points[k].fx = pc->scratch[k].fx;
        r->points[k].fy = pc->scratch[k].fy;
    }
}

void sl_merge(symline_result *r, uint32_t gap_px, uint32_t dev_q8, uint32_t curve_dev_q8,
              uint32_t width, uint32_t height, void *ws, size_t ws_size)
{
    const uint64_t gap2 = ((uint64_t)gap_px << SL_Q8_SHIFT) * ((uint64_t)gap_px << SL_Q8_SHIFT);
    /* Segment ends lie within the frame (give or take a few px): no stretch
     * of a line needs to reach farther than this. */
    const int64_t ext_max = ((int64_t)width + height + 64) << SL_Q8_SHIFT;
    uint32_t i, w;
    bool changed = true;
    uint8_t *rest = NULL;
    size_t rest_bytes = 0u;
    /* Both in caller memory, not on the stack (a firmware's budget). */
    sl_pieces *const pc = pieces_init(r, &rest, &rest_bytes);
    sl_endgrid *g = NULL;
    /* The grid lives in the workspace or else in what is left of the free
     * end of the point storage; without room for it every pair is tried,
     * with the same result. */
    if (dev_q8 <= SL_PX_Q8(SYMLINE_MAX_DIM)) {
        g = sl_endgrid_init(ws, ws_size, width, height, r->segment_count);
        if (g == NULL) {
            g = sl_endgrid_init(rest, rest_bytes, width, height, r->segment_count);
        }
    }
    for (i = 0; g != NULL && i < r->segment_count; i++) {
        if (r->segments[i].kind == SYMLINE_KIND_LINE) {
            sl_endgrid_add(g, &r->segments[i], i);
        }
    }
    /* In slot order, each line takes the first later line that joins it,
     * again and again (the grown line may reach lines it missed), until a
     * whole round joins nothing. */
    while (changed) {
        changed = false;
        for (i = 0; i < r->segment_count; i++) {
            if (r->segments[i].kind != SYMLINE_KIND_LINE) {
                continue;
            }
            while (join_first(r, pc, i, gap2, gap_px, dev_q8, curve_dev_q8, g, ext_max)) {
                changed = true;
            }
        }
    }
    if (pc != NULL) {
        pieces_layout(r, pc);
    }
    for (i = 0, w = 0; i < r->segment_count; i++) {
        if (r->segments[i].kind != SL_GONE) {
            if (w != i) {
                copy_segment(&r->segments[w], &r->segments[i]);
            }
            w++;
        }
    }
    r->segment_count = w;
}

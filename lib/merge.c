/* SPDX-License-Identifier: Apache-2.0 */
/*
 * The merge of collinear line pieces that an occluder (a robot, a ball) or a
 * junction split: close ends, each piece on the other's line, and the joined
 * piece still straight. The joined piece's points are made contiguous in the
 * point storage by rotating the points in between (three reversals), so a
 * segment is always one range of points.
 */
#include "merge.h"

#include "fixed.h"
#include "segindex.h"
#include "segments.h"
#include "tracer.h"

/* What joined_dev() returns for a pair whose joined piece would be a curve
 * (and pair_dev() for a pair that may not join). */
#define SL_NO_JOIN UINT32_MAX

static uint64_t dist2(int32_t ax, int32_t ay, int32_t bx, int32_t by)
{
    /* Ends within 2^25 Q8 of the frame (merge.h): differences fit 32 bits. */
    const int32_t dx = ax - bx, dy = ay - by;
    return (uint64_t)((int64_t)dx * dx + (int64_t)dy * dy);
}

/* End i (0..3: a's two, then b's two) of the pair; x in *x, y in *y. In
 * its callers, where the ends stay in registers. */
static SL_ALWAYS_INLINE void end_of(const symline_segment *a, const symline_segment *b, uint32_t i,
                                    int32_t *x, int32_t *y)
{
    const symline_segment *s = i < 2u ? a : b;
    *x = (i & 1u) ? s->x1 : s->x0;
    *y = (i & 1u) ? s->y1 : s->y0;
}

/* True when the spans a0..a1 and b0..b1 (either order) are more than gap
 * apart (differences of ends within 2^25 Q8 of the frame fit 32 bits). */
static bool apart(int32_t a0, int32_t a1, int32_t b0, int32_t b1, int32_t gap)
{
    const int32_t alo = a0 < a1 ? a0 : a1, ahi = a0 < a1 ? a1 : a0;
    const int32_t blo = b0 < b1 ? b0 : b1, bhi = b0 < b1 ? b1 : b0;
    return blo - ahi > gap || alo - bhi > gap;
}

/* symline_i_line_dist_q8(ax, ay, dx, dy, px, py) > dev. Where the build
 * optimises for speed, mostly without its square root: for a chord of
 * length len = isqrt(l2) >= 1 and a cross product that fits 32 bits the
 * distance is cross / len rounded down, above dev exactly when
 * len <= t = cross / (dev + 1), that is when l2 < (t + 1)^2 (ends within
 * 2^25 Q8 of the frame: l2 < 2^56, so any t >= 2^28 passes). */
static bool off_line(int32_t ax, int32_t ay, int32_t dx, int32_t dy, int32_t px, int32_t py,
                     uint32_t dev)
{
    if (SL_FOR_SPEED && dev < UINT32_MAX) {
        const int32_t wx = px - ax, wy = py - ay;
        const uint64_t l2 = (uint64_t)((int64_t)dx * dx + (int64_t)dy * dy);
        const int64_t c = (int64_t)wx * dy - (int64_t)wy * dx;
        const uint64_t cross = (uint64_t)(c < 0 ? -c : c);
        if (l2 != 0u && cross <= UINT32_MAX) {
            const uint64_t t = (uint32_t)cross / (dev + 1u);
            return t >= ((uint64_t)1u << 28) || l2 < (t + 1u) * (t + 1u);
        }
    }
    return symline_i_line_dist_q8(ax, ay, dx, dy, px, py) > dev;
}

/* Whether line b may join line a: close ends, each piece on the other's line.
 * Sets the joined ends (the extreme ends along the longer piece) as j's
 * (left partly set when false). */
SL_NOINLINE static bool mergeable(const symline_segment *a, const symline_segment *b,
                                  uint32_t gap_q8, uint32_t dev_q8, symline_segment *j)
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
    /* Ends within 2^25 Q8 of the frame keep |proj| far below both limits:
     * the first end sets lo and hi. */
    int64_t lo = INT64_MAX, hi = INT64_MIN;
    uint64_t g = ~(uint64_t)0;
    uint32_t i;
    /* The gap first: the closest pair of ends (no square root, and most
     * pairs of a cluttered frame fail it); then each end on the other
     * piece's line. Both must hold, so the order changes only the cost. */
    for (i = 0; i < 4u; i++) {
        int32_t x, y, ox, oy;
        uint64_t t;
        end_of(a, b, i >> 1, &x, &y);
        end_of(a, b, 2u | (i & 1u), &ox, &oy);
        t = dist2(x, y, ox, oy);
        g = t < g ? t : g;
    }
    if (g > (uint64_t)gap_q8 * gap_q8) {
        return false;
    }
    /* Each end on the other piece's line; the new ends (j's, written as the
     * ends pass): the extreme end points along the longer piece. */
    for (i = 0; i < 4u; i++) {
        const symline_segment *o = i < 2u ? b : a;
        int32_t x, y;
        int64_t proj;
        end_of(a, b, i, &x, &y);
        if (off_line(o->x0, o->y0, o->x1 - o->x0, o->y1 - o->y0, x, y, dev_q8)) {
            return false;
        }
        proj = (int64_t)x * dx + (int64_t)y * dy;
        if (proj < lo) {
            lo = proj;
            j->x0 = x;
            j->y0 = y;
        }
        if (proj > hi) {
            hi = proj;
            j->x1 = x;
            j->y1 = y;
        }
    }
    return true;
}

/* A slot whose segment was absorbed (kind is a symline_kind otherwise); the
 * slots are compacted when the merge is done, so that a slot keeps its number
 * in the grid of ends meanwhile. */
#define SL_GONE 0xFFu
/* A curve found not joinable (below): its points and chord do not change
 * while it joins nothing, so it stays so; a curve again when the merge is done. */
#define SL_STIFF 0xFEu

/* A line may join; so may a piece taken for a curve whose points (p),
 * smoothed, stay within half the curve threshold of its chord: a straight
 * piece whose ridge jitters on the turf, not an arc of the circle. A curve
 * is asked once (SL_STIFF). */
static bool joinable(symline_segment *s, const symline_point *p, uint32_t curve_q8)
{
    if (s->kind == SYMLINE_KIND_LINE) {
        return true;
    }
    if (s->kind == SYMLINE_KIND_CURVE &&
        symline_i_smooth_dev(p, s->count, 0u, s) <= curve_q8 / 2u) {
        return true;
    }
    s->kind = SL_STIFF;
    return false;
}

/* Byte by byte: a struct assignment or memcpy may become a libc call. */
static void copy_bytes(void *d, const void *s, size_t n)
{
    uint8_t *o = (uint8_t *)d;
    const uint8_t *i = (const uint8_t *)s;
    while (n-- != 0u) {
        *o++ = *i++;
    }
}

static void copy_points(symline_point *d, const symline_point *s, uint32_t n)
{
    copy_bytes(d, s, (size_t)n * sizeof(symline_point));
}

#define SL_NO_NODE 0xFFFFFFFFu
/* Later pieces from which on the grid of ends is walked (join_first()). */
#define SL_MERGE_WALK_MIN 64u

/*
 * The merge's state, and what makes it near-linear without changing a
 * single join:
 * - The grid of ends: node 2 s + e (end e of slot s) in the list of the
 *   32 px cell of that end (head, next; slots [0, indexed) entered), built
 *   at the start of each round. A piece j joining piece i has an end within
 *   the gap of one of i's ends and within the merge deviation of i's line,
 *   so the cells along i's line, stretched by the gap past both ends, list
 *   every j that can join i. Within a round only the piece in hand grows
 *   and the later pieces it takes are marked gone, so the grid of the
 *   round's start is exact for every later piece; the candidates are tried
 *   in slot order, as all pairs would be.
 * - The layout: rather than rotating every point between two joined pieces
 *   into place (which made the joins of a cluttered frame quadratic in its
 *   points), each piece's points are copied in slot order to the free end
 *   of the point storage (out), a join appending the absorbed piece's
 *   points, and copied back at the end of a round: the layout the rotations
 *   give. Without room for it (or with points not laid out piece after
 *   piece in slot order), the rotations.
 */
typedef struct merger {
    symline_result *r;
    uint32_t n; /* slots */
    uint32_t gap_q8, dev_q8, curve_q8;
    uint32_t cols, rows; /* of the grid; cols 0: no grid, every later piece is tried */
    int32_t margin;      /* Q8, across i's line */
    uint32_t *head, *next, *cand, cand_cap, indexed;
    symline_point *out; /* NULL: rotations */
    uint32_t pos;       /* where the piece in hand starts in out */
    symline_point *ap;  /* the piece in hand's points (in out, or in place) */
    /* Where the round's layout in out begins, to save time (SL_FOR_SPEED;
     * else at 0): the pieces before it stay in place, their layout unchanged
     * until a first join (SL_NO_NODE while none). */
    uint32_t from;
} merger;

/* Piece j joins piece i (i < j): the joined ends and max_dev (e's), j's points
 * right behind i's, slot j gone. */
static void absorb(merger *m, uint32_t i, uint32_t j, const symline_segment *e)
{
    symline_result *r = m->r;
    symline_segment *a = &r->segments[i];
    const uint32_t b_first = r->segments[j].first, b_count = r->segments[j].count;
    const uint32_t mid0 = a->first + a->count;
    const uint32_t midn = b_first - mid0;
    const uint8_t lb = r->segments[j].level;
    if (SL_FOR_SPEED && m->out != NULL && m->from == SL_NO_NODE) {
        /* The round's first join: the layout in out begins with the piece
         * in hand (the pieces before it keep their places). */
        m->from = m->pos;
        m->ap = m->out + m->pos;
        copy_points(m->ap, r->points + a->first, a->count);
    }
    copy_bytes(a, e, offsetof(symline_segment, first)); /* the ends and max_dev */
    a->kind = SYMLINE_KIND_LINE;
    a->level = a->level > lb ? a->level : lb;
    a->merged = true; /* points piece after piece (curvejoin.c) */
    if (m->out != NULL) {
        copy_points(m->ap + a->count, r->points + b_first, b_count);
    } else {
        uint32_t k;
        symline_i_reverse_points(r->points + mid0, midn);
        symline_i_reverse_points(r->points + b_first, b_count);
        symline_i_reverse_points(r->points + mid0, midn + b_count);
        for (k = i + 1u; k < j; k++) {
            r->segments[k].first += b_count;
        }
    }
    a->count += b_count;
    r->segments[j].kind = SL_GONE;
}

/* The joined piece's max_dev, or SL_NO_JOIN when it would be a curve by
 * the curve threshold plus half a block of level (j: the joined ends; the
 * pieces' points: a's in hand, b's in place). Kept apart from mergeable() so
 * their frames are never on the stack together. */
SL_NOINLINE static uint32_t joined_dev(const merger *m, const symline_segment *a,
                                       const symline_segment *b, const symline_segment *j,
                                       uint32_t level)
{
    uint32_t d = 0u, sm = 0u, k;
    for (k = 0; k < 2u; k++) {
        const symline_point *p = k ? m->r->points + b->first : m->ap;
        const uint32_t n = k ? b->count : a->count;
        uint32_t dev[2]; /* max_dev, smoothed */
        symline_i_chord_devs(p, n, 0u, j, SL_SMOOTH_WIN, dev);
        d = dev[0] > d ? dev[0] : d;
        sm = dev[1] > sm ? dev[1] : sm;
    }
    return symline_i_is_curve(j, sm, m->curve_q8 + symline_i_block_half_q8(level)) ? SL_NO_JOIN : d;
}

/* The joined piece's max_dev when piece j may join piece i (e: the joined
 * ends), else SL_NO_JOIN. */
static uint32_t pair_dev(const merger *m, uint32_t i, uint32_t j, symline_segment *e)
{
    const symline_segment *a = &m->r->segments[i];
    symline_segment *b = &m->r->segments[j];
    const uint32_t level = a->level > b->level ? a->level : b->level;
    const symline_point *bp = m->r->points + b->first;
    /* The cheap geometric tests first, where speed counts the pieces' boxes
     * before them (no product: ends further apart in x or in y than the
     * gap fail the gap); all depend on the two pieces alone (joinable()
     * only keeps its answer), so the order changes nothing but the cost. */
    if (b->kind == SL_GONE || b->kind == SL_STIFF ||
        (SL_FOR_SPEED && (apart(a->x0, a->x1, b->x0, b->x1, (int32_t)m->gap_q8) ||
                          apart(a->y0, a->y1, b->y0, b->y1, (int32_t)m->gap_q8))) ||
        !mergeable(a, b, m->gap_q8, m->dev_q8 + symline_i_block_half_q8(level), e) ||
        !joinable(b, bp, m->curve_q8)) {
        return SL_NO_JOIN;
    }
    return joined_dev(m, a, b, e, level);
}

/*
 * The slots with an end in the cells within m->margin of a's chord
 * stretched by the gap past both ends, in m->cand (in cell order, a slot
 * may come twice). Returns their number, or -1 when more than m->cand_cap
 * were found: then every later piece is tried.
 */
SL_NOINLINE static int32_t candidates(merger *m, const symline_segment *a)
{
    const int32_t dx = a->x1 - a->x0, dy = a->y1 - a->y0;
    const uint32_t ux = (uint32_t)(dx < 0 ? -dx : dx), uy = (uint32_t)(dy < 0 ? -dy : dy);
    const uint32_t cheb = ux > uy ? ux : uy;
    /* Whole multiples of a's direction, longer than the gap (the larger of
     * |dx|, |dy| is no longer than the chord). */
    const int32_t k = cheb > 0u ? (int32_t)(m->gap_q8 / cheb + 1u) : 0;
    symline_i_cellwalk q;
    q.cols = m->cols;
    q.rows = m->rows;
    q.mode = SL_WALK_GATHER;
    q.head = m->head;
    q.next = m->next;
    q.cand = m->cand;
    q.cand_cap = m->cand_cap;
    q.n = 0u;
    symline_i_cellwalk_chord(&q, a->x0 - dx * k, a->y0 - dy * k, a->x1 + dx * k, a->y1 + dy * k,
                             m->margin);
    return q.n > q.cand_cap ? -1 : (int32_t)q.n;
}

/* Piece i takes the first later piece (in slot order) that joins it: true,
 * or false when none does. */
static bool join_first(merger *m, uint32_t i)
{
    symline_segment e; /* the joined ends */
    uint32_t j = i + 1u;
    /* The grid's walk costs as much as testing some dozens of pieces: only
     * for more later pieces than that (either way the same piece joins). */
    if (m->cols != 0u && m->n - i > SL_MERGE_WALK_MIN) {
        const int32_t nc = candidates(m, &m->r->segments[i]);
        if (nc >= 0) {
            uint32_t best = SL_NO_NODE, k;
            /* The first in slot order that joins is the smallest candidate
             * that does (the tests depend on the two pieces alone); failing
             * that, the pieces not in the grid. */
            for (k = 0; k < (uint32_t)nc; k++) {
                const uint32_t c = m->cand[k];
                symline_segment t;
                if (c > i && c < best) {
                    t.max_dev = pair_dev(m, i, c, &t);
                    if (t.max_dev != SL_NO_JOIN) {
                        best = c;
                        copy_bytes(&e, &t, sizeof(e));
                    }
                }
            }
            if (best != SL_NO_NODE) {
                absorb(m, i, best, &e);
                return true;
            }
            j = m->indexed > j ? m->indexed : j;
        }
    }
    for (; j < m->n; j++) {
        e.max_dev = pair_dev(m, i, j, &e);
        if (e.max_dev != SL_NO_JOIN) {
            absorb(m, i, j, &e);
            return true;
        }
    }
    return false;
}

/* The grid's lists of the slots in it, in their ends' cells. */
static void grid_build(merger *m)
{
    uint32_t c, node;
    for (c = 0; c < m->cols * m->rows; c++) {
        m->head[c] = SL_NO_NODE;
    }
    for (node = 0; node < 2u * m->indexed; node++) { /* end node & 1 of slot node / 2 */
        const symline_segment *g = &m->r->segments[node >> 1];
        if (g->kind != SL_GONE) {
            c = symline_i_cell_at(m->cols, m->rows, (node & 1u) ? g->x1 : g->x0,
                                  (node & 1u) ? g->y1 : g->y0);
            m->next[node] = m->head[c];
            m->head[c] = node;
        }
    }
}

/* The grid in ws (cells, then two nodes per slot for as many slots as leave
 * a quarter for the candidates); none when ws is too small or the
 * thresholds too large for its 32-bit walk (then every pair is tried). */
static void grid_init(merger *m, void *ws, size_t bytes, uint32_t width, uint32_t height)
{
    uint8_t *cur = (uint8_t *)ws;
    size_t e;
    const uint32_t cells = symline_i_grid_dims(width, height, &m->cols, &m->rows);
    m->head = ws == NULL ? NULL
                         : (uint32_t *)symline_i_carve(&cur, cur + bytes,
                                                       (size_t)cells * sizeof(uint32_t));
    if (m->head == NULL) {
        m->cols = 0u;
        return;
    }
    e = (size_t)((uint8_t *)ws + bytes - cur) / sizeof(uint32_t);
    m->indexed = (size_t)m->n < e * 3u / 8u ? m->n : (uint32_t)(e * 3u / 8u);
    m->next = (uint32_t *)(void *)cur;
    m->cand = m->next + 2u * (size_t)m->indexed;
    e -= 2u * (size_t)m->indexed;
    m->cand_cap = e > 0xFFFFFFu ? 0xFFFFFFu : (uint32_t)e; /* too few: every later piece */
    /* A joining piece's end lies within the deviation of i's line (plus the
     * coarsest scale's half block, plus rounding). */
    m->margin = (int32_t)(m->dev_q8 + symline_i_block_half_q8(SYMLINE_DETECT_MAX_LEVELS - 1u) +
                          SL_PX_Q8(1u));
}

void symline_i_merge(const symline_i_run *d, void *ws, size_t ws_size)
{
    symline_result *r = d->r;
    const symline_config *cfg = d->cfg;
    const uint32_t gap_px =
        cfg->merge_gap == SYMLINE_MERGE_GAP_AUTO ? d->img->width / 8u : cfg->merge_gap;
    merger m;
    uint32_t i, w;
    bool changed = true;
    m.r = r;
    m.n = r->segment_count;
    m.gap_q8 = gap_px << SL_Q8_SHIFT; /* gap_px <= SYMLINE_MAX_DIM: no wrap */
    m.dev_q8 = cfg->merge_dev_q8;
    m.curve_q8 = cfg->curve_dev_q8;
    /* Room for the layout: as many points again as there are. */
    m.out = r->point_count != 0u && r->point_cap - r->point_count >= r->point_count
                ? r->points + r->point_count
                : NULL;
    grid_init(&m, ws, ws_size, d->img->width, d->img->height);
    /* In slot order, each piece takes the first later piece that joins it,
     * again and again (the grown piece may reach pieces it missed), until a
     * whole round joins nothing. */
    while (changed) {
        changed = false;
        m.pos = 0u;
        if (SL_FOR_SPEED) {
            m.from = SL_NO_NODE;
        }
        if (m.cols != 0u) {
            grid_build(&m);
        }
        for (i = 0; i < m.n; i++) {
            symline_segment *a = &r->segments[i];
            if (a->kind == SL_GONE) {
                continue;
            }
            m.ap = r->points + a->first;
            if (SL_FOR_SPEED && m.from == SL_NO_NODE && a->first != m.pos) {
                m.from = m.pos; /* not in place: the layout in out begins */
            }
            if (m.out != NULL && (!SL_FOR_SPEED || m.from != SL_NO_NODE)) {
                m.ap = m.out + m.pos;
                copy_points(m.ap, r->points + a->first, a->count);
                a->first = m.pos;
            }
            /* Whether piece i may join at all does not change while it is
             * tried against the others (a join makes it a line). */
            if (joinable(a, m.ap, m.curve_q8)) {
                while (join_first(&m, i)) {
                    changed = true;
                }
            }
            m.pos += a->count;
        }
        if (m.out != NULL && (!SL_FOR_SPEED || m.from != SL_NO_NODE)) {
            /* From the round's first join on (SL_NO_NODE: all in place). */
            const uint32_t from = SL_FOR_SPEED ? m.from : 0u;
            copy_points(r->points + from, m.out + from, m.pos - from);
        }
    }
    for (i = 0, w = 0; i < m.n; i++) {
        if (r->segments[i].kind == SL_STIFF) {
            r->segments[i].kind = SYMLINE_KIND_CURVE;
        }
        if (r->segments[i].kind != SL_GONE) {
            copy_bytes(&r->segments[w++], &r->segments[i], sizeof(symline_segment));
        }
    }
    r->segment_count = w;
}

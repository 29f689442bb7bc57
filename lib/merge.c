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
#include "segments.h"
#include "tracer.h"

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
    if (g > gap2) {
        return false;
    }
    for (i = 0; i < 4u; i++) {
        const symline_segment *o = i < 2u ? b : a;
        int32_t x, y;
        end_of(a, b, i, &x, &y);
        if (symline_i_line_dist_q8(o->x0, o->y0, o->x1 - o->x0, o->y1 - o->y0, x, y) > dev_q8) {
            return false;
        }
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

/* The joined piece's max_dev, or SL_JOINED_IS_CURVE when it would be a curve. Kept
 * apart from mergeable() so their frames are never on the stack together. */
SL_NOINLINE static uint32_t joined_dev(const symline_segment *a, const symline_segment *b,
                                       const symline_point *pts, const int32_t ends[4],
                                       uint32_t curve_q8)
{
    uint32_t d =
        symline_i_max_dev(pts + a->first, a->count, 0u, ends[0], ends[1], ends[2], ends[3]);
    uint32_t sm =
        symline_i_smooth_dev(pts + a->first, a->count, 0u, ends[0], ends[1], ends[2], ends[3]);
    const uint32_t d2 =
        symline_i_max_dev(pts + b->first, b->count, 0u, ends[0], ends[1], ends[2], ends[3]);
    const uint32_t sm2 =
        symline_i_smooth_dev(pts + b->first, b->count, 0u, ends[0], ends[1], ends[2], ends[3]);
    d = d2 > d ? d2 : d;
    sm = sm2 > sm ? sm2 : sm;
    return symline_i_is_curve(ends[0], ends[1], ends[2], ends[3], sm, curve_q8) ? SL_JOINED_IS_CURVE
                                                                                : d;
}

/* A line may join; so may a piece taken for a curve whose points, smoothed,
 * stay within half the curve threshold of its chord: a straight piece whose
 * ridge jitters on the turf, not an arc of the circle. */
static bool joinable(const symline_segment *s, const symline_point *pts, uint32_t curve_q8)
{
    return s->kind == SYMLINE_KIND_LINE ||
           symline_i_smooth_dev(pts + s->first, s->count, 0u, s->x0, s->y0, s->x1, s->y1) <=
               curve_q8 / 2u;
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

/* Moves segment j's points right behind segment i's (i < j, ranges ordered), removes j. */
static void absorb(symline_result *r, uint32_t i, uint32_t j)
{
    symline_segment *a = &r->segments[i];
    const uint32_t b_first = r->segments[j].first, b_count = r->segments[j].count;
    const uint32_t mid0 = a->first + a->count;
    const uint32_t midn = b_first - mid0;
    uint32_t k;
    symline_i_reverse_points(r->points + mid0, midn);
    symline_i_reverse_points(r->points + b_first, b_count);
    symline_i_reverse_points(r->points + mid0, midn + b_count);
    for (k = i + 1u; k < j; k++) {
        r->segments[k].first += b_count;
    }
    a->count += b_count;
    for (k = j; k + 1u < r->segment_count; k++) {
        copy_segment(&r->segments[k], &r->segments[k + 1u]);
    }
    r->segment_count--;
}

void symline_i_merge(symline_result *r, uint32_t gap_px, uint32_t dev_q8, uint32_t curve_dev_q8)
{
    const uint64_t gap2 = ((uint64_t)gap_px << SL_Q8_SHIFT) * ((uint64_t)gap_px << SL_Q8_SHIFT);
    uint32_t i, j;
    bool changed = true;
    while (changed) {
        changed = false;
        for (i = 0; i < r->segment_count; i++) {
            /* Whether piece i may join at all does not change while it is
             * tried against the others (a join makes it a line): asked once,
             * not for every pair (that cost a cluttered 2560x1920 frame 10x
             * its detection time). */
            if (!joinable(&r->segments[i], r->points, curve_dev_q8)) {
                continue;
            }
            for (j = i + 1u; j < r->segment_count; j++) {
                int32_t ends[4];
                uint32_t dev;
                symline_segment *a = &r->segments[i];
                const symline_segment *b = &r->segments[j];
                const uint32_t level = a->level > b->level ? a->level : b->level;
                const uint32_t thr = curve_dev_q8 + symline_i_block_half_q8(level);
                /* The cheap geometric test first; both are pure, so the order
                 * changes nothing but the cost. */
                if (!mergeable(a, b, gap2, dev_q8 + symline_i_block_half_q8(level), ends) ||
                    !joinable(b, r->points, curve_dev_q8)) {
                    continue;
                }
                dev = joined_dev(a, b, r->points, ends, thr);
                if (dev == SL_JOINED_IS_CURVE) {
                    continue;
                }
                set_ends(a, ends[0], ends[1], ends[2], ends[3]);
                a->max_dev = dev;
                a->kind = SYMLINE_KIND_LINE;
                a->level = (uint8_t)level;
                a->merged = true; /* points piece after piece (curvejoin.c) */
                absorb(r, i, j);
                changed = true;
                j = i; /* the grown segment may now reach pieces it missed */
            }
        }
    }
}

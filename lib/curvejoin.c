/* SPDX-License-Identifier: Apache-2.0 */
/*
 * Curve continuation: a line piece that continues a curve smoothly is part of
 * that curve. The flat top and bottom of the centre circle seen from a robot's
 * height stay within a pixel or two of their chord, so on their own they pass
 * for lines; but they end where a curved piece of the circle begins (another
 * axis or scale traced it) and leave it in the same direction. A straight
 * field line meets the circle across it (the halfway line) or not at all, so
 * the direction test keeps lines that merely touch a curve.
 */
#include "curvejoin.h"

#include "fixed.h"

/* A curve's direction at an end is taken over up to this many points. */
#define SL_TANGENT_SPAN 8
/* Ends within 3 px of each other, plus the block size of the line's scale. */
#define SL_JOIN_TOL_Q8 SL_PX_Q8(3u)

/* Direction of line s in px, halved until both parts are within +-1023 so
 * that every product below stays in 32 bits. */
static void line_dir(const symline_segment *s, int32_t *dx, int32_t *dy)
{
    *dx = (s->x1 - s->x0) / (int32_t)SL_Q8_ONE;
    *dy = (s->y1 - s->y0) / (int32_t)SL_Q8_ONE;
    while (SL_OUTSIDE(*dx, 1023) || SL_OUTSIDE(*dy, 1023)) {
        *dx /= 2;
        *dy /= 2;
    }
}

/* True when line s continues curve c at one of c's ends: an end of s within tol
 * (Q8, in x and y) of it, s leaving that end where c came from, within 30
 * degrees. */
static bool continues(const symline_segment *s, const symline_segment *c, const symline_point *pts,
                      int32_t tol)
{
    const symline_point *p = pts + c->first;
    const int32_t last = (int32_t)c->count - 1;
    const int32_t j = last < SL_TANGENT_SPAN ? last : SL_TANGENT_SPAN;
    int32_t ldx, ldy, e;
    line_dir(s, &ldx, &ldy);
    for (e = 0; e < 4; e++) {
        /* e & 1: c's end (else its start); e & 2: s's end x1 (else x0). */
        const int32_t at = (e & 1) ? last : 0, in = (e & 1) ? last - j : j;
        const int32_t cdx = (int32_t)p[at].x - p[in].x, cdy = (int32_t)p[at].y - p[in].y;
        int32_t gx, gy; /* the gap between the two ends, Q8 */
        symline_i_pt_off(&p[at], 0u, NULL, &gx, &gy);
        gx -= (e & 2) ? s->x1 : s->x0;
        gy -= (e & 2) ? s->y1 : s->y0;
        /* s leaves its end x1 along +dir, its end x0 along -dir; continuing c
         * means leaving against c's outward direction. */
        const int32_t dot = (e & 2) ? -(ldx * cdx + ldy * cdy) : ldx * cdx + ldy * cdy;
        /* Ends within tol in x and y; cos^2 >= 3/4 (within 30 degrees), where
         * |c| <= 8 * sqrt(2) and |l| < 1448 keep the products in 32 bits. */
        if (!SL_OUTSIDE(gx, tol) && !SL_OUTSIDE(gy, tol) && dot > 0 &&
            4 * dot * dot >= 3 * (ldx * ldx + ldy * ldy) * (cdx * cdx + cdy * cdy)) {
            return true;
        }
    }
    return false;
}

/* Whether point q can lie within tol (Q8, in x and y) of an end of s, by
 * its pixel (half a pixel more): a cheap test before continues(), since
 * every curve is asked for every line. */
static bool near_end(const symline_point *q, const symline_segment *s, int32_t tol)
{
    const int32_t m = tol + (int32_t)SL_Q8_ONE / 2;
    const int32_t x = (int32_t)q->x << SL_Q8_SHIFT, y = (int32_t)q->y << SL_Q8_SHIFT;
    return (!SL_OUTSIDE(x - s->x0, m) && !SL_OUTSIDE(y - s->y0, m)) ||
           (!SL_OUTSIDE(x - s->x1, m) && !SL_OUTSIDE(y - s->y1, m));
}

void symline_i_curve_join(symline_result *r)
{
    uint32_t i, k;
    /* One round in storage order: passes run fine scale first, horizontal
     * before vertical, so most flat pieces come after the curve they continue. */
    for (i = 0; i < r->segment_count; i++) {
        symline_segment *s = &r->segments[i];
        const int32_t tol = (int32_t)(SL_JOIN_TOL_Q8 + symline_i_block_q8(s->level));
        /* A merged line has its points piece after piece, not in one run a
         * curve could be drawn through. */
        for (k = 0; s->kind == SYMLINE_KIND_LINE && !s->merged && k < r->segment_count; k++) {
            const symline_segment *c = &r->segments[k];
            if (c->kind == SYMLINE_KIND_CURVE &&
                (near_end(&r->points[c->first], s, tol) ||
                 near_end(&r->points[c->first + c->count - 1u], s, tol)) &&
                continues(s, c, r->points, tol)) {
                s->kind = SYMLINE_KIND_CURVE;
            }
        }
    }
}

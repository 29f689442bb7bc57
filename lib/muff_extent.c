/* SPDX-License-Identifier: Apache-2.0 */
/*
 * Muff lines as segments: which line points support a peak's line, where
 * along the line they lie, and the fitted segment over their extent.
 *
 * Everything is done in the line's dominant-axis frame (u along the axis the
 * line runs closer to, v across it), so the position along the line is
 * simply u: one counter per pixel of the longer side finds the longest run
 * of supporting points without a gap, and the fit is a least-squares v(u)
 * with |dv/du| near 1 at most, well conditioned.
 */
#include "muff_internal.h"

#include "fixed.h"

static uint32_t sec16_of(int32_t slope16)
{
    return (uint32_t)symline_i_isqrt64(((uint64_t)1u << 32) +
                                       (uint64_t)((int64_t)slope16 * slope16));
}

void symline_i_uvline_through(symline_i_uvline *l, uint32_t ax, uint32_t ay, uint32_t bx,
                              uint32_t by)
{
    const int32_t dx = (int32_t)bx - (int32_t)ax, dy = (int32_t)by - (int32_t)ay;
    const int32_t adx = dx < 0 ? -dx : dx, ady = dy < 0 ? -dy : dy;
    l->u_is_y = (uint8_t)(ady > adx);
    if (!l->u_is_y) {
        l->u0 = (int32_t)(ax << 8);
        l->v0 = (int32_t)(ay << 8);
        l->slope16 = dx != 0 ? (int32_t)(((int64_t)dy * 65536) / dx) : 0;
    } else {
        l->u0 = (int32_t)(ay << 8);
        l->v0 = (int32_t)(ax << 8);
        l->slope16 = (int32_t)(((int64_t)dx * 65536) / dy);
    }
    l->sec16 = sec16_of(l->slope16);
}

/* v (Q8) of the line at u (Q8). */
static int32_t v_at(const symline_i_uvline *l, int32_t u8)
{
    const int64_t t = (int64_t)l->slope16 * (u8 - l->u0);
    return l->v0 + (int32_t)(t >= 0 ? (t + 32768) >> 16 : -((-t + 32768) >> 16));
}

/* u and v of a point in Q8 px, its sub-pixel offset (1/128 px) included. */
static int32_t u_q8(const symline_i_uvline *l, const symline_point *p)
{
    return l->u_is_y ? (int32_t)(p->y << 8) + 2 * p->fy : (int32_t)(p->x << 8) + 2 * p->fx;
}

static int32_t v_q8(const symline_i_uvline *l, const symline_point *p)
{
    return l->u_is_y ? (int32_t)(p->x << 8) + 2 * p->fx : (int32_t)(p->y << 8) + 2 * p->fy;
}

/* |v distance| (Q8) of point p to l; the pixel u of p in *u. */
static uint32_t v_dist(const symline_i_uvline *l, const symline_point *p, uint32_t *u)
{
    const int32_t d = v_q8(l, p) - v_at(l, u_q8(l, p));
    *u = l->u_is_y ? p->y : p->x;
    return (uint32_t)(d < 0 ? -d : d);
}

/* Longest (most points) run of non-empty bins [*lo, *hi] without a gap above gap; its points. */
static uint32_t best_run(const uint16_t *bins, uint32_t umax, uint32_t gap, uint32_t *lo,
                         uint32_t *hi)
{
    uint32_t u, start = 0u, last = 0u, sum = 0u, best = 0u;
    for (u = 0; u <= umax; u++) {
        if (bins[u] == 0u) {
            continue;
        }
        if (sum != 0u && u - last > gap) {
            if (sum > best) {
                best = sum;
                *lo = start;
                *hi = last;
            }
            sum = 0u;
        }
        if (sum == 0u) {
            start = u;
        }
        sum += bins[u];
        last = u;
    }
    if (sum > best) {
        best = sum;
        *lo = start;
        *hi = last;
    }
    return best;
}

/* 1 when the non-empty bins cover at least fill_pct % of [lo, hi]; gaps of up
 * to `skip` bins count as covered (a coarse scale's points lie 2^level px
 * apart). Collinear clutter (nets, spectators) fails it: its points line up
 * only here and there. */
static int well_filled(const uint16_t *bins, uint32_t lo, uint32_t hi, uint32_t skip,
                       uint32_t fill_pct)
{
    uint32_t u, empty = 0u, last = lo;
    for (u = lo + 1u; u <= hi; u++) {
        if (bins[u] != 0u) {
            const uint32_t g = u - last - 1u;
            empty += g > skip ? g - skip : 0u;
            last = u;
        }
    }
    return (uint64_t)empty * 100u <= (uint64_t)(100u - fill_pct) * (hi - lo + 1u);
}

/* Least-squares v(u) through the k gathered points, in l's frame. */
void symline_i_extent_fit(const symline_i_extent *e, uint32_t n, const symline_i_uvline *l,
                          symline_i_uvline *out)
{
    const symline_point *p = e->pts + e->used;
    uint64_t su = 0u, sv = 0u;
    int64_t cuu = 0, cuv = 0;
    int32_t mu4, mv4;
    uint32_t k;
    if (n == 0u) {
        return;
    }
    /* sums in Q4 px (coordinates are >= -1/2 px: sub-pixel offsets at 0 stay
     * above -64/128, so +8 keeps them non-negative) */
    for (k = 0; k < n; k++) {
        su += (uint64_t)((u_q8(l, &p[k]) + 128) >> 4);
        sv += (uint64_t)((v_q8(l, &p[k]) + 128) >> 4);
    }
    mu4 = (int32_t)((su + n / 2u) / n) - 8;
    mv4 = (int32_t)((sv + n / 2u) / n) - 8;
    for (k = 0; k < n; k++) {
        const int64_t du = (int64_t)(((u_q8(l, &p[k]) + 128) >> 4) - 8) - mu4;
        const int64_t dv = (int64_t)(((v_q8(l, &p[k]) + 128) >> 4) - 8) - mv4;
        cuu += du * du;
        cuv += du * dv;
    }
    /* keep cuv * 2^16 within 64 bits */
    while (cuv > ((int64_t)1 << 46) || cuv < -((int64_t)1 << 46)) {
        cuv /= 2;
        cuu /= 2;
    }
    out->u_is_y = l->u_is_y;
    out->u0 = mu4 * 16;
    out->v0 = mv4 * 16;
    out->slope16 = cuu > 0 ? (int32_t)((cuv * 65536) / cuu) : 0;
    if (out->slope16 > (1 << 17)) {
        out->slope16 = 1 << 17;
    } else if (out->slope16 < -(1 << 17)) {
        out->slope16 = -(1 << 17);
    }
    out->sec16 = sec16_of(out->slope16);
}

static int32_t clamp_q8(int32_t v, uint32_t max_px)
{
    const int32_t hi = (int32_t)(max_px << 8);
    return v < 0 ? 0 : (v > hi ? hi : v);
}

/* Swaps two points field by field (a struct copy may become a memcpy call). */
static void swap_points(symline_point *a, symline_point *b)
{
    const uint16_t x = a->x, y = a->y;
    const int8_t fx = a->fx, fy = a->fy;
    a->x = b->x;
    a->y = b->y;
    a->fx = b->fx;
    a->fy = b->fy;
    b->x = x;
    b->y = y;
    b->fx = fx;
    b->fy = fy;
}

void symline_i_extent_segment(const symline_i_extent *e, const symline_i_uvline *ft, uint32_t cnt,
                              symline_segment *s)
{
    const uint32_t vmax = (ft->u_is_y ? e->width : e->height) - 1u;
    const uint32_t lo = e->lo, hi = e->hi;
    uint32_t k, u, dev = 0u;
    int32_t v_lo, v_hi;
    for (k = 0; k < cnt; k++) {
        const uint32_t d = v_dist(ft, &e->pts[e->used + k], &u);
        dev = d > dev ? d : dev;
    }
    v_lo = clamp_q8(v_at(ft, (int32_t)(lo << 8)), vmax);
    v_hi = clamp_q8(v_at(ft, (int32_t)(hi << 8)), vmax);
    if (!ft->u_is_y) {
        s->x0 = (int32_t)(lo << 8);
        s->y0 = v_lo;
        s->x1 = (int32_t)(hi << 8);
        s->y1 = v_hi;
    } else {
        s->x0 = v_lo;
        s->y0 = (int32_t)(lo << 8);
        s->x1 = v_hi;
        s->y1 = (int32_t)(hi << 8);
    }
    s->max_dev = (uint32_t)(((uint64_t)dev << 16) / ft->sec16);
    s->first = e->used;
    s->count = cnt;
    s->kind = SYMLINE_KIND_LINE;
    /* The axis as muff.h defines it, from the end points: a fit parametrised
     * along y can still end up flatter than 45 degrees. */
    {
        const int32_t dx = s->x1 - s->x0, dy = s->y1 - s->y0;
        const uint32_t adx = (uint32_t)(dx < 0 ? -dx : dx), ady = (uint32_t)(dy < 0 ? -dy : dy);
        s->axis = (uint8_t)(adx >= ady ? SYMLINE_AXIS_HORIZONTAL : SYMLINE_AXIS_VERTICAL);
    }
    s->level = 0u;
    s->merged = false;
}

uint32_t symline_i_extent_gather(symline_i_extent *e, const symline_i_uvline *l, uint32_t tol_q8)
{
    const uint32_t umax = (l->u_is_y ? e->height : e->width) - 1u;
    const uint64_t lim = (uint64_t)tol_q8 * l->sec16; /* |dv| * 2^16 <= tol * sec */
    uint32_t k, u, lo = 0u, hi = 0u, cnt = 0u;
    for (u = 0; u <= umax; u++) {
        e->bins[u] = 0u;
    }
    for (k = e->used; k < e->n; k++) {
        if (((uint64_t)v_dist(l, &e->pts[k], &u) << 16) <= lim && e->bins[u] != 0xFFFFu) {
            e->bins[u]++;
        }
    }
    if (best_run(e->bins, umax, e->gap, &lo, &hi) < e->cfg->min_points ||
        !well_filled(e->bins, lo, hi, e->width / 160u, e->cfg->min_fill_pct)) {
        return 0u;
    }
    for (k = e->used; k < e->n; k++) {
        if (((uint64_t)v_dist(l, &e->pts[k], &u) << 16) <= lim && u >= lo && u <= hi) {
            swap_points(&e->pts[e->used + cnt], &e->pts[k]);
            cnt++;
        }
    }
    if (cnt < e->cfg->min_points ||
        (uint64_t)(hi - lo) * l->sec16 < ((uint64_t)e->cfg->min_length << 16)) {
        return 0u;
    }
    e->lo = lo;
    e->hi = hi;
    return cnt;
}

/* SPDX-License-Identifier: Apache-2.0 */
/*
 * Intersections of detected segments (L, T, X): every line is crossed with
 * every other line and with every curve (a polyline through every few of its
 * points); crossings of one junction are gathered into one intersection whose
 * rays are the pieces leaving it. Two curves are not crossed with each other:
 * where two curves meet end to end is the centre circle cut by the tracer at
 * its sharpest bend, not a corner, and curves crossing each other are rare.
 * Works on segments only, never on pixels; the caller's output array doubles
 * as the list of junctions gathered so far, so no other memory is needed.
 *
 * Geometry runs in 32-bit integers only: coordinates in internal units of
 * 2^shift Q8 units, chosen per call so that they stay below 2^14 (quarter
 * pixels up to 4095 px, coarser on larger frames); then every product of two
 * differences fits 31 bits, and no 64-bit division (a library routine with a
 * large stack frame on small cores) is needed.
 */
#include "intersections.h"

#include "common.h" /* SL_NOINLINE */

/* Largest |coordinate| of a segment end, Q8 (65535 px). */
#define IX_COORD_MAX ((int32_t)(SYMLINE_MAX_DIM << 8))
/* Scale levels above this do not widen the gap further. */
#define IX_LEVEL_MAX 5u
/* A curve's polyline takes every 8th point at full resolution (chords of
 * 8-11 px, within 0.1 px of a circle of 100 px radius), fewer at coarser
 * scales (points 2^level px apart), every point from scale 3 on. */
static const uint8_t IX_STEPS[IX_LEVEL_MAX + 1u] = {8u, 4u, 2u, 1u, 1u, 1u};
/* A stem meeting a bar at angle a stops short of it by about (half the bar's
 * width) / sin(a): the gap grows with 1/sin of the angle between the two,
 * up to this factor (sin >= 1/4, angles >= 14.5 degrees). */
#define IX_GAP_GROWTH 4u
#define IX_DEG_180 (180u * 256u)
#define IX_DEG_90 (90u * 256u)

void symline_intersection_config_default(symline_intersection_config *cfg)
{
    if (cfg == NULL) {
        return;
    }
    cfg->min_angle_q8 = 20u * 256u;
    cfg->gap_q8 = 10u * 256u;
    cfg->gap_pct = 50u;
    cfg->arm_q8 = 10u * 256u;
    cfg->merge_q8 = 10u * 256u;
    cfg->min_length_q8 = 16u * 256u;
}

/* ---- integer helpers ---- */

/* atan(k/32) in Q8 degrees, k = 0..32. */
static const uint16_t ATAN_Q8[33] = {0,     458,   916,   1371,  1824,  2273, 2719, 3159, 3593,
                                     4021,  4443,  4856,  5262,  5660,  6049, 6429, 6801, 7163,
                                     7516,  7859,  8193,  8518,  8834,  9141, 9439, 9728, 10008,
                                     10280, 10544, 10799, 11047, 11287, 11520};

/* atan(lo/hi) in Q8 degrees for 0 <= lo <= hi, hi > 0: [0, 45*256]. */
static uint32_t atan_ratio(uint32_t lo, uint32_t hi)
{
    uint32_t t, i, f;
    while (hi >= 32768u) { /* keep lo << 16 in 32 bits; hi stays >= 2^14 */
        hi >>= 1;
        lo >>= 1;
    }
    t = (lo << 16) / hi; /* Q16, 0..65536 */
    i = t >> 11;
    f = t & 2047u;
    if (i >= 32u) {
        return ATAN_Q8[32];
    }
    return ATAN_Q8[i] + (((uint32_t)(ATAN_Q8[i + 1u] - ATAN_Q8[i]) * f + 1024u) >> 11);
}

uint32_t symline_i_heading_q8(int32_t dx, int32_t dy)
{
    const uint32_t ax = dx < 0 ? 0u - (uint32_t)dx : (uint32_t)dx;
    const uint32_t ay = dy < 0 ? 0u - (uint32_t)dy : (uint32_t)dy;
    uint32_t q;
    if (ax == 0u && ay == 0u) {
        return 0u;
    }
    q = ay <= ax ? atan_ratio(ay, ax) : IX_DEG_90 - atan_ratio(ax, ay); /* first quadrant */
    if (dx < 0) {
        q = dy < 0 ? IX_DEG_180 + q : IX_DEG_180 - q;
    } else if (dy < 0 && q != 0u) {
        q = SYMLINE_DEG_Q8_FULL - q;
    }
    return q;
}

/* Angle between two directions, [0, 180*256]. */
static uint32_t turn_between(uint32_t a, uint32_t b)
{
    const uint32_t d = a > b ? a - b : b - a;
    return d > IX_DEG_180 ? SYMLINE_DEG_Q8_FULL - d : d;
}

/* Angle between the lines carrying two directions, [0, 90*256]. */
static uint32_t lines_between(uint32_t a, uint32_t b)
{
    const uint32_t d = turn_between(a, b);
    return d > IX_DEG_90 ? IX_DEG_180 - d : d;
}

/* ---- a segment as a polyline ---- */

typedef struct ix_vec {
    int32_t x, y; /* internal units: Q8 >> shift */
} ix_vec;

typedef struct ix_params {
    uint32_t shift;     /* internal unit = 2^shift Q8 units (6: quarter pixels) */
    uint32_t min_angle; /* Q8 degrees */
    int32_t arm;        /* internal units, >= 1 */
    uint32_t merge;     /* Q8 px */
} ix_params;

/* A segment seen as a polyline, with its box and gap tolerance. */
typedef struct ix_poly {
    const symline_segment *s;
    const symline_point *pts; /* a curve's points, or NULL: the chord */
    const ix_params *ip;
    uint32_t n;       /* vertices, >= 2 */
    uint32_t step;    /* points from one vertex to the next */
    uint32_t index;   /* in the result's segments */
    ix_vec lo, hi;    /* box of the vertices grown by the gap */
    int32_t gap_base; /* how far a free end may stop short of a crossing met
                         at a right angle */
    int32_t gap;      /* ... at any angle: min(IX_GAP_GROWTH gap_base, gap_pct
                         of its size) */
} ix_poly;

typedef struct ix_hit {
    int32_t x, y;   /* internal units */
    int32_t ta, tb; /* Q16 along chord a, chord b */
} ix_hit;

/* Q8 -> internal units, rounding down (no shift of a negative value). */
static int32_t iu_of(int32_t v, uint32_t shift)
{
    return v >= 0 ? (int32_t)((uint32_t)v >> shift)
                  : -(int32_t)(((uint32_t)-v + (1u << shift) - 1u) >> shift);
}

static ix_vec vertex(const ix_poly *p, uint32_t k)
{
    const uint32_t sh = p->ip->shift;
    ix_vec v;
    if (p->pts == NULL) {
        v.x = iu_of(k == 0u ? p->s->x0 : p->s->x1, sh);
        v.y = iu_of(k == 0u ? p->s->y0 : p->s->y1, sh);
    } else {
        /* the point with its sub-pixel offset (1/128 px) */
        const symline_point *q = p->pts + (k + 1u >= p->n ? p->s->count - 1u : k * p->step);
        v.x = iu_of((int32_t)q->x * 256 + q->fx * 2, sh);
        v.y = iu_of((int32_t)q->y * 256 + q->fy * 2, sh);
    }
    return v;
}

/* Length of (dx, dy) within 7 % (max + 3/8 min), without a root. */
static uint32_t approx_len(int32_t dx, int32_t dy)
{
    const uint32_t ax = dx < 0 ? 0u - (uint32_t)dx : (uint32_t)dx;
    const uint32_t ay = dy < 0 ? 0u - (uint32_t)dy : (uint32_t)dy;
    return ax > ay ? ax + 3u * ay / 8u : ay + 3u * ax / 8u;
}

static int is_curve(const symline_segment *s)
{
    return s->kind == SYMLINE_KIND_CURVE && s->count >= 2u;
}

/* Segment i as a polyline: box, size and gaps. 0 when it takes no part
 * (smaller than the configured minimum length or than one arm: it could not
 * give a ray). The size is the chord, or for a curve its box when larger (a
 * closed loop). */
SL_NOINLINE static int poly_init(ix_poly *p, const symline_result *r, uint32_t i,
                                 const symline_intersection_config *c, const ix_params *ip)
{
    const symline_segment *s = &r->segments[i];
    const uint32_t level = s->level < IX_LEVEL_MAX ? s->level : IX_LEVEL_MAX;
    uint32_t k, size;
    int32_t g;
    ix_vec a, v;
    p->s = s;
    p->ip = ip;
    p->index = i;
    p->pts = NULL;
    p->n = 2u;
    if (is_curve(s)) {
        p->step = IX_STEPS[level];
        p->pts = r->points + s->first;
        p->n = (s->count - 1u + p->step - 1u) / p->step + 1u;
    }
    a = vertex(p, 0u);
    v = a;
    p->lo = a;
    p->hi = a;
    for (k = 1u; k < p->n; k++) {
        v = vertex(p, k);
        p->lo.x = v.x < p->lo.x ? v.x : p->lo.x;
        p->lo.y = v.y < p->lo.y ? v.y : p->lo.y;
        p->hi.x = v.x > p->hi.x ? v.x : p->hi.x;
        p->hi.y = v.y > p->hi.y ? v.y : p->hi.y;
    }
    size = approx_len(v.x - a.x, v.y - a.y);
    k = (uint32_t)(p->hi.x - p->lo.x) > (uint32_t)(p->hi.y - p->lo.y)
            ? (uint32_t)(p->hi.x - p->lo.x)
            : (uint32_t)(p->hi.y - p->lo.y);
    size = size > k ? size : k;
    if (size < (uint32_t)ip->arm || (size << ip->shift) < c->min_length_q8) {
        return 0;
    }
    p->gap_base = (int32_t)((c->gap_q8 * (level + 1u)) >> ip->shift);
    g = (int32_t)(size / 100u * c->gap_pct + size % 100u * c->gap_pct / 100u);
    p->gap = p->gap_base * (int32_t)IX_GAP_GROWTH < g ? p->gap_base * (int32_t)IX_GAP_GROWTH : g;
    p->lo.x -= p->gap;
    p->lo.y -= p->gap;
    p->hi.x += p->gap;
    p->hi.y += p->gap;
    return 1;
}

/* ---- crossing a chord with a line ---- */

/* |v| * 2^-16 * |t|, signed, for |v| < 2^15, |t| < 2^28 (Q16): 32 bits only. */
static int32_t q16_mul(int32_t v, int32_t t)
{
    const uint32_t av = v < 0 ? 0u - (uint32_t)v : (uint32_t)v;
    const uint32_t at = t < 0 ? 0u - (uint32_t)t : (uint32_t)t;
    const uint32_t m = av * (at >> 16) + ((av * ((at & 0xFFFFu) >> 1) + 16384u) >> 15);
    return (v < 0) != (t < 0) ? -(int32_t)m : (int32_t)m;
}

/* n / d in Q16 for |n| <= 4096 d, d > 0: both brought below 2^16 first, then
 * two 32-bit divisions. */
static int32_t q16_div(int32_t n, int32_t d)
{
    uint32_t an = n < 0 ? 0u - (uint32_t)n : (uint32_t)n, ud = (uint32_t)d, q, r, v;
    while (ud >= 65536u) {
        ud >>= 1;
        an >>= 1;
    }
    q = an / ud;
    r = an % ud;
    v = (q << 16) + ((r << 16) + ud / 2u) / ud;
    return n < 0 ? -(int32_t)v : (int32_t)v;
}

/* Is the crossing (x, y) at parameter t (Q16) of chord v0 -> v1 of p close
 * enough to it: on it, or beyond a free end by at most the gap there,
 * gap_base / sin(angle between the chords), at most p->gap?
 * `free_lo`, `free_hi`: the chord's start / end is a free end. */
SL_NOINLINE static int near_chord(const ix_poly *p, int32_t t, ix_vec x, ix_vec v0, ix_vec v1,
                                  int free_lo, int free_hi, uint32_t sin_q8)
{
    uint32_t d;
    if (t >= 0 && t <= 65536) {
        return t < 65536 || free_hi;
    }
    if ((t < 0 && !free_lo) || (t > 65536 && !free_hi)) {
        return 0;
    }
    d = t < 0 ? approx_len(x.x - v0.x, x.y - v0.y) : approx_len(x.x - v1.x, x.y - v1.y);
    return d <= (uint32_t)p->gap && d * sin_q8 <= (uint32_t)p->gap_base * 256u;
}

/* Crossing of chord ka of a with the line b. Differences of coordinates stay
 * below 2^15 internal units, so every product fits 31 bits. */
SL_NOINLINE static int cross(const ix_poly *a, uint32_t ka, const ix_poly *b, ix_hit *h)
{
    const ix_vec p0 = vertex(a, ka), p1 = vertex(a, ka + 1u);
    const ix_vec q0 = vertex(b, 0u), q1 = vertex(b, 1u);
    const int32_t rx = p1.x - p0.x, ry = p1.y - p0.y;
    const int32_t sx = q1.x - q0.x, sy = q1.y - q0.y;
    const int32_t wx = q0.x - p0.x, wy = q0.y - p0.y;
    int32_t den = rx * sy - ry * sx, nt = wx * sy - wy * sx, nu = wx * ry - wy * rx;
    uint32_t lrs, sin_q8;
    ix_vec x;
    if (den < 0) {
        den = -den;
        nt = -nt;
        nu = -nu;
    }
    /* parallel, off an inner chord of a curve, or beyond 4096 chord lengths
     * (the gap decides below) */
    if (den == 0 || (ka != 0u && nt < 0) || (ka + 2u < a->n && nt >= den) ||
        (nt < 0 ? -nt : nt) / 4096 > den || (nu < 0 ? -nu : nu) / 4096 > den) {
        return 0;
    }
    h->ta = q16_div(nt, den);
    h->tb = q16_div(nu, den);
    x.x = p0.x + q16_mul(rx, h->ta);
    x.y = p0.y + q16_mul(ry, h->ta);
    h->x = x.x;
    h->y = x.y;
    /* sin of the angle between the chords, Q8: den / (|r| |s|), at most 1 (the
     * lengths are approximate) */
    lrs = approx_len(rx, ry) * approx_len(sx, sy);
    sin_q8 = lrs > 1u ? (uint32_t)q16_div(den, (int32_t)(lrs >> 1)) >> 9 : 256u;
    sin_q8 = sin_q8 < 256u ? sin_q8 : 256u;
    /* a crossing on a vertex between two chords of a curve counts once */
    return near_chord(a, h->ta, x, p0, p1, ka == 0u, ka + 2u == a->n, sin_q8) &&
           near_chord(b, h->tb, x, q0, q1, 1, 1, sin_q8);
}

/* ---- rays ---- */

/* The piece of p leaving the crossing (x, y), found on chord k at t (Q16),
 * toward p's start (back) or end: 1 with its far point when p goes on for at
 * least one arm past the crossing. The far point lies two arms along p (a
 * curve: exactly, between vertices) or at p's end (a line: its end, so its
 * ray has the direction of its whole chord). Part of a gap bridged beyond a
 * free end does not count as going on. */
static int ray_of(const ix_poly *p, uint32_t k, int32_t t, int32_t x, int32_t y, int back,
                  const ix_params *ip, ix_vec *far)
{
    const uint32_t reach = 2u * (uint32_t)ip->arm;
    uint32_t v, acc = 0u;
    ix_vec prev, w;
    if ((back && t < 0) || (!back && t > 65536)) {
        return 0; /* the crossing lies beyond this end */
    }
    prev.x = x;
    prev.y = y;
    if (t < 0 || t > 65536) {
        prev = vertex(p, t < 0 ? 0u : p->n - 1u);
    }
    v = back ? k : k + 1u;
    for (;;) {
        uint32_t len;
        w = vertex(p, v);
        len = approx_len(w.x - prev.x, w.y - prev.y);
        if (acc + len >= reach && p->pts != NULL) {
            /* the point at `reach`: r = share of this chord, Q16 */
            const int32_t r = (int32_t)(((reach - acc) << 16) / len);
            w.x = prev.x + q16_mul(w.x - prev.x, r);
            w.y = prev.y + q16_mul(w.y - prev.y, r);
            acc = reach;
            break;
        }
        acc += len;
        if (acc >= reach || (back ? v == 0u : v + 1u == p->n)) {
            break;
        }
        prev = w;
        v = back ? v - 1u : v + 1u;
    }
    *far = w;
    return acc >= (uint32_t)ip->arm;
}

/* The rays of p at a crossing on its chord k: 0, 1 or 2 into rays[]. A curve
 * going on both ways takes its tangent from the chord between the two far
 * points, which is parallel to the tangent on a circle (a chord from the
 * crossing to one far point is off by half the arc's turn). */
SL_NOINLINE static uint32_t rays_of(const ix_poly *p, uint32_t k, const ix_hit *h, int32_t t,
                                    const ix_params *ip, uint32_t *rays)
{
    ix_vec back = {0, 0}, fwd = {0, 0};
    const int hb = ray_of(p, k, t, h->x, h->y, 1, ip, &back);
    const int hf = ray_of(p, k, t, h->x, h->y, 0, ip, &fwd);
    uint32_t n = 0u;
    if (hb && hf && p->pts != NULL) {
        rays[1] = symline_i_heading_q8(fwd.x - back.x, fwd.y - back.y);
        rays[0] = (rays[1] + IX_DEG_180) % SYMLINE_DEG_Q8_FULL;
        return 2u;
    }
    if (hb) {
        rays[n++] = symline_i_heading_q8(back.x - h->x, back.y - h->y);
    }
    if (hf) {
        rays[n++] = symline_i_heading_q8(fwd.x - h->x, fwd.y - h->y);
    }
    return n;
}

/* ---- gathering crossings into intersections ---- */

/* Adds v to the ascending list of n (< cap) values unless an equal one, or
 * for rays one closer than min_angle, is there. */
static void add_sorted(uint32_t *list, uint8_t *n, uint32_t cap, uint32_t v, uint32_t min_angle,
                       int is_ray)
{
    uint32_t i, k = *n;
    for (i = 0; i < k; i++) {
        if (list[i] == v || (is_ray && turn_between(list[i], v) < min_angle)) {
            return; /* the same piece, seen from another pair */
        }
    }
    if (k >= cap) {
        return;
    }
    for (i = k; i > 0u && list[i - 1u] > v; i--) {
        list[i] = list[i - 1u];
    }
    list[i] = v;
    *n = (uint8_t)(k + 1u);
}

/* The rays of a crossing of a and b into rays[]: their number, or 0 when
 * either gives none or the two meet at less than the minimum angle (one line
 * continuing, or parallel lines). Pieces on one line (angle 0) never meet,
 * also with a minimum angle of 0: their rays would count once, and an
 * intersection needs two. */
SL_NOINLINE static uint32_t hit_rays(const ix_poly *a, uint32_t ka, const ix_poly *b,
                                     const ix_hit *h, const ix_params *ip, uint32_t *rays)
{
    const uint32_t na = rays_of(a, ka, h, h->ta, ip, rays);
    uint32_t nr;
    if (na == 0u) {
        return 0u;
    }
    nr = na + rays_of(b, 0u, h, h->tb, ip, rays + na);
    return nr == na || lines_between(rays[0], rays[na]) < (ip->min_angle != 0u ? ip->min_angle : 1u)
               ? 0u
               : nr;
}

/* The crossing h of segments sa and sb with its rays joins the intersection
 * within the merge distance, or starts a new one. */
SL_NOINLINE static void gather(symline_intersection_result *out, const ix_params *ip,
                               const ix_hit *h, const uint32_t *rays, uint32_t nr, uint32_t sa,
                               uint32_t sb)
{
    /* back to Q8 (an accepted crossing lies within a gap of the frame) */
    const int32_t x = h->x * (int32_t)(1u << ip->shift), y = h->y * (int32_t)(1u << ip->shift);
    symline_intersection *it = NULL;
    uint32_t i;
    for (i = 0; i < out->count && it == NULL; i++) {
        if (approx_len(out->items[i].x - x, out->items[i].y - y) <= ip->merge) {
            it = &out->items[i];
        }
    }
    if (it == NULL) {
        if (out->count >= out->cap) {
            out->truncated = 1u;
            return;
        }
        it = &out->items[out->count++];
        it->x = x;
        it->y = y;
        it->ray_count = 0u;
        it->segment_count = 0u;
        it->support = 0u;
    } else if (it->support < 255u) {
        /* running mean of the crossings gathered here */
        it->x += (x - it->x) / ((int32_t)it->support + 1);
        it->y += (y - it->y) / ((int32_t)it->support + 1);
    }
    if (it->support < 255u) {
        it->support++;
    }
    for (i = 0; i < nr; i++) {
        add_sorted(it->rays, &it->ray_count, SYMLINE_INTERSECTION_RAYS, rays[i], ip->min_angle, 1);
    }
    add_sorted(it->segments, &it->segment_count, SYMLINE_INTERSECTION_SEGMENTS, sa, 0u, 0);
    add_sorted(it->segments, &it->segment_count, SYMLINE_INTERSECTION_SEGMENTS, sb, 0u, 0);
    it->type = (uint8_t)(it->ray_count - 2u);
}

/* ---- arguments ---- */

static uint32_t abs_of(int32_t v)
{
    return v < 0 ? 0u - (uint32_t)v : (uint32_t)v;
}

/* Checks the arguments; *shift: the internal unit (2^shift Q8 units) that
 * keeps every coordinate below 2^14 units (Q2 for frames up to 4095 px). */
SL_NOINLINE static symline_status check_args(const symline_result *r,
                                             const symline_intersection_config *c, uint32_t *shift)
{
    uint32_t i, k, top = 1u; /* largest |coordinate|, Q8 */
    if (c->min_angle_q8 > IX_DEG_90 || c->gap_q8 > 65536u || c->gap_pct > 100u ||
        c->arm_q8 < 256u || c->arm_q8 > 65536u || c->merge_q8 > 65536u ||
        c->min_length_q8 > (SYMLINE_MAX_DIM << 8)) {
        return SYMLINE_ERR_CONFIG;
    }
    if (r->segment_count > 0u && r->segments == NULL) {
        return SYMLINE_ERR_NULL;
    }
    if (r->segment_count > r->segment_cap || r->point_count > r->point_cap) {
        return SYMLINE_ERR_RANGE;
    }
    for (i = 0; i < r->segment_count; i++) {
        const symline_segment *s = &r->segments[i];
        const uint32_t ax = abs_of(s->x0) > abs_of(s->x1) ? abs_of(s->x0) : abs_of(s->x1);
        const uint32_t ay = abs_of(s->y0) > abs_of(s->y1) ? abs_of(s->y0) : abs_of(s->y1);
        if ((s->kind != SYMLINE_KIND_LINE && s->kind != SYMLINE_KIND_CURVE) ||
            ax > (uint32_t)IX_COORD_MAX || ay > (uint32_t)IX_COORD_MAX) {
            return SYMLINE_ERR_RANGE;
        }
        top |= ax | ay; /* the bit length is what counts */
        if (is_curve(s)) {
            if (r->points == NULL) {
                return SYMLINE_ERR_NULL;
            }
            if (s->count > r->point_count || s->first > r->point_count - s->count) {
                return SYMLINE_ERR_RANGE;
            }
            for (k = 0; k < s->count; k++) {
                top |=
                    ((uint32_t)r->points[s->first + k].x | r->points[s->first + k].y) * 256u + 255u;
            }
        }
    }
    /* top < 2^(14 + shift) */
    for (*shift = 6u; (top >> (14u + *shift)) != 0u; (*shift)++) {
    }
    return SYMLINE_OK;
}

symline_status symline_intersections(const symline_result *lines,
                                     const symline_intersection_config *cfg,
                                     symline_intersection_result *out)
{
    ix_params ip;
    uint32_t i, j, k;
    symline_status st;
    if (lines == NULL || cfg == NULL || out == NULL || (out->items == NULL && out->cap > 0u)) {
        return SYMLINE_ERR_NULL;
    }
    st = check_args(lines, cfg, &ip.shift);
    if (st != SYMLINE_OK) {
        return st;
    }
    ip.min_angle = cfg->min_angle_q8;
    ip.arm = (int32_t)(cfg->arm_q8 >> ip.shift);
    ip.arm = ip.arm > 0 ? ip.arm : 1;
    ip.merge = cfg->merge_q8;
    out->count = 0u;
    out->truncated = 0u;
    /* Each line with every later line and with every curve; a curve is the
     * outer polyline, walked chord by chord against the line's box. */
    for (i = 0; i < lines->segment_count; i++) {
        ix_poly a;
        if (!poly_init(&a, lines, i, cfg, &ip)) {
            continue;
        }
        for (j = a.pts != NULL ? 0u : i + 1u; j < lines->segment_count; j++) {
            const symline_segment *sj = &lines->segments[j];
            /* first the box of its ends (Q8) grown by its largest possible gap */
            const int32_t gj =
                (int32_t)((cfg->gap_q8 *
                           ((sj->level < IX_LEVEL_MAX ? sj->level : IX_LEVEL_MAX) + 1u) *
                           IX_GAP_GROWTH) >>
                          ip.shift);
            ix_poly b;
            if (is_curve(sj) || iu_of(sj->x0 < sj->x1 ? sj->x0 : sj->x1, ip.shift) - gj > a.hi.x ||
                iu_of(sj->x0 > sj->x1 ? sj->x0 : sj->x1, ip.shift) + gj < a.lo.x ||
                iu_of(sj->y0 < sj->y1 ? sj->y0 : sj->y1, ip.shift) - gj > a.hi.y ||
                iu_of(sj->y0 > sj->y1 ? sj->y0 : sj->y1, ip.shift) + gj < a.lo.y ||
                !poly_init(&b, lines, j, cfg, &ip) || b.lo.x > a.hi.x || a.lo.x > b.hi.x ||
                b.lo.y > a.hi.y || a.lo.y > b.hi.y) {
                continue;
            }
            for (k = 0; k + 1u < a.n; k++) {
                const ix_vec v0 = vertex(&a, k), v1 = vertex(&a, k + 1u);
                /* the chord's box, grown by the gap at a free end only */
                const int32_t g = (k == 0u || k + 2u == a.n) ? a.gap : 0;
                ix_hit h;
                uint32_t rays[4], nr;
                if ((v0.x < v1.x ? v0.x : v1.x) - g <= b.hi.x &&
                    (v0.x > v1.x ? v0.x : v1.x) + g >= b.lo.x &&
                    (v0.y < v1.y ? v0.y : v1.y) - g <= b.hi.y &&
                    (v0.y > v1.y ? v0.y : v1.y) + g >= b.lo.y && cross(&a, k, &b, &h) &&
                    (nr = hit_rays(&a, k, &b, &h, &ip, rays)) != 0u) {
                    gather(out, &ip, &h, rays, nr, a.index, b.index);
                }
            }
        }
    }
    return SYMLINE_OK;
}

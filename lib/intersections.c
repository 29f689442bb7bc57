/*
 * Intersections of detected segments (L, T, X): pairs of segments are
 * crossed as polylines (a line: its two ends; a curve: every few of its
 * points), crossings of one junction are gathered into one intersection
 * whose rays are the pieces leaving it. Works on segments only, never on
 * pixels; the caller's output array doubles as the list of junctions
 * gathered so far, so no other memory is needed.
 *
 * Geometry runs in Q4 pixels (1/16 px): coordinates up to 65535 px fit 21
 * bits, so every cross product of two differences fits 44 bits of int64.
 */
#include "intersections.h"

#include "detect_internal.h" /* sl_isqrt64, SL_NOINLINE */

/* Largest |coordinate| of a segment end, Q8 (65535 px). */
#define IX_COORD_MAX ((int32_t)(SYMLINE_MAX_DIM << 8))
/* A curve's polyline takes every IX_STEP-th point at full resolution (about
 * 4-6 px chords), every point from scale 2 on (points 4 px apart there). */
#define IX_STEP 4u
/* A stem meeting a bar at angle a stops short of it by about (half the bar's
 * width) / sin(a): the gap grows with 1/sin of the angle between the two,
 * up to this factor (sin >= 1/4, angles >= 14.5 degrees). */
#define IX_SIN_MIN_Q8 64
/* Scale levels above this do not widen the gap further. */
#define IX_LEVEL_MAX 5u
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
static const uint16_t ATAN_Q8[33] = {
    0,    458,  916,  1371, 1824, 2273, 2719, 3159, 3593,  4021,  4443,
    4856, 5262, 5660, 6049, 6429, 6801, 7163, 7516, 7859,  8193,  8518,
    8834, 9141, 9439, 9728, 10008, 10280, 10544, 10799, 11047, 11287, 11520};

/* atan(lo/hi) in Q8 degrees for 0 <= lo <= hi, hi > 0: [0, 45*256]. */
static uint32_t atan_ratio(uint64_t lo, uint64_t hi)
{
    uint32_t t, i, f;
    while (hi >= 32768u) { /* keep lo << 16 in 32 bits; hi stays >= 2^14 */
        hi >>= 1;
        lo >>= 1;
    }
    t = (uint32_t)((lo << 16) / hi); /* Q16, 0..65536 */
    i = t >> 11;
    f = t & 2047u;
    if (i >= 32u) {
        return ATAN_Q8[32];
    }
    return ATAN_Q8[i] + (((uint32_t)(ATAN_Q8[i + 1u] - ATAN_Q8[i]) * f + 1024u) >> 11);
}

uint32_t sl_heading_q8(int64_t dx, int64_t dy)
{
    const uint64_t ax = (uint64_t)(dx < 0 ? -dx : dx), ay = (uint64_t)(dy < 0 ? -dy : dy);
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
    int32_t x, y; /* Q4 */
} ix_vec;

/* A segment seen as a polyline, with its box and gap tolerance. */
typedef struct ix_poly {
    const symline_point *pts; /* a curve's points, or NULL: the chord */
    uint32_t n;               /* vertices, >= 2 */
    uint32_t step;            /* points from one vertex to the next */
    uint32_t last;            /* index of the curve's last point */
    uint32_t index;           /* in the result's segments */
    ix_vec a, b;              /* chord ends */
    ix_vec lo, hi;            /* box of the vertices grown by the gap */
    int32_t gap_base;         /* how far a free end may stop short of a crossing
                                 meeting at a right angle */
    int32_t gap_cap;          /* ... and at any angle (part of the length) */
    int32_t gap;              /* the largest of those: min(4 * gap_base, gap_cap) */
} ix_poly;

typedef struct ix_params {
    uint32_t min_angle; /* Q8 degrees */
    int32_t arm;        /* Q4 px */
    int64_t merge2;     /* (Q8 px)^2 */
} ix_params;

/* Q8 -> Q4, rounding down. */
static int32_t q4_of(int32_t v)
{
    return v >= 0 ? v / 16 : -((15 - v) / 16);
}

static ix_vec vertex(const ix_poly *p, uint32_t k)
{
    ix_vec v;
    if (p->pts == NULL) {
        v = k == 0u ? p->a : p->b;
    } else {
        const symline_point *q = p->pts + (k + 1u >= p->n ? p->last : k * p->step);
        v.x = (int32_t)q->x * 16;
        v.y = (int32_t)q->y * 16;
    }
    return v;
}

static int64_t dist2(int64_t dx, int64_t dy)
{
    return dx * dx + dy * dy;
}

static uint32_t length_of(ix_vec a, ix_vec b)
{
    return (uint32_t)sl_isqrt64((uint64_t)dist2((int64_t)b.x - a.x, (int64_t)b.y - a.y));
}

static void grow_box(ix_poly *p, ix_vec v)
{
    p->lo.x = v.x < p->lo.x ? v.x : p->lo.x;
    p->lo.y = v.y < p->lo.y ? v.y : p->lo.y;
    p->hi.x = v.x > p->hi.x ? v.x : p->hi.x;
    p->hi.y = v.y > p->hi.y ? v.y : p->hi.y;
}

/* Segment i as a polyline; 0 when it takes no part (smaller than the
 * configured minimum length or than one arm: it could not give a ray). */
static int poly_init(ix_poly *p, const symline_result *r, uint32_t i,
                     const symline_intersection_config *c, const ix_params *ip)
{
    const symline_segment *s = &r->segments[i];
    const uint32_t level = s->level < IX_LEVEL_MAX ? s->level : IX_LEVEL_MAX;
    uint32_t len, gap, k;
    p->index = i;
    p->a.x = q4_of(s->x0);
    p->a.y = q4_of(s->y0);
    p->b.x = q4_of(s->x1);
    p->b.y = q4_of(s->y1);
    p->pts = NULL;
    p->n = 2u;
    p->step = 1u;
    p->last = 1u;
    if (s->kind == SYMLINE_KIND_CURVE && s->count >= 2u) {
        p->pts = r->points + s->first;
        p->last = s->count - 1u;
        p->step = s->level >= 2u ? 1u : IX_STEP >> s->level;
        p->n = (p->last + p->step - 1u) / p->step + 1u;
        p->a = vertex(p, 0u);
        p->b = vertex(p, p->n - 1u);
    }
    p->lo = p->a;
    p->hi = p->a;
    for (k = 1u; k < p->n; k++) {
        grow_box(p, vertex(p, k));
    }
    /* size: the chord, or for a curve its box when larger (a closed loop) */
    len = length_of(p->a, p->b);
    k = (uint32_t)(p->hi.x - p->lo.x) > (uint32_t)(p->hi.y - p->lo.y)
            ? (uint32_t)(p->hi.x - p->lo.x)
            : (uint32_t)(p->hi.y - p->lo.y);
    len = len > k ? len : k;
    if (len < (uint32_t)ip->arm || len * 16u < c->min_length_q8) {
        return 0;
    }
    gap = (c->gap_q8 << level) / 16u;
    k = (uint32_t)(((uint64_t)len * c->gap_pct) / 100u);
    p->gap_base = (int32_t)gap;
    p->gap_cap = (int32_t)k;
    gap = gap * (256u / IX_SIN_MIN_Q8);
    p->gap = (int32_t)(gap < k ? gap : k);
    p->lo.x -= p->gap;
    p->lo.y -= p->gap;
    p->hi.x += p->gap;
    p->hi.y += p->gap;
    return 1;
}

static int boxes_meet(ix_vec alo, ix_vec ahi, ix_vec blo, ix_vec bhi)
{
    return alo.x <= bhi.x && blo.x <= ahi.x && alo.y <= bhi.y && blo.y <= ahi.y;
}

/* ---- crossing two chords ---- */

/* a / b rounded to nearest, b > 0. */
static int64_t div_round(int64_t a, int64_t b)
{
    return (a >= 0 ? a + b / 2 : a - b / 2) / b;
}

typedef struct ix_hit {
    int32_t x, y;   /* Q4 */
    int32_t ta, tb; /* Q16 along chord a, chord b */
} ix_hit;

/* Is parameter t (Q16) of crossing (x, y) on chord k (v0 -> v1) of p
 * acceptable: on the chord (the end excluded but on the last chord, so a
 * crossing at a vertex counts once), or beyond a free end by at most the gap? */
static int on_chord(const ix_poly *p, uint32_t k, int64_t t, int64_t x, int64_t y, ix_vec v0,
                    ix_vec v1, int64_t sin_q8)
{
    int64_t g = (int64_t)p->gap_base * 256 / sin_q8, g2;
    g = g < p->gap_cap ? g : p->gap_cap;
    g2 = g * g;
    if (t < 0) {
        return k == 0u && dist2(x - v0.x, y - v0.y) <= g2;
    }
    if (t < 65536) {
        return 1;
    }
    if (k + 2u < p->n) {
        return 0;
    }
    return t == 65536 || dist2(x - v1.x, y - v1.y) <= g2;
}

/* Crossing of chord ka of a (p0 -> p1) and chord kb of b (q0 -> q1). */
static int cross_chords(const ix_poly *a, uint32_t ka, ix_vec p0, ix_vec p1, const ix_poly *b,
                        uint32_t kb, ix_vec q0, ix_vec q1, ix_hit *h)
{
    const int64_t rx = (int64_t)p1.x - p0.x, ry = (int64_t)p1.y - p0.y;
    const int64_t sx = (int64_t)q1.x - q0.x, sy = (int64_t)q1.y - q0.y;
    const int64_t wx = (int64_t)q0.x - p0.x, wy = (int64_t)q0.y - p0.y;
    int64_t den = rx * sy - ry * sx, nt = wx * sy - wy * sx, nu = wx * ry - wy * rx;
    int64_t t, u, x, y, sin_q8;
    if (den == 0) {
        return 0; /* parallel */
    }
    if (den < 0) {
        den = -den;
        nt = -nt;
        nu = -nu;
    }
    /* Interior chords only cross within [0, 1); end chords within 4096
     * chord lengths (the gap decides below); keeps t * 65536 in range. */
    if ((ka != 0u && nt < 0) || (ka + 2u < a->n && nt >= den) || (kb != 0u && nu < 0) ||
        (kb + 2u < b->n && nu >= den) || nt > den * 4096 || -nt > den * 4096 ||
        nu > den * 4096 || -nu > den * 4096) {
        return 0;
    }
    {
        /* sin of the angle between the chords, Q8, at least IX_SIN_MIN_Q8 */
        const uint64_t rr = sl_isqrt64((uint64_t)(rx * rx + ry * ry));
        const uint64_t ss = sl_isqrt64((uint64_t)(sx * sx + sy * sy));
        sin_q8 = rr * ss == 0u ? 256 : den * 256 / (int64_t)(rr * ss);
        sin_q8 = sin_q8 < IX_SIN_MIN_Q8 ? IX_SIN_MIN_Q8 : sin_q8;
    }
    t = div_round(nt * 65536, den);
    u = div_round(nu * 65536, den);
    x = p0.x + div_round(rx * t, 65536);
    y = p0.y + div_round(ry * t, 65536);
    if (!on_chord(a, ka, t, x, y, p0, p1, sin_q8) || !on_chord(b, kb, u, x, y, q0, q1, sin_q8)) {
        return 0;
    }
    h->x = (int32_t)x;
    h->y = (int32_t)y;
    h->ta = (int32_t)t;
    h->tb = (int32_t)u;
    return 1;
}

/* ---- rays ---- */

/* The piece of p leaving the crossing (x, y), found on chord k at t (Q16),
 * toward p's start (back) or end: 1 with its direction when p goes on for
 * at least one arm past the crossing. The direction is taken to the vertex
 * two arms along p (or p's end), so a curve gives its tangent, a line the
 * direction of its whole chord. Part of a gap bridged beyond a free end
 * does not count as going on. */
static int ray_of(const ix_poly *p, uint32_t k, int32_t t, int32_t x, int32_t y, int back,
                  const ix_params *ip, uint32_t *deg, ix_vec *far)
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
        prev = t < 0 ? vertex(p, 0u) : vertex(p, p->n - 1u);
    }
    v = back ? k : k + 1u;
    for (;;) {
        w = vertex(p, v);
        acc += length_of(prev, w);
        if (acc >= reach || (back ? v == 0u : v + 1u == p->n)) {
            break;
        }
        prev = w;
        v = back ? v - 1u : v + 1u;
    }
    if (acc < (uint32_t)ip->arm) {
        return 0;
    }
    *deg = sl_heading_q8((int64_t)w.x - x, (int64_t)w.y - y);
    *far = w;
    return 1;
}

/* The rays of p at a crossing on its chord k: 0, 1 or 2 into rays[]. A curve
 * going on both ways takes its tangent from the chord between the two far
 * points, which is parallel to the tangent on a circle (a chord from the
 * crossing to one far point is off by half the arc's turn). */
static uint32_t rays_of(const ix_poly *p, uint32_t k, int32_t t, int32_t x, int32_t y,
                        const ix_params *ip, uint32_t *rays)
{
    ix_vec back, fwd;
    uint32_t n = (uint32_t)ray_of(p, k, t, x, y, 1, ip, &rays[0], &back);
    n += (uint32_t)ray_of(p, k, t, x, y, 0, ip, &rays[n], &fwd);
    if (n == 2u && p->pts != NULL) {
        rays[1] = sl_heading_q8((int64_t)fwd.x - back.x, (int64_t)fwd.y - back.y);
        rays[0] = (rays[1] + IX_DEG_180) % SYMLINE_DEG_Q8_FULL;
    }
    return n;
}

/* ---- gathering crossings into intersections ---- */

static void add_ray(symline_intersection *it, uint32_t deg, uint32_t min_angle)
{
    uint32_t i, n = it->ray_count;
    for (i = 0; i < n; i++) {
        if (turn_between(it->rays[i], deg) < min_angle || it->rays[i] == deg) {
            return; /* the same piece, seen from another pair */
        }
    }
    if (n >= SYMLINE_INTERSECTION_RAYS) {
        return;
    }
    for (i = n; i > 0u && it->rays[i - 1u] > deg; i--) {
        it->rays[i] = it->rays[i - 1u];
    }
    it->rays[i] = deg;
    it->ray_count = (uint8_t)(n + 1u);
}

static void add_segment(symline_intersection *it, uint32_t s)
{
    uint32_t i, n = it->segment_count;
    for (i = 0; i < n; i++) {
        if (it->segments[i] == s) {
            return;
        }
    }
    if (n >= SYMLINE_INTERSECTION_SEGMENTS) {
        return;
    }
    for (i = n; i > 0u && it->segments[i - 1u] > s; i--) {
        it->segments[i] = it->segments[i - 1u];
    }
    it->segments[i] = s;
    it->segment_count = (uint8_t)(n + 1u);
}

/* Adds the crossing of segments sa and sb at (x, y) (Q8) with its rays to
 * the intersection within merge distance, or starts a new one. */
static void gather(symline_intersection_result *out, const ix_params *ip, int32_t x, int32_t y,
                   const uint32_t *rays, uint32_t nr, uint32_t sa, uint32_t sb)
{
    symline_intersection *it = NULL;
    uint32_t i;
    for (i = 0; i < out->count; i++) {
        const symline_intersection *c = &out->items[i];
        if (dist2((int64_t)c->x - x, (int64_t)c->y - y) <= ip->merge2) {
            it = &out->items[i];
            break;
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
        add_ray(it, rays[i], ip->min_angle);
    }
    add_segment(it, sa);
    add_segment(it, sb);
    it->type = (uint8_t)(it->ray_count - 2u);
}

/* Joins intersections that ended up closer than the merge distance (a curve
 * can cross a line, or come near it, at several chords of one junction, and
 * an intersection's mean moves as crossings join it). */
static void settle(symline_intersection_result *out, const ix_params *ip)
{
    uint32_t i, j, k;
    for (i = 0; i < out->count; i++) {
        symline_intersection *a = &out->items[i];
        for (j = i + 1u; j < out->count;) {
            const symline_intersection *b = &out->items[j];
            if (dist2((int64_t)a->x - b->x, (int64_t)a->y - b->y) > ip->merge2) {
                j++;
                continue;
            }
            {
                const int32_t wa = a->support, wb = b->support;
                a->x = (int32_t)(((int64_t)a->x * wa + (int64_t)b->x * wb) / (wa + wb));
                a->y = (int32_t)(((int64_t)a->y * wa + (int64_t)b->y * wb) / (wa + wb));
                a->support = (uint8_t)(wa + wb > 255 ? 255 : wa + wb);
            }
            for (k = 0; k < b->ray_count; k++) {
                add_ray(a, b->rays[k], ip->min_angle);
            }
            for (k = 0; k < b->segment_count; k++) {
                add_segment(a, b->segments[k]);
            }
            a->type = (uint8_t)(a->ray_count - 2u);
            for (k = j + 1u; k < out->count; k++) {
                out->items[k - 1u] = out->items[k];
            }
            out->count--;
        }
    }
}

/* A crossing of a and b: their rays, the angle test, then gathering. */
static void take_hit(const ix_poly *a, uint32_t ka, const ix_poly *b, uint32_t kb,
                     const ix_hit *h, const ix_params *ip, symline_intersection_result *out)
{
    uint32_t rays[4];
    const uint32_t na = rays_of(a, ka, h->ta, h->x, h->y, ip, rays);
    uint32_t nr;
    if (na == 0u) {
        return;
    }
    nr = na + rays_of(b, kb, h->tb, h->x, h->y, ip, rays + na);
    if (nr == na || lines_between(rays[0], rays[na]) < ip->min_angle) {
        return; /* b gives no ray, or one line continuing / parallel lines */
    }
    if (nr == 2u && a->pts != NULL && b->pts != NULL) {
        return; /* two curves meeting end to end: where the tracer cut the centre
                   circle's ellipse at its sharpest bend, not a corner */
    }
    gather(out, ip, h->x * 16, h->y * 16, rays, nr, a->index, b->index);
}

/* Every crossing of the polylines a and b. */
SL_NOINLINE static void meet(const ix_poly *a, const ix_poly *b, const ix_params *ip,
                             symline_intersection_result *out)
{
    uint32_t ka, kb;
    for (ka = 0; ka + 1u < a->n; ka++) {
        const ix_vec p0 = vertex(a, ka), p1 = vertex(a, ka + 1u);
        ix_vec alo, ahi;
        alo.x = (p0.x < p1.x ? p0.x : p1.x) - a->gap;
        alo.y = (p0.y < p1.y ? p0.y : p1.y) - a->gap;
        ahi.x = (p0.x > p1.x ? p0.x : p1.x) + a->gap;
        ahi.y = (p0.y > p1.y ? p0.y : p1.y) + a->gap;
        if (!boxes_meet(alo, ahi, b->lo, b->hi)) {
            continue;
        }
        for (kb = 0; kb + 1u < b->n; kb++) {
            const ix_vec q0 = vertex(b, kb), q1 = vertex(b, kb + 1u);
            ix_vec blo, bhi;
            ix_hit h;
            blo.x = (q0.x < q1.x ? q0.x : q1.x) - b->gap;
            blo.y = (q0.y < q1.y ? q0.y : q1.y) - b->gap;
            bhi.x = (q0.x > q1.x ? q0.x : q1.x) + b->gap;
            bhi.y = (q0.y > q1.y ? q0.y : q1.y) + b->gap;
            if (boxes_meet(alo, ahi, blo, bhi) &&
                cross_chords(a, ka, p0, p1, b, kb, q0, q1, &h)) {
                take_hit(a, ka, b, kb, &h, ip, out);
            }
        }
    }
}

/* ---- arguments ---- */

static symline_status check_config(const symline_intersection_config *c)
{
    if (c->min_angle_q8 > IX_DEG_90 || c->gap_q8 > 65536u || c->gap_pct > 100u ||
        c->arm_q8 < 256u || c->arm_q8 > 65536u || c->merge_q8 > 65536u ||
        c->min_length_q8 > (SYMLINE_MAX_DIM << 8)) {
        return SYMLINE_ERR_CONFIG;
    }
    return SYMLINE_OK;
}

static int coord_ok(int32_t v)
{
    return v >= -IX_COORD_MAX && v <= IX_COORD_MAX;
}

static symline_status check_lines(const symline_result *r)
{
    uint32_t i;
    if (r->segment_count > 0u && r->segments == NULL) {
        return SYMLINE_ERR_NULL;
    }
    if (r->segment_count > r->segment_cap || r->point_count > r->point_cap) {
        return SYMLINE_ERR_RANGE;
    }
    for (i = 0; i < r->segment_count; i++) {
        const symline_segment *s = &r->segments[i];
        if ((s->kind != SYMLINE_KIND_LINE && s->kind != SYMLINE_KIND_CURVE) || !coord_ok(s->x0) ||
            !coord_ok(s->y0) || !coord_ok(s->x1) || !coord_ok(s->y1)) {
            return SYMLINE_ERR_RANGE;
        }
        if (s->kind == SYMLINE_KIND_CURVE && s->count >= 2u) {
            if (r->points == NULL) {
                return SYMLINE_ERR_NULL;
            }
            if (s->count > r->point_count || s->first > r->point_count - s->count) {
                return SYMLINE_ERR_RANGE;
            }
        }
    }
    return SYMLINE_OK;
}

symline_status symline_intersections(const symline_result *lines,
                                     const symline_intersection_config *cfg,
                                     symline_intersection_result *out)
{
    ix_params ip;
    uint32_t i, j;
    symline_status st;
    if (lines == NULL || cfg == NULL || out == NULL || (out->items == NULL && out->cap > 0u)) {
        return SYMLINE_ERR_NULL;
    }
    st = check_config(cfg);
    if (st == SYMLINE_OK) {
        st = check_lines(lines);
    }
    if (st != SYMLINE_OK) {
        return st;
    }
    ip.min_angle = cfg->min_angle_q8;
    ip.arm = (int32_t)(cfg->arm_q8 / 16u);
    ip.merge2 = (int64_t)cfg->merge_q8 * cfg->merge_q8;
    out->count = 0u;
    out->truncated = 0u;
    for (i = 0; i + 1u < lines->segment_count; i++) {
        ix_poly a;
        if (!poly_init(&a, lines, i, cfg, &ip)) {
            continue;
        }
        for (j = i + 1u; j < lines->segment_count; j++) {
            ix_poly b;
            if (poly_init(&b, lines, j, cfg, &ip) && boxes_meet(a.lo, a.hi, b.lo, b.hi)) {
                meet(&a, &b, &ip, out);
            }
        }
    }
    settle(out, &ip);
    return SYMLINE_OK;
}

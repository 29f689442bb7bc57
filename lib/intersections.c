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

#include "common.h" /* SL_NOINLINE */

/* Largest |coordinate| of a segment end, Q8 (65535 px). */
#define IX_COORD_MAX ((int32_t)(SYMLINE_MAX_DIM << 8))
/* A curve's polyline takes every IX_STEP-th point at full resolution (chords
 * of 8-11 px, within 0.1 px of a circle of 100 px radius), fewer at coarser
 * scales (points 2^level px apart), every point from scale 3 on. */
#define IX_STEP 8u
/* A stem meeting a bar at angle a stops short of it by about (half the bar's
 * width) / sin(a): the gap grows with 1/sin of the angle between the two,
 * up to this factor (sin >= 1/4, angles >= 14.5 degrees). */
#define IX_GAP_GROWTH 4u
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
    t = ((uint32_t)lo << 16) / (uint32_t)hi; /* Q16, 0..65536; a 32-bit division */
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

/* A segment seen as a polyline, with its box and gap tolerance. Kept small:
 * two of these live on the stack under the deepest call. */
typedef struct ix_poly {
    const symline_segment *s;
    const symline_point *pts; /* a curve's points, or NULL: the chord */
    uint32_t n;               /* vertices, >= 2 */
    uint32_t index;           /* in the result's segments */
    ix_vec lo, hi;            /* box of the vertices grown by the gap */
    int32_t gap_base;         /* how far a free end may stop short of a crossing
                                 meeting at a right angle */
    int32_t gap;              /* at least the largest gap: 4 * gap_base, or the cap */
    int32_t cheb;             /* longest chord, Chebyshev (max of |dx|, |dy|) */
} ix_poly;

typedef struct ix_params {
    uint32_t min_angle; /* Q8 degrees */
    uint32_t gap_pct;   /* the gap's cap, % of a segment's length */
    int32_t arm;        /* Q4 px */
    int64_t merge2;     /* (Q8 px)^2 */
} ix_params;

/* Q8 -> Q4, rounding down. */
static int32_t q4_of(int32_t v)
{
    return v >= 0 ? v / 16 : -((15 - v) / 16);
}

/* Points from one vertex of a curve to the next at this scale level. */
static uint32_t curve_step(const symline_segment *s)
{
    return s->level >= 3u ? 1u : IX_STEP >> s->level;
}

static ix_vec vertex(const ix_poly *p, uint32_t k)
{
    ix_vec v;
    if (p->pts == NULL) {
        v.x = q4_of(k == 0u ? p->s->x0 : p->s->x1);
        v.y = q4_of(k == 0u ? p->s->y0 : p->s->y1);
    } else {
        const symline_point *q = p->pts + (k + 1u >= p->n ? p->s->count - 1u : k * curve_step(p->s));
        v.x = (int32_t)q->x * 16;
        v.y = (int32_t)q->y * 16;
    }
    return v;
}

static int64_t dist2(int64_t dx, int64_t dy)
{
    return dx * dx + dy * dy;
}


static void grow_box(ix_poly *p, ix_vec v)
{
    p->lo.x = v.x < p->lo.x ? v.x : p->lo.x;
    p->lo.y = v.y < p->lo.y ? v.y : p->lo.y;
    p->hi.x = v.x > p->hi.x ? v.x : p->hi.x;
    p->hi.y = v.y > p->hi.y ? v.y : p->hi.y;
}

static int is_curve(const symline_segment *s)
{
    return s->kind == SYMLINE_KIND_CURVE && s->count >= 2u;
}

/* Gap at a right angle for a segment of this scale level, Q4. */
static uint32_t level_gap(const symline_segment *s, const symline_intersection_config *c)
{
    const uint32_t level = s->level < IX_LEVEL_MAX ? s->level : IX_LEVEL_MAX;
    return c->gap_q8 * (level + 1u) / 16u;
}

/* Segment i as a polyline with the box of its vertices. */
static void poly_shape(ix_poly *p, const symline_result *r, uint32_t i)
{
    const symline_segment *s = &r->segments[i];
    uint32_t k;
    ix_vec prev;
    p->s = s;
    p->index = i;
    p->pts = NULL;
    p->n = 2u;
    if (is_curve(s)) {
        const uint32_t step = curve_step(s);
        p->pts = r->points + s->first;
        p->n = (s->count - 1u + step - 1u) / step + 1u;
    }
    prev = vertex(p, 0u);
    p->lo = prev;
    p->hi = prev;
    p->cheb = 0;
    for (k = 1u; k < p->n; k++) {
        const ix_vec v = vertex(p, k);
        const int32_t dx = v.x > prev.x ? v.x - prev.x : prev.x - v.x;
        const int32_t dy = v.y > prev.y ? v.y - prev.y : prev.y - v.y;
        p->cheb = dx > p->cheb ? dx : p->cheb;
        p->cheb = dy > p->cheb ? dy : p->cheb;
        grow_box(p, v);
        prev = v;
    }
}

/* Its size and gap tolerances; the box grows by the gap. 0 when the segment
 * takes no part (smaller than the configured minimum length or than one arm:
 * it could not give a ray). In squares: no root for most segments. */
SL_NOINLINE static int poly_fit(ix_poly *p, const symline_segment *s,
                                const symline_intersection_config *c, const ix_params *ip)
{
    const int32_t ext = (p->hi.x - p->lo.x) > (p->hi.y - p->lo.y) ? p->hi.x - p->lo.x
                                                                  : p->hi.y - p->lo.y;
    const int64_t minl = (int64_t)c->min_length_q8; /* Q8 */
    const ix_vec a = vertex(p, 0u), b = vertex(p, p->n - 1u);
    const uint32_t l1 = (uint32_t)(b.x > a.x ? b.x - a.x : a.x - b.x) +
                        (uint32_t)(b.y > a.y ? b.y - a.y : a.y - b.y);
    int64_t len2 = dist2((int64_t)b.x - a.x, (int64_t)b.y - a.y);
    uint32_t g, cap;
    /* size: the chord, or for a curve its box when larger (a closed loop) */
    len2 = len2 > (int64_t)ext * ext ? len2 : (int64_t)ext * ext;
    if (len2 < (int64_t)ip->arm * ip->arm || len2 * 256 < minl * minl) {
        return 0;
    }
    p->gap_base = (int32_t)level_gap(s, c);
    /* the box grows by at least the largest gap: 4 gap_base, or the cap taken
     * from |dx| + |dy| >= the length (a box a little too large is only slower) */
    g = (uint32_t)p->gap_base * IX_GAP_GROWTH;
    cap = (l1 > (uint32_t)ext ? l1 : (uint32_t)ext) / 100u * c->gap_pct + (uint32_t)c->gap_pct;
    p->gap = (int32_t)(g < cap ? g : cap);
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

typedef struct ix_hit {
    int32_t x, y;   /* Q4 */
    int32_t ta, tb; /* Q16 along chord a, chord b */
} ix_hit;

/* round(n * 65536 / d) for d in [1, 65535], |n| <= 4096 d: two 32-bit divisions
 * (a 64-bit one would call a library routine with a large stack frame). */
static int32_t q16_div(int32_t n, int32_t d)
{
    const uint32_t an = (uint32_t)(n < 0 ? -n : n), ud = (uint32_t)d;
    const uint32_t q = an / ud, r = an % ud;
    const uint32_t v = (q << 16) + ((r << 16) + ud / 2u) / ud;
    return n < 0 ? -(int32_t)v : (int32_t)v;
}

/* round(v * t / 65536). */
static int64_t q16_mul(int64_t v, int32_t t)
{
    const int64_t p = v * t;
    return p >= 0 ? (p + 32768) / 65536 : -((-p + 32768) / 65536);
}

/* Length of (dx, dy) within 7 % (max + 3/8 min), without a root. */
static uint64_t approx_len64(int64_t dx, int64_t dy)
{
    const uint64_t ax = (uint64_t)(dx < 0 ? -dx : dx), ay = (uint64_t)(dy < 0 ? -dy : dy);
    return ax > ay ? ax + 3u * ay / 8u : ay + 3u * ax / 8u;
}

/* Square of p's size: its chord, or its box when larger (a closed loop). */
static int64_t size2(const ix_poly *p)
{
    const ix_vec a = vertex(p, 0u), b = vertex(p, p->n - 1u);
    const int64_t ext = (p->hi.x - p->lo.x) > (p->hi.y - p->lo.y) ? p->hi.x - p->lo.x - 2 * p->gap
                                                                  : p->hi.y - p->lo.y - 2 * p->gap;
    const int64_t len2 = dist2((int64_t)b.x - a.x, (int64_t)b.y - a.y);
    return len2 > ext * ext ? len2 : ext * ext;
}

/* Is a crossing dist beyond a free end of p close enough? At most gap_base /
 * sin(angle between the chords), IX_GAP_GROWTH gap_base, and gap_pct of p's size:
 * sin = den / (lr ls), so dist sin <= gap_base reads dist den <= gap_base lr ls. */
static int within_gap(const ix_poly *p, uint64_t dist, int64_t den, uint32_t lr, uint32_t ls,
                      const ix_params *ip)
{
    return dist <= IX_GAP_GROWTH * (uint64_t)p->gap_base &&
           (int64_t)dist * den <= (int64_t)p->gap_base * lr * ls &&
           (int64_t)(dist * dist) * 10000 <= size2(p) * ip->gap_pct * ip->gap_pct;
}

/* Is parameter t (Q16) of crossing (x, y) on chord k (v0 -> v1) of p
 * acceptable: on the chord (the end excluded but on the last chord, so a
 * crossing at a vertex counts once), or beyond a free end within the gap? */
static int on_chord(const ix_poly *p, uint32_t k, int32_t t, int64_t x, int64_t y, ix_vec v0,
                    ix_vec v1, int64_t den, uint32_t lr, uint32_t ls, const ix_params *ip)
{
    if (t < 0) {
        return k == 0u && within_gap(p, approx_len64(x - v0.x, y - v0.y), den, lr, ls, ip);
    }
    if (t < 65536) {
        return 1;
    }
    if (k + 2u < p->n) {
        return 0;
    }
    return t == 65536 || within_gap(p, approx_len64(x - v1.x, y - v1.y), den, lr, ls, ip);
}

/* Crossing of chord ka of a and chord kb of b. Not
 * inlined: its 64-bit temporaries stay off the stack of the rays below. */
SL_NOINLINE static int cross_chords(const ix_poly *a, uint32_t ka, const ix_poly *b, uint32_t kb,
                                    const ix_params *ip, ix_hit *h)
{
    const ix_vec p0 = vertex(a, ka), p1 = vertex(a, ka + 1u);
    const ix_vec q0 = vertex(b, kb), q1 = vertex(b, kb + 1u);
    /* differences of Q4 coordinates fit 22 bits; their products need 64 */
    const int32_t rx = p1.x - p0.x, ry = p1.y - p0.y;
    const int32_t sx = q1.x - q0.x, sy = q1.y - q0.y;
    const int32_t wx = q0.x - p0.x, wy = q0.y - p0.y;
    int64_t den = (int64_t)rx * sy - (int64_t)ry * sx;
    int64_t nt = (int64_t)wx * sy - (int64_t)wy * sx, nu = (int64_t)wx * ry - (int64_t)wy * rx;
    int32_t t, u;
    int64_t x, y;
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
        /* t, u in Q16 by 32-bit divisions: den brought below 2^16 (with nt, nu;
         * |nt|, |nu| <= 4096 den keeps them in 29 bits) */
        int64_t d = den, n1 = nt, n2 = nu;
        while (d >= 65536) {
            d /= 2;
            n1 /= 2;
            n2 /= 2;
        }
        t = q16_div((int32_t)n1, (int32_t)d);
        u = q16_div((int32_t)n2, (int32_t)d);
    }
    x = p0.x + q16_mul(rx, t);
    y = p0.y + q16_mul(ry, t);
    {
        const uint32_t lr = (uint32_t)approx_len64(rx, ry), ls = (uint32_t)approx_len64(sx, sy);
        if (!on_chord(a, ka, t, x, y, p0, p1, den, lr, ls, ip) ||
            !on_chord(b, kb, u, x, y, q0, q1, den, lr, ls, ip)) {
            return 0;
        }
    }
    h->x = (int32_t)x;
    h->y = (int32_t)y;
    h->ta = t;
    h->tb = u;
    return 1;
}

/* ---- rays ---- */

/* Length of b - a within 7 % (max + 3/8 min), without a root. */
static uint32_t approx_len(ix_vec a, ix_vec b)
{
    const uint32_t dx = (uint32_t)(b.x > a.x ? b.x - a.x : a.x - b.x);
    const uint32_t dy = (uint32_t)(b.y > a.y ? b.y - a.y : a.y - b.y);
    return dx > dy ? dx + 3u * dy / 8u : dy + 3u * dx / 8u;
}

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
        prev = t < 0 ? vertex(p, 0u) : vertex(p, p->n - 1u);
    }
    v = back ? k : k + 1u;
    for (;;) {
        const uint32_t step_len = approx_len(prev, w = vertex(p, v));
        if (acc + step_len >= reach && p->pts != NULL && step_len > 0u) {
            /* the point at `reach`: r = share of this chord, Q16 */
            const int32_t r = (int32_t)(((reach - acc) << 16) / step_len);
            w.x = prev.x + (int32_t)q16_mul((int64_t)w.x - prev.x, r);
            w.y = prev.y + (int32_t)q16_mul((int64_t)w.y - prev.y, r);
            acc = reach;
            break;
        }
        acc += step_len;
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
SL_NOINLINE static uint32_t rays_of(const ix_poly *p, uint32_t k, int32_t t, int32_t x, int32_t y,
                                    const ix_params *ip, uint32_t *rays)
{
    ix_vec back = {0, 0}, fwd = {0, 0};
    const int hb = ray_of(p, k, t, x, y, 1, ip, &back);
    const int hf = ray_of(p, k, t, x, y, 0, ip, &fwd);
    uint32_t n = 0u;
    if (hb && hf && p->pts != NULL) {
        rays[1] = sl_heading_q8((int64_t)fwd.x - back.x, (int64_t)fwd.y - back.y);
        rays[0] = (rays[1] + IX_DEG_180) % SYMLINE_DEG_Q8_FULL;
        return 2u;
    }
    if (hb) {
        rays[n++] = sl_heading_q8((int64_t)back.x - x, (int64_t)back.y - y);
    }
    if (hf) {
        rays[n++] = sl_heading_q8((int64_t)fwd.x - x, (int64_t)fwd.y - y);
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
SL_NOINLINE static void gather(symline_intersection_result *out, const ix_params *ip, int32_t x, int32_t y,
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

/* *d = *s, member by member (a structure assignment may become a memcpy call,
 * and the core links no libc). */
static void copy_item(symline_intersection *d, const symline_intersection *s)
{
    uint32_t k;
    d->x = s->x;
    d->y = s->y;
    d->type = s->type;
    d->ray_count = s->ray_count;
    d->segment_count = s->segment_count;
    d->support = s->support;
    for (k = 0; k < SYMLINE_INTERSECTION_RAYS; k++) {
        d->rays[k] = s->rays[k];
    }
    for (k = 0; k < SYMLINE_INTERSECTION_SEGMENTS; k++) {
        d->segments[k] = s->segments[k];
    }
}

/* Joins intersections that ended up closer than the merge distance (a curve
 * can cross a line, or come near it, at several chords of one junction, and
 * an intersection's mean moves as crossings join it). */
SL_NOINLINE static void settle(symline_intersection_result *out, const ix_params *ip)
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
                /* weighted mean; the two are within the merge distance (< 2^17) */
                const int32_t wa = a->support, wb = b->support;
                a->x += (b->x - a->x) * wb / (wa + wb);
                a->y += (b->y - a->y) * wb / (wa + wb);
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
                copy_item(&out->items[k - 1u], &out->items[k]);
            }
            out->count--;
        }
    }
}

/* A crossing of a and b: their rays, the angle test, then gathering. */
SL_NOINLINE static void take_hit(const ix_poly *a, uint32_t ka, const ix_poly *b, uint32_t kb,
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

/* Box of chord k (v0 -> v1) of p: grown by the gap at a free end only, the
 * only place a crossing may lie off the chord. */
static void chord_box(const ix_poly *p, uint32_t k, ix_vec v0, ix_vec v1, ix_vec *lo, ix_vec *hi)
{
    const int32_t g = (k == 0u || k + 2u == p->n) ? p->gap : 0;
    lo->x = (v0.x < v1.x ? v0.x : v1.x) - g;
    lo->y = (v0.y < v1.y ? v0.y : v1.y) - g;
    hi->x = (v0.x > v1.x ? v0.x : v1.x) + g;
    hi->y = (v0.y > v1.y ? v0.y : v1.y) + g;
}

/* How many chords from vertex v on cannot reach the box lo..hi grown by g:
 * v lies d > 0 away (Chebyshev) and each chord moves at most `cheb`. */
static uint32_t chords_clear(ix_vec v, ix_vec lo, ix_vec hi, int32_t g, int32_t cheb)
{
    int32_t d = lo.x - g - v.x;
    d = v.x - hi.x - g > d ? v.x - hi.x - g : d;
    d = lo.y - g - v.y > d ? lo.y - g - v.y : d;
    d = v.y - hi.y - g > d ? v.y - hi.y - g : d;
    return d > 0 && cheb > 0 ? (uint32_t)((d - 1) / cheb) : 0u;
}

/* Where a walk over the chord pairs of two polylines stands. */
typedef struct ix_walk {
    uint32_t ka, kb; /* chord of a; next chord of b */
    int inner;       /* 1 while the chords of b are walked for chord ka */
    ix_vec alo, ahi; /* box of chord ka */
    ix_hit hit;      /* where the two chords cross */
} ix_walk;

/* The next pair of chords of a and b whose boxes meet (chord w->ka of a,
 * chord w->kb - 1 of b); 0 when there is none. Runs of chords far from the
 * other polyline are stepped over, so two curves cost about their lengths,
 * not the product of their vertex counts. A walk, not a loop that handles
 * each pair, so that the handling is not called from under its frame. */
SL_NOINLINE static int walk_next(const ix_poly *a, const ix_poly *b, ix_walk *w)
{
    uint32_t skip;
    for (;;) {
        if (!w->inner) {
            ix_vec p0, p1;
            if (w->ka + 1u >= a->n) {
                return 0;
            }
            p0 = vertex(a, w->ka);
            skip = w->ka + 2u < a->n
                       ? chords_clear(p0, b->lo, b->hi, w->ka == 0u ? a->gap : 0, a->cheb)
                       : 0u;
            if (skip > 0u) {
                /* never over the last chord: its free end reaches out by the gap */
                w->ka = w->ka + skip < a->n - 2u ? w->ka + skip : a->n - 2u;
                continue;
            }
            p1 = vertex(a, w->ka + 1u);
            chord_box(a, w->ka, p0, p1, &w->alo, &w->ahi);
            if (!boxes_meet(w->alo, w->ahi, b->lo, b->hi)) {
                w->ka++;
                continue;
            }
            w->inner = 1;
            w->kb = 0u;
        }
        while (w->kb + 1u < b->n) {
            const ix_vec q0 = vertex(b, w->kb);
            ix_vec q1, blo, bhi;
            skip = w->kb + 2u < b->n ? chords_clear(q0, w->alo, w->ahi,
                                                    w->kb == 0u ? b->gap : 0, b->cheb)
                                     : 0u;
            if (skip > 0u) {
                w->kb = w->kb + skip < b->n - 2u ? w->kb + skip : b->n - 2u;
                continue;
            }
            q1 = vertex(b, w->kb + 1u);
            chord_box(b, w->kb, q0, q1, &blo, &bhi);
            w->kb++;
            if (boxes_meet(w->alo, w->ahi, blo, bhi)) {
                return 1;
            }
        }
        w->inner = 0;
        w->ka++;
    }
}

/* 1 when line s cannot come near a: the box of its ends (Q8, as given) grown
 * by at most its gap misses a's box. */
SL_NOINLINE static int far_apart(const ix_poly *a, const symline_segment *s,
                                 const symline_intersection_config *c)
{
    /* |dx| + |dy| >= the length: its gap is at most g (Q8) */
    const uint32_t l1 = (uint32_t)(s->x0 > s->x1 ? s->x0 - s->x1 : s->x1 - s->x0) +
                        (uint32_t)(s->y0 > s->y1 ? s->y0 - s->y1 : s->y1 - s->y0);
    const uint32_t gc = l1 / 100u * c->gap_pct + 256u;
    uint32_t g = level_gap(s, c) * IX_GAP_GROWTH * 16u;
    g = gc < g ? gc : g;
    return (s->x0 < s->x1 ? s->x0 : s->x1) - (int32_t)g > a->hi.x * 16 + 15 ||
           (s->x0 > s->x1 ? s->x0 : s->x1) + (int32_t)g < a->lo.x * 16 ||
           (s->y0 < s->y1 ? s->y0 : s->y1) - (int32_t)g > a->hi.y * 16 + 15 ||
           (s->y0 > s->y1 ? s->y0 : s->y1) + (int32_t)g < a->lo.y * 16;
}

/* ---- arguments ---- */

SL_NOINLINE static symline_status check_config(const symline_intersection_config *c)
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

SL_NOINLINE static symline_status check_lines(const symline_result *r)
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
    ip.gap_pct = cfg->gap_pct;
    ip.merge2 = (int64_t)cfg->merge_q8 * cfg->merge_q8;
    out->count = 0u;
    out->truncated = 0u;
    /* Each pair once. A curve's polyline is walked only when it is the outer
     * one of a pair (the inner one's box is built anew for every pair), so a
     * line and a curve are met from the curve's side. One frame holds both
     * polylines and the walk, so the deepest call stays small. */
    for (i = 0; i < lines->segment_count; i++) {
        const int ci = is_curve(&lines->segments[i]);
        ix_poly a;
        poly_shape(&a, lines, i);
        if (!poly_fit(&a, &lines->segments[i], cfg, &ip)) {
            continue;
        }
        for (j = ci ? 0u : i + 1u; j < lines->segment_count; j++) {
            const symline_segment *sj = &lines->segments[j];
            const int cj = is_curve(sj);
            ix_poly b;
            ix_walk w;
            if (j == i || (cj && (!ci || j < i)) || (!cj && far_apart(&a, sj, cfg))) {
                continue; /* itself, the other way round, once already, or far */
            }
            poly_shape(&b, lines, j);
            if (!poly_fit(&b, sj, cfg, &ip) || !boxes_meet(a.lo, a.hi, b.lo, b.hi)) {
                continue;
            }
            w.ka = 0u;
            w.kb = 0u;
            w.inner = 0;
            while (walk_next(&a, &b, &w)) {
                if (cross_chords(&a, w.ka, &b, w.kb - 1u, &ip, &w.hit)) {
                    take_hit(&a, w.ka, &b, w.kb - 1u, &w.hit, &ip, out);
                }
            }
        }
    }
    settle(out, &ip);
    return SYMLINE_OK;
}

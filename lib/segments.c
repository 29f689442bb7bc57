/* SPDX-License-Identifier: Apache-2.0 */
/*
 * From traced chains to segments: corner cuts, fit and classification, and
 * nearness to earlier segments.
 *
 * All geometry is integer: coordinates in Q8 pixels (int32), products in
 * int64, lengths through an integer square root.
 */
#include "segments.h"

/* Corner test span (points on either side) and threshold cos^2(40 deg) ~ 587/1000. */
#define SL_CORNER_SPAN 4
#define SL_COS2_NUM 587
#define SL_COS2_DEN 1000

/* Turn at point i: cos of the angle between the chords i-K..i and i..i+K,
 * as a signed ratio num/den of squares (num = dot*|dot|, den = |v1|^2 |v2|^2).
 * p is a traced chain: neighbours differ by at most 1 in x and y, so each
 * chord component is within +-K and every product here fits 32 bits. */
static void turn_at(const symline_point *p, uint32_t i, int32_t *num, int32_t *den)
{
    const int32_t ax = (int32_t)p[i].x - (int32_t)p[i - SL_CORNER_SPAN].x;
    const int32_t ay = (int32_t)p[i].y - (int32_t)p[i - SL_CORNER_SPAN].y;
    const int32_t bx = (int32_t)p[i + SL_CORNER_SPAN].x - (int32_t)p[i].x;
    const int32_t by = (int32_t)p[i + SL_CORNER_SPAN].y - (int32_t)p[i].y;
    const int32_t dot = ax * bx + ay * by;
    *num = dot * (dot < 0 ? -dot : dot);
    *den = (ax * ax + ay * ay) * (bx * bx + by * by);
}

uint32_t symline_i_corner_cut(const symline_point *p, uint32_t n)
{
    /* The sharpest point of the first run of turning points; n if none (and
     * for chains too short for the test: the loop does not run). */
    uint32_t i, best = n;
    /* The threshold itself: the first turning point is sharper. */
    int32_t bnum = SL_COS2_NUM, bden = SL_COS2_DEN;
    for (i = SL_CORNER_SPAN; i + SL_CORNER_SPAN < n; i++) {
        int32_t num, den;
        turn_at(p, i, &num, &den);
        if (num * SL_COS2_DEN >= SL_COS2_NUM * den) {
            if (best != n) {
                break; /* the run ended */
            }
            continue;
        }
        /* num/den < bnum/bden, denominators positive (chords of K steps are never empty). */
        if (num * bden < bnum * den) {
            best = i;
            bnum = num;
            bden = den;
        }
    }
    return best;
}

/* The length of (dx, dy), rounded down; 32-bit operands, 64-bit squares, a
 * length below 2^31.5 (32 bits). */
SL_NOINLINE static uint32_t hypot_q(int32_t dx, int32_t dy)
{
    return (uint32_t)symline_i_isqrt64((uint64_t)((int64_t)dx * dx + (int64_t)dy * dy));
}

uint32_t symline_i_line_dist_q8(int32_t ax, int32_t ay, int32_t dx, int32_t dy, int32_t px,
                                int32_t py)
{
    /* Differences of Q8 coordinates of one frame fit 25 bits; products 64. */
    const int32_t wx = px - ax, wy = py - ay;
    const uint32_t len = hypot_q(dx, dy);
    int64_t c;
    uint64_t cross;
    if (len == 0u) {
        return hypot_q(wx, wy);
    }
    c = (int64_t)wx * dy - (int64_t)wy * dx;
    cross = (uint64_t)(c < 0 ? -c : c);
    return symline_i_div_q8(cross, len);
}

/* Where the build optimises for speed, the per-point helpers below are
 * computed in their loops (a call per point cost more than the arithmetic). */
#if SL_FOR_SPEED
#define SL_PER_POINT SL_ALWAYS_INLINE
#else
#define SL_PER_POINT SL_NOINLINE
#endif

/* u f[0] + v f[1] + f[2] for point q's grid coordinates in 1/128, u = 128 x
 * + fx, v = 128 y + fy: the cross of a linear form (lin_form()). */
static SL_ALWAYS_INLINE int64_t lin_cross(const symline_point *q, const int64_t f[3])
{
    return (int64_t)(((int32_t)q->x << 7) + q->fx) * f[0] +
           (int64_t)(((int32_t)q->y << 7) + q->fy) * f[1] + f[2];
}

/* Cross product of point q's offset from (x0, y0) with the chord direction
 * (dx, dy), all Q8: |.| / len is its distance to the chord's line. With no
 * direction, its squared distance to (x0, y0). Differences of Q8 coordinates
 * of one frame fit 25 bits: 32-bit operands, 64-bit products. Where the
 * build optimises for speed, f holds the cross as a linear form of the
 * point's grid coordinates in 1/128 (lin_form()): the same value, without
 * the position's shifts per point. */
static SL_PER_POINT int64_t chord_cross(const symline_point *q, uint32_t level, const int32_t g[4],
                                        const int64_t f[3])
{
    const int32_t dx = g[2], dy = g[3];
    int32_t wx, wy;
    if (SL_FOR_SPEED && (dx | dy) != 0) {
        return lin_cross(q, f);
    }
    if (SL_FOR_SPEED) {
        wx = symline_i_pt_q8x(q, level) - g[0];
        wy = symline_i_pt_q8y(q, level) - g[1];
    } else {
        symline_i_pt_off(q, level, g, &wx, &wy);
    }
    return (dx | dy) == 0 ? (int64_t)wx * wx + (int64_t)wy * wy
                          : (int64_t)wx * dy - (int64_t)wy * dx;
}

/* The cross of chord_cross() as u f[0] + v f[1] + f[2] for a point's grid
 * coordinates u = 128 x + fx, v = 128 y + fy: its Q8 position is u s + h
 * (s = 2^(level+1), h the block's half, fixed.h), so the cross
 * (u s + h - x0) dy - (v s + h - y0) dx. Every term stays below 2^53. */
static void lin_form(uint32_t level, const int32_t g[4], int64_t f[3])
{
    const int64_t sc = (int64_t)1 << (level + 1u);
    const int32_t h = (int32_t)symline_i_block_half_q8(level);
    f[0] = (int64_t)g[3] * sc;
    f[1] = -(int64_t)g[2] * sc;
    f[2] = (int64_t)(h - g[0]) * g[3] - (int64_t)(h - g[1]) * g[2];
}

/* Where the build optimises for speed on a 64-bit core (SL_FOR_SPEED_DEEP),
 * a chord with a direction is swept by window_ring(): the crosses of the
 * last SL_RING points are kept (a power of two), so that a window of up to
 * that many points drops its oldest cross without computing it again (the
 * window of five of every fit in locals, window_five()). A
 * 32-bit core would hold them on the stack, on the fit's path, the deepest
 * of the detection: it computes that cross again. */
#define SL_RING 8u

/* window_max() for a chord with a direction and 1 <= win <= SL_RING, f its
 * linear form (lin_form()): the largest and smallest cross and window sum
 * (from 0), whose larger magnitude is the largest |.|. The ring starts at
 * zero, so a window's first points drop nothing; an entry is read before it
 * is written (win = SL_RING drops the one it replaces). */
static void window_ring(const symline_point *p, uint32_t n, const int64_t f[3], uint32_t win,
                        uint64_t best[2])
{
    int64_t hi = 0, lo = 0, shi = 0, slo = 0, sum = 0, ring[SL_RING];
    uint32_t i;
    for (i = 0; i < SL_RING; i++) {
        ring[i] = 0;
    }
    for (i = 0; i < n; i++) {
        const int64_t c = lin_cross(&p[i], f);
        hi = c > hi ? c : hi;
        lo = c < lo ? c : lo;
        if (win == 1u) {
            continue;
        }
        sum += c - ring[(i - win) & (SL_RING - 1u)];
        ring[i & (SL_RING - 1u)] = c;
        if (i + 1u >= win) {
            shi = sum > shi ? sum : shi;
            slo = sum < slo ? sum : slo;
        }
    }
    best[0] = (uint64_t)(hi > -lo ? hi : -lo);
    best[1] = win == 1u ? best[0] : (uint64_t)(shi > -slo ? shi : -slo);
}

/* window_ring() for win = SL_SMOOTH_WIN, the window of every fit and every
 * merge, with n >= win: the window's crosses in locals that take turns (the
 * sweep unrolled by the window), none in memory and no ring index. The same
 * sums, so the same answer. */
#if SL_FOR_SPEED_DEEP
typedef char symline_i_window_is_five[SL_SMOOTH_WIN == 5u ? 1 : -1];

typedef struct five_state {
    int64_t hi, lo, shi, slo, sum;
} five_state;

/* One point: its cross c replaces the window's oldest, *r. */
static SL_ALWAYS_INLINE void five_step(five_state *w, const symline_point *q, const int64_t f[3],
                                       int64_t *r)
{
    const int64_t c = lin_cross(q, f);
    w->hi = c > w->hi ? c : w->hi;
    w->lo = c < w->lo ? c : w->lo;
    w->sum += c - *r;
    *r = c;
    w->shi = w->sum > w->shi ? w->sum : w->shi;
    w->slo = w->sum < w->slo ? w->sum : w->slo;
}

static void window_five(const symline_point *p, uint32_t n, const int64_t f[3], uint64_t best[2])
{
    five_state w = {0, 0, 0, 0, 0};
    int64_t r0 = 0, r1 = 0, r2 = 0, r3 = 0, r4 = 0;
    uint32_t i;
    /* The first window: no sum before it counts (shi, slo stay 0 until it
     * is complete, as in window_ring()). */
    five_step(&w, p, f, &r0);
    five_step(&w, p + 1, f, &r1);
    five_step(&w, p + 2, f, &r2);
    five_step(&w, p + 3, f, &r3);
    w.shi = 0;
    w.slo = 0;
    five_step(&w, p + 4, f, &r4);
    for (i = 5u; i + 5u <= n; i += 5u) {
        five_step(&w, p + i, f, &r0);
        five_step(&w, p + i + 1u, f, &r1);
        five_step(&w, p + i + 2u, f, &r2);
        five_step(&w, p + i + 3u, f, &r3);
        five_step(&w, p + i + 4u, f, &r4);
    }
    if (i < n) {
        five_step(&w, p + i, f, &r0);
    }
    if (i + 1u < n) {
        five_step(&w, p + i + 1u, f, &r1);
    }
    if (i + 2u < n) {
        five_step(&w, p + i + 2u, f, &r2);
    }
    if (i + 3u < n) {
        five_step(&w, p + i + 3u, f, &r3);
    }
    best[0] = (uint64_t)(w.hi > -w.lo ? w.hi : -w.lo);
    best[1] = (uint64_t)(w.shi > -w.slo ? w.shi : -w.slo);
}
#endif

/* The largest |sum| of the crosses of `win` consecutive points of p[0..n-1]
 * (best[1]) and, where the build optimises for speed, in the same sweep the
 * largest |cross| of a point (best[0]). */
static void window_max(const symline_point *p, uint32_t n, uint32_t level, const int32_t g[4],
                       uint32_t win, uint64_t best[2])
{
    int64_t sum = 0, f[3];
    uint32_t i;
    best[0] = best[1] = 0u;
    f[0] = f[1] = f[2] = 0; /* not an initialiser: no memset call */
    if (SL_FOR_SPEED) {
        lin_form(level, g, f);
    }
    if (SL_FOR_SPEED_DEEP && (g[2] | g[3]) != 0 && win <= SL_RING) {
#if SL_FOR_SPEED_DEEP
        if (win == SL_SMOOTH_WIN && n >= win) {
            window_five(p, n, f, best);
            return;
        }
#endif
        window_ring(p, n, f, win, best);
        return;
    }
    for (i = 0; i < n; i++) {
        const int64_t c = chord_cross(&p[i], level, g, f);
        if (SL_FOR_SPEED) {
            const uint64_t a = (uint64_t)(c < 0 ? -c : c);
            best[0] = a > best[0] ? a : best[0];
            if (win == 1u) {
                continue;
            }
        }
        sum += c;
        if (i >= win) {
            sum -= chord_cross(&p[i - win], level, g, f);
        }
        if (i + 1u >= win) {
            const uint64_t m = (uint64_t)(sum < 0 ? -sum : sum);
            best[1] = m > best[1] ? m : best[1];
        }
    }
    if (SL_FOR_SPEED && win == 1u) {
        best[1] = best[0];
    }
}

/* The sweep over p[0..n-1] (n > 0) for chord c: *win clamped to what it
 * means for the chord, best as window_max() sets it; returns the chord's
 * length (0: no direction, best holds squared distances to the end). */
static uint64_t chord_sweep(const symline_point *p, uint32_t n, uint32_t level,
                            const symline_segment *c, uint32_t *win, uint64_t best[2])
{
    /* The chord: its first end and its direction (x0, y0, dx, dy). */
    const int32_t dx = c->x1 - c->x0, dy = c->y1 - c->y0, g[4] = {c->x0, c->y0, dx, dy};
    /* The cross product is linear in the point: a window's mean point lies
     * sum / win from the chord. The largest one first, one square root and
     * one division at the end. With no direction: the distance to the end
     * itself, point by point. */
    *win = (dx | dy) == 0 || *win < 1u ? 1u : (*win > n ? n : *win);
    window_max(p, n, level, g, *win, best);
    return hypot_q(dx, dy); /* 0 for no direction */
}

/* The distance (Q8) a sweep's best stands for: best / (win len), or its
 * square root for no direction (len 0). */
static uint32_t dev_of(uint64_t best, uint64_t len, uint32_t win)
{
    /* floor(floor(best / win) / len) = floor(best / (win len)): no 64-bit
     * division (its library helper's frame would deepen the stack). */
    return len == 0u ? (uint32_t)symline_i_isqrt64(best) : symline_i_div_q8(best, len * win);
}

SL_NOINLINE uint32_t symline_i_chord_dev(const symline_point *p, uint32_t n, uint32_t level,
                                         const symline_segment *c, uint32_t win)
{
    uint64_t best[2], len;
    if (n == 0u) {
        return 0u;
    }
    len = chord_sweep(p, n, level, c, &win, best);
    return dev_of(best[1], len, win);
}

#if SL_FOR_SPEED /* segments.h: two sweeps where the build optimises for size */
void symline_i_chord_devs(const symline_point *p, uint32_t n, uint32_t level,
                          const symline_segment *c, uint32_t win, uint32_t dev[2])
{
    uint64_t best[2], len;
    if (n == 0u) {
        dev[0] = dev[1] = 0u;
        return;
    }
    len = chord_sweep(p, n, level, c, &win, best);
    dev[0] = dev_of(best[0], len, 1u);
    dev[1] = dev_of(best[1], len, win);
}
#endif

/* A curve bends away from its chord by more than the threshold and by more
 * than 1/32 of the chord: a straight line's pixel steps and noise stay near
 * 1-2 px however long it is, while an arc's sagitta grows with its chord. */
bool symline_i_is_curve(const symline_segment *c, uint32_t max_dev, uint32_t thr)
{
    /* 25 bits: Q8 coordinates of one frame */
    const int32_t dx = c->x1 - c->x0, dy = c->y1 - c->y0;
    const uint32_t chord = hypot_q(dx, dy);
    return max_dev > thr && (uint64_t)max_dev * 32u > chord;
}

/*
 * Least-squares line through the points (principal axis of their scatter),
 * in integers: the ends become the first and last point projected onto it,
 * which gives sub-pixel ends and removes the one-pixel jitter of traced
 * points. Long chains are sampled (at most 2048 points) so that every sum and
 * every division stays in 32 bits; only products use 64 bits. Returns false when
 * the scatter has no direction (all points equal).
 */
#define SL_FIT_SAMPLES 2048u

/* The fit's frame: the points' level, the origin o (Q8 full
 * resolution) and the mean (mx, my) (Q4, relative to the origin). */
typedef struct symline_i_fitframe {
    uint32_t level;
    int32_t o[2], mx, my;
} symline_i_fitframe;

/* Point q in Q4 full resolution relative to the origin, minus the mean. */
static SL_PER_POINT void rel_q4(const symline_point *q, const symline_i_fitframe *f, int32_t *x,
                                int32_t *y)
{
    if (SL_FOR_SPEED) {
        *x = symline_i_pt_q8x(q, f->level) - f->o[0];
        *y = symline_i_pt_q8y(q, f->level) - f->o[1];
    } else {
        symline_i_pt_off(q, f->level, f->o, x, y);
    }
    *x = *x / 16 - f->mx;
    *y = *y / 16 - f->my;
}

SL_NOINLINE static bool ls_ends(const symline_point *p, uint32_t n, uint32_t level,
                                symline_segment *s)
{
    /* Coordinates in Q4 full resolution, relative to the first point. */
    const uint32_t step = n / SL_FIT_SAMPLES + 1u;
    symline_i_fitframe f;
    int32_t ux, uy, len;
    uint32_t sx = 0u, sy = 0u; /* the second sweep's sums wrap unused */
    int64_t a = 0, b = 0, c = 0;
    uint32_t i, k, cnt = 0u;
    f.level = level;
    symline_i_pt_off(&p[0], level, NULL, &f.o[0], &f.o[1]);
    /* Two sweeps: the mean (mx, my still 0), then the scatter about it. */
    f.mx = f.my = 0;
    if (SL_FOR_SPEED) {
        /* The same in one sweep: the sums of the offsets d, their squares and
         * products, then sum (d - m)^2 = sum d^2 - 2 m sum d + cnt m^2 (and
         * alike for the product), exact in 64 bits: |d| < 2^21 (a Q8
         * difference of 25 bits over 16), at most 2^11 samples, so every sum
         * and term stays below 2^55. The mean divides the 32-bit sums, as
         * the first sweep does. */
        int64_t tx = 0, ty = 0;
        for (i = 0; i < n; i += step) {
            int32_t dx, dy;
            rel_q4(&p[i], &f, &dx, &dy);
            tx += dx;
            ty += dy;
            cnt++;
            a += (int64_t)dx * dx;
            b += (int64_t)dx * dy;
            c += (int64_t)dy * dy;
        }
        f.mx = (int32_t)(uint32_t)tx / (int32_t)cnt;
        f.my = (int32_t)(uint32_t)ty / (int32_t)cnt;
        a += f.mx * ((int64_t)f.mx * cnt - 2 * tx);
        b += (int64_t)f.mx * f.my * cnt - (int64_t)f.mx * ty - (int64_t)f.my * tx;
        c += f.my * ((int64_t)f.my * cnt - 2 * ty);
    }
    for (k = SL_FOR_SPEED ? 2u : 0u; k < 2u; k++) {
        for (i = 0; i < n; i += step) {
            int32_t dx, dy;
            rel_q4(&p[i], &f, &dx, &dy);
            sx += (uint32_t)dx;
            sy += (uint32_t)dy;
            cnt++;
            a += (int64_t)dx * dx;
            b += (int64_t)dx * dy;
            c += (int64_t)dy * dy;
        }
        if (k == 0u) {
            f.mx = (int32_t)sx / (int32_t)cnt;
            f.my = (int32_t)sy / (int32_t)cnt;
            a = b = c = 0;
        }
    }
    /* Until a, c (never negative) and |b| are below 2^30. */
    while ((a | c) >= ((int64_t)1 << 30) ||
           (uint64_t)(b + ((int64_t)1 << 30) - 1) > ((uint64_t)1 << 31) - 2u) {
        a >>= 1;
        b /= 2;
        c >>= 1;
    }
    {
        /* Below 2^30 each: 32-bit operands, 64-bit products. b^2 <= ac (less
         * the halvings' rounding) keeps the larger eigenvalue lam = (a + c) / 2
         * + r within a + c + 1 < 2^31. */
        const int32_t a32 = (int32_t)a, c32 = (int32_t)c, ac = a32 - c32, b32 = (int32_t)b;
        const uint32_t lam = (uint32_t)(a32 + c32) / 2u +
                             (uint32_t)symline_i_isqrt64((uint64_t)((int64_t)ac * ac) / 4u +
                                                         (uint64_t)((int64_t)b32 * b32));
        ux = a32 >= c32 ? (int32_t)(lam - (uint32_t)c32) : b32;
        uy = a32 >= c32 ? b32 : (int32_t)(lam - (uint32_t)a32);
    }
    /* Halved until both are within +-2^15: their squares' sum fits 32 bits. */
    while (SL_OUTSIDE(ux, 32767) || SL_OUTSIDE(uy, 32767)) {
        ux /= 2;
        uy /= 2;
    }
    len = (int32_t)hypot_q(ux, uy);
    if (len == 0) {
        return false;
    }
    /* Unit direction in Q15 (32-bit divisions). */
    ux = ux * 32768 / len;
    uy = uy * 32768 / len;
    for (i = 0; i < 2u; i++) {
        int32_t qx, qy;
        int64_t t;
        rel_q4(&p[i == 0u ? 0u : n - 1u], &f, &qx, &qy);
        t = (int64_t)qx * ux + (int64_t)qy * uy; /* Q4 * Q15 */
        /* Back to Q8 absolute: mean + t*u, Q4*Q15*Q15 -> Q8 is a shift by 26. */
        const int32_t ex = f.o[0] + f.mx * 16 + (int32_t)((t * ux) >> 26);
        const int32_t ey = f.o[1] + f.my * 16 + (int32_t)((t * uy) >> 26);
        if (i == 0u) {
            s->x0 = ex;
            s->y0 = ey;
        } else {
            s->x1 = ex;
            s->y1 = ey;
        }
    }
    return true;
}

/*
 * Bend of a piece: the mean signed distance to the chord of the points in the
 * chord's middle half minus that of the points in its outer quarters (Q8 px
 * of the pass's grid, absolute). Pixel steps and noise of a straight line average
 * out (and a tilted chord cancels by symmetry), while an arc keeps about two
 * thirds of its sagitta: a flat piece of the centre circle is told from a line
 * even where its largest deviation stays under the curve threshold.
 */
/* sum / (cnt len) in Q7 grid pixels, signed (Q7 keeps a difference of two in range). */
SL_NOINLINE static int32_t mean_q7(int64_t sum, uint32_t cnt, uint32_t len)
{
    const uint32_t a =
        symline_i_div_q8((uint64_t)(sum < 0 ? -sum : sum) << SL_Q8_SHIFT, (uint64_t)cnt * len);
    return sum < 0 ? -(int32_t)(a >> 1) : (int32_t)(a >> 1);
}

uint32_t symline_i_bend_q8(const symline_point *p, uint32_t n)
{
    /* Grid coordinates: differences fit 32 bits, products 64. */
    const int32_t x0 = p[0].x, y0 = p[0].y;
    const int32_t dx = (int32_t)p[n - 1u].x - x0, dy = (int32_t)p[n - 1u].y - y0;
    const int64_t dd = (int64_t)dx * dx + (int64_t)dy * dy;
    /* Below 2^17: grid coordinates are 16-bit. */
    const uint32_t len = (uint32_t)symline_i_isqrt64((uint64_t)dd);
    int64_t sm = 0, so = 0;
    uint32_t nm = 0u, no = 0u, i;
    int32_t d;
    for (i = 0; i < n; i++) {
        const int32_t wx = (int32_t)p[i].x - x0, wy = (int32_t)p[i].y - y0;
        const int64_t t = 4 * ((int64_t)wx * dx + (int64_t)wy * dy);
        const int64_t c = (int64_t)wx * dy - (int64_t)wy * dx;
        if ((uint64_t)(t - dd) <= (uint64_t)(2 * dd)) { /* dd <= t <= 3 dd */
            sm += c;
            nm++;
        } else {
            so += c;
            no++;
        }
    }
    if (nm == 0u || no == 0u || len == 0u) {
        return 0u;
    }
    d = mean_q7(sm, nm, len) - mean_q7(so, no, len);
    d = d < 0 ? -d : d;
    return (uint32_t)d << 1;
}

/* The chord of p[0..n-1]'s first and last point as s's ends, its max_dev,
 * and the smoothed deviation from it (returned). */
static uint32_t chord_ends(const symline_point *p, uint32_t n, uint32_t level, symline_segment *s)
{
    uint32_t dev[2];
    symline_i_pt_off(&p[0], level, NULL, &s->x0, &s->y0);
    symline_i_pt_off(&p[n - 1u], level, NULL, &s->x1, &s->y1);
    symline_i_chord_devs(p, n, level, s, SL_SMOOTH_WIN, dev);
    s->max_dev = dev[0];
    return dev[1];
}

void symline_i_fit(const symline_point *p, uint32_t n, uint32_t level, uint32_t curve_dev_q8,
                   symline_segment *s)
{
    const uint32_t thr = curve_dev_q8 + symline_i_block_half_q8(level);
    bool curve;
    curve = symline_i_is_curve(s, chord_ends(p, n, level, s), thr);
    s->kind = (uint8_t)(curve ? SYMLINE_KIND_CURVE : SYMLINE_KIND_LINE);
    if (s->kind == SYMLINE_KIND_LINE && n >= 3u && ls_ends(p, n, level, s)) {
        s->max_dev = symline_i_max_dev(p, n, level, s);
    }
    s->level = (uint8_t)level;
    s->merged = false;
}

/* symline_i_near_run(); where the build optimises for speed, also inline in
 * symline_i_near_segment(), whose frame then stays the only one a chain's
 * test of an earlier curve adds (no call per curve either). */
#if SL_FOR_SPEED
#define SL_RUN_INLINE SL_ALWAYS_INLINE
#else
#define SL_RUN_INLINE
#endif
static SL_RUN_INLINE bool near_run(const symline_point *p, uint32_t last, const symline_i_near *q)
{
    uint32_t i;
    for (i = 0; i < last; i += SL_POLY_STEP) {
        const symline_point *a = &p[i], *b = &p[i + SL_POLY_STEP < last ? i + SL_POLY_STEP : last];
        /* Whole pixels: the tolerance is 2 px and more, the offsets would only cost. */
        if (symline_i_near_chord((int32_t)a->x << SL_Q8_SHIFT, (int32_t)a->y << SL_Q8_SHIFT,
                                 (int32_t)b->x << SL_Q8_SHIFT, (int32_t)b->y << SL_Q8_SHIFT, q)) {
            return true;
        }
    }
    return false;
}

bool symline_i_near_run(const symline_point *p, uint32_t last, const symline_i_near *q)
{
    return near_run(p, last, q);
}

bool symline_i_near_segment(const symline_segment *s, const symline_point *pts,
                            const symline_i_near *q)
{
    if (s->kind == SYMLINE_KIND_LINE || s->count < 2u) {
        return symline_i_near_chord(s->x0, s->y0, s->x1, s->y1, q);
    }
    return near_run(pts + s->first, s->count - 1u, q);
}

void symline_i_bend_check(const symline_point *p, uint32_t n, uint32_t level, uint32_t bend_thr,
                          symline_segment *s)
{
    if (symline_i_bend_q8(p, n) < bend_thr) {
        return;
    }
    /* A curve keeps the chord of its first and last point (no line fit). */
    s->kind = SYMLINE_KIND_CURVE;
    (void)chord_ends(p, n, level, s);
}

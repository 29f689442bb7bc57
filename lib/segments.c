/*
 * From traced chains to segments: corner cuts, fit and classification,
 * nearness to earlier segments, and the merge of collinear pieces.
 *
 * All geometry is integer: coordinates in Q8 pixels (int32), products in
 * int64, lengths through an integer square root.
 */
#include "detect_internal.h"

uint64_t sl_isqrt64(uint64_t v)
{
    uint64_t r = 0u, bit = (uint64_t)1u << 62;
    while (bit > v) {
        bit >>= 2;
    }
    while (bit != 0u) {
        if (v >= r + bit) {
            v -= r + bit;
            r = (r >> 1) + bit;
        } else {
            r >>= 1;
        }
        bit >>= 2;
    }
    return r;
}

/* Corner test span (points on either side) and threshold cos^2(40 deg) ~ 587/1000. */
#define SL_CORNER_SPAN 4
#define SL_COS2_NUM 587
#define SL_COS2_DEN 1000

/* Turn at point i: cos of the angle between the chords i-K..i and i..i+K,
 * as a signed ratio num/den of squares (num = dot*|dot|, den = |v1|^2 |v2|^2). */
static void turn_at(const symline_point *p, uint32_t i, int64_t *num, int64_t *den)
{
    const int32_t ax = (int32_t)p[i].x - (int32_t)p[i - SL_CORNER_SPAN].x;
    const int32_t ay = (int32_t)p[i].y - (int32_t)p[i - SL_CORNER_SPAN].y;
    const int32_t bx = (int32_t)p[i + SL_CORNER_SPAN].x - (int32_t)p[i].x;
    const int32_t by = (int32_t)p[i + SL_CORNER_SPAN].y - (int32_t)p[i].y;
    const int64_t dot = (int64_t)ax * bx + (int64_t)ay * by;
    *num = dot * (dot < 0 ? -dot : dot);
    *den = ((int64_t)ax * ax + (int64_t)ay * ay) * ((int64_t)bx * bx + (int64_t)by * by);
}

static int is_corner(int64_t num, int64_t den)
{
    return num * SL_COS2_DEN < (int64_t)SL_COS2_NUM * den;
}

uint32_t sl_corner_cut(const symline_point *p, uint32_t n)
{
    uint32_t i;
    if (n < 2u * SL_CORNER_SPAN + 1u) {
        return n;
    }
    for (i = SL_CORNER_SPAN; i + SL_CORNER_SPAN < n; i++) {
        int64_t num, den;
        turn_at(p, i, &num, &den);
        if (is_corner(num, den)) {
            /* Cut at the sharpest point of this run of turning points. */
            uint32_t best = i, j;
            int64_t bnum = num, bden = den;
            for (j = i + 1u; j + SL_CORNER_SPAN < n; j++) {
                int64_t jn, jd;
                turn_at(p, j, &jn, &jd);
                if (!is_corner(jn, jd)) {
                    break;
                }
                /* jn/jd < bnum/bden, denominators positive (chords of K steps are never empty). */
                if (jn * bden < bnum * jd) {
                    best = j;
                    bnum = jn;
                    bden = jd;
                }
            }
            return best;
        }
    }
    return n;
}

/* Distance (Q8) of point (px, py) to the line through a with direction (dx, dy), all Q8. */
static uint32_t line_dist_q8(int32_t ax, int32_t ay, int32_t dx, int32_t dy, int32_t px,
                             int32_t py)
{
    const int64_t wx = (int64_t)px - ax, wy = (int64_t)py - ay;
    const uint64_t len = sl_isqrt64((uint64_t)((int64_t)dx * dx + (int64_t)dy * dy));
    int64_t cross;
    if (len == 0u) {
        return (uint32_t)sl_isqrt64((uint64_t)(wx * wx + wy * wy));
    }
    cross = wx * dy - wy * dx;
    if (cross < 0) {
        cross = -cross;
    }
    return (uint32_t)((uint64_t)cross / len);
}

static uint32_t max_dev_q8(const symline_point *p, uint32_t n, uint32_t level, int32_t x0,
                           int32_t y0, int32_t x1, int32_t y1)
{
    uint32_t i, best = 0u;
    for (i = 0; i < n; i++) {
        const uint32_t d =
            line_dist_q8(x0, y0, x1 - x0, y1 - y0, sl_q8(p[i].x, level), sl_q8(p[i].y, level));
        if (d > best) {
            best = d;
        }
    }
    return best;
}

/* A curve bends away from its chord by more than the threshold and by more
 * than 1/32 of the chord: a straight line's pixel steps and noise stay near
 * 1-2 px however long it is, while an arc's sagitta grows with its chord. */
static int sl_is_curve(const symline_segment *s, uint32_t thr)
{
    const int64_t dx = (int64_t)s->x1 - s->x0, dy = (int64_t)s->y1 - s->y0;
    const uint64_t chord = sl_isqrt64((uint64_t)(dx * dx + dy * dy));
    return s->max_dev > thr && (uint64_t)s->max_dev * 32u > chord;
}

/* Shifts the pair right until both magnitudes are below 2^bits (keeps the ratio). */
static void shrink(int64_t *a, int64_t *b, unsigned bits)
{
    const int64_t lim = (int64_t)1 << bits;
    while (*a >= lim || *a <= -lim || *b >= lim || *b <= -lim) {
        *a /= 2;
        *b /= 2;
    }
}

/*
 * Least-squares line through the points (principal axis of their scatter),
 * in integers: the ends become the first and last point projected onto it,
 * which gives sub-pixel ends and removes the one-pixel jitter of traced
 * points. Returns 0 when the scatter has no direction (all points equal).
 */
static int ls_ends(const symline_point *p, uint32_t n, uint32_t level, symline_segment *s)
{
    int64_t sx = 0, sy = 0, a = 0, b = 0, c = 0, mx, my, r, lam, vx, vy, vv, dot;
    uint32_t i;
    /* Means in Q8 of full resolution. */
    for (i = 0; i < n; i++) {
        sx += sl_q8(p[i].x, level);
        sy += sl_q8(p[i].y, level);
    }
    mx = sx / (int64_t)n;
    my = sy / (int64_t)n;
    /* Second moments in Q4 (products fit: |d| < 2^21, n < 2^21). */
    for (i = 0; i < n; i++) {
        const int64_t dx = ((int64_t)sl_q8(p[i].x, level) - mx) / 16;
        const int64_t dy = ((int64_t)sl_q8(p[i].y, level) - my) / 16;
        a += dx * dx;
        b += dx * dy;
        c += dy * dy;
    }
    while (a >= ((int64_t)1 << 30) || c >= ((int64_t)1 << 30) || b >= ((int64_t)1 << 30) ||
           b <= -((int64_t)1 << 30)) {
        a /= 2;
        b /= 2;
        c /= 2;
    }
    r = (int64_t)sl_isqrt64((uint64_t)((a - c) * (a - c) / 4 + b * b));
    lam = (a + c) / 2 + r;
    if (a >= c) {
        vx = lam - c;
        vy = b;
    } else {
        vx = b;
        vy = lam - a;
    }
    if (vx == 0 && vy == 0) {
        return 0;
    }
    shrink(&vx, &vy, 15);
    vv = vx * vx + vy * vy;
    if (vv == 0) {
        return 0;
    }
    dot = ((int64_t)s->x0 - mx) * vx + ((int64_t)s->y0 - my) * vy;
    s->x0 = (int32_t)(mx + dot * vx / vv);
    s->y0 = (int32_t)(my + dot * vy / vv);
    dot = ((int64_t)s->x1 - mx) * vx + ((int64_t)s->y1 - my) * vy;
    s->x1 = (int32_t)(mx + dot * vx / vv);
    s->y1 = (int32_t)(my + dot * vy / vv);
    return 1;
}

void sl_fit(const symline_point *p, uint32_t n, uint32_t level, uint32_t curve_dev_q8,
            symline_segment *s)
{
    const uint32_t thr = curve_dev_q8 + (((1u << level) - 1u) << 7);
    s->x0 = sl_q8(p[0].x, level);
    s->y0 = sl_q8(p[0].y, level);
    s->x1 = sl_q8(p[n - 1u].x, level);
    s->y1 = sl_q8(p[n - 1u].y, level);
    s->max_dev = max_dev_q8(p, n, level, s->x0, s->y0, s->x1, s->y1);
    s->kind = (uint8_t)(sl_is_curve(s, thr) ? SYMLINE_KIND_CURVE : SYMLINE_KIND_LINE);
    if (s->kind == SYMLINE_KIND_LINE && n >= 3u) {
        symline_segment f = *s;
        if (ls_ends(p, n, level, &f)) {
            f.max_dev = max_dev_q8(p, n, level, f.x0, f.y0, f.x1, f.y1);
            *s = f;
        }
    }
    s->level = (uint8_t)level;
    s->reserved = 0u;
}

/* 1 when (px, py) lies within tol of the segment a-b (all Q8). */
static int near_chord(int32_t ax, int32_t ay, int32_t bx, int32_t by, int32_t px, int32_t py,
                      int32_t tol)
{
    int64_t dx, dy, wx, wy, t, dd;
    if ((px < ax - tol && px < bx - tol) || (px > ax + tol && px > bx + tol) ||
        (py < ay - tol && py < by - tol) || (py > ay + tol && py > by + tol)) {
        return 0;
    }
    dx = (int64_t)bx - ax;
    dy = (int64_t)by - ay;
    wx = (int64_t)px - ax;
    wy = (int64_t)py - ay;
    t = wx * dx + wy * dy;
    dd = dx * dx + dy * dy;
    if (t <= 0 || dd == 0) {
        return wx * wx + wy * wy <= (int64_t)tol * tol;
    }
    if (t >= dd) {
        const int64_t ex = (int64_t)px - bx, ey = (int64_t)py - by;
        return ex * ex + ey * ey <= (int64_t)tol * tol;
    }
    return line_dist_q8(ax, ay, bx - ax, by - ay, px, py) <= (uint32_t)tol;
}

/* Curves are followed through every SL_POLY_STEP-th point. */
#define SL_POLY_STEP 4u

int sl_near_segment(const symline_segment *s, const symline_point *pts, int32_t x, int32_t y,
                    int32_t tol_q8)
{
    uint32_t i;
    const symline_point *p = pts + s->first;
    if (s->kind == SYMLINE_KIND_LINE || s->count < 2u) {
        return near_chord(s->x0, s->y0, s->x1, s->y1, x, y, tol_q8);
    }
    for (i = 0; i + 1u < s->count; i += SL_POLY_STEP) {
        const uint32_t j = (i + SL_POLY_STEP < s->count) ? i + SL_POLY_STEP : s->count - 1u;
        if (near_chord((int32_t)p[i].x << 8, (int32_t)p[i].y << 8, (int32_t)p[j].x << 8,
                       (int32_t)p[j].y << 8, x, y, tol_q8)) {
            return 1;
        }
    }
    return 0;
}

/* ---- merge of collinear pieces ---- */

static void reverse_pts(symline_point *p, uint32_t n)
{
    uint32_t i;
    for (i = 0; i < n / 2u; i++) {
        const symline_point t = p[i];
        p[i] = p[n - 1u - i];
        p[n - 1u - i] = t;
    }
}

static uint64_t dist2(int32_t ax, int32_t ay, int32_t bx, int32_t by)
{
    const int64_t dx = (int64_t)ax - bx, dy = (int64_t)ay - by;
    return (uint64_t)(dx * dx + dy * dy);
}

/* Largest distance of a segment's points (full-resolution integers) to a chord. */
static uint32_t dev_of_points(const symline_point *p, uint32_t n, int32_t x0, int32_t y0,
                              int32_t x1, int32_t y1)
{
    uint32_t i, best = 0u;
    for (i = 0; i < n; i++) {
        const uint32_t d =
            line_dist_q8(x0, y0, x1 - x0, y1 - y0, (int32_t)p[i].x << 8, (int32_t)p[i].y << 8);
        if (d > best) {
            best = d;
        }
    }
    return best;
}

/* Tries to merge line b into line a; 1 when the geometry allows it (ends set in *ends). */
static int mergeable(const symline_segment *a, const symline_segment *b, const symline_point *pts,
                     uint64_t gap2, uint32_t dev_q8, uint32_t curve_q8, int32_t ends[4],
                     uint32_t *dev)
{
    const int32_t ex[4] = {a->x0, a->x1, b->x0, b->x1};
    const int32_t ey[4] = {a->y0, a->y1, b->y0, b->y1};
    const int32_t adx = a->x1 - a->x0, ady = a->y1 - a->y0;
    const int32_t bdx = b->x1 - b->x0, bdy = b->y1 - b->y0;
    uint64_t g = dist2(a->x0, a->y0, b->x0, b->y0), t;
    int64_t lo, hi, proj;
    uint32_t i, ilo = 0u, ihi = 0u, d1, d2;
    t = dist2(a->x0, a->y0, b->x1, b->y1);
    g = t < g ? t : g;
    t = dist2(a->x1, a->y1, b->x0, b->y0);
    g = t < g ? t : g;
    t = dist2(a->x1, a->y1, b->x1, b->y1);
    g = t < g ? t : g;
    if (g > gap2) {
        return 0;
    }
    if (line_dist_q8(a->x0, a->y0, adx, ady, b->x0, b->y0) > dev_q8 ||
        line_dist_q8(a->x0, a->y0, adx, ady, b->x1, b->y1) > dev_q8 ||
        line_dist_q8(b->x0, b->y0, bdx, bdy, a->x0, a->y0) > dev_q8 ||
        line_dist_q8(b->x0, b->y0, bdx, bdy, a->x1, a->y1) > dev_q8) {
        return 0;
    }
    /* New ends: the extreme end points along the longer piece. */
    {
        const int a_longer =
            dist2(a->x0, a->y0, a->x1, a->y1) >= dist2(b->x0, b->y0, b->x1, b->y1);
        const int32_t dx = a_longer ? adx : bdx;
        const int32_t dy = a_longer ? ady : bdy;
        lo = hi = (int64_t)ex[0] * dx + (int64_t)ey[0] * dy;
        for (i = 1u; i < 4u; i++) {
            proj = (int64_t)ex[i] * dx + (int64_t)ey[i] * dy;
            if (proj < lo) {
                lo = proj;
                ilo = i;
            }
            if (proj > hi) {
                hi = proj;
                ihi = i;
            }
        }
    }
    ends[0] = ex[ilo];
    ends[1] = ey[ilo];
    ends[2] = ex[ihi];
    ends[3] = ey[ihi];
    d1 = dev_of_points(pts + a->first, a->count, ends[0], ends[1], ends[2], ends[3]);
    d2 = dev_of_points(pts + b->first, b->count, ends[0], ends[1], ends[2], ends[3]);
    *dev = d1 > d2 ? d1 : d2;
    {
        symline_segment m = *a;
        m.x0 = ends[0];
        m.y0 = ends[1];
        m.x1 = ends[2];
        m.y1 = ends[3];
        m.max_dev = *dev;
        return !sl_is_curve(&m, curve_q8);
    }
}

/* Moves segment j's points right behind segment i's (i < j, ranges ordered), removes j. */
static void absorb(symline_result *r, uint32_t i, uint32_t j)
{
    symline_segment *a = &r->segments[i];
    const symline_segment b = r->segments[j];
    const uint32_t mid0 = a->first + a->count;
    const uint32_t midn = b.first - mid0;
    uint32_t k;
    reverse_pts(r->points + mid0, midn);
    reverse_pts(r->points + b.first, b.count);
    reverse_pts(r->points + mid0, midn + b.count);
    for (k = i + 1u; k < j; k++) {
        r->segments[k].first += b.count;
    }
    a->count += b.count;
    for (k = j; k + 1u < r->segment_count; k++) {
        r->segments[k] = r->segments[k + 1u];
    }
    r->segment_count--;
}

void sl_merge(symline_result *r, uint32_t gap_px, uint32_t dev_q8, uint32_t curve_dev_q8)
{
    const uint64_t gap2 = ((uint64_t)gap_px << 8) * ((uint64_t)gap_px << 8);
    uint32_t i, j;
    int changed = 1;
    while (changed) {
        changed = 0;
        for (i = 0; i < r->segment_count; i++) {
            if (r->segments[i].kind != SYMLINE_KIND_LINE) {
                continue;
            }
            for (j = i + 1u; j < r->segment_count; j++) {
                int32_t ends[4];
                uint32_t dev;
                symline_segment *a = &r->segments[i];
                const symline_segment *b = &r->segments[j];
                const uint32_t lv = a->level > b->level ? a->level : b->level;
                const uint32_t thr = curve_dev_q8 + (((1u << lv) - 1u) << 7);
                if (b->kind != SYMLINE_KIND_LINE) {
                    continue;
                }
                if (!mergeable(a, b, r->points, gap2, dev_q8 + (((1u << lv) - 1u) << 7), thr,
                               ends, &dev)) {
                    continue;
                }
                a->x0 = ends[0];
                a->y0 = ends[1];
                a->x1 = ends[2];
                a->y1 = ends[3];
                a->max_dev = dev;
                a->level = (uint8_t)lv;
                absorb(r, i, j);
                changed = 1;
                j = i; /* the grown segment may now reach pieces it missed */
            }
        }
    }
}

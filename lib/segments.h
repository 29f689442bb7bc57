/* SPDX-License-Identifier: Apache-2.0 */
/*
 * From traced chains to segments (segments.c): corner cuts, the fit and the
 * line/curve decision, and the geometry the later stages share (distances
 * to chords and segments). Coordinates in Q8 px (fixed.h).
 */
#ifndef SYMLINE_LIB_SEGMENTS_H
#define SYMLINE_LIB_SEGMENTS_H

#include "common.h"
#include "fixed.h"
#include "symline/detect.h"

/* Length of the first piece of chain p[0..n-1] before a sharp corner (n if none). */
uint32_t symline_i_corner_cut(const symline_point *p, uint32_t n);

/* Fits a segment to p[0..n-1] (grid coordinates at `level`): ends, max_dev,
 * kind (a curve when max_dev exceeds curve_dev_q8 plus half a block), level;
 * first, count and axis are left to the caller. */
void symline_i_fit(const symline_point *p, uint32_t n, uint32_t level, uint32_t curve_dev_q8,
                   symline_segment *s);

/* Bend of p[0..n-1] (grid coordinates): mean distance to the chord of the middle
 * half minus that of the outer quarters, Q8 grid px, absolute. */
uint32_t symline_i_bend_q8(const symline_point *p, uint32_t n);

/* Makes line s (fitted to p[0..n-1] at `level`) a curve when its bend reaches
 * bend_thr: kind, raw chord ends and max_dev. */
void symline_i_bend_check(const symline_point *p, uint32_t n, uint32_t level, uint32_t bend_thr,
                          symline_segment *s);

/* Distance (Q8) of (px, py) to the line through a with direction (dx, dy), all Q8. */
uint32_t symline_i_line_dist_q8(int32_t ax, int32_t ay, int32_t dx, int32_t dy, int32_t px,
                                int32_t py);

/* Largest distance (Q8) to the chord of c (its ends x0,y0-x1,y1, Q8; nothing
 * else of c is read) of the mean of every `win` consecutive points of
 * p[0..n-1] (grid coordinates at `level`; level 0 for full-resolution
 * points); win 1: of every point. With equal chord ends: the distance to that
 * end. 0 for no points. */
uint32_t symline_i_chord_dev(const symline_point *p, uint32_t n, uint32_t level,
                             const symline_segment *c, uint32_t win);

/* The same for win 1 (dev[0], the max_dev) and win (dev[1]): in one sweep
 * where the build optimises for speed, else in two (the smaller code). */
#if SL_FOR_SPEED
void symline_i_chord_devs(const symline_point *p, uint32_t n, uint32_t level,
                          const symline_segment *c, uint32_t win, uint32_t dev[2]);
#else
static inline void symline_i_chord_devs(const symline_point *p, uint32_t n, uint32_t level,
                                        const symline_segment *c, uint32_t win, uint32_t dev[2])
{
    dev[0] = symline_i_chord_dev(p, n, level, c, 1u);
    dev[1] = symline_i_chord_dev(p, n, level, c, win);
}
#endif

/* Points per window of the smoothed deviation: a traced ridge on turf jitters
 * by a pixel or two from point to point, an arc's sagitta does not average out. */
#define SL_SMOOTH_WIN 5u

/* Largest distance (Q8) of the points to the chord: a segment's max_dev. */
static inline uint32_t symline_i_max_dev(const symline_point *p, uint32_t n, uint32_t level,
                                         const symline_segment *c)
{
    return symline_i_chord_dev(p, n, level, c, 1u);
}

/* The same for the mean of every SL_SMOOTH_WIN consecutive points: the bend
 * of the piece without the point-to-point jitter of its ridge. */
static inline uint32_t symline_i_smooth_dev(const symline_point *p, uint32_t n, uint32_t level,
                                            const symline_segment *c)
{
    return symline_i_chord_dev(p, n, level, c, SL_SMOOTH_WIN);
}

/* Curve test: max_dev above thr and above 1/32 of c's chord (its ends). */
bool symline_i_is_curve(const symline_segment *c, uint32_t max_dev, uint32_t thr);

/* Curves are followed through every SL_POLY_STEP-th point (symline_i_near_segment(),
 * and the grid of earlier segments, segindex.c). */
#define SL_POLY_STEP 4u

/* A nearness query: is the full-resolution point (x, y) (Q8) within tol
 * (Q8) of a segment or piece? */
typedef struct symline_i_near {
    int32_t x, y, tol;
} symline_i_near;

/* True when q's point lies within q's tolerance of the segment a-b (all Q8):
 * the test of symline_i_near_run() and symline_i_near_segment(), inline
 * here for the grid of earlier segments (segindex.c, SL_FOR_SPEED_DEEP). */
static inline bool symline_i_near_chord(int32_t ax, int32_t ay, int32_t bx, int32_t by,
                                        const symline_i_near *q)
{
    const int32_t px = q->x, py = q->y, tol = q->tol;
    /* Differences of Q8 coordinates fit 32 bits; only products need 64. */
    int32_t dx, dy, wx, wy, c;
    uint32_t t2; /* the tolerance (never negative), halved with the rest */
    int64_t t, dd;
    if ((px < ax - tol && px < bx - tol) || (px > ax + tol && px > bx + tol) ||
        (py < ay - tol && py < by - tol) || (py > ay + tol && py > by + tol)) {
        return false;
    }
    dx = bx - ax;
    dy = by - ay;
    wx = px - ax;
    wy = py - ay;
    t = (int64_t)wx * dx + (int64_t)wy * dy;
    dd = (int64_t)dx * dx + (int64_t)dy * dy;
    if (t <= 0 || t >= dd) {
        /* Beyond an end (or no chord, t = 0): the distance to that end. */
        const int32_t ex = t <= 0 ? wx : px - bx, ey = t <= 0 ? wy : py - by;
        return (int64_t)ex * ex + (int64_t)ey * ey <= (int64_t)tol * tol;
    }
    /* Inside the chord: |w x d| <= tol |d|, squared. Coarsen all lengths alike
     * until the squares fit 64 bits (a 640 px frame loses 1/32 px at most);
     * no square root and no division, so this stays cheap and shallow. */
    t2 = (uint32_t)tol;
    while (SL_OUTSIDE(dx, 32767) || SL_OUTSIDE(dy, 32767) || SL_OUTSIDE(wx, 32767) ||
           SL_OUTSIDE(wy, 32767) || t2 > 32767u) {
        dx /= 2;
        dy /= 2;
        wx /= 2;
        wy /= 2;
        t2 /= 2u;
    }
    /* All within +-32767 now: the cross and the squares fit 32 bits. */
    c = wx * dy - wy * dx;
    return (int64_t)c * c <= (int64_t)((uint64_t)(t2 * t2) * (uint32_t)(dx * dx + dy * dy));
}

#if SL_FOR_SPEED_DEEP
/* symline_i_near_chord() of one chord for many points (a chain along an
 * earlier segment, segindex.c): what depends on the chord and the
 * tolerance alone, once. */
typedef struct symline_i_chord_prep {
    int32_t ax, ay, bx, by, tol; /* the chord and the tolerance, Q8 */
    int32_t lox, loy;            /* the box: x, y - lox, loy in 0 .. spanx, spany */
    uint32_t spanx, spany;
    int32_t dx, dy;   /* b - a */
    int64_t dd;       /* |b - a|^2 */
    uint32_t sh;      /* the halvings dx, dy and tol need to fit 16 bits */
    int32_t wlim;     /* |w| <= wlim: w needs no more than sh */
    int32_t dxs, dys; /* dx, dy halved sh times */
    int64_t lim;      /* (tol halved sh times)^2 (dxs^2 + dys^2) */
} symline_i_chord_prep;

/* v / 2^sh rounded towards 0 (v halved sh times as C's / 2 does). */
static inline int32_t symline_i_halve(int32_t v, uint32_t sh)
{
    return v < 0 ? -(int32_t)((uint32_t)-v >> sh) : (int32_t)((uint32_t)v >> sh);
}

static inline void symline_i_chord_prepare(symline_i_chord_prep *c, int32_t ax, int32_t ay,
                                           int32_t bx, int32_t by, int32_t tol)
{
    const int32_t dx = bx - ax, dy = by - ay;
    const uint32_t mx = (uint32_t)(dx < 0 ? -dx : dx), my = (uint32_t)(dy < 0 ? -dy : dy);
    uint32_t sh = 0u, t2;
    c->ax = ax;
    c->ay = ay;
    c->bx = bx;
    c->by = by;
    c->tol = tol;
    c->lox = (ax < bx ? ax : bx) - tol;
    c->loy = (ay < by ? ay : by) - tol;
    c->spanx = mx + 2u * (uint32_t)tol;
    c->spany = my + 2u * (uint32_t)tol;
    c->dx = dx;
    c->dy = dy;
    c->dd = (int64_t)dx * dx + (int64_t)dy * dy;
    /* symline_i_near_chord()'s halvings stop when every value is within
     * +-32767; |v| halved j times is |v| >> j, so the largest decides */
    while (((mx | my | (uint32_t)tol) >> sh) > 32767u) {
        sh++;
    }
    c->sh = sh;
    c->wlim = (int32_t)((32768u << sh) - 1u);
    c->dxs = symline_i_halve(dx, sh);
    c->dys = symline_i_halve(dy, sh);
    t2 = (uint32_t)tol >> sh;
    c->lim = (int64_t)((uint64_t)(t2 * t2) * (uint32_t)(c->dxs * c->dxs + c->dys * c->dys));
}

/* symline_i_near_chord() of c's chord for q (q->tol = c->tol): the same
 * answer. Where the point's offset needs more halvings than the chord (rare:
 * past the box test it is at most the chord's extent plus the tolerance),
 * that function itself. */
static inline bool symline_i_near_prepared(const symline_i_chord_prep *c, const symline_i_near *q)
{
    const int32_t px = q->x, py = q->y, wx = px - c->ax, wy = py - c->ay;
    int64_t t;
    int32_t cr;
    if ((uint32_t)(px - c->lox) > c->spanx || (uint32_t)(py - c->loy) > c->spany) {
        return false;
    }
    t = (int64_t)wx * c->dx + (int64_t)wy * c->dy;
    if (t <= 0 || t >= c->dd) {
        const int32_t ex = t <= 0 ? wx : px - c->bx, ey = t <= 0 ? wy : py - c->by;
        return (int64_t)ex * ex + (int64_t)ey * ey <= (int64_t)c->tol * c->tol;
    }
    if (SL_OUTSIDE(wx, c->wlim) || SL_OUTSIDE(wy, c->wlim)) {
        return symline_i_near_chord(c->ax, c->ay, c->bx, c->by, q);
    }
    cr = symline_i_halve(wx, c->sh) * c->dys - symline_i_halve(wy, c->sh) * c->dxs;
    return (int64_t)cr * cr <= c->lim;
}
#endif

/* True when q's point lies within q's tolerance of the polyline through
 * p[0], p[SL_POLY_STEP], p[2 SL_POLY_STEP], ... and p[last] (whole pixels):
 * symline_i_near_segment()'s test of a curve, or of a run of it. */
bool symline_i_near_run(const symline_point *p, uint32_t last, const symline_i_near *q);
/* True when q's point lies within q's tolerance of segment s (its chord for
 * lines, its points for curves). */
bool symline_i_near_segment(const symline_segment *s, const symline_point *pts,
                            const symline_i_near *q);

#endif /* SYMLINE_LIB_SEGMENTS_H */

/* SPDX-License-Identifier: Apache-2.0 */
/*
 * From chains to segments (lib/segments.c): corner cuts, the least-squares
 * fit and the line/curve decision, the bend of flat arcs, distances to
 * chords and nearness to earlier segments (one by one, and point by point
 * and chain by chain through the grid of earlier segments, lib/segindex.c).
 */
#include <setjmp.h>
#include <stdarg.h>
#include <stdbool.h>
#include <stddef.h>
#include <stdint.h>
#include <string.h>

#include <cmocka.h>

#include "pass.h"
#include "segindex.h"
#include "segments.h"

/* An L: 7 points down x = 0, then 8 to the right along y = 6. */
static uint32_t l_chain(symline_point *p)
{
    uint32_t n = 0u, i;
    memset(p, 0, 15u * sizeof *p); /* no sub-pixel offsets */
    for (i = 0; i <= 6u; i++, n++) {
        p[n].x = 0;
        p[n].y = (uint16_t)i;
    }
    for (i = 1; i <= 8u; i++, n++) {
        p[n].x = (uint16_t)i;
        p[n].y = 6;
    }
    return n;
}

static void corner_cut(void **state)
{
    symline_point p[32];
    const uint32_t n = l_chain(p);
    uint32_t at, i;
    (void)state;
    /* Cut at (or next to) the corner point p[6] = (0, 6): the vertical arm first. */
    at = symline_i_corner_cut(p, n);
    assert_true(at >= 5u && at <= 7u);
    /* The rest is straight: no further cut. */
    assert_int_equal(symline_i_corner_cut(p + at, n - at), n - at);
    /* A straight chain and a chain too short to judge are never cut. */
    for (i = 0; i < 20u; i++) {
        p[i].x = (uint16_t)i;
        p[i].y = (uint16_t)(i / 3u);
    }
    assert_int_equal(symline_i_corner_cut(p, 20), 20);
    l_chain(p);
    assert_int_equal(symline_i_corner_cut(p, 8), 8);
}

static void fit_line_and_curve(void **state)
{
    symline_point p[64];
    symline_segment s;
    uint32_t i;
    (void)state;
    memset(p, 0, sizeof(p)); /* no sub-pixel offsets */
    for (i = 0; i < 40u; i++) {
        p[i].x = (uint16_t)(10u + i);
        p[i].y = (uint16_t)(20u + i / 4u);
    }
    symline_i_fit(p, 40, 0, 512, &s);
    assert_int_equal(s.kind, SYMLINE_KIND_LINE);
    /* Least-squares ends: on the staircase's centre line y = 19.625 + (x - 10) / 4. */
    assert_true(s.x0 >= 10 * 256 - 64 && s.x0 <= 10 * 256 + 64);
    assert_true(s.x1 >= 49 * 256 - 64 && s.x1 <= 49 * 256 + 64);
    assert_true(s.y0 >= 19 * 256 + 96 && s.y0 <= 19 * 256 + 224);
    assert_true(s.y1 >= 29 * 256 + 64 && s.y1 <= 29 * 256 + 192);
    assert_true(s.max_dev < 128u);
    /* A half circle of radius 12 around (30, 30). */
    {
        static const int8_t c[][2] = {{12, 0},  {12, 2},  {11, 4},  {11, 5}, {10, 7},  {8, 9},
                                      {7, 10},  {5, 11},  {4, 11},  {2, 12}, {0, 12},  {-2, 12},
                                      {-4, 11}, {-5, 11}, {-7, 10}, {-8, 9}, {-10, 7}, {-11, 5},
                                      {-11, 4}, {-12, 2}, {-12, 0}};
        for (i = 0; i < 21u; i++) {
            p[i].x = (uint16_t)(30 + c[i][0]);
            p[i].y = (uint16_t)(30 + c[i][1]);
        }
        symline_i_fit(p, 21, 0, 512, &s);
        assert_int_equal(s.kind, SYMLINE_KIND_CURVE);
        assert_true(s.max_dev >= 11u * 256u && s.max_dev <= 13u * 256u);
    }
    /* Level 1: coordinates are block centres. */
    p[0].x = 0;
    p[0].y = 0;
    p[1].x = 4;
    p[1].y = 0;
    symline_i_fit(p, 2, 1, 512, &s);
    assert_int_equal(s.x0, 128);
    assert_int_equal(s.x1, 8 * 256 + 128);
}

static void bend_tells_flat_arc_from_line(void **state)
{
    symline_point p[64];
    symline_segment s;
    uint32_t i;
    (void)state;
    memset(p, 0, sizeof(p)); /* no sub-pixel offsets */
    /* A staircase line (slope 1/4): pixel steps average out. */
    for (i = 0; i < 60u; i++) {
        p[i].x = (uint16_t)(10u + i);
        p[i].y = (uint16_t)(20u + i / 4u);
    }
    assert_true(symline_i_bend_q8(p, 60) < 40u);
    /* A flat arc: y = 20 + round((x - 40)^2 / 400), sagitta 2 px over 60 px. */
    for (i = 0; i < 60u; i++) {
        const int32_t dx = (int32_t)i - 30;
        p[i].x = (uint16_t)(10u + i);
        p[i].y = (uint16_t)(20 + (dx * dx + 200) / 450);
    }
    symline_i_fit(p, 60, 0, 512, &s);
    assert_int_equal(s.kind, SYMLINE_KIND_LINE);  /* under the max_dev threshold ... */
    assert_true(symline_i_bend_q8(p, 60) >= 80u); /* ... but it bends */
}

/* c with the chord (x0, y0)-(x1, y1), Q8. */
static const symline_segment *chord(symline_segment *c, int32_t x0, int32_t y0, int32_t x1,
                                    int32_t y1)
{
    memset(c, 0, sizeof(*c));
    c->x0 = x0;
    c->y0 = y0;
    c->x1 = x1;
    c->y1 = y1;
    return c;
}

static void distances(void **state)
{
    symline_point p[4];
    symline_segment c;
    (void)state;
    memset(p, 0, sizeof(p)); /* no sub-pixel offsets */
    /* (3, 4) px from the line through the origin along x: 4 px (Q8). */
    assert_int_equal(symline_i_line_dist_q8(0, 0, 256, 0, 3 * 256, 4 * 256), 4u * 256u);
    /* A zero direction: the distance to the point itself (5 px). */
    assert_int_equal(symline_i_line_dist_q8(0, 0, 0, 0, 3 * 256, 4 * 256), 5u * 256u);
    /* The largest distance of points to a chord, at level 0 and at level 1 (block centres). */
    p[0].x = 0;
    p[0].y = 0;
    p[1].x = 5;
    p[1].y = 2;
    p[2].x = 10;
    p[2].y = 0;
    assert_int_equal(symline_i_max_dev(p, 3, 0, chord(&c, 0, 0, 10 * 256, 0)), 2u * 256u);
    assert_int_equal(symline_i_max_dev(p, 3, 1, chord(&c, 128, 128, 20 * 256 + 128, 128)),
                     4u * 256u);
    /* Curve test: above the threshold and above 1/32 of the chord. */
    assert_true(symline_i_is_curve(chord(&c, 0, 0, 64 * 256, 0), 3u * 256u, 512u));
    /* not above the threshold */
    assert_false(symline_i_is_curve(chord(&c, 0, 0, 64 * 256, 0), 512u, 512u));
    /* under 1/32 of 200 px */
    assert_false(symline_i_is_curve(chord(&c, 0, 0, 200 * 256, 0), 6u * 256u, 512u));
}

/* symline_i_near_segment() of s for the point (x, y) and tolerance tol (Q8). */
static bool near(const symline_segment *s, const symline_point *pts, int32_t x, int32_t y,
                 int32_t tol)
{
    symline_i_near q;
    q.x = x;
    q.y = y;
    q.tol = tol;
    return symline_i_near_segment(s, pts, &q);
}

static void near_segment(void **state)
{
    symline_point pts[16];
    symline_segment s;
    uint32_t i;
    (void)state;
    memset(pts, 0, sizeof pts);
    memset(&s, 0, sizeof s);
    /* A line from (10, 10) to (50, 10). */
    s.x0 = 10 * 256;
    s.y0 = 10 * 256;
    s.x1 = 50 * 256;
    s.y1 = 10 * 256;
    s.kind = SYMLINE_KIND_LINE;
    s.count = 2;
    assert_true(near(&s, pts, 30 * 256, 11 * 256, 512));  /* 1 px off the chord */
    assert_false(near(&s, pts, 30 * 256, 13 * 256, 512)); /* 3 px off */
    assert_true(near(&s, pts, 51 * 256, 10 * 256, 512));  /* 1 px beyond an end */
    assert_false(near(&s, pts, 53 * 256, 10 * 256, 512)); /* 3 px beyond it */
    /* A curve is followed along its points, not its chord: an L of points. */
    for (i = 0; i < 8u; i++) {
        pts[i].x = 10;
        pts[i].y = (uint16_t)(10u + 2u * i);
        pts[8u + i].x = (uint16_t)(10u + 2u * i);
        pts[8u + i].y = 24;
    }
    s.kind = SYMLINE_KIND_CURVE;
    s.first = 0;
    s.count = 16;
    s.x0 = 10 * 256;
    s.y0 = 10 * 256;
    s.x1 = 24 * 256;
    s.y1 = 24 * 256;
    assert_true(near(&s, pts, 10 * 256, 17 * 256, 256));  /* on the vertical arm */
    assert_false(near(&s, pts, 17 * 256, 17 * 256, 256)); /* on the chord only */
}

/* A small deterministic generator (tests only). */
static uint32_t rnd(uint32_t *s)
{
    *s = *s * 1664525u + 1013904223u;
    return *s >> 8;
}

/* A traced chain of n grid points from (x, y): neighbours differ by at most
 * 1, with sub-pixel offsets in -64..63. */
static void random_chain(symline_point *p, uint32_t n, uint32_t x, uint32_t y, uint32_t *s)
{
    uint32_t i;
    for (i = 0; i < n; i++) {
        p[i].x = (uint16_t)x;
        p[i].y = (uint16_t)y;
        p[i].fx = (int8_t)((int32_t)(rnd(s) % 128u) - 64);
        p[i].fy = (int8_t)((int32_t)(rnd(s) % 128u) - 64);
        x = x + rnd(s) % 3u - 1u;
        y = y + rnd(s) % 3u - 1u;
    }
}

/* symline_i_chord_dev() the plain way: every window's sum of crosses from
 * the points' Q8 positions, or every point's distance to a chord end. */
static uint32_t chord_dev_ref(const symline_point *p, uint32_t n, uint32_t level,
                              const symline_segment *c, uint32_t win)
{
    const int64_t dx = c->x1 - c->x0, dy = c->y1 - c->y0;
    uint64_t best = 0u;
    uint32_t i, j;
    if (n == 0u) {
        return 0u;
    }
    if (dx == 0 && dy == 0) {
        for (i = 0; i < n; i++) {
            const int64_t wx = symline_i_pt_q8x(&p[i], level) - c->x0;
            const int64_t wy = symline_i_pt_q8y(&p[i], level) - c->y0;
            const uint64_t d = (uint64_t)(wx * wx + wy * wy);
            best = d > best ? d : best;
        }
        return (uint32_t)symline_i_isqrt64(best);
    }
    win = win < 1u ? 1u : (win > n ? n : win);
    for (i = 0; i + win <= n; i++) {
        int64_t sum = 0;
        for (j = i; j < i + win; j++) {
            sum += (symline_i_pt_q8x(&p[j], level) - c->x0) * dy -
                   (symline_i_pt_q8y(&p[j], level) - c->y0) * dx;
        }
        best = (uint64_t)(sum < 0 ? -sum : sum) > best ? (uint64_t)(sum < 0 ? -sum : sum) : best;
    }
    return symline_i_div_q8(best, symline_i_isqrt64((uint64_t)(dx * dx + dy * dy)) * win);
}

/* The sweeps (one window, and the pair of symline_i_chord_devs()) against
 * the plain sums, for every window width up to past the ring of crosses the
 * speed builds keep, short and long chains, and chords with no direction. */
static void chord_dev_every_window(void **state)
{
    symline_point p[96];
    symline_segment c;
    uint32_t seed = 7u, t;
    (void)state;
    memset(&c, 0, sizeof c);
    for (t = 0; t < 200u; t++) {
        const uint32_t n = 1u + rnd(&seed) % 96u, level = rnd(&seed) % 4u;
        uint32_t win, dev[2];
        random_chain(p, n, 200u + rnd(&seed) % 100u, 200u + rnd(&seed) % 100u, &seed);
        c.x0 = symline_i_pt_q8x(&p[0], level) + (int32_t)(rnd(&seed) % 2048u) - 1024;
        c.y0 = symline_i_pt_q8y(&p[0], level) + (int32_t)(rnd(&seed) % 2048u) - 1024;
        c.x1 = t % 10u == 0u ? c.x0 : symline_i_pt_q8x(&p[n - 1u], level);
        c.y1 = t % 10u == 0u ? c.y0 : symline_i_pt_q8y(&p[n - 1u], level);
        for (win = 0; win <= 12u; win++) {
            assert_int_equal(symline_i_chord_dev(p, n, level, &c, win),
                             chord_dev_ref(p, n, level, &c, win));
        }
        symline_i_chord_devs(p, n, level, &c, SL_SMOOTH_WIN, dev);
        assert_int_equal(dev[0], chord_dev_ref(p, n, level, &c, 1u));
        assert_int_equal(dev[1], chord_dev_ref(p, n, level, &c, SL_SMOOTH_WIN));
    }
    /* Four points 8 px off one side, then one 24 px off the other: the
     * first four alone sum to more than any window of five (the first
     * window is counted only once it is complete), for every length from
     * one window to three (every tail of a sweep taken by whole windows). */
    for (t = SL_SMOOTH_WIN; t <= 3u * SL_SMOOTH_WIN; t++) {
        uint32_t i, dev[2];
        memset(p, 0, sizeof p);
        for (i = 0; i < t; i++) {
            p[i].x = (uint16_t)(100u + 4u * i);
            p[i].y = (uint16_t)(i < 4u ? 108u : i == 4u ? 76u : 100u);
        }
        c.x0 = symline_i_pt_q8x(&p[0], 0u);
        c.y0 = 100 << 8;
        c.x1 = symline_i_pt_q8x(&p[t - 1u], 0u);
        c.y1 = 100 << 8;
        symline_i_chord_devs(p, t, 0u, &c, SL_SMOOTH_WIN, dev);
        assert_int_equal(dev[1], chord_dev_ref(p, t, 0u, &c, SL_SMOOTH_WIN));
        assert_int_equal(symline_i_chord_dev(p, t, 0u, &c, SL_SMOOTH_WIN), dev[1]);
    }
}

/* A chord prepared once answers as the chord's own test for every point
 * (64-bit speed builds, where the grid of earlier segments prepares the
 * entry a chain runs along): chords of every length up to a 65535 px frame
 * and tolerances up to 256 px (both need halvings), points across the band's
 * edge and around the ends, and far points whose offsets need more halvings
 * than the chord. */
static void prepared_chord_is_chord(void **state)
{
#if SL_FOR_SPEED_DEEP
    uint32_t seed = 23u, t, i;
    (void)state;
    for (t = 0; t < 4000u; t++) {
        /* Q8 coordinates within 2^(11 + t % 14) (a 8 px to a 65535 px frame) */
        const uint32_t span = 1u << (11u + t % 14u);
        const int32_t ax = (int32_t)(rnd(&seed) % span), ay = (int32_t)(rnd(&seed) % span);
        const int32_t bx = t % 7u == 0u ? ax : (int32_t)(rnd(&seed) % span);
        const int32_t by = t % 7u == 0u ? ay : (int32_t)(rnd(&seed) % span);
        const int32_t tol = (int32_t)(rnd(&seed) % (t % 5u == 0u ? 65536u : 1024u));
        symline_i_chord_prep c;
        symline_i_chord_prepare(&c, ax, ay, bx, by, tol);
        for (i = 0; i < 64u; i++) {
            symline_i_near q;
            const int64_t u = (int64_t)(rnd(&seed) % 1200u) - 100; /* along, per mille */
            const int32_t n = (int32_t)(rnd(&seed) % 4u) - 2;      /* normal, tol units */
            const int32_t dx = bx - ax, dy = by - ay;
            const int32_t len = (int32_t)(dx < 0 ? -dx : dx) + (dy < 0 ? -dy : dy) + 1;
            const int32_t off = (int32_t)(rnd(&seed) % 65u) - 32; /* around the edge */
            q.tol = tol;
            if (i % 8u == 7u) { /* anywhere in the frame, far ones too */
                q.x = (int32_t)(rnd(&seed) % (1u << 24));
                q.y = (int32_t)(rnd(&seed) % (1u << 24));
            } else {
                /* along the chord at u, moved n tolerances (+ off) across */
                q.x =
                    ax + (int32_t)(dx * u / 1000) - (int32_t)((int64_t)dy * (n * tol + off) / len);
                q.y =
                    ay + (int32_t)(dy * u / 1000) + (int32_t)((int64_t)dx * (n * tol + off) / len);
            }
            assert_int_equal(symline_i_near_prepared(&c, &q),
                             symline_i_near_chord(ax, ay, bx, by, &q));
        }
    }
    /* At the edges of the halvings: chord lengths and tolerances of 2^k - 1,
     * 2^k and 2^k + 1 (Q8), points whose offsets from the first end lie at
     * the edge of the chord's halvings, across the band's edge. */
    for (t = 0; t < 6u * 3u * 3u; t++) {
        static const int32_t edge[6] = {32767, 32768, 65535, 65536, 131072, 262144};
        const int32_t big = edge[t / 9u] + (int32_t)(t % 3u) - 1, tol = edge[(t / 3u) % 3u];
        const int32_t ax = 1000, ay = 2000, bx = ax + big / 3, by = ay + big;
        symline_i_chord_prep c;
        symline_i_chord_prepare(&c, ax, ay, bx, by, tol);
        for (i = 0; i < 10u; i++) {
            /* down a column of the band, and at each change of the answer
             * every point either side */
            const int32_t wx = (int32_t)((32768u << c.sh) + (i % 5u)) - 3;
            const int32_t step = big / 512 + 1;
            symline_i_near q;
            bool last = false;
            int32_t y;
            q.tol = tol;
            q.x = ax + (i < 5u ? wx : -wx);
            for (y = ay - 2 * big; y < ay + 3 * big; y += step) {
                int32_t k;
                q.y = y;
                if (symline_i_near_chord(ax, ay, bx, by, &q) == last) {
                    continue;
                }
                last = !last;
                for (k = y - step - 2; k <= y + 2; k++) {
                    q.y = k;
                    assert_int_equal(symline_i_near_prepared(&c, &q),
                                     symline_i_near_chord(ax, ay, bx, by, &q));
                }
            }
        }
    }
#else
    (void)state;
    skip(); /* size builds and 32-bit cores test each point from the chord */
#endif
}

/* The grid of earlier segments answers as testing every segment does, for
 * points along paths (its entry found last is tried first), and a cell it
 * lists nothing in holds no point near any segment (what the pass's chain
 * search relies on to skip the test). */
/* The frame and the earlier segments of the grid tests: NSEG random chains
 * of PER full-resolution points, every third one a curve. */
enum {
    W = 320,
    H = 240,
    NSEG = 12,
    PER = 24
};

static void earlier_segments(symline_result *r, symline_segment *segs, symline_point *pts,
                             uint32_t *seed)
{
    uint32_t k;
    memset(r, 0, sizeof *r);
    memset(segs, 0, NSEG * sizeof *segs);
    r->points = pts;
    r->segments = segs;
    for (k = 0; k < NSEG; k++) {
        symline_segment *s = &segs[k];
        symline_point *q = &pts[k * PER];
        uint32_t i;
        random_chain(q, PER, 20u + rnd(seed) % (W - 40u), 20u + rnd(seed) % (H - 40u), seed);
        for (i = 0; i < PER; i++) {
            q[i].fx = 0; /* full-resolution points, as the pass keeps them */
            q[i].fy = 0;
        }
        s->first = k * PER;
        s->count = PER;
        s->kind = (uint8_t)(k % 3u == 0u ? SYMLINE_KIND_CURVE : SYMLINE_KIND_LINE);
        s->x0 = symline_i_pt_q8x(&q[0], 0u);
        s->y0 = symline_i_pt_q8y(&q[0], 0u);
        s->x1 = symline_i_pt_q8x(&q[PER - 1u], 0u);
        s->y1 = symline_i_pt_q8y(&q[PER - 1u], 0u);
    }
}

/* Whether any of the segments is near the full-resolution point (Q8). */
static bool near_any(const symline_result *r, int32_t x, int32_t y, int32_t tol)
{
    symline_i_near q;
    uint32_t k;
    q.x = x;
    q.y = y;
    q.tol = tol;
    for (k = 0; k < NSEG; k++) {
        if (symline_i_near_segment(&r->segments[k], r->points, &q)) {
            return true;
        }
    }
    return false;
}

static void grid_near_equals_every_segment(void **state)
{
    static uint32_t mem[4096];
    static symline_point pts[NSEG * PER];
    symline_segment segs[NSEG];
    symline_result r;
    symline_i_segindex ix;
    uint32_t seed = 11u, t;
    (void)state;
    assert_true(symline_i_segindex_ws_size(W, H) <= sizeof mem);
    earlier_segments(&r, segs, pts, &seed);
    for (t = 0; t < 16u; t++) {
        /* Levels 0..3, and id areas from roomy to too small for every
         * segment (the speed builds keep the count's cells at its far end
         * while they fit). */
        const int32_t tol = symline_i_cover_tol_q8(t % 4u);
        const size_t ends = 10u * 8u * 4u + 16u; /* the 10 x 8 cells, aligned */
        const size_t room[4] = {sizeof mem, ends + 4u * 90u, ends + 4u * 60u, ends + 4u * 45u};
        uint32_t x = rnd(&seed) % W, y = rnd(&seed) % H, i;
        symline_i_segindex_build(&ix, mem, room[t / 4u], NULL, 0u, W, H, &r, NSEG, tol);
        if (t < 4u) {
            assert_int_equal(ix.indexed, NSEG);
        }
        ix.hit = SL_NO_HIT;
        for (i = 0; i < 4000u; i++) {
            const int32_t qx = (int32_t)(x << 8), qy = (int32_t)(y << 8);
            const bool any = near_any(&r, qx, qy, tol);
            assert_int_equal(symline_i_segindex_near(&ix, &r, NSEG, qx, qy, tol), any);
            if (ix.indexed == NSEG &&
                symline_i_segindex_cell_empty(&ix, symline_i_cell_at(ix.cols, ix.rows, qx, qy))) {
                assert_false(any);
            }
            /* A walk of single steps, now and then a jump. */
            x = i % 200u == 199u ? rnd(&seed) % W : (x + rnd(&seed) % 3u + W - 1u) % W;
            y = i % 200u == 199u ? rnd(&seed) % H : (y + rnd(&seed) % 3u + H - 1u) % H;
        }
    }
    /* Id areas from just the ids' size up: the same grid however few of the
     * count's cells the speed builds keep for the fill at its far end. */
    for (t = 0; t < 4u; t++) {
        static uint32_t ref[4096];
        const int32_t tol = symline_i_cover_tol_q8(t);
        const size_t ends = 10u * 8u * 4u + 16u;
        symline_i_segindex big;
        uint32_t cells, sum, extra;
        symline_i_segindex_build(&big, ref, sizeof ref, NULL, 0u, W, H, &r, NSEG, tol);
        assert_int_equal(big.indexed, NSEG);
        cells = big.cols * big.rows;
        sum = big.end[cells - 1u];
        for (extra = 0; extra < sum + 8u; extra += 1u + extra / 4u) {
            symline_i_segindex_build(&ix, mem, ends + 4u * ((size_t)sum + extra), NULL, 0u, W, H,
                                     &r, NSEG, tol);
            assert_int_equal(ix.indexed, NSEG);
            assert_memory_equal(ix.end, big.end, (size_t)cells * sizeof(uint32_t));
            assert_memory_equal(ix.ids, big.ids, (size_t)sum * sizeof(uint32_t));
        }
    }
}

#if SL_FOR_SPEED
/* A chain's scan through the grid (symline_i_segindex_scan(), speed builds)
 * stops at the first of its points whose nearness to any segment is the one
 * asked for, as testing every point against every segment finds it: chains
 * at levels 0..3 that run along a segment and then wander off, scanned from
 * several points on, with the entry the last point was near kept from scan
 * to scan as a chain's pass keeps it. */
static void grid_scan_equals_every_point(void **state)
{
    static uint32_t mem[4096];
    static symline_point pts[NSEG * PER];
    symline_segment segs[NSEG];
    symline_result r;
    symline_i_segindex ix;
    uint32_t seed = 23u, level, t;
    (void)state;
    earlier_segments(&r, segs, pts, &seed);
    for (level = 0; level <= 3u; level++) {
        const int32_t tol = symline_i_cover_tol_q8(level);
        const uint32_t gw = W >> level, gh = H >> level;
        symline_i_segindex_build(&ix, mem, sizeof mem, NULL, 0u, W, H, &r, NSEG, tol);
        assert_int_equal(ix.indexed, NSEG);
        for (t = 0; t < 400u; t++) {
            symline_point c[64];
            bool cov[64];
            const uint32_t n = 1u + rnd(&seed) % 64u, k = rnd(&seed) % NSEG;
            const uint32_t along = rnd(&seed) % (PER + 1u);
            uint32_t i, from, x = 0u, y = 0u;
            memset(c, 0, sizeof c);
            for (i = 0; i < n; i++) {
                if (i < along) { /* along segment k, in grid pixels */
                    x = pts[k * PER + i % PER].x >> level;
                    y = pts[k * PER + i % PER].y >> level;
                } else { /* then a walk of single steps */
                    x = x + rnd(&seed) % 3u - 1u;
                    y = y + rnd(&seed) % 3u - 1u;
                    x = x >= gw ? (x > gw ? 0u : gw - 1u) : x;
                    y = y >= gh ? (y > gh ? 0u : gh - 1u) : y;
                }
                c[i].x = (uint16_t)x;
                c[i].y = (uint16_t)y;
                cov[i] = near_any(&r, symline_i_q8(x, level), symline_i_q8(y, level), tol);
            }
            ix.hit = SL_NO_HIT;
            for (from = 0; from < n; from += 1u + rnd(&seed) % 5u) {
                uint32_t want[2] = {from, from}, b;
                while (want[0] < n && cov[want[0]]) {
                    want[0]++;
                }
                while (want[1] < n && !cov[want[1]]) {
                    want[1]++;
                }
                for (b = 0; b < 2u; b++) {
                    const symline_point *got = symline_i_segindex_scan(&ix, &r, NSEG, c + from,
                                                                       c + n, level, tol, b != 0u);
                    assert_int_equal(got - c, want[b]);
                }
            }
        }
    }
}
#endif

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(corner_cut),
        cmocka_unit_test(fit_line_and_curve),
        cmocka_unit_test(bend_tells_flat_arc_from_line),
        cmocka_unit_test(distances),
        cmocka_unit_test(near_segment),
        cmocka_unit_test(chord_dev_every_window),
        cmocka_unit_test(prepared_chord_is_chord),
        cmocka_unit_test(grid_near_equals_every_segment),
#if SL_FOR_SPEED
        cmocka_unit_test(grid_scan_equals_every_point),
#endif
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}

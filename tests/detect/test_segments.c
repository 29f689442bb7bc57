/* SPDX-License-Identifier: Apache-2.0 */
/*
 * From chains to segments (lib/segments.c): corner cuts, the least-squares
 * fit and the line/curve decision, the bend of flat arcs, distances to
 * chords and nearness to earlier segments.
 */
#include <setjmp.h>
#include <stdarg.h>
#include <stdbool.h>
#include <stddef.h>
#include <stdint.h>
#include <string.h>

#include <cmocka.h>

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

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(corner_cut),
        cmocka_unit_test(fit_line_and_curve),
        cmocka_unit_test(bend_tells_flat_arc_from_line),
        cmocka_unit_test(distances),
        cmocka_unit_test(near_segment),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}

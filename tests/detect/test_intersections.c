/* SPDX-License-Identifier: Apache-2.0 */
/*
 * symline_intersections(): L, T and X on hand-made segment sets and on
 * hand-made frames run through symline_detect(); what must not be an
 * intersection (parallel lines, pieces of one line, far-apart segments);
 * degenerate input and argument errors; the integer heading.
 */
#include <math.h>
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <stdlib.h>
#include <string.h>

#include <cmocka.h>

#include "intersections.h"
#include "symline/detect.h"
#include "testutil.h"

#define PI 3.14159265358979323846
#define MAXSEG 64
#define MAXPTS 16384
#define MAXIX 8

typedef struct scene {
    symline_segment seg[MAXSEG];
    symline_point pts[MAXPTS];
    symline_result res;
    symline_intersection items[MAXIX];
    symline_intersection_result ix;
    symline_intersection_config cfg;
} scene;

static void scene_init(scene *s)
{
    memset(s, 0, sizeof *s);
    s->res.segments = s->seg;
    s->res.segment_cap = MAXSEG;
    s->res.points = s->pts;
    s->res.point_cap = MAXPTS;
    s->ix.items = s->items;
    s->ix.cap = MAXIX;
    symline_intersection_config_default(&s->cfg);
}

/* A straight segment, pixels. */
static void add_line(scene *s, double x0, double y0, double x1, double y1)
{
    symline_segment *g = &s->seg[s->res.segment_count++];
    g->x0 = (int32_t)lround(x0 * 256.0);
    g->y0 = (int32_t)lround(y0 * 256.0);
    g->x1 = (int32_t)lround(x1 * 256.0);
    g->y1 = (int32_t)lround(y1 * 256.0);
    g->kind = SYMLINE_KIND_LINE;
}

/* A curve: an arc of the circle (cx, cy, r) from angle a0 to a1 (degrees,
 * image convention), points about 1 px apart, rounded to pixels. */
static void add_arc(scene *s, double cx, double cy, double r, double a0, double a1)
{
    symline_segment *g = &s->seg[s->res.segment_count++];
    const double step = 1.0 / r * 180.0 / PI;
    const int n = (int)((a1 - a0) / step) + 1;
    int k;
    g->kind = SYMLINE_KIND_CURVE;
    g->first = s->res.point_count;
    for (k = 0; k < n; k++) {
        const double a = (a0 + (a1 - a0) * k / (n - 1)) * PI / 180.0;
        symline_point *p = &s->pts[s->res.point_count++];
        p->x = (uint16_t)lround(cx + r * cos(a));
        p->y = (uint16_t)lround(cy + r * sin(a));
    }
    g->count = (uint32_t)n;
    g->x0 = s->pts[g->first].x * 256;
    g->y0 = s->pts[g->first].y * 256;
    g->x1 = s->pts[g->first + g->count - 1u].x * 256;
    g->y1 = s->pts[g->first + g->count - 1u].y * 256;
    g->max_dev = 2048u;
}

static uint32_t run(scene *s)
{
    assert_int_equal(symline_intersections(&s->res, &s->cfg, &s->ix), SYMLINE_OK);
    return s->ix.count;
}

/* Angle between two directions in degrees, [0, 180]. */
static double turn(double a, double b)
{
    double d = fabs(a - b);
    return d > 180.0 ? 360.0 - d : d;
}

/* Intersection i is of the given type at (x, y) within tol px, with the given
 * rays (degrees, ascending) within rtol degrees. */
static void expect_ix(const scene *s, uint32_t i, int type, double x, double y, double tol,
                      const double *rays, uint32_t nrays, double rtol)
{
    const symline_intersection *it = &s->ix.items[i];
    uint32_t k;
    assert_true(i < s->ix.count);
    print_message("intersection %u: type %d at %.2f %.2f, rays", i, it->type, it->x / 256.0,
                  it->y / 256.0);
    for (k = 0; k < it->ray_count; k++) {
        print_message(" %.2f", it->rays[k] / 256.0);
    }
    print_message("\n");
    assert_int_equal(it->type, type);
    assert_true(fabs(it->x / 256.0 - x) <= tol);
    assert_true(fabs(it->y / 256.0 - y) <= tol);
    assert_int_equal(it->ray_count, nrays);
    for (k = 0; k < nrays; k++) {
        assert_true(it->rays[k] < SYMLINE_DEG_Q8_FULL);
        assert_true(k == 0u || it->rays[k - 1u] < it->rays[k]);
        assert_true(turn(it->rays[k] / 256.0, rays[k]) <= rtol);
    }
    for (k = 1; k < it->segment_count; k++) {
        assert_true(it->segments[k - 1u] < it->segments[k]);
    }
}

/* ---- hand-made segment sets ---- */

static void test_l(void **state)
{
    static const double rays[2] = {0.0, 90.0};
    scene s;
    (void)state;
    scene_init(&s);
    /* both stop a few px short of the corner at (100, 100), as the tracer leaves them */
    add_line(&s, 104.0, 100.0, 220.0, 100.0);
    add_line(&s, 100.0, 230.0, 100.0, 105.0);
    assert_int_equal(run(&s), 1);
    expect_ix(&s, 0, SYMLINE_INTERSECTION_L, 100.0, 100.0, 0.5, rays, 2, 0.05);
    assert_int_equal(s.ix.items[0].segment_count, 2);
    assert_int_equal(s.ix.items[0].segments[0], 0);
    assert_int_equal(s.ix.items[0].segments[1], 1);
    assert_int_equal(s.ix.truncated, 0);
}

static void test_t(void **state)
{
    static const double rays[3] = {0.0, 90.0, 180.0};
    scene s;
    (void)state;
    scene_init(&s);
    add_line(&s, 40.0, 100.0, 260.0, 100.0);
    add_line(&s, 150.0, 106.0, 150.0, 220.0);
    assert_int_equal(run(&s), 1);
    expect_ix(&s, 0, SYMLINE_INTERSECTION_T, 150.0, 100.0, 0.5, rays, 3, 0.05);
}

static void test_t_split_bar(void **state)
{
    /* the tracer cut the bar at the junction: still one T */
    static const double rays[3] = {0.0, 90.0, 180.0};
    scene s;
    (void)state;
    scene_init(&s);
    add_line(&s, 40.0, 100.0, 145.0, 100.0);
    add_line(&s, 150.0, 106.0, 150.0, 220.0);
    add_line(&s, 156.0, 100.0, 260.0, 100.0);
    assert_int_equal(run(&s), 1);
    expect_ix(&s, 0, SYMLINE_INTERSECTION_T, 150.0, 100.0, 0.5, rays, 3, 0.05);
    assert_int_equal(s.ix.items[0].segment_count, 3);
}

static void test_x(void **state)
{
    static const double rays[4] = {45.0, 135.0, 225.0, 315.0};
    scene s;
    (void)state;
    scene_init(&s);
    add_line(&s, 20.0, 20.0, 180.0, 180.0);
    add_line(&s, 20.0, 180.0, 180.0, 20.0);
    assert_int_equal(run(&s), 1);
    expect_ix(&s, 0, SYMLINE_INTERSECTION_X, 100.0, 100.0, 0.5, rays, 4, 0.05);
}

static void test_x_of_pieces(void **state)
{
    /* a line cut in two where another crosses it: one X */
    static const double rays[4] = {0.0, 90.0, 180.0, 270.0};
    scene s;
    (void)state;
    scene_init(&s);
    add_line(&s, 40.0, 100.0, 260.0, 100.0);
    add_line(&s, 150.0, 20.0, 150.0, 94.0);
    add_line(&s, 150.0, 106.0, 150.0, 200.0);
    assert_int_equal(run(&s), 1);
    expect_ix(&s, 0, SYMLINE_INTERSECTION_X, 150.0, 100.0, 0.5, rays, 4, 0.05);
}

static void test_oblique_t(void **state)
{
    /* a stem meeting a bar at 40 degrees stops further short (gap / sin) */
    const double a = 40.0 * PI / 180.0;
    const double rays[3] = {0.0, 180.0, 220.0};
    scene s;
    (void)state;
    scene_init(&s);
    add_line(&s, 20.0, 150.0, 300.0, 150.0);
    add_line(&s, 150.0 - 13.0 * cos(a), 150.0 - 13.0 * sin(a), 150.0 - 120.0 * cos(a),
             150.0 - 120.0 * sin(a));
    assert_int_equal(run(&s), 1);
    /* ends off the quarter-pixel grid the stage works in: 0.1 degree */
    expect_ix(&s, 0, SYMLINE_INTERSECTION_T, 150.0, 150.0, 0.5, rays, 3, 0.1);
}

static void test_circle_and_line(void **state)
{
    /* the halfway line through the centre circle: two crossings */
    static const double rays[4] = {0.0, 90.0, 180.0, 270.0};
    scene s;
    (void)state;
    scene_init(&s);
    add_arc(&s, 160.0, 120.0, 60.0, 45.0, 404.0);
    add_line(&s, 20.0, 120.0, 300.0, 120.0);
    assert_int_equal(run(&s), 2);
    if (s.ix.items[0].x > s.ix.items[1].x) {
        const symline_intersection t = s.ix.items[0];
        s.ix.items[0] = s.ix.items[1];
        s.ix.items[1] = t;
    }
    expect_ix(&s, 0, SYMLINE_INTERSECTION_X, 100.0, 120.0, 1.0, rays, 4, 2.0);
    expect_ix(&s, 1, SYMLINE_INTERSECTION_X, 220.0, 120.0, 1.0, rays, 4, 2.0);
}

static void test_none_parallel(void **state)
{
    scene s;
    (void)state;
    scene_init(&s);
    add_line(&s, 20.0, 100.0, 220.0, 100.0);
    add_line(&s, 20.0, 108.0, 220.0, 108.0);
    add_line(&s, 20.0, 130.0, 220.0, 125.0); /* 1.4 degrees off */
    assert_int_equal(run(&s), 0);
    assert_int_equal(s.ix.truncated, 0);
}

static void test_none_collinear(void **state)
{
    /* pieces of one line, end to end or bent a little (10 degrees) */
    scene s;
    (void)state;
    scene_init(&s);
    add_line(&s, 20.0, 100.0, 120.0, 100.0);
    add_line(&s, 126.0, 100.0, 220.0, 100.0);
    add_line(&s, 220.0, 100.0, 318.5, 117.4);
    assert_int_equal(run(&s), 0);
}

static void test_none_far(void **state)
{
    scene s;
    (void)state;
    scene_init(&s);
    add_line(&s, 20.0, 20.0, 120.0, 20.0);
    add_line(&s, 300.0, 200.0, 300.0, 300.0);
    /* a stem ending 40 px before a bar: not a T */
    add_line(&s, 20.0, 400.0, 220.0, 400.0);
    add_line(&s, 120.0, 440.0, 120.0, 560.0);
    assert_int_equal(run(&s), 0);
}

static void test_large_frame(void **state)
{
    /* coordinates up to 65535 px: the stage works in 4 px units there */
    static const double rays[3] = {0.0, 90.0, 180.0};
    scene s;
    (void)state;
    scene_init(&s);
    add_line(&s, 65006.0, 60000.0, 65535.0, 60000.0);
    add_line(&s, 64800.0, 60000.0, 64994.0, 60000.0);
    add_line(&s, 65000.0, 60008.0, 65000.0, 60300.0);
    assert_int_equal(run(&s), 1);
    expect_ix(&s, 0, SYMLINE_INTERSECTION_T, 65000.0, 60000.0, 4.0, rays, 3, 1.0);
    /* the largest coordinates are accepted, one beyond is not */
    scene_init(&s);
    add_line(&s, 0.0, 65535.0, 65535.0, 0.0);
    s.seg[0].x0 = -65535 * 256;
    assert_int_equal(run(&s), 0);
    s.seg[0].x0 = -65535 * 256 - 1;
    assert_int_equal(symline_intersections(&s.res, &s.cfg, &s.ix), SYMLINE_ERR_RANGE);
}

/* Random segments and curves anywhere up to +-65535 px, random settings: always
 * SYMLINE_OK, consistent intersections, nothing beyond the capacity (run under
 * the asan preset, also no undefined behaviour). */
static void test_random_segments(void **state)
{
    static scene s;
    uint32_t seed = 4242u, iter, i, k;
    (void)state;
    for (iter = 0; iter < 3000u; iter++) {
        const uint32_t n = tu_rand(&seed) % 40u;
        const uint32_t span = tu_rand(&seed) % 4u == 0u ? 65535u : 700u;
        scene_init(&s);
        s.ix.cap = tu_rand(&seed) % (MAXIX + 1u);
        for (i = 0; i < n; i++) {
            symline_segment *g = &s.seg[s.res.segment_count++];
            g->x0 = (int32_t)(tu_rand(&seed) % (span * 256u)) - (int32_t)(tu_rand(&seed) % 512u);
            g->y0 = (int32_t)(tu_rand(&seed) % (span * 256u)) - (int32_t)(tu_rand(&seed) % 512u);
            g->x1 = (int32_t)(tu_rand(&seed) % (span * 256u));
            g->y1 = (int32_t)(tu_rand(&seed) % (span * 256u));
            g->level = (uint8_t)(tu_rand(&seed) % 7u);
            if (tu_rand(&seed) % 3u == 0u && s.res.point_count + 200u < MAXPTS) {
                int32_t x = (int32_t)(tu_rand(&seed) % span), y = (int32_t)(tu_rand(&seed) % span);
                g->kind = SYMLINE_KIND_CURVE;
                g->first = s.res.point_count;
                g->count = 2u + tu_rand(&seed) % 198u;
                for (k = 0; k < g->count; k++) {
                    symline_point *p = &s.pts[s.res.point_count++];
                    x += (int32_t)(tu_rand(&seed) % 5u) - 2;
                    y += (int32_t)(tu_rand(&seed) % 5u) - 2;
                    x = x < 0 ? 0 : x > 65535 ? 65535 : x;
                    y = y < 0 ? 0 : y > 65535 ? 65535 : y;
                    p->x = (uint16_t)x;
                    p->y = (uint16_t)y;
                    p->fx = (int8_t)((int32_t)(tu_rand(&seed) % 128u) - 64);
                    p->fy = (int8_t)((int32_t)(tu_rand(&seed) % 128u) - 64);
                }
            }
        }
        if (tu_rand(&seed) % 4u == 0u) {
            /* a quarter of these at 0, where rays of one direction meet */
            s.cfg.min_angle_q8 =
                tu_rand(&seed) % 4u == 0u ? 0u : tu_rand(&seed) % (90u * 256u + 1u);
            s.cfg.gap_q8 = tu_rand(&seed) % 65537u;
            s.cfg.gap_pct = tu_rand(&seed) % 101u;
            s.cfg.arm_q8 = 256u + tu_rand(&seed) % 65281u;
            s.cfg.merge_q8 = tu_rand(&seed) % 65537u;
            s.cfg.min_length_q8 = tu_rand(&seed) % 70000u;
        }
        assert_int_equal(symline_intersections(&s.res, &s.cfg, &s.ix), SYMLINE_OK);
        assert_true(s.ix.count <= s.ix.cap);
        for (i = 0; i < s.ix.count; i++) {
            const symline_intersection *it = &s.items[i];
            assert_true(it->ray_count >= 2u && it->ray_count <= SYMLINE_INTERSECTION_RAYS);
            assert_int_equal(it->type, it->ray_count - 2u);
            assert_true(it->segment_count >= 2u);
            for (k = 0; k < it->ray_count; k++) {
                assert_true(it->rays[k] < SYMLINE_DEG_Q8_FULL);
                assert_true(k == 0u || it->rays[k - 1u] < it->rays[k]);
            }
            for (k = 0; k < it->segment_count; k++) {
                assert_true(it->segments[k] < n);
            }
        }
    }
}

static void test_degenerate(void **state)
{
    scene s;
    symline_intersection_result none = {NULL, 0, 7, 7};
    (void)state;
    scene_init(&s);
    /* no segments */
    assert_int_equal(run(&s), 0);
    s.res.segments = NULL;
    s.res.segment_cap = 0;
    assert_int_equal(run(&s), 0);
    s.res.segments = s.seg;
    s.res.segment_cap = MAXSEG;
    /* one segment, a zero-length one, a 1-point curve */
    add_line(&s, 10.0, 10.0, 200.0, 10.0);
    assert_int_equal(run(&s), 0);
    add_line(&s, 50.0, 50.0, 50.0, 50.0);
    assert_int_equal(run(&s), 0);
    s.seg[2].kind = SYMLINE_KIND_CURVE;
    s.seg[2].first = 0;
    s.seg[2].count = 1;
    s.res.segment_count = 3;
    assert_int_equal(run(&s), 0);
    /* an L with no room for it: counted as truncated, nothing written */
    scene_init(&s);
    add_line(&s, 104.0, 100.0, 220.0, 100.0);
    add_line(&s, 100.0, 230.0, 100.0, 105.0);
    assert_int_equal(symline_intersections(&s.res, &s.cfg, &none), SYMLINE_OK);
    assert_int_equal(none.count, 0);
    assert_int_equal(none.truncated, 1);
}

static void test_truncated(void **state)
{
    /* a grid of 3 x 3 crossings into room for 4: no write beyond the array */
    scene s;
    symline_intersection *buf;
    symline_intersection_result out;
    uint32_t k;
    (void)state;
    scene_init(&s);
    for (k = 0; k < 3u; k++) {
        add_line(&s, 10.0, 50.0 + 50.0 * k, 210.0, 50.0 + 50.0 * k);
        add_line(&s, 50.0 + 50.0 * k, 10.0, 50.0 + 50.0 * k, 210.0);
    }
    buf = (symline_intersection *)tu_guard_alloc(4u * sizeof *buf);
    out.items = buf;
    out.cap = 4u;
    assert_int_equal(symline_intersections(&s.res, &s.cfg, &out), SYMLINE_OK);
    assert_int_equal(out.count, 4);
    assert_int_equal(out.truncated, 1);
    assert_true(tu_guard_ok((const uint8_t *)buf, 4u * sizeof *buf));
    tu_guard_free((uint8_t *)buf);
    /* room for 8 of the 9 X */
    s.ix.cap = MAXIX + 0u;
    assert_int_equal(run(&s), MAXIX);
    assert_int_equal(s.ix.truncated, 1);
}

static void test_errors(void **state)
{
    scene s;
    symline_intersection_config bad;
    (void)state;
    scene_init(&s);
    add_line(&s, 104.0, 100.0, 220.0, 100.0);
    add_line(&s, 100.0, 230.0, 100.0, 105.0);
    s.ix.count = 77u;
    assert_int_equal(symline_intersections(NULL, &s.cfg, &s.ix), SYMLINE_ERR_NULL);
    assert_int_equal(symline_intersections(&s.res, NULL, &s.ix), SYMLINE_ERR_NULL);
    assert_int_equal(symline_intersections(&s.res, &s.cfg, NULL), SYMLINE_ERR_NULL);
    s.ix.items = NULL;
    assert_int_equal(symline_intersections(&s.res, &s.cfg, &s.ix), SYMLINE_ERR_NULL);
    s.ix.items = s.items;
    s.res.segments = NULL;
    assert_int_equal(symline_intersections(&s.res, &s.cfg, &s.ix), SYMLINE_ERR_NULL);
    s.res.segments = s.seg;
    bad = s.cfg;
    bad.min_angle_q8 = 90u * 256u + 1u;
    assert_int_equal(symline_intersections(&s.res, &bad, &s.ix), SYMLINE_ERR_CONFIG);
    bad = s.cfg;
    bad.arm_q8 = 0u;
    assert_int_equal(symline_intersections(&s.res, &bad, &s.ix), SYMLINE_ERR_CONFIG);
    bad = s.cfg;
    bad.gap_pct = 101u;
    assert_int_equal(symline_intersections(&s.res, &bad, &s.ix), SYMLINE_ERR_CONFIG);
    /* bad segments: kind, coordinate, points outside the result, counts above caps */
    s.seg[1].kind = 9u;
    assert_int_equal(symline_intersections(&s.res, &s.cfg, &s.ix), SYMLINE_ERR_RANGE);
    s.seg[1].kind = SYMLINE_KIND_LINE;
    s.seg[1].x1 = INT32_MIN;
    assert_int_equal(symline_intersections(&s.res, &s.cfg, &s.ix), SYMLINE_ERR_RANGE);
    s.seg[1].x1 = 100 * 256;
    s.seg[1].kind = SYMLINE_KIND_CURVE;
    s.seg[1].first = 0xFFFFFFF0u;
    s.seg[1].count = 0x20u;
    s.res.point_count = 16u;
    assert_int_equal(symline_intersections(&s.res, &s.cfg, &s.ix), SYMLINE_ERR_RANGE);
    s.res.points = NULL;
    assert_int_equal(symline_intersections(&s.res, &s.cfg, &s.ix), SYMLINE_ERR_NULL);
    s.res.points = s.pts;
    s.seg[1].kind = SYMLINE_KIND_LINE;
    s.res.segment_count = MAXSEG + 1u;
    assert_int_equal(symline_intersections(&s.res, &s.cfg, &s.ix), SYMLINE_ERR_RANGE);
    /* nothing written on an error */
    assert_int_equal(s.ix.count, 77u);
    s.res.segment_count = 2u;
    symline_intersection_config_default(NULL);
    assert_int_equal(run(&s), 1);
}

static void test_heading(void **state)
{
    int32_t dx, dy;
    double worst = 0.0;
    (void)state;
    assert_int_equal(symline_i_heading_q8(0, 0), 0);
    assert_int_equal(symline_i_heading_q8(5, 0), 0);
    assert_int_equal(symline_i_heading_q8(0, 5), 90 * 256);
    assert_int_equal(symline_i_heading_q8(-5, 0), 180 * 256);
    assert_int_equal(symline_i_heading_q8(0, -5), 270 * 256);
    assert_int_equal(symline_i_heading_q8(7, 7), 45 * 256);
    assert_int_equal(symline_i_heading_q8(-7, -7), 225 * 256);
    assert_int_equal(symline_i_heading_q8(INT32_MAX, -INT32_MAX), 315 * 256);
    assert_int_equal(symline_i_heading_q8(INT32_MIN, 0), 180 * 256);
    for (dy = -300; dy <= 300; dy += 7) {
        for (dx = -300; dx <= 300; dx += 5) {
            double want, got;
            if (dx == 0 && dy == 0) {
                continue;
            }
            want = atan2((double)dy, (double)dx) * 180.0 / PI;
            want = want < 0.0 ? want + 360.0 : want;
            got = symline_i_heading_q8(dx, dy) / 256.0;
            assert_true(got >= 0.0 && got < 360.0);
            worst = fmax(worst, turn(got, want));
        }
    }
    assert_true(worst <= 0.01);
}

/* ---- hand-made frames through the detector ---- */

#define FW 320
#define FH 240

/* Carpet noise with painted lines (width 5) along the given segments. */
static uint8_t *paint(const double (*lines)[4], int n)
{
    uint8_t *px = (uint8_t *)malloc((size_t)FW * FH);
    uint32_t s = 777u;
    int x, y, k;
    for (y = 0; y < FH; y++) {
        for (x = 0; x < FW; x++) {
            int v = 70 + (int)(tu_rand(&s) % 16u);
            for (k = 0; k < n; k++) {
                const double ax = lines[k][0], ay = lines[k][1];
                const double bx = lines[k][2] - ax, by = lines[k][3] - ay;
                double t = ((x - ax) * bx + (y - ay) * by) / (bx * bx + by * by);
                t = t < 0.0 ? 0.0 : t > 1.0 ? 1.0 : t;
                if (hypot(x - ax - t * bx, y - ay - t * by) <= 2.5) {
                    v = 200 + (int)(tu_rand(&s) % 16u);
                }
            }
            px[y * FW + x] = (uint8_t)v;
        }
    }
    return px;
}

/* Detects the frame and expects exactly one intersection of this type at
 * (x, y) within 2 px, its rays within 3 degrees. */
static void detect_one(const double (*lines)[4], int n, int type, double x, double y,
                       const double *rays, uint32_t nrays)
{
    uint8_t *px = paint(lines, n);
    symline_image img = {FW, FH, FW, px};
    symline_config cfg;
    scene *s = (scene *)calloc(1, sizeof *s);
    size_t need;
    void *ws;
    scene_init(s);
    symline_config_default(&cfg);
    need = symline_detect_workspace_size(FW, FH, &cfg);
    ws = malloc(need);
    assert_int_equal(symline_detect(&img, &cfg, ws, need, &s->res), SYMLINE_OK);
    assert_int_equal(s->res.truncated, 0);
    assert_int_equal(run(s), 1);
    expect_ix(s, 0, type, x, y, 2.0, rays, nrays, 3.0);
    free(ws);
    free(s);
    free(px);
}

static void test_frame_l(void **state)
{
    static const double lines[2][4] = {{80, 60, 280, 60}, {80, 60, 80, 210}};
    static const double rays[2] = {0.0, 90.0};
    (void)state;
    detect_one(lines, 2, SYMLINE_INTERSECTION_L, 80.0, 60.0, rays, 2);
}

static void test_frame_t(void **state)
{
    static const double lines[2][4] = {{30, 60, 290, 60}, {160, 60, 160, 210}};
    static const double rays[3] = {0.0, 90.0, 180.0};
    (void)state;
    detect_one(lines, 2, SYMLINE_INTERSECTION_T, 160.0, 60.0, rays, 3);
}

static void test_frame_x(void **state)
{
    /* a slanted crossing: rays off the axes */
    static const double lines[2][4] = {{40, 40, 280, 200}, {40, 200, 280, 40}};
    const double a = atan2(160.0, 240.0) * 180.0 / PI;
    const double rays[4] = {a, 180.0 - a, 180.0 + a, 360.0 - a};
    (void)state;
    detect_one(lines, 2, SYMLINE_INTERSECTION_X, 160.0, 120.0, rays, 4);
}

static void test_frame_none(void **state)
{
    /* two parallel lines and a line-free frame: no intersection */
    static const double lines[2][4] = {{30, 60, 290, 70}, {30, 140, 290, 150}};
    uint8_t *px = paint(lines, 2);
    symline_image img = {FW, FH, FW, px};
    symline_config cfg;
    scene *s = (scene *)calloc(1, sizeof *s);
    size_t need;
    void *ws;
    int pass;
    symline_config_default(&cfg);
    need = symline_detect_workspace_size(FW, FH, &cfg);
    ws = malloc(need);
    (void)state;
    for (pass = 0; pass < 2; pass++) {
        scene_init(s);
        assert_int_equal(symline_detect(&img, &cfg, ws, need, &s->res), SYMLINE_OK);
        assert_true(pass == 1 || s->res.segment_count >= 2u);
        assert_int_equal(run(s), 0);
        free(px);
        px = paint(lines, 0);
        img.data = px;
    }
    free(ws);
    free(s);
    free(px);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_l),
        cmocka_unit_test(test_t),
        cmocka_unit_test(test_t_split_bar),
        cmocka_unit_test(test_x),
        cmocka_unit_test(test_x_of_pieces),
        cmocka_unit_test(test_oblique_t),
        cmocka_unit_test(test_circle_and_line),
        cmocka_unit_test(test_none_parallel),
        cmocka_unit_test(test_none_collinear),
        cmocka_unit_test(test_none_far),
        cmocka_unit_test(test_large_frame),
        cmocka_unit_test(test_random_segments),
        cmocka_unit_test(test_degenerate),
        cmocka_unit_test(test_truncated),
        cmocka_unit_test(test_errors),
        cmocka_unit_test(test_heading),
        cmocka_unit_test(test_frame_l),
        cmocka_unit_test(test_frame_t),
        cmocka_unit_test(test_frame_x),
        cmocka_unit_test(test_frame_none),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}

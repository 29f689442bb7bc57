/* SPDX-License-Identifier: Apache-2.0 */
/*
 * symline_detect() (lib/detect.c): arguments and errors, workspace figures,
 * truncation without overflow, lines found and reported once. The strip
 * processing is tested in test_linepoints.c.
 */
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include <cmocka.h>

#include "symline/detect.h"
#include "synth_frame.h"
#include "testutil.h"

/* ---- API ---- */

typedef struct fixture {
    symline_image img;
    uint8_t *px;
    symline_config cfg;
    void *ws;
    size_t wsn;
    symline_segment segs[256];
    symline_point pts[200000];
    symline_result res;
} fixture;

static fixture F;

static void setup_fixture(void)
{
    F.px = synth_frame(160, 120, 160);
    F.img.width = 160;
    F.img.height = 120;
    F.img.stride = 160;
    F.img.data = F.px;
    symline_config_default(&F.cfg);
    F.wsn = symline_detect_workspace_size(160, 120, &F.cfg);
    F.ws = malloc(F.wsn);
    F.res.segments = F.segs;
    F.res.segment_cap = 256;
    F.res.points = F.pts;
    F.res.point_cap = 200000;
    F.res.segment_count = 77;
    F.res.point_count = 77;
    F.res.truncated = true; /* marks: none of these may change on an error */
}

static void teardown_fixture(void)
{
    free(F.px);
    free(F.ws);
}

static void unchanged(void)
{
    assert_int_equal(F.res.segment_count, 77);
    assert_int_equal(F.res.point_count, 77);
    assert_true(F.res.truncated);
}

static void errors(void **state)
{
    symline_image bad;
    symline_config c;
    symline_result r;
    (void)state;
    setup_fixture();
    assert_int_equal(symline_detect(NULL, &F.cfg, F.ws, F.wsn, &F.res), SYMLINE_ERR_NULL);
    assert_int_equal(symline_detect(&F.img, NULL, F.ws, F.wsn, &F.res), SYMLINE_ERR_NULL);
    assert_int_equal(symline_detect(&F.img, &F.cfg, NULL, F.wsn, &F.res), SYMLINE_ERR_NULL);
    assert_int_equal(symline_detect(&F.img, &F.cfg, F.ws, F.wsn, NULL), SYMLINE_ERR_NULL);
    r = F.res;
    r.points = NULL;
    assert_int_equal(symline_detect(&F.img, &F.cfg, F.ws, F.wsn, &r), SYMLINE_ERR_NULL);
    bad = F.img;
    bad.stride = 10;
    assert_int_equal(symline_detect(&bad, &F.cfg, F.ws, F.wsn, &F.res), SYMLINE_ERR_STRIDE);
    bad = F.img;
    bad.width = 0;
    assert_int_equal(symline_detect(&bad, &F.cfg, F.ws, F.wsn, &F.res), SYMLINE_ERR_SIZE);
    assert_int_equal(symline_detect(&F.img, &F.cfg, F.ws, F.wsn - 1u, &F.res), SYMLINE_ERR_BUFFER);
    c = F.cfg;
    c.radius = 0;
    assert_int_equal(symline_detect(&F.img, &c, F.ws, F.wsn, &F.res), SYMLINE_ERR_CONFIG);
    c = F.cfg;
    c.radius = 33;
    assert_int_equal(symline_detect(&F.img, &c, F.ws, F.wsn, &F.res), SYMLINE_ERR_CONFIG);
    c = F.cfg;
    c.axes = (symline_axes)3;
    assert_int_equal(symline_detect(&F.img, &c, F.ws, F.wsn, &F.res), SYMLINE_ERR_CONFIG);
    c = F.cfg;
    c.filter = (symline_filter)2;
    assert_int_equal(symline_detect(&F.img, &c, F.ws, F.wsn, &F.res), SYMLINE_ERR_CONFIG);
    c = F.cfg;
    c.levels = 6;
    assert_int_equal(symline_detect(&F.img, &c, F.ws, F.wsn, &F.res), SYMLINE_ERR_CONFIG);
    c = F.cfg;
    c.illumination = 256;
    assert_int_equal(symline_detect(&F.img, &c, F.ws, F.wsn, &F.res), SYMLINE_ERR_CONFIG);
    c = F.cfg;
    c.contrast_pct = 101;
    assert_int_equal(symline_detect(&F.img, &c, F.ws, F.wsn, &F.res), SYMLINE_ERR_CONFIG);
    unchanged();
    assert_int_equal(symline_detect_workspace_size(0, 10, &F.cfg), 0);
    assert_int_equal(symline_detect_workspace_size(10, 70000, &F.cfg), 0);
    assert_int_equal(symline_detect_workspace_size(10, 10, NULL), 0);
    assert_int_equal(symline_detect_workspace_size(10, 10, &c), 0);
    symline_config_default(NULL); /* no crash */
    teardown_fixture();
}

static void finds_lines(void **state)
{
    uint32_t i, horiz = 0u, vert = 0u, curves = 0u;
    (void)state;
    setup_fixture();
    assert_int_equal(symline_detect(&F.img, &F.cfg, F.ws, F.wsn, &F.res), SYMLINE_OK);
    assert_int_equal(F.res.truncated, 0);
    for (i = 0; i < F.res.segment_count; i++) {
        const symline_segment *s = &F.segs[i];
        assert_true(s->first + s->count <= F.res.point_count);
        if (s->kind == SYMLINE_KIND_CURVE) {
            curves++;
        } else if (s->y0 >= 20 * 256 && s->y0 <= 21 * 256 && s->y1 >= 20 * 256 &&
                   s->y1 <= 21 * 256 && s->count > 100u) {
            horiz++;
        } else if (s->x0 >= 80 * 256 && s->x0 <= 81 * 256 && s->x1 >= 80 * 256 &&
                   s->x1 <= 81 * 256) {
            vert++;
        }
    }
    assert_true(horiz >= 1u);  /* the thin horizontal line */
    assert_true(vert >= 1u);   /* the vertical line, found once (not also by the other axis) */
    assert_true(curves >= 1u); /* the ring */
    teardown_fixture();
}

static void truncation_never_overflows(void **state)
{
    uint32_t cap;
    (void)state;
    setup_fixture();
    for (cap = 0; cap < 400u; cap += 37u) {
        symline_result r;
        uint8_t *pg = tu_guard_alloc((size_t)cap * sizeof(symline_point) + 1u);
        uint8_t *sg = tu_guard_alloc(3u * sizeof(symline_segment));
        r.segments = (symline_segment *)(void *)sg;
        r.segment_cap = 3;
        r.points = (symline_point *)(void *)pg;
        r.point_cap = cap;
        assert_int_equal(symline_detect(&F.img, &F.cfg, F.ws, F.wsn, &r), SYMLINE_OK);
        assert_int_equal(r.truncated, 1);
        assert_true(r.segment_count <= 3u);
        assert_true(r.point_count <= cap);
        assert_true(tu_guard_ok(pg, (size_t)cap * sizeof(symline_point) + 1u));
        assert_true(tu_guard_ok(sg, 3u * sizeof(symline_segment)));
        tu_guard_free(pg);
        tu_guard_free(sg);
    }
    teardown_fixture();
}

static void stride_and_workspace_do_not_matter(void **state)
{
    symline_image img2;
    uint8_t *px2 = synth_frame(160, 120, 173);
    symline_segment segs2[256];
    symline_result r2;
    uint8_t *big;
    (void)state;
    setup_fixture();
    assert_int_equal(symline_detect(&F.img, &F.cfg, F.ws, F.wsn, &F.res), SYMLINE_OK);
    img2.width = 160;
    img2.height = 120;
    img2.stride = 173;
    img2.data = px2;
    /* make_frame's noise depends on the stride: copy the first frame's pixels */
    {
        uint32_t y;
        for (y = 0; y < 120u; y++) {
            memcpy(px2 + y * 173u, F.px + y * 160u, 160u);
        }
    }
    big = (uint8_t *)malloc(F.wsn + 100u);
    memset(big, 0xFF, F.wsn + 100u);
    r2 = F.res;
    r2.segments = segs2;
    r2.points = (symline_point *)malloc(200000u * sizeof(symline_point));
    assert_int_equal(symline_detect(&img2, &F.cfg, big + 3, F.wsn, &r2), SYMLINE_OK);
    assert_int_equal(r2.segment_count, F.res.segment_count);
    assert_memory_equal(segs2, F.segs, F.res.segment_count * sizeof(symline_segment));
    assert_memory_equal(r2.points, F.pts, F.res.point_count * sizeof(symline_point));
    free(r2.points);
    free(big);
    free(px2);
    teardown_fixture();
}

static void workspace_figures(void **state)
{
    symline_config c;
    size_t a, b;
    (void)state;
    symline_config_default(&c);
    c.axes = SYMLINE_AXES_HORIZONTAL;
    a = symline_detect_workspace_size(320, 240, &c);
    assert_true(a > 0u && a <= 32u * 1024u);
    /* Height adds only the row index (4 bytes per row), never a frame-sized map. */
    b = symline_detect_workspace_size(320, 480, &c);
    assert_true(b >= a && b - a <= 4u * 240u + 16u);
    /* Width scales it. */
    b = symline_detect_workspace_size(640, 240, &c);
    assert_true(b > a + 320u * 10u);
    c.axes = SYMLINE_AXES_VERTICAL;
    assert_true(symline_detect_workspace_size(320, 240, &c) <= a);
    printf("workspace bytes (axis horizontal, defaults):\n");
    {
        static const uint32_t dims[3][2] = {{160, 120}, {320, 240}, {640, 480}};
        static const uint32_t radii[2] = {3, 10};
        uint32_t i, j;
        for (j = 0; j < 2u; j++) {
            for (i = 0; i < 3u; i++) {
                c.axes = SYMLINE_AXES_HORIZONTAL;
                c.radius = radii[j];
                printf("  %ux%u m=%u: %zu (levels=1: ", dims[i][0], dims[i][1], radii[j],
                       symline_detect_workspace_size(dims[i][0], dims[i][1], &c));
                c.levels = 1;
                printf("%zu)\n", symline_detect_workspace_size(dims[i][0], dims[i][1], &c));
                c.levels = 0;
            }
        }
    }
}

/* A line seen by both axes (45 degrees) or at several scales (wide) is reported once. */
static uint32_t count_segments_on(const uint8_t *px, uint32_t w, uint32_t h)
{
    symline_image img;
    symline_config cfg;
    symline_segment segs[64];
    symline_result r;
    size_t wsn;
    void *ws;
    uint32_t n;
    img.width = w;
    img.height = h;
    img.stride = w;
    img.data = px;
    symline_config_default(&cfg);
    wsn = symline_detect_workspace_size(w, h, &cfg);
    ws = malloc(wsn);
    r.segments = segs;
    r.segment_cap = 64;
    r.points = (symline_point *)malloc(100000u * sizeof(symline_point));
    r.point_cap = 100000;
    assert_int_equal(symline_detect(&img, &cfg, ws, wsn, &r), SYMLINE_OK);
    assert_int_equal(r.truncated, 0);
    n = r.segment_count;
    free(ws);
    free(r.points);
    return n;
}

static void reported_once(void **state)
{
    const uint32_t w = 320, h = 240;
    uint8_t *px = (uint8_t *)malloc((size_t)w * h);
    uint32_t x, y, s = 777u;
    (void)state;
    /* A 3 px line at 45 degrees on a noisy carpet: both axes see it. */
    for (y = 0; y < h; y++) {
        for (x = 0; x < w; x++) {
            const int32_t d = (int32_t)x - (int32_t)y - 40;
            px[y * w + x] = (uint8_t)((d >= -1 && d <= 1) ? 200u : 70u + tu_rand(&s) % 10u);
        }
    }
    assert_int_equal(count_segments_on(px, w, h), 1);
    /* A 14 px wide horizontal line: found at a coarse scale only, once. */
    for (y = 0; y < h; y++) {
        for (x = 0; x < w; x++) {
            px[y * w + x] = (uint8_t)((y >= 100u && y < 114u) ? 210u : 70u + tu_rand(&s) % 10u);
        }
    }
    assert_int_equal(count_segments_on(px, w, h), 1);
    free(px);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(errors),
        cmocka_unit_test(finds_lines),
        cmocka_unit_test(truncation_never_overflows),
        cmocka_unit_test(stride_and_workspace_do_not_matter),
        cmocka_unit_test(workspace_figures),
        cmocka_unit_test(reported_once),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}

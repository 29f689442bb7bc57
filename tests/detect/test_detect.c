/*
 * symline_detect(): arguments and errors, workspace figures, truncation
 * without overflow, and strip processing against a plain full-frame path.
 */
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include <cmocka.h>

#include "linepoints.h"
#include "pass.h"
#include "imgio.h"
#include "symline/extrema.h"
#include "symline/symmetry.h"
#include "testutil.h"

/* ---- a synthetic test frame: lines of several widths, a ring, noise, a saturated block ---- */

static void draw_disc(uint8_t *px, uint32_t w, uint32_t h, uint32_t stride, int32_t cx,
                      int32_t cy, int32_t r2_in, int32_t r2_out, uint8_t v)
{
    uint32_t x, y;
    for (y = 0; y < h; y++) {
        for (x = 0; x < w; x++) {
            const int32_t dx = (int32_t)x - cx, dy = (int32_t)y - cy;
            const int32_t d2 = dx * dx + dy * dy;
            if (d2 >= r2_in && d2 <= r2_out) {
                px[y * stride + x] = v;
            }
        }
    }
}

/* Frame w x h with the given stride (bytes), deterministic. */
static uint8_t *make_frame(uint32_t w, uint32_t h, uint32_t stride)
{
    uint8_t *px = (uint8_t *)malloc((size_t)stride * h);
    uint32_t x, y, s = 12345u;
    for (y = 0; y < h; y++) {
        for (x = 0; x < stride; x++) {
            px[y * stride + x] = (uint8_t)(60u + tu_rand(&s) % 24u);
        }
    }
    for (x = 0; x < w; x++) {
        /* a 2 px horizontal line, a 9 px one, a slanted 3 px one */
        for (y = 20; y < 22; y++) {
            px[y * stride + x] = 200;
        }
        for (y = 60; y < 69; y++) {
            px[y * stride + x] = 190;
        }
        for (y = 0; y < 3; y++) {
            const uint32_t yy = 90u + x / 3u + y;
            if (yy < h) {
                px[yy * stride + x] = 180;
            }
        }
    }
    for (y = 0; y < h; y++) { /* a vertical line */
        px[y * stride + w / 2u] = 210;
        px[y * stride + w / 2u + 1u] = 205;
    }
    draw_disc(px, w, h, stride, (int32_t)w / 4, (int32_t)h * 2 / 3, 400, 484, 220);
    for (y = 100; y < 130 && y < h; y++) { /* a saturated block: long plateaus */
        for (x = 10; x < 40 && x < w; x++) {
            px[y * stride + x] = 255;
        }
    }
    return px;
}

/* ---- the full-frame path: whole grid image, whole maps, same filter rule ---- */

static int plateau_ok(const uint32_t *E, const sl_pass *p, uint32_t x, uint32_t y)
{
    uint32_t b;
    if (p->axis == SYMLINE_AXIS_HORIZONTAL) {
        for (b = y; b + 1u < p->h && E[(b + 1u) * p->w + x] == E[y * p->w + x]; b++) {
        }
        return b - y <= p->lag;
    }
    for (b = x; b + 1u < p->w && E[y * p->w + b + 1u] == E[y * p->w + x]; b++) {
    }
    return b - x <= p->lag;
}

/* Extremum of the given kind at (x, y) that passes the plateau rule. */
static int marked(const uint8_t *map, const uint32_t *E, const sl_pass *p, uint32_t x, uint32_t y,
                  uint8_t kind)
{
    return map[y * p->w + x] == kind && plateau_ok(E, p, x, y);
}

static uint32_t full_frame_points(const symline_image *img, const sl_pass *p, symline_point *out)
{
    const uint32_t w = p->w, h = p->h, k = p->k, D = p->filter.a_distance;
    uint8_t *g = (uint8_t *)malloc((size_t)w * h);
    uint16_t *acc = (uint16_t *)malloc((size_t)img->width * sizeof(uint16_t));
    uint32_t *E = (uint32_t *)malloc((size_t)w * h * sizeof(uint32_t));
    uint8_t *map = (uint8_t *)malloc((size_t)w * h);
    symline_image gi;
    size_t wsn;
    void *ws;
    uint32_t x, y, n = 0u;
    for (y = 0; y < h; y++) {
        sl_grid_row(img, p, y, acc, g + (size_t)y * w);
    }
    gi.width = w;
    gi.height = h;
    gi.stride = w;
    gi.data = g;
    wsn = symline_extrema_workspace_size(w, h, p->axis, p->m);
    ws = malloc(wsn);
    assert_int_equal(symline_energy_frame(&gi, p->axis, p->m, E, w, (size_t)w * h), SYMLINE_OK);
    assert_int_equal(symline_extrema(&gi, p->axis, p->m, map, w, (size_t)w * h, ws, wsn),
                     SYMLINE_OK);
    for (y = 0; y < h; y++) {
        for (x = 0; x < w; x++) {
            uint32_t c, lo, hi, i, a = 0u;
            if (!marked(map, E, p, x, y, SYMLINE_MAP_S)) {
                continue;
            }
            c = g[y * w + x];
            if (p->axis == SYMLINE_AXIS_HORIZONTAL) {
                lo = g[(y >= k ? y - k : 0u) * w + x];
                hi = g[(y + k < h ? y + k : h - 1u) * w + x];
            } else {
                lo = g[y * w + (x >= k ? x - k : 0u)];
                hi = g[y * w + (x + k < w ? x + k : w - 1u)];
            }
            if (!sl_linefilter_gray(&p->filter, c, lo, hi)) {
                continue;
            }
            if (D != 0u) {
                for (i = 0; i <= 2u * D; i++) {
                    const int32_t o = (int32_t)i - (int32_t)D;
                    const int32_t xx = (int32_t)x + (p->axis == SYMLINE_AXIS_VERTICAL ? o : 0);
                    const int32_t yy = (int32_t)y + (p->axis == SYMLINE_AXIS_HORIZONTAL ? o : 0);
                    if (xx >= 0 && yy >= 0 && (uint32_t)xx < w && (uint32_t)yy < h &&
                        marked(map, E, p, (uint32_t)xx, (uint32_t)yy, SYMLINE_MAP_A)) {
                        a = 1u;
                    }
                }
                if (!a) {
                    continue;
                }
            }
            out[n].x = (uint16_t)x;
            out[n].y = (uint16_t)y;
            n++;
        }
    }
    free(g);
    free(acc);
    free(E);
    free(map);
    free(ws);
    return n;
}

/* Strip path (what symline_detect runs) vs full-frame path, one pass. */
static void compare_pass(const symline_image *img, const symline_config *cfg, symline_axis axis,
                         uint32_t level)
{
    sl_pass p;
    size_t wsn;
    uint8_t *ws;
    symline_point *a, *b;
    uint32_t *row_start, na = 0u, nb, i, y;
    uint8_t trunc = 0u;
    sl_pass_setup(&p, cfg, axis, level, img->width, img->height);
    wsn = sl_collect_ws_size(&p, img->width);
    ws = tu_guard_alloc(wsn);
    memset(ws, 0x5A, wsn); /* results must not depend on what the workspace held */
    a = (symline_point *)malloc((size_t)p.w * p.h * sizeof(symline_point));
    b = (symline_point *)malloc((size_t)p.w * p.h * sizeof(symline_point));
    row_start = (uint32_t *)malloc(((size_t)p.h + 1u) * sizeof(uint32_t));
    assert_int_equal(sl_collect(img, &p, ws, wsn, a, p.w * p.h, &na, row_start, &trunc),
                     SYMLINE_OK);
    assert_true(tu_guard_ok(ws, wsn));
    assert_int_equal(trunc, 0);
    nb = full_frame_points(img, &p, b);
    assert_true(na > 10u); /* the frame has lines: an empty list would prove nothing */
    assert_int_equal(na, nb);
    for (i = 0; i < na; i++) {
        assert_int_equal(a[i].x, b[i].x);
        assert_int_equal(a[i].y, b[i].y);
    }
    /* the row index matches the list */
    for (y = 0; y < p.h; y++) {
        for (i = row_start[y]; i < row_start[y + 1u]; i++) {
            assert_int_equal(a[i].y, y);
        }
    }
    assert_int_equal(row_start[p.h], na);
    tu_guard_free(ws);
    free(a);
    free(b);
    free(row_start);
}

static void strip_identity_on(const symline_image *img)
{
    symline_config cfg;
    uint32_t level, ax, f;
    for (f = 0; f < 2u; f++) {
        for (level = 0; level < 3u; level++) {
            for (ax = 0; ax < 2u; ax++) {
                symline_config_default(&cfg);
                if (f == 1u) {
                    cfg.filter = SYMLINE_FILTER_PAPER;
                    cfg.illumination = 100u;
                }
                compare_pass(img, &cfg, ax == 0u ? SYMLINE_AXIS_HORIZONTAL : SYMLINE_AXIS_VERTICAL,
                             level);
            }
        }
    }
    /* another radius */
    symline_config_default(&cfg);
    cfg.radius = 5;
    compare_pass(img, &cfg, SYMLINE_AXIS_HORIZONTAL, 0);
    compare_pass(img, &cfg, SYMLINE_AXIS_VERTICAL, 1);
}

static void strip_identity_synthetic(void **state)
{
    symline_image img;
    uint8_t *px = make_frame(203, 157, 211);
    (void)state;
    img.width = 203;
    img.height = 157;
    img.stride = 211;
    img.data = px;
    strip_identity_on(&img);
    free(px);
}

static void strip_identity_real(void **state)
{
    imgio_gray g;
    char err[256];
    symline_image img;
    (void)state;
    assert_int_equal(imgio_read_gray(SYMLINE_TEST_DATA "/msl_20190606_r2_cam0_20190606_204340.pgm",
                                     &g, err, sizeof err),
                     0);
    img.width = g.width;
    img.height = g.height;
    img.stride = g.width;
    img.data = g.px;
    strip_identity_on(&img);
    imgio_free(&g);
}

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
    F.px = make_frame(160, 120, 160);
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
    F.res.truncated = 7;
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
    assert_int_equal(F.res.truncated, 7);
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
    assert_true(horiz >= 1u); /* the thin horizontal line */
    assert_true(vert >= 1u);  /* the vertical line, found once (not also by the other axis) */
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
    uint8_t *px2 = make_frame(160, 120, 173);
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
        cmocka_unit_test(strip_identity_synthetic),
        cmocka_unit_test(strip_identity_real),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}

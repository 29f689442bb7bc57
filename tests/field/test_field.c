/* SPDX-License-Identifier: Apache-2.0 */
/*
 * The field boundary (symline/field.h) on hand-made frames with known
 * answers: a boundary at a known row, at a known slant, bent once by a field
 * corner, with legs and a robot cutting into the carpet, with shadow stripes
 * and a thick line on it; a carpet clipped to black; a lens's black rim;
 * degenerate frames; argument errors and workspace bounds.
 */
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <stdlib.h>
#include <string.h>

#include <cmocka.h>

#include "symline/detect.h"
#include "symline/field.h"
#include "testutil.h"

#define W 320u
#define H 240u

/* Carpet: mid-gray grain; above the boundary: a smooth bright wall. */
static uint8_t carpet_px(uint32_t *s)
{
    return (uint8_t)(80u + tu_rand(s) % 32u);
}

/* Fills a W x H frame: carpet where y >= top(x), wall above. */
typedef int32_t (*top_fn)(int32_t x);

static uint8_t *make_field(top_fn top)
{
    uint8_t *px = (uint8_t *)malloc((size_t)W * H);
    uint32_t x, y, s = 2024u;
    assert_non_null(px);
    for (y = 0; y < H; y++) {
        for (x = 0; x < W; x++) {
            px[y * W + x] =
                (int32_t)y >= top((int32_t)x) ? carpet_px(&s) : (uint8_t)(190u + x / 64u);
        }
    }
    return px;
}

/* Runs the stage with default settings on a width x height frame. */
static symline_status find(const uint8_t *px, uint32_t w, uint32_t h, symline_field_boundary *b)
{
    symline_field_config fc;
    symline_image img;
    size_t need;
    uint8_t *ws;
    symline_status st;
    symline_field_config_default(&fc);
    img.width = w;
    img.height = h;
    img.stride = w;
    img.data = px;
    need = symline_field_workspace_size(w, h, &fc);
    assert_true(need > 0u);
    ws = tu_guard_alloc(need);
    memset(b, 0xEE, sizeof *b);
    st = symline_field_find(&img, &fc, ws, need, b);
    assert_true(tu_guard_ok(ws, need));
    tu_guard_free(ws);
    return st;
}

/* Checks the polyline's form: left edge to right edge, x increasing, rows in [0, h]. */
static void check_form(const symline_field_boundary *b, uint32_t w, uint32_t h)
{
    uint32_t i;
    assert_true(b->count >= 1u && b->count <= SYMLINE_FIELD_MAX_VERTICES);
    assert_int_equal(b->v[0].x, 0);
    assert_int_equal(b->v[b->count - 1u].x, (int32_t)w - 1);
    for (i = 0; i < b->count; i++) {
        assert_true(b->v[i].y >= 0 && b->v[i].y <= (int32_t)h);
        if (i > 0u) {
            assert_true(b->v[i].x > b->v[i - 1u].x);
        }
    }
}

/* At every 8th column of [x0, x1], the boundary lies at most `low` px below
 * want(x) and at most `high` px above it (too high only keeps clutter, too
 * low loses field lines). */
static void check_near_in(const symline_field_boundary *b, top_fn want, int32_t low, int32_t high,
                          int32_t x0, int32_t x1)
{
    int32_t x;
    for (x = x0; x <= x1; x += 8) {
        const int32_t d = symline_field_y(b, x) - want(x);
        if (d > low || d < -high) {
            uint32_t i;
            for (i = 0; i < b->count; i++) {
                print_message("(%d,%d) ", (int)b->v[i].x, (int)b->v[i].y);
            }
            fail_msg("x=%d: boundary %d, want %d", (int)x, (int)symline_field_y(b, x),
                     (int)want(x));
        }
    }
}

/* The grid has 8 px rows and columns 16 px apart: a boundary is found to
 * within about a cell. */
static void check_near(const symline_field_boundary *b, top_fn want, int32_t low, int32_t high)
{
    check_near_in(b, want, low, high, 0, (int32_t)W - 1);
}

static int32_t top_row(int32_t x)
{
    (void)x;
    return 100;
}

static int32_t top_slant(int32_t x)
{
    return 60 + x / 4; /* 60 at the left edge, 139 at the right */
}

static int32_t top_corner(int32_t x)
{
    /* A field corner at x = 200, y = 40: one bend, the sides fall away. */
    return 40 + (x < 200 ? 200 - x : x - 200) / 2;
}

static void test_known_row(void **state)
{
    symline_field_boundary b;
    uint8_t *px = make_field(top_row);
    (void)state;
    assert_int_equal(find(px, W, H, &b), SYMLINE_OK);
    check_form(&b, W, H);
    check_near(&b, top_row, 8, 8);
    assert_true(symline_field_above(&b, 160, 90));
    assert_false(symline_field_above(&b, 160, 110));
    free(px);
}

static void test_known_slant(void **state)
{
    symline_field_boundary b;
    uint8_t *px = make_field(top_slant);
    (void)state;
    assert_int_equal(find(px, W, H, &b), SYMLINE_OK);
    check_form(&b, W, H);
    check_near(&b, top_slant, 8, 12);
    free(px);
}

static void test_corner(void **state)
{
    symline_field_boundary b;
    uint8_t *px = make_field(top_corner);
    (void)state;
    assert_int_equal(find(px, W, H, &b), SYMLINE_OK);
    check_form(&b, W, H);
    check_near(&b, top_corner, 8, 24);
    /* The corner is the highest point, both sides fall away from it. */
    assert_true(symline_field_y(&b, 200) < symline_field_y(&b, 100));
    assert_true(symline_field_y(&b, 200) < symline_field_y(&b, 300));
    free(px);
}

/* Legs (dark, from the top down into the carpet), a robot (a dark block on
 * the carpet), a thick white line across and shadow stripes on it: none of
 * them pulls the boundary down. */
static void test_occluders_and_light(void **state)
{
    symline_field_boundary b;
    uint8_t *px = make_field(top_row);
    uint32_t x, y;
    (void)state;
    for (y = 0; y < H; y++) {
        for (x = 0; x < W; x++) {
            uint8_t *p = &px[y * W + x];
            if (((x >= 100u && x < 120u) || (x >= 140u && x < 160u)) && y < 200u) {
                *p = 30; /* two legs reaching into the carpet */
            } else if (x >= 240u && x < 290u && y >= 70u && y < 180u) {
                *p = (uint8_t)(y % 16u < 12u ? 45u : 200u); /* a robot: smooth, banded */
            } else if (y >= 150u && y < 162u) {
                *p = 235; /* a thick line across the whole frame */
            } else if (y >= 100u && ((x + 2u * y) / 40u) % 3u == 0u) {
                *p = (uint8_t)(*p * 3u / 5u); /* shadow stripes on the carpet */
            }
        }
    }
    assert_int_equal(find(px, W, H, &b), SYMLINE_OK);
    check_form(&b, W, H);
    /* Within a cell, but near the image edges, where a column has neighbours
     * on one side only (here a shadow right under the edge and a leg nearby
     * hold the first columns down): there within three cells. */
    check_near_in(&b, top_row, 8, 8, 32, (int32_t)W - 33);
    check_near_in(&b, top_row, 24, 8, 0, (int32_t)W - 1);
    free(px);
}

/* All carpet: the boundary lies at (or above) the top: nothing is dropped. */
static void test_all_carpet(void **state)
{
    symline_field_boundary b;
    uint8_t *px = (uint8_t *)malloc((size_t)W * H);
    uint32_t i, s = 7u;
    int32_t x;
    (void)state;
    assert_non_null(px);
    for (i = 0; i < W * H; i++) {
        px[i] = carpet_px(&s);
    }
    assert_int_equal(find(px, W, H, &b), SYMLINE_OK);
    check_form(&b, W, H);
    for (x = 0; x < (int32_t)W; x++) {
        assert_int_equal(symline_field_y(&b, x), 0);
        assert_false(symline_field_above(&b, x, 0));
    }
    free(px);
}

/* A carpet clipped to black (a dim hall, an under-exposed frame) with white
 * lines on it, a bright wall above: black cells, which the carpet model
 * leaves out as a lens's corners while they are a minority of its band, are
 * most of it here and are the carpet. The boundary lies no lower than the
 * carpet's top (at the frame's bottom it would drop every line); it may lie
 * higher: a black carpet has no grain that tells a smooth wall from it. */
static void test_black_carpet(void **state)
{
    symline_field_boundary b;
    uint8_t *px = make_field(top_row);
    uint32_t x, y;
    (void)state;
    for (y = (uint32_t)top_row(0); y < H; y++) {
        for (x = 0; x < W; x++) {
            const bool line = (y >= 150u && y < 158u) || x % 80u < 6u;
            px[y * W + x] = line ? 230u : 0u;
        }
    }
    assert_int_equal(find(px, W, H, &b), SYMLINE_OK);
    check_form(&b, W, H);
    check_near(&b, top_row, 8, (int32_t)H);
    assert_true(b.carpet_mean < 12u);
    free(px);
}

/* A darkened frame through a fisheye lens: its black rim and the dimmed
 * carpet beside it fill the lowest four grid rows, more than a barrier (three
 * of the frame's 30 rows), so every column's scan ends in them. The rim is
 * taken as free below the carpet (the lowest half barrier's rows) and the
 * scan runs again: the boundary lies at the known row, not at the bottom. */
static void test_black_rim(void **state)
{
    symline_field_boundary b;
    uint8_t *px = make_field(top_row);
    (void)state;
    memset(px + (size_t)(H - 32u) * W, 0, (size_t)32u * W);
    assert_int_equal(find(px, W, H, &b), SYMLINE_OK);
    check_form(&b, W, H);
    check_near(&b, top_row, 8, 8);
    /* The same under a dim ceiling, the frame's top row of cells, which the
     * first scan reads last: the second scan starts from the frame's own
     * lowest row again, not from what the first one read. */
    memset(px, 20, (size_t)8u * W);
    assert_int_equal(find(px, W, H, &b), SYMLINE_OK);
    check_form(&b, W, H);
    check_near(&b, top_row, 8, 8);
    free(px);
}

/* Uniform frames (all white, all black) and tiny ones must not fail; a
 * uniform frame is one carpet-like region, so nothing lies above it. */
static void test_degenerate(void **state)
{
    static const uint32_t sizes[][2] = {{1, 1}, {8, 8}, {2, 1}, {1, 9}, {3, 200}, {333, 2}};
    static const uint8_t fills[] = {0, 255, 128};
    symline_field_boundary b;
    uint8_t *px = (uint8_t *)malloc((size_t)W * H);
    uint32_t i, f;
    (void)state;
    assert_non_null(px);
    for (f = 0; f < sizeof fills; f++) {
        memset(px, fills[f], (size_t)W * H);
        assert_int_equal(find(px, W, H, &b), SYMLINE_OK);
        check_form(&b, W, H);
        assert_int_equal(symline_field_y(&b, 0), 0);
        assert_int_equal(symline_field_y(&b, (int32_t)W - 1), 0);
        for (i = 0; i < sizeof sizes / sizeof sizes[0]; i++) {
            assert_int_equal(find(px, sizes[i][0], sizes[i][1], &b), SYMLINE_OK);
            check_form(&b, sizes[i][0], sizes[i][1]);
        }
    }
    /* Salt and pepper: no homogeneous region at all; still a valid answer. */
    {
        uint32_t s = 99u;
        for (i = 0; i < W * H; i++) {
            px[i] = (tu_rand(&s) & 1u) ? 255u : 0u;
        }
        assert_int_equal(find(px, W, H, &b), SYMLINE_OK);
        check_form(&b, W, H);
    }
    free(px);
}

/* A boundary below the image (no field in view): every pixel is above it.
 * One above it: none is. Queries clamp x to the polyline. */
static void test_query(void **state)
{
    symline_field_boundary b;
    (void)state;
    memset(&b, 0, sizeof b);
    assert_int_equal(symline_field_y(NULL, 3), 0);
    assert_int_equal(symline_field_y(&b, 3), 0); /* empty */
    assert_false(symline_field_above(&b, 3, -5));
    b.count = 2u;
    b.v[0].x = 0;
    b.v[0].y = (int32_t)H;
    b.v[1].x = (int32_t)W - 1;
    b.v[1].y = (int32_t)H;
    assert_true(symline_field_above(&b, 0, 0));
    assert_true(symline_field_above(&b, (int32_t)W - 1, (int32_t)H - 1));
    assert_true(symline_field_above(&b, -10, 5));
    assert_true(symline_field_above(&b, 5000, 5));
    b.v[0].y = 0;
    b.v[1].y = 0;
    assert_false(symline_field_above(&b, 17, 0));
    /* Interpolation: from (0, 0) to (319, 100), rounded toward the top. */
    b.v[1].y = 100;
    assert_int_equal(symline_field_y(&b, 0), 0);
    assert_int_equal(symline_field_y(&b, 319), 100);
    assert_int_equal(symline_field_y(&b, 160), 50); /* 160 * 100 / 319 = 50.2 */
    b.count = SYMLINE_FIELD_MAX_VERTICES + 1u;      /* corrupt: treated as empty */
    assert_int_equal(symline_field_y(&b, 5), 0);
}

static void test_errors(void **state)
{
    symline_field_config fc;
    symline_field_boundary b, before;
    symline_image img;
    uint8_t px[64] = {0};
    uint8_t ws[4096];
    size_t need;
    (void)state;
    symline_field_config_default(&fc);
    symline_field_config_default(NULL);
    img.width = 8;
    img.height = 8;
    img.stride = 8;
    img.data = px;
    need = symline_field_workspace_size(8, 8, &fc);
    assert_true(need > 0u && need <= sizeof ws);
    memset(&b, 0x5A, sizeof b);
    before = b;
    assert_int_equal(symline_field_find(NULL, &fc, ws, need, &b), SYMLINE_ERR_NULL);
    assert_int_equal(symline_field_find(&img, NULL, ws, need, &b), SYMLINE_ERR_NULL);
    assert_int_equal(symline_field_find(&img, &fc, NULL, need, &b), SYMLINE_ERR_NULL);
    assert_int_equal(symline_field_find(&img, &fc, ws, need, NULL), SYMLINE_ERR_NULL);
    assert_int_equal(symline_field_find(&img, &fc, ws, need - 1u, &b), SYMLINE_ERR_BUFFER);
    img.stride = 7;
    assert_int_equal(symline_field_find(&img, &fc, ws, need, &b), SYMLINE_ERR_STRIDE);
    img.stride = 8;
    img.width = 0;
    assert_int_equal(symline_field_find(&img, &fc, ws, need, &b), SYMLINE_ERR_SIZE);
    img.width = 8;
    fc.cell = 3u; /* not a power of two */
    assert_int_equal(symline_field_find(&img, &fc, ws, need, &b), SYMLINE_ERR_CONFIG);
    assert_int_equal(symline_field_workspace_size(8, 8, &fc), 0u);
    fc.cell = 0u;
    fc.miss_cost = 0u;
    assert_int_equal(symline_field_find(&img, &fc, ws, need, &b), SYMLINE_ERR_CONFIG);
    fc.miss_cost = 2u;
    fc.band_pct = 101u;
    assert_int_equal(symline_field_find(&img, &fc, ws, need, &b), SYMLINE_ERR_CONFIG);
    assert_memory_equal(&b, &before, sizeof b);
    symline_field_config_default(&fc);
    assert_int_equal(symline_field_workspace_size(0, 8, &fc), 0u);
    assert_int_equal(symline_field_workspace_size(8, 65536, &fc), 0u);
    assert_int_equal(symline_field_workspace_size(8, 8, NULL), 0u);
    /* Working memory: per grid column, plus the model band's cells. */
    assert_true(symline_field_workspace_size(320, 240, &fc) < 2048u);
    assert_true(symline_field_workspace_size(640, 480, &fc) < 4096u);
    assert_true(symline_field_workspace_size(640, 480, &fc) <
                symline_field_workspace_size(640, 960, &fc));
    assert_int_equal(symline_field_find(&img, &fc, ws, need, &b), SYMLINE_OK);
}

/* The detector with the boundary: a bright line painted on the wall above
 * the field is dropped by default, kept with SYMLINE_FIELD_KEEP, and the
 * line on the carpet is found in every mode; OFF reports no boundary. */
static uint32_t detect_rows(const uint8_t *px, symline_field_mode mode, symline_result *r,
                            uint32_t *above, uint32_t *below)
{
    symline_config cfg;
    symline_image img;
    static symline_segment segs[256];
    static symline_point pts[2u * W * H];
    int guards_ok;
    uint32_t i;
    symline_config_default(&cfg);
    cfg.field_boundary = mode;
    img.width = W;
    img.height = H;
    img.stride = W;
    img.data = px;
    memset(r, 0, sizeof *r);
    r->segments = segs;
    r->segment_cap = 256u;
    r->points = pts;
    r->point_cap = 2u * W * H;
    assert_int_equal(tu_detect_guarded(&img, &cfg, r, &guards_ok), SYMLINE_OK);
    assert_true(guards_ok);
    *above = *below = 0u;
    for (i = 0; i < r->segment_count; i++) {
        const int32_t y = (r->segments[i].y0 + r->segments[i].y1) / 512;
        if (y < 100) {
            (*above)++;
        } else {
            (*below)++;
        }
    }
    return r->segment_count;
}

static void test_detector_drops_above(void **state)
{
    symline_result r;
    uint32_t above, below, x, y;
    uint8_t *px = make_field(top_row);
    (void)state;
    for (x = 20u; x < W - 20u; x++) {
        for (y = 48u; y < 52u; y++) {
            px[y * W + x] = 60; /* a dark band on the wall ... */
        }
        for (y = 40u; y < 44u; y++) {
            px[y * W + x] = 250; /* ... and a bright stripe: line-like, above the field */
        }
        for (y = 170u; y < 174u; y++) {
            px[y * W + x] = 230; /* a painted line on the carpet */
        }
    }
    (void)detect_rows(px, SYMLINE_FIELD_KEEP, &r, &above, &below);
    assert_true(r.field.count >= 2u);
    assert_true(above >= 1u); /* the wall stripe is found when kept ... */
    assert_true(below >= 1u);
    (void)detect_rows(px, SYMLINE_FIELD_DROP, &r, &above, &below);
    assert_int_equal(above, 0u); /* ... and dropped by default */
    assert_true(below >= 1u);
    check_near(&r.field, top_row, 8, 8);
    (void)detect_rows(px, SYMLINE_FIELD_OFF, &r, &above, &below);
    assert_int_equal(r.field.count, 0u);
    assert_true(above >= 1u && below >= 1u);
    free(px);
}

static void test_detector_config(void **state)
{
    symline_config cfg;
    (void)state;
    symline_config_default(&cfg);
    assert_int_equal(cfg.field_boundary, SYMLINE_FIELD_DROP);
    cfg.field_boundary = (symline_field_mode)3;
    assert_int_equal(symline_detect_workspace_size(W, H, &cfg), 0u);
    symline_config_default(&cfg);
    cfg.field.cell = 5u;
    assert_int_equal(symline_detect_workspace_size(W, H, &cfg), 0u);
    symline_config_default(&cfg);
    cfg.field_margin = 70000u;
    assert_int_equal(symline_detect_workspace_size(W, H, &cfg), 0u);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_known_row),       cmocka_unit_test(test_known_slant),
        cmocka_unit_test(test_corner),          cmocka_unit_test(test_occluders_and_light),
        cmocka_unit_test(test_all_carpet),      cmocka_unit_test(test_black_carpet),
        cmocka_unit_test(test_black_rim),
        cmocka_unit_test(test_degenerate),      cmocka_unit_test(test_query),
        cmocka_unit_test(test_errors),          cmocka_unit_test(test_detector_drops_above),
        cmocka_unit_test(test_detector_config),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}

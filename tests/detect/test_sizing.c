/* SPDX-License-Identifier: Apache-2.0 */
/*
 * Sizing the caller's buffers without trial: the compile-time workspace bound
 * against symline_detect_workspace_size(), points_needed against the point
 * storage a frame really needs, and symline_config_check() naming the field
 * that is out of range.
 */
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include <cmocka.h>

#include "imgio.h"
#include "symline/detect.h"

/* A compile-time size really is a constant expression. */
static uint8_t static_ws[SYMLINE_DETECT_WORKSPACE_SIZE(320, 240, 3, 0, 0)];

/* The A distance the filter uses (what the macro's last argument means). */
static uint32_t filter_a(const symline_config *c)
{
    if (c->filter != SYMLINE_FILTER_PAPER) {
        return 0u;
    }
    return c->a_distance != 0u ? c->a_distance : c->radius;
}

/* Bytes of the bound that the library does not use on a frame w wide: the
 * field boundary's lanes (64-bit targets), which a library built for size
 * (lib/common.h, __OPTIMIZE_SIZE__; the tests share its flags) leaves out. */
#if defined(__OPTIMIZE_SIZE__)
#define SIZING_UNUSED_LANES(w)                                                                     \
    SYMLINE_DETECT_WS_LANES_((size_t)(w) / SYMLINE_DETECT_WS_CELL_(w) + 1u)
#else
#define SIZING_UNUSED_LANES(w) ((size_t)0u)
#endif

/* The bound holds and stays within the fixed part plus a little per row and column. */
static void check_bound(uint32_t w, uint32_t h, const symline_config *c)
{
    symline_config worst = *c;
    size_t exact, bound;
    /* The field boundary's search at its largest: every grid column, the
     * carpet model from all rows (the bound holds for any such setting). */
    worst.field.band_pct = 100u;
    worst.field.col_cells = 1u;
    exact = symline_detect_workspace_size(w, h, &worst);
    bound = SYMLINE_DETECT_WORKSPACE_SIZE(w, h, c->radius, filter_a(c), c->levels);
    if (exact == 0u) {
        return; /* a size the detector rejects */
    }
    if (bound < symline_detect_workspace_size(w, h, c)) {
        fail();
    }
    /* Never below; and where the horizontal axis runs (the bound's case), a few hundred
     * bytes over at most, plus an eighth where the scales differ from its worst case,
     * plus what the library leaves unused. */
    if (bound < exact || (c->axes != SYMLINE_AXES_VERTICAL &&
                          bound - exact > SYMLINE_DETECT_WS_FIXED + 8u * (2u * c->radius + 1u) +
                                              exact / 8u + SIZING_UNUSED_LANES(w))) {
        fprintf(stderr, "%ux%u radius %u a %u axes %d levels %u filter %d: exact %zu, bound %zu\n",
                w, h, c->radius, filter_a(c), (int)c->axes, c->levels, (int)c->filter, exact,
                bound);
        fail();
    }
}

static void test_workspace_macro_bounds_the_query(void **state)
{
    static const uint32_t sizes[][2] = {
        {1, 1},       {2, 3},     {7, 5},     {16, 16},   {33, 17},   {64, 48},
        {160, 120},   {320, 240}, {321, 241}, {640, 480}, {608, 800}, {1280, 720},
        {1920, 1080}, {4000, 16}, {16, 4000}, {65535, 2}, {2, 65535}};
    static const uint32_t radii[] = {1, 2, 3, 5, 8, 16, 31, 32};
    static const uint32_t a_dist[] = {0, 1, 3, 32};
    size_t si, ri, ai;
    int axes, filter;
    uint32_t levels;
    symline_config c;
    (void)state;
    symline_config_default(&c);
    assert_true(sizeof static_ws >= symline_detect_workspace_size(320, 240, &c));
    for (si = 0; si < sizeof sizes / sizeof sizes[0]; si++) {
        for (ri = 0; ri < sizeof radii / sizeof radii[0]; ri++) {
            for (filter = 0; filter < 2; filter++) {
                for (ai = 0; ai < (filter ? sizeof a_dist / sizeof a_dist[0] : 1u); ai++) {
                    for (axes = 0; axes < 3; axes++) {
                        for (levels = 0; levels <= 5u; levels++) {
                            symline_config_default(&c);
                            c.radius = radii[ri];
                            c.filter = (symline_filter)filter;
                            c.a_distance = a_dist[ai];
                            c.axes = (symline_axes)axes;
                            c.levels = levels;
                            check_bound(sizes[si][0], sizes[si][1], &c);
                        }
                    }
                }
            }
        }
    }
}

typedef struct frame {
    imgio_gray img;
    symline_image view;
} frame;

static void load(frame *f, const char *name)
{
    char path[512], err[256];
    snprintf(path, sizeof path, "%s/%s", SYMLINE_TEST_DATA, name);
    assert_int_equal(imgio_read_gray(path, &f->img, err, sizeof err), 0);
    f->view.width = f->img.width;
    f->view.height = f->img.height;
    f->view.stride = f->img.width;
    f->view.data = f->img.px;
}

/* One detection with point_cap points; the segments and points land in the given arrays. */
static symline_result detect(const frame *f, const symline_config *c, symline_point *pts,
                             uint32_t cap, symline_segment *segs, uint32_t segcap)
{
    symline_result r;
    const size_t n = symline_detect_workspace_size(f->view.width, f->view.height, c);
    void *ws = malloc(n);
    assert_non_null(ws);
    memset(&r, 0, sizeof r);
    r.segments = segs;
    r.segment_cap = segcap;
    r.points = pts;
    r.point_cap = cap;
    assert_int_equal(symline_detect(&f->view, c, ws, n, &r), SYMLINE_OK);
    free(ws);
    return r;
}

/*
 * points_needed is exact: with that capacity the result is the same as with
 * plenty, one point less runs out; after running out it asks for more than
 * it had.
 */
static void check_points_needed(const char *name, const symline_config *c)
{
    enum {
        SEGS = 4096
    };
    frame f;
    symline_segment *s1 = malloc(SEGS * sizeof *s1), *s2 = malloc(SEGS * sizeof *s2);
    symline_point *p1, *p2;
    symline_result big, same, less;
    uint32_t plenty, need, i;
    load(&f, name);
    plenty = 2u * f.view.width * f.view.height + 1024u;
    p1 = malloc((size_t)plenty * sizeof *p1);
    p2 = malloc((size_t)plenty * sizeof *p2);
    assert_non_null(s1);
    assert_non_null(s2);
    assert_non_null(p1);
    assert_non_null(p2);
    big = detect(&f, c, p1, plenty, s1, SEGS);
    need = big.points_needed;
    assert_false(big.truncated);
    assert_true(need > 0u); /* the frame has line points: an empty run would prove nothing */
    assert_true(need >= big.point_count);
    assert_true(need < plenty);

    same = detect(&f, c, p2, need, s2, SEGS);
    assert_false(same.truncated);
    assert_int_equal(same.points_needed, need);
    assert_int_equal(same.segment_count, big.segment_count);
    assert_int_equal(same.point_count, big.point_count);
    for (i = 0; i < big.segment_count; i++) {
        assert_memory_equal(&s1[i], &s2[i], sizeof s1[i]);
    }
    assert_memory_equal(p1, p2, (size_t)big.point_count * sizeof *p1);

    less = detect(&f, c, p2, need - 1u, s2, SEGS);
    assert_true(less.truncated);
    assert_true(less.points_needed > need - 1u);
    /* far too little: still a request above the capacity */
    less = detect(&f, c, p2, need / 8u, s2, SEGS);
    assert_true(less.truncated);
    assert_true(less.points_needed > need / 8u);
    free(s1);
    free(s2);
    free(p1);
    free(p2);
    imgio_free(&f.img);
}

static void test_points_needed_is_exact(void **state)
{
    static const char *frames[] = {"msl_20190606_r2_cam0_20190606_204340.pgm",
                                   "msl_20240719_r5_cam3_20240719_090755.pgm", "crops/circle.pgm",
                                   "crops/goalarea.pgm"};
    size_t i;
    symline_config c;
    (void)state;
    for (i = 0; i < sizeof frames / sizeof frames[0]; i++) {
        symline_config_default(&c);
        check_points_needed(frames[i], &c);
        c.filter = SYMLINE_FILTER_PAPER; /* many more line points */
        c.illumination = 100u;
        c.adaptive = 0u;
        check_points_needed(frames[i], &c);
        symline_config_default(&c);
        c.axes = SYMLINE_AXES_VERTICAL;
        c.levels = 1u;
        check_points_needed(frames[i], &c);
    }
}

/*
 * The point storage beyond what a frame needs changes nothing. Where the
 * build keeps the coarse scales' grid rows at the storage's end (the grid
 * row cache, lib/linepoints.h, 64-bit speed builds) it does so for a pass
 * at level l once the storage holds the rows of levels l .. top and the
 * cache's head above twice the scale's grid in points after the points kept
 * so far (at most the result's): every capacity from points_needed on a
 * little, and every one around each scale's threshold, gives the result of
 * plenty, on a 320x240 window of a bundled frame with both axes and three
 * scales, and with one axis and four (the rows of levels 2 and 3 made from
 * level 1's sums). (Where the grid of earlier segments takes point storage,
 * test_points_needed_is_exact compares plenty, rows shared, with
 * points_needed, rows built.)
 */
static void same_as(const frame *f, const symline_config *c, const symline_result *big,
                    const symline_segment *s1, const symline_point *p1, uint32_t cap,
                    symline_segment *s2, uint32_t segcap, symline_point *p2)
{
    const symline_result r = detect(f, c, p2, cap, s2, segcap);
    uint32_t i;
    assert_false(r.truncated);
    assert_int_equal(r.points_needed, big->points_needed);
    assert_int_equal(r.segment_count, big->segment_count);
    assert_int_equal(r.point_count, big->point_count);
    for (i = 0; i < big->segment_count; i++) {
        assert_memory_equal(&s1[i], &s2[i], sizeof s1[i]);
    }
    assert_memory_equal(p1, p2, (size_t)big->point_count * sizeof *p1);
}

static void check_any_room(const frame *f, const symline_config *c)
{
    enum {
        SEGS = 1024
    };
    const uint32_t plenty = 2u * f->view.width * f->view.height + 1024u;
    symline_segment *s1 = malloc(SEGS * sizeof *s1), *s2 = malloc(SEGS * sizeof *s2);
    symline_point *p1 = malloc((size_t)plenty * sizeof *p1);
    symline_point *p2 = malloc((size_t)plenty * sizeof *p2);
    symline_result big;
    uint32_t cap, level;
    assert_non_null(s1);
    assert_non_null(s2);
    assert_non_null(p1);
    assert_non_null(p2);
    big = detect(f, c, p1, plenty, s1, SEGS);
    assert_false(big.truncated);
    assert_true(big.segment_count > 0u);
    for (cap = big.points_needed; cap <= big.points_needed + 64u; cap++) {
        same_as(f, c, &big, s1, p1, cap, s2, SEGS, p2);
    }
    for (level = 1u; level < c->levels; level++) {
        const uint32_t g = (f->view.width >> level) * (f->view.height >> level);
        /* the cache's bytes at this level: its head and levels level .. top */
        uint32_t bytes = (SYMLINE_DETECT_MAX_LEVELS + 1u) * 2u, l, t; /* head: a row per level */
        for (l = level; l < c->levels; l++) {
            bytes += (f->view.width >> l) * (f->view.height >> l);
        }
        /* the threshold after no point kept, from one below */
        t = 2u * g + (bytes + (uint32_t)sizeof(symline_point) - 1u) / sizeof(symline_point) - 1u;
        for (cap = t > big.points_needed ? t : big.points_needed; cap <= t + big.point_count + 1u;
             cap++) {
            same_as(f, c, &big, s1, p1, cap, s2, SEGS, p2);
        }
    }
    free(s1);
    free(s2);
    free(p1);
    free(p2);
}

static void test_more_room_same_result(void **state)
{
    frame f, win;
    symline_config c;
    (void)state;
    load(&f, "msl_20190606_r2_cam0_20190606_204340.pgm");
    assert_true(f.view.width >= 320u && f.view.height >= 560u);
    /* the window of rows 320..559, columns 0..319: carpet and lines */
    win.view.width = 320u;
    win.view.height = 240u;
    win.view.stride = f.view.stride;
    win.view.data = f.view.data + (size_t)320u * f.view.stride;
    symline_config_default(&c);
    c.levels = 3u;
    check_any_room(&win, &c);
    c.field_boundary = SYMLINE_FIELD_OFF; /* every row of every scale */
    check_any_room(&win, &c);
    symline_config_default(&c);
    c.axes = SYMLINE_AXES_HORIZONTAL;
    c.levels = 4u;
    check_any_room(&win, &c);
    c.axes = SYMLINE_AXES_VERTICAL;
    c.field_boundary = SYMLINE_FIELD_OFF;
    check_any_room(&win, &c);
    imgio_free(&f.img);
}

static void expect_field(void (*spoil)(symline_config *), symline_config_field want)
{
    symline_config c;
    symline_config_field field = SYMLINE_CFG_NONE;
    symline_config_default(&c);
    spoil(&c);
    assert_int_equal(symline_config_check(&c, &field), SYMLINE_ERR_CONFIG);
    assert_int_equal(field, want);
    assert_int_equal(symline_config_check(&c, NULL), SYMLINE_ERR_CONFIG);
}

static void bad_axes(symline_config *c)
{
    c->axes = (symline_axes)7;
}
static void bad_radius0(symline_config *c)
{
    c->radius = 0u;
}
static void bad_radius(symline_config *c)
{
    c->radius = 33u;
}
static void bad_levels(symline_config *c)
{
    c->levels = 6u;
}
static void bad_filter(symline_config *c)
{
    c->filter = (symline_filter)2;
}
static void bad_illum(symline_config *c)
{
    c->illumination = 256u;
}
static void bad_bright(symline_config *c)
{
    c->bright_sigma10 = -101;
}
static void bad_ridge(symline_config *c)
{
    c->ridge_sigma10 = 101u;
}
static void bad_side(symline_config *c)
{
    c->side_sigma10 = 101;
}
static void bad_adist(symline_config *c)
{
    c->a_distance = 33u;
}
static void bad_cpct(symline_config *c)
{
    c->contrast_pct = 101u;
}
static void bad_cmin(symline_config *c)
{
    c->contrast_min = 256u;
}
static void bad_asym(symline_config *c)
{
    c->contrast_asym_pct = 1001u;
}
static void bad_minlen(symline_config *c)
{
    c->min_length = SYMLINE_MAX_DIM + 1u;
}
static void bad_curve(symline_config *c)
{
    c->curve_dev_q8 = (SYMLINE_MAX_DIM << 8) + 1u;
}
static void bad_bend(symline_config *c)
{
    c->curve_bend_q8 = (SYMLINE_MAX_DIM << 8) + 1u;
}
static void bad_mdev(symline_config *c)
{
    c->merge_dev_q8 = (SYMLINE_MAX_DIM << 8) + 1u;
}
static void bad_fmode(symline_config *c)
{
    c->field_boundary = (symline_field_mode)9;
}
static void bad_fmargin(symline_config *c)
{
    c->field_margin = SYMLINE_MAX_DIM + 1u;
}
static void bad_two(symline_config *c)
{
    c->levels = 9u;
    c->min_length = SYMLINE_MAX_DIM + 1u;
}

static void test_config_check_names_the_field(void **state)
{
    symline_config c;
    symline_config_field field = SYMLINE_CFG_RADIUS;
    static uint8_t ws[64];
    static symline_point pts[4];
    static const uint8_t px[4] = {0, 0, 0, 0};
    symline_image img = {2, 2, 2, px};
    symline_result r = {NULL, 0, 0, pts, 4, 0, 0, {0}, 0};
    (void)state;
    symline_config_default(&c);
    assert_int_equal(symline_config_check(&c, &field), SYMLINE_OK);
    assert_int_equal(field, SYMLINE_CFG_NONE);
    field = SYMLINE_CFG_RADIUS;
    assert_int_equal(symline_config_check(NULL, &field), SYMLINE_ERR_NULL);
    assert_int_equal(field, SYMLINE_CFG_NONE);
    expect_field(bad_axes, SYMLINE_CFG_AXES);
    expect_field(bad_radius0, SYMLINE_CFG_RADIUS);
    expect_field(bad_radius, SYMLINE_CFG_RADIUS);
    expect_field(bad_levels, SYMLINE_CFG_LEVELS);
    expect_field(bad_filter, SYMLINE_CFG_FILTER);
    expect_field(bad_illum, SYMLINE_CFG_ILLUMINATION);
    expect_field(bad_bright, SYMLINE_CFG_BRIGHT_SIGMA10);
    expect_field(bad_ridge, SYMLINE_CFG_RIDGE_SIGMA10);
    expect_field(bad_side, SYMLINE_CFG_SIDE_SIGMA10);
    expect_field(bad_adist, SYMLINE_CFG_A_DISTANCE);
    expect_field(bad_cpct, SYMLINE_CFG_CONTRAST_PCT);
    expect_field(bad_cmin, SYMLINE_CFG_CONTRAST_MIN);
    expect_field(bad_asym, SYMLINE_CFG_CONTRAST_ASYM_PCT);
    expect_field(bad_minlen, SYMLINE_CFG_MIN_LENGTH);
    expect_field(bad_curve, SYMLINE_CFG_CURVE_DEV_Q8);
    expect_field(bad_bend, SYMLINE_CFG_CURVE_BEND_Q8);
    expect_field(bad_mdev, SYMLINE_CFG_MERGE_DEV_Q8);
    expect_field(bad_fmode, SYMLINE_CFG_FIELD_BOUNDARY);
    expect_field(bad_fmargin, SYMLINE_CFG_FIELD_MARGIN);
    expect_field(bad_two, SYMLINE_CFG_LEVELS); /* the first one, in declaration order */
    /* symline_detect() refuses exactly what the check names */
    symline_config_default(&c);
    c.side_sigma10 = 150;
    assert_int_equal(symline_detect(&img, &c, ws, sizeof ws, &r), SYMLINE_ERR_CONFIG);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_workspace_macro_bounds_the_query),
        cmocka_unit_test(test_points_needed_is_exact),
        cmocka_unit_test(test_more_room_same_result),
        cmocka_unit_test(test_config_check_names_the_field),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}

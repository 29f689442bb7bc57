/* SPDX-License-Identifier: Apache-2.0 */
/*
 * Argument checking and memory discipline of the operator and extrema API:
 * every bad argument gets its specific status and nothing is written; static
 * buffers sized by the workspace queries are enough; nothing is written
 * outside the buffers given.
 */
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdio.h>
#include <string.h>

#include <cmocka.h>

#include "symline/extrema.h"
#include "symline/symmetry.h"
#include "testutil.h"

#define W 37u
#define H 23u

static uint8_t pixels[W * H];
/* Static buffers, as firmware would have them. */
static uint8_t out_static[W * H];
static uint8_t ws_static[2048];

static symline_image make_image(void)
{
    symline_image img;
    uint32_t i, s = 99u;
    for (i = 0; i < W * H; i++) {
        pixels[i] = (uint8_t)tu_rand(&s);
    }
    img.width = W;
    img.height = H;
    img.stride = W;
    img.data = pixels;
    return img;
}

typedef symline_status (*frame_fn)(const symline_image *, symline_axis, uint32_t, uint8_t *,
                                   uint32_t, size_t, void *, size_t);
typedef size_t (*ws_fn)(uint32_t, uint32_t, symline_axis, uint32_t);

static void check_errors(frame_fn fn, ws_fn wsq)
{
    symline_image img = make_image(), bad;
    const size_t ws = wsq(W, H, SYMLINE_AXIS_HORIZONTAL, 3);
    memset(out_static, 0x5a, sizeof out_static);
    assert_true(ws > 0 && ws <= sizeof ws_static);

    assert_int_equal(
        fn(NULL, SYMLINE_AXIS_HORIZONTAL, 3, out_static, W, sizeof out_static, ws_static, ws),
        SYMLINE_ERR_NULL);
    bad = img;
    bad.data = NULL;
    assert_int_equal(
        fn(&bad, SYMLINE_AXIS_HORIZONTAL, 3, out_static, W, sizeof out_static, ws_static, ws),
        SYMLINE_ERR_NULL);
    assert_int_equal(
        fn(&img, SYMLINE_AXIS_HORIZONTAL, 3, NULL, W, sizeof out_static, ws_static, ws),
        SYMLINE_ERR_NULL);
    assert_int_equal(
        fn(&img, SYMLINE_AXIS_HORIZONTAL, 3, out_static, W, sizeof out_static, NULL, ws),
        SYMLINE_ERR_NULL);
    bad = img;
    bad.width = 0;
    assert_int_equal(
        fn(&bad, SYMLINE_AXIS_HORIZONTAL, 3, out_static, W, sizeof out_static, ws_static, ws),
        SYMLINE_ERR_SIZE);
    bad = img;
    bad.height = 0;
    assert_int_equal(
        fn(&bad, SYMLINE_AXIS_HORIZONTAL, 3, out_static, W, sizeof out_static, ws_static, ws),
        SYMLINE_ERR_SIZE);
    bad = img;
    bad.width = 65536;
    bad.stride = 65536;
    assert_int_equal(
        fn(&bad, SYMLINE_AXIS_HORIZONTAL, 3, out_static, W, sizeof out_static, ws_static, ws),
        SYMLINE_ERR_SIZE);
    bad = img;
    bad.height = 65536;
    assert_int_equal(
        fn(&bad, SYMLINE_AXIS_VERTICAL, 3, out_static, W, sizeof out_static, ws_static, ws),
        SYMLINE_ERR_SIZE);
    bad = img;
    bad.stride = W - 1;
    assert_int_equal(
        fn(&bad, SYMLINE_AXIS_HORIZONTAL, 3, out_static, W, sizeof out_static, ws_static, ws),
        SYMLINE_ERR_STRIDE);
    assert_int_equal(
        fn(&img, SYMLINE_AXIS_HORIZONTAL, 3, out_static, W - 1, sizeof out_static, ws_static, ws),
        SYMLINE_ERR_STRIDE);
    assert_int_equal(
        fn(&img, SYMLINE_AXIS_HORIZONTAL, 0, out_static, W, sizeof out_static, ws_static, ws),
        SYMLINE_ERR_RADIUS);
    assert_int_equal(
        fn(&img, SYMLINE_AXIS_HORIZONTAL, 256, out_static, W, sizeof out_static, ws_static, ws),
        SYMLINE_ERR_RADIUS);
    assert_int_equal(fn(&img, (symline_axis)7, 3, out_static, W, sizeof out_static, ws_static, ws),
                     SYMLINE_ERR_AXIS);
    assert_int_equal(fn(&img, SYMLINE_AXIS_HORIZONTAL, 3, out_static, W, W * H - 1, ws_static, ws),
                     SYMLINE_ERR_BUFFER);
    assert_int_equal(fn(&img, SYMLINE_AXIS_HORIZONTAL, 3, out_static, W + 1, W * H, ws_static, ws),
                     SYMLINE_ERR_BUFFER);
    assert_int_equal(
        fn(&img, SYMLINE_AXIS_HORIZONTAL, 3, out_static, W, sizeof out_static, ws_static, 16),
        SYMLINE_ERR_BUFFER);
    /* a huge stride whose plane size would wrap 32 bits is a too-small buffer, not a wrap */
    assert_int_equal(fn(&img, SYMLINE_AXIS_HORIZONTAL, 3, out_static, 0xFFFFFFFFu,
                        sizeof out_static, ws_static, ws),
                     SYMLINE_ERR_BUFFER);
    /* no failing call wrote anything */
    {
        size_t i;
        for (i = 0; i < sizeof out_static; i++) {
            assert_int_equal(out_static[i], 0x5a);
        }
    }
    /* and the static buffers are enough, for both axes, at any workspace alignment */
    assert_int_equal(
        fn(&img, SYMLINE_AXIS_HORIZONTAL, 3, out_static, W, sizeof out_static, ws_static, ws),
        SYMLINE_OK);
    assert_true(wsq(W, H, SYMLINE_AXIS_VERTICAL, 3) + 1 <= sizeof ws_static);
    assert_int_equal(fn(&img, SYMLINE_AXIS_VERTICAL, 3, out_static, W, sizeof out_static,
                        ws_static + 1, wsq(W, H, SYMLINE_AXIS_VERTICAL, 3)),
                     SYMLINE_OK);
}

static void test_symmetry_errors(void **state)
{
    (void)state;
    check_errors(symline_symmetry, symline_symmetry_workspace_size);
}

static void test_extrema_errors(void **state)
{
    (void)state;
    check_errors(symline_extrema, symline_extrema_workspace_size);
}

static void test_workspace_queries(void **state)
{
    (void)state;
    assert_int_equal(symline_symmetry_workspace_size(0, 10, SYMLINE_AXIS_VERTICAL, 3), 0);
    assert_int_equal(symline_symmetry_workspace_size(10, 65536, SYMLINE_AXIS_VERTICAL, 3), 0);
    assert_int_equal(symline_symmetry_workspace_size(10, 10, (symline_axis)2, 3), 0);
    assert_int_equal(symline_extrema_workspace_size(10, 10, SYMLINE_AXIS_VERTICAL, 0), 0);
    assert_int_equal(symline_extrema_workspace_size(10, 10, SYMLINE_AXIS_VERTICAL, 256), 0);
    /* O(width): the height and the radius do not change the working memory */
    assert_int_equal(symline_extrema_workspace_size(320, 240, SYMLINE_AXIS_HORIZONTAL, 3),
                     symline_extrema_workspace_size(320, 65535, SYMLINE_AXIS_HORIZONTAL, 255));
    assert_true(symline_extrema_workspace_size(320, 240, SYMLINE_AXIS_HORIZONTAL, 3) <= 20u * 320u);
    assert_int_equal(symline_colrun_buffer_size(0), 0);
    assert_int_equal(symline_colrun_buffer_size(65536), 0);
}

static void test_row_primitives_errors(void **state)
{
    uint8_t q[8] = {0};
    uint32_t E[8];
    uint8_t map[8];
    const uint8_t *rows[7] = {q, q, q, q, q, q, q};
    symline_colrun cr;
    uint8_t buf[256];
    symline_extremum ev[8];
    uint32_t count = 99;
    (void)state;
    assert_int_equal(symline_energy_row(NULL, 8, 3, E), SYMLINE_ERR_NULL);
    assert_int_equal(symline_energy_row(q, 8, 3, NULL), SYMLINE_ERR_NULL);
    assert_int_equal(symline_energy_row(q, 0, 3, E), SYMLINE_ERR_SIZE);
    assert_int_equal(symline_energy_row(q, 65536, 3, E), SYMLINE_ERR_SIZE);
    assert_int_equal(symline_energy_row(q, 8, 0, E), SYMLINE_ERR_RADIUS);
    assert_int_equal(symline_energy_across(NULL, 3, 8, E), SYMLINE_ERR_NULL);
    assert_int_equal(symline_energy_across(rows, 3, 0, E), SYMLINE_ERR_SIZE);
    assert_int_equal(symline_energy_across(rows, 256, 8, E), SYMLINE_ERR_RADIUS);
    rows[3] = NULL;
    assert_int_equal(symline_energy_across(rows, 3, 8, E), SYMLINE_ERR_NULL);
    assert_int_equal(symline_s8_row(E, 8, 0, map), SYMLINE_ERR_RADIUS);
    E[0] = symline_emax(3) + 1;
    assert_int_equal(symline_s8_row(E, 1, 3, map), SYMLINE_ERR_RANGE);
    assert_int_equal(symline_extrema_row(NULL, 8, map), SYMLINE_ERR_NULL);
    assert_int_equal(symline_extrema_row(E, 0, map), SYMLINE_ERR_SIZE);
    assert_int_equal(symline_colrun_init(&cr, 8, buf, 8), SYMLINE_ERR_BUFFER);
    assert_int_equal(symline_colrun_init(&cr, 0, buf, sizeof buf), SYMLINE_ERR_SIZE);
    assert_int_equal(symline_colrun_init(&cr, 8, buf, sizeof buf), SYMLINE_OK);
    assert_int_equal(symline_colrun_push(&cr, E, ev, 7, &count), SYMLINE_ERR_BUFFER);
    assert_int_equal(symline_colrun_push(&cr, E, ev, 8, &count), SYMLINE_OK);
    assert_int_equal(count, 0);
    {
        symline_image img = {8, 1, 8, q};
        assert_int_equal(symline_energy_across_image(&img, 1, 3, E), SYMLINE_ERR_RANGE);
    }
    assert_int_equal(symline_emax(0), 0);
    assert_int_equal(symline_emax(256), 0);
    assert_int_equal(symline_emax(255), 65025u * 32640u);
}

static void test_status_strings(void **state)
{
    int s;
    (void)state;
    for (s = SYMLINE_ERR_CONFIG; s <= SYMLINE_OK; s++) {
        const char *t = symline_status_str((symline_status)s);
        assert_non_null(t);
        assert_string_not_equal(t, "unknown status");
    }
    assert_string_equal(symline_status_str((symline_status)42), "unknown status");
}

/* The version string spells the three numbers. */
static void test_version(void **state)
{
    char spelled[32];
    (void)state;
    snprintf(spelled, sizeof spelled, "%d.%d.%d", SYMLINE_VERSION_MAJOR, SYMLINE_VERSION_MINOR,
             SYMLINE_VERSION_PATCH);
    assert_string_equal(spelled, SYMLINE_VERSION_STRING);
}

/* Largest accepted sizes: 65535 wide (one row) and 65535 high (one column). */
static void test_extreme_sizes(void **state)
{
    static uint8_t line[65535];
    static uint8_t out[65535];
    static uint8_t ws[65535 * 20 + 64];
    symline_image img;
    uint32_t i, s = 7;
    size_t need;
    (void)state;
    for (i = 0; i < 65535; i++) {
        line[i] = (uint8_t)tu_rand(&s);
    }
    img.width = 65535;
    img.height = 1;
    img.stride = 65535;
    img.data = line;
    need = symline_extrema_workspace_size(65535, 1, SYMLINE_AXIS_HORIZONTAL, 255);
    assert_true(need > 0 && need <= sizeof ws);
    assert_int_equal(
        symline_extrema(&img, SYMLINE_AXIS_HORIZONTAL, 255, out, 65535, sizeof out, ws, need),
        SYMLINE_OK);
    for (i = 0; i < 65535; i++) {
        assert_int_equal(out[i], 0); /* a one-row image has only border runs along columns */
    }
    img.width = 1;
    img.height = 65535;
    img.stride = 1;
    need = symline_extrema_workspace_size(1, 65535, SYMLINE_AXIS_HORIZONTAL, 255);
    assert_int_equal(
        symline_extrema(&img, SYMLINE_AXIS_HORIZONTAL, 255, out, 1, sizeof out, ws, need),
        SYMLINE_OK);
    need = symline_symmetry_workspace_size(1, 65535, SYMLINE_AXIS_HORIZONTAL, 255);
    assert_int_equal(
        symline_symmetry(&img, SYMLINE_AXIS_HORIZONTAL, 255, out, 1, sizeof out, ws, need),
        SYMLINE_OK);
    /* spot-check against the formula at the centre and at the border */
    {
        uint32_t e0 = tu_energy_direct(line, 1, 65535, 0, 255);
        uint32_t ec = tu_energy_direct(line, 1, 65535, 30000, 255);
        uint32_t em = symline_emax(255);
        assert_int_equal(out[0], (uint8_t)((510ull * (em - e0) + em) / (2ull * em)));
        assert_int_equal(out[30000], (uint8_t)((510ull * (em - ec) + em) / (2ull * em)));
    }
}

/* The documented in-place case: vertical axis, output over the input, same stride. */
static void test_symmetry_in_place_vertical(void **state)
{
    static uint8_t buf[W * H], ref[W * H];
    symline_image img = make_image();
    const size_t ws = symline_symmetry_workspace_size(W, H, SYMLINE_AXIS_VERTICAL, 5);
    (void)state;
    assert_int_equal(
        symline_symmetry(&img, SYMLINE_AXIS_VERTICAL, 5, ref, W, sizeof ref, ws_static, ws),
        SYMLINE_OK);
    memcpy(buf, pixels, sizeof buf);
    img.data = buf;
    assert_int_equal(
        symline_symmetry(&img, SYMLINE_AXIS_VERTICAL, 5, buf, W, sizeof buf, ws_static, ws),
        SYMLINE_OK);
    assert_memory_equal(buf, ref, sizeof buf);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_symmetry_errors),   cmocka_unit_test(test_extrema_errors),
        cmocka_unit_test(test_workspace_queries), cmocka_unit_test(test_row_primitives_errors),
        cmocka_unit_test(test_status_strings),    cmocka_unit_test(test_version),
        cmocka_unit_test(test_extreme_sizes),     cmocka_unit_test(test_symmetry_in_place_vertical),
    };
    return cmocka_run_group_tests_name("core_api", tests, NULL, NULL);
}

/* SPDX-License-Identifier: Apache-2.0 */
/*
 * The profiled core (SYMLINE_PROFILE, include/symline/profile.h): the stage
 * marks of a default detection on a bundled real frame. Every stage of the
 * default pipeline is entered, the detection starts in setup and ends with
 * SYMLINE_STAGE_NONE, no mark is out of range, and the stage names are
 * distinct. (detect_golden_profiled checks that the marks change no output.)
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
#include "symline/profile.h"

static uint32_t g_calls, g_bad;
static uint32_t g_entered[SYMLINE_STAGE_COUNT];
static symline_stage g_first, g_last;

void symline_profile_mark(symline_stage stage)
{
    if ((unsigned)stage >= (unsigned)SYMLINE_STAGE_COUNT) {
        g_bad++;
        return;
    }
    if (g_calls == 0u) {
        g_first = stage;
    }
    g_last = stage;
    g_calls++;
    g_entered[stage]++;
}

static void default_detection_marks_every_stage(void **state)
{
    char path[1024], err[256];
    imgio_gray g;
    symline_image img;
    symline_config cfg;
    symline_result r;
    size_t wsn;
    void *ws;
    uint32_t k;
    (void)state;
    snprintf(path, sizeof path, "%s/%s", SYMLINE_TEST_DATA,
             "msl_20250403_r4_cam3_20250403_221433.pgm");
    assert_int_equal(imgio_read_gray(path, &g, err, sizeof err), 0);
    img.width = g.width;
    img.height = g.height;
    img.stride = g.width;
    img.data = g.px;
    symline_config_default(&cfg);
    wsn = symline_detect_workspace_size(g.width, g.height, &cfg);
    ws = malloc(wsn);
    memset(&r, 0, sizeof r);
    r.segment_cap = 8192u;
    r.point_cap = 2u * g.width * g.height + 1024u;
    r.segments = (symline_segment *)malloc(r.segment_cap * sizeof(symline_segment));
    r.points = (symline_point *)malloc(r.point_cap * sizeof(symline_point));
    assert_non_null(ws);
    assert_int_equal(symline_detect(&img, &cfg, ws, wsn, &r), SYMLINE_OK);
    assert_true(r.segment_count > 0u);
    assert_int_equal(g_bad, 0);
    assert_int_equal(g_first, SYMLINE_STAGE_SETUP);
    assert_int_equal(g_last, SYMLINE_STAGE_NONE);
    assert_int_equal(g_entered[SYMLINE_STAGE_NONE], 1);
    for (k = 1; k < SYMLINE_STAGE_COUNT; k++) {
        if (g_entered[k] == 0u) {
            fail_msg("stage %s was never entered", symline_stage_name((symline_stage)k));
        }
    }
    /* The filter's byte test is marked per grid row: at least once per row
     * of the full-resolution passes (two axes); the energies and extrema
     * only where it leaves candidates. */
    assert_true(g_entered[SYMLINE_STAGE_FILTER] >= 2u * g.height);
    free(ws);
    free(r.segments);
    free(r.points);
    imgio_free(&g);
}

static void a_rejected_call_still_ends_with_none(void **state)
{
    symline_config cfg;
    symline_result r;
    uint8_t ws[16];
    (void)state;
    g_calls = 0u;
    symline_config_default(&cfg);
    memset(&r, 0, sizeof r);
    assert_int_equal(symline_detect(NULL, &cfg, ws, sizeof ws, &r), SYMLINE_ERR_NULL);
    assert_int_equal(g_first, SYMLINE_STAGE_SETUP);
    assert_int_equal(g_last, SYMLINE_STAGE_NONE);
    assert_int_equal(g_calls, 2);
}

static void stage_names_are_distinct(void **state)
{
    uint32_t i, j;
    (void)state;
    for (i = 0; i < SYMLINE_STAGE_COUNT; i++) {
        const char *a = symline_stage_name((symline_stage)i);
        assert_non_null(a);
        assert_string_not_equal(a, "?");
        for (j = 0; j < i; j++) {
            assert_string_not_equal(a, symline_stage_name((symline_stage)j));
        }
    }
    assert_string_equal(symline_stage_name(SYMLINE_STAGE_OPERATOR), "operator");
    assert_string_equal(symline_stage_name(SYMLINE_STAGE_COUNT), "?");
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(default_detection_marks_every_stage),
        cmocka_unit_test(a_rejected_call_still_ends_with_none),
        cmocka_unit_test(stage_names_are_distinct),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}

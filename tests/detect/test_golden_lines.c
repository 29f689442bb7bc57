/* SPDX-License-Identifier: Apache-2.0 */
/*
 * Golden JSON of the bundled real frames: symline_detect() + the JSON
 * writer of docs/format.md must reproduce tests/golden/lines/NAME.json byte for byte
 * (regenerate with tests/golden/lines/regenerate.sh after a reviewed change).
 * Two frames also darkened by 40 gray levels (NAME.m40.json): on them the
 * field boundary's first column scan finds carpet in fewer than half of the
 * columns and scans again above the fisheye's black rim, a path the frames
 * as they are do not take; every build that runs this test (SIMD, portable,
 * -Os, AArch64, and the Cortex-M builds' own golden program) must agree.
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
#include "segjson.h"
#include "symline/detect.h"

static char *slurp(FILE *f, size_t *len)
{
    char *buf;
    long n;
    fseek(f, 0, SEEK_END);
    n = ftell(f);
    fseek(f, 0, SEEK_SET);
    buf = (char *)malloc((size_t)n + 1u);
    *len = fread(buf, 1, (size_t)n, f);
    buf[*len] = '\0';
    return buf;
}

/* What a frame goes through before the detection, and its golden file's suffix. */
enum variant {
    AS_IS,
    PAPER,
    DARK40
};
static const char *const SUFFIX[3] = {"", ".paper", ".m40"};

static void check_frame(const char *name, enum variant v)
{
    char path[1024], err[256];
    imgio_gray g;
    symline_image img;
    symline_config cfg;
    symline_result r;
    symline_intersection_config icfg;
    symline_intersection items[256];
    symline_intersection_result ix = {items, 256u, 0u, 0u};
    size_t wsn, got_len, want_len;
    void *ws;
    FILE *out, *want;
    char *got_s, *want_s;
    snprintf(path, sizeof path, "%s/%s.pgm", SYMLINE_TEST_DATA, name);
    assert_int_equal(imgio_read_gray(path, &g, err, sizeof err), 0);
    img.width = g.width;
    img.height = g.height;
    img.stride = g.width;
    img.data = g.px;
    if (v == DARK40) { /* what `symline-bright --add -40` writes */
        size_t i;
        for (i = 0; i < (size_t)g.width * g.height; i++) {
            g.px[i] = (uint8_t)(g.px[i] > 40u ? g.px[i] - 40u : 0u);
        }
    }
    symline_config_default(&cfg);
    if (v == PAPER) { /* what `symline lines --filter paper` sets */
        cfg.filter = SYMLINE_FILTER_PAPER;
        cfg.illumination = 100u;
        cfg.adaptive = false;
    }
    wsn = symline_detect_workspace_size(g.width, g.height, &cfg);
    ws = malloc(wsn);
    memset(&r, 0, sizeof r);
    r.segment_cap = 8192u;
    r.point_cap = 2u * g.width * g.height + 1024u;
    r.segments = (symline_segment *)malloc(r.segment_cap * sizeof(symline_segment));
    r.points = (symline_point *)malloc(r.point_cap * sizeof(symline_point));
    assert_int_equal(symline_detect(&img, &cfg, ws, wsn, &r), SYMLINE_OK);
    assert_true(r.segment_count > 0u);
    out = tmpfile();
    assert_non_null(out);
    symline_intersection_config_default(&icfg);
    assert_int_equal(symline_intersections(&r, &icfg, &ix), SYMLINE_OK);
    assert_int_equal(ix.truncated, 0);
    assert_int_equal(segjson_write_ix(out, g.width, g.height, &r, &ix), 0);
    got_s = slurp(out, &got_len);
    snprintf(path, sizeof path, "%s/lines/%s%s.json", SYMLINE_GOLDEN, name, SUFFIX[v]);
    want = fopen(path, "rb");
    assert_non_null(want);
    want_s = slurp(want, &want_len);
    if (got_len != want_len || memcmp(got_s, want_s, got_len) != 0) {
        fprintf(stderr, "%s differs from the detector's output\n", path);
    }
    assert_int_equal(got_len, want_len);
    assert_memory_equal(got_s, want_s, got_len);
    fclose(out);
    fclose(want);
    free(got_s);
    free(want_s);
    free(ws);
    free(r.segments);
    free(r.points);
    imgio_free(&g);
}

static void frame_20190606(void **state)
{
    (void)state;
    check_frame("msl_20190606_r2_cam0_20190606_204340", AS_IS);
}

static void frame_20240719(void **state)
{
    (void)state;
    check_frame("msl_20240719_r5_cam3_20240719_090755", AS_IS);
}

static void frame_20240719_dark40(void **state)
{
    (void)state;
    check_frame("msl_20240719_r5_cam3_20240719_090755", DARK40);
}

static void frame_20250403(void **state)
{
    (void)state;
    check_frame("msl_20250403_r4_cam3_20250403_221433", AS_IS);
}

static void frame_20250403_dark40(void **state)
{
    (void)state;
    check_frame("msl_20250403_r4_cam3_20250403_221433", DARK40);
}

static void frame_20250403_paper(void **state)
{
    (void)state;
    check_frame("msl_20250403_r4_cam3_20250403_221433", PAPER);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(frame_20190606),        cmocka_unit_test(frame_20240719),
        cmocka_unit_test(frame_20240719_dark40), cmocka_unit_test(frame_20250403),
        cmocka_unit_test(frame_20250403_dark40), cmocka_unit_test(frame_20250403_paper),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}

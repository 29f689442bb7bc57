/* SPDX-License-Identifier: Apache-2.0 */
/*
 * The merge of collinear line pieces (lib/merge.c).
 */
#include <setjmp.h>
#include <stdarg.h>
#include <stdbool.h>
#include <stddef.h>
#include <stdint.h>
#include <string.h>

#include <cmocka.h>

#include "merge.h"

static void merge_collinear(void **state)
{
    symline_point pts[64];
    symline_segment segs[4];
    symline_result r;
    uint32_t i;
    (void)state;
    memset(pts, 0, sizeof(pts)); /* no sub-pixel offsets */
    /* Two pieces of y = 5 (x 0..9 and 20..29) with a curve between them in storage. */
    for (i = 0; i < 10u; i++) {
        pts[i].x = (uint16_t)i;
        pts[i].y = 5;
        pts[13u + i].x = (uint16_t)(20u + i);
        pts[13u + i].y = 5;
    }
    for (i = 0; i < 3u; i++) {
        pts[10u + i].x = 50;
        pts[10u + i].y = (uint16_t)(40u + i);
    }
    memset(segs, 0, sizeof segs);
    segs[0].x1 = 9 * 256;
    segs[0].y0 = segs[0].y1 = 5 * 256;
    segs[0].count = 10;
    segs[1].x0 = segs[1].x1 = 50 * 256;
    segs[1].y0 = 40 * 256;
    segs[1].y1 = 42 * 256;
    segs[1].first = 10;
    segs[1].count = 3;
    segs[1].kind = SYMLINE_KIND_CURVE;
    segs[2].x0 = 20 * 256;
    segs[2].x1 = 29 * 256;
    segs[2].y0 = segs[2].y1 = 5 * 256;
    segs[2].first = 13;
    segs[2].count = 10;
    r.segments = segs;
    r.segment_cap = 4;
    r.segment_count = 3;
    r.points = pts;
    r.point_cap = 64;
    r.point_count = 23;
    r.truncated = false;
    symline_i_merge(&r, 8, 640, 512, 64, 64, NULL, 0); /* gap 11 px > 8: no merge */
    assert_int_equal(r.segment_count, 3);
    assert_false(segs[0].merged);
    symline_i_merge(&r, 12, 640, 512, 64, 64, NULL, 0);
    assert_int_equal(r.segment_count, 2);
    assert_int_equal(segs[0].x0, 0);
    assert_int_equal(segs[0].x1, 29 * 256);
    assert_int_equal(segs[0].count, 20);
    for (i = 0; i < 20u; i++) {
        assert_int_equal(pts[i].y, 5); /* the pieces' points are contiguous now */
    }
    assert_int_equal(segs[1].first, 20);
    assert_int_equal(pts[20].x, 50);
    /* The joined line says so; the curve was not touched. */
    assert_true(segs[0].merged);
    assert_false(segs[1].merged);
    assert_int_equal(segs[1].kind, SYMLINE_KIND_CURVE);
}

static void merge_keeps_bent_joins_apart(void **state)
{
    symline_point pts[64];
    symline_segment segs[2];
    symline_result r;
    uint32_t i;
    (void)state;
    memset(pts, 0, sizeof(pts)); /* no sub-pixel offsets */
    /* Two pieces 4 px apart, the second 3 px lower: ends not on each other's line. */
    for (i = 0; i < 10u; i++) {
        pts[i].x = (uint16_t)i;
        pts[i].y = 5;
        pts[10u + i].x = (uint16_t)(14u + i);
        pts[10u + i].y = 8;
    }
    memset(segs, 0, sizeof segs);
    segs[0].x1 = 9 * 256;
    segs[0].y0 = segs[0].y1 = 5 * 256;
    segs[0].count = 10;
    segs[1].x0 = 14 * 256;
    segs[1].x1 = 23 * 256;
    segs[1].y0 = segs[1].y1 = 8 * 256;
    segs[1].first = 10;
    segs[1].count = 10;
    r.segments = segs;
    r.segment_cap = 2;
    r.segment_count = 2;
    r.points = pts;
    r.point_cap = 64;
    r.point_count = 20;
    r.truncated = false;
    symline_i_merge(&r, 12, 640, 512, 64, 64, NULL, 0); /* 3 px off > 2.5 px */
    assert_int_equal(r.segment_count, 2);
    symline_i_merge(&r, 12, 1024, 5120, 64, 64, NULL, 0); /* 4 px allowed; the joined piece (1.2 px off its chord) is no curve */
    assert_int_equal(r.segment_count, 1);
    assert_true(segs[0].merged);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(merge_collinear),
        cmocka_unit_test(merge_keeps_bent_joins_apart),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}

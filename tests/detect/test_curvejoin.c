/* SPDX-License-Identifier: Apache-2.0 */
/*
 * Curve continuation (lib/curvejoin.c): a line that continues a curve
 * smoothly becomes a curve; one that leaves it across, or a merged line,
 * stays a line.
 */
#include <setjmp.h>
#include <stdarg.h>
#include <stdbool.h>
#include <stddef.h>
#include <stdint.h>
#include <string.h>

#include <cmocka.h>

#include "curvejoin.h"

/* A segment over pts[first .. first+count-1] with the chord of its end points. */
static void seg_of(symline_segment *s, const symline_point *pts, uint32_t first, uint32_t count,
                   symline_kind kind)
{
    memset(s, 0, sizeof *s);
    s->first = first;
    s->count = count;
    s->kind = (uint8_t)kind;
    s->x0 = pts[first].x * 256;
    s->y0 = pts[first].y * 256;
    s->x1 = pts[first + count - 1u].x * 256;
    s->y1 = pts[first + count - 1u].y * 256;
}

static void line_continuing_a_curve_is_a_curve(void **state)
{
    symline_point pts[128];
    symline_segment segs[4];
    symline_result r;
    uint32_t i, n = 0u;
    (void)state;
    memset(pts, 0, sizeof(pts)); /* no sub-pixel offsets */
    /* Curve: y = 200 - x^2/80 for x = 0..40 (leaves at 45 degrees up-right). */
    for (i = 0; i <= 40u; i++, n++) {
        pts[n].x = (uint16_t)(10u + i);
        pts[n].y = (uint16_t)(200u - (i * i + 40u) / 80u);
    }
    seg_of(&segs[0], pts, 0, 41, SYMLINE_KIND_CURVE);
    /* Line 1 continues it in its direction (up-right from (51, 179)). */
    for (i = 0; i < 20u; i++, n++) {
        pts[n].x = (uint16_t)(51u + i);
        pts[n].y = (uint16_t)(179u - i);
    }
    seg_of(&segs[1], pts, 41, 20, SYMLINE_KIND_LINE);
    /* Line 2 leaves the curve's start across it (straight down from (10, 201)). */
    for (i = 0; i < 20u; i++, n++) {
        pts[n].x = 10;
        pts[n].y = (uint16_t)(201u + i);
    }
    seg_of(&segs[2], pts, 61, 20, SYMLINE_KIND_LINE);
    /* Line 3 continues the curve too, but it was merged: its
     * points run back and forth, no polyline through them, so it stays a line. */
    for (i = 0; i < 20u; i++, n++) {
        pts[n].x = (uint16_t)(i < 10u ? 9u - i : i - 10u + 0u);
        pts[n].y = 200;
    }
    seg_of(&segs[3], pts, 81, 20, SYMLINE_KIND_LINE);
    segs[3].x0 = 9 * 256;
    segs[3].x1 = 0;
    segs[3].merged = true;
    r.segments = segs;
    r.segment_cap = 4;
    r.segment_count = 4;
    r.points = pts;
    r.point_cap = 128;
    r.point_count = n;
    r.truncated = false;
    symline_i_curve_join(&r);
    assert_int_equal(segs[1].kind, SYMLINE_KIND_CURVE);
    assert_int_equal(segs[2].kind, SYMLINE_KIND_LINE);
    assert_int_equal(segs[3].kind, SYMLINE_KIND_LINE);
    assert_true(segs[3].merged);
    assert_int_equal(r.segment_count, 4);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(line_continuing_a_curve_is_a_curve),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}

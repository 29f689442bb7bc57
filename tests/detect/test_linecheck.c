/* SPDX-License-Identifier: Apache-2.0 */
/*
 * The field-line checks (linecheck.c) and what they do in symline_detect():
 * a wide piece high in the field (a post standing on the carpet) is dropped,
 * a painted line beside it is kept; a painted line whose ridge wanders on the
 * turf and is cut by gaps comes out as one straight segment.
 */
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <stdlib.h>
#include <string.h>

#include <cmocka.h>

#include "linecheck.h"
#include "symline/detect.h"
#include "testutil.h"

#define W 320u
#define H 240u
#define WALL_ROWS 60u

/* A piece of n points at grid row y, columns x0.. */
static void row_piece(symline_point *q, uint32_t n, uint32_t x0, uint32_t y)
{
    uint32_t i;
    memset(q, 0, n * sizeof *q);
    for (i = 0; i < n; i++) {
        q[i].x = (uint16_t)(x0 + i);
        q[i].y = (uint16_t)y;
    }
}

static void too_wide_by_row(void **state)
{
    uint16_t rows[64];
    symline_point q[16];
    uint32_t i;
    (void)state;
    for (i = 0; i < 64u; i++) {
        rows[i] = 20u; /* boundary at grid row 20 of 100 */
    }
    /* The upper quarter of the field is rows 20..39 (80 / 4 = 20). */
    row_piece(q, 16, 10, 30);
    assert_true(symline_i_linecheck_too_wide(rows, 1u, 100u, q, 16));
    row_piece(q, 16, 10, 39);
    assert_true(symline_i_linecheck_too_wide(rows, 2u, 100u, q, 16));
    row_piece(q, 16, 10, 40);
    assert_false(symline_i_linecheck_too_wide(rows, 1u, 100u, q, 16));
    /* Above the boundary: not paint either. */
    row_piece(q, 16, 10, 5);
    assert_true(symline_i_linecheck_too_wide(rows, 3u, 100u, q, 16));
    /* Full resolution: no width to judge. */
    row_piece(q, 16, 10, 30);
    assert_false(symline_i_linecheck_too_wide(rows, 0u, 100u, q, 16));
    /* A boundary at the top of the frame says nothing of the distance. */
    for (i = 0; i < 64u; i++) {
        rows[i] = 0u;
    }
    row_piece(q, 16, 10, 3);
    assert_false(symline_i_linecheck_too_wide(rows, 1u, 100u, q, 16));
    assert_false(symline_i_linecheck_too_wide(rows, 1u, 100u, q, 0));
}

/* Carpet grain below row WALL_ROWS, a smooth bright wall above it. */
static uint8_t *field_frame(void)
{
    uint8_t *px = (uint8_t *)malloc((size_t)W * H);
    uint32_t x, y, s = 77u;
    assert_non_null(px);
    for (y = 0; y < H; y++) {
        for (x = 0; x < W; x++) {
            px[y * W + x] =
                y >= WALL_ROWS ? (uint8_t)(80u + tu_rand(&s) % 32u) : (uint8_t)(190u + x / 64u);
        }
    }
    return px;
}

static void fill(uint8_t *px, uint32_t x0, uint32_t x1, uint32_t y0, uint32_t y1, uint8_t v)
{
    uint32_t x, y;
    for (y = y0; y < y1; y++) {
        for (x = x0; x < x1; x++) {
            px[y * W + x] = v;
        }
    }
}

static symline_segment segs[256];
static symline_point pts[4u * W * H];

static void detect(const uint8_t *px, symline_field_mode mode, symline_result *r)
{
    symline_config cfg;
    symline_image img;
    int guards_ok;
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
    r->point_cap = 4u * W * H;
    assert_int_equal(tu_detect_guarded(&img, &cfg, r, &guards_ok), SYMLINE_OK);
    assert_true(guards_ok);
}

/* Segments with both ends inside the box (pixels). */
static uint32_t inside(const symline_result *r, int32_t x0, int32_t x1, int32_t y0, int32_t y1)
{
    uint32_t i, k = 0u;
    for (i = 0; i < r->segment_count; i++) {
        const symline_segment *s = &r->segments[i];
        const int32_t ax = s->x0 / 256, ay = s->y0 / 256, bx = s->x1 / 256, by = s->y1 / 256;
        k += (ax >= x0 && ax <= x1 && bx >= x0 && bx <= x1 && ay >= y0 && ay <= y1 && by >= y0 &&
              by <= y1)
                 ? 1u
                 : 0u;
    }
    return k;
}

/* The longest segment; its length in px. */
static const symline_segment *longest(const symline_result *r, int32_t *len)
{
    const symline_segment *best = NULL;
    uint32_t i;
    *len = 0;
    for (i = 0; i < r->segment_count; i++) {
        const symline_segment *s = &r->segments[i];
        const int32_t dx = (s->x1 - s->x0) / 256, dy = (s->y1 - s->y0) / 256;
        const int32_t l = abs(dx) > abs(dy) ? abs(dx) : abs(dy);
        if (l > *len) {
            *len = l;
            best = s;
        }
    }
    return best;
}

static void post_dropped_line_kept(void **state)
{
    symline_result r;
    uint8_t *px = field_frame();
    (void)state;
    /* A post 14 px wide standing on the carpet just below the wall, and a
     * painted line 4 px wide lower in the field, beside it. */
    fill(px, 100, 114, WALL_ROWS, WALL_ROWS + 50u, 225);
    fill(px, 130, 300, 180, 184, 215);
    detect(px, SYMLINE_FIELD_KEEP, &r);
    assert_true(inside(&r, 96, 118, WALL_ROWS - 4, WALL_ROWS + 54) >= 1u); /* found when kept */
    detect(px, SYMLINE_FIELD_DROP, &r);
    assert_true(r.field.count >= 2u);
    assert_int_equal(inside(&r, 96, 118, WALL_ROWS - 4, WALL_ROWS + 54), 0u); /* dropped */
    assert_true(inside(&r, 126, 304, 178, 186) >= 1u);                        /* kept */
    free(px);
}

static void wandering_line_is_one_segment(void **state)
{
    symline_result r;
    uint8_t *px = field_frame();
    const symline_segment *s;
    int32_t len;
    uint32_t x;
    (void)state;
    /* A 3 px painted line along row 150 whose ridge steps by a pixel every
     * 10 px (ragged paint), cut twice by 6 px gaps of carpet (turf noise). */
    for (x = 20; x < 300; x++) {
        const uint32_t y = 149u + (x / 10u) % 2u;
        if ((x >= 110 && x < 116) || (x >= 200 && x < 206)) {
            continue;
        }
        fill(px, x, x + 1u, y, y + 3u, 210);
    }
    detect(px, SYMLINE_FIELD_DROP, &r);
    s = longest(&r, &len);
    assert_non_null(s);
    assert_true(len >= 270);
    assert_int_equal(s->kind, SYMLINE_KIND_LINE);
    assert_int_equal(inside(&r, 10, 310, 140, 160), 1u);
    free(px);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(too_wide_by_row),
        cmocka_unit_test(post_dropped_line_kept),
        cmocka_unit_test(wandering_line_is_one_segment),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}

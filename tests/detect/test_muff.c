/* SPDX-License-Identifier: Apache-2.0 */
/*
 * The Muff-space line finder (the paper's first method): two known lines give two accumulator
 * peaks at the perimeter cells where they cross the border, and two segments
 * over the extent of their points; the perimeter coordinates; the end-to-end
 * call on a drawn frame; argument errors.
 */
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdlib.h>
#include <string.h>

#include <cmocka.h>

#include "muff_internal.h"
#include "symline/muff.h"

#define W 100u
#define H 80u

/* A horizontal line y = 19, x = 10..89, and a vertical one x = 62, y = 5..70.
 * Both cross the border inside perimeter cells (not on a cell boundary, where
 * the votes would split between two neighbouring pairs). */
/* p: room for 200 points */
static uint32_t two_lines(symline_point *p)
{
    uint32_t n = 0, x, y;
    memset(p, 0, 200 * sizeof *p);
    for (x = 10; x <= 89; x++) {
        p[n].x = (uint16_t)x;
        p[n++].y = 19;
    }
    for (y = 5; y <= 70; y++) {
        if (y != 19) {
            p[n].x = 62;
            p[n++].y = (uint16_t)y;
        }
    }
    return n;
}

static void test_perimeter(void **state)
{
    symline_i_perim p;
    uint32_t s, x, y;
    (void)state;
    symline_i_perim_setup(&p, W, H, 4);
    assert_int_equal(p.len, 2u * 99u + 2u * 79u);
    assert_int_equal(p.ncell, 89u);
    assert_int_equal(symline_i_perim_coord(&p, 0, 0), 0u);
    assert_int_equal(symline_i_perim_coord(&p, 99, 20), 119u);
    assert_int_equal(symline_i_perim_coord(&p, 60, 79), 217u);
    assert_int_equal(symline_i_perim_coord(&p, 0, 20), 336u);
    for (s = 0; s < p.len; s++) {
        symline_i_perim_point(&p, s, &x, &y);
        assert_true(x == 0 || y == 0 || x == 99 || y == 79);
        assert_int_equal(symline_i_perim_coord(&p, x, y), s);
    }
}

/* y = 19 crosses the border at (99, 19): s = 118, cell 29, and (0, 19): s = 337,
 * cell 84; x = 62 at (62, 0): s = 62, cell 15, and (62, 79): s = 215, cell 53. */
static void test_two_peaks(void **state)
{
    symline_i_perim p;
    symline_point pts[200];
    uint16_t cx[89], cy[89];
    symline_i_peak peaks[8];
    uint16_t *acc;
    uint32_t n, np;
    int h = 0, v = 0, k;
    (void)state;
    n = two_lines(pts);
    symline_i_perim_setup(&p, W, H, 4);
    symline_i_cell_centres(&p, cx, cy);
    acc = (uint16_t *)calloc((size_t)symline_i_pair_count(&p), sizeof(uint16_t));
    assert_non_null(acc);
    symline_i_muff_vote(&p, cx, cy, pts, n, acc);
    np = symline_i_muff_peaks(&p, acc, 24, 2, peaks, 8);
    assert_true(np >= 2u);
    for (k = 0; k < 2; k++) {
        h |= peaks[k].i == 29 && peaks[k].j == 84;
        v |= peaks[k].i == 15 && peaks[k].j == 53;
    }
    if (!h || !v) {
        fail_msg("strongest peaks (%u,%u) %u votes and (%u,%u) %u votes; want (29,84) and (15,53)",
                 peaks[0].i, peaks[0].j, peaks[0].votes, peaks[1].i, peaks[1].j, peaks[1].votes);
    }
    /* every other peak is much weaker */
    for (k = 2; k < (int)np; k++) {
        assert_true(peaks[k].votes * 2u < peaks[1].votes);
    }
    free(acc);
}

static void near_q8(int32_t got, int32_t want_px, int32_t tol_q8)
{
    const int32_t d = got - want_px * 256;
    if (d > tol_q8 || d < -tol_q8) {
        fail_msg("coordinate %.2f px, want %d", (double)got / 256.0, want_px);
    }
}

static void test_two_segments(void **state)
{
    symline_muff_config c;
    symline_point pts[200];
    symline_segment segs[8];
    symline_result r;
    uint16_t *acc;
    void *ws;
    size_t acc_size, ws_size;
    uint32_t n, k;
    int h = -1, v = -1;
    (void)state;
    symline_muff_config_default(&c);
    c.cell = 4;
    n = two_lines(pts);
    acc_size = symline_muff_accumulator_size(W, H, &c);
    ws_size = symline_muff_workspace_size(W, H, &c);
    assert_int_equal(acc_size, 89u * 88u / 2u * 2u);
    acc = (uint16_t *)malloc(acc_size);
    ws = malloc(ws_size);
    memset(&r, 0, sizeof r);
    r.segments = segs;
    r.segment_cap = 8;
    r.points = pts;
    r.point_cap = 200;
    assert_int_equal(symline_muff_find(W, H, &c, acc, acc_size, ws, ws_size, n, &r), SYMLINE_OK);
    assert_int_equal(r.segment_count, 2u);
    for (k = 0; k < 2; k++) {
        if (segs[k].axis == SYMLINE_AXIS_HORIZONTAL) {
            h = (int)k;
        } else {
            v = (int)k;
        }
        assert_int_equal(segs[k].kind, SYMLINE_KIND_LINE);
        /* within the support distance (2 px): the other line's points next to
         * the crossing support the first line found */
        if (segs[k].max_dev > 512u) {
            fail_msg("segment %u: max_dev %u/256 px, ends (%d,%d)-(%d,%d)/256", k, segs[k].max_dev,
                     segs[k].x0, segs[k].y0, segs[k].x1, segs[k].y1);
        }
    }
    assert_true(h >= 0 && v >= 0);
    /* ends at the extent of the points, not at the border */
    near_q8(segs[h].x0, 10, 64);
    near_q8(segs[h].y0, 19, 64);
    near_q8(segs[h].x1, 89, 64);
    near_q8(segs[h].y1, 19, 64);
    near_q8(segs[v].x0, 62, 64);
    near_q8(segs[v].y0, 5, 64);
    near_q8(segs[v].x1, 62, 64);
    near_q8(segs[v].y1, 70, 64);
    /* every point supports one of them, each within 2 px of its segment */
    assert_int_equal(segs[0].count + segs[1].count, n);
    assert_int_equal(r.point_count, n);
    for (k = 0; k < segs[h].count; k++) {
        assert_true(abs((int)pts[segs[h].first + k].y - 19) <= 2);
    }
    for (k = 0; k < segs[v].count; k++) {
        assert_true(abs((int)pts[segs[v].first + k].x - 62) <= 2);
    }
    free(acc);
    free(ws);
}

/* Points every 6 px along a line: enough votes and no gap above `gap`, but
 * they cover a sixth of its length, so the fill test rejects them. */
static void test_sparse_line(void **state)
{
    symline_muff_config c;
    symline_point pts[32];
    symline_segment segs[4];
    symline_result r;
    uint16_t *acc;
    void *ws;
    size_t acc_size, ws_size;
    uint32_t n = 0, x;
    (void)state;
    memset(pts, 0, sizeof pts);
    for (x = 10; x <= 88; x += 6) {
        pts[n].x = (uint16_t)x;
        pts[n++].y = 30;
    }
    symline_muff_config_default(&c);
    c.cell = 4;
    c.min_votes = 8;
    c.gap = 10;
    acc_size = symline_muff_accumulator_size(W, H, &c);
    ws_size = symline_muff_workspace_size(W, H, &c);
    acc = (uint16_t *)malloc(acc_size);
    ws = malloc(ws_size);
    memset(&r, 0, sizeof r);
    r.segments = segs;
    r.segment_cap = 4;
    r.points = pts;
    r.point_cap = 32;
    assert_int_equal(symline_muff_find(W, H, &c, acc, acc_size, ws, ws_size, n, &r), SYMLINE_OK);
    assert_int_equal(r.segment_count, 0u);
    c.min_fill_pct = 0;
    assert_int_equal(symline_muff_find(W, H, &c, acc, acc_size, ws, ws_size, n, &r), SYMLINE_OK);
    assert_int_equal(r.segment_count, 1u);
    near_q8(segs[0].x0, 10, 64);
    near_q8(segs[0].x1, 88, 64);
    free(acc);
    free(ws);
}

/* End to end: a bright cross drawn on a dark frame, through the line filter. */
static void test_detect_muff(void **state)
{
    const uint32_t w = 160, h = 120;
    uint8_t *px = (uint8_t *)malloc((size_t)w * h);
    symline_image img = {160, 120, 160, NULL};
    symline_config cfg;
    symline_muff_config mc;
    symline_segment segs[16];
    symline_point *pts = (symline_point *)malloc(8192 * sizeof(symline_point));
    symline_result r;
    uint16_t *acc;
    void *ws;
    size_t acc_size, ws_size;
    uint32_t x, y, k, found = 0;
    (void)state;
    for (y = 0; y < h; y++) {
        for (x = 0; x < w; x++) {
            const int on = (y >= 59 && y <= 61 && x >= 20 && x <= 139) ||
                           (x >= 99 && x <= 101 && y >= 10 && y <= 109);
            px[(size_t)y * w + x] = (uint8_t)(on ? 210 : 60 + (x * 7 + y * 13) % 9);
        }
    }
    img.data = px;
    symline_config_default(&cfg);
    symline_muff_config_default(&mc);
    acc_size = symline_muff_accumulator_size(w, h, &mc);
    ws_size = symline_detect_muff_workspace_size(w, h, &cfg, &mc);
    assert_true(acc_size > 0u && ws_size > 0u);
    acc = (uint16_t *)malloc(acc_size);
    ws = malloc(ws_size);
    memset(&r, 0, sizeof r);
    r.segments = segs;
    r.segment_cap = 16;
    r.points = pts;
    r.point_cap = 8192;
    assert_int_equal(symline_detect_muff(&img, &cfg, &mc, acc, acc_size, ws, ws_size, &r),
                     SYMLINE_OK);
    for (k = 0; k < r.segment_count; k++) {
        const symline_segment *s = &segs[k];
        if (s->axis == SYMLINE_AXIS_HORIZONTAL && abs(s->y0 - 60 * 256) < 256 &&
            abs(s->y1 - 60 * 256) < 256 && s->x0 < 30 * 256 && s->x1 > 129 * 256) {
            found |= 1u;
        }
        if (s->axis == SYMLINE_AXIS_VERTICAL && abs(s->x0 - 100 * 256) < 256 &&
            abs(s->x1 - 100 * 256) < 256 && s->y0 < 20 * 256 && s->y1 > 99 * 256) {
            found |= 2u;
        }
    }
    assert_int_equal(found, 3u);
    free(acc);
    free(ws);
    free(pts);
    free(px);
}

static void test_errors(void **state)
{
    symline_muff_config c;
    symline_point pts[4] = {{1, 1, 0, 0}, {2, 2, 0, 0}, {3, 3, 0, 0}, {200, 3, 0, 0}};
    symline_segment segs[2];
    symline_result r;
    uint16_t acc[4096];
    uint8_t ws[4096];
    (void)state;
    symline_muff_config_default(&c);
    memset(&r, 0, sizeof r);
    r.segments = segs;
    r.segment_cap = 2;
    r.points = pts;
    r.point_cap = 4;
    assert_int_equal(symline_muff_accumulator_size(2, 50, &c), 0u);
    assert_int_equal(symline_muff_accumulator_size(50, 50, NULL), 0u);
    assert_int_equal(symline_muff_find(50, 40, &c, NULL, sizeof acc, ws, sizeof ws, 3, &r),
                     SYMLINE_ERR_NULL);
    assert_int_equal(symline_muff_find(2, 40, &c, acc, sizeof acc, ws, sizeof ws, 3, &r),
                     SYMLINE_ERR_SIZE);
    assert_int_equal(symline_muff_find(50, 40, &c, acc, 16, ws, sizeof ws, 3, &r),
                     SYMLINE_ERR_BUFFER);
    assert_int_equal(symline_muff_find(50, 40, &c, acc, sizeof acc, ws, 16, 3, &r),
                     SYMLINE_ERR_BUFFER);
    assert_int_equal(symline_muff_find(50, 40, &c, acc, sizeof acc, ws, sizeof ws, 5, &r),
                     SYMLINE_ERR_BUFFER);
    assert_int_equal(symline_muff_find(50, 40, &c, acc, sizeof acc, ws, sizeof ws, 4, &r),
                     SYMLINE_ERR_RANGE);
    pts[3].x = 0; /* inside the frame, but an offset outside -64..63 */
    pts[3].fx = -65;
    assert_int_equal(symline_muff_find(50, 40, &c, acc, sizeof acc, ws, sizeof ws, 4, &r),
                     SYMLINE_ERR_RANGE);
    pts[3].fx = -64;
    pts[3].fy = 64;
    assert_int_equal(symline_muff_find(50, 40, &c, acc, sizeof acc, ws, sizeof ws, 4, &r),
                     SYMLINE_ERR_RANGE);
    pts[3].fy = 63;
    assert_int_equal(symline_muff_find(50, 40, &c, acc, sizeof acc, ws, sizeof ws, 4, &r),
                     SYMLINE_OK);
    c.nms_cells = 17;
    assert_int_equal(symline_muff_find(50, 40, &c, acc, sizeof acc, ws, sizeof ws, 3, &r),
                     SYMLINE_ERR_CONFIG);
    symline_muff_config_default(&c);
    assert_int_equal(symline_muff_find(50, 40, &c, acc, sizeof acc, ws, sizeof ws, 3, &r),
                     SYMLINE_OK);
    assert_int_equal(r.segment_count, 0u); /* three points are no line */
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_perimeter),    cmocka_unit_test(test_two_peaks),
        cmocka_unit_test(test_two_segments), cmocka_unit_test(test_sparse_line),
        cmocka_unit_test(test_detect_muff),  cmocka_unit_test(test_errors),
    };
    return cmocka_run_group_tests_name("muff", tests, NULL, NULL);
}

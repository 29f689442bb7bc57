/* SPDX-License-Identifier: Apache-2.0 */
/*
 * The merge of collinear line pieces (lib/merge.c).
 */
#include <setjmp.h>
#include <stdarg.h>
#include <stdbool.h>
#include <stddef.h>
#include <stdint.h>
#include <stdlib.h>
#include <string.h>

#include <cmocka.h>

#include "merge.h"

/* The merge of r with these thresholds, for a w x h frame. */
static void merge(symline_result *r, uint32_t gap, uint32_t dev, uint32_t curve, uint32_t w,
                  uint32_t h, void *ws, size_t ws_size)
{
    symline_config cfg;
    symline_image img;
    symline_i_run d;
    symline_config_default(&cfg);
    cfg.merge_gap = gap;
    cfg.merge_dev_q8 = dev;
    cfg.curve_dev_q8 = curve;
    memset(&img, 0, sizeof img);
    img.width = w;
    img.height = h;
    memset(&d, 0, sizeof d);
    d.cfg = &cfg;
    d.img = &img;
    d.r = r;
    symline_i_merge(&d, ws, ws_size);
}

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
    merge(&r, 8, 640, 512, 64, 64, NULL, 0); /* gap 11 px > 8: no merge */
    assert_int_equal(r.segment_count, 3);
    assert_false(segs[0].merged);
    merge(&r, 12, 640, 512, 64, 64, NULL, 0);
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
    merge(&r, 12, 640, 512, 64, 64, NULL, 0); /* 3 px off > 2.5 px */
    assert_int_equal(r.segment_count, 2);
    merge(&r, 12, 1024, 5120, 64, 64, NULL,
          0); /* 4 px allowed; the joined piece (1.2 px off its chord) is no curve */
    assert_int_equal(r.segment_count, 1);
    assert_true(segs[0].merged);
}

/* A random frame's pieces: nlines lines of 256x256 px cut into pieces with
 * gaps of 0..20 px, some 2 px off their line, some curves, levels 0..2, in
 * shuffled slot order; points laid out piece after piece. */
static uint32_t rnd(uint32_t *state)
{
    *state = *state * 1103515245u + 12345u;
    return (*state >> 8) & 0xFFFFu;
}

#define RAND_SEGS 160u
#define RAND_PTS 12000u

static void random_pieces(uint32_t seed, symline_result *r, symline_segment *segs,
                          symline_point *pts)
{
    uint32_t st = seed, n = 0, np = 0, i;
    symline_segment tmp;
    while (n < RAND_SEGS) {
        const int32_t x0 = (int32_t)(rnd(&st) % 256u), y0 = (int32_t)(rnd(&st) % 256u);
        const int32_t x1 = (int32_t)(rnd(&st) % 256u), y1 = (int32_t)(rnd(&st) % 256u);
        const int32_t len = abs(x1 - x0) > abs(y1 - y0) ? abs(x1 - x0) : abs(y1 - y0);
        int32_t t = 0;
        if (len < 8) {
            continue;
        }
        while (t < len && n < RAND_SEGS) {
            const int32_t piece = 3 + (int32_t)(rnd(&st) % 40u);
            const int32_t off = rnd(&st) % 5u == 0u ? 2 : 0;
            const bool curve = rnd(&st) % 7u == 0u;
            const int32_t end = t + piece < len ? t + piece : len;
            symline_segment *s = &segs[n];
            int32_t k;
            memset(s, 0, sizeof *s);
            s->first = np;
            for (k = t; k <= end; k++) {
                const int32_t bow = curve ? (k - t) * (end - k) / 8 : 0;
                pts[np].x = (uint16_t)(x0 + (x1 - x0) * k / len + off + bow);
                pts[np].y = (uint16_t)(y0 + (y1 - y0) * k / len + bow);
                pts[np].fx = (int8_t)(rnd(&st) % 64u) - 32;
                pts[np].fy = 0;
                np++;
            }
            s->count = np - s->first;
            s->x0 = pts[s->first].x * 256;
            s->y0 = pts[s->first].y * 256;
            s->x1 = pts[np - 1u].x * 256;
            s->y1 = pts[np - 1u].y * 256;
            s->kind = curve ? SYMLINE_KIND_CURVE : SYMLINE_KIND_LINE;
            s->level = (uint8_t)(rnd(&st) % 3u);
            s->max_dev = 256;
            n++;
            t = end + (int32_t)(rnd(&st) % 21u);
        }
    }
    /* Shuffle the slots, then lay the points out again in slot order. */
    for (i = n - 1u; i > 0u; i--) {
        const uint32_t j = rnd(&st) % (i + 1u);
        tmp = segs[i];
        segs[i] = segs[j];
        segs[j] = tmp;
    }
    {
        static symline_point copy[RAND_PTS];
        uint32_t w = 0;
        memcpy(copy, pts, np * sizeof *pts);
        for (i = 0; i < n; i++) {
            memcpy(pts + w, copy + segs[i].first, segs[i].count * sizeof *pts);
            segs[i].first = w;
            w += segs[i].count;
        }
    }
    memset(r, 0, sizeof *r);
    r->segments = segs;
    r->segment_cap = RAND_SEGS;
    r->segment_count = n;
    r->points = pts;
    r->point_cap = np;
    r->point_count = np;
}

/* The grid of ends finds the very joins of every pair tried in slot order:
 * random pieces merged with no workspace and no free point storage (all
 * pairs, rotations), against a full grid with room for the layout, a grid
 * too small for every piece, and a grid with too few candidate slots. */
static void merge_grid_equals_all_pairs(void **state)
{
    static symline_segment ref_segs[RAND_SEGS], segs[RAND_SEGS];
    static symline_point ref_pts[2u * RAND_PTS], pts[2u * RAND_PTS];
    static uint32_t ws[4096];
    const size_t ws_sizes[] = {sizeof ws, 64u * 4u + 4u * 96u, 64u * 4u + 4u * 70u,
                               64u * 4u + 300u};
    uint32_t seed, v, joins = 0u;
    (void)state;
    for (seed = 1u; seed <= 40u; seed++) {
        for (v = 0; v < 2u * (sizeof ws_sizes / sizeof ws_sizes[0]); v++) {
            symline_result ref, r;
            const uint32_t gap = 4u + seed % 24u;
            random_pieces(seed, &ref, ref_segs, ref_pts);
            merge(&ref, gap, 640, 512, 256, 256, NULL, 0);
            random_pieces(seed, &r, segs, pts);
            r.point_cap = v & 1u ? 2u * RAND_PTS : r.point_count; /* room for the layout */
            merge(&r, gap, 640, 512, 256, 256, ws, ws_sizes[v / 2u]);
            assert_int_equal(r.segment_count, ref.segment_count);
            assert_memory_equal(segs, ref_segs, r.segment_count * sizeof segs[0]);
            assert_memory_equal(pts, ref_pts, r.point_count * sizeof pts[0]);
            joins += RAND_SEGS - r.segment_count;
        }
    }
    assert_true(joins > 1000u); /* the sets do merge */
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(merge_collinear),
        cmocka_unit_test(merge_keeps_bent_joins_apart),
        cmocka_unit_test(merge_grid_equals_all_pairs),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}

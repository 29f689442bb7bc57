/*
 * Tracer and segment-stage unit tests on hand-made line-point maps.
 */
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <string.h>

#include <cmocka.h>

#include "curvejoin.h"
#include "merge.h"
#include "segments.h"
#include "tracer.h"

#define MAXP 512u

/* A hand-made map: rows of '#' (line point) and '.' (nothing). */
typedef struct map {
    symline_point pts[MAXP];
    uint32_t row_start[65];
    uint32_t n, h;
} map;

static void load(map *m, const char *const *rows, uint32_t h)
{
    uint32_t y, x;
    m->n = 0u;
    m->h = h;
    for (y = 0; y < h; y++) {
        m->row_start[y] = m->n;
        for (x = 0; rows[y][x] != '\0'; x++) {
            if (rows[y][x] == '#') {
                m->pts[m->n].x = (uint16_t)x;
                m->pts[m->n].y = (uint16_t)y;
                m->n++;
            }
        }
    }
    m->row_start[h] = m->n;
}

/* Traces everything; chain lengths to len[], first/last points to ends[]. */
static uint32_t trace_all(map *m, uint32_t *len, symline_point (*ends)[2], uint32_t maxc)
{
    sl_tracer t;
    symline_point dst[MAXP];
    uint32_t c = 0u, count;
    uint8_t cut = 0u;
    sl_tracer_init(&t, m->pts, m->n, m->row_start, m->h);
    while (sl_tracer_next(&t, dst, MAXP, &count, &cut)) {
        assert_true(c < maxc);
        len[c] = count;
        ends[c][0] = dst[0];
        ends[c][1] = dst[count - 1u];
        c++;
    }
    assert_int_equal(cut, 0);
    return c;
}

#define ROWS(...) static const char *const rows[] = {__VA_ARGS__}; \
    load(&m, rows, (uint32_t)(sizeof rows / sizeof rows[0]))

static void assert_pt(symline_point p, unsigned x, unsigned y)
{
    assert_int_equal(p.x, x);
    assert_int_equal(p.y, y);
}

static void straight(void **state)
{
    map m;
    uint32_t len[8];
    symline_point ends[8][2];
    (void)state;
    ROWS("........", ".######.", "........");
    assert_int_equal(trace_all(&m, len, ends, 8), 1);
    assert_int_equal(len[0], 6);
    assert_pt(ends[0][0], 1, 1);
    assert_pt(ends[0][1], 6, 1);
}

static void diagonal(void **state)
{
    map m;
    uint32_t len[8];
    symline_point ends[8][2];
    (void)state;
    ROWS("#....", ".#...", "..#..", "...#.", "....#");
    assert_int_equal(trace_all(&m, len, ends, 8), 1);
    assert_int_equal(len[0], 5);
    assert_pt(ends[0][0], 0, 0);
    assert_pt(ends[0][1], 4, 4);
}

static void staircase(void **state)
{
    map m;
    uint32_t len[8];
    symline_point ends[8][2];
    (void)state;
    /* Slope 1/3: runs of three joined by diagonal steps. */
    ROWS("###.........", "...###......", "......###...", ".........###");
    assert_int_equal(trace_all(&m, len, ends, 8), 1);
    assert_int_equal(len[0], 12);
    assert_pt(ends[0][0], 0, 0);
    assert_pt(ends[0][1], 11, 3);
}

static void l_corner(void **state)
{
    map m;
    uint32_t len[8];
    symline_point ends[8][2];
    symline_point dst[MAXP];
    sl_tracer t;
    uint32_t count, cut_at;
    uint8_t cut = 0u;
    (void)state;
    ROWS("#.........", "#.........", "#.........", "#.........", "#.........", "#.........",
         "#########.");
    assert_int_equal(trace_all(&m, len, ends, 8), 1);
    assert_int_equal(len[0], 15);
    /* The segment stage cuts the chain at the corner: the vertical arm, then the rest. */
    load(&m, rows, 7);
    sl_tracer_init(&t, m.pts, m.n, m.row_start, m.h);
    assert_int_equal(sl_tracer_next(&t, dst, MAXP, &count, &cut), 1);
    cut_at = sl_corner_cut(dst, count);
    assert_true(cut_at >= 5u && cut_at <= 7u);
    assert_pt(dst[6], 0, 6); /* the corner point */
    assert_int_equal(sl_corner_cut(dst + cut_at, count - cut_at), count - cut_at);
}

static void t_junction(void **state)
{
    map m;
    uint32_t len[8];
    symline_point ends[8][2];
    (void)state;
    /* The bar is traced first (raster order) straight through the junction;
     * the stem stops next to it. */
    ROWS("###########", ".....#.....", ".....#.....", ".....#.....", ".....#.....");
    assert_int_equal(trace_all(&m, len, ends, 8), 2);
    assert_int_equal(len[0], 11);
    assert_pt(ends[0][0], 0, 0);
    assert_pt(ends[0][1], 10, 0);
    assert_int_equal(len[1], 4);
    assert_pt(ends[1][0], 5, 4);
    assert_pt(ends[1][1], 5, 1);
}

static void x_crossing(void **state)
{
    map m;
    uint32_t len[8];
    symline_point ends[8][2];
    (void)state;
    /* The vertical line starts first and runs straight through the crossing; the
     * horizontal one comes out as two halves that stop beside it. */
    ROWS(".....#.....", ".....#.....", ".....#.....", ".....#.....", ".....#.....",
         "###########", ".....#.....", ".....#.....", ".....#.....", ".....#.....",
         ".....#.....");
    assert_int_equal(trace_all(&m, len, ends, 8), 3);
    assert_int_equal(len[0], 11);
    assert_pt(ends[0][0], 5, 0);
    assert_pt(ends[0][1], 5, 10);
    assert_int_equal(len[1], 5);
    assert_pt(ends[1][0], 0, 5);
    assert_pt(ends[1][1], 4, 5);
    assert_int_equal(len[2], 5);
    assert_pt(ends[2][0], 10, 5);
    assert_pt(ends[2][1], 6, 5);
}

static void closed_loop(void **state)
{
    map m;
    uint32_t len[8];
    symline_point ends[8][2];
    (void)state;
    /* No point has a single neighbour: found in the second phase, traced round. */
    ROWS("...####...", "..#....#..", ".#......#.", ".#......#.", "..#....#..", "...####...");
    assert_int_equal(trace_all(&m, len, ends, 8), 1);
    assert_int_equal(len[0], m.n);
    assert_pt(ends[0][0], 3, 0);
}

static void isolated_and_pairs(void **state)
{
    map m;
    uint32_t len[8];
    symline_point ends[8][2];
    (void)state;
    ROWS("#...#.....", "..........", "..##....#.", "........#.", "#.........");
    /* Isolated points (type A) give nothing; each pair is a two-point chain. */
    assert_int_equal(trace_all(&m, len, ends, 8), 2);
    assert_int_equal(len[0], 2);
    assert_pt(ends[0][0], 2, 2);
    assert_pt(ends[0][1], 3, 2);
    assert_int_equal(len[1], 2);
    assert_pt(ends[1][0], 8, 2);
    assert_pt(ends[1][1], 8, 3);
}

static void classification(void **state)
{
    map m;
    sl_tracer t;
    (void)state;
    ROWS("#.....", "..###.", "...#..");
    sl_tracer_init(&t, m.pts, m.n, m.row_start, m.h);
    assert_int_equal(sl_neighbours(&t, 0, 0), 0); /* A */
    assert_int_equal(sl_neighbours(&t, 2, 1), 2); /* C: (3,1) and (3,2) */
    assert_int_equal(sl_neighbours(&t, 4, 1), 2);
    assert_int_equal(sl_neighbours(&t, 3, 1), 3);
}

static void storage_exhaustion(void **state)
{
    map m;
    sl_tracer t;
    symline_point dst[8];
    uint32_t count, i;
    uint8_t cut = 0u;
    (void)state;
    ROWS("##########");
    for (i = 0; i < 8u; i++) {
        dst[i].x = 0xBEEFu;
        dst[i].y = 0xBEEFu;
    }
    sl_tracer_init(&t, m.pts, m.n, m.row_start, m.h);
    assert_int_equal(sl_tracer_next(&t, dst, 4, &count, &cut), 1);
    assert_int_equal(count, 4);
    assert_int_equal(cut, 1);
    for (i = 4; i < 8u; i++) {
        assert_int_equal(dst[i].x, 0xBEEFu); /* nothing beyond the capacity */
    }
    /* The rest is still there and comes out as further chains. */
    cut = 0u;
    assert_int_equal(sl_tracer_next(&t, dst, 8, &count, &cut), 1);
    assert_int_equal(count, 6);
    assert_int_equal(cut, 0);
    assert_int_equal(sl_tracer_next(&t, dst, 0, &count, &cut), 0);
    assert_int_equal(cut, 1);
}

static void fit_line_and_curve(void **state)
{
    symline_point p[64];
    symline_segment s;
    uint32_t i;
    (void)state;
    for (i = 0; i < 40u; i++) {
        p[i].x = (uint16_t)(10u + i);
        p[i].y = (uint16_t)(20u + i / 4u);
    }
    sl_fit(p, 40, 0, 512, &s);
    assert_int_equal(s.kind, SYMLINE_KIND_LINE);
    /* Least-squares ends: on the staircase's centre line y = 19.625 + (x - 10) / 4. */
    assert_true(s.x0 >= 10 * 256 - 64 && s.x0 <= 10 * 256 + 64);
    assert_true(s.x1 >= 49 * 256 - 64 && s.x1 <= 49 * 256 + 64);
    assert_true(s.y0 >= 19 * 256 + 96 && s.y0 <= 19 * 256 + 224);
    assert_true(s.y1 >= 29 * 256 + 64 && s.y1 <= 29 * 256 + 192);
    assert_true(s.max_dev < 128u);
    /* A half circle of radius 12 around (30, 30). */
    {
        static const int8_t c[][2] = {{12, 0}, {12, 2}, {11, 4}, {11, 5}, {10, 7}, {8, 9},
                                      {7, 10}, {5, 11}, {4, 11}, {2, 12}, {0, 12}, {-2, 12},
                                      {-4, 11}, {-5, 11}, {-7, 10}, {-8, 9}, {-10, 7},
                                      {-11, 5}, {-11, 4}, {-12, 2}, {-12, 0}};
        for (i = 0; i < 21u; i++) {
            p[i].x = (uint16_t)(30 + c[i][0]);
            p[i].y = (uint16_t)(30 + c[i][1]);
        }
        sl_fit(p, 21, 0, 512, &s);
        assert_int_equal(s.kind, SYMLINE_KIND_CURVE);
        assert_true(s.max_dev >= 11u * 256u && s.max_dev <= 13u * 256u);
    }
    /* Level 1: coordinates are block centres. */
    p[0].x = 0;
    p[0].y = 0;
    p[1].x = 4;
    p[1].y = 0;
    sl_fit(p, 2, 1, 512, &s);
    assert_int_equal(s.x0, 128);
    assert_int_equal(s.x1, 8 * 256 + 128);
}

static void merge_collinear(void **state)
{
    symline_point pts[64];
    symline_segment segs[4];
    symline_result r;
    uint32_t i;
    (void)state;
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
    r.truncated = 0;
    sl_merge(&r, 8, 640, 512); /* gap 11 px > 8: no merge */
    assert_int_equal(r.segment_count, 3);
    sl_merge(&r, 12, 640, 512);
    assert_int_equal(r.segment_count, 2);
    assert_int_equal(segs[0].x0, 0);
    assert_int_equal(segs[0].x1, 29 * 256);
    assert_int_equal(segs[0].count, 20);
    for (i = 0; i < 20u; i++) {
        assert_int_equal(pts[i].y, 5); /* the pieces' points are contiguous now */
    }
    assert_int_equal(segs[1].first, 20);
    assert_int_equal(pts[20].x, 50);
}

static void bend_tells_flat_arc_from_line(void **state)
{
    symline_point p[64];
    symline_segment s;
    uint32_t i;
    (void)state;
    /* A staircase line (slope 1/4): pixel steps average out. */
    for (i = 0; i < 60u; i++) {
        p[i].x = (uint16_t)(10u + i);
        p[i].y = (uint16_t)(20u + i / 4u);
    }
    assert_true(sl_bend_q8(p, 60) < 40u);
    /* A flat arc: y = 20 + round((x - 40)^2 / 400), sagitta 2 px over 60 px. */
    for (i = 0; i < 60u; i++) {
        const int32_t dx = (int32_t)i - 30;
        p[i].x = (uint16_t)(10u + i);
        p[i].y = (uint16_t)(20 + (dx * dx + 200) / 450);
    }
    sl_fit(p, 60, 0, 512, &s);
    assert_int_equal(s.kind, SYMLINE_KIND_LINE); /* under the max_dev threshold ... */
    assert_true(sl_bend_q8(p, 60) >= 80u);        /* ... but it bends */
}

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
    /* Line 3 continues the curve too, but it was merged (reserved = 1): its
     * points run back and forth, no polyline through them, so it stays a line. */
    for (i = 0; i < 20u; i++, n++) {
        pts[n].x = (uint16_t)(i < 10u ? 9u - i : i - 10u + 0u);
        pts[n].y = 200;
    }
    seg_of(&segs[3], pts, 81, 20, SYMLINE_KIND_LINE);
    segs[3].x0 = 9 * 256;
    segs[3].x1 = 0;
    segs[3].reserved = 1;
    r.segments = segs;
    r.segment_cap = 4;
    r.segment_count = 4;
    r.points = pts;
    r.point_cap = 128;
    r.point_count = n;
    r.truncated = 0;
    sl_curve_join(&r, 0); /* off: nothing changes but the flags */
    assert_int_equal(segs[1].kind, SYMLINE_KIND_LINE);
    assert_int_equal(segs[3].reserved, 0);
    segs[3].reserved = 1;
    sl_curve_join(&r, 1);
    assert_int_equal(segs[1].kind, SYMLINE_KIND_CURVE);
    assert_int_equal(segs[2].kind, SYMLINE_KIND_LINE);
    assert_int_equal(segs[3].kind, SYMLINE_KIND_LINE);
    assert_int_equal(segs[3].reserved, 0);
    assert_int_equal(r.segment_count, 4);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(straight),        cmocka_unit_test(diagonal),
        cmocka_unit_test(staircase),       cmocka_unit_test(l_corner),
        cmocka_unit_test(t_junction),      cmocka_unit_test(x_crossing),
        cmocka_unit_test(closed_loop),     cmocka_unit_test(isolated_and_pairs),
        cmocka_unit_test(classification),  cmocka_unit_test(storage_exhaustion),
        cmocka_unit_test(fit_line_and_curve), cmocka_unit_test(merge_collinear),
        cmocka_unit_test(bend_tells_flat_arc_from_line),
        cmocka_unit_test(line_continuing_a_curve_is_a_curve),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}

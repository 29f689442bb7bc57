/* SPDX-License-Identifier: Apache-2.0 */
/*
 * The line tracer (lib/tracer.c) on hand-made line-point maps: chains,
 * junctions, loops, classification by neighbours, storage exhaustion.
 */
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <string.h>

#include <cmocka.h>

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
    symline_i_tracer t;
    symline_point dst[MAXP];
    uint32_t c = 0u, count;
    bool cut = false;
    symline_i_tracer_init(&t, m->pts, m->n, m->row_start, m->h);
    while (symline_i_tracer_next(&t, dst, MAXP, &count, &cut)) {
        assert_true(c < maxc);
        len[c] = count;
        ends[c][0] = dst[0];
        ends[c][1] = dst[count - 1u];
        c++;
    }
    assert_int_equal(cut, 0);
    return c;
}

#define ROWS(...)                                                                                  \
    static const char *const rows[] = {__VA_ARGS__};                                               \
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
    (void)state;
    ROWS("#.........", "#.........", "#.........", "#.........", "#.........", "#.........",
         "#########.");
    /* One chain round the corner; the segment stage cuts it (test_segments.c). */
    assert_int_equal(trace_all(&m, len, ends, 8), 1);
    assert_int_equal(len[0], 15);
    assert_pt(ends[0][0], 0, 0);
    assert_pt(ends[0][1], 8, 6);
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
    ROWS(".....#.....", ".....#.....", ".....#.....", ".....#.....", ".....#.....", "###########",
         ".....#.....", ".....#.....", ".....#.....", ".....#.....", ".....#.....");
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
    symline_i_tracer t;
    (void)state;
    ROWS("#.....", "..###.", "...#..");
    symline_i_tracer_init(&t, m.pts, m.n, m.row_start, m.h);
    assert_int_equal(symline_i_neighbours(&t, 0, 0), 0); /* A */
    assert_int_equal(symline_i_neighbours(&t, 2, 1), 2); /* C: (3,1) and (3,2) */
    assert_int_equal(symline_i_neighbours(&t, 4, 1), 2);
    assert_int_equal(symline_i_neighbours(&t, 3, 1), 3);
}

static void storage_exhaustion(void **state)
{
    map m;
    symline_i_tracer t;
    symline_point dst[8];
    uint32_t count, i;
    bool cut = false;
    (void)state;
    ROWS("##########");
    for (i = 0; i < 8u; i++) {
        dst[i].x = 0xBEEFu;
        dst[i].y = 0xBEEFu;
    }
    symline_i_tracer_init(&t, m.pts, m.n, m.row_start, m.h);
    assert_int_equal(symline_i_tracer_next(&t, dst, 4, &count, &cut), 1);
    assert_int_equal(count, 4);
    assert_int_equal(cut, 1);
    for (i = 4; i < 8u; i++) {
        assert_int_equal(dst[i].x, 0xBEEFu); /* nothing beyond the capacity */
    }
    /* The rest is still there and comes out as further chains. */
    cut = false;
    assert_int_equal(symline_i_tracer_next(&t, dst, 8, &count, &cut), 1);
    assert_int_equal(count, 6);
    assert_int_equal(cut, 0);
    assert_int_equal(symline_i_tracer_next(&t, dst, 0, &count, &cut), 0);
    assert_int_equal(cut, 1);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(straight),       cmocka_unit_test(diagonal),
        cmocka_unit_test(staircase),      cmocka_unit_test(l_corner),
        cmocka_unit_test(t_junction),     cmocka_unit_test(x_crossing),
        cmocka_unit_test(closed_loop),    cmocka_unit_test(isolated_and_pairs),
        cmocka_unit_test(classification), cmocka_unit_test(storage_exhaustion),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}

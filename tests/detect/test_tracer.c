/* SPDX-License-Identifier: Apache-2.0 */
/*
 * The line tracer (lib/tracer.c) on hand-made line-point maps: chains,
 * junctions, loops, classification by neighbours, storage exhaustion; and on
 * random maps against the same rules on a plain grid.
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

/* The rules of tracer.c on a plain grid (presence and visited flags per
 * pixel), the reference for the list-based tracer on random maps: same
 * chains, points, order and cuts whatever the tracer does to be fast. */
#define RW 720u
#define RH 40u
#define RMAXP (RW * RH)

typedef struct grid {
    uint8_t on[RH][RW], vis[RH][RW];
    uint32_t w, h;
} grid;

static const int DXR[8] = {1, 1, 0, -1, -1, -1, 0, 1};
static const int DYR[8] = {0, 1, 1, 1, 0, -1, -1, -1};
static const uint32_t TURNR[5] = {0, 1, 7, 2, 6};

static bool ref_on(const grid *g, int x, int y)
{
    return x >= 0 && y >= 0 && (uint32_t)x < g->w && (uint32_t)y < g->h && g->on[y][x];
}

/* follow() of tracer.c: from (x, y), last step direction dir (8: a start,
 * directions 0..7 in order). */
static bool ref_follow(grid *g, int x, int y, uint32_t dir, symline_point *dst, uint32_t cap,
                       uint32_t *pos, bool *cut)
{
    bool moved = false;
    for (;;) {
        const uint32_t tries = dir == 8u ? 8u : 5u;
        uint32_t o;
        if (dir != 8u && *pos >= cap) {
            *cut = true;
            return true;
        }
        for (o = 0; o < tries; o++) {
            const uint32_t d = dir == 8u ? o : (dir + TURNR[o]) & 7u;
            const int nx = x + DXR[d], ny = y + DYR[d];
            if (ref_on(g, nx, ny) && !g->vis[ny][nx]) {
                if (*pos >= cap) {
                    *cut = true;
                    return true;
                }
                g->vis[ny][nx] = 1u;
                dst[*pos].x = (uint16_t)nx;
                dst[*pos].y = (uint16_t)ny;
                (*pos)++;
                x = nx;
                y = ny;
                dir = d;
                break;
            }
        }
        if (o == tries) {
            return moved;
        }
        moved = true;
    }
}

static void ref_reverse(symline_point *p, uint32_t n)
{
    uint32_t i;
    for (i = 0; i < n / 2u; i++) {
        const symline_point v = p[i];
        p[i] = p[n - 1u - i];
        p[n - 1u - i] = v;
    }
}

/* The reference's next chain; *phase, *scan: where its scan is (raster index y * w + x). */
static bool ref_next(grid *g, uint32_t *phase, uint32_t *scan, symline_point *dst, uint32_t cap,
                     uint32_t *count, bool *cut)
{
    *count = 0u;
    if (cap == 0u) {
        *cut = true;
        return false;
    }
    for (; *phase < 2u; (*phase)++, *scan = 0u) {
        while (*scan < g->w * g->h) {
            const uint32_t s = (*scan)++;
            const int x = (int)(s % g->w), y = (int)(s / g->w);
            uint32_t pos = 1u;
            if (!g->on[y][x] || g->vis[y][x]) {
                continue;
            }
            if (*phase == 0u) {
                uint32_t c = 0u, d;
                for (d = 0; d < 8u; d++) {
                    c += ref_on(g, x + DXR[d], y + DYR[d]);
                }
                if (c != 1u) {
                    if (c == 0u) {
                        g->vis[y][x] = 1u;
                    }
                    continue;
                }
            }
            g->vis[y][x] = 1u;
            if (!ref_follow(g, x, y, 8u, dst, cap, &pos, cut)) {
                continue;
            }
            dst[0].x = (uint16_t)x;
            dst[0].y = (uint16_t)y;
            if (*phase == 1u && pos < cap) {
                const uint32_t fwd = pos;
                (void)ref_follow(g, x, y, 8u, dst, cap, &pos, cut);
                ref_reverse(dst, pos);
                ref_reverse(dst + (pos - fwd), fwd);
            }
            *count = pos;
            return true;
        }
    }
    return false;
}

static uint32_t rnd_state = 12345u;

static uint32_t rnd(uint32_t n)
{
    rnd_state = rnd_state * 1103515245u + 12345u;
    return (rnd_state >> 8) % n;
}

/* A random map: scattered points at density pct, plus walks (lines that
 * wander by one pixel, cross and touch), plus, when wide, dense runs. */
static void random_grid(grid *g, uint32_t w, uint32_t h, uint32_t pct, uint32_t walks, bool runs)
{
    uint32_t x, y, k;
    memset(g, 0, sizeof *g);
    g->w = w;
    g->h = h;
    for (y = 0; y < h; y++) {
        for (x = 0; x < w; x++) {
            g->on[y][x] = (uint8_t)(rnd(100u) < pct);
        }
    }
    for (k = 0; k < walks; k++) {
        int px = (int)rnd(w), py = (int)rnd(h);
        const uint32_t d0 = rnd(8u), len = 3u + rnd(3u * (w + h) / 2u);
        uint32_t s;
        for (s = 0; s < len; s++) {
            const uint32_t d = (d0 + (rnd(4u) == 0u ? rnd(3u) + 7u : 0u)) & 7u;
            if (!ref_on(g, px, py) && px >= 0 && py >= 0 && (uint32_t)px < w && (uint32_t)py < h) {
                g->on[py][px] = 1u;
            }
            px += DXR[d];
            py += DYR[d];
        }
    }
    if (runs) { /* rows far from alike: one side of a row full, the next row's other side */
        for (y = 0; y + 1u < h; y += 2u) {
            const uint32_t cut = rnd(w);
            for (x = 0; x < w; x++) {
                if (rnd(100u) < 70u) {
                    g->on[y + (x < cut ? 0u : 1u)][x] = 1u;
                }
            }
        }
    }
}

static symline_point r_pts[RMAXP], r_dst[RMAXP], r_ref[RMAXP];
static uint32_t r_rows[RH + 2u];
static grid r_grid;

/* Traces a random grid with the tracer and with the reference, chain by chain
 * with capacity cap, and compares everything they write. */
static void compare_with_reference(grid *g, uint32_t cap)
{
    symline_i_tracer t;
    uint32_t n = 0u, x, y, phase = 0u, scan = 0u, count, rcount;
    bool cut = false, rcut = false;
    for (y = 0; y < g->h; y++) {
        r_rows[y] = n;
        for (x = 0; x < g->w; x++) {
            if (g->on[y][x]) {
                r_pts[n].x = (uint16_t)x;
                r_pts[n].y = (uint16_t)y;
                r_pts[n].fx = (int8_t)rnd(256u); /* whatever the collection left */
                r_pts[n].fy = (int8_t)rnd(256u);
                n++;
            }
        }
    }
    r_rows[g->h] = n;
    r_rows[g->h + 1u] = 0u;
    symline_i_tracer_init(&t, r_pts, n, r_rows, g->h);
    for (;;) {
        const bool got = symline_i_tracer_next(&t, r_dst, cap, &count, &cut);
        const bool rgot = ref_next(g, &phase, &scan, r_ref, cap, &rcount, &rcut);
        assert_int_equal(got, rgot);
        assert_int_equal(cut, rcut);
        if (!got) {
            break;
        }
        assert_int_equal(count, rcount);
        for (x = 0; x < count; x++) {
            assert_int_equal(r_dst[x].x, r_ref[x].x);
            assert_int_equal(r_dst[x].y, r_ref[x].y);
        }
    }
    if (SL_FOR_SPEED) { /* the count that ends the scans early */
        assert_int_equal(t.left, 0);
    }
    /* Every point visited or not as the reference left it. */
    for (y = 0; y < g->h; y++) {
        for (x = r_rows[y]; x < r_rows[y + 1u]; x++) {
            assert_int_equal(r_pts[x].y == SL_VISITED, g->vis[y][r_pts[x].x] != 0u);
        }
    }
}

static void random_maps(void **state)
{
    uint32_t k;
    (void)state;
    for (k = 0; k < 1500u; k++) {
        const bool wide = k % 10u == 9u;
        const uint32_t w = wide ? RW - rnd(40u) : 1u + rnd(48u);
        const uint32_t h = 1u + rnd(wide ? RH : 32u);
        const uint32_t pct = rnd(4u) == 0u ? rnd(60u) : rnd(8u);
        const uint32_t cap = rnd(5u) == 0u ? 1u + rnd(12u) : RMAXP;
        random_grid(&r_grid, w, h, pct, rnd(6u), wide && rnd(2u) == 0u);
        compare_with_reference(&r_grid, cap);
    }
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
        cmocka_unit_test(random_maps),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}

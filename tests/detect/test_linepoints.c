/* SPDX-License-Identifier: Apache-2.0 */
/*
 * Line points of one pass (lib/linepoints.c): the strip processing over a
 * ring of rows gives exactly the points of a plain full-frame path (whole
 * grid image, whole energy and extrema maps, the same filter rule), for both
 * axes, three scales, both filters, several contrast limits and two radii,
 * on a synthetic and a real frame and on one of flat bands (plateaus);
 * the same list in the columns below a field boundary; nothing is written
 * outside the workspace.
 */
#include <setjmp.h>
#include <stdarg.h>
#include <stdbool.h>
#include <stddef.h>
#include <stdint.h>
#include <stdlib.h>
#include <string.h>

#include <cmocka.h>

#include "imgio.h"
#include "linepoints.h"
#include "pass.h"
#include "symline/extrema.h"
#include "symline/symmetry.h"
#include "synth_frame.h"
#include "testutil.h"

/* ---- the full-frame path: whole grid image, whole maps, same filter rule ---- */

static int plateau_ok(const uint32_t *E, const symline_i_pass *p, uint32_t x, uint32_t y)
{
    uint32_t b;
    if (p->axis == SYMLINE_AXIS_HORIZONTAL) {
        for (b = y; b + 1u < p->h && E[(b + 1u) * p->w + x] == E[y * p->w + x]; b++) {
        }
        return b - y <= p->lag;
    }
    for (b = x; b + 1u < p->w && E[y * p->w + b + 1u] == E[y * p->w + x]; b++) {
    }
    return b - x <= p->lag;
}

/* Extremum of the given kind at (x, y) that passes the plateau rule. */
static int marked(const uint8_t *map, const uint32_t *E, const symline_i_pass *p, uint32_t x,
                  uint32_t y, uint8_t kind)
{
    return map[y * p->w + x] == kind && plateau_ok(E, p, x, y);
}

static uint32_t full_frame_points(const symline_image *img, const symline_i_pass *p,
                                  symline_point *out)
{
    const uint32_t w = p->w, h = p->h, k = p->k, D = p->filter.a_distance;
    uint8_t *g = (uint8_t *)malloc((size_t)w * h);
    uint16_t *acc = (uint16_t *)malloc((size_t)img->width * sizeof(uint16_t));
    uint32_t *E = (uint32_t *)malloc((size_t)w * h * sizeof(uint32_t));
    uint8_t *map = (uint8_t *)malloc((size_t)w * h);
    symline_image gi;
    size_t wsn;
    void *ws;
    uint32_t x, y, n = 0u;
    for (y = 0; y < h; y++) {
        symline_i_grid_row(img, p, y, acc, g + (size_t)y * w, NULL);
    }
    gi.width = w;
    gi.height = h;
    gi.stride = w;
    gi.data = g;
    wsn = symline_extrema_workspace_size(w, h, p->axis, p->m);
    ws = malloc(wsn);
    assert_int_equal(symline_energy_frame(&gi, p->axis, p->m, E, w, (size_t)w * h), SYMLINE_OK);
    assert_int_equal(symline_extrema(&gi, p->axis, p->m, map, w, (size_t)w * h, ws, wsn),
                     SYMLINE_OK);
    for (y = 0; y < h; y++) {
        for (x = 0; x < w; x++) {
            uint32_t c, lo, hi, i, a = 0u;
            if (!marked(map, E, p, x, y, SYMLINE_MAP_S)) {
                continue;
            }
            c = g[y * w + x];
            if (p->axis == SYMLINE_AXIS_HORIZONTAL) {
                lo = g[(y >= k ? y - k : 0u) * w + x];
                hi = g[(y + k < h ? y + k : h - 1u) * w + x];
            } else {
                lo = g[y * w + (x >= k ? x - k : 0u)];
                hi = g[y * w + (x + k < w ? x + k : w - 1u)];
            }
            if (!symline_i_linefilter_gray(&p->filter, c, lo, hi)) {
                continue;
            }
            if (D != 0u) {
                for (i = 0; i <= 2u * D; i++) {
                    const int32_t o = (int32_t)i - (int32_t)D;
                    const int32_t xx = (int32_t)x + (p->axis == SYMLINE_AXIS_VERTICAL ? o : 0);
                    const int32_t yy = (int32_t)y + (p->axis == SYMLINE_AXIS_HORIZONTAL ? o : 0);
                    if (xx >= 0 && yy >= 0 && (uint32_t)xx < w && (uint32_t)yy < h &&
                        marked(map, E, p, (uint32_t)xx, (uint32_t)yy, SYMLINE_MAP_A)) {
                        a = 1u;
                    }
                }
                if (!a) {
                    continue;
                }
            }
            out[n].x = (uint16_t)x;
            out[n].y = (uint16_t)y;
            n++;
        }
    }
    free(g);
    free(acc);
    free(E);
    free(map);
    free(ws);
    return n;
}

/* Strip path (what symline_detect runs) vs full-frame path, one pass. */
static void compare_pass(const symline_image *img, const symline_config *cfg, symline_axis axis,
                         uint32_t level)
{
    symline_i_pass p;
    size_t wsn;
    uint8_t *ws;
    symline_point *a, *b;
    uint32_t *row_start, na = 0u, nb, i, y;
    uint32_t dropped = 0u;
    symline_i_pass_setup(&p, cfg, axis, level, img->width, img->height);
    wsn = symline_i_collect_ws_size(&p, img->width);
    ws = tu_guard_alloc(wsn);
    memset(ws, 0x5A, wsn); /* results must not depend on what the workspace held */
    a = (symline_point *)malloc((size_t)p.w * p.h * sizeof(symline_point));
    b = (symline_point *)malloc((size_t)p.w * p.h * sizeof(symline_point));
    row_start = (uint32_t *)malloc(((size_t)p.h + 1u) * sizeof(uint32_t));
    assert_int_equal(symline_i_collect(img, &p, ws, wsn, a, p.w * p.h, &na, row_start, &dropped),
                     SYMLINE_OK);
    assert_true(tu_guard_ok(ws, wsn));
    assert_int_equal(dropped, 0);
    nb = full_frame_points(img, &p, b);
    assert_true(na > 10u); /* the frame has lines: an empty list would prove nothing */
    assert_int_equal(na, nb);
    for (i = 0; i < na; i++) {
        assert_int_equal(a[i].x, b[i].x);
        assert_int_equal(a[i].y, b[i].y);
    }
    /* the row index matches the list */
    for (y = 0; y < p.h; y++) {
        for (i = row_start[y]; i < row_start[y + 1u]; i++) {
            assert_int_equal(a[i].y, y);
        }
    }
    assert_int_equal(row_start[p.h], na);
    /* Below a field boundary: each row decided only from the first to the
     * last column that keeps it (their first kept rows in field[]), every
     * row above the first kept one left out, whatever rows the ring down the
     * columns must read above them. Boundaries: flat at several heights, a
     * random walk, a peak, none in some columns (rows below the grid). */
    for (i = 0; i < 6u; i++) {
        uint16_t *field = (uint16_t *)malloc((size_t)p.w * sizeof(uint16_t));
        uint32_t *rs = (uint32_t *)malloc(((size_t)p.h + 1u) * sizeof(uint32_t));
        uint32_t nc = 0u, j = 0u, x, s = 7u + i;
        int32_t walk = (int32_t)(p.h / 2u);
        for (x = 0; x < p.w; x++) {
            const uint32_t flat[3] = {1u, p.h / 3u, p.h - 1u};
            walk += (int32_t)(tu_rand(&s) % 5u) - 2;
            walk = walk < 0 ? 0 : walk > (int32_t)p.h + 3 ? (int32_t)p.h + 3 : walk;
            field[x] = (uint16_t)(i < 3u    ? flat[i]
                                  : i == 3u ? (uint32_t)walk
                                  : i == 4u ? (x < p.w / 2u ? p.h - x * p.h / p.w : x * p.h / p.w)
                                            : (x % 7u == 0u ? p.h + 1u : p.h / 4u + x % 5u));
        }
        memset(ws, 0x5A, wsn);
        p.field = field;
        assert_int_equal(symline_i_collect(img, &p, ws, wsn, b, p.w * p.h, &nc, rs, &dropped),
                         SYMLINE_OK);
        p.field = NULL;
        assert_true(tu_guard_ok(ws, wsn));
        /* the whole list's points in the columns of their rows, in order */
        for (y = 0; y < p.h; y++) {
            uint32_t x0 = 0u, x1 = p.w, k;
            while (x0 < x1 && field[x0] > y) {
                x0++;
            }
            while (x1 > x0 && field[x1 - 1u] > y) {
                x1--;
            }
            assert_int_equal(rs[y], j);
            for (k = row_start[y]; k < row_start[y + 1u]; k++) {
                if (a[k].x >= x0 && a[k].x < x1) {
                    assert_true(j < nc);
                    assert_int_equal(b[j].x, a[k].x);
                    assert_int_equal(b[j].y, a[k].y);
                    j++;
                }
            }
        }
        assert_int_equal(j, nc);
        assert_int_equal(rs[p.h], nc);
        free(field);
        free(rs);
    }
    tu_guard_free(ws);
    free(a);
    free(b);
    free(row_start);
}

static void strip_identity_on(const symline_image *img)
{
    symline_config cfg;
    uint32_t level, ax, f;
    for (f = 0; f < 2u; f++) {
        for (level = 0; level < 3u; level++) {
            for (ax = 0; ax < 2u; ax++) {
                symline_config_default(&cfg);
                if (f == 1u) {
                    cfg.filter = SYMLINE_FILTER_PAPER;
                    cfg.illumination = 100u;
                }
                compare_pass(img, &cfg, ax == 0u ? SYMLINE_AXIS_HORIZONTAL : SYMLINE_AXIS_VERTICAL,
                             level);
            }
        }
    }
    /* the contrast filter's percent tests and limits, down the columns
     * (where the speed builds decide blocks of candidates in lanes) and
     * along the rows */
    for (f = 0; f < 3u; f++) {
        static const uint32_t pct[3] = {30u, 0u, 5u}, asym[3] = {40u, 257u, 0u},
                              min[3] = {0u, 9u, 1u};
        symline_config_default(&cfg);
        cfg.contrast_pct = pct[f];
        cfg.contrast_asym_pct = asym[f];
        cfg.contrast_min = min[f];
        compare_pass(img, &cfg, SYMLINE_AXIS_HORIZONTAL, f);
        compare_pass(img, &cfg, SYMLINE_AXIS_VERTICAL, 0);
    }
    /* another radius */
    symline_config_default(&cfg);
    cfg.radius = 5;
    compare_pass(img, &cfg, SYMLINE_AXIS_HORIZONTAL, 0);
    compare_pass(img, &cfg, SYMLINE_AXIS_VERTICAL, 1);
}

static void strip_identity_synthetic(void **state)
{
    symline_image img;
    uint8_t *px = synth_frame(203, 157, 211);
    (void)state;
    img.width = 203;
    img.height = 157;
    img.stride = 211;
    img.data = px;
    strip_identity_on(&img);
    free(px);
}

static void strip_identity_real(void **state)
{
    imgio_gray g;
    char err[256];
    symline_image img;
    (void)state;
    assert_int_equal(imgio_read_gray(SYMLINE_TEST_DATA "/msl_20190606_r2_cam0_20190606_204340.pgm",
                                     &g, err, sizeof err),
                     0);
    img.width = g.width;
    img.height = g.height;
    img.stride = g.width;
    img.data = g.px;
    strip_identity_on(&img);
    imgio_free(&g);
}

/* Flat bands and steps of a few gray levels: runs of equal energies
 * (plateaus) of every length, down the columns and along the rows, which
 * the extremum decision follows on its slow path. */
static void strip_identity_plateaus(void **state)
{
    const uint32_t w = 97u, h = 83u;
    uint8_t *px = (uint8_t *)malloc((size_t)w * h);
    uint32_t s = 11u, x, y;
    symline_image img;
    (void)state;
    for (y = 0; y < h;) {
        /* a band of 1..7 rows; blocks of 1..7 columns of 2 gray values */
        const uint32_t rows = 1u + tu_rand(&s) % 7u;
        const uint8_t g0 = (uint8_t)(80u + 40u * (tu_rand(&s) % 4u));
        uint32_t r;
        for (x = 0; x < w;) {
            const uint32_t cols = 1u + tu_rand(&s) % 7u;
            const uint8_t g = (uint8_t)(tu_rand(&s) % 3u == 0u ? 250u : g0);
            for (r = 0; r < rows && y + r < h; r++) {
                uint32_t c;
                for (c = 0; c < cols && x + c < w; c++) {
                    px[(y + r) * w + x + c] = g;
                }
            }
            x += cols;
        }
        y += rows;
    }
    img.width = w;
    img.height = h;
    img.stride = w;
    img.data = px;
    strip_identity_on(&img);
    free(px);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(strip_identity_synthetic),
        cmocka_unit_test(strip_identity_real),
        cmocka_unit_test(strip_identity_plateaus),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}

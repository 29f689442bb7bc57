/* SPDX-License-Identifier: Apache-2.0 */
/*
 * Golden tests: the optimised core against images produced by the plain
 * reference (tests/golden/regenerate.sh), bit for bit, for both axes and
 * radii 1, 2, 3, 5, 10, 50, with tight and padded strides.
 */
#define _POSIX_C_SOURCE 200809L
#include <dirent.h>
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include <cmocka.h>

#include "imgio.h"
#include "symline/extrema.h"
#include "symline/symmetry.h"
#include "testutil.h"

typedef struct golden_case {
    char path[512];
    char input[512];
    symline_axis axis;
    uint32_t m;
    int extrema;
} golden_case;

/* "<set>_<base>.<axis>.m<R>.<s8|ext>.pgm" -> the case. 0 on success. */
static int parse_name(const char *dir, const char *name, golden_case *c)
{
    char buf[256], *set, *base, *axis, *rad, *kind, *us;
    if (strlen(name) >= sizeof buf) {
        return -1;
    }
    strcpy(buf, name);
    set = buf;
    us = strchr(buf, '_');
    if (us == NULL) {
        return -1;
    }
    *us = '\0';
    base = us + 1;
    axis = strchr(base, '.');
    if (axis == NULL) {
        return -1;
    }
    *axis++ = '\0';
    rad = strchr(axis, '.');
    if (rad == NULL) {
        return -1;
    }
    *rad++ = '\0';
    kind = strchr(rad, '.');
    if (kind == NULL || rad[0] != 'm') {
        return -1;
    }
    *kind++ = '\0';
    c->m = (uint32_t)atoi(rad + 1);
    c->axis = strcmp(axis, "vertical") == 0 ? SYMLINE_AXIS_VERTICAL : SYMLINE_AXIS_HORIZONTAL;
    c->extrema = strncmp(kind, "ext", 3) == 0;
    snprintf(c->path, sizeof c->path, "%s/%s", dir, name);
    snprintf(c->input, sizeof c->input, "%s/%s/%s.pgm", SYMLINE_TEST_DATA, set, base);
    return 0;
}

/* Runs the core on `in` viewed with input stride w+in_pad, output stride w+out_pad. */
static void run_and_compare(const golden_case *c, const imgio_gray *in, const imgio_gray *gold,
                            uint32_t in_pad, uint32_t out_pad)
{
    const uint32_t w = in->width, h = in->height;
    const uint32_t is = w + in_pad, os = w + out_pad;
    const size_t in_len = (size_t)(h - 1) * is + w, out_len = (size_t)(h - 1) * os + w;
    uint8_t *src = tu_guard_alloc(in_len);
    uint8_t *out = tu_guard_alloc(out_len);
    size_t ws_size = c->extrema ? symline_extrema_workspace_size(w, h, c->axis, c->m)
                                : symline_symmetry_workspace_size(w, h, c->axis, c->m);
    uint8_t *ws = tu_guard_alloc(ws_size);
    symline_image img;
    symline_status st;
    uint32_t x, y, seed = 0x1234567u;
    assert_non_null(src);
    assert_non_null(out);
    assert_non_null(ws);
    assert_true(ws_size > 0);
    for (y = 0; y < h; y++) {
        for (x = 0; x < is && (size_t)y * is + x < in_len; x++) {
            /* pixels, and junk in the padding that must never be read into results */
            src[(size_t)y * is + x] = x < w ? in->px[(size_t)y * w + x] : (uint8_t)tu_rand(&seed);
        }
    }
    img.width = w;
    img.height = h;
    img.stride = is;
    img.data = src;
    st = c->extrema ? symline_extrema(&img, c->axis, c->m, out, os, out_len, ws, ws_size)
                    : symline_symmetry(&img, c->axis, c->m, out, os, out_len, ws, ws_size);
    assert_int_equal(st, SYMLINE_OK);
    assert_true(tu_guard_ok(out, out_len));
    assert_true(tu_guard_ok(ws, ws_size));
    for (y = 0; y < h; y++) {
        for (x = 0; x < w; x++) {
            const uint8_t got = out[(size_t)y * os + x], want = gold->px[(size_t)y * w + x];
            if (got != want) {
                fail_msg("%s: pixel (%u,%u) is %u, golden %u (input stride %u, output stride %u)",
                         c->path, x, y, got, want, is, os);
            }
        }
        for (x = w; x < os && y + 1 < h; x++) {
            assert_int_equal(out[(size_t)y * os + x], TU_GUARD_BYTE);
        }
    }
    tu_guard_free(src);
    tu_guard_free(out);
    tu_guard_free(ws);
}

static void test_one(void **state)
{
    const golden_case *c = (const golden_case *)*state;
    imgio_gray in, gold;
    char err[600];
    if (imgio_read_gray(c->input, &in, err, sizeof err) != 0 ||
        imgio_read_gray(c->path, &gold, err, sizeof err) != 0) {
        fail_msg("%s", err);
    }
    assert_int_equal(in.width, gold.width);
    assert_int_equal(in.height, gold.height);
    /* Padding is initialised to the guard byte in the output, so it doubles as a check. */
    run_and_compare(c, &in, &gold, 0, 0);
    run_and_compare(c, &in, &gold, 5, 3);
    imgio_free(&in);
    imgio_free(&gold);
}

static int cmp_names(const void *a, const void *b)
{
    return strcmp(((const struct CMUnitTest *)a)->name, ((const struct CMUnitTest *)b)->name);
}

int main(void)
{
    const char *dir = SYMLINE_GOLDEN "/core";
    DIR *d = opendir(dir);
    struct dirent *e;
    struct CMUnitTest *tests = NULL;
    size_t n = 0, cap = 0;
    int rc;
    if (d == NULL) {
        fprintf(stderr, "cannot open %s\n", dir);
        return 1;
    }
    while ((e = readdir(d)) != NULL) {
        golden_case *c;
        if (strstr(e->d_name, ".pgm") == NULL) {
            continue;
        }
        c = (golden_case *)calloc(1, sizeof *c);
        if (c == NULL || parse_name(dir, e->d_name, c) != 0) {
            fprintf(stderr, "bad golden file name %s\n", e->d_name);
            closedir(d);
            return 1;
        }
        if (n == cap) {
            cap = cap ? cap * 2 : 512;
            tests = (struct CMUnitTest *)realloc(tests, cap * sizeof *tests);
        }
        memset(&tests[n], 0, sizeof tests[n]);
        tests[n].name = strdup(e->d_name);
        tests[n].test_func = test_one;
        tests[n].initial_state = c;
        n++;
    }
    closedir(d);
    /* The suite must not pass vacuously: 18 inputs x 2 axes x 6 radii x 2 outputs. */
    if (n < 432) {
        fprintf(stderr, "only %zu golden files found in %s\n", n, dir);
        return 1;
    }
    qsort(tests, n, sizeof *tests, cmp_names);
    rc = _cmocka_run_group_tests("golden", tests, n, NULL, NULL);
    return rc;
}

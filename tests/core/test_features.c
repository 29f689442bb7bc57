/* SPDX-License-Identifier: Apache-2.0 */
/*
 * Symmetry feature points and the vertical symmetry histogram (docs/format.md):
 * hand-made images with known answers, the definition (two extrema maps of
 * symline_extrema()) on random images with long plateaus, the golden JSON of
 * the plain reference (tests/golden/features/), and argument errors.
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
#include "symline/features.h"
#include "symline/histogram.h"
#include "testutil.h"

/* Feature points of img through the API (asserts success); caller frees. */
static symline_point *features_of(const symline_image *img, uint32_t m, uint32_t *n)
{
    const size_t ws_size = symline_features_workspace_size(img->width, img->height, m);
    const uint32_t cap = symline_features_max_points(img->width, img->height);
    uint8_t *ws = tu_guard_alloc(ws_size);
    uint8_t *buf = tu_guard_alloc(((size_t)cap + 1u) * sizeof(symline_point));
    symline_point *pts = (symline_point *)malloc(((size_t)cap + 1u) * sizeof(symline_point));
    assert_true(ws_size > 0u);
    assert_non_null(pts);
    assert_int_equal(symline_features(img, m, ws, ws_size, (symline_point *)buf, cap, n),
                     SYMLINE_OK);
    assert_true(*n <= cap);
    assert_true(tu_guard_ok(ws, ws_size));
    assert_true(tu_guard_ok(buf, ((size_t)cap + 1u) * sizeof(symline_point)));
    memcpy(pts, buf, (size_t)*n * sizeof(symline_point));
    tu_guard_free(ws);
    tu_guard_free(buf);
    return pts;
}

static void histogram_of(const symline_image *img, uint32_t m, uint16_t *counts)
{
    const size_t ws_size = symline_histogram_workspace_size(img->width, m);
    uint8_t *ws = tu_guard_alloc(ws_size);
    assert_int_equal(symline_histogram(img, m, counts, img->width, ws, ws_size), SYMLINE_OK);
    assert_true(tu_guard_ok(ws, ws_size));
    tu_guard_free(ws);
}

/* Background of noise 0..59, so that S points of the background scatter. */
static uint8_t *noise_image(uint32_t w, uint32_t h, uint32_t seed)
{
    uint8_t *px = (uint8_t *)malloc((size_t)w * h);
    size_t i;
    assert_non_null(px);
    for (i = 0; i < (size_t)w * h; i++) {
        px[i] = (uint8_t)(tu_rand(&seed) % 60u);
    }
    return px;
}

/* A bright vertical bar 5 px wide: the histogram's one highest bin is its column, every row. */
static void test_bar_histogram_peak(void **state)
{
    const uint32_t w = 61, h = 40, bar = 23;
    uint8_t *px = noise_image(w, h, 0x2468ace1u);
    uint16_t counts[61];
    symline_image img = {61, 40, 61, NULL};
    uint32_t x, y, m;
    (void)state;
    for (y = 0; y < h; y++) {
        for (x = bar - 2u; x <= bar + 2u; x++) {
            px[(size_t)y * w + x] = 200u;
        }
    }
    img.data = px;
    for (m = 1u; m <= 3u; m++) {
        histogram_of(&img, m, counts);
        assert_int_equal(counts[bar], h);
        for (x = 0; x < w; x++) {
            if (x != bar) {
                assert_true(counts[x] < h);
            }
        }
    }
    free(px);
}

/* A plus sign of two 3 px wide arms: a feature point at its centre. */
static void test_cross_feature_at_centre(void **state)
{
    const uint32_t w = 45, h = 37, cx = 20, cy = 17, arm = 9;
    uint8_t *px = noise_image(w, h, 0x13579bdfu);
    symline_image img = {45, 37, 45, NULL};
    uint32_t x, y, m, i, n;
    (void)state;
    for (y = cy - 1u; y <= cy + 1u; y++) {
        for (x = cx - arm; x <= cx + arm; x++) {
            px[(size_t)y * w + x] = 220u;
        }
    }
    for (x = cx - 1u; x <= cx + 1u; x++) {
        for (y = cy - arm; y <= cy + arm; y++) {
            px[(size_t)y * w + x] = 220u;
        }
    }
    img.data = px;
    for (m = 1u; m <= 5u; m++) {
        symline_point *p = features_of(&img, m, &n);
        int found = 0;
        for (i = 0; i < n; i++) {
            found |= p[i].x == cx && p[i].y == cy;
        }
        if (!found) {
            fail_msg("radius %u: no feature point at the cross centre (%u, %u)", m, cx, cy);
        }
        free(p);
    }
    free(px);
}

/* The definition: S in both maps of symline_extrema(), raster order, and the
 * histogram = S points of the vertical map per column. Few gray levels make
 * long plateaus of equal energy (late, out-of-order reports down the columns). */
static void test_definition_random(void **state)
{
    uint32_t seed = 0x9e3779b9u, round;
    (void)state;
    for (round = 0; round < 60u; round++) {
        const uint32_t w = 1u + tu_rand(&seed) % 50u, h = 1u + tu_rand(&seed) % 50u;
        const uint32_t m = 1u + tu_rand(&seed) % 12u, levels = 2u + tu_rand(&seed) % 3u;
        const uint32_t pad = tu_rand(&seed) % 4u, stride = w + pad;
        uint8_t *px = (uint8_t *)malloc((size_t)stride * h);
        uint8_t *hm = (uint8_t *)malloc((size_t)w * h), *vm = (uint8_t *)malloc((size_t)w * h);
        uint16_t *counts = (uint16_t *)malloc(w * sizeof(uint16_t));
        symline_image img;
        symline_point *p;
        uint32_t x, y, n, k = 0u;
        size_t ws_size;
        void *ws;
        for (y = 0; y < h; y++) {
            for (x = 0; x < stride; x++) {
                /* blocks of constant value: plateaus in both directions */
                uint32_t v = tu_rand(&seed);
                px[(size_t)y * stride + x] =
                    (uint8_t)((v % 7u == 0u) ? (v >> 8) % levels * 80u
                                             : ((x / 3u + y / 4u) % levels) * 80u);
            }
        }
        img.width = w;
        img.height = h;
        img.stride = stride;
        img.data = px;
        ws_size = symline_extrema_workspace_size(w, h, SYMLINE_AXIS_HORIZONTAL, m);
        ws = malloc(ws_size);
        assert_int_equal(
            symline_extrema(&img, SYMLINE_AXIS_HORIZONTAL, m, hm, w, (size_t)w * h, ws, ws_size),
            SYMLINE_OK);
        free(ws);
        ws_size = symline_extrema_workspace_size(w, h, SYMLINE_AXIS_VERTICAL, m);
        ws = malloc(ws_size);
        assert_int_equal(
            symline_extrema(&img, SYMLINE_AXIS_VERTICAL, m, vm, w, (size_t)w * h, ws, ws_size),
            SYMLINE_OK);
        free(ws);
        p = features_of(&img, m, &n);
        for (y = 0; y < h; y++) {
            for (x = 0; x < w; x++) {
                const size_t i = (size_t)y * w + x;
                if (hm[i] == SYMLINE_MAP_S && vm[i] == SYMLINE_MAP_S) {
                    if (k >= n || p[k].x != x || p[k].y != y) {
                        fail_msg("round %u (%ux%u m=%u): feature %u should be (%u, %u)", round, w,
                                 h, m, k, x, y);
                    }
                    k++;
                }
            }
        }
        assert_int_equal(k, n);
        histogram_of(&img, m, counts);
        for (x = 0; x < w; x++) {
            uint32_t c = 0u;
            for (y = 0; y < h; y++) {
                c += vm[(size_t)y * w + x] == SYMLINE_MAP_S;
            }
            assert_int_equal(counts[x], c);
        }
        free(p);
        free(px);
        free(hm);
        free(vm);
        free(counts);
    }
}

/* The row call accumulates what the frame call computes. */
static void test_histogram_rows(void **state)
{
    const uint32_t w = 33, h = 21, m = 2;
    uint8_t *px = noise_image(w, h, 0xdeadbeefu);
    uint16_t a[33], b[33];
    symline_image img = {33, 21, 33, NULL};
    const size_t ws_size = symline_histogram_workspace_size(w, m);
    void *ws = malloc(ws_size);
    uint32_t y;
    (void)state;
    img.data = px;
    histogram_of(&img, m, a);
    memset(b, 0, sizeof b);
    for (y = 0; y < h; y++) {
        assert_int_equal(symline_histogram_row(px + (size_t)y * w, w, m, b, ws, ws_size),
                         SYMLINE_OK);
    }
    assert_memory_equal(a, b, sizeof a);
    free(ws);
    free(px);
}

static void test_errors(void **state)
{
    uint8_t px[12 * 10];
    symline_image img = {12, 10, 12, px};
    symline_point pts[64];
    uint16_t counts[12];
    uint8_t ws[4096];
    uint32_t n = 0, i, need;
    (void)state;
    for (i = 0; i < sizeof px; i++) {
        px[i] = (uint8_t)((i % 12u == 5u || i / 12u == 4u) ? 200u : (i * 37u) % 50u);
    }
    assert_int_equal(symline_features_workspace_size(0, 10, 3), 0u);
    assert_int_equal(symline_features_workspace_size(12, 10, 0), 0u);
    assert_int_equal(symline_histogram_workspace_size(12, 256), 0u);
    assert_int_equal(symline_features_max_points(2, 100), 0u);
    assert_int_equal(symline_features_max_points(5, 5), 5u);
    assert_int_equal(symline_features(NULL, 3, ws, sizeof ws, pts, 64, &n), SYMLINE_ERR_NULL);
    assert_int_equal(symline_features(&img, 3, NULL, sizeof ws, pts, 64, &n), SYMLINE_ERR_NULL);
    assert_int_equal(symline_features(&img, 3, ws, sizeof ws, NULL, 64, &n), SYMLINE_ERR_NULL);
    assert_int_equal(symline_features(&img, 0, ws, sizeof ws, pts, 64, &n), SYMLINE_ERR_RADIUS);
    assert_int_equal(symline_features(&img, 3, ws, 8, pts, 64, &n), SYMLINE_ERR_BUFFER);
    assert_int_equal(symline_features(&img, 1, ws, sizeof ws, pts, 64, &n), SYMLINE_OK);
    need = n;
    assert_true(need >= 1u);
    assert_int_equal(symline_features(&img, 1, ws, sizeof ws, pts, need - 1u, &n),
                     SYMLINE_ERR_BUFFER);
    assert_int_equal(n, need);
    img.stride = 11;
    assert_int_equal(symline_features(&img, 3, ws, sizeof ws, pts, 64, &n), SYMLINE_ERR_STRIDE);
    assert_int_equal(symline_histogram(&img, 3, counts, 12, ws, sizeof ws), SYMLINE_ERR_STRIDE);
    img.stride = 12;
    assert_int_equal(symline_histogram(&img, 3, counts, 11, ws, sizeof ws), SYMLINE_ERR_BUFFER);
    assert_int_equal(symline_histogram(&img, 3, NULL, 12, ws, sizeof ws), SYMLINE_ERR_NULL);
    assert_int_equal(symline_histogram(&img, 300, counts, 12, ws, sizeof ws), SYMLINE_ERR_RADIUS);
    assert_int_equal(symline_histogram(&img, 3, counts, 12, ws, 16), SYMLINE_ERR_BUFFER);
    assert_int_equal(symline_histogram_row(px, 0, 3, counts, ws, sizeof ws), SYMLINE_ERR_SIZE);
}

/* ---- golden JSON of the plain reference ---- */

typedef struct golden_json {
    char path[512];
    char input[512];
    uint32_t m;
    int features;
} golden_json;

static char *slurp(const char *path)
{
    FILE *f = fopen(path, "rb");
    char *s;
    long n;
    if (f == NULL) {
        return NULL;
    }
    fseek(f, 0, SEEK_END);
    n = ftell(f);
    fseek(f, 0, SEEK_SET);
    s = (char *)malloc((size_t)n + 1u);
    if (s != NULL && fread(s, 1, (size_t)n, f) != (size_t)n) {
        free(s);
        s = NULL;
    }
    if (s != NULL) {
        s[n] = '\0';
    }
    fclose(f);
    return s;
}

/* The JSON of `symline features|histogram` for img, built from the API. */
static char *json_of(const golden_json *c, const symline_image *img)
{
    size_t cap = 64u + (size_t)img->width * img->height * 16u, len;
    char *s = (char *)malloc(cap);
    uint32_t i;
    assert_non_null(s);
    len = (size_t)snprintf(s, cap, "{\"width\": %u, \"height\": %u, \"radius\": %u, ", img->width,
                           img->height, c->m);
    if (c->features) {
        uint32_t n;
        symline_point *p = features_of(img, c->m, &n);
        len += (size_t)snprintf(s + len, cap - len, "\"points\": [");
        for (i = 0; i < n; i++) {
            len += (size_t)snprintf(s + len, cap - len, i ? ", [%u, %u]" : "[%u, %u]",
                                    (unsigned)p[i].x, (unsigned)p[i].y);
        }
        free(p);
    } else {
        uint16_t *counts = (uint16_t *)malloc(img->width * sizeof(uint16_t));
        histogram_of(img, c->m, counts);
        len += (size_t)snprintf(s + len, cap - len, "\"counts\": [");
        for (i = 0; i < img->width; i++) {
            len += (size_t)snprintf(s + len, cap - len, i ? ", %u" : "%u", (unsigned)counts[i]);
        }
        free(counts);
    }
    snprintf(s + len, cap - len, "]}\n");
    return s;
}

static void test_golden_one(void **state)
{
    const golden_json *c = (const golden_json *)*state;
    imgio_gray in;
    char err[600], *want, *got;
    uint32_t pad;
    if (imgio_read_gray(c->input, &in, err, sizeof err) != 0) {
        fail_msg("%s", err);
    }
    want = slurp(c->path);
    assert_non_null(want);
    for (pad = 0; pad <= 3u; pad += 3u) {
        const uint32_t stride = in.width + pad;
        uint8_t *px = (uint8_t *)malloc((size_t)stride * in.height);
        symline_image img;
        uint32_t y;
        memset(px, 0xA5, (size_t)stride * in.height);
        for (y = 0; y < in.height; y++) {
            memcpy(px + (size_t)y * stride, in.px + (size_t)y * in.width, in.width);
        }
        img.width = in.width;
        img.height = in.height;
        img.stride = stride;
        img.data = px;
        got = json_of(c, &img);
        if (strcmp(got, want) != 0) {
            fail_msg("%s differs from the library's output (stride %u)", c->path, stride);
        }
        free(got);
        free(px);
    }
    free(want);
    imgio_free(&in);
}

int main(void)
{
    static const struct CMUnitTest fixed[] = {
        cmocka_unit_test(test_bar_histogram_peak),
        cmocka_unit_test(test_cross_feature_at_centre),
        cmocka_unit_test(test_definition_random),
        cmocka_unit_test(test_histogram_rows),
        cmocka_unit_test(test_errors),
    };
    const char *dir = SYMLINE_GOLDEN "/features";
    struct CMUnitTest golden[256];
    DIR *d = opendir(dir);
    struct dirent *e;
    size_t n = 0;
    int rc;
    if (d == NULL) {
        fprintf(stderr, "cannot open %s\n", dir);
        return 1;
    }
    while ((e = readdir(d)) != NULL && n < 256u) {
        /* "<set>_<base>.m<R>.<features|histogram>.json" */
        golden_json *c = (golden_json *)calloc(1, sizeof *c);
        char name[256], *us, *dot;
        if (strstr(e->d_name, ".json") == NULL || strlen(e->d_name) >= sizeof name) {
            free(c);
            continue;
        }
        strcpy(name, e->d_name);
        us = strchr(name, '_');
        dot = strstr(name, ".m");
        if (c == NULL || us == NULL || dot == NULL) {
            fprintf(stderr, "bad golden file name %s\n", e->d_name);
            free(c);
            closedir(d);
            return 1;
        }
        *us = '\0';
        *dot = '\0';
        c->m = (uint32_t)atoi(dot + 2);
        c->features = strstr(dot + 2, ".features.") != NULL;
        snprintf(c->path, sizeof c->path, "%s/%s", dir, e->d_name);
        snprintf(c->input, sizeof c->input, "%s/%s/%s.pgm", SYMLINE_TEST_DATA, name, us + 1);
        golden[n].name = strdup(e->d_name);
        golden[n].test_func = test_golden_one;
        golden[n].setup_func = NULL;
        golden[n].teardown_func = NULL;
        golden[n].initial_state = c;
        n++;
    }
    closedir(d);
    /* Must not pass vacuously: 18 inputs x 3 radii x 2 outputs. */
    if (n < 108u) {
        fprintf(stderr, "only %zu golden files found in %s\n", n, dir);
        return 1;
    }
    rc = cmocka_run_group_tests_name("features", fixed, NULL, NULL);
    rc |= _cmocka_run_group_tests("features_golden", golden, n, NULL, NULL);
    while (n-- > 0u) {
        free((void *)golden[n].name);
        free(golden[n].initial_state);
    }
    return rc;
}

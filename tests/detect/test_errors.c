/* SPDX-License-Identifier: Apache-2.0 */
/*
 * The error contract of the public entry points (docs/errors.md): each bad
 * argument gives its status code, and a call that fails leaves every
 * caller-visible output as it was. Every configuration field is tried just
 * outside its range and at its limit.
 */
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <stdlib.h>
#include <string.h>

#include <cmocka.h>

#include "symline/detect.h"
#include "symline/extrema.h"
#include "symline/symmetry.h"

#define W 96u
#define H 72u

static uint8_t frame[W * H];

/* Gray 40 with a bright horizontal and a bright vertical bar, 3 px wide. */
static void make_frame(void)
{
    uint32_t x, y;
    for (y = 0; y < H; y++) {
        for (x = 0; x < W; x++) {
            frame[y * W + x] =
                (uint8_t)((y >= 30u && y < 33u) || (x >= 60u && x < 63u) ? 220u : 40u);
        }
    }
}

typedef struct outputs {
    symline_segment segs[64];
    symline_point pts[4 * W * H];
    symline_result res;
} outputs;

static outputs out_a, out_b;

/* The result fields of a and b alike (each pointing at its own arrays). */
static void assert_same_result(const outputs *a, const outputs *b)
{
    assert_ptr_equal(a->res.segments, a->segs);
    assert_ptr_equal(a->res.points, a->pts);
    assert_int_equal(a->res.segment_cap, b->res.segment_cap);
    assert_int_equal(a->res.point_cap, b->res.point_cap);
    assert_int_equal(a->res.segment_count, b->res.segment_count);
    assert_int_equal(a->res.point_count, b->res.point_count);
    assert_int_equal(a->res.truncated, b->res.truncated);
    assert_memory_equal(a->segs, b->segs, sizeof a->segs);
    assert_memory_equal(a->pts, b->pts, sizeof a->pts);
}

static void outputs_reset(outputs *o)
{
    memset(o->segs, 0x5A, sizeof o->segs);
    memset(o->pts, 0x5A, sizeof o->pts);
    o->res.segments = o->segs;
    o->res.segment_cap = 64u;
    o->res.points = o->pts;
    o->res.point_cap = 4u * W * H;
    o->res.segment_count = 12345u;
    o->res.point_count = 54321u;
    o->res.truncated = true;
}

/* symline_detect() with cfg: its status; on an error, asserts nothing changed. */
static symline_status detect_with(const symline_config *cfg)
{
    const symline_image img = {W, H, W, frame};
    symline_config def;
    size_t n;
    void *ws;
    symline_status st;
    symline_config_default(&def);
    n = symline_detect_workspace_size(W, H, &def);
    ws = malloc(n + 4096u);
    outputs_reset(&out_a);
    outputs_reset(&out_b);
    st = symline_detect(&img, cfg, ws, n + 4096u, &out_a.res);
    if (st != SYMLINE_OK) {
        assert_same_result(&out_a, &out_b);
        /* An invalid configuration has no workspace size either. */
        assert_int_equal(symline_detect_workspace_size(W, H, cfg), 0);
    }
    free(ws);
    return st;
}

/* A field set to `bad` is ERR_CONFIG, set to `good` (its limit) it is fine. */
#define FIELD(name, good, bad)                                                                     \
    do {                                                                                           \
        symline_config c;                                                                          \
        symline_config_default(&c);                                                                \
        c.name = bad;                                                                              \
        if (detect_with(&c) != SYMLINE_ERR_CONFIG) {                                               \
            fail_msg("%s = %s accepted", #name, #bad);                                             \
        }                                                                                          \
        symline_config_default(&c);                                                                \
        c.name = good;                                                                             \
        if (detect_with(&c) != SYMLINE_OK) {                                                       \
            fail_msg("%s = %s refused", #name, #good);                                             \
        }                                                                                          \
    } while (0)

static void every_config_field_at_and_past_its_limits(void **state)
{
    (void)state;
    make_frame();
    FIELD(axes, SYMLINE_AXES_BOTH, (symline_axes)3);
    FIELD(radius, 1u, 0u);
    FIELD(radius, SYMLINE_DETECT_MAX_RADIUS, SYMLINE_DETECT_MAX_RADIUS + 1u);
    FIELD(levels, SYMLINE_DETECT_MAX_LEVELS, SYMLINE_DETECT_MAX_LEVELS + 1u);
    FIELD(filter, SYMLINE_FILTER_PAPER, (symline_filter)2);
    FIELD(illumination, 255u, 256u);
    FIELD(bright_sigma10, -100, -101);
    FIELD(bright_sigma10, 100, 101);
    FIELD(ridge_sigma10, 100u, 101u);
    FIELD(side_sigma10, -100, -101);
    FIELD(side_sigma10, 100, 101);
    FIELD(a_distance, SYMLINE_DETECT_MAX_A_DISTANCE, SYMLINE_DETECT_MAX_A_DISTANCE + 1u);
    FIELD(contrast_pct, 100u, 101u);
    FIELD(contrast_min, 255u, 256u);
    FIELD(contrast_asym_pct, 1000u, 1001u);
    FIELD(min_length, 65535u, 65536u);
    FIELD(curve_dev_q8, 65535u << 8, (65535u << 8) + 1u);
    FIELD(curve_bend_q8, 65535u << 8, (65535u << 8) + 1u);
    FIELD(merge_dev_q8, 65535u << 8, (65535u << 8) + 1u);
    /* merge_gap: 0..65535 or SYMLINE_MERGE_GAP_AUTO; from 2^24 its square wrapped. */
    FIELD(merge_gap, 65535u, 65536u);
    FIELD(merge_gap, SYMLINE_MERGE_GAP_AUTO, 1u << 24);
    FIELD(merge_gap, 0u, SYMLINE_MERGE_GAP_AUTO - 1u);
    FIELD(field_boundary, SYMLINE_FIELD_KEEP, (symline_field_mode)3);
    FIELD(field_margin, 65535u, 65536u);
}

static void detect_argument_errors(void **state)
{
    symline_config cfg;
    symline_image img = {W, H, W, frame};
    size_t n;
    uint8_t *ws;
    (void)state;
    make_frame();
    symline_config_default(&cfg);
    n = symline_detect_workspace_size(W, H, &cfg);
    assert_true(n > 0u);
    ws = (uint8_t *)malloc(n);
    outputs_reset(&out_a);
    assert_int_equal(symline_detect(NULL, &cfg, ws, n, &out_a.res), SYMLINE_ERR_NULL);
    assert_int_equal(symline_detect(&img, NULL, ws, n, &out_a.res), SYMLINE_ERR_NULL);
    assert_int_equal(symline_detect(&img, &cfg, NULL, n, &out_a.res), SYMLINE_ERR_NULL);
    assert_int_equal(symline_detect(&img, &cfg, ws, n, NULL), SYMLINE_ERR_NULL);
    out_a.res.points = NULL; /* NULL with a capacity */
    assert_int_equal(symline_detect(&img, &cfg, ws, n, &out_a.res), SYMLINE_ERR_NULL);
    outputs_reset(&out_a);
    out_a.res.segments = NULL;
    assert_int_equal(symline_detect(&img, &cfg, ws, n, &out_a.res), SYMLINE_ERR_NULL);
    outputs_reset(&out_a);
    img.data = NULL;
    assert_int_equal(symline_detect(&img, &cfg, ws, n, &out_a.res), SYMLINE_ERR_NULL);
    img.data = frame;
    img.width = 0u;
    assert_int_equal(symline_detect(&img, &cfg, ws, n, &out_a.res), SYMLINE_ERR_SIZE);
    img.width = SYMLINE_MAX_DIM + 1u;
    assert_int_equal(symline_detect(&img, &cfg, ws, n, &out_a.res), SYMLINE_ERR_SIZE);
    img.width = W;
    img.height = 0u;
    assert_int_equal(symline_detect(&img, &cfg, ws, n, &out_a.res), SYMLINE_ERR_SIZE);
    img.height = H;
    img.stride = W - 1u;
    assert_int_equal(symline_detect(&img, &cfg, ws, n, &out_a.res), SYMLINE_ERR_STRIDE);
    img.stride = W;
    /* Workspace one byte short, and none. */
    assert_int_equal(symline_detect(&img, &cfg, ws, n - 1u, &out_a.res), SYMLINE_ERR_BUFFER);
    assert_int_equal(symline_detect(&img, &cfg, ws, 0u, &out_a.res), SYMLINE_ERR_BUFFER);
    /* Nothing of the result was touched by any of these. */
    outputs_reset(&out_b);
    assert_same_result(&out_a, &out_b);
    assert_int_equal(symline_detect_workspace_size(0u, H, &cfg), 0);
    assert_int_equal(symline_detect_workspace_size(W, SYMLINE_MAX_DIM + 1u, &cfg), 0);
    assert_int_equal(symline_detect_workspace_size(W, H, NULL), 0);
    free(ws);
}

/* Output storage of capacity 0 (NULL allowed then): the detection runs, finds
 * lines it cannot store and says so (truncated); NULL + 0 was computed here. */
static void zero_capacity_outputs(void **state)
{
    symline_config cfg;
    const symline_image img = {W, H, W, frame};
    symline_result r;
    size_t n;
    void *ws;
    (void)state;
    make_frame();
    symline_config_default(&cfg);
    n = symline_detect_workspace_size(W, H, &cfg);
    ws = malloc(n);
    memset(&r, 0, sizeof r);
    assert_int_equal(symline_detect(&img, &cfg, ws, n, &r), SYMLINE_OK);
    assert_int_equal(r.segment_count, 0);
    assert_int_equal(r.point_count, 0);
    assert_true(r.truncated);
    /* Points but no segments. */
    outputs_reset(&out_a);
    out_a.res.segments = NULL;
    out_a.res.segment_cap = 0u;
    assert_int_equal(symline_detect(&img, &cfg, ws, n, &out_a.res), SYMLINE_OK);
    assert_int_equal(out_a.res.segment_count, 0);
    assert_true(out_a.res.truncated);
    /* With room: the two bars, nothing truncated. */
    outputs_reset(&out_a);
    assert_int_equal(symline_detect(&img, &cfg, ws, n, &out_a.res), SYMLINE_OK);
    assert_true(out_a.res.segment_count >= 2u);
    assert_false(out_a.res.truncated);
    free(ws);
}

/* The operator and extrema: each bad argument its code, outputs untouched. */
static void operator_argument_errors(void **state)
{
    static uint8_t out[W * H], ref[W * H];
    static uint32_t E[W * H];
    symline_image img = {W, H, W, frame};
    const size_t n = W * H;
    size_t ws_n;
    uint8_t *ws;
    (void)state;
    make_frame();
    ws_n = symline_extrema_workspace_size(W, H, SYMLINE_AXIS_HORIZONTAL, 3u);
    assert_true(ws_n >= symline_symmetry_workspace_size(W, H, SYMLINE_AXIS_HORIZONTAL, 3u));
    ws = (uint8_t *)malloc(ws_n);
    memset(out, 0x77, sizeof out);
    memcpy(ref, out, sizeof out);
#define BOTH(expect, img_, axis_, m_, out_, stride_, len_, ws_, wsn_)                              \
    do {                                                                                           \
        assert_int_equal(symline_symmetry(img_, axis_, m_, out_, stride_, len_, ws_, wsn_),        \
                         expect);                                                                  \
        assert_int_equal(symline_extrema(img_, axis_, m_, out_, stride_, len_, ws_, wsn_),         \
                         expect);                                                                  \
        assert_memory_equal(out, ref, sizeof out);                                                 \
    } while (0)
    BOTH(SYMLINE_ERR_NULL, NULL, SYMLINE_AXIS_HORIZONTAL, 3u, out, W, n, ws, ws_n);
    BOTH(SYMLINE_ERR_NULL, &img, SYMLINE_AXIS_HORIZONTAL, 3u, NULL, W, n, ws, ws_n);
    BOTH(SYMLINE_ERR_NULL, &img, SYMLINE_AXIS_HORIZONTAL, 3u, out, W, n, NULL, ws_n);
    BOTH(SYMLINE_ERR_RADIUS, &img, SYMLINE_AXIS_HORIZONTAL, 0u, out, W, n, ws, ws_n);
    BOTH(SYMLINE_ERR_RADIUS, &img, SYMLINE_AXIS_HORIZONTAL, SYMLINE_MAX_RADIUS + 1u, out, W, n, ws,
         ws_n);
    BOTH(SYMLINE_ERR_AXIS, &img, (symline_axis)2, 3u, out, W, n, ws, ws_n);
    BOTH(SYMLINE_ERR_STRIDE, &img, SYMLINE_AXIS_HORIZONTAL, 3u, out, W - 1u, n, ws, ws_n);
    BOTH(SYMLINE_ERR_BUFFER, &img, SYMLINE_AXIS_HORIZONTAL, 3u, out, W, n - 1u, ws, ws_n);
    BOTH(SYMLINE_ERR_BUFFER, &img, SYMLINE_AXIS_HORIZONTAL, 3u, out, W, 0u, ws, ws_n);
    BOTH(SYMLINE_ERR_BUFFER, &img, SYMLINE_AXIS_HORIZONTAL, 3u, out, W, n, ws, 0u);
    img.stride = W - 1u;
    BOTH(SYMLINE_ERR_STRIDE, &img, SYMLINE_AXIS_HORIZONTAL, 3u, out, W, n, ws, ws_n);
    img.stride = W;
    img.width = 0u;
    BOTH(SYMLINE_ERR_SIZE, &img, SYMLINE_AXIS_HORIZONTAL, 3u, out, W, n, ws, ws_n);
    img.width = SYMLINE_MAX_DIM + 1u;
    BOTH(SYMLINE_ERR_SIZE, &img, SYMLINE_AXIS_HORIZONTAL, 3u, out, W, n, ws, ws_n);
    img.width = W;
    /* Energies: an E plane one element short. */
    memset(E, 0x77, sizeof E);
    assert_int_equal(symline_energy_frame(&img, SYMLINE_AXIS_VERTICAL, 3u, E, W, n - 1u),
                     SYMLINE_ERR_BUFFER);
    assert_int_equal(symline_energy_frame(&img, SYMLINE_AXIS_VERTICAL, 3u, E, W - 1u, n),
                     SYMLINE_ERR_STRIDE);
    assert_int_equal(E[0], 0x77777777u);
    assert_int_equal(symline_energy_row(NULL, W, 3u, E), SYMLINE_ERR_NULL);
    assert_int_equal(symline_energy_row(frame, 0u, 3u, E), SYMLINE_ERR_SIZE);
    assert_int_equal(symline_energy_row(frame, W, 0u, E), SYMLINE_ERR_RADIUS);
    assert_int_equal(symline_energy_across_image(&img, H, 3u, E), SYMLINE_ERR_RANGE);
    assert_int_equal(E[0], 0x77777777u);
    /* The good calls work with exactly-sized buffers. */
    assert_int_equal(symline_symmetry(&img, SYMLINE_AXIS_HORIZONTAL, 3u, out, W, n, ws, ws_n),
                     SYMLINE_OK);
    assert_int_equal(symline_extrema(&img, SYMLINE_AXIS_HORIZONTAL, 3u, out, W, n, ws, ws_n),
                     SYMLINE_OK);
    free(ws);
#undef BOTH
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(every_config_field_at_and_past_its_limits),
        cmocka_unit_test(detect_argument_errors),
        cmocka_unit_test(zero_capacity_outputs),
        cmocka_unit_test(operator_argument_errors),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}

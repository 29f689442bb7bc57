/* SPDX-License-Identifier: Apache-2.0 */
/*
 * Fuzz target: the vertical symmetry histogram (symline/histogram.h).
 * symline_histogram() with fuzzer-chosen geometry and stride, radius (0,
 * 1..11, 253..258), counts length and workspace size (exact, one short, zero,
 * larger) and NULL pointers; symline_histogram_row() on one row with
 * fuzzer-chosen starting counts (65535 too), width, radius and workspace.
 * Checks: no read past the pixels (allocated to the byte), guard bytes after
 * the counts and the workspace untouched, a known status, the counts
 * untouched on an error; on success the frame's counts equal the sum of
 * symline_histogram_row() over its rows, are 0 in the first and last
 * columns and at most the height, and a row adds 0 or 1 per column,
 * saturating at 65535.
 */
#include <stdint.h>
#include <stdlib.h>
#include <string.h>

#include "fuzz_lib.h"
#include "symline/histogram.h"

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size);

static uint32_t pick_radius(fz_in *in)
{
    const uint32_t v = fz_u8(in);
    if (v >= 250u) {
        return 253u + (v - 250u);
    }
    return v % 12u;
}

static uint32_t pick_width(fz_in *in)
{
    const uint32_t v = fz_u8(in);
    if (v == 255u) {
        return 65536u;
    }
    if (v == 254u) {
        return 65535u;
    }
    if (v == 253u) {
        return 1000u + fz_u16(in) % 64536u;
    }
    return v % 128u; /* 0 (invalid) .. 127 */
}

static void entry_frame(fz_in *in)
{
    uint32_t w = pick_width(in), h = fz_dim(in), stride, m, len, x, y;
    const uint32_t nulls = fz_u8(in);
    const int none = (nulls & 0xC0u) == 0xC0u;
    size_t img_len, wsq, wsn, cb;
    uint8_t *px, *ws, *counts;
    symline_image img;
    symline_status st;

    if (w > 1000u && h > 4u) {
        h = 1u + h % 4u;
    }
    stride = w + (fz_u8(in) % 4u == 0u ? fz_u8(in) % 9u : 0u);
    if (fz_u8(in) % 16u == 0u && w > 0u) {
        stride = w - 1u;
    }
    m = pick_radius(in);
    wsq = symline_histogram_workspace_size(w, m);
    if ((wsq > 0u) != (w >= 1u && w <= 65535u && m >= 1u && m <= 255u)) {
        abort();
    }
    wsn = fz_size(in, wsq > 0u ? wsq : 64u);
    len = (uint32_t)fz_size(in, w);
    cb = (size_t)len * 2u;
    counts = fz_buf(cb, 0x5A);
    ws = fz_buf(wsn, 0x33);
    if (w > 65535u && h > 1u) {
        h = 1u;
    }
    px = fz_image(in, w, h, stride > w ? stride : w, &img_len);
    img.width = w;
    img.height = h;
    img.stride = stride;
    img.data = none && (nulls & 1u) ? NULL : px;
    st = symline_histogram(none && (nulls & 2u) ? NULL : &img, m,
                           none && (nulls & 4u) ? NULL : (uint16_t *)(void *)counts, len,
                           none && (nulls & 8u) ? NULL : ws, wsn);
    fz_check_status(st, "symline_histogram");
    fz_check_guard(counts, cb, "counts");
    fz_check_guard(ws, wsn, "workspace");
    if (st != SYMLINE_OK) {
        fz_check_untouched(counts, cb, 0x5A, "counts");
    } else {
        /* The same from the rows, one at a time. */
        uint16_t *sum = (uint16_t *)calloc((size_t)w + 1u, sizeof *sum);
        const uint16_t *c = (const uint16_t *)(const void *)counts;
        if (sum == NULL) {
            abort();
        }
        for (y = 0; y < h; y++) {
            if (symline_histogram_row(px + (size_t)y * stride, w, m, sum, ws, wsn) != SYMLINE_OK) {
                abort();
            }
        }
        fz_check_guard(ws, wsn, "workspace");
        for (x = 0; x < w; x++) {
            if (c[x] != sum[x] || c[x] > h || ((x == 0u || x + 1u == w) && c[x] != 0u)) {
                fprintf(stderr, "histogram column %u: %u, rows sum to %u, height %u\n", x, c[x],
                        sum[x], h);
                abort();
            }
        }
        fz_check_untouched(counts + (size_t)w * 2u, cb - (size_t)w * 2u, 0x5A,
                           "counts beyond width");
        free(sum);
    }
    free(px);
    free(ws);
    free(counts);
}

static void entry_row(fz_in *in)
{
    const uint32_t w = pick_width(in), m = pick_radius(in);
    const uint32_t nulls = fz_u8(in);
    const int none = (nulls & 0xC0u) == 0xC0u;
    const uint32_t n = w > 65535u ? 65536u : w;
    size_t wsq = symline_histogram_workspace_size(w, m), wsn, img_len, x;
    uint8_t *ws, *counts, *px;
    uint16_t *start;
    symline_status st;

    wsn = fz_size(in, wsq > 0u ? wsq : 64u);
    counts = fz_buf((size_t)n * 2u, 0);
    start = (uint16_t *)(void *)counts;
    for (x = 0; x < n; x++) {
        const uint32_t v = fz_u8(in);
        start[x] = (uint16_t)(v >= 192u ? 65535u - v % 2u : v % 4u);
    }
    {
        uint16_t *copy = (uint16_t *)malloc((size_t)n * 2u + 2u);
        if (copy == NULL) {
            abort();
        }
        memcpy(copy, start, (size_t)n * 2u);
        ws = fz_buf(wsn, 0x33);
        px = fz_image(in, n > 0u ? n : 1u, 1u, n > 0u ? n : 1u, &img_len);
        st = symline_histogram_row(none && (nulls & 1u) ? NULL : px, w, m,
                                   none && (nulls & 2u) ? NULL : start,
                                   none && (nulls & 4u) ? NULL : ws, wsn);
        fz_check_status(st, "symline_histogram_row");
        fz_check_guard(counts, (size_t)n * 2u, "counts");
        fz_check_guard(ws, wsn, "workspace");
        for (x = 0; x < n; x++) {
            const uint32_t d = (uint32_t)start[x] - copy[x];
            if (st != SYMLINE_OK
                    ? start[x] != copy[x]
                    : (start[x] < copy[x] || d > 1u || (copy[x] == 65535u && start[x] != 65535u) ||
                       ((x == 0u || x + 1u == n) && d != 0u))) {
                fprintf(stderr, "histogram row column %zu: %u -> %u (status %d)\n", x, copy[x],
                        start[x], (int)st);
                abort();
            }
        }
        free(copy);
    }
    free(px);
    free(ws);
    free(counts);
}

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
    fz_in in = {data, size};
    if (fz_u8(&in) & 1u) {
        entry_row(&in);
    } else {
        entry_frame(&in);
    }
    return 0;
}

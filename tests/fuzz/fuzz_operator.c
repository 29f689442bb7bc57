/* SPDX-License-Identifier: Apache-2.0 */
/*
 * Fuzz target: the operator and extrema entry points with fuzzer-chosen
 * width, height, strides, radius, axis, NULL pointers and buffer sizes
 * (exact, one short, zero, larger). Checks: no read past the image (the
 * pixels are allocated to the byte), no write past an output (guard bytes),
 * and nothing written by a call that fails.
 */
#include <stdint.h>
#include <stdlib.h>
#include <string.h>

#include "fuzz_util.h"
#include "symline/extrema.h"
#include "symline/symmetry.h"

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size);

/* 1..48 mostly; sometimes 0 or 65536 (invalid), or 65535 (then the other side is 1). */
static uint32_t pick_dim(fz_in *in)
{
    const uint32_t v = fz_u8(in);
    if (v == 0u) {
        return 0u;
    }
    if (v == 255u) {
        return 65536u;
    }
    if (v == 254u) {
        return 65535u;
    }
    return 1u + v % 48u;
}

static uint32_t pick_stride(fz_in *in, uint32_t w)
{
    const uint32_t v = fz_u8(in) % 8u;
    if (v == 0u) {
        return w > 0u ? w - 1u : 0u; /* too small: ERR_STRIDE */
    }
    return w + (v == 1u ? 0u : fz_u8(in) % 17u);
}

static uint32_t pick_radius(fz_in *in)
{
    const uint32_t v = fz_u8(in);
    if (v >= 250u) {
        return 253u + (v - 250u); /* 253 .. 258: around the largest valid radius */
    }
    return v % 12u; /* 0 (invalid) .. 11 */
}

/* A guarded output of n bytes; NULL (for the NULL checks) when null is set. */
static uint8_t *out_buf(size_t n, int null)
{
    return null ? NULL : fz_buf(n, 0x5A);
}

static void done_out(uint8_t *b, size_t n, symline_status st, const char *what)
{
    if (b == NULL) {
        return;
    }
    fz_check_guard(b, n, what);
    if (st != SYMLINE_OK) {
        fz_check_untouched(b, n, 0x5A, what);
    }
    free(b);
}

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
    fz_in in = {data, size};
    const uint32_t entry = fz_u8(&in) % 9u;
    uint32_t w = pick_dim(&in), h = pick_dim(&in);
    const uint32_t nulls =
        fz_u8(&in); /* bit 0: image/input NULL, bit 1: output NULL, bit 2: ws NULL */
    uint32_t stride, m;
    symline_axis axis;
    symline_image img;
    symline_status st = SYMLINE_OK;
    size_t img_len;
    uint8_t *px;
    if (w >= 65535u && h >= 65535u) {
        h = 1u;
    } else if ((w >= 65535u && h > 2u) || (h >= 65535u && w > 2u)) {
        return 0; /* keep every execution small */
    }
    stride = pick_stride(&in, w);
    m = pick_radius(&in);
    if ((w >= 4096u || h >= 4096u) && m > 11u) {
        /* the largest radii on the longest strips cost seconds under the
         * sanitizers (h * m row sums): keep them to the smaller images */
        m = 1u + m % 11u;
    }
    axis = (symline_axis)(fz_u8(&in) % 3u); /* 2: not an axis */
    px = fz_image(&in, w, h, stride > w ? stride : w, &img_len);
    img.width = w;
    img.height = h;
    img.stride = stride;
    img.data = (nulls & 1u) ? NULL : px;

    switch (entry) {
    case 0: { /* one row along the row */
        const size_t n = (size_t)w * 4u;
        uint8_t *E = out_buf(n, (nulls & 2u) != 0u);
        st = symline_energy_row((nulls & 1u) ? NULL : px, w > 65536u ? 1u : (w <= img_len ? w : 0u),
                                m, (uint32_t *)(void *)E);
        done_out(E, n, st, "energy_row E");
        break;
    }
    case 1: { /* one row across 2m+1 rows, some of them outside the image */
        const uint32_t span = (m >= 1u && m <= 300u) ? 2u * m + 1u : 1u;
        const uint8_t **rows = (const uint8_t **)calloc(span, sizeof *rows);
        const uint32_t holes = fz_u32(&in);
        const size_t n = (size_t)w * 4u;
        uint8_t *E = out_buf(n, (nulls & 2u) != 0u);
        uint32_t i;
        if (rows == NULL) {
            abort();
        }
        for (i = 0; i < span; i++) {
            /* Each non-NULL row holds exactly w pixels of the image buffer. */
            const uint32_t y = h > 0u ? i % h : 0u;
            const int hole = (holes >> (i % 32u)) & 1u;
            rows[i] = (hole || w == 0u || (size_t)y * stride + w > img_len)
                          ? NULL
                          : px + (size_t)y * stride;
        }
        if (nulls & 1u) {
            rows[span / 2u] = NULL; /* the centre row must not be NULL */
        }
        st = symline_energy_across((nulls & 4u) ? NULL : rows, m, w, (uint32_t *)(void *)E);
        done_out(E, n, st, "energy_across E");
        free((void *)rows);
        break;
    }
    case 2: { /* a row of a whole image, y possibly outside */
        const uint32_t y = h > 0u ? fz_u32(&in) % (h + 2u) : 0u;
        const size_t n = (size_t)w * 4u;
        uint8_t *E = out_buf(n, (nulls & 2u) != 0u);
        st = symline_energy_across_image(&img, y, m, (uint32_t *)(void *)E);
        done_out(E, n, st, "energy_across_image E");
        break;
    }
    case 3: { /* energies to S8: E values from the input, some above Emax */
        const uint32_t n = w > 4096u ? 4096u : w;
        uint32_t *E = (uint32_t *)malloc((size_t)n * 4u + 4u);
        uint8_t *out = out_buf(n, (nulls & 2u) != 0u);
        const uint32_t emax = symline_emax(m);
        uint32_t i;
        if (E == NULL) {
            abort();
        }
        for (i = 0; i < n; i++) {
            const uint32_t v = fz_u32(&in);
            E[i] = (v & 1u) ? v : (emax > 0u ? v % (emax + 1u) : v);
        }
        st = symline_s8_row((nulls & 1u) ? NULL : E, n, m, out);
        done_out(out, n, st, "s8_row out");
        free(E);
        break;
    }
    case 4: { /* whole-frame energies with a fuzzed E stride and length */
        const uint32_t es = pick_stride(&in, w);
        const size_t need = (h > 0u && w > 0u) ? (size_t)(h - 1u) * es + w : 0u;
        const size_t len = fz_size(&in, need);
        uint8_t *E = out_buf(len * 4u, (nulls & 2u) != 0u);
        st = symline_energy_frame(&img, axis, m, (uint32_t *)(void *)E, es, len);
        done_out(E, len * 4u, st, "energy_frame E");
        break;
    }
    case 5:   /* the symmetry image */
    case 8: { /* the extrema map */
        const uint32_t os = pick_stride(&in, w);
        const size_t need = (h > 0u && w > 0u) ? (size_t)(h - 1u) * os + w : 0u;
        const size_t len = fz_size(&in, need);
        const size_t wsq = entry == 5u ? symline_symmetry_workspace_size(w, h, axis, m)
                                       : symline_extrema_workspace_size(w, h, axis, m);
        const size_t wsn = fz_size(&in, wsq > 0u ? wsq : fz_u16(&in));
        uint8_t *out = out_buf(len, (nulls & 2u) != 0u);
        uint8_t *ws = (nulls & 4u) ? NULL : fz_buf(wsn, 0x33);
        if (entry == 5u) {
            st = symline_symmetry(&img, axis, m, out, os, len, ws, wsn);
        } else {
            st = symline_extrema(&img, axis, m, out, os, len, ws, wsn);
        }
        done_out(out, len, st, entry == 5u ? "symmetry out" : "extrema map");
        if (ws != NULL) {
            fz_check_guard(ws, wsn, "workspace");
            free(ws);
        }
        break;
    }
    case 6: { /* extrema of one row */
        const uint32_t n = w > 4096u ? 4096u : w;
        uint32_t *E = (uint32_t *)malloc((size_t)n * 4u + 4u);
        uint8_t *map = out_buf(n, (nulls & 2u) != 0u);
        uint32_t i;
        if (E == NULL) {
            abort();
        }
        for (i = 0; i < n; i++) {
            E[i] = fz_u8(&in) % 4u; /* few values: long equal runs */
        }
        st = symline_extrema_row((nulls & 1u) ? NULL : E, n, map);
        done_out(map, n, st, "extrema_row map");
        free(E);
        break;
    }
    case 7: { /* the column-run follower over h rows */
        symline_colrun cr;
        const size_t bq = symline_colrun_buffer_size(w);
        const size_t bn = fz_size(&in, bq > 0u ? bq : 64u);
        uint8_t *buf = fz_buf(bn, 0x11);
        const uint32_t wn = w > 4096u ? 4096u : w;
        const uint32_t cap = fz_u8(&in) % 3u == 0u ? (wn > 0u ? wn - 1u : 0u) : wn;
        uint32_t *E = (uint32_t *)malloc((size_t)wn * 4u + 4u);
        uint8_t *ev = fz_buf((size_t)cap * sizeof(symline_extremum), 0x22);
        const uint32_t rows = w > 4096u ? 0u : (h > 200u ? 200u : h);
        uint32_t y, i;
        if (E == NULL) {
            abort();
        }
        st = symline_colrun_init(&cr, w, (nulls & 4u) ? NULL : buf, bn);
        for (y = 0; st == SYMLINE_OK && y < rows; y++) {
            uint32_t count = 0xFFFFFFFFu;
            for (i = 0; i < wn; i++) {
                E[i] = fz_u8(&in) % 4u;
            }
            st = symline_colrun_push(&cr, E, (symline_extremum *)(void *)ev, cap, &count);
            if (st == SYMLINE_OK && count > cap) {
                abort();
            }
        }
        fz_check_guard(buf, bn, "colrun buffer");
        fz_check_guard(ev, (size_t)cap * sizeof(symline_extremum), "colrun events");
        free(buf);
        free(ev);
        free(E);
        break;
    }
    default: break;
    }
    (void)st;
    free(px);
    return 0;
}

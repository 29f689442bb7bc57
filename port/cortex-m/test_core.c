/* SPDX-License-Identifier: Apache-2.0 */
/*
 * The core's golden and argument checks, run on the target (Cortex-M under
 * qemu): every golden case of tests/golden/core (symmetry images and
 * extrema maps from the plain reference) is recomputed here from the
 * embedded input and compared byte for byte. All buffers are static.
 *
 * Built with SYMLINE_FW_INJECT_FAILURE, one output byte is corrupted before
 * the comparison: that variant must fail, which proves a failing check on the
 * target reaches CI.
 */
#include <stdint.h>
#include <string.h>

#include "symline/extrema.h"
#include "symline/symmetry.h"

#include "fwdata.h"
#include "fwtest.h"
#include "test_port.h"

unsigned fw_checks, fw_failures;

extern const fw_golden fw_golden_cases[];
extern const unsigned fw_golden_count;

#define MAX_PIXELS (96u * 72u)
#define WS_BYTES 4096u

static uint8_t out[MAX_PIXELS];
/* One byte more than any workspace so the checks can start it misaligned. */
static uint64_t ws_store[WS_BYTES / 8u + 1u];

/* Index of the first differing byte, or n when equal. */
static uint32_t first_diff(const uint8_t *a, const uint8_t *b, uint32_t n)
{
    uint32_t i;
    for (i = 0; i < n && a[i] == b[i]; i++) {
    }
    return i;
}

static void check_case(const fw_golden *g, uint8_t *ws)
{
    const symline_axis axis = (symline_axis)g->axis;
    const uint32_t w = g->in->width, h = g->in->height, n = w * h;
    const symline_image img = {w, h, w, g->in->px};
    size_t need;
    symline_status st;
    uint32_t d;

    FW_CHECK(n <= MAX_PIXELS, "%s: %lux%lu frame larger than the test buffers", g->name,
             (unsigned long)w, (unsigned long)h);
    if (n > MAX_PIXELS) {
        return;
    }
    need = symline_symmetry_workspace_size(w, h, axis, g->m);
    FW_CHECK(need > 0u && need <= WS_BYTES, "%s: symmetry workspace %lu", g->name,
             (unsigned long)need);
    st = symline_symmetry(&img, axis, g->m, out, w, n, ws, need);
#ifdef SYMLINE_FW_INJECT_FAILURE
    if (g == &fw_golden_cases[0]) {
        out[0] ^= 1u;
    }
#endif
    d = first_diff(out, g->s8->px, n);
    FW_CHECK(st == SYMLINE_OK && d == n, "%s symmetry: status %d, first difference at (%lu, %lu)",
             g->name, (int)st, (unsigned long)(d % w), (unsigned long)(d / w));

    need = symline_extrema_workspace_size(w, h, axis, g->m);
    FW_CHECK(need > 0u && need <= WS_BYTES, "%s: extrema workspace %lu", g->name,
             (unsigned long)need);
    st = symline_extrema(&img, axis, g->m, out, w, n, ws, need);
    d = first_diff(out, g->ext->px, n);
    FW_CHECK(st == SYMLINE_OK && d == n, "%s extrema: status %d, first difference at (%lu, %lu)",
             g->name, (int)st, (unsigned long)(d % w), (unsigned long)(d / w));
}

/* Specific errors for bad arguments, and nothing written when a check fails. */
static void check_errors(uint8_t *ws)
{
    static const uint8_t px[12] = {1, 2, 3, 4, 5, 6, 7, 8, 9, 10, 11, 12};
    const symline_image img = {4u, 3u, 4u, px};
    const symline_image bad_stride = {4u, 3u, 3u, px};
    const symline_image no_data = {4u, 3u, 4u, NULL};
    uint8_t small[12];
    uint32_t E[4];
    size_t need = symline_extrema_workspace_size(4u, 3u, SYMLINE_AXIS_HORIZONTAL, 3u);
    uint32_t i;

    for (i = 0; i < 12u; i++) {
        small[i] = 0xA5u;
    }
    FW_CHECK(symline_symmetry(NULL, SYMLINE_AXIS_VERTICAL, 3u, small, 4u, 12u, ws, WS_BYTES) ==
                 SYMLINE_ERR_NULL,
             "NULL image");
    FW_CHECK(symline_symmetry(&no_data, SYMLINE_AXIS_VERTICAL, 3u, small, 4u, 12u, ws, WS_BYTES) ==
                 SYMLINE_ERR_NULL,
             "NULL pixels");
    FW_CHECK(symline_symmetry(&bad_stride, SYMLINE_AXIS_VERTICAL, 3u, small, 4u, 12u, ws,
                              WS_BYTES) == SYMLINE_ERR_STRIDE,
             "image stride < width");
    FW_CHECK(symline_symmetry(&img, SYMLINE_AXIS_VERTICAL, 0u, small, 4u, 12u, ws, WS_BYTES) ==
                 SYMLINE_ERR_RADIUS,
             "m = 0");
    FW_CHECK(symline_symmetry(&img, SYMLINE_AXIS_VERTICAL, 256u, small, 4u, 12u, ws, WS_BYTES) ==
                 SYMLINE_ERR_RADIUS,
             "m = 256");
    FW_CHECK(symline_symmetry(&img, (symline_axis)7, 3u, small, 4u, 12u, ws, WS_BYTES) ==
                 SYMLINE_ERR_AXIS,
             "bad axis");
    FW_CHECK(symline_symmetry(&img, SYMLINE_AXIS_VERTICAL, 3u, small, 4u, 11u, ws, WS_BYTES) ==
                 SYMLINE_ERR_BUFFER,
             "output one byte short");
    /* Far too small whatever the alignment of ws (the size includes alignment slack). */
    FW_CHECK(symline_extrema(&img, SYMLINE_AXIS_HORIZONTAL, 3u, small, 4u, 12u, ws, 8u) ==
                 SYMLINE_ERR_BUFFER,
             "workspace of 8 bytes");
    FW_CHECK(symline_extrema(&img, SYMLINE_AXIS_HORIZONTAL, 3u, small, 4u, 12u, NULL, need) ==
                 SYMLINE_ERR_NULL,
             "NULL workspace");
    FW_CHECK(symline_extrema(&img, SYMLINE_AXIS_HORIZONTAL, 3u, small, 3u, 12u, ws, need) ==
                 SYMLINE_ERR_STRIDE,
             "map stride < width");
    FW_CHECK(symline_energy_row(px, 0u, 3u, E) == SYMLINE_ERR_SIZE, "empty row");
    FW_CHECK(symline_s8_row(E, 4u, 0u, small) == SYMLINE_ERR_RADIUS, "s8 radius 0");
    FW_CHECK(first_diff(small, (const uint8_t *)"\xA5\xA5\xA5\xA5\xA5\xA5\xA5\xA5\xA5\xA5\xA5\xA5",
                        12u) == 12u,
             "an output was written by a failing call");
}

int main(void)
{
    /* Workspaces have no alignment requirement: use a misaligned one. */
    uint8_t *ws = (uint8_t *)ws_store + 1;
    unsigned i;
    printf("symline target tests: %u golden cases\n", fw_golden_count);
    for (i = 0; i < fw_golden_count; i++) {
        check_case(&fw_golden_cases[i], ws);
    }
    check_errors(ws);
    fw_port_checks();
    return fw_test_end("symline target tests");
}

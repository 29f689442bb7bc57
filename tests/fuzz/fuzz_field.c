/* SPDX-License-Identifier: Apache-2.0 */
/*
 * Fuzz target: the field boundary (symline/field.h). symline_field_find()
 * with fuzzer-chosen geometry and stride, every symline_field_config field
 * (default, inside its range, at a limit, one past either limit, any 32-bit
 * value), workspace size (exact, one byte short, zero, larger) and NULL
 * pointers; then symline_field_y() and symline_field_above() on its boundary
 * and on a fuzzer-made one (0 to 30 vertices, within the documented ranges).
 * Checks: no read past the image (pixels allocated to the byte), guard bytes
 * after the workspace and the boundary untouched, a known status, ERR_CONFIG
 * exactly for a field out of its range (and then a workspace query of 0),
 * the boundary unchanged on an error, and on success a polyline from x = 0 to
 * x = width-1 with x increasing and rows within 0..height, interpolated
 * between its vertices, symline_field_above() agreeing with symline_field_y().
 */
#include <stdint.h>
#include <stdlib.h>
#include <string.h>

#include "fuzz_lib.h"
#include "symline/field.h"

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size);

/* The boundary's queries at x against its vertices (any x, documented ones). */
static void check_queries(const symline_field_boundary *b, int32_t x, int32_t y)
{
    const int32_t fy = symline_field_y(b, x);
    int32_t lo = 0, hi = 0;
    uint32_t i;
    if (b->count == 0u || b->count > SYMLINE_FIELD_MAX_VERTICES) {
        /* Empty: row 0 and nothing above it; beyond the vertex limit (not a
         * boundary symline makes): row 0, so only rows above the image are above. */
        if (fy != 0 || symline_field_above(b, x, y) != (b->count != 0u && y < 0 ? 1 : 0)) {
            abort();
        }
        return;
    }
    /* Clamped to the polyline's x range, interpolated: within the rows of
     * the vertices around x. */
    if (x <= b->v[0].x) {
        lo = hi = b->v[0].y;
    } else if (x >= b->v[b->count - 1u].x) {
        lo = hi = b->v[b->count - 1u].y;
    } else {
        for (i = 1u; i < b->count; i++) {
            if (x <= b->v[i].x) {
                lo = b->v[i - 1u].y < b->v[i].y ? b->v[i - 1u].y : b->v[i].y;
                hi = b->v[i - 1u].y > b->v[i].y ? b->v[i - 1u].y : b->v[i].y;
                if (x == b->v[i].x) {
                    lo = hi = b->v[i].y;
                }
                break;
            }
        }
    }
    if (fy < lo || fy > hi) {
        fprintf(stderr, "symline_field_y(%d) = %d outside %d..%d\n", x, fy, lo, hi);
        abort();
    }
    if (symline_field_above(b, x, y) != (y < fy ? 1 : 0)) {
        abort();
    }
}

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
    fz_in in = {data, size};
    symline_field_config fc;
    symline_field_boundary *b, made;
    symline_image img;
    uint32_t w = fz_dim(&in), h = fz_dim(&in), stride, i;
    const uint32_t nulls = fz_u8(&in); /* bits 0-3: image, data, config, ws, out NULL (rarely) */
    size_t img_len, wsq, wsn;
    uint8_t *px, *ws, before[sizeof(symline_field_boundary)];
    symline_status st;
    int32_t qx, qy;

    if (fz_u8(&in) % 8u == 0u) {
        /* Now and then a large frame, one row or column of it. */
        const uint32_t big = 1000u + fz_u16(&in) % 64536u;
        if (fz_u8(&in) & 1u) {
            w = big;
            h = 1u + h % 4u;
        } else {
            h = big;
            w = 1u + w % 4u;
        }
    }
    stride = w + (fz_u8(&in) % 4u == 0u ? fz_u8(&in) % 9u : 0u);
    if (fz_u8(&in) % 16u == 0u && w > 0u) {
        stride = w - 1u; /* ERR_STRIDE */
    }
    fz_field_config(&in, &fc);
    wsq = symline_field_workspace_size(w, h, &fc);
    if ((wsq > 0u) !=
        (fz_field_config_ok(&fc) && w >= 1u && h >= 1u && w <= 65535u && h <= 65535u)) {
        abort(); /* the query is 0 exactly for invalid arguments */
    }
    if (symline_field_workspace_size(w, h, NULL) != 0u) {
        abort();
    }
    wsn = fz_size(&in, wsq > 0u ? wsq : 256u);
    ws = fz_buf(wsn, 0x33);
    b = (symline_field_boundary *)(void *)fz_buf(sizeof *b, 0x5A);
    memcpy(before, b, sizeof before);
    qx = (int32_t)fz_u32(&in);
    qy = (int32_t)fz_u32(&in);
    if (w > 65535u && h > 1u) {
        h = 1u;
    }
    if (h > 65535u && w > 1u) {
        w = 1u;
    }
    px = fz_image(&in, w, h, stride > w ? stride : w, &img_len);
    img.width = w;
    img.height = h;
    img.stride = stride;
    img.data = (nulls & 2u) && (nulls & 0xC0u) == 0xC0u ? NULL : px;

    st = symline_field_find((nulls & 1u) && (nulls & 0xC0u) == 0xC0u ? NULL : &img,
                            (nulls & 4u) && (nulls & 0xC0u) == 0xC0u ? NULL : &fc,
                            (nulls & 8u) && (nulls & 0xC0u) == 0xC0u ? NULL : ws, wsn,
                            (nulls & 16u) && (nulls & 0xC0u) == 0xC0u ? NULL : b);
    fz_check_status(st, "symline_field_find");
    fz_check_guard(ws, wsn, "workspace");
    fz_check_guard((const uint8_t *)b, sizeof *b, "boundary");
    if ((nulls & 0xC0u) != 0xC0u && symline_image_check(&img) == SYMLINE_OK &&
        (st == SYMLINE_ERR_CONFIG) != !fz_field_config_ok(&fc)) {
        abort(); /* ERR_CONFIG exactly for a field out of its range */
    }
    if (st != SYMLINE_OK) {
        if (memcmp(before, b, sizeof before) != 0) {
            abort(); /* the boundary changed on an error */
        }
    } else {
        const uint32_t cell = fc.cell != 0u ? fc.cell : (w >= 1024u ? 16u : 8u);
        fz_check_boundary(b, w, h);
        if (b->cell != cell) {
            abort();
        }
        check_queries(b, qx, qy);
        check_queries(b, (int32_t)(qx % (int32_t)(w + 2u)) - 1, qy % (int32_t)(h + 2u));
        for (i = 0; i < b->count; i++) {
            if (symline_field_y(b, b->v[i].x) != b->v[i].y) {
                abort(); /* the polyline runs through its vertices */
            }
        }
    }

    /* A boundary made by hand: 0..30 vertices, x increasing within the
     * frame's documented range, rows 0..65535. */
    memset(&made, 0, sizeof made);
    made.count = fz_u8(&in) % 31u;
    {
        int32_t x = (int32_t)(fz_u16(&in) % 64u);
        for (i = 0; i < made.count && i < SYMLINE_FIELD_MAX_VERTICES; i++) {
            made.v[i].x = x;
            made.v[i].y = (int32_t)(fz_u8(&in) & 1u ? fz_u16(&in) : fz_u8(&in));
            x += 1 + (int32_t)(fz_u8(&in) & 1u ? fz_u16(&in) % 4096u : fz_u8(&in) % 16u);
            if (x > 65534) {
                made.count = i + 1u;
                break;
            }
        }
    }
    check_queries(&made, qx, qy);
    check_queries(&made, (int32_t)(qx % 80) - 8, qy % 300);
    if (symline_field_y(NULL, qx) != 0 || symline_field_above(NULL, qx, qy) != 0) {
        abort();
    }
    symline_field_config_default(NULL);

    free(px);
    free(ws);
    free(b);
    return 0;
}

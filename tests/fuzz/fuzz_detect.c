/* SPDX-License-Identifier: Apache-2.0 */
/*
 * Fuzz target: symline_detect() with fuzzer-chosen geometry, every
 * configuration field (its default, inside its range, just outside it, or
 * any 32-bit value; the field boundary's mode, margin and settings too),
 * workspace size and output capacities (exact, one short, zero, NULL), and
 * symline_config_check() and symline_image_check() on the same arguments.
 * Checks: no read past the image, no write past the workspace or the outputs
 * (guard bytes), a known status, nothing changed in the result on an error,
 * symline_config_check() naming a culprit exactly when symline_detect()
 * reports ERR_CONFIG, and a consistent result on success (counts within the
 * capacities, points_needed within the point capacity when not truncated,
 * every segment's points stored and inside the frame, the field boundary a
 * polyline across the frame).
 */
#include <stdint.h>
#include <stdlib.h>
#include <string.h>

#include "fuzz_lib.h"
#include "symline/detect.h"

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size);

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
    fz_in in = {data, size};
    symline_config cfg;
    symline_image img;
    symline_result res, before;
    uint32_t w = fz_dim(&in), h = fz_dim(&in), stride, i;
    const uint32_t nulls = fz_u8(&in);
    size_t img_len, wsq, wsn, seg_bytes, pt_bytes;
    uint8_t *px, *ws, *segs, *pts;
    symline_status st, cst;
    symline_config_field bad = SYMLINE_CFG_NONE;
    uint32_t field_sel;

    stride = w + (fz_u8(&in) % 4u == 0u ? fz_u8(&in) % 9u : 0u);
    if (fz_u8(&in) % 16u == 0u && w > 0u) {
        stride = w - 1u; /* ERR_STRIDE */
    }
    fz_detect_config(&in, &cfg);
    wsq = symline_detect_workspace_size(w, h, &cfg);
    wsn = fz_size(&in, wsq > 0u ? wsq : 256u);
    memset(&res, 0, sizeof res);
    res.segment_cap = fz_u8(&in) % 4u == 0u ? 0u : fz_u8(&in) % 48u;
    {
        const uint32_t full = (w <= 65535u && h <= 65535u) ? 2u * w * h + 1024u : 1024u;
        const uint32_t mode = fz_u8(&in) % 4u;
        res.point_cap = mode == 0u ? full : (mode == 1u ? 0u : fz_u16(&in) % (full + 1u));
    }
    seg_bytes = (size_t)res.segment_cap * sizeof(symline_segment);
    pt_bytes = (size_t)res.point_cap * sizeof(symline_point);
    segs = fz_buf(seg_bytes, 0x5A);
    pts = fz_buf(pt_bytes, 0x5A);
    /* NULL arrays are allowed with a capacity of 0 only. */
    res.segments = ((nulls & 1u) || (res.segment_cap == 0u && (nulls & 8u)))
                       ? NULL
                       : (symline_segment *)(void *)segs;
    res.points = ((nulls & 2u) || (res.point_cap == 0u && (nulls & 16u)))
                     ? NULL
                     : (symline_point *)(void *)pts;
    res.segment_count = 0xDEADu;
    res.point_count = 0xBEEFu;
    res.truncated = true;
    memcpy(&before, &res, sizeof res);

    if (w > 65535u && h > 1u) {
        h = 1u; /* invalid anyway; keep the pixels small */
    }
    px = fz_image(&in, w, h, stride > w ? stride : w, &img_len);
    img.width = w;
    img.height = h;
    img.stride = stride;
    img.data = (nulls & 4u) ? NULL : px;

    /* The field boundary's mode, margin and settings: from the bytes after the
     * ones read so far (the pixels repeat them), mostly the defaults. */
    field_sel = fz_u8(&in);
    if (field_sel % 4u == 3u) {
        cfg.field_boundary = (symline_field_mode)fz_pick(&in, (uint32_t)cfg.field_boundary, 0, 2);
        cfg.field_margin = fz_pick(&in, cfg.field_margin, 0, 65535);
        fz_field_config(&in, &cfg.field);
        wsq = symline_detect_workspace_size(w, h, &cfg);
        wsn = fz_size(&in, wsq > 0u ? wsq : 256u);
    }
    ws = fz_buf(wsn, 0x33);

    /* symline_config_check names a culprit exactly when it reports an error. */
    cst = symline_config_check(&cfg, (field_sel & 4u) ? NULL : &bad);
    fz_check_status(cst, "symline_config_check");
    if ((cst != SYMLINE_OK && cst != SYMLINE_ERR_CONFIG) ||
        (unsigned)bad > (unsigned)SYMLINE_CFG_FIELD ||
        ((field_sel & 4u) == 0u && (cst == SYMLINE_OK) != (bad == SYMLINE_CFG_NONE)) ||
        (!fz_field_config_ok(&cfg.field) && cst == SYMLINE_OK) ||
        (bad == SYMLINE_CFG_FIELD && fz_field_config_ok(&cfg.field))) {
        abort();
    }
    if (symline_config_check(NULL, &bad) != SYMLINE_ERR_NULL || bad != SYMLINE_CFG_NONE) {
        abort();
    }
    /* The workspace query is 0 exactly for invalid arguments. */
    if ((cst == SYMLINE_OK && w >= 1u && h >= 1u && w <= 65535u && h <= 65535u) !=
        (symline_detect_workspace_size(w, h, &cfg) > 0u)) {
        abort();
    }

    st = symline_detect(&img, (nulls & 32u) ? NULL : &cfg, (nulls & 64u) ? NULL : ws, wsn,
                        (nulls & 128u) ? NULL : &res);
    fz_check_status(st, "symline_detect");
    fz_check_status(symline_image_check(&img), "symline_image_check");
    if ((nulls & (4u | 32u | 64u | 128u)) == 0u && symline_image_check(&img) == SYMLINE_OK &&
        !(res.segments == NULL && res.segment_cap != 0u) &&
        !(res.points == NULL && res.point_cap != 0u) &&
        (st == SYMLINE_ERR_CONFIG) != (cst == SYMLINE_ERR_CONFIG)) {
        abort(); /* symline_detect and symline_config_check disagree */
    }

    fz_check_guard(segs, seg_bytes, "segments");
    fz_check_guard(pts, pt_bytes, "points");
    fz_check_guard(ws, wsn, "workspace");
    if (st != SYMLINE_OK) {
        if (memcmp(&res, &before, sizeof res) != 0) {
            abort(); /* the result struct changed on an error */
        }
        fz_check_untouched(segs, seg_bytes, 0x5A, "segments");
        fz_check_untouched(pts, pt_bytes, 0x5A, "points");
    } else {
        if (res.segment_count > res.segment_cap || res.point_count > res.point_cap ||
            (!res.truncated && res.points_needed > res.point_cap)) {
            abort();
        }
        if (cfg.field_boundary == SYMLINE_FIELD_OFF) {
            if (res.field.count != 0u) {
                abort();
            }
        } else {
            fz_check_boundary(&res.field, w, h);
        }
        for (i = 0; i < res.segment_count; i++) {
            const symline_segment *s = &res.segments[i];
            uint32_t k;
            if (s->count > res.point_count || s->first > res.point_count - s->count ||
                s->kind > 1u || s->axis > 1u || s->level > 5u) {
                abort();
            }
            for (k = 0; k < s->count; k++) {
                const symline_point *p = &res.points[s->first + k];
                if (p->x >= w || p->y >= h) {
                    abort();
                }
            }
        }
    }
    free(px);
    free(ws);
    free(segs);
    free(pts);
    return 0;
}

/* SPDX-License-Identifier: Apache-2.0 */
/*
 * Fuzz target: symline_detect() with fuzzer-chosen geometry, every
 * configuration field (its default, inside its range, just outside it, or
 * any 32-bit value), workspace size and output capacities (exact, one short,
 * zero, NULL). Checks: no read past the image, no write past the workspace
 * or the outputs (guard bytes), nothing changed in the result on an error,
 * and a consistent result on success (counts within the capacities, every
 * segment's points stored and inside the frame).
 */
#include <stdint.h>
#include <stdlib.h>
#include <string.h>

#include "fuzz_util.h"
#include "symline/detect.h"

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size);

/* A field with documented range [lo, hi]: default, inside, just outside, anything. */
static uint32_t pick_field(fz_in *in, uint32_t def, int64_t lo, int64_t hi)
{
    switch (fz_u8(in) % 8u) {
    case 0:
    case 1:
    case 2: return def;
    case 3: return (uint32_t)(lo + (int64_t)(fz_u32(in) % (uint64_t)(hi - lo + 1)));
    case 4: return (uint32_t)(hi + 1);
    case 5: return (uint32_t)(lo - 1);
    case 6: return (uint32_t)(fz_u8(in) & 1u ? lo : hi);
    default: return fz_u32(in);
    }
}

static uint32_t pick_dim(fz_in *in)
{
    const uint32_t v = fz_u8(in);
    if (v == 0u) {
        return 0u;
    }
    if (v == 255u) {
        return 65536u;
    }
    return 1u + v % 96u;
}

static int result_equal(const symline_result *a, const symline_result *b)
{
    return a->segments == b->segments && a->segment_cap == b->segment_cap &&
           a->segment_count == b->segment_count && a->points == b->points &&
           a->point_cap == b->point_cap && a->point_count == b->point_count &&
           a->truncated == b->truncated;
}

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
    fz_in in = {data, size};
    symline_config cfg, def;
    symline_image img;
    symline_result res, before;
    uint32_t w = pick_dim(&in), h = pick_dim(&in), stride, i;
    const uint32_t nulls = fz_u8(&in);
    size_t img_len, wsq, wsn, seg_bytes, pt_bytes;
    uint8_t *px, *ws, *segs, *pts;
    symline_status st;

    stride = w + (fz_u8(&in) % 4u == 0u ? fz_u8(&in) % 9u : 0u);
    if (fz_u8(&in) % 16u == 0u && w > 0u) {
        stride = w - 1u; /* ERR_STRIDE */
    }
    symline_config_default(&def);
    cfg = def;
    cfg.axes = (symline_axes)pick_field(&in, (uint32_t)def.axes, 0, 2);
    cfg.radius = pick_field(&in, def.radius, 1, 32);
    cfg.levels = pick_field(&in, def.levels, 0, 5);
    cfg.filter = (symline_filter)pick_field(&in, (uint32_t)def.filter, 0, 1);
    cfg.illumination = pick_field(&in, def.illumination, 0, 255);
    cfg.adaptive = pick_field(&in, def.adaptive, 0, 1);
    cfg.bright_sigma10 = (int32_t)pick_field(&in, (uint32_t)def.bright_sigma10, -100, 100);
    cfg.ridge_sigma10 = pick_field(&in, def.ridge_sigma10, 0, 100);
    cfg.side_sigma10 = (int32_t)pick_field(&in, (uint32_t)def.side_sigma10, -100, 100);
    cfg.a_distance = pick_field(&in, def.a_distance, 0, 32);
    cfg.contrast_pct = pick_field(&in, def.contrast_pct, 0, 100);
    cfg.contrast_min = pick_field(&in, def.contrast_min, 0, 255);
    cfg.contrast_asym_pct = pick_field(&in, def.contrast_asym_pct, 0, 1000);
    cfg.min_length = pick_field(&in, def.min_length, 0, 65535);
    cfg.curve_dev_q8 = pick_field(&in, def.curve_dev_q8, 0, 65535 << 8);
    cfg.curve_bend_q8 = pick_field(&in, def.curve_bend_q8, 0, 65535 << 8);
    cfg.merge_gap = pick_field(&in, def.merge_gap, 0, 65535);
    cfg.merge_dev_q8 = pick_field(&in, def.merge_dev_q8, 0, 65535 << 8);
    if (fz_u8(&in) % 4u != 0u) {
        /* Mostly small line lengths, so that short fuzzed frames give segments. */
        cfg.min_length = fz_u8(&in) % 16u;
    }

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
    ws = fz_buf(wsn, 0x33);
    /* NULL arrays are allowed with a capacity of 0 only. */
    res.segments = ((nulls & 1u) || (res.segment_cap == 0u && (nulls & 8u))) ? NULL : (symline_segment *)(void *)segs;
    res.points = ((nulls & 2u) || (res.point_cap == 0u && (nulls & 16u))) ? NULL : (symline_point *)(void *)pts;
    res.segment_count = 0xDEADu;
    res.point_count = 0xBEEFu;
    res.truncated = true;
    before = res;

    if (w > 65535u && h > 1u) {
        h = 1u; /* invalid anyway; keep the pixels small */
    }
    px = fz_image(&in, w, h, stride > w ? stride : w, &img_len);
    img.width = w;
    img.height = h;
    img.stride = stride;
    img.data = (nulls & 4u) ? NULL : px;

    st = symline_detect(&img, (nulls & 32u) ? NULL : &cfg, (nulls & 64u) ? NULL : ws, wsn,
                        (nulls & 128u) ? NULL : &res);

    fz_check_guard(segs, seg_bytes, "segments");
    fz_check_guard(pts, pt_bytes, "points");
    fz_check_guard(ws, wsn, "workspace");
    if (st != SYMLINE_OK) {
        if (!result_equal(&res, &before)) {
            abort(); /* the result struct changed on an error */
        }
        fz_check_untouched(segs, seg_bytes, 0x5A, "segments");
        fz_check_untouched(pts, pt_bytes, 0x5A, "points");
    } else {
        if (res.segment_count > res.segment_cap || res.point_count > res.point_cap) {
            abort();
        }
        for (i = 0; i < res.segment_count; i++) {
            const symline_segment *s = &res.segments[i];
            uint32_t k;
            if (s->count > res.point_count || s->first > res.point_count - s->count || s->kind > 1u ||
                s->axis > 1u || s->level > 5u) {
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

/* SPDX-License-Identifier: Apache-2.0 */
/*
 * Fuzz target: 2x2 binning (symline/binning.h). symline_bin2() with
 * fuzzer-chosen geometry, stride and buffer size (exact, one short, zero,
 * NULL): no read past the image, no write past the buffer, nothing written on
 * an error, the exact means on success. Then the binned frame's detection,
 * moved back by symline_result_unbin2(): counts kept, every point inside the
 * frame, levels from 1, the field boundary a polyline across the frame.
 * Last, symline_result_unbin2() on a result of fuzzed contents: a known
 * status, nothing changed on an error.
 */
#include <stdint.h>
#include <stdlib.h>
#include <string.h>

#include "fuzz_lib.h"
#include "symline/binning.h"
#include "symline/detect.h"

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size);

/* The binned frame's detection, moved back to the w x h frame. */
static void detect_binned(const symline_image *half, uint32_t w, uint32_t h)
{
    symline_config cfg;
    symline_result res;
    symline_segment segs[64];
    const uint32_t pcap = 2u * half->width * half->height + 1024u;
    symline_point *pts = (symline_point *)malloc(pcap * sizeof *pts);
    size_t need;
    uint8_t *ws;
    uint32_t i, ns, np;
    symline_status st;
    symline_config_default(&cfg);
    cfg.min_length = 4u; /* small frames: short pieces too */
    need = symline_detect_workspace_size(half->width, half->height, &cfg);
    ws = (uint8_t *)malloc(need);
    if (pts == NULL || ws == NULL) {
        abort();
    }
    memset(&res, 0, sizeof res);
    res.segments = segs;
    res.segment_cap = 64u;
    res.points = pts;
    res.point_cap = pcap;
    st = symline_detect(half, &cfg, ws, need, &res);
    if (st != SYMLINE_OK) {
        abort(); /* a valid frame, configuration and workspace */
    }
    ns = res.segment_count;
    np = res.point_count;
    st = symline_result_unbin2(&res, w, h);
    if (st != SYMLINE_OK || res.segment_count != ns || res.point_count != np) {
        abort(); /* a detection's own result always moves back */
    }
    for (i = 0; i < np; i++) {
        if (pts[i].x >= w || pts[i].y >= h || pts[i].fx < -64 || pts[i].fx > 63 ||
            pts[i].fy < -64 || pts[i].fy > 63) {
            abort();
        }
    }
    for (i = 0; i < ns; i++) {
        if (segs[i].level < 1u || segs[i].first + segs[i].count > np) {
            abort();
        }
    }
    fz_check_boundary(&res.field, w, h);
    free(ws);
    free(pts);
}

/* unbin2 on fuzzed contents: a known status; nothing changed on an error. */
static void unbin_fuzzed(fz_in *in)
{
    symline_segment segs[4], segs0[4];
    symline_point pts[8], pts0[8];
    symline_result r, r0;
    const uint32_t w = fz_u16(in), h = fz_u16(in);
    symline_status st;
    uint32_t i;
    memset(&r, 0, sizeof r);
    for (i = 0; i < 4u; i++) {
        segs[i].x0 = (int32_t)fz_u32(in);
        segs[i].y0 = (int32_t)fz_u32(in);
        segs[i].x1 = (int32_t)fz_u32(in);
        segs[i].y1 = (int32_t)fz_u32(in);
        segs[i].max_dev = fz_u32(in);
        segs[i].first = fz_u32(in);
        segs[i].count = fz_u32(in);
        segs[i].kind = (uint8_t)fz_u8(in);
        segs[i].axis = (uint8_t)fz_u8(in);
        segs[i].level = (uint8_t)fz_u8(in);
        segs[i].merged = (fz_u8(in) & 1u) != 0u;
    }
    for (i = 0; i < 8u; i++) {
        pts[i].x = (uint16_t)fz_u16(in);
        pts[i].y = (uint16_t)fz_u16(in);
        pts[i].fx = (int8_t)((int32_t)(fz_u8(in) % 128u) - 64);
        pts[i].fy = (int8_t)((int32_t)(fz_u8(in) % 128u) - 64);
    }
    r.segments = (fz_u8(in) & 1u) ? NULL : segs;
    r.segment_cap = fz_u8(in) % 6u;
    r.segment_count = fz_u8(in) % 6u;
    r.points = (fz_u8(in) & 1u) ? NULL : pts;
    r.point_cap = fz_u8(in) % 10u;
    r.point_count = fz_u8(in) % 10u;
    if (r.segment_cap > 4u || r.point_cap > 8u) {
        r.segment_cap = r.segment_cap > 4u ? 4u : r.segment_cap;
        r.point_cap = r.point_cap > 8u ? 8u : r.point_cap;
    }
    r.field.count = fz_u8(in) % 26u;
    for (i = 0; i < SYMLINE_FIELD_MAX_VERTICES; i++) {
        r.field.v[i].x = (int32_t)fz_u16(in) - 8;
        r.field.v[i].y = (int32_t)fz_u16(in) - 8;
    }
    r.field.cell = (uint8_t)fz_u8(in);
    memcpy(segs0, segs, sizeof segs);
    memcpy(pts0, pts, sizeof pts);
    r0 = r;
    st = symline_result_unbin2((fz_u8(in) % 32u == 0u) ? NULL : &r, w, h);
    fz_check_status(st, "symline_result_unbin2");
    if (st != SYMLINE_OK &&
        (memcmp(segs, segs0, sizeof segs) != 0 || memcmp(pts, pts0, sizeof pts) != 0 ||
         memcmp(&r, &r0, sizeof r) != 0)) {
        abort(); /* changed on an error */
    }
}

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
    fz_in in = {data, size};
    uint32_t w = fz_dim(&in), h = fz_dim(&in), stride, x, y;
    const uint32_t nulls = fz_u8(&in);
    const size_t need = symline_bin2_size(w, h);
    size_t img_len, n;
    uint8_t *px, *buf;
    symline_image img, half;
    symline_status st;

    stride = w + (fz_u8(&in) % 4u == 0u ? fz_u8(&in) % 9u : 0u);
    if (fz_u8(&in) % 16u == 0u && w > 0u) {
        stride = w - 1u; /* ERR_STRIDE */
    }
    if (w > 65535u && h > 1u) {
        h = 1u; /* invalid anyway; keep the pixels small */
    }
    n = fz_size(&in, need > 0u ? need : 64u);
    buf = fz_buf(n, 0x5A);
    px = fz_image(&in, w, h, stride > w ? stride : w, &img_len);
    img.width = w;
    img.height = h;
    img.stride = stride;
    img.data = (nulls & 1u) ? NULL : px;
    memset(&half, 0, sizeof half);
    st = symline_bin2((nulls & 2u) && (nulls & 4u) ? NULL : &img, (nulls & 8u) ? NULL : buf, n,
                      (nulls & 16u) ? NULL : &half);
    fz_check_status(st, "symline_bin2");
    fz_check_guard(buf, n, "binned image");
    if (st != SYMLINE_OK) {
        fz_check_untouched(buf, n, 0x5A, "binned image");
        if (half.data != NULL) {
            abort();
        }
    } else {
        if (half.width != w / 2u || half.height != h / 2u || half.stride != w / 2u ||
            half.data != buf || n < need) {
            abort();
        }
        for (y = 0; y < half.height; y++) {
            for (x = 0; x < half.width; x++) {
                const uint8_t *a = px + (size_t)2u * y * stride + 2u * x;
                const uint32_t s = (uint32_t)a[0] + a[1] + a[stride] + a[stride + 1u];
                if (buf[(size_t)y * half.width + x] != (uint8_t)((s + 2u) / 4u)) {
                    abort();
                }
            }
        }
        detect_binned(&half, w, h);
    }
    unbin_fuzzed(&in);
    free(px);
    free(buf);
    return 0;
}

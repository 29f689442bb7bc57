/* SPDX-License-Identifier: Apache-2.0 */
/*
 * Fuzz target: symmetry feature points (symline/features.h).
 * symline_features() with fuzzer-chosen geometry and stride, radius (0,
 * 1..11, 253..258), workspace size (exact, one byte short, zero, larger),
 * point capacity (0, the frame's count, one short, symline_features_max_points,
 * any) and NULL pointers, with the size queries.
 * Checks: no read past the image (pixels allocated to the byte), guard bytes
 * after the workspace and the points untouched, a known status; on an
 * argument error *count and the points untouched; when the points do not fit,
 * ERR_BUFFER with *count the frame's number, and a second call with that
 * capacity succeeds with the same number; on success the points in raster
 * order, each once, whole pixels inside the frame's border, never two
 * adjacent along a row or a column, at most symline_features_max_points(), and
 * exactly the pixels that are S points of both symline_extrema() maps.
 */
#include <stdint.h>
#include <stdlib.h>
#include <string.h>

#include "fuzz_lib.h"
#include "symline/extrema.h"
#include "symline/features.h"

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size);

static uint32_t pick_radius(fz_in *in)
{
    const uint32_t v = fz_u8(in);
    if (v >= 250u) {
        return 253u + (v - 250u); /* 253 .. 258: around the largest valid radius */
    }
    return v % 12u; /* 0 (invalid) .. 11 */
}

/* The S points of both extrema maps, in raster order; returns their number
 * or UINT32_MAX when the maps could not be made. */
static uint32_t reference(const symline_image *img, uint32_t m, symline_point *out, uint32_t cap)
{
    const uint32_t w = img->width, h = img->height;
    uint8_t *mh = (uint8_t *)malloc((size_t)w * h), *mv = (uint8_t *)malloc((size_t)w * h);
    size_t nh = symline_extrema_workspace_size(w, h, SYMLINE_AXIS_HORIZONTAL, m);
    size_t nv = symline_extrema_workspace_size(w, h, SYMLINE_AXIS_VERTICAL, m);
    void *ws = malloc((nh > nv ? nh : nv) + 1u);
    uint32_t n = 0u, x, y;
    if (mh == NULL || mv == NULL || ws == NULL) {
        abort();
    }
    if (symline_extrema(img, SYMLINE_AXIS_HORIZONTAL, m, mh, w, (size_t)w * h, ws, nh) !=
            SYMLINE_OK ||
        symline_extrema(img, SYMLINE_AXIS_VERTICAL, m, mv, w, (size_t)w * h, ws, nv) !=
            SYMLINE_OK) {
        n = UINT32_MAX;
    } else {
        for (y = 0; y < h; y++) {
            for (x = 0; x < w; x++) {
                const size_t i = (size_t)y * w + x;
                if (mh[i] == SYMLINE_MAP_S && mv[i] == SYMLINE_MAP_S) {
                    if (n < cap) {
                        out[n].x = (uint16_t)x;
                        out[n].y = (uint16_t)y;
                    }
                    n++;
                }
            }
        }
    }
    free(mh);
    free(mv);
    free(ws);
    return n;
}

static void check_points(const symline_image *img, uint32_t m, const symline_point *p, uint32_t n)
{
    const uint32_t w = img->width, h = img->height;
    uint32_t i;
    uint8_t *seen;
    if (n > symline_features_max_points(w, h)) {
        abort();
    }
    seen = (uint8_t *)calloc((size_t)w * h + 1u, 1u);
    if (seen == NULL) {
        abort();
    }
    for (i = 0; i < n; i++) {
        if (p[i].x < 1u || p[i].y < 1u || p[i].x + 1u >= w || p[i].y + 1u >= h || p[i].fx != 0 ||
            p[i].fy != 0 ||
            (i > 0u &&
             (p[i].y < p[i - 1u].y || (p[i].y == p[i - 1u].y && p[i].x <= p[i - 1u].x)))) {
            fprintf(stderr, "feature point %u (%u,%u) offset (%d,%d), frame %ux%u\n", i, p[i].x,
                    p[i].y, p[i].fx, p[i].fy, w, h);
            abort();
        }
        seen[(size_t)p[i].y * w + p[i].x] = 1u;
    }
    for (i = 0; i < n; i++) {
        const size_t k = (size_t)p[i].y * w + p[i].x;
        if (seen[k + 1u] || seen[k + w]) {
            fprintf(stderr, "feature points adjacent at (%u,%u)\n", p[i].x, p[i].y);
            abort();
        }
    }
    free(seen);
    if ((size_t)w * h <= 96u * 96u) {
        symline_point *r = (symline_point *)calloc((size_t)n + 1u, sizeof *r);
        uint32_t rn;
        if (r == NULL) {
            abort();
        }
        rn = reference(img, m, r, n);
        if (rn != n) {
            fprintf(stderr, "features: %u points, the extrema maps have %u\n", n, rn);
            abort();
        }
        for (i = 0; i < n; i++) {
            if (r[i].x != p[i].x || r[i].y != p[i].y) {
                fprintf(stderr, "feature point %u: (%u,%u), the extrema maps (%u,%u)\n", i, p[i].x,
                        p[i].y, r[i].x, r[i].y);
                abort();
            }
        }
        free(r);
    }
}

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
    fz_in in = {data, size};
    uint32_t w = fz_dim(&in), h = fz_dim(&in), stride, m, cap, count = 0xDEADu;
    const uint32_t nulls = fz_u8(&in);
    const int none = (nulls & 0xC0u) == 0xC0u;
    size_t img_len, wsq, wsn, pt_bytes;
    uint8_t *px, *ws, *pts;
    symline_image img;
    symline_status st;

    if (fz_u8(&in) % 16u == 0u) {
        /* a wide or a tall strip */
        /* mostly up to 4099 px (the cost grows with the radius times the
         * area), sometimes the largest size */
        const uint32_t big = fz_u8(&in) == 255u ? 65535u : 200u + fz_u16(&in) % 3900u;
        if (fz_u8(&in) & 1u) {
            w = big;
            h = 1u + h % 6u;
        } else {
            h = big;
            w = 1u + w % 6u;
        }
    }
    stride = w + (fz_u8(&in) % 4u == 0u ? fz_u8(&in) % 9u : 0u);
    if (fz_u8(&in) % 16u == 0u && w > 0u) {
        stride = w - 1u;
    }
    m = pick_radius(&in);
    wsq = symline_features_workspace_size(w, h, m);
    if ((wsq > 0u) != (w >= 1u && h >= 1u && w <= 65535u && h <= 65535u && m >= 1u && m <= 255u)) {
        abort(); /* the query is 0 exactly for invalid arguments */
    }
    wsn = fz_size(&in, wsq > 0u ? wsq : 256u);
    switch (fz_u8(&in) % 4u) {
    case 0: cap = 0u; break;
    case 1: cap = symline_features_max_points(w, h); break;
    case 2: cap = fz_u8(&in) % 8u; break;
    default: cap = fz_u16(&in) % 512u; break;
    }
    if (cap > 1u << 20) {
        cap = 1u << 20;
    }
    pt_bytes = (size_t)cap * sizeof(symline_point);
    pts = fz_buf(pt_bytes, 0x5A);
    ws = fz_buf(wsn, 0x33);
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
    img.data = none && (nulls & 1u) ? NULL : px;

    st = symline_features(
        none && (nulls & 2u) ? NULL : &img, m, none && (nulls & 4u) ? NULL : ws, wsn,
        (none && (nulls & 8u)) || (cap == 0u && (nulls & 16u)) ? NULL
                                                               : (symline_point *)(void *)pts,
        cap, none && (nulls & 32u) ? NULL : &count);
    fz_check_status(st, "symline_features");
    fz_check_guard(ws, wsn, "workspace");
    fz_check_guard(pts, pt_bytes, "points");
    if (st == SYMLINE_OK) {
        if (count > cap) {
            abort();
        }
        check_points(&img, m, (const symline_point *)(const void *)pts, count);
    } else if (st == SYMLINE_ERR_BUFFER && count != 0xDEADu) {
        /* The points did not fit: *count is the frame's number; again with it. */
        uint8_t *more;
        uint32_t again = 0xDEADu;
        if (count <= cap || wsn < wsq) {
            abort();
        }
        more = fz_buf((size_t)count * sizeof(symline_point), 0x5A);
        st = symline_features(&img, m, ws, wsn, (symline_point *)(void *)more, count, &again);
        fz_check_guard(more, (size_t)count * sizeof(symline_point), "points");
        if (st != SYMLINE_OK || again != count) {
            abort();
        }
        check_points(&img, m, (const symline_point *)(const void *)more, count);
        free(more);
    } else {
        if (count != 0xDEADu) {
            abort();
        }
        fz_check_untouched(pts, pt_bytes, 0x5A, "points");
    }
    if (symline_features_max_points(w, h) !=
        (w >= 3u && h >= 3u && w <= 65535u && h <= 65535u
             ? (uint32_t)(((uint64_t)(w - 2u) * (h - 2u) + 1u) / 2u)
             : 0u)) {
        abort();
    }
    free(px);
    free(ws);
    free(pts);
    return 0;
}

/* SPDX-License-Identifier: Apache-2.0 */
/*
 * Pixel format table and luma extraction for the capture sources.
 */
#include "pixfmt.h"

#include <ctype.h>
#include <string.h>

static const pixfmt_info formats[] = {
    {PIXFMT_FOURCC('G', 'R', 'E', 'Y'), "GREY", PIXFMT_LUMA_PLANE, 0, 0, 1, 0, 0, 0, NULL},
    {PIXFMT_FOURCC('N', 'V', '1', '2'), "NV12", PIXFMT_LUMA_PLANE, 0, 1, 1, 0, 0, 0, NULL},
    {PIXFMT_FOURCC('N', 'V', '2', '1'), "NV21", PIXFMT_LUMA_PLANE, 0, 2, 1, 0, 0, 0, NULL},
    {PIXFMT_FOURCC('Y', 'U', '1', '2'), "YU12", PIXFMT_LUMA_PLANE, 0, 3, 1, 0, 0, 0, NULL},
    {PIXFMT_FOURCC('Y', 'V', '1', '2'), "YV12", PIXFMT_LUMA_PLANE, 0, 4, 1, 0, 0, 0, NULL},
    {PIXFMT_FOURCC('N', 'V', '1', '6'), "NV16", PIXFMT_LUMA_PLANE, 0, 5, 1, 0, 0, 0, NULL},
    {PIXFMT_FOURCC('N', 'V', '6', '1'), "NV61", PIXFMT_LUMA_PLANE, 0, 6, 1, 0, 0, 0, NULL},
    {PIXFMT_FOURCC('4', '2', '2', 'P'), "422P", PIXFMT_LUMA_PLANE, 0, 7, 1, 0, 0, 0, NULL},
    /* Multi-planar variants (luma in its own buffer, plane 0). */
    {PIXFMT_FOURCC('N', 'M', '1', '2'), "NM12", PIXFMT_LUMA_PLANE, 0, 1, 1, 0, 0, 0, NULL},
    {PIXFMT_FOURCC('N', 'M', '2', '1'), "NM21", PIXFMT_LUMA_PLANE, 0, 2, 1, 0, 0, 0, NULL},
    {PIXFMT_FOURCC('Y', 'M', '1', '2'), "YM12", PIXFMT_LUMA_PLANE, 0, 3, 1, 0, 0, 0, NULL},
    {PIXFMT_FOURCC('Y', 'M', '2', '1'), "YM21", PIXFMT_LUMA_PLANE, 0, 4, 1, 0, 0, 0, NULL},
    {PIXFMT_FOURCC('N', 'M', '1', '6'), "NM16", PIXFMT_LUMA_PLANE, 0, 5, 1, 0, 0, 0, NULL},
    {PIXFMT_FOURCC('N', 'M', '6', '1'), "NM61", PIXFMT_LUMA_PLANE, 0, 6, 1, 0, 0, 0, NULL},
    {PIXFMT_FOURCC('Y', 'M', '1', '6'), "YM16", PIXFMT_LUMA_PLANE, 0, 7, 1, 0, 0, 0, NULL},
    {PIXFMT_FOURCC('Y', 'U', 'Y', 'V'), "YUYV", PIXFMT_PACKED_422, 0, 10, 2, 0, 0, 0, NULL},
    {PIXFMT_FOURCC('Y', 'V', 'Y', 'U'), "YVYU", PIXFMT_PACKED_422, 0, 11, 2, 0, 0, 0, NULL},
    {PIXFMT_FOURCC('U', 'Y', 'V', 'Y'), "UYVY", PIXFMT_PACKED_422, 1, 12, 2, 0, 0, 0, NULL},
    {PIXFMT_FOURCC('V', 'Y', 'U', 'Y'), "VYUY", PIXFMT_PACKED_422, 1, 13, 2, 0, 0, 0, NULL},
    /* Packed RGB, byte order in memory as named by V4L2. */
    {PIXFMT_FOURCC('R', 'G', 'B', '3'), "RGB3", PIXFMT_PACKED_RGB, 0, 20, 3, 0, 1, 2, NULL},
    {PIXFMT_FOURCC('B', 'G', 'R', '3'), "BGR3", PIXFMT_PACKED_RGB, 0, 21, 3, 2, 1, 0, NULL},
    {PIXFMT_FOURCC('X', 'R', '2', '4'), "XR24", PIXFMT_PACKED_RGB, 0, 22, 4, 2, 1, 0, NULL},
    {PIXFMT_FOURCC('A', 'R', '2', '4'), "AR24", PIXFMT_PACKED_RGB, 0, 23, 4, 2, 1, 0, NULL},
    {PIXFMT_FOURCC('X', 'B', '2', '4'), "XB24", PIXFMT_PACKED_RGB, 0, 24, 4, 0, 1, 2, NULL},
    {PIXFMT_FOURCC('A', 'B', '2', '4'), "AB24", PIXFMT_PACKED_RGB, 0, 25, 4, 0, 1, 2, NULL},
    /* 8-bit Bayer mosaics: raw sensors without an ISP. */
    {PIXFMT_FOURCC('B', 'A', '8', '1'), "BA81", PIXFMT_BAYER8, 0, 30, 1, 0, 0, 0, "BGGR"},
    {PIXFMT_FOURCC('G', 'B', 'R', 'G'), "GBRG", PIXFMT_BAYER8, 0, 31, 1, 0, 0, 0, "GBRG"},
    {PIXFMT_FOURCC('G', 'R', 'B', 'G'), "GRBG", PIXFMT_BAYER8, 0, 32, 1, 0, 0, 0, "GRBG"},
    {PIXFMT_FOURCC('R', 'G', 'G', 'B'), "RGGB", PIXFMT_BAYER8, 0, 33, 1, 0, 0, 0, "RGGB"},
    /* Motion-JPEG: decoding costs more than any raw format, so it comes last. */
    {PIXFMT_FOURCC('M', 'J', 'P', 'G'), "MJPG", PIXFMT_JPEG, 0, 40, 0, 0, 0, 0, NULL},
    {PIXFMT_FOURCC('J', 'P', 'E', 'G'), "JPEG", PIXFMT_JPEG, 0, 41, 0, 0, 0, 0, NULL},
};

size_t pixfmt_count(void)
{
    return sizeof formats / sizeof formats[0];
}

const pixfmt_info *pixfmt_at(size_t i)
{
    return i < pixfmt_count() ? &formats[i] : NULL;
}

const pixfmt_info *pixfmt_find(uint32_t fourcc)
{
    size_t i;
    for (i = 0; i < pixfmt_count(); i++) {
        if (formats[i].fourcc == fourcc) {
            return &formats[i];
        }
    }
    return NULL;
}

const pixfmt_info *pixfmt_by_name(const char *name)
{
    char up[5];
    size_t i, n;
    if (name == NULL) {
        return NULL;
    }
    n = strlen(name);
    if (n != 4) {
        return NULL;
    }
    for (i = 0; i < 4; i++) {
        up[i] = (char)toupper((unsigned char)name[i]);
    }
    up[4] = '\0';
    /* I420 is the common name of YU12 outside V4L2. */
    if (strcmp(up, "I420") == 0) {
        return pixfmt_find(PIXFMT_FOURCC('Y', 'U', '1', '2'));
    }
    /* BA81 is V4L2's fourcc of the BGGR mosaic. */
    if (strcmp(up, "BGGR") == 0) {
        return pixfmt_find(PIXFMT_FOURCC('B', 'A', '8', '1'));
    }
    for (i = 0; i < pixfmt_count(); i++) {
        if (strcmp(formats[i].name, up) == 0) {
            return &formats[i];
        }
    }
    return NULL;
}

void pixfmt_fourcc_str(uint32_t fourcc, char out[5])
{
    int i;
    for (i = 0; i < 4; i++) {
        unsigned c = (fourcc >> (8 * i)) & 0xffu;
        out[i] = (c >= 0x20 && c < 0x7f) ? (char)c : '?';
    }
    out[4] = '\0';
}

uint64_t pixfmt_min_stride(const pixfmt_info *fmt, uint32_t width)
{
    return (uint64_t)fmt->bytes_per_pixel * width;
}

static void rgb_to_luma(const pixfmt_info *fmt, const uint8_t *src, uint32_t src_stride, uint32_t width,
                        uint32_t height, uint8_t *dst, uint32_t dst_stride)
{
    uint32_t y;
    const size_t bpp = fmt->bytes_per_pixel, n = width;
    const size_t ro = fmt->r, go = fmt->g, bo = fmt->b;
    for (y = 0; y < height; y++) {
        const uint8_t *s = src + (size_t)y * src_stride;
        uint8_t *d = dst + (size_t)y * dst_stride;
        size_t x;
        for (x = 0; x < n; x++) {
            const uint8_t *p = s + x * bpp;
            /* The same rounding as imgio's colour conversion, so replayed PNGs and live frames agree. */
            d[x] = (uint8_t)((299u * p[ro] + 587u * p[go] + 114u * p[bo] + 500u) / 1000u);
        }
    }
}

/* Index of the neighbour of i at offset d (-1 or +1) in 0..n-1, the mosaic mirrored by two at the ends. */
static uint32_t bayer_at(uint32_t i, int d, uint32_t n)
{
    if (d < 0) {
        return i >= 1u ? i - 1u : (n > 1u ? 1u : 0u);
    }
    return i + 1u < n ? i + 1u : (n >= 2u ? n - 2u : 0u);
}

static void bayer_to_luma(const pixfmt_info *fmt, const uint8_t *src, uint32_t src_stride, uint32_t width,
                          uint32_t height, uint8_t *dst, uint32_t dst_stride)
{
    /* Per colour, twice its BT.601 weight in thousandths (green counts twice per window). */
    uint32_t coef[2][2][3][3]; /* [y parity][x parity][dy + 1][dx + 1] */
    static const uint32_t k[3] = {1u, 2u, 1u};
    uint32_t py, px, dy, dx, y;
    for (py = 0; py < 2u; py++) {
        for (px = 0; px < 2u; px++) {
            for (dy = 0; dy < 3u; dy++) {
                for (dx = 0; dx < 3u; dx++) {
                    const char c = fmt->cfa[((py + dy + 1u) & 1u) * 2u + ((px + dx + 1u) & 1u)];
                    const uint32_t w = c == 'R' ? 598u : (c == 'G' ? 587u : 228u);
                    coef[py][px][dy][dx] = k[dy] * k[dx] * w;
                }
            }
        }
    }
    for (y = 0; y < height; y++) {
        const uint8_t *rows[3];
        uint8_t *d = dst + (size_t)y * dst_stride;
        uint32_t x;
        rows[0] = src + (size_t)bayer_at(y, -1, height) * src_stride;
        rows[1] = src + (size_t)y * src_stride;
        rows[2] = src + (size_t)bayer_at(y, 1, height) * src_stride;
        for (x = 0; x < width; x++) {
            uint32_t(*c)[3] = coef[y & 1u][x & 1u];
            const uint32_t xm = bayer_at(x, -1, width), xp = bayer_at(x, 1, width);
            uint32_t sum = 0;
            for (dy = 0; dy < 3u; dy++) {
                sum += c[dy][0] * rows[dy][xm] + c[dy][1] * rows[dy][x] + c[dy][2] * rows[dy][xp];
            }
            /* The weights add up to 4 windows x 2000. */
            d[x] = (uint8_t)((sum + 4000u) / 8000u);
        }
    }
}

void pixfmt_unpack_luma(const pixfmt_info *fmt, const uint8_t *src, uint32_t src_stride,
                        uint32_t width, uint32_t height, uint8_t *dst, uint32_t dst_stride)
{
    uint32_t y;
    size_t x;
    const size_t n = width;
    const uint32_t off = fmt->luma_offset;
    if (fmt->layout == PIXFMT_PACKED_RGB) {
        rgb_to_luma(fmt, src, src_stride, width, height, dst, dst_stride);
        return;
    }
    if (fmt->layout == PIXFMT_BAYER8) {
        bayer_to_luma(fmt, src, src_stride, width, height, dst, dst_stride);
        return;
    }
    if (fmt->layout != PIXFMT_PACKED_422) {
        return; /* luma planes need no unpacking; JPEG is decoded elsewhere */
    }
    for (y = 0; y < height; y++) {
        /* Every second byte, from a fixed phase: with a size_t index (no wrap-around)
         * the compiler turns this into vector shuffles. */
        const uint8_t *s = src + (size_t)y * src_stride + off;
        uint8_t *d = dst + (size_t)y * dst_stride;
        for (x = 0; x < n; x++) {
            d[x] = s[2 * x];
        }
    }
}

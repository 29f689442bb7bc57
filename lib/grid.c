/* SPDX-License-Identifier: Apache-2.0 */
/*
 * The scale grid: rows of the frame box-downsampled by 2^level, rounded
 * block means. Every coarse pass reads the whole frame once through here,
 * so the rows are summed in lanes over whole rows: the block rows added
 * down in 16-bit lanes (at most 32 * 255), then neighbours added pairwise,
 * halving the row per step, while 16 bits hold the sums (levels <= 4:
 * 256 * 255 < 2^16). The size builds (SL_FOR_SPEED 0) and level 5 sum
 * one block at a time. A version from port/ (SYMLINE_PORT_GRID) replaces
 * the detector's row call (symline_i_grid_row(), linepoints.c), whose
 * reference this is then.
 */
#include "grid.h"

/* Neighbour pairs of a[0 .. 2n-1] into b[0 .. n-1]. */
static void pairs(const uint16_t *restrict a, size_t n, uint16_t *restrict b)
{
    size_t x;
    for (x = 0; x < n; x++) {
        b[x] = (uint16_t)(a[2u * x] + a[2u * x + 1u]);
    }
}

/* The portable lane loops: all w pixels (levels 1..4). acc (w 2^level
 * entries) holds the row's pair sums, then each halving after the last. */
static void lanes(const uint8_t *src, size_t stride, uint32_t level, uint32_t w, uint16_t *acc,
                  uint8_t *out)
{
    const uint32_t shift = 2u * level;
    uint32_t d;
    size_t x, n = ((size_t)w << level) / 2u;
    uint16_t *a = acc;
    for (x = 0; x < n; x++) {
        acc[x] = (uint16_t)(src[2u * x] + src[2u * x + 1u]);
    }
    for (d = 1u; d < (1u << level); d++) {
        const uint8_t *r = src + (size_t)d * stride;
        for (x = 0; x < n; x++) {
            acc[x] = (uint16_t)(acc[x] + r[2u * x] + r[2u * x + 1u]);
        }
    }
    for (; n > w; n /= 2u) {
        pairs(a, n / 2u, a + n);
        a += n;
    }
    for (x = 0; x < w; x++) {
        out[x] = (uint8_t)(((uint32_t)a[x] + ((1u << shift) >> 1)) >> shift);
    }
}

void symline_i_grid_level_row(const symline_image *img, uint32_t level, uint32_t y, uint16_t *acc,
                              uint8_t *out, uint8_t *twin)
{
    /* The width in a local: out (bytes) might alias the image's fields. */
    const uint32_t w = img->width >> level;
    const size_t stride = img->stride;
    const uint8_t *src = img->data + ((size_t)y << level) * stride;
    if (SL_FOR_SPEED && level - 1u < 4u) { /* levels 1..4 */
        lanes(src, stride, level, w, acc, out);
        symline_i_grid_twin(out, 0u, w, twin);
        return;
    }
    symline_i_grid_blocks(src, stride, level, 0u, w, out);
    symline_i_grid_twin(out, 0u, w, twin);
}

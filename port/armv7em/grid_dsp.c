/* SPDX-License-Identifier: Apache-2.0 */
/*
 * symline_i_grid_row() (the scale grid's box sums, lib/linepoints.c) with the
 * ARMv7E-M DSP instructions (Cortex-M4, M7), selected at build time (CMake
 * option SYMLINE_SIMD, port/CMakeLists.txt) in place of the portable
 * reference symline_i_grid_row_c(), with the same output (the target tests,
 * port/cortex-m/test_core.c, compare the two).
 *
 * Why: the reference adds the block's rows into a row of 16-bit sums and then
 * the sums across, a load and a store per frame pixel and row. Here the
 * bytes are read a word at a time and summed in registers: 2x2 blocks in two
 * 16-bit halves (UXTAB16 adds bytes 0 and 2, or 1 and 3, of a word to the
 * halves), four outputs per step; larger blocks four bytes per USADA8
 * (the sum of absolute differences against zero is the sum of the bytes).
 * The rounding half block starts the sums.
 */
#include <arm_acle.h>
#include <string.h>

#include "linepoints.h"

static inline uint32_t load4(const uint8_t *p)
{
    uint32_t v;
    memcpy(&v, p, sizeof v); /* one LDR: ARMv7-M reads unaligned words */
    return v;
}

/* Two 2x2 sums plus 2 in the halves of the result: pixels 0-1 and 2-3 of
 * the words a (upper row) and b (lower row). */
static inline uint32_t sums2x2(uint32_t a, uint32_t b)
{
    uint32_t t = __uxtab16(0x00020002u, a);
    t = __uxtab16(t, (a >> 8) | (a << 24));
    t = __uxtab16(t, b);
    return __uxtab16(t, (b >> 8) | (b << 24));
}

void symline_i_grid_row(const symline_image *img, const symline_i_pass *p, uint32_t y,
                        uint16_t *acc, uint8_t *out)
{
    const uint32_t level = p->level, w = p->w, s = 1u << level, shift = 2u * level;
    const size_t stride = img->stride;
    const uint8_t *src = img->data + (size_t)(y * s) * stride;
    uint32_t x = 0u;
    if (level == 1u) {
        const uint8_t *r0 = src, *r1 = src + stride;
        for (; x + 4u <= w; x += 4u, r0 += 8, r1 += 8) {
            /* (out0, out1) and (out2, out3) in 16-bit halves, then bytes. */
            uint32_t lo = (sums2x2(load4(r0), load4(r1)) >> 2) & 0x00ff00ffu;
            uint32_t hi = (sums2x2(load4(r0 + 4), load4(r1 + 4)) >> 2) & 0x00ff00ffu;
            uint32_t v;
            lo |= lo >> 8;
            hi |= hi >> 8;
            v = (lo & 0xffffu) | (hi << 16); /* PKHBT */
            memcpy(out + x, &v, sizeof v);
        }
    } else if (level >= 2u && level <= 7u) {
        const uint32_t half = (1u << shift) >> 1;
        for (; x < w; x++) {
            const uint8_t *b = src + (size_t)x * s;
            uint32_t sum = half, d, i;
            for (d = 0; d < s; d++, b += stride) {
                for (i = 0; i < s; i += 4u) {
                    sum = __usada8(load4(b + i), 0u, sum);
                }
            }
            out[x] = (uint8_t)(sum >> shift);
        }
        return;
    }
    if (x < w) {
        /* The rest of the row (the last 1..3 blocks at level 1): one block
         * at a time as the portable code would. */
        for (; x < w; x++) {
            const uint8_t *b = src + (size_t)x * s;
            uint32_t sum = (1u << shift) >> 1, d, i;
            for (d = 0; d < s; d++, b += stride) {
                for (i = 0; i < s; i++) {
                    sum += b[i];
                }
            }
            out[x] = (uint8_t)(sum >> shift);
        }
    }
    (void)acc;
}

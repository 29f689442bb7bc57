/* SPDX-License-Identifier: Apache-2.0 */
/*
 * symline_i_grid_row() (the scale grid's box sums: lib/grid.h; the portable
 * row call in lib/linepoints.c, over lib/grid.c) with the ARMv7E-M DSP
 * instructions (Cortex-M4, M7), selected at build time (CMake
 * option SYMLINE_SIMD, port/CMakeLists.txt) in place of the portable
 * reference symline_i_grid_row_c(), with the same output (the target tests,
 * port/cortex-m/test_core.c, compare the two).
 *
 * Why: the reference adds the block's rows into a row of 16-bit sums and then
 * the sums across, a load and a store per frame pixel and row. Here the
 * bytes are read a word at a time and summed in registers: 2x2 blocks in two
 * 16-bit halves (UXTAB16 adds bytes 0 and 2, or 1 and 3, of a word to the
 * halves), four outputs per step; larger blocks four bytes per USADA8
 * (the sum of absolute differences against zero is the sum of the bytes),
 * the 4x4 and 8x8 blocks of levels 2 and 3 unrolled. The rounding half
 * block starts the sums.
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

/* The 2x2 blocks' step, four outputs: (out0, out1) and (out2, out3) in the
 * 16-bit halves of two sums (the second in a0's register once a0 is
 * added), shifted, narrowed to bytes, packed; STORE writes the word. */
#define SL_GRID_L1_STEP(STORE)                                                    \
    "1:\n\t"                                                                      \
    "ldr     %[a0], [%[r0]], #4\n\t"                                              \
    "ldr     %[a1], [%[r0]], #4\n\t"                                              \
    "ldr     %[b0], [%[r1]], #4\n\t"                                              \
    "ldr     %[b1], [%[r1]], #4\n\t"                                              \
    "uxtab16 %[t0], %[half], %[a0]\n\t"                                           \
    "uxtab16 %[t0], %[t0], %[a0], ror #8\n\t"                                     \
    "uxtab16 %[t0], %[t0], %[b0]\n\t"                                             \
    "uxtab16 %[t0], %[t0], %[b0], ror #8\n\t"                                     \
    "uxtab16 %[a0], %[half], %[a1]\n\t"                                           \
    "uxtab16 %[a0], %[a0], %[a1], ror #8\n\t"                                     \
    "uxtab16 %[a0], %[a0], %[b1]\n\t"                                             \
    "uxtab16 %[a0], %[a0], %[b1], ror #8\n\t"                                     \
    "and     %[t0], %[bytes], %[t0], lsr #2\n\t" /* out0 | out1 << 16 */           \
    "and     %[a0], %[bytes], %[a0], lsr #2\n\t" /* out2 | out3 << 16 */           \
    "orr     %[t0], %[t0], %[t0], lsr #8\n\t"                                     \
    "orr     %[a0], %[a0], %[a0], lsr #8\n\t"                                     \
    "pkhbt   %[t0], %[t0], %[a0], lsl #16\n\t"                                    \
    STORE                                                                         \
    "cmp     %[o], %[end]\n\t"                                                     \
    "bne     1b"

/* The row into out and, where twin is not NULL, into twin; returns how many
 * of its first pixels are in twin already (the rest is copied). */
static uint32_t row(const symline_image *img, const symline_i_pass *p, uint32_t y, uint8_t *out,
                    uint8_t *twin)
{
    const uint32_t level = p->level, w = p->w, s = 1u << level, shift = 2u * level;
    const size_t stride = img->stride;
    const uint8_t *src = img->data + (size_t)(y * s) * stride;
    uint32_t x = 0u;
    if (level == 1u) {
        /* 2x2 blocks, four outputs per step (SL_GRID_L1_STEP), stored to
         * twin as well where it is wanted. In assembly because GCC does not
         * fold the rotations and shifts into the operands that take them (32
         * instructions per step instead of 20). */
        const uint32_t steps = w / 4u;
        if (steps > 0u) {
            const uint8_t *r0 = src, *r1 = src + stride;
            uint8_t *o = out, *tw = twin;
            const uint8_t *const end = out + 4u * steps;
            const uint32_t half = 0x00020002u, bytes = 0x00ff00ffu;
            uint32_t a0, a1, b0, b1, t0;
            if (tw == NULL) {
                __asm__ volatile(SL_GRID_L1_STEP("str     %[t0], [%[o]], #4\n\t")
                                 : [r0] "+r"(r0), [r1] "+r"(r1), [o] "+r"(o), [a0] "=&r"(a0),
                                   [a1] "=&r"(a1), [b0] "=&r"(b0), [b1] "=&r"(b1),
                                   [t0] "=&r"(t0)
                                 : [end] "r"(end), [half] "r"(half), [bytes] "r"(bytes)
                                 : "cc", "memory");
            } else {
                __asm__ volatile(SL_GRID_L1_STEP("str     %[t0], [%[o]], #4\n\t"
                                                 "str     %[t0], [%[tw]], #4\n\t")
                                 : [r0] "+r"(r0), [r1] "+r"(r1), [o] "+r"(o), [tw] "+r"(tw),
                                   [a0] "=&r"(a0), [a1] "=&r"(a1), [b0] "=&r"(b0),
                                   [b1] "=&r"(b1), [t0] "=&r"(t0)
                                 : [end] "r"(end), [half] "r"(half), [bytes] "r"(bytes)
                                 : "cc", "memory");
            }
            x = 4u * steps;
        }
        /* The last 1..3 blocks one at a time, as the portable code would. */
        symline_i_grid_blocks(src, stride, 1u, x, w, out);
        return x;
    } else if (level == 2u) {
        /* 4x4 blocks: one word per row */
        for (; x < w; x++) {
            const uint8_t *b = src + (size_t)x * 4u;
            uint32_t sum = __usada8(load4(b), 0u, 8u);
            sum = __usada8(load4(b + stride), 0u, sum);
            sum = __usada8(load4(b + 2u * stride), 0u, sum);
            sum = __usada8(load4(b + 3u * stride), 0u, sum);
            out[x] = (uint8_t)(sum >> 4);
        }
        return 0u;
    } else if (level == 3u) {
        /* 8x8 blocks: two words per row */
        for (; x < w; x++) {
            const uint8_t *b = src + (size_t)x * 8u;
            uint32_t sum = 32u, d;
            for (d = 0; d < 8u; d += 2u, b += 2u * stride) {
                sum = __usada8(load4(b), 0u, sum);
                sum = __usada8(load4(b + 4), 0u, sum);
                sum = __usada8(load4(b + stride), 0u, sum);
                sum = __usada8(load4(b + stride + 4), 0u, sum);
            }
            out[x] = (uint8_t)(sum >> 6);
        }
        return 0u;
    } else if (level >= 4u && level <= 7u) {
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
        return 0u;
    }
    /* Other levels (0, above 7): one block at a time as the portable code. */
    symline_i_grid_blocks(src, stride, level, 0u, w, out);
    return 0u;
}

void symline_i_grid_row(const symline_image *img, const symline_i_pass *p, uint32_t y,
                        uint16_t *acc, uint8_t *out, uint8_t *twin)
{
    const uint32_t w = p->w; /* a local: twin might alias p */
    symline_i_grid_twin(out, row(img, p, y, out, twin), w, twin);
    (void)acc;
}

/* SPDX-License-Identifier: Apache-2.0 */
/*
 * The symmetry operator's row bodies symline_i_energy_row() and
 * symline_i_energy_across() with AArch64 Advanced SIMD (NEON) intrinsics,
 * selected at build time (CMake option SYMLINE_SIMD, port/CMakeLists.txt) in
 * place of the portable references symline_i_energy_*_c() of lib/symmetry.c,
 * with the same output (tests/core/test_operator_simd.c compares them).
 *
 * Why: the reference adds one pair offset j at a time over the whole row,
 * loading and storing the row of 32-bit energies again for every pair. Here
 * all pairs of a block of 16 pixels are summed in registers and stored once,
 * and NEON has the exact operations: |a - b| in bytes (vabd), its square
 * widened to 16 bits (vmull, 255^2 < 2^16) and the weighted square added to
 * 32 bits (vmlal by the weight m+1-j <= 255), 9 instructions per pair and
 * 16 pixels. Every radius up to 255 fits: an energy is below 2^32. The passes
 * over a row, its ends and tail: ../symmetry_rows.h.
 */
#include <arm_neon.h>

/* Every radius the public calls take. */
#define SL_PORT_RADIUS_MAX 255u
#include "../symmetry_rows.h"

static inline __attribute__((always_inline)) void
run_pass(const sl_pass *ps, uint32_t np, uint32_t count, uint32_t init, int add, uint32_t *E)
{
    const uint8_t *lo[SL_PASS_PAIRS], *hi[SL_PASS_PAIRS];
    uint16_t w[SL_PASS_PAIRS];
    const uint32x4_t vinit = vdupq_n_u32(init);
    uint32_t p;
    size_t x = 0u;
    for (p = 0; p < np; p++) {
        lo[p] = ps->lo[p];
        hi[p] = ps->hi[p];
        w[p] = (uint16_t)ps->w[p];
    }
    for (;;) {
        uint32x4_t acc[4];
        int i;
        if (x + 16u > count) {
            if (x == count || add || count < 16u) {
                break;
            }
            x = count - 16u; /* the last 16 entries once more: the same values, rewritten */
        }
        for (i = 0; i < 4; i++) {
            acc[i] = add ? vld1q_u32(E + x + 4u * (size_t)i) : vinit;
        }
        for (p = 0; p < np; p++) {
            const uint8x16_t d = vabdq_u8(vld1q_u8(lo[p] + x), vld1q_u8(hi[p] + x));
            const uint16x8_t sl = vmull_u8(vget_low_u8(d), vget_low_u8(d));
            const uint16x8_t sh = vmull_high_u8(d, d);
            acc[0] = vmlal_n_u16(acc[0], vget_low_u16(sl), w[p]);
            acc[1] = vmlal_high_n_u16(acc[1], sl, w[p]);
            acc[2] = vmlal_n_u16(acc[2], vget_low_u16(sh), w[p]);
            acc[3] = vmlal_high_n_u16(acc[3], sh, w[p]);
        }
        for (i = 0; i < 4; i++) {
            vst1q_u32(E + x + 4u * (size_t)i, acc[i]);
        }
        if (x + 16u == count) {
            return;
        }
        x += 16u;
    }
    pass_tail(ps, np, x, count, init, add, E);
}

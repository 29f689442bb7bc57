/* SPDX-License-Identifier: Apache-2.0 */
/*
 * The S decision of a row's candidates at radius m = 3 (lib/linepoints.h)
 * with AArch64 Advanced SIMD (NEON) intrinsics, selected at build time
 * (CMake option SYMLINE_SIMD, port/CMakeLists.txt) in place of the
 * portable reference, with the same result (tests/core/test_linepoints_simd.c
 * compares them):
 *
 * symline_i_s_along3_keep() for symline_i_s_along3_keep_c(): entries
 * p[-4 .. 3] and p[-3 .. 4] of a candidate in two 8-byte loads, widened;
 * the pairs of E(i-1), E(i), E(i+1) lie 2j entries apart for d_j, so lanes
 * shifted by vext give d_j of all three in lanes 0 .. 2, and three widening
 * multiply-accumulates the energies 3 d1^2 + 2 d2^2 + d3^2 in 32-bit lanes.
 */
#include <arm_neon.h>

#include "linepoints.h"

/* The code of symline_i_s_along3_c() at p. */
static inline uint32_t s_along3(const uint8_t *p)
{
    const int16x8_t a = vreinterpretq_s16_u16(vmovl_u8(vld1_u8(p - 4))); /* -4 .. 3 */
    const int16x8_t b = vreinterpretq_s16_u16(vmovl_u8(vld1_u8(p - 3))); /* -3 .. 4 */
    /* d1: -2 .. 0 less 0 .. 2; d2: -3 .. -1 less 1 .. 3; d3: -4 .. -2 less 2 .. 4 */
    const int16x4_t d1 = vget_low_s16(vsubq_s16(vextq_s16(a, a, 2), vextq_s16(a, a, 4)));
    const int16x4_t d2 = vget_low_s16(vsubq_s16(vextq_s16(a, a, 1), vextq_s16(a, a, 5)));
    const int16x4_t d3 = vget_low_s16(vsubq_s16(a, vextq_s16(b, b, 5)));
    /* E(i-1), E(i), E(i+1) (and a lane of no use) */
    const int32x4_t e =
        vmlal_s16(vmlal_s16(vmull_s16(d3, d3), d2, vadd_s16(d2, d2)), d1, vmul_n_s16(d1, 3));
    const int32x4_t d = vsubq_s32(e, vdupq_laneq_s32(e, 1));
    const int32_t up = vgetq_lane_s32(d, 0), dn = vgetq_lane_s32(d, 2);
    return up < 0 || dn < 0 ? 0u : (up > 0 && dn > 0 ? 1u : 2u);
}

uint32_t symline_i_s_along3_keep(const uint8_t *row, uint16_t *cand, uint32_t k, uint64_t *plateau)
{
    const uint16_t *const end = cand + k;
    uint16_t *in = cand, *o = cand; /* the next kept entry goes to o */
    uint64_t pl = 0u;
    for (; in != end; in++) {
        const uint32_t x = *in, code = s_along3(row + x);
        *o = (uint16_t)x;
        if (code > 1u) { /* rare */
            pl |= (uint64_t)1 << (o - cand);
        }
        o += code != 0u ? 1 : 0;
    }
    *plateau = pl;
    return (uint32_t)(o - cand);
}

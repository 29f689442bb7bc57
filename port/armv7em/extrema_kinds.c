/* SPDX-License-Identifier: Apache-2.0 */
/*
 * symline_i_extrema_kinds() for ARMv7-M cores (built for Cortex-M4, M7 with
 * the DSP versions of port/armv7em/), selected at build time (CMake option
 * SYMLINE_SIMD, port/CMakeLists.txt) in place of the portable reference
 * symline_i_extrema_kinds_c() of lib/extrema.c, with the same output (the
 * target tests, port/cortex-m/test_core.c, compare the two).
 *
 * Why: a core without vector lanes pays for every operation of the
 * reference's branch-free decision, which is written for SIMD lanes (about
 * 21 instructions per entry as GCC compiles it for the M4). Here an entry
 * equal to a neighbour (a plateau, which the caller's slow path decides
 * anyway) leaves by the branch of the flag-setting subtraction; every other
 * entry has nonzero differences d1 = mid - up and d2 = mid - dn, so it is an
 * S point when both are negative (the sign of d1 & d2) and an A point when
 * neither is (the sign of d1 | d2): with the subtractions six data
 * operations, two entries per step from doubleword loads, 11.5 instructions
 * per entry. In assembly because GCC turns the decision back into
 * conditional moves and spills.
 */
#include "extrema.h"

uint32_t symline_i_extrema_kinds(const uint32_t *restrict up, const uint32_t *restrict mid,
                                 const uint32_t *restrict dn, uint32_t n, uint8_t *restrict map)
{
    const uint32_t pairs = n / 2u;
    uint32_t flat = 0u;
    if (pairs > 0u) {
        const uint32_t *const end = up + 2u * pairs;
        const uint32_t k = SYMLINE_MAP_A;
        uint32_t a0, a1, b0, b1, c0, c1;
        __asm__ volatile(
            "1:\n\t"
            "ldrd   %[a0], %[a1], [%[up]], #8\n\t"
            "ldrd   %[b0], %[b1], [%[mid]], #8\n\t"
            "ldrd   %[c0], %[c1], [%[dn]], #8\n\t"
            /* entry 0: d1 in a0, d2 in c0, the kind into c0 */
            "subs   %[a0], %[b0], %[a0]\n\t"
            "beq    3f\n\t"
            "subs   %[c0], %[b0], %[c0]\n\t"
            "beq    3f\n\t"
            "and    %[b0], %[a0], %[c0]\n\t"
            "orr    %[a0], %[a0], %[c0]\n\t"
            "bic    %[c0], %[k], %[a0], lsr #24\n\t" /* A: d1 | d2 not negative */
            "orr    %[c0], %[c0], %[b0], asr #31\n\t" /* S: d1 & d2 negative */
            "2:\n\t"
            "strb   %[c0], [%[map]], #1\n\t"
            /* entry 1 */
            "subs   %[a1], %[b1], %[a1]\n\t"
            "beq    5f\n\t"
            "subs   %[c1], %[b1], %[c1]\n\t"
            "beq    5f\n\t"
            "and    %[b1], %[a1], %[c1]\n\t"
            "orr    %[a1], %[a1], %[c1]\n\t"
            "bic    %[c1], %[k], %[a1], lsr #24\n\t"
            "orr    %[c1], %[c1], %[b1], asr #31\n\t"
            "4:\n\t"
            "strb   %[c1], [%[map]], #1\n\t"
            "cmp    %[up], %[end]\n\t"
            "bne    1b\n\t"
            "b      9f\n\t"
            /* an entry equal to a neighbour: neither kind, and a plateau */
            "3:\n\t"
            "mov    %[c0], #0\n\t"
            "mov    %[flat], #1\n\t"
            "b      2b\n\t"
            "5:\n\t"
            "mov    %[c1], #0\n\t"
            "mov    %[flat], #1\n\t"
            "b      4b\n\t"
            "9:"
            : [up] "+r"(up), [mid] "+r"(mid), [dn] "+r"(dn), [map] "+r"(map), [flat] "+r"(flat),
              [a0] "=&r"(a0), [a1] "=&r"(a1), [b0] "=&r"(b0), [b1] "=&r"(b1), [c0] "=&r"(c0),
              [c1] "=&r"(c1)
            : [end] "r"(end), [k] "r"(k)
            : "cc", "memory");
    }
    if ((n & 1u) != 0u) {
        flat |= symline_i_extrema_kinds_c(up, mid, dn, 1u, map);
    }
    return flat;
}

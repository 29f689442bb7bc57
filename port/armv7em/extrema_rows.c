/* SPDX-License-Identifier: Apache-2.0 */
/*
 * symline_i_extrema_along() and symline_i_extrema_across() for ARMv7-M cores
 * (built for Cortex-M4, M7 with the DSP versions of port/armv7em/), selected
 * at build time (CMake option SYMLINE_SIMD, port/CMakeLists.txt) in place of
 * the portable references of lib/extrema.c, with the same output (the
 * target tests, port/cortex-m/test_port.c, compare them).
 *
 * Why: a core without vector lanes pays for every operation of the
 * references' branch-free decision. Here an entry equal to a neighbour (a
 * plateau, rare) leaves the loop by the branch of a flag-setting subtraction
 * and sets its plateau bit there; every other entry has nonzero differences,
 * so its kind takes four data operations on their signs. In assembly
 * because GCC turns the decision back into conditional moves and spills.
 * Blocks of up to 32 entries: one plateau word each.
 */
#include "extrema.h"

/* Along a row, n <= 32 entries: with d1 = E[x] - E[x-1] and d2 = E[x] -
 * E[x+1] both nonzero, an S point when both are negative (the sign of
 * d1 & d2), an A point when neither is (the sign of d1 | d2). Two entries per
 * step; returns the plateau bits. */
static uint32_t along32(const uint32_t *E, uint32_t n, uint8_t *map)
{
    uint32_t bits = 0u;
    const uint32_t pairs = n / 2u;
    uint8_t *map0 = map; /* in-out below: a register of its own */
    if (pairs > 0u) {
        const uint32_t *const end = E + 1u + 2u * pairs; /* E + 1 loads first */
        const uint32_t k = SYMLINE_MAP_A;
        uint32_t a = E[-1], b = E[0], c, d, t1, t2;
        E++;
        __asm__ volatile(
            "1:\n\t"
            "ldrd   %[c], %[d], [%[E]], #8\n\t"
            /* entry 0: (a, b, c) */
            "subs   %[t1], %[b], %[a]\n\t"
            "beq    3f\n\t"
            "subs   %[t2], %[b], %[c]\n\t"
            "beq    4f\n\t"
            "and    %[a], %[t1], %[t2]\n\t"
            "orr    %[t1], %[t1], %[t2]\n\t"
            "bic    %[t2], %[k], %[t1], lsr #24\n\t"
            "orr    %[t2], %[t2], %[a], asr #31\n\t"
            "2:\n\t"
            "strb   %[t2], [%[map]], #1\n\t"
            /* entry 1: (b, c, d) */
            "subs   %[t1], %[c], %[b]\n\t"
            "beq    6f\n\t"
            "subs   %[t2], %[c], %[d]\n\t"
            "beq    7f\n\t"
            "and    %[a], %[t1], %[t2]\n\t"
            "orr    %[t1], %[t1], %[t2]\n\t"
            "bic    %[t2], %[k], %[t1], lsr #24\n\t"
            "orr    %[t2], %[t2], %[a], asr #31\n\t"
            "5:\n\t"
            "strb   %[t2], [%[map]], #1\n\t"
            "mov    %[a], %[c]\n\t"
            "mov    %[b], %[d]\n\t"
            "cmp    %[E], %[end]\n\t"
            "bne    1b\n\t"
            "b      9f\n\t"
            /* entry 0 equal to its left neighbour: a plateau end unless
             * equal to the right one too */
            "3:\n\t"
            "subs   %[t2], %[b], %[c]\n\t"
            "beq    8f\n\t"
            "4:\n\t"
            "sub    %[t1], %[map], %[map0]\n\t"
            "movs   %[t2], #1\n\t"
            "lsl    %[t2], %[t2], %[t1]\n\t"
            "orr    %[bits], %[bits], %[t2]\n\t"
            "8:\n\t"
            "movs   %[t2], #0\n\t"
            "b      2b\n\t"
            /* entry 1 likewise */
            "6:\n\t"
            "subs   %[t2], %[c], %[d]\n\t"
            "beq    10f\n\t"
            "7:\n\t"
            "sub    %[t1], %[map], %[map0]\n\t"
            "movs   %[t2], #1\n\t"
            "lsl    %[t2], %[t2], %[t1]\n\t"
            "orr    %[bits], %[bits], %[t2]\n\t"
            "10:\n\t"
            "movs   %[t2], #0\n\t"
            "b      5b\n\t"
            "9:"
            : [E] "+r"(E), [map] "+r"(map), [bits] "+r"(bits), [map0] "+r"(map0), [a] "+r"(a),
              [b] "+r"(b), [c] "=&r"(c), [d] "=&r"(d), [t1] "=&r"(t1), [t2] "=&r"(t2)
            : [end] "r"(end), [k] "r"(k)
            : "cc", "memory");
        E--;
    }
    if ((n & 1u) != 0u) { /* the last entry, E[0] here */
        const uint32_t d1 = E[0] - E[-1], d2 = E[0] - E[1];
        if (d1 == 0u || d2 == 0u) {
            *map = SYMLINE_MAP_NONE;
            bits |= (uint32_t)((d1 == 0u) != (d2 == 0u)) << (n - 1u);
        } else {
            *map = (uint8_t)((((d1 | d2) >> 31) ? 0u : (uint32_t)SYMLINE_MAP_A) |
                             ((d1 & d2) >> 31) * 0xffu);
        }
    }
    return bits;
}

/* Down the columns, n <= 32 entries: with the sign u of mid - up and e = dn
 * - mid both nonzero, an S point when u < 0 < e (the sign of u & ~e), an A
 * point when e < 0 < u (the sign of e & ~u); the next row's sign is that of
 * e. Returns the plateau bits. */
static uint32_t across32(const uint32_t *mid, const uint32_t *dn, int8_t *sg, uint32_t n,
                         uint8_t *map)
{
    uint32_t bits = 0u, b, c, u, e;
    uint8_t *map0 = map; /* in-out below: a register of its own */
    const uint32_t *const end = mid + n;
    const uint32_t k = SYMLINE_MAP_A, one = 1u;
    __asm__ volatile(
        "1:\n\t"
        "ldr    %[b], [%[mid]], #4\n\t"
        "ldr    %[c], [%[dn]], #4\n\t"
        "ldrsb  %[u], [%[sg]]\n\t"
        "subs   %[e], %[c], %[b]\n\t"
        "beq    3f\n\t"
        "cmp    %[u], #0\n\t"
        "beq    4f\n\t"
        "bic    %[b], %[u], %[e]\n\t"
        "bic    %[c], %[e], %[u]\n\t"
        "and    %[c], %[k], %[c], asr #24\n\t"
        "orr    %[c], %[c], %[b], asr #31\n\t"
        "orr    %[u], %[one], %[e], asr #31\n\t"
        "2:\n\t"
        "strb   %[u], [%[sg]], #1\n\t"
        "strb   %[c], [%[map]], #1\n\t"
        "cmp    %[mid], %[end]\n\t"
        "bne    1b\n\t"
        "b      9f\n\t"
        /* mid == dn: a plateau end unless mid == up too; the next sign 0 */
        "3:\n\t"
        "movs   %[c], #0\n\t"
        "cmp    %[u], #0\n\t"
        "mov    %[u], #0\n\t"
        "beq    2b\n\t"
        "5:\n\t"
        "sub    %[b], %[map], %[map0]\n\t"
        "lsl    %[b], %[one], %[b]\n\t"
        "orr    %[bits], %[bits], %[b]\n\t"
        "b      2b\n\t"
        /* mid == up != dn: a plateau end */
        "4:\n\t"
        "movs   %[c], #0\n\t"
        "orr    %[u], %[one], %[e], asr #31\n\t"
        "b      5b\n\t"
        "9:"
        : [mid] "+r"(mid), [dn] "+r"(dn), [sg] "+r"(sg), [map] "+r"(map), [bits] "+r"(bits),
          [map0] "+r"(map0), [b] "=&r"(b), [c] "=&r"(c), [u] "=&r"(u), [e] "=&r"(e)
        : [end] "r"(end), [k] "r"(k), [one] "r"(one)
        : "cc", "memory");
    return bits;
}

uint32_t symline_i_extrema_along(const uint32_t *E, uint32_t n, uint8_t *restrict map,
                                 uint32_t *restrict ev)
{
    uint32_t x0, any = 0u;
    for (x0 = 0; x0 < n; x0 += 32u) {
        const uint32_t bits = along32(E + x0, (n - x0 > 32u) ? 32u : n - x0, map + x0);
        ev[x0 / 32u] = bits;
        any |= bits;
    }
    return any;
}

uint32_t symline_i_extrema_across(const uint32_t *restrict mid, const uint32_t *restrict dn,
                                  int8_t *restrict sg, uint32_t n, uint8_t *restrict map,
                                  uint32_t *restrict ev)
{
    uint32_t x0, any = 0u;
    for (x0 = 0; x0 < n; x0 += 32u) {
        const uint32_t bits =
            across32(mid + x0, dn + x0, sg + x0, (n - x0 > 32u) ? 32u : n - x0, map + x0);
        ev[x0 / 32u] = bits;
        any |= bits;
    }
    return any;
}

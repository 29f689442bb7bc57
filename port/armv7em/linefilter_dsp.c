/* SPDX-License-Identifier: Apache-2.0 */
/*
 * The line filter's row work with the ARMv7E-M DSP instructions (Cortex-M4,
 * M7), selected at build time (CMake option SYMLINE_SIMD, port/CMakeLists.txt)
 * in place of the portable references, with the same output (the target
 * tests, port/cortex-m/test_port.c, compare them):
 *
 * symline_i_drop_dim_s() (reference symline_i_drop_dim_s_c(), lib/linepoints.c)
 * drops the S points that the filter's first gray tests reject, four map
 * entries per step in byte lanes: the brighter side by USUB8 and SEL, the
 * ridge above it by a saturating subtraction (UQSUB8), and the three limits as
 * saturating subtractions that leave zero exactly where a test passes; a step
 * without S points stops after its test (UADD8 and SEL). On a real frame
 * about one entry in four of a map row is an S point, and this leaves about
 * one in twenty for the scalar tests. The loop is in assembly, 27
 * instructions for a step with S points and 7 without, where GCC's takes
 * about 38 and 14.
 *
 * symline_i_find_s() (reference symline_i_find_s_c(), lib/linefilter.h) then
 * finds those few eight entries per step: adding 1 to every byte lane (UADD8)
 * carries out of exactly the S lanes (255), which sets their GE flags, and SEL
 * turns the flags into a byte mask.
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

/* 0xff in the byte lanes of w that hold an S point, 0 elsewhere. */
static inline uint32_t s_lanes(uint32_t w)
{
    (void)__uadd8(w, 0x01010101u); /* GE: w's byte is 255 */
    return (uint32_t)__sel(0xffffffffu, 0u);
}

static inline uint32_t bytes4(uint32_t v)
{
    return v * 0x01010101u;
}

void symline_i_drop_dim_s(const symline_i_linefilter *f, const uint8_t *c, const uint8_t *lo,
                          const uint8_t *hi, uint32_t n, uint8_t *map)
{
    const uint32_t mg = bytes4(f->min_gray < 255u ? f->min_gray : 255u);
    uint32_t sm = bytes4(255u), rm = 0u, x = 0u;
    if (f->kind != SYMLINE_FILTER_PAPER) {
        sm = bytes4(f->side_max < 255u ? f->side_max : 255u);
        rm = bytes4(f->ridge_min < 1u ? 1u : f->ridge_min < 255u ? f->ridge_min : 255u);
    } else {
        lo = c; /* the paper's filter: gray only (side c, ridge 0 >= rm = 0) */
        hi = c;
    }
    if (n >= 4u) {
        /* x runs from -4 * steps up to 0 against the ends of the rows; the
         * limits are read from memory (the registers are all taken). */
        const uint32_t steps = n / 4u;
        const uint8_t *const ce = c + 4u * steps, *const le = lo + 4u * steps,
                             *const he = hi + 4u * steps;
        uint8_t *const me = map + 4u * steps;
        const uint32_t ones = 0x01010101u, zero = 0u;
        uint32_t i = 0u - 4u * steps, m, t, cv, lv, hv, k;
        __asm__ volatile(
            "1:\n\t"
            "ldr    %[m], [%[me], %[i]]\n\t"
            "uadd8  %[t], %[m], %[ones]\n\t" /* GE: an S point (255) */
            "sel    %[t], %[ones], %[zero]\n\t"
            "cmp    %[t], #0\n\t"
            "beq    2f\n\t"
            "ldr    %[cv], [%[ce], %[i]]\n\t"
            "ldr    %[lv], [%[le], %[i]]\n\t"
            "ldr    %[hv], [%[he], %[i]]\n\t"
            "usub8  %[t], %[lv], %[hv]\n\t" /* GE: lo >= hi */
            "sel    %[lv], %[lv], %[hv]\n\t" /* the brighter side */
            "uqsub8 %[hv], %[cv], %[lv]\n\t" /* the ridge above it, or 0 */
            /* zero in the lanes that pass all three tests */
            "ldr    %[k], %[mg]\n\t"
            "uqsub8 %[cv], %[k], %[cv]\n\t"
            "ldr    %[k], %[sm]\n\t"
            "uqsub8 %[lv], %[lv], %[k]\n\t"
            "orr    %[cv], %[cv], %[lv]\n\t"
            "ldr    %[k], %[rm]\n\t"
            "uqsub8 %[hv], %[k], %[hv]\n\t"
            "orr    %[cv], %[cv], %[hv]\n\t"
            "usub8  %[t], %[zero], %[cv]\n\t" /* GE: the lane passes */
            "sel    %[t], %[zero], %[m]\n\t" /* the map where it fails */
            "and    %[t], %[t], #0x7f7f7f7f\n\t" /* 0x7f where an S point fails */
            "orr    %[t], %[t], %[t], lsl #1\n\t"
            "bic    %[m], %[m], %[t]\n\t"
            "str    %[m], [%[me], %[i]]\n\t"
            "2:\n\t"
            "adds   %[i], %[i], #4\n\t"
            "bne    1b"
            : [i] "+r"(i), [m] "=&r"(m), [t] "=&r"(t), [cv] "=&r"(cv), [lv] "=&r"(lv),
              [hv] "=&r"(hv), [k] "=&r"(k)
            : [me] "r"(me), [ce] "r"(ce), [le] "r"(le), [he] "r"(he), [ones] "r"(ones),
              [zero] "r"(zero), [mg] "m"(mg), [sm] "m"(sm), [rm] "m"(rm)
            : "cc", "memory");
        x = 4u * steps;
    }
    /* The last 1..3 entries one at a time (here rather than by a call of the
     * reference: this runs at the bottom of the detector's deepest chain). */
    for (; x < n; x++) {
        const uint32_t side = lo[x] > hi[x] ? lo[x] : hi[x];
        const uint32_t ridge = c[x] > side ? (uint32_t)c[x] - side : 0u;
        if (map[x] == SYMLINE_MAP_S && (c[x] < (mg & 0xffu) || side > (sm & 0xffu) ||
                                        ridge < (rm & 0xffu))) {
            map[x] = SYMLINE_MAP_NONE;
        }
    }
}

uint32_t symline_i_find_s(const uint8_t *map, uint32_t x, uint32_t n)
{
    if (x + 8u <= n) {
        const uint8_t *p = map + x;
        const uint8_t *const last = map + (n - 8u);
        do {
            uint32_t m = s_lanes(load4(p));
            if (m != 0u) {
                return (uint32_t)(p - map) + (uint32_t)__builtin_ctz(m) / 8u;
            }
            m = s_lanes(load4(p + 4));
            if (m != 0u) {
                return (uint32_t)(p - map) + 4u + (uint32_t)__builtin_ctz(m) / 8u;
            }
            p += 8;
        } while (p <= last);
        x = (uint32_t)(p - map);
    }
    return symline_i_find_s_c(map, x, n);
}

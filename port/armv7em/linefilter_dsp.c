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
 * saturating subtractions that leave zero exactly where a test passes. On a
 * real frame about one entry in four of a map row is an S point, and this
 * leaves about one in twenty for the scalar tests.
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
    for (; x + 4u <= n; x += 4u) {
        const uint32_t mv = load4(map + x);
        const uint32_t s = s_lanes(mv);
        if (s != 0u) {
            const uint32_t cv = load4(c + x), lv = load4(lo + x), hv = load4(hi + x);
            uint32_t side, ridge, fail;
            (void)__usub8(lv, hv); /* GE: lo >= hi */
            side = (uint32_t)__sel(lv, hv);
            ridge = (uint32_t)__uqsub8(cv, side);
            /* zero in a lane exactly where c >= mg, side <= sm and ridge >= rm */
            fail = (uint32_t)__uqsub8(mg, cv) | (uint32_t)__uqsub8(side, sm) |
                   (uint32_t)__uqsub8(rm, ridge);
            (void)__usub8(0u, fail); /* GE: the lane passes (fail == 0) */
            fail = (uint32_t)__sel(0u, 0xffffffffu);
            if ((s & fail) != 0u) {
                const uint32_t v = mv & ~(s & fail);
                memcpy(map + x, &v, sizeof v);
            }
        }
    }
    if (x < n) {
        symline_i_drop_dim_s_c(f, c + x, lo + x, hi + x, n - x, map + x);
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

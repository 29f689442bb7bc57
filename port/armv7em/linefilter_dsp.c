/* SPDX-License-Identifier: Apache-2.0 */
/*
 * The line filter's byte test over a row with the ARMv7E-M DSP instructions
 * (Cortex-M4, M7), selected at build time (CMake option SYMLINE_SIMD,
 * port/CMakeLists.txt) in place of the portable reference of
 * lib/linefilter.h, with the same result (the target tests,
 * port/cortex-m/test_port.c, compare them):
 *
 * symline_i_line_cand() for symline_i_line_cand_c(): four entries per word
 * in byte lanes, the brighter side by USUB8 and SEL, side + ridge_min
 * saturating by UQADD8, and the three limits as saturating subtractions
 * (UQSUB8) that leave zero exactly where a test passes; 1 minus all three,
 * saturating, is 1 in a lane that passes. One to five entries in a hundred
 * pass, so a step tests 16 entries and one branch skips it when none
 * passes; only then are its lanes visited. The step is in assembly, 54
 * instructions (3.4 per entry: 3 loads and 9 lane instructions per word,
 * 3 ORs, 3 for the branches), where GCC's from the same intrinsics takes
 * 68 (it keeps the row pointers on the stack). On the benchmark's
 * 320x240 frame (tools/firmware/insnprof.sh) this function takes 12.3
 * instructions per frame pixel, the portable reference, inlined, about 37.
 */
#include <arm_acle.h>
#include <string.h>

#include "linefilter.h"

static inline uint32_t load4(const uint8_t *p)
{
    uint32_t v;
    memcpy(&v, p, sizeof v); /* one LDR: ARMv7-M reads unaligned words */
    return v;
}

/* 1 in the byte lanes of entries x .. x+3 that pass the byte test, else 0. */
static inline uint32_t pass4(const uint8_t *c, const uint8_t *lo, const uint8_t *hi, uint32_t x,
                             uint32_t mg, uint32_t rm, uint32_t sm)
{
    const uint32_t cv = load4(c + x), lv = load4(lo + x), hv = load4(hi + x);
    uint32_t side;
    (void)__usub8(lv, hv); /* GE: lo >= hi */
    side = __sel(lv, hv);
    /* how far c stays below each need, and side above side_max: 0 passes */
    return __uqsub8(
        __uqsub8(__uqsub8(0x01010101u, __uqsub8(__uqadd8(side, rm), cv)), __uqsub8(mg, cv)),
        __uqsub8(side, sm));
}

/* Appends base + lane for every lane of p that holds 1; false when out
 * filled up (then *next is the entry after the last one). */
static inline int report(uint32_t p, uint32_t base, uint16_t *out, uint32_t *k, uint32_t *next)
{
    for (; p != 0u; p &= p - 1u) {
        const uint32_t i = base + (uint32_t)__builtin_ctz(p) / 8u;
        out[(*k)++] = (uint16_t)i;
        if (*k == SL_LINE_CAND_MAX) {
            *next = i + 1u;
            return 0;
        }
    }
    return 1;
}

/* The test of one word, 4 entries, in byte lanes; p: where their lanes go
 * as 1 (pass) or 0 (cv, lv, hv: scratch). */
#define SL_WORD_TEST(p)                                                                            \
    "ldr    %[lv], [%[pl]], #4\n\t"                                                                \
    "ldr    %[hv], [%[ph]], #4\n\t"                                                                \
    "usub8  %[cv], %[lv], %[hv]\n\t" /* GE: lo >= hi */                                            \
    "ldr    %[cv], [%[pc]], #4\n\t"                                                                \
    "sel    %[lv], %[lv], %[hv]\n\t" /* side: the brighter one */                                  \
    "uqadd8 %[hv], %[lv], %[rm]\n\t" /* side + ridge_min, at most 255 */                           \
    "uqsub8 %[hv], %[hv], %[cv]\n\t" /* how far c stays below that */                              \
    "uqsub8 %[cv], %[mg], %[cv]\n\t" /* ... below min_gray */                                      \
    "uqsub8 %[lv], %[lv], %[sm]\n\t" /* side above side_max */                                     \
    "uqsub8 " p ", %[ones], %[hv]\n\t"                                                             \
    "uqsub8 " p ", " p ", %[cv]\n\t"                                                               \
    "uqsub8 " p ", " p ", %[lv]\n\t" /* 1 where all three are 0 */

uint32_t symline_i_line_cand(const symline_i_prefilter *pf, const uint8_t *c, const uint8_t *lo,
                             const uint8_t *hi, uint32_t x, uint32_t n, uint16_t *out,
                             uint32_t *next)
{
    const uint32_t mg = pf->min_gray * 0x01010101u, rm = pf->ridge_min * 0x01010101u;
    const uint32_t sm = pf->side_max * 0x01010101u;
    uint32_t k = 0u;
    if (n < 4u) {
        return symline_i_line_cand_c(pf, c, lo, hi, x, n, out, next);
    }
    while (x + 16u <= n) {
        /* Steps of 16 entries up to the first with a candidate (most have none). */
        const uint8_t *pc = c + x, *pl = lo + x, *ph = hi + x;
        const uint8_t *const end = pc + (n - x) / 16u * 16u;
        const uint32_t ones = 0x01010101u;
        uint32_t acc, cv, lv, hv, j;
        /* Word j's lanes go to acc shifted left by j: bit 8 * lane + j is
         * entry 4 * j + lane of the step. */
        /* clang-format off */
        __asm__ volatile("1:\n\t"
                         SL_WORD_TEST("%[acc]")
                         SL_WORD_TEST("%[hv]")
                         "orr    %[acc], %[acc], %[hv], lsl #1\n\t"
                         SL_WORD_TEST("%[hv]")
                         "orr    %[acc], %[acc], %[hv], lsl #2\n\t"
                         SL_WORD_TEST("%[hv]")
                         "orrs   %[acc], %[acc], %[hv], lsl #3\n\t"
                         "bne    2f\n\t" /* a candidate in the step */
                         "cmp    %[pc], %[end]\n\t"
                         "bne    1b\n\t"
                         "2:"
                         : [pc] "+r"(pc), [pl] "+r"(pl), [ph] "+r"(ph), [acc] "=&r"(acc),
                           [cv] "=&r"(cv), [lv] "=&r"(lv), [hv] "=&r"(hv)
                         : [end] "r"(end), [mg] "r"(mg), [rm] "r"(rm), [sm] "r"(sm),
                           [ones] "r"(ones)
                         : "cc", "memory");
        /* clang-format on */
        x = (uint32_t)(pc - c);
        if (acc == 0u) {
            break;
        }
        for (j = 0u; j < 4u; j++) {
            if (!report((acc >> j) & 0x01010101u, x - 16u + 4u * j, out, &k, next)) {
                return k;
            }
        }
    }
    for (; x + 4u <= n; x += 4u) {
        if (!report(pass4(c, lo, hi, x, mg, rm, sm), x, out, &k, next)) {
            return k;
        }
    }
    if (x < n) {
        /* The last 4 entries, without those before x. */
        const uint32_t base = n - 4u;
        if (!report(pass4(c, lo, hi, base, mg, rm, sm) & (0xffffffffu << (8u * (x - base))), base,
                    out, &k, next)) {
            return k;
        }
    }
    *next = n;
    return k;
}

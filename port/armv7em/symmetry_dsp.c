/* SPDX-License-Identifier: Apache-2.0 */
/*
 * The symmetry operator's row bodies symline_i_energy_row() and
 * symline_i_energy_across() with the ARMv7E-M DSP instructions (Cortex-M4,
 * M7: ACLE's __ARM_FEATURE_SIMD32), selected at build time (CMake option
 * SYMLINE_SIMD, port/CMakeLists.txt) in place of the portable references
 * symline_i_energy_*_c() of lib/symmetry.c, with the same output (the
 * target tests, port/cortex-m/test_core.c, compare them).
 *
 * Why: the reference adds one pair offset at a time over the whole row,
 * loading and storing the row of 32-bit energies again for every pair, and
 * reads the gray values a byte at a time. Here four pixels are read in one
 * word per row; |a - b| of the four bytes is two byte-lane subtractions and
 * a select (USUB8, USUB8, SEL); the differences are spread into two 16-bit
 * halves each (UXTB16), multiplied by the weight in both halves at once (one
 * MUL: w * 255 < 2^15 keeps the halves apart) and the weighted squares added
 * to the four energies by 16 x 16 multiply-accumulates (SMLABB, SMLATT), all
 * pairs in registers before one store. The passes over a row, its ends and
 * tail: ../symmetry_rows.h.
 */
#include <arm_acle.h>
#include <string.h>

/* w * 255 must stay below 2^15 in a signed 16-bit half: weights up to 128. */
#define SL_PORT_RADIUS_MAX 128u
#include "../symmetry_rows.h"

static inline uint32_t load4(const uint8_t *p)
{
    uint32_t v;
    memcpy(&v, p, sizeof v); /* one LDR: ARMv7-M reads unaligned words */
    return v;
}

/* The weighted square of the byte differences |a - b| of four pixels, added
 * to e0..e3 (pixels 0..3) at weight w; W1: w is 1. */
#define SL_PAIR4(a, b, w, W1)                                                                      \
    do {                                                                                           \
        const uint8x4_t ab_ = __usub8((a), (b));                                                  \
        const uint8x4_t ba_ = __usub8((b), (a)); /* GE: b >= a */                                 \
        const uint32_t d_ = (uint32_t)__sel(ba_, ab_);                                            \
        const int16x2_t dl_ = (int16x2_t)__uxtb16(d_);               /* pixels 0, 2 */            \
        const int16x2_t dh_ = (int16x2_t)__uxtb16((d_ >> 8) | (d_ << 24));    /* pixels 1, 3 */            \
        const int16x2_t wl_ = (W1) ? dl_ : (int16x2_t)((uint32_t)dl_ * (w));                      \
        const int16x2_t wh_ = (W1) ? dh_ : (int16x2_t)((uint32_t)dh_ * (w));                      \
        e0 = __smlabb(dl_, wl_, e0);                                                               \
        e2 = __smlatt(dl_, wl_, e2);                                                               \
        e1 = __smlabb(dh_, wh_, e1);                                                               \
        e3 = __smlatt(dh_, wh_, e3);                                                               \
    } while (0)

/*
 * The detector's radius 3 in one pass (pairs at weights 3, 2, 1, no pair
 * leaving the image, so no border term): count & ~3 entries, returned. The
 * six row pointers, the energies' pointer, four energies and three
 * temporaries take all fourteen core registers, which GCC's allocator does
 * not manage for this loop from C (it spills the row pointers and reloads
 * them every step), hence the loop body in assembly: 42 instructions per
 * four pixels, per pair two loads, |a - b| (USUB8, USUB8, SEL), the halves
 * (UXTB16, UXTB16 ROR 8), the weight (one shift or add) and four
 * multiply-accumulates.
 */
SL_NOINLINE static uint32_t pass_r3(const sl_pass *ps, uint32_t count, uint32_t *E)
{
    const uint8_t *l0 = ps->lo[0], *h0 = ps->hi[0], *l1 = ps->lo[1], *h1 = ps->hi[1];
    const uint8_t *l2 = ps->lo[2], *h2 = ps->hi[2];
    const uint32_t n = count & ~3u;
    uint32_t *const end = E + n;
    uint32_t a, b, t, e0, e1, e2, e3;
    if (n == 0u) {
        return 0u;
    }
    __asm__ volatile(
        "1:\n\t"
        /* pair 1, weight 3: e = 3 d^2 */
        "ldr    %[a], [%[l0]], #4\n\t"
        "ldr    %[b], [%[h0]], #4\n\t"
        "usub8  %[t], %[a], %[b]\n\t"
        "usub8  %[a], %[b], %[a]\n\t"
        "sel    %[a], %[a], %[t]\n\t"
        "uxtb16 %[b], %[a]\n\t"
        "uxtb16 %[a], %[a], ror #8\n\t"
        "add    %[t], %[b], %[b], lsl #1\n\t"
        "smulbb %[e0], %[b], %[t]\n\t"
        "smultt %[e2], %[b], %[t]\n\t"
        "add    %[t], %[a], %[a], lsl #1\n\t"
        "smulbb %[e1], %[a], %[t]\n\t"
        "smultt %[e3], %[a], %[t]\n\t"
        /* pair 2, weight 2 */
        "ldr    %[a], [%[l1]], #4\n\t"
        "ldr    %[b], [%[h1]], #4\n\t"
        "usub8  %[t], %[a], %[b]\n\t"
        "usub8  %[a], %[b], %[a]\n\t"
        "sel    %[a], %[a], %[t]\n\t"
        "uxtb16 %[b], %[a]\n\t"
        "uxtb16 %[a], %[a], ror #8\n\t"
        "lsl    %[t], %[b], #1\n\t"
        "smlabb %[e0], %[b], %[t], %[e0]\n\t"
        "smlatt %[e2], %[b], %[t], %[e2]\n\t"
        "lsl    %[t], %[a], #1\n\t"
        "smlabb %[e1], %[a], %[t], %[e1]\n\t"
        "smlatt %[e3], %[a], %[t], %[e3]\n\t"
        /* pair 3, weight 1 */
        "ldr    %[a], [%[l2]], #4\n\t"
        "ldr    %[b], [%[h2]], #4\n\t"
        "usub8  %[t], %[a], %[b]\n\t"
        "usub8  %[a], %[b], %[a]\n\t"
        "sel    %[a], %[a], %[t]\n\t"
        "uxtb16 %[b], %[a]\n\t"
        "uxtb16 %[a], %[a], ror #8\n\t"
        "smlabb %[e0], %[b], %[b], %[e0]\n\t"
        "smlatt %[e2], %[b], %[b], %[e2]\n\t"
        "smlabb %[e1], %[a], %[a], %[e1]\n\t"
        "smlatt %[e3], %[a], %[a], %[e3]\n\t"
        "strd   %[e2], %[e3], [%[E], #8]\n\t"
        "strd   %[e0], %[e1], [%[E]], #16\n\t"
        "ldr    %[t], %[end]\n\t"
        "cmp    %[E], %[t]\n\t"
        "bne    1b"
        : [l0] "+r"(l0), [h0] "+r"(h0), [l1] "+r"(l1), [h1] "+r"(h1), [l2] "+r"(l2),
          [h2] "+r"(h2), [E] "+r"(E), [a] "=&r"(a), [b] "=&r"(b), [t] "=&r"(t), [e0] "=&r"(e0),
          [e1] "=&r"(e1), [e2] "=&r"(e2), [e3] "=&r"(e3)
        : [end] "m"(end)
        : "cc", "memory");
    return n;
}

static inline __attribute__((always_inline)) void
run_pass(const sl_pass *ps, uint32_t np, uint32_t count, uint32_t init, int add, uint32_t *E)
{
    const uint8_t *lo[SL_PASS_PAIRS], *hi[SL_PASS_PAIRS];
    uint32_t w[SL_PASS_PAIRS];
    uint32_t p;
    size_t x = 0u;
    for (p = 0; p < np; p++) {
        lo[p] = ps->lo[p];
        hi[p] = ps->hi[p];
        w[p] = ps->w[p];
    }
    if (np == 3u && !add && init == 0u && ps->w[0] == 3u && ps->w[1] == 2u && ps->w[2] == 1u) {
        pass_tail(ps, np, pass_r3(ps, count, E), count, init, add, E);
        return;
    }
    for (; x + 4u <= count; x += 4u) {
        int32_t e0, e1, e2, e3;
        if (add) {
            e0 = (int32_t)E[x];
            e1 = (int32_t)E[x + 1u];
            e2 = (int32_t)E[x + 2u];
            e3 = (int32_t)E[x + 3u];
        } else {
            e0 = e1 = e2 = e3 = (int32_t)init;
        }
        for (p = 0; p < np; p++) {
            const uint32_t a = load4(lo[p] + x), b = load4(hi[p] + x);
            SL_PAIR4(a, b, w[p], 0);
        }
        E[x] = (uint32_t)e0;
        E[x + 1u] = (uint32_t)e1;
        E[x + 2u] = (uint32_t)e2;
        E[x + 3u] = (uint32_t)e3;
    }
    pass_tail(ps, np, x, count, init, add, E);
}

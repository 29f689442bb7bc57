/* SPDX-License-Identifier: Apache-2.0 */
/*
 * The symmetry operator's row bodies symline_i_energy_row() and
 * symline_i_energy_across() with the ARMv7E-M DSP instructions (Cortex-M4,
 * M7: ACLE's __ARM_FEATURE_SIMD32), selected at build time (CMake option
 * SYMLINE_SIMD, port/CMakeLists.txt) in place of the portable references
 * symline_i_energy_*_c() of lib/symmetry.c, with the same output (the
 * target tests, port/cortex-m/test_port.c, compare them).
 *
 * Why: the reference reads the gray values a byte at a time and multiplies
 * per pixel. Here four pixels are read in one word per row; |a - b| of the
 * four bytes is two byte-lane subtractions and a select (USUB8, USUB8, SEL);
 * the differences are spread into two 16-bit halves each (UXTB16), multiplied
 * by the weight in both halves at once (one MUL: w * 255 < 2^15 keeps the
 * halves apart) and the weighted squares added to the four energies by
 * 16 x 16 multiply-accumulates (SMLABB, SMLATT). The detector's radius 3
 * sums its three pairs in registers and stores the energies once (pass_r3);
 * other radii add one pair at a time over the row. Small stack frames: the
 * detector calls these at the bottom of its deepest call chain.
 */
#include <arm_acle.h>
#include <string.h>

#include "symmetry.h"

/* 255^2: the squared difference counted for a pair that leaves the image. */
#define SL_DMAX2 65025u
/* w * 255 must stay below 2^15 in a signed 16-bit half. */
#define SL_W_MAX 128u

static inline uint32_t load4(const uint8_t *p)
{
    uint32_t v;
    memcpy(&v, p, sizeof v); /* one LDR: ARMv7-M reads unaligned words */
    return v;
}

/*
 * The radius-3 pass: E[x] = 3 d1^2 + 2 d2^2 + d3^2, dj = p[2j-2][x] -
 * p[2j-1][x], for x < count & ~3 (returned). The six row pointers, the
 * energies' pointer, four energies and three temporaries take all fourteen
 * core registers, which GCC's allocator does not manage for this loop from C
 * (it spills the row pointers and reloads them every step), hence the loop
 * in assembly: 42 instructions per four pixels, per pair two loads, |a - b|
 * (USUB8, USUB8, SEL), the halves (UXTB16, UXTB16 ROR 8), the weight (one
 * add or shift) and four multiply-accumulates.
 */
SL_NOINLINE static uint32_t pass_r3(const uint8_t *const p[6], uint32_t count, uint32_t *E)
{
    const uint8_t *l0 = p[0], *h0 = p[1], *l1 = p[2], *h1 = p[3], *l2 = p[4], *h2 = p[5];
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
        "usub8  %[a], %[b], %[a]\n\t" /* GE: b >= a */
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

/* E[x] += w * (a[x] - b[x])^2 for x < count: one pair over a row, four
 * pixels per step where the weight fits the 16-bit halves. */
SL_NOINLINE static void add_pair(const uint8_t *a, const uint8_t *b, uint32_t w, uint32_t count,
                                 uint32_t *E)
{
    uint32_t x = 0u;
    if (w <= SL_W_MAX) {
        for (; x + 4u <= count; x += 4u) {
            const uint32_t va = load4(a + x), vb = load4(b + x);
            const uint8x4_t ab = __usub8(va, vb);
            const uint8x4_t ba = __usub8(vb, va); /* GE: b >= a */
            const uint32_t d = (uint32_t)__sel(ba, ab);
            const int16x2_t dl = (int16x2_t)__uxtb16(d);                   /* pixels 0, 2 */
            const int16x2_t dh = (int16x2_t)__uxtb16((d >> 8) | (d << 24)); /* pixels 1, 3 */
            const int16x2_t wl = (int16x2_t)((uint32_t)dl * w);
            const int16x2_t wh = (int16x2_t)((uint32_t)dh * w);
            E[x] = (uint32_t)__smlabb(dl, wl, (int32_t)E[x]);
            E[x + 1u] = (uint32_t)__smlabb(dh, wh, (int32_t)E[x + 1u]);
            E[x + 2u] = (uint32_t)__smlatt(dl, wl, (int32_t)E[x + 2u]);
            E[x + 3u] = (uint32_t)__smlatt(dh, wh, (int32_t)E[x + 3u]);
        }
    }
    for (; x < count; x++) {
        const int32_t d = (int32_t)a[x] - (int32_t)b[x];
        E[x] += w * (uint32_t)(d * d);
    }
}

static void fill(uint32_t *E, uint32_t count, uint32_t value)
{
    uint32_t x;
    for (x = 0; x < count; x++) {
        E[x] = value;
    }
}

/* The energy at k < m entries from the nearer end of a row, q + k its
 * centre: the pairs beyond the end count 255^2 each. */
static uint32_t row_end(const uint8_t *q, uint32_t m, uint32_t k)
{
    const uint32_t t = m - k;
    uint32_t e = SL_DMAX2 * (t * (t + 1u) / 2u), j;
    for (j = 1u; j <= k; j++) {
        const int32_t d = (int32_t)q[k - j] - (int32_t)q[k + j];
        e += (m + 1u - j) * (uint32_t)(d * d);
    }
    return e;
}

/* Entries x0 .. count-1 of the radius-3 sum, p as for pass_r3(). */
static void tail_r3(const uint8_t *const p[6], uint32_t x0, uint32_t count, uint32_t *E)
{
    uint32_t x, j;
    for (x = x0; x < count; x++) {
        uint32_t e = 0u;
        for (j = 0; j < 3u; j++) {
            const int32_t d = (int32_t)p[2u * j][x] - (int32_t)p[2u * j + 1u][x];
            e += (3u - j) * (uint32_t)(d * d);
        }
        E[x] = e;
    }
}

void symline_i_energy_row(const uint8_t *q, uint32_t n, uint32_t m, uint32_t *E)
{
    uint32_t j;
    const uint8_t *c;
    if (n < 2u * m + 8u) {
        symline_i_energy_row_c(q, n, m, E);
        return;
    }
    /* The m entries at either end, where pairs leave the row. */
    for (j = 0; j < m; j++) {
        E[j] = row_end(q, m, j);
        E[n - 1u - j] = row_end(q + (n - 1u - 2u * j), m, j);
    }
    /* The interior m .. n-1-m, where every pair lies in the row. */
    c = q + m;
    if (m == 3u) {
        const uint8_t *const p[6] = {c - 1, c + 1, c - 2, c + 2, c - 3, c + 3};
        tail_r3(p, pass_r3(p, n - 6u, E + 3), n - 6u, E + 3);
        return;
    }
    fill(E + m, n - 2u * m, 0u);
    for (j = 1u; j <= m; j++) {
        add_pair(c - j, c + j, m + 1u - j, n - 2u * m, E + m);
    }
}

void symline_i_energy_across(const uint8_t *const *rows, uint32_t m, uint32_t width, uint32_t *E)
{
    uint32_t j, border = 0u;
    if (m == 3u && rows[0] != NULL && rows[1] != NULL && rows[2] != NULL && rows[4] != NULL &&
        rows[5] != NULL && rows[6] != NULL) {
        const uint8_t *const p[6] = {rows[2], rows[4], rows[1], rows[5], rows[0], rows[6]};
        tail_r3(p, pass_r3(p, width, E), width, E);
        return;
    }
    /* A pair with a partner outside the image adds the same 255^2 to every column. */
    for (j = 1u; j <= m; j++) {
        if (rows[m - j] == NULL || rows[m + j] == NULL) {
            border += (m + 1u - j) * SL_DMAX2;
        }
    }
    fill(E, width, border);
    for (j = 1u; j <= m; j++) {
        if (rows[m - j] != NULL && rows[m + j] != NULL) {
            add_pair(rows[m - j], rows[m + j], m + 1u - j, width, E);
        }
    }
}

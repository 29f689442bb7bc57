/* SPDX-License-Identifier: Apache-2.0 */
/*
 * The scale grid's rows (lib/grid.c) with SSE2 intrinsics (x86-64
 * baseline), selected at build time (CMake option SYMLINE_SIMD,
 * port/CMakeLists.txt) in place of the portable lane loops, with the same
 * output (tests/core/test_grid_simd.c compares them). Sixteen, eight, then
 * four grid pixels per step, then single blocks: the whole row, written
 * once or, for the ring down the columns, twice (each store twice, no
 * copy). Other levels (0, above 5) take the reference.
 *
 * Why: every coarse pass reads the whole frame, so the cost is in the loads
 * and the few operations per load. Blocks of 2: each 16-bit lane of a row
 * vector is lo + 256 hi of two neighbouring pixels; the two rows added as
 * they are (wrapping) and their hi bytes beside give lo + hi sums =
 * W - 255 H, exact in 16 bits (W + H * 0xFF01 mod 2^16). Blocks of 4: two
 * rows' 4-byte groups interleaved, psadbw sums a block's two rows at once.
 * Blocks of 8 columns and more: psadbw against zero sums 8 bytes at once.
 * (Fewer instructions than 16-bit lanes at level 2; the grid stage of
 * tools/bench/stages.sh counts them.) The column indices are size_t (no
 * zero extension per step) and the steps of levels 1 and 2 are 16 pixels
 * wide (one pack and store for two halves).
 */
#include <emmintrin.h>
#include <string.h>

#include "linepoints.h"

static inline __m128i load16(const uint8_t *p)
{
    return _mm_loadu_si128((const __m128i *)(const void *)p);
}

/* 0xFF01 in every lane, as a value the compiler does not see: GCC would
 * turn the multiplies by it into a shift and a subtraction (and a copy,
 * 2-operand SSE2), three instructions for one. Taken once per row. */
static inline __m128i ff01(void)
{
    __m128i v = _mm_set1_epi16((short)0xFF01);
#if defined(__GNUC__)
    __asm__("" : "+x"(v));
#endif
    return v;
}

/* *v done before the loads after this: GCC would load all of a step's
 * rows first and spill them (SSE2 has 16 registers). */
static inline void settle(__m128i *v)
{
#if defined(__GNUC__)
    __asm__ volatile("" : "+x"(*v) : : "memory");
#endif
}

/* The row's bytes x .. x+15, x+7 or x+3 (the low ones of v) to out, and to
 * twin where the caller wants the row twice (twin NULL: not; a constant
 * where these are inlined). */
static SL_ALWAYS_INLINE void put16(uint8_t *out, uint8_t *twin, size_t x, __m128i v)
{
    _mm_storeu_si128((__m128i *)(void *)(out + x), v);
    if (twin != NULL) {
        _mm_storeu_si128((__m128i *)(void *)(twin + x), v);
    }
}

static SL_ALWAYS_INLINE void put8(uint8_t *out, uint8_t *twin, size_t x, __m128i v)
{
    _mm_storel_epi64((__m128i *)(void *)(out + x), v);
    if (twin != NULL) {
        _mm_storel_epi64((__m128i *)(void *)(twin + x), v);
    }
}

static SL_ALWAYS_INLINE void put4(uint8_t *out, uint8_t *twin, size_t x, __m128i v)
{
    const uint32_t t = (uint32_t)_mm_cvtsi128_si32(v);
    memcpy(out + x, &t, 4u);
    if (twin != NULL) {
        memcpy(twin + x, &t, 4u);
    }
}

/* Level 1: the rounded 2 x 2 means of 8 columns of 2 rows u, v: the rows
 * added as they are (W, wrapping) and their hi bytes (H), lo + hi sums =
 * W - 255 H = W + H * 0xFF01 (<= 4 * 255), exact in 16 bits; two fewer
 * operations than adding the lo and hi bytes apart. */
static SL_ALWAYS_INLINE __m128i level1_of(__m128i u, __m128i v, __m128i k)
{
    const __m128i half = _mm_set1_epi16(2);
    const __m128i H = _mm_add_epi16(_mm_srli_epi16(u, 8), _mm_srli_epi16(v, 8));
    const __m128i S = _mm_add_epi16(_mm_add_epi16(u, v), _mm_mullo_epi16(H, k));
    return _mm_srli_epi16(_mm_add_epi16(S, half), 2);
}

static SL_ALWAYS_INLINE __m128i level1_sums(const uint8_t *b, size_t stride, __m128i k)
{
    return level1_of(load16(b), load16(b + stride), k);
}

static SL_ALWAYS_INLINE uint32_t level1(const uint8_t *src, size_t stride, uint32_t w, uint8_t *out,
                                        uint8_t *twin)
{
    const __m128i k = ff01();
    const uint8_t *b = src;
    const size_t w16 = w & ~15u;
    size_t x = 0u; /* size_t: no zero extension per step */
    __m128i a;
    for (; x < w16; x += 16u, b += 32) {
        a = level1_sums(b, stride, k);
        put16(out, twin, x, _mm_packus_epi16(a, level1_sums(b + 16, stride, k)));
    }
    if (x + 8u <= w) {
        a = level1_sums(b, stride, k);
        put8(out, twin, x, _mm_packus_epi16(a, a));
        x += 8u;
        b += 16;
    }
    if (x + 4u <= w) { /* 8 columns: the low halves */
        a = level1_of(_mm_loadl_epi64((const __m128i *)(const void *)b),
                      _mm_loadl_epi64((const __m128i *)(const void *)(b + stride)), k);
        put4(out, twin, x, _mm_packus_epi16(a, a));
        x += 4u;
    }
    return (uint32_t)x;
}

/* Level 2: two rows' 4-column groups side by side (unpacklo/hi_epi32), so
 * that psadbw sums one block's two rows per 64-bit lane: the sums of blocks
 * 0, 1 (P[0]) and 2, 3 (P[1]) of 16 columns of rows 0..3. */
static SL_ALWAYS_INLINE void level2_sums(const uint8_t *b, size_t stride, __m128i *P)
{
    const __m128i z = _mm_setzero_si128();
    const __m128i r0 = load16(b), r1 = load16(b + stride);
    const __m128i r2 = load16(b + 2u * stride), r3 = load16(b + 3u * stride);
    P[0] = _mm_add_epi32(_mm_sad_epu8(_mm_unpacklo_epi32(r0, r1), z),
                         _mm_sad_epu8(_mm_unpacklo_epi32(r2, r3), z));
    P[1] = _mm_add_epi32(_mm_sad_epu8(_mm_unpackhi_epi32(r0, r1), z),
                         _mm_sad_epu8(_mm_unpackhi_epi32(r2, r3), z));
}

/* Level 2: the rounded means of 8 blocks from 32 columns (16-bit lanes). */
static SL_ALWAYS_INLINE __m128i level2_means(const uint8_t *b, size_t stride)
{
    const __m128i half = _mm_set1_epi16(8);
    __m128i P[4], S;
    level2_sums(b, stride, P);
    level2_sums(b + 16, stride, P + 2);
    /* Block sums <= 16 * 255 in the even 32-bit lanes: packed twice. */
    S = _mm_packs_epi32(_mm_packs_epi32(P[0], P[1]), _mm_packs_epi32(P[2], P[3]));
    return _mm_srli_epi16(_mm_add_epi16(S, half), 4);
}

static SL_ALWAYS_INLINE uint32_t level2(const uint8_t *src, size_t stride, uint32_t w, uint8_t *out,
                                        uint8_t *twin)
{
    const __m128i half = _mm_set1_epi16(8);
    const uint8_t *b = src;
    const size_t w16 = w & ~15u;
    __m128i P[2], S;
    size_t x = 0u;
    for (; x < w16; x += 16u, b += 64) {
        S = level2_means(b, stride);
        put16(out, twin, x, _mm_packus_epi16(S, level2_means(b + 32, stride)));
    }
    if (x + 8u <= w) {
        S = level2_means(b, stride);
        put8(out, twin, x, _mm_packus_epi16(S, S));
        x += 8u;
        b += 32;
    }
    if (x + 4u <= w) { /* one vector */
        level2_sums(b, stride, P);
        S = _mm_packs_epi32(P[0], P[1]);
        S = _mm_srli_epi16(_mm_add_epi16(_mm_packs_epi32(S, S), half), 4);
        put4(out, twin, x, _mm_packus_epi16(S, S));
        x += 4u;
    }
    return (uint32_t)x;
}

/* Sums of 8 rows of nv <= 4 vectors (16 nv columns from b), two blocks of
 * 8 columns per vector in its 64-bit lanes. The rows unrolled: a loop's
 * counting would add a third to the work. */
static SL_ALWAYS_INLINE void sums8(const uint8_t *b, size_t stride, uint32_t nv, __m128i *P)
{
    const __m128i z = _mm_setzero_si128();
    uint32_t i;
    for (i = 0; i < nv; i++) {
        const uint8_t *c = b + 16u * i;
        const __m128i s01 =
            _mm_add_epi32(_mm_sad_epu8(load16(c), z), _mm_sad_epu8(load16(c + stride), z));
        const __m128i s23 = _mm_add_epi32(_mm_sad_epu8(load16(c + 2u * stride), z),
                                          _mm_sad_epu8(load16(c + 3u * stride), z));
        const __m128i s45 = _mm_add_epi32(_mm_sad_epu8(load16(c + 4u * stride), z),
                                          _mm_sad_epu8(load16(c + 5u * stride), z));
        const __m128i s67 = _mm_add_epi32(_mm_sad_epu8(load16(c + 6u * stride), z),
                                          _mm_sad_epu8(load16(c + 7u * stride), z));
        P[i] = _mm_add_epi32(_mm_add_epi32(s01, s23), _mm_add_epi32(s45, s67));
    }
}

/* Level 3: one block of 8 columns per 64-bit lane of psadbw. */
static SL_ALWAYS_INLINE uint32_t level3(const uint8_t *src, size_t stride, uint32_t w, uint8_t *out,
                                        uint8_t *twin)
{
    const __m128i half = _mm_set1_epi16(32);
    const uint8_t *b = src;
    const size_t w8 = w & ~7u;
    __m128i P[4], S;
    size_t x = 0u;
    for (; x < w8; x += 8u, b += 64) {
        sums8(b, stride, 2u, P);
        S = _mm_packs_epi32(P[0], P[1]);
        settle(&S);
        sums8(b + 32, stride, 2u, P + 2);
        /* Block sums <= 64 * 255 in the even 32-bit lanes: packed twice. */
        S = _mm_packs_epi32(S, _mm_packs_epi32(P[2], P[3]));
        S = _mm_srli_epi16(_mm_add_epi16(S, half), 6);
        put8(out, twin, x, _mm_packus_epi16(S, S));
    }
    if (x + 4u <= w) { /* two vectors */
        sums8(b, stride, 2u, P);
        S = _mm_packs_epi32(P[0], P[1]);
        S = _mm_srli_epi16(_mm_add_epi16(_mm_packs_epi32(S, S), half), 6);
        put4(out, twin, x, _mm_packus_epi16(S, S));
        x += 4u;
    }
    return (uint32_t)x;
}

/* Level 4: blocks of one vector, four at a time, each summed as two blocks
 * of 8 rows (sums8()) one after the other: psadbw's two half-block sums
 * added, the block sums (<= 256 * 255) rounded in 32-bit lanes. */
static SL_ALWAYS_INLINE uint32_t level4(const uint8_t *src, size_t stride, uint32_t w, uint8_t *out,
                                        uint8_t *twin)
{
    const __m128i half = _mm_set1_epi32(128);
    const uint8_t *b = src;
    const size_t w4 = w & ~3u;
    size_t x = 0u;
    for (; x < w4; x += 4u, b += 64) {
        __m128i P[8], P0, P1, P2, P3, S;
        uint32_t i;
        for (i = 0; i < 4u; i++) { /* each block's rows 0..7 and 8..15 */
            sums8(b + 16u * i, stride, 1u, &P[2u * i]);
            sums8(b + 16u * i + 8u * stride, stride, 1u, &P[2u * i + 1u]);
            P[2u * i] = _mm_add_epi32(P[2u * i], P[2u * i + 1u]);
            settle(&P[2u * i]);
        }
        P0 = P[0], P1 = P[2], P2 = P[4], P3 = P[6];
        /* Blocks 0, 1 and 2, 3 in the low 32 bits of the 64-bit lanes. */
        P0 = _mm_add_epi32(_mm_unpacklo_epi64(P0, P1), _mm_unpackhi_epi64(P0, P1));
        P2 = _mm_add_epi32(_mm_unpacklo_epi64(P2, P3), _mm_unpackhi_epi64(P2, P3));
        S = _mm_unpacklo_epi64(_mm_shuffle_epi32(P0, 0x08), _mm_shuffle_epi32(P2, 0x08));
        S = _mm_srli_epi32(_mm_add_epi32(S, half), 8);
        S = _mm_packs_epi32(S, S);
        put4(out, twin, x, _mm_packus_epi16(S, S));
    }
    return (uint32_t)x;
}

/* Pixels x0 .. w-1 one at a time (levels 2..5; the tails of the steps
 * above, and all of level 5): each block row by psadbw, 4, 8 or 16 bytes at
 * a time. */
static uint32_t singles(const uint8_t *src, size_t stride, uint32_t level, uint32_t x0, uint32_t w,
                        uint8_t *out)
{
    const uint32_t s = 1u << level, shift = 2u * level;
    const __m128i z = _mm_setzero_si128();
    uint32_t x, d, i;
    for (x = x0; x < w; x++) {
        const uint8_t *b = src + (size_t)x * s;
        __m128i P = z;
        for (d = 0; d < s; d++, b += stride) {
            if (level == 2u) {
                uint32_t t;
                memcpy(&t, b, 4u);
                P = _mm_add_epi32(P, _mm_sad_epu8(_mm_cvtsi32_si128((int)t), z));
            } else if (level == 3u) {
                P = _mm_add_epi32(
                    P, _mm_sad_epu8(_mm_loadl_epi64((const __m128i *)(const void *)b), z));
            } else {
                for (i = 0; i < s; i += 16u) {
                    P = _mm_add_epi32(P, _mm_sad_epu8(load16(b + i), z));
                }
            }
        }
        P = _mm_add_epi32(P, _mm_srli_si128(P, 8));
        out[x] = (uint8_t)(((uint32_t)_mm_cvtsi128_si32(P) + ((1u << shift) >> 1)) >> shift);
    }
    return w;
}

/* The row by the steps above (two is whether the row goes to twin too, a
 * constant in each inlined copy), then the last blocks one at a time. */
static SL_ALWAYS_INLINE void row(const uint8_t *src, size_t stride, uint32_t level, uint32_t w,
                                 uint8_t *out, uint8_t *twin)
{
    uint32_t x, i;
    if (level == 1u) {
        x = level1(src, stride, w, out, twin);
        for (i = x; i < w; i++) { /* at most three */
            const uint8_t *b = src + (size_t)i * 2u;
            out[i] = (uint8_t)(((uint32_t)b[0] + b[1] + b[stride] + b[stride + 1u] + 2u) >> 2);
        }
    } else {
        x = level == 2u   ? level2(src, stride, w, out, twin)
            : level == 3u ? level3(src, stride, w, out, twin)
            : level == 4u ? level4(src, stride, w, out, twin)
                          : 0u;
        (void)singles(src, stride, level, x, w, out);
    }
    symline_i_grid_twin(out, x, w, twin);
}

void symline_i_grid_row(const symline_image *img, const symline_i_pass *p, uint32_t y,
                        uint16_t *acc, uint8_t *out, uint8_t *twin)
{
    const uint32_t level = p->level, w = p->w;
    const size_t stride = img->stride;
    const uint8_t *src = img->data + ((size_t)y << level) * stride;
    if (level - 1u >= 5u) { /* levels 1..5 here */
        symline_i_grid_row_c(img, p, y, acc, out, twin);
    } else if (twin == NULL) {
        row(src, stride, level, w, out, NULL);
    } else {
        row(src, stride, level, w, out, twin);
    }
}

/* Eight neighbour pair sums of the 16 sums in u, v: pmaddwd by ones (the
 * sums below level 4 are < 2^15, their pairs too: signed lanes hold them),
 * packed. */
static SL_ALWAYS_INLINE __m128i pairs_of(__m128i u, __m128i v)
{
    const __m128i one = _mm_set1_epi16(1);
    return _mm_packs_epi32(_mm_madd_epi16(u, one), _mm_madd_epi16(v, one));
}

static SL_ALWAYS_INLINE __m128i pairs8(const uint16_t *s)
{
    return pairs_of(_mm_loadu_si128((const __m128i *)(const void *)s),
                    _mm_loadu_si128((const __m128i *)(const void *)(s + 8)));
}

/* The grid pyramid (grid.h): level 1's row, sixteen pixels a step, from the
 * sums of level1_of() before their rounding, and where asked their pairs
 * into level 2's sums (fold: 0 none, 1 the first row, 2 the second, with
 * level 2's row; a constant in each inlined copy). */
static SL_ALWAYS_INLINE size_t sums1(const uint8_t *src, size_t stride, size_t w16, uint8_t *out,
                                     uint16_t *acc, uint8_t *out2, uint32_t fold)
{
    const __m128i k = ff01(), half = _mm_set1_epi16(2), half2 = _mm_set1_epi16(8);
    size_t x = 0u;
    for (; x < w16; x += 16u) {
        const uint8_t *b = src + 2u * x;
        const __m128i u0 = load16(b), v0 = load16(b + stride);
        const __m128i u1 = load16(b + 16), v1 = load16(b + 16 + stride);
        const __m128i H0 = _mm_add_epi16(_mm_srli_epi16(u0, 8), _mm_srli_epi16(v0, 8));
        const __m128i H1 = _mm_add_epi16(_mm_srli_epi16(u1, 8), _mm_srli_epi16(v1, 8));
        const __m128i S0 = _mm_add_epi16(_mm_add_epi16(u0, v0), _mm_mullo_epi16(H0, k));
        const __m128i S1 = _mm_add_epi16(_mm_add_epi16(u1, v1), _mm_mullo_epi16(H1, k));
        _mm_storeu_si128((__m128i *)(void *)(out + x),
                         _mm_packus_epi16(_mm_srli_epi16(_mm_add_epi16(S0, half), 2),
                                          _mm_srli_epi16(_mm_add_epi16(S1, half), 2)));
        if (fold == 1u) {
            _mm_storeu_si128((__m128i *)(void *)(acc + x / 2u), pairs_of(S0, S1));
        } else if (fold == 2u) {
            __m128i a = _mm_loadu_si128((const __m128i *)(const void *)(acc + x / 2u));
            a = _mm_add_epi16(a, pairs_of(S0, S1));
            _mm_storeu_si128((__m128i *)(void *)(acc + x / 2u), a);
            a = _mm_srli_epi16(_mm_add_epi16(a, half2), 4);
            _mm_storel_epi64((__m128i *)(void *)(out2 + x / 2u), _mm_packus_epi16(a, a));
        }
    }
    return x;
}

void symline_i_grid_sums1(const uint8_t *src, size_t stride, uint32_t w, uint8_t *out,
                          uint16_t *acc, uint8_t *out2)
{
    const size_t w16 = w & ~15u;
    const size_t x = acc == NULL    ? sums1(src, stride, w16, out, NULL, NULL, 0u)
                     : out2 == NULL ? sums1(src, stride, w16, out, acc, NULL, 1u)
                                    : sums1(src, stride, w16, out, acc, out2, 2u);
    symline_i_grid_sums1_from(x, src, stride, w, out, acc, out2);
}

/* A grid row's second half folded in: acc + the pairs (<= 256 * 255, 16-bit
 * lanes wrap-free), stored, and the rounded means. */
static SL_ALWAYS_INLINE __m128i fold8(const uint16_t *s, uint16_t *acc, __m128i half, __m128i sh)
{
    const __m128i a = _mm_add_epi16(_mm_loadu_si128((const __m128i *)(const void *)acc), pairs8(s));
    _mm_storeu_si128((__m128i *)(void *)acc, a);
    return _mm_srl_epi16(_mm_add_epi16(a, half), sh);
}

void symline_i_grid_fold(const uint16_t *s, uint32_t w, uint32_t level, uint16_t *acc, uint8_t *out)
{
    const size_t w8 = w & ~7u;
    size_t x = 0u;
    if (out == NULL) {
        for (; x < w8; x += 8u) {
            _mm_storeu_si128((__m128i *)(void *)(acc + x), pairs8(s + 2u * x));
        }
    } else {
        const __m128i half = _mm_set1_epi16((short)(1u << (2u * level - 1u)));
        const __m128i sh = _mm_cvtsi32_si128((int)(2u * level));
        for (; x + 16u <= w; x += 16u) {
            const __m128i a = fold8(s + 2u * x, acc + x, half, sh);
            _mm_storeu_si128((__m128i *)(void *)(out + x),
                             _mm_packus_epi16(a, fold8(s + 2u * x + 16u, acc + x + 8u, half, sh)));
        }
        if (x < w8) {
            const __m128i a = fold8(s + 2u * x, acc + x, half, sh);
            _mm_storel_epi64((__m128i *)(void *)(out + x), _mm_packus_epi16(a, a));
            x += 8u;
        }
    }
    symline_i_grid_fold_c(s + 2u * x, w - (uint32_t)x, level, acc + x,
                          out != NULL ? out + x : NULL);
}

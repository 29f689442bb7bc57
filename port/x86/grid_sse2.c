/* SPDX-License-Identifier: Apache-2.0 */
/*
 * The scale grid's rows (lib/grid.c) with SSE2 intrinsics (x86-64
 * baseline), selected at build time (CMake option SYMLINE_SIMD,
 * port/CMakeLists.txt) in place of the portable lane loops, with the same
 * output (tests/core/test_grid_simd.c compares them). Sixteen, eight, then
 * four grid pixels per step, then single blocks: the whole row. Other
 * levels (0, above 5) take the reference.
 *
 * Why: every coarse pass reads the whole frame, so the cost is in the loads.
 * Each 16-bit lane of a row vector is lo + 256 hi of two neighbouring
 * pixels. Blocks of 2: the lo and hi bytes of the two rows added. Blocks of
 * 4: the rows are added as they are (wrapping) with their hi bytes beside,
 * lo + hi sums = W - 255 H, exact in 16 bits (W + H * 0xFF01 mod 2^16): two
 * adds and a shift per 16 pixels and row. Blocks of 8 columns and more:
 * psadbw against zero sums 8 bytes at once. Eight pixels per step at level
 * 2: with sixteen GCC hoists the loads of all rows and spills them
 * (callgrind: 0.49 instead of 0.42 instructions per frame pixel).
 */
#include <emmintrin.h>
#include <string.h>

#include "linepoints.h"

static inline __m128i load16(const uint8_t *p)
{
    return _mm_loadu_si128((const __m128i *)(const void *)p);
}

/* The low 4 bytes of v to out. */
static inline void store4(uint8_t *out, __m128i v)
{
    const uint32_t t = (uint32_t)_mm_cvtsi128_si32(v);
    memcpy(out, &t, 4u);
}

/* Pair sums of nv <= 2 vectors (16 nv columns from b) over s <= 16 rows:
 * W + H * 0xFF01. */
static SL_ALWAYS_INLINE void pair_sums(const uint8_t *b, size_t stride, uint32_t s, uint32_t nv,
                                       __m128i *S)
{
    const __m128i k = _mm_set1_epi16((short)0xFF01);
    __m128i W[2], H[2];
    uint32_t d, i;
    for (i = 0; i < nv; i++) {
        W[i] = load16(b + 16u * i);
        H[i] = _mm_srli_epi16(W[i], 8);
    }
    for (d = 1u; d < s; d++) {
        b += stride;
        for (i = 0; i < nv; i++) {
            const __m128i v = load16(b + 16u * i);
            W[i] = _mm_add_epi16(W[i], v);
            H[i] = _mm_add_epi16(H[i], _mm_srli_epi16(v, 8));
        }
    }
    for (i = 0; i < nv; i++) {
        S[i] = _mm_add_epi16(W[i], _mm_mullo_epi16(H[i], k));
    }
}

/* Level 1: the 2 x 2 sums (<= 4 * 255) of 16 columns of 2 rows, from the
 * low and high bytes of their 16-bit lanes. */
static SL_ALWAYS_INLINE __m128i level1_of(__m128i u, __m128i v)
{
    const __m128i lo = _mm_set1_epi16(0xFF), half = _mm_set1_epi16(2);
    const __m128i t = _mm_add_epi16(_mm_and_si128(u, lo), _mm_and_si128(v, lo));
    const __m128i h = _mm_add_epi16(_mm_srli_epi16(u, 8), _mm_srli_epi16(v, 8));
    return _mm_srli_epi16(_mm_add_epi16(_mm_add_epi16(t, h), half), 2);
}

static SL_ALWAYS_INLINE __m128i level1_sums(const uint8_t *b, size_t stride)
{
    return level1_of(load16(b), load16(b + stride));
}

static uint32_t level1(const uint8_t *src, size_t stride, uint32_t w, uint8_t *out)
{
    uint32_t x = 0u;
    __m128i a;
    for (; x + 16u <= w; x += 16u) {
        a = level1_sums(src + (size_t)x * 2u, stride);
        _mm_storeu_si128((__m128i *)(void *)(out + x),
                         _mm_packus_epi16(a, level1_sums(src + (size_t)x * 2u + 16u, stride)));
    }
    if (x + 8u <= w) {
        a = level1_sums(src + (size_t)x * 2u, stride);
        _mm_storel_epi64((__m128i *)(void *)(out + x), _mm_packus_epi16(a, a));
        x += 8u;
    }
    if (x + 4u <= w) { /* 8 columns: the low halves */
        const uint8_t *b = src + (size_t)x * 2u;
        a = level1_of(_mm_loadl_epi64((const __m128i *)(const void *)b),
                      _mm_loadl_epi64((const __m128i *)(const void *)(b + stride)));
        store4(out + x, _mm_packus_epi16(a, a));
        x += 4u;
    }
    return x;
}

/* Level 2: pair sums (<= 8 * 255, signed 16 bits for madd) of 4 rows, then
 * neighbouring pairs added by madd into 32-bit lanes and packed back. */
static SL_ALWAYS_INLINE __m128i level2_sums(const __m128i *S)
{
    const __m128i ones = _mm_set1_epi16(1), half = _mm_set1_epi16(8);
    const __m128i B = _mm_packs_epi32(_mm_madd_epi16(S[0], ones), _mm_madd_epi16(S[1], ones));
    return _mm_srli_epi16(_mm_add_epi16(B, half), 4);
}

static uint32_t level2(const uint8_t *src, size_t stride, uint32_t w, uint8_t *out)
{
    __m128i S[2], a;
    uint32_t x = 0u;
    for (; x + 8u <= w; x += 8u) {
        pair_sums(src + (size_t)x * 4u, stride, 4u, 2u, S);
        a = level2_sums(S);
        _mm_storel_epi64((__m128i *)(void *)(out + x), _mm_packus_epi16(a, a));
    }
    if (x + 4u <= w) { /* one vector: its 4 sums twice */
        pair_sums(src + (size_t)x * 4u, stride, 4u, 1u, S);
        S[1] = S[0];
        a = level2_sums(S);
        store4(out + x, _mm_packus_epi16(a, a));
        x += 4u;
    }
    return x;
}

/* Level 3: one block of 8 columns per 64-bit lane of psadbw. */
static uint32_t level3(const uint8_t *src, size_t stride, uint32_t w, uint8_t *out)
{
    const __m128i z = _mm_setzero_si128(), half = _mm_set1_epi16(32);
    uint32_t x, d;
    for (x = 0; x + 8u <= w; x += 8u) {
        const uint8_t *b = src + (size_t)x * 8u;
        __m128i P0 = z, P1 = z, P2 = z, P3 = z, S;
        for (d = 0; d < 8u; d++, b += stride) {
            P0 = _mm_add_epi32(P0, _mm_sad_epu8(load16(b), z));
            P1 = _mm_add_epi32(P1, _mm_sad_epu8(load16(b + 16), z));
            P2 = _mm_add_epi32(P2, _mm_sad_epu8(load16(b + 32), z));
            P3 = _mm_add_epi32(P3, _mm_sad_epu8(load16(b + 48), z));
        }
        /* Block sums <= 64 * 255 in the even 32-bit lanes: packed twice. */
        S = _mm_packs_epi32(_mm_packs_epi32(P0, P1), _mm_packs_epi32(P2, P3));
        S = _mm_srli_epi16(_mm_add_epi16(S, half), 6);
        _mm_storel_epi64((__m128i *)(void *)(out + x), _mm_packus_epi16(S, S));
    }
    if (x + 4u <= w) { /* two vectors */
        const uint8_t *b = src + (size_t)x * 8u;
        __m128i P0 = z, P1 = z, S;
        for (d = 0; d < 8u; d++, b += stride) {
            P0 = _mm_add_epi32(P0, _mm_sad_epu8(load16(b), z));
            P1 = _mm_add_epi32(P1, _mm_sad_epu8(load16(b + 16), z));
        }
        S = _mm_packs_epi32(P0, P1);
        S = _mm_srli_epi16(_mm_add_epi16(_mm_packs_epi32(S, S), half), 6);
        store4(out + x, _mm_packus_epi16(S, S));
        x += 4u;
    }
    return x;
}

/* Level 4: blocks of one vector, four at a time: psadbw's two half-block
 * sums added, the block sums (<= 256 * 255) rounded in 32-bit lanes. */
static uint32_t level4(const uint8_t *src, size_t stride, uint32_t w, uint8_t *out)
{
    const __m128i z = _mm_setzero_si128(), half = _mm_set1_epi32(128);
    uint32_t x, d;
    for (x = 0; x + 4u <= w; x += 4u) {
        const uint8_t *b = src + (size_t)x * 16u;
        __m128i P0 = z, P1 = z, P2 = z, P3 = z, S;
        for (d = 0; d < 16u; d++, b += stride) {
            P0 = _mm_add_epi32(P0, _mm_sad_epu8(load16(b), z));
            P1 = _mm_add_epi32(P1, _mm_sad_epu8(load16(b + 16), z));
            P2 = _mm_add_epi32(P2, _mm_sad_epu8(load16(b + 32), z));
            P3 = _mm_add_epi32(P3, _mm_sad_epu8(load16(b + 48), z));
        }
        /* Blocks 0, 1 and 2, 3 in the low 32 bits of the 64-bit lanes. */
        P0 = _mm_add_epi32(_mm_unpacklo_epi64(P0, P1), _mm_unpackhi_epi64(P0, P1));
        P2 = _mm_add_epi32(_mm_unpacklo_epi64(P2, P3), _mm_unpackhi_epi64(P2, P3));
        S = _mm_unpacklo_epi64(_mm_shuffle_epi32(P0, 0x08), _mm_shuffle_epi32(P2, 0x08));
        S = _mm_srli_epi32(_mm_add_epi32(S, half), 8);
        S = _mm_packs_epi32(S, S);
        store4(out + x, _mm_packus_epi16(S, S));
    }
    return x;
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

void symline_i_grid_row(const symline_image *img, const symline_i_pass *p, uint32_t y,
                        uint16_t *acc, uint8_t *out)
{
    const uint32_t level = p->level, w = p->w;
    const size_t stride = img->stride;
    const uint8_t *src = img->data + ((size_t)y << level) * stride;
    uint32_t x;
    if (level == 1u) {
        for (x = level1(src, stride, w, out); x < w; x++) { /* at most three */
            const uint8_t *b = src + (size_t)x * 2u;
            out[x] = (uint8_t)(((uint32_t)b[0] + b[1] + b[stride] + b[stride + 1u] + 2u) >> 2);
        }
    } else if (level == 2u) {
        (void)singles(src, stride, 2u, level2(src, stride, w, out), w, out);
    } else if (level == 3u) {
        (void)singles(src, stride, 3u, level3(src, stride, w, out), w, out);
    } else if (level == 4u) {
        (void)singles(src, stride, 4u, level4(src, stride, w, out), w, out);
    } else if (level == 5u) {
        (void)singles(src, stride, 5u, 0u, w, out);
    } else {
        symline_i_grid_row_c(img, p, y, acc, out);
    }
}

/* SPDX-License-Identifier: Apache-2.0 */
/*
 * Helpers of the fuzz targets: the fuzzer's bytes read as choices, and
 * caller buffers followed by guard bytes that must stay untouched.
 */
#ifndef SYMLINE_FUZZ_UTIL_H
#define SYMLINE_FUZZ_UTIL_H

#include <stddef.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

/* The fuzzer's input consumed front to back; zeros once it runs out. */
typedef struct fz_in {
    const uint8_t *p;
    size_t n;
} fz_in;

static inline uint32_t fz_u8(fz_in *in)
{
    uint32_t v = 0;
    if (in->n > 0) {
        v = in->p[0];
        in->p++;
        in->n--;
    }
    return v;
}

static inline uint32_t fz_u16(fz_in *in)
{
    const uint32_t lo = fz_u8(in);
    return lo | (fz_u8(in) << 8);
}

static inline uint32_t fz_u32(fz_in *in)
{
    const uint32_t lo = fz_u16(in);
    return lo | (fz_u16(in) << 16);
}

/* A value in [lo, hi] (hi - lo < 2^32 - 1). */
static inline uint32_t fz_range(fz_in *in, uint32_t lo, uint32_t hi)
{
    return lo + fz_u32(in) % (hi - lo + 1u);
}

/* A size from its exact need: exact, one short, zero, or more (mode from the input). */
static inline size_t fz_size(fz_in *in, size_t need)
{
    switch (fz_u8(in) % 4u) {
    case 0: return need;
    case 1: return need > 0 ? need - 1u : 0u;
    case 2: return 0u;
    default: return need + (fz_u8(in) % 64u);
    }
}

#define FZ_GUARD 64u
#define FZ_FILL 0xA5u

/* A caller buffer of n bytes filled with `fill`, then FZ_GUARD guard bytes. */
static inline uint8_t *fz_buf(size_t n, uint8_t fill)
{
    uint8_t *b = (uint8_t *)malloc(n + FZ_GUARD);
    if (b == NULL) {
        abort();
    }
    memset(b, fill, n);
    memset(b + n, FZ_FILL, FZ_GUARD);
    return b;
}

/* Aborts (a finding) when a guard byte after b[0..n-1] was written. */
static inline void fz_check_guard(const uint8_t *b, size_t n, const char *what)
{
    size_t i;
    for (i = 0; i < FZ_GUARD; i++) {
        if (b[n + i] != FZ_FILL) {
            fprintf(stderr, "guard byte %zu after %s (%zu bytes) written\n", i, what, n);
            abort();
        }
    }
}

/* Aborts when any of b[0..n-1] differs from fill (an output written on an error). */
static inline void fz_check_untouched(const uint8_t *b, size_t n, uint8_t fill, const char *what)
{
    size_t i;
    for (i = 0; i < n; i++) {
        if (b[i] != fill) {
            fprintf(stderr, "%s byte %zu written by a call that failed\n", what, i);
            abort();
        }
    }
}

/* Image pixels: exactly the bytes symline may read ((h-1)*stride + w), no
 * guard, so that AddressSanitizer reports any read past them. Filled from
 * the rest of the input, repeated. */
static inline uint8_t *fz_image(fz_in *in, uint32_t w, uint32_t h, uint32_t stride, size_t *len)
{
    const size_t n = (h > 0u && w > 0u) ? (size_t)(h - 1u) * stride + w : 1u;
    uint8_t *b = (uint8_t *)malloc(n);
    size_t i;
    if (b == NULL) {
        abort();
    }
    for (i = 0; i < n; i++) {
        b[i] = in->n > 0 ? in->p[i % in->n] : (uint8_t)(i * 37u);
    }
    *len = n;
    return b;
}

#endif

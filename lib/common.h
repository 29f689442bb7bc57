/* SPDX-License-Identifier: Apache-2.0 */
/*
 * The few macros and inline helpers every module of the core shares:
 * workspace carving and argument checks. Not part of the public API; each
 * stage's own interface is in its private header (symmetry.h, extrema.h,
 * linefilter.h, linepoints.h, tracer.h, subpixel.h, segments.h, merge.h,
 * curvejoin.h, pass.h, fixed.h).
 */
#ifndef SYMLINE_COMMON_H
#define SYMLINE_COMMON_H

#include <stdbool.h>
#include <stddef.h>
#include <stdint.h>

#include "symline/types.h"

/* Keeps a helper with a large frame out of its caller's frame, so the deepest
 * stack path stays short (measured by tools/firmware/check.sh). */
#if defined(__GNUC__)
#define SL_NOINLINE __attribute__((noinline))
#else
#define SL_NOINLINE
#endif

/* 1 where the build optimises for speed, 0 where it optimises for size
 * (-Os, the firmware builds): code that only saves time (shortcuts, unrolled
 * or lane loops) is written as `if (SL_FOR_SPEED ...)` and folds away
 * there. The results are the same either way. */
#if defined(__OPTIMIZE_SIZE__)
#define SL_FOR_SPEED 0
#else
#define SL_FOR_SPEED 1
#endif

/* Speed-only code that makes a frame on the detection's deepest paths
 * larger (a ring of crosses, a test inline, the grid row cache of
 * linepoints.h): where the build optimises for speed on a 64-bit core only.
 * The 32-bit targets are the firmware's, whose detection must stay within
 * 512 B of stack (tools/firmware/check.sh). */
#define SL_FOR_SPEED_DEEP (SL_FOR_SPEED && UINTPTR_MAX > 0xFFFFFFFFu)

/* Copies a small routine into each caller even at -Os, where a constant
 * argument then folds away (extrema.c). */
#if defined(__GNUC__)
#define SL_ALWAYS_INLINE inline __attribute__((always_inline))
#else
#define SL_ALWAYS_INLINE inline
#endif

/* True when v lies outside -lim..lim (lim >= 0, v + lim without overflow):
 * one comparison instead of two. */
#define SL_OUTSIDE(v, lim) ((uint32_t)((v) + (lim)) > 2u * (uint32_t)(lim))

/* Alignment every workspace carve-out is rounded to. */
#define SL_ALIGN 8u

static inline size_t symline_i_align_up(size_t n)
{
    return (n + (SL_ALIGN - 1u)) & ~(size_t)(SL_ALIGN - 1u);
}

/* Carves `bytes` from a workspace cursor, aligned; NULL if it does not fit. */
static inline void *symline_i_carve_here(uint8_t **cur, uint8_t *end, size_t bytes)
{
    uintptr_t p = ((uintptr_t)*cur + (SL_ALIGN - 1u)) & ~(uintptr_t)(SL_ALIGN - 1u);
    if (p > (uintptr_t)end || bytes > (size_t)((uintptr_t)end - p)) {
        return NULL;
    }
    *cur = (uint8_t *)(p + bytes);
    return (void *)p;
}

/* The same, out of line (status.c). */
void *symline_i_carve_shared(uint8_t **cur, uint8_t *end, size_t bytes);

/* What the stages call: where the build optimises for size (-Os, the
 * firmware builds), the one shared copy instead of one per object; else
 * inline (and GCC's -fanalyzer then sees where the pointer points). */
static inline void *symline_i_carve(uint8_t **cur, uint8_t *end, size_t bytes)
{
#if defined(__OPTIMIZE_SIZE__)
    return symline_i_carve_shared(cur, end, bytes);
#else
    return symline_i_carve_here(cur, end, bytes);
#endif
}

/*
 * Checks that a caller buffer of `len` elements holds `rows` rows of `cols`
 * elements `stride` apart. Computed in 64 bits so no size can wrap.
 */
static inline symline_status symline_i_check_plane(uint32_t cols, uint32_t rows, uint32_t stride,
                                                   size_t len)
{
    uint64_t need;
    if (stride < cols) {
        return SYMLINE_ERR_STRIDE;
    }
    need = (uint64_t)(rows - 1u) * stride + cols;
    if ((uint64_t)len < need) {
        return SYMLINE_ERR_BUFFER;
    }
    return SYMLINE_OK;
}

static inline symline_status symline_i_check_radius(uint32_t m)
{
    return (m >= 1u && m <= SYMLINE_MAX_RADIUS) ? SYMLINE_OK : SYMLINE_ERR_RADIUS;
}

static inline symline_status symline_i_check_axis(symline_axis axis)
{
    return (axis == SYMLINE_AXIS_HORIZONTAL || axis == SYMLINE_AXIS_VERTICAL) ? SYMLINE_OK
                                                                              : SYMLINE_ERR_AXIS;
}

/* True when a workspace query's arguments are valid (sizes 1..65535, known axis, radius 1..255). */
static inline bool symline_i_query_ok(uint32_t width, uint32_t height, symline_axis axis,
                                      uint32_t m)
{
    return width != 0u && width <= SYMLINE_MAX_DIM && height != 0u && height <= SYMLINE_MAX_DIM &&
           symline_i_check_axis(axis) == SYMLINE_OK && symline_i_check_radius(m) == SYMLINE_OK;
}

#endif /* SYMLINE_COMMON_H */

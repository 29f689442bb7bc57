/*
 * Helpers shared by the core modules. Not part of the public API.
 */
#ifndef SYMLINE_INTERNAL_H
#define SYMLINE_INTERNAL_H

#include <stddef.h>
#include <stdint.h>

#include "symline/types.h"

/* 255^2: the squared difference counted for a pair that leaves the image. */
#define SL_DMAX2 65025u

/* Alignment every workspace carve-out is rounded to. */
#define SL_ALIGN 8u

static inline size_t sl_align_up(size_t n)
{
    return (n + (SL_ALIGN - 1u)) & ~(size_t)(SL_ALIGN - 1u);
}

/* Carves `bytes` from a workspace cursor, aligned; NULL if it does not fit. */
static inline void *sl_carve(uint8_t **cur, uint8_t *end, size_t bytes)
{
    uintptr_t p = ((uintptr_t)*cur + (SL_ALIGN - 1u)) & ~(uintptr_t)(SL_ALIGN - 1u);
    if (p > (uintptr_t)end || bytes > (size_t)((uintptr_t)end - p)) {
        return NULL;
    }
    *cur = (uint8_t *)(p + bytes);
    return (void *)p;
}

/*
 * Checks that a caller buffer of `len` elements holds `rows` rows of `cols`
 * elements `stride` apart. Computed in 64 bits so no size can wrap.
 */
static inline symline_status sl_check_plane(uint32_t cols, uint32_t rows, uint32_t stride,
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

static inline symline_status sl_check_radius(uint32_t m)
{
    return (m >= 1u && m <= SYMLINE_MAX_RADIUS) ? SYMLINE_OK : SYMLINE_ERR_RADIUS;
}

static inline symline_status sl_check_axis(symline_axis axis)
{
    return (axis == SYMLINE_AXIS_HORIZONTAL || axis == SYMLINE_AXIS_VERTICAL) ? SYMLINE_OK
                                                                               : SYMLINE_ERR_AXIS;
}

#endif /* SYMLINE_INTERNAL_H */

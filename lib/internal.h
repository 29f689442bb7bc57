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

/* 1 when a workspace query's arguments are valid (sizes 1..65535, known axis, radius 1..255). */
static inline int sl_query_ok(uint32_t width, uint32_t height, symline_axis axis, uint32_t m)
{
    return width != 0u && width <= SYMLINE_MAX_DIM && height != 0u && height <= SYMLINE_MAX_DIM &&
           sl_check_axis(axis) == SYMLINE_OK && sl_check_radius(m) == SYMLINE_OK;
}

/*
 * Start of every whole-frame operator call: checks the image, axis, radius
 * and an output plane of height rows of width elements (out, out_stride,
 * out_len), then carves one row of uint32_t energies from the workspace.
 * On success *cur points past the carved row, ready for further carving.
 */
symline_status sl_frame_begin(const symline_image *img, symline_axis axis, uint32_t m,
                              const void *out, uint32_t out_stride, size_t out_len, void *ws,
                              size_t ws_size, uint8_t **cur, uint8_t **end, uint32_t **E);

#endif /* SYMLINE_INTERNAL_H */

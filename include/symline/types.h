/* SPDX-License-Identifier: Apache-2.0 */
/*
 * symline — common types: status codes, the image view, the symmetry axis.
 *
 * Everything in symline works on caller-owned memory. Nothing here allocates,
 * uses floating point or performs I/O.
 */
#ifndef SYMLINE_TYPES_H
#define SYMLINE_TYPES_H

#include <stddef.h>
#include <stdint.h>

#include "symline/version.h"

#ifdef __cplusplus
extern "C" {
#endif

/* Largest accepted image width and height, in pixels. */
#define SYMLINE_MAX_DIM 65535u
/* Symmetry radius m: 1 <= m <= SYMLINE_MAX_RADIUS. */
#define SYMLINE_MAX_RADIUS 255u

/* Values of an extrema map (in memory and in PGM files written by the tools). */
#define SYMLINE_MAP_NONE 0u /* neither extremum */
#define SYMLINE_MAP_A 128u  /* symmetry minimum: an asymmetry ("A") point */
#define SYMLINE_MAP_S 255u  /* symmetry maximum: a symmetry axis ("S") point */

/*
 * Status codes. Every entry point returns one; SYMLINE_OK is 0 and every
 * error is negative, so `if (st < 0)` catches all failures. No output buffer
 * is written when an argument check fails.
 */
typedef enum symline_status {
    SYMLINE_OK = 0,
    SYMLINE_ERR_NULL = -1,   /* a required pointer is NULL */
    SYMLINE_ERR_SIZE = -2,   /* width or height is 0 or above SYMLINE_MAX_DIM */
    SYMLINE_ERR_STRIDE = -3, /* a stride is smaller than the row length */
    SYMLINE_ERR_RADIUS = -4, /* radius is 0 or above SYMLINE_MAX_RADIUS */
    SYMLINE_ERR_AXIS = -5,   /* axis is not one of enum symline_axis */
    SYMLINE_ERR_BUFFER = -6, /* an output buffer or workspace is too small */
    SYMLINE_ERR_RANGE = -7,  /* a row/strip index or count is out of range */
    SYMLINE_ERR_CONFIG = -8  /* a configuration field is out of its range */
} symline_status;

/* A short, static English name for a status code (never NULL). */
const char *symline_status_str(symline_status st);

/*
 * Which mirror the operator measures.
 *
 * SYMLINE_AXIS_VERTICAL:   symmetry about a vertical axis, computed along each
 *                          row (q = a row, n = width); finds near-vertical lines.
 * SYMLINE_AXIS_HORIZONTAL: symmetry about a horizontal axis, computed along each
 *                          column (q = a column, n = height); finds
 *                          near-horizontal lines (the usual field-line case).
 */
typedef enum symline_axis {
    SYMLINE_AXIS_HORIZONTAL = 0,
    SYMLINE_AXIS_VERTICAL = 1
} symline_axis;

/*
 * A read-only view of an 8-bit gray image, row-major.
 * Pixel (x, y) is data[y * stride + x]. 1 <= width, height <= SYMLINE_MAX_DIM,
 * stride >= width (bytes). The caller owns the pixels; symline only reads
 * data[0 .. (height-1)*stride + width-1].
 */
typedef struct symline_image {
    uint32_t width;
    uint32_t height;
    uint32_t stride;
    const uint8_t *data;
} symline_image;

/* Checks an image view: SYMLINE_OK, or ERR_NULL / ERR_SIZE / ERR_STRIDE. */
symline_status symline_image_check(const symline_image *img);

#ifdef __cplusplus
}
#endif

#endif /* SYMLINE_TYPES_H */

/* SPDX-License-Identifier: Apache-2.0 */
/*
 * The scale grid (grid.c): rows of the frame box-downsampled by 2^level,
 * each grid pixel the rounded mean of its 2^level x 2^level block,
 * (sum + 2^(2 level - 1)) >> 2 level.
 */
#ifndef SYMLINE_LIB_GRID_H
#define SYMLINE_LIB_GRID_H

#include "common.h"
#include "symline/types.h"

/* Row y of the level-`level` grid (0..SYMLINE_DETECT_MAX_LEVELS; the
 * detector reads the frame's rows themselves at level 0) into
 * out[0 .. (img->width >> level) - 1], and copied to twin unless it is
 * NULL; the frame holds rows y 2^level .. (y + 1) 2^level - 1. acc: scratch
 * of img->width uint16_t (the portable lane loops; size builds leave it
 * alone). The portable C. */
void symline_i_grid_level_row(const symline_image *img, uint32_t level, uint32_t y, uint16_t *acc,
                              uint8_t *out, uint8_t *twin);

/* Grid pixels x0 .. w-1 of the row whose blocks start at src (frame rows
 * `stride` bytes apart), one block at a time: the size builds' form, and
 * where a port's lanes leave the last few blocks of a row. Inline, so that
 * the size builds keep the code they had. */
static inline void symline_i_grid_blocks(const uint8_t *src, size_t stride, uint32_t level,
                                         uint32_t x0, uint32_t w, uint8_t *out)
{
    const uint32_t s = 1u << level, shift = 2u * level;
    uint8_t *o = out + x0;
    uint32_t d, i;
    for (src += (size_t)x0 * s; o < out + w; o++, src += s) {
        const uint8_t *b = src;
        uint32_t sum = 0u; /* the half block added after: Cortex-M0+ code keeps
                            * the sum in a register then (GCC 12 -Os) */
        for (d = 0; d < s; d++, b += stride) {
            for (i = 0; i < s; i++) {
                sum += b[i];
            }
        }
        *o = (uint8_t)((sum + ((1u << shift) >> 1)) >> shift); /* rounded */
    }
}

/* out[x0 .. w-1] to twin[x0 .. w-1] where twin is not NULL: the row's
 * second copy where it was not stored twice. */
static inline void symline_i_grid_twin(const uint8_t *out, uint32_t x0, uint32_t w, uint8_t *twin)
{
    if (twin != NULL) {
        uint32_t x;
        for (x = x0; x < w; x++) {
            twin[x] = out[x];
        }
    }
}

struct symline_i_pass; /* linepoints.h */

/* The row y of pass p's grid, as above at p->level, into out and, where
 * twin is not NULL, into twin as well (the ring of rows down the columns
 * holds each row twice, linepoints.c; writing both saves copying). A port's
 * version (port/, SYMLINE_PORT_GRID, CMake option SYMLINE_SIMD) replaces it;
 * symline_i_grid_row_c() is then the portable reference, with the same
 * output (tests/core/test_grid_simd.c; the Cortex-M target tests for
 * port/armv7em/). */
void symline_i_grid_row(const symline_image *img, const struct symline_i_pass *p, uint32_t y,
                        uint16_t *acc, uint8_t *out, uint8_t *twin);
#ifdef SYMLINE_PORT_GRID
void symline_i_grid_row_c(const symline_image *img, const struct symline_i_pass *p, uint32_t y,
                          uint16_t *acc, uint8_t *out, uint8_t *twin);
#endif

#endif /* SYMLINE_LIB_GRID_H */

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
 * out[0 .. (img->width >> level) - 1]; the frame holds rows
 * y 2^level .. (y + 1) 2^level - 1. acc: scratch of img->width uint16_t
 * (the portable lane loops; size builds leave it alone). The portable C. */
void symline_i_grid_level_row(const symline_image *img, uint32_t level, uint32_t y, uint16_t *acc,
                              uint8_t *out);

struct symline_i_pass; /* linepoints.h */

/* The row y of pass p's grid, as above at p->level (linepoints.c). A port's
 * version (port/, SYMLINE_PORT_GRID, CMake option SYMLINE_SIMD) replaces it;
 * symline_i_grid_row_c() is then the portable reference, with the same
 * output (tests/core/test_grid_simd.c; the Cortex-M target tests for
 * port/armv7em/). */
void symline_i_grid_row(const symline_image *img, const struct symline_i_pass *p, uint32_t y,
                        uint16_t *acc, uint8_t *out);
#ifdef SYMLINE_PORT_GRID
void symline_i_grid_row_c(const symline_image *img, const struct symline_i_pass *p, uint32_t y,
                          uint16_t *acc, uint8_t *out);
#endif

#endif /* SYMLINE_LIB_GRID_H */

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
 * detector reads the frame's rows themselves at level 0) into out[0 .. (img->width >> level) - 1];
 * the frame holds rows y 2^level .. (y + 1) 2^level - 1. acc: scratch of
 * img->width uint16_t (the portable lane loops; the SIMD versions and size
 * builds leave it alone). */
void symline_i_grid_row(const symline_image *img, uint32_t level, uint32_t y, uint16_t *acc,
                        uint8_t *out);

#ifdef SYMLINE_PORT_GRID
/*
 * Where the build has a SIMD version (port/, CMake option SYMLINE_SIMD):
 * symline_i_grid_lanes() writes out[0 .. x-1] of the grid row whose blocks
 * start at src (frame rows src, src + stride, ..., 2^level of them) and
 * returns x <= w, the pixels done in whole vectors (0 at level 0); symline_i_grid_row()
 * does the rest block by block. symline_i_grid_row_c() is the portable
 * reference with the same output (tests/core/test_grid_simd.c).
 */
uint32_t symline_i_grid_lanes(const uint8_t *src, size_t stride, uint32_t level, uint32_t w,
                              uint8_t *out);
void symline_i_grid_row_c(const symline_image *img, uint32_t level, uint32_t y, uint16_t *acc,
                          uint8_t *out);
#endif

#endif /* SYMLINE_LIB_GRID_H */

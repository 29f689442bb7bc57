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

/*
 * The grid pyramid (64-bit speed builds: the grid row cache, linepoints.h):
 * level 1's rows from the frame with their block sums, and each coarser
 * level's rows from the sums of the level below, two of its rows per row,
 * instead of from the frame's blocks again. The same rounded means as
 * above: the sums are exact (<= 256 * 255 at level 4, 16 bits).
 */

/* Level 1's row from the frame rows at src and src + stride: out[x] the
 * rounded means of the 2 x 2 blocks, x < w; where acc is not NULL, their sums
 * folded into level 2's, acc[0 .. w/2 - 1], as symline_i_grid_fold() does
 * (out2 NULL: the first of a level-2 row's two rows; else the second, and
 * the level-2 row to out2). The portable reference; symline_i_grid_sums1()
 * the build's choice. */
static inline void symline_i_grid_sums1_c(const uint8_t *src, size_t stride, uint32_t w,
                                          uint8_t *out, uint16_t *acc, uint8_t *out2)
{
    uint32_t x, prev = 0u;
    for (x = 0; x < w; x++) {
        const uint8_t *b = src + 2u * (size_t)x;
        const uint32_t s = (uint32_t)b[0] + b[1] + b[stride] + b[stride + 1u];
        out[x] = (uint8_t)((s + 2u) >> 2);
        if (acc != NULL && (x & 1u) != 0u) {
            uint16_t *const a = &acc[x >> 1];
            *a = (uint16_t)(out2 == NULL ? prev + s : *a + prev + s);
            if (out2 != NULL) {
                out2[x >> 1] = (uint8_t)((*a + 8u) >> 4);
            }
        }
        prev = s;
    }
}

/* symline_i_grid_sums1_c() from pixel x on, x even (so that level 2's pairs
 * are the row's): the pixels after a port's steps. */
static inline void symline_i_grid_sums1_from(size_t x, const uint8_t *src, size_t stride,
                                             uint32_t w, uint8_t *out, uint16_t *acc, uint8_t *out2)
{
    symline_i_grid_sums1_c(src + 2u * x, stride, w - (uint32_t)x, out + x,
                           acc != NULL ? acc + x / 2u : NULL, out2 != NULL ? out2 + x / 2u : NULL);
}

/* One row of the level below's sums s[0 .. 2w-1] folded into level
 * `level`'s (3..4; any of 2..4) sums acc[0 .. w-1]: the first of the two rows of a grid
 * row (out NULL) sets acc[x] = s[2x] + s[2x+1], the second adds the same
 * and writes the grid row's rounded means to out. The portable reference;
 * symline_i_grid_fold() the build's choice. */
static inline void symline_i_grid_fold_c(const uint16_t *s, uint32_t w, uint32_t level,
                                         uint16_t *acc, uint8_t *out)
{
    const uint32_t shift = 2u * level;
    uint32_t x;
    for (x = 0; x < w; x++) {
        const uint32_t pair = (uint32_t)s[2u * (size_t)x] + s[2u * (size_t)x + 1u];
        if (out == NULL) {
            acc[x] = (uint16_t)pair;
        } else {
            acc[x] = (uint16_t)(acc[x] + pair);
            out[x] = (uint8_t)(((uint32_t)acc[x] + ((1u << shift) >> 1)) >> shift);
        }
    }
}

/* A port's versions (SYMLINE_PORT_GRID_SUMS), with the same output
 * (tests/core/test_grid_simd.c). */
#ifdef SYMLINE_PORT_GRID_SUMS
void symline_i_grid_sums1(const uint8_t *src, size_t stride, uint32_t w, uint8_t *out,
                          uint16_t *acc, uint8_t *out2);
void symline_i_grid_fold(const uint16_t *s, uint32_t w, uint32_t level, uint16_t *acc,
                         uint8_t *out);
#else
#define symline_i_grid_sums1 symline_i_grid_sums1_c
#define symline_i_grid_fold symline_i_grid_fold_c
#endif

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

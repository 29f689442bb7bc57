/* SPDX-License-Identifier: Apache-2.0 */
/*
 * The field boundary stage (fieldboundary.c): private interface for the
 * detector, which runs the stage before its passes and drops line points
 * above the boundary. Not part of the public API.
 */
#ifndef SYMLINE_FIELDBOUNDARY_H
#define SYMLINE_FIELDBOUNDARY_H

#include "symline/detect.h"
#include "symline/field.h"
#include "common.h"

/* symline_field_find() without the argument checks (valid image, config,
 * workspace of symline_field_workspace_size() bytes). */
void symline_i_field_run(const symline_image *img, const symline_field_config *fc, uint8_t *ws,
                         size_t ws_size, symline_field_boundary *out);

#if SL_FOR_SPEED_DEEP
/* symline_i_field_run() with the column scan cell by cell, as builds without
 * its lanes (fieldboundary.c) run it: for the test that compares the two. */
void symline_i_field_run_scalar(const symline_image *img, const symline_field_config *fc,
                                uint8_t *ws, size_t ws_size, symline_field_boundary *out);
#endif

/* 1 when every setting of fc is in its range. */
bool symline_i_field_config_ok(const symline_field_config *fc);

/* The first kept row of every column of a pass grid at `level` (w columns,
 * frame `width` px wide): grid row y is kept when its centre lies at most
 * `margin` px above boundary b (b->count >= 1, as symline_i_field_run()
 * leaves it). rows: w entries. */
void symline_i_field_rows(const symline_field_boundary *b, uint32_t level, uint32_t w,
                          uint32_t width, uint32_t margin, uint16_t *rows);

/* Drops the points of a pass's raster list (row_start[0..h], points in grid
 * coordinates) that lie above rows[x] (w entries); compacts the list in
 * place (x, y only: the offsets are set later, symline_i_subpixel()) and
 * returns the number kept. */
uint32_t symline_i_field_drop(const uint16_t *rows, uint32_t w, symline_point *pts,
                              uint32_t *row_start, uint32_t h);

/* Relative texture, Q8, clamped to 255: d / sum over the same n pixels. */
static inline uint8_t symline_i_field_tex(uint32_t d, uint32_t sum, uint32_t n)
{
    const uint32_t t = (d << 8) / (sum + n);
    return (uint8_t)(t < 255u ? t : 255u);
}

/* Mean gray value and relative texture of the cell of n (>= 1) pixels
 * from p. Every other pair of neighbours measures the grain as well as all
 * of them at half the cost: each pair's difference as its sum less twice
 * its smaller value, doubled. The stage's cost is here. */
static inline void symline_i_field_cell(const uint8_t *p, uint32_t n, uint32_t *mean, uint32_t *tex)
{
    uint32_t i, sum = 0u, lows = 0u, pairs;
    if (n == 0u) {
        *mean = 0u; /* not reached: a cell starts inside its row */
        *tex = 0u;
        return;
    }
    for (i = 0; i + 1u < n; i += 2u) {
        const uint32_t a = p[i], b = p[i + 1u];
        sum += a + b;
        lows += a < b ? a : b;
    }
    pairs = sum;
    if (i < n) {
        sum += p[i]; /* an odd cell's last pixel */
    }
    *mean = sum / n;
    *tex = symline_i_field_tex(2u * (pairs - 2u * lows), sum, n);
}

/* A cell of 8 px from the sum of its gray values and the sum of its pairs'
 * smaller values (symline_i_field_cell() with n = 8): mean and texture to
 * out[0] and out[1]; the last step of the ports' lanes. */
static inline void symline_i_field_put8(uint8_t *out, uint32_t sum, uint32_t lows)
{
    out[0] = (uint8_t)(sum >> 3);
    out[1] = symline_i_field_tex(2u * (sum - 2u * lows), sum, 8u);
}

/* The cells of 8 px c = 0 .. n-1 that start at row + c * sx (sx >= 8), each
 * inside the row: mean and texture (symline_i_field_cell()) to out[2 c] and
 * out[2 c + 1]. symline_i_field_cells8_c() is the portable reference;
 * symline_i_field_cells8() a version from port/ (SYMLINE_PORT_FIELD_CELLS,
 * CMake option SYMLINE_SIMD) with the same output, two cells a step in
 * lanes, which the grid's rows call where the build optimises for speed. */
static inline void symline_i_field_cells8_c(const uint8_t *row, size_t sx, uint32_t n, uint8_t *out)
{
    uint32_t c;
    for (c = 0; c < n; c++, row += sx, out += 2) {
        uint32_t m, t;
        symline_i_field_cell(row, 8u, &m, &t);
        out[0] = (uint8_t)m;
        out[1] = (uint8_t)t;
    }
}
#ifdef SYMLINE_PORT_FIELD_CELLS
void symline_i_field_cells8(const uint8_t *row, size_t sx, uint32_t n, uint8_t *out);
#endif

#endif /* SYMLINE_FIELDBOUNDARY_H */

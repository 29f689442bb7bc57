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

#endif /* SYMLINE_FIELDBOUNDARY_H */

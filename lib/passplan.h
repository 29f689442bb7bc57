/* SPDX-License-Identifier: Apache-2.0 */
/*
 * The passes a detector configuration runs (detect.c): its range check, the
 * number of scales for a frame, and the axes. Shared by symline_detect() and
 * symline_line_points() (framepoints.c), so both run the same passes.
 */
#ifndef SYMLINE_LIB_PASSPLAN_H
#define SYMLINE_LIB_PASSPLAN_H

#include "common.h"
#include "symline/detect.h"

/* The configuration's ranges, then ws_size against the workspace query:
 * SYMLINE_OK, SYMLINE_ERR_CONFIG or SYMLINE_ERR_BUFFER (img already checked). */
symline_status symline_i_config_ws_check(const symline_image *img, const symline_config *cfg,
                                         size_t ws_size);

/* Number of scales for a width x height frame (1 = full resolution only). */
uint32_t symline_i_level_count(const symline_config *c, uint32_t width, uint32_t height);

/* Axes per scale (1 or 2) and the i-th of them (horizontal first). */
uint32_t symline_i_axis_count(const symline_config *c);
symline_axis symline_i_axis_of(const symline_config *c, uint32_t i);

#endif /* SYMLINE_LIB_PASSPLAN_H */

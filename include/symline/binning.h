/* SPDX-License-Identifier: Apache-2.0 */
/*
 * symline — 2x2 binning: large frames detected at half size.
 *
 * The detector's pixel-unit settings (radius 3 at full resolution, four
 * scales, min_length, the field boundary's cells) suit frames of about
 * 320..800 px across. A frame of a million pixels or more shows the same
 * field lines twice as wide and the carpet's grain twice as coarse: it is
 * detected better, and in about half the time (the binning included;
 * docs/RESULTS.md, "Large frames"), at half size. These three steps do that
 * around symline_detect():
 *
 *     if (symline_bin2_advised(w, h)) {
 *         symline_image half;
 *         st = symline_bin2(&img, buf, symline_bin2_size(w, h), &half);
 *         st = symline_detect(&half, &cfg, ws, ws_size, &res);  // ws for half's size
 *         st = symline_result_unbin2(&res, w, h);   // back to frame coordinates
 *     }
 *
 * An optional module: firmware that never calls it does not link it. No
 * allocation, no floating point, no I/O; the caller owns every buffer.
 */
#ifndef SYMLINE_BINNING_H
#define SYMLINE_BINNING_H

#include <stdbool.h>
#include <stddef.h>
#include <stdint.h>

#include "symline/detect.h"

#ifdef __cplusplus
extern "C" {
#endif

/* Frames of at least this many pixels are advised to be binned (1024 x 768). */
#define SYMLINE_BIN2_ADVISED_PIXELS 786432u

/*
 * Whether a width x height frame is better detected at half size: true from
 * SYMLINE_BIN2_ADVISED_PIXELS pixels on (1024x768, 1280x720, 1280x960 and
 * larger; not 960x720 or 800x600; false for a side above SYMLINE_MAX_DIM).
 * Measured on the annotated real frames at 1.5 and 2 times their size
 * (docs/RESULTS.md, "Large frames").
 */
bool symline_bin2_advised(uint32_t width, uint32_t height);

/*
 * Bytes of the binned image of a width x height frame: (width / 2) *
 * (height / 2), rows packed; 0 when either side is below 2 or above
 * SYMLINE_MAX_DIM.
 */
size_t symline_bin2_size(uint32_t width, uint32_t height);

/*
 * Bins `in` 2x2 into buf (size bytes, at least symline_bin2_size()): each
 * output pixel is the mean of a 2x2 block, rounded half up; an odd last
 * column or row is left out. *out becomes a view of buf (width / 2 x
 * height / 2, stride = width / 2). Output pixel (x, y) covers input pixels
 * 2x..2x+1, 2y..2y+1: its centre lies at (2x + 1/2, 2y + 1/2) in the frame.
 * ERR_NULL, ERR_SIZE (a side below 2), ERR_STRIDE (as symline_image_check()),
 * ERR_BUFFER (size too small); nothing is written then.
 */
symline_status symline_bin2(const symline_image *in, uint8_t *buf, size_t size, symline_image *out);

/*
 * Moves a result that symline_detect() (or symline_detect_muff()) gave for
 * the binned image of a width x height frame into that frame's coordinates,
 * in place: segment ends c -> 2 c + 1/2 px (Q8: 2 c + 128), max_dev doubled,
 * level + 1 (a binned frame's scale l is the frame's scale l + 1); every
 * stored point the same way, exactly (its pixel and its 1/128 px offset);
 * the field boundary's vertices x -> 2 x, y -> 2 y (its first field row),
 * the right edge vertex at width - 1 (a second one where the binned frame
 * was one pixel wide), "no field" (y = height / 2) at height, its cell
 * doubled. Run it once, before symline_intersections().
 * ERR_NULL (r, or an array its counts need, NULL), ERR_SIZE (width or
 * height below 2 or above SYMLINE_MAX_DIM), ERR_RANGE (counts beyond the
 * capacities, a segment or point outside the binned frame, a level of 255);
 * nothing is changed then.
 */
symline_status symline_result_unbin2(symline_result *r, uint32_t width, uint32_t height);

#ifdef __cplusplus
}
#endif

#endif /* SYMLINE_BINNING_H */

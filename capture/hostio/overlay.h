/* SPDX-License-Identifier: Apache-2.0 */
/*
 * Host I/O: detections drawn over a frame (symline overlay, symline-capture
 * --snapshot-every). Host-only code: allocates and writes files.
 */
#ifndef SYMLINE_HOSTIO_OVERLAY_H
#define SYMLINE_HOSTIO_OVERLAY_H

#include <stddef.h>
#include <stdint.h>

#include "symline/detect.h"
#include "symline/intersections.h"

/*
 * Writes the gray frame (width x height, `stride` bytes per row), dimmed to
 * 3/4, in colour with the segments of r drawn over it: lines solid red along
 * their chord, curves dotted cyan along their points; a 3-pixel pen on
 * frames 480 px wide or more; the field boundary (r->field, when computed)
 * solid yellow. PNG when path ends in ".png", else PPM.
 * Returns 0, or -1 with a message naming the file in err.
 */
int overlay_write(const char *path, const uint8_t *gray, uint32_t width, uint32_t height,
                  uint32_t stride, const symline_result *r, char *err, size_t errlen);

/* The same, and the intersections of ix (when not NULL) over the segments: each
 * ray a short spoke from the point, and a small square around it, green for L,
 * orange for T, magenta for X. */
int overlay_write_ix(const char *path, const uint8_t *gray, uint32_t width, uint32_t height,
                     uint32_t stride, const symline_result *r,
                     const symline_intersection_result *ix, char *err, size_t errlen);

#endif

/* SPDX-License-Identifier: Apache-2.0 */
/*
 * The JSON form of a detection (docs/format.md), shared by the CLI, the capture
 * loop, the tests and the Cortex-M golden check. Needs only stdio.
 */
#ifndef SYMLINE_HOSTIO_SEGJSON_H
#define SYMLINE_HOSTIO_SEGJSON_H

#include <stdint.h>
#include <stdio.h>

#include "symline/detect.h"
#include "symline/intersections.h"

/*
 * Writes one JSON object for the result of a width x height frame to f:
 *   {"width": W, "height": H, "truncated": false,
 *    "segments": [{"x0":..,"y0":..,"x1":..,"y1":..,"points":N,"max_dev":..,
 *                  "kind":"line"|"curve","axis":"horizontal"|"vertical","level":L
 *                  [, "polyline": [[x,y],...]]}, ...]
 *    [, "field_boundary": [[x,y],...]]}
 * Coordinates and max_dev in pixels (Q8 values printed with 2 decimals).
 * Curves carry a polyline through every 4th of their points and the last one.
 * "field_boundary" (integer pixels, x increasing from 0 to W-1; rows at and
 * below the polyline are field) is written when r->field.count > 0.
 * Ends with a newline. Returns 0, or -1 when writing failed.
 */
int segjson_write(FILE *f, uint32_t width, uint32_t height, const symline_result *r);

/* The same object with "file": NAME as its first key (when file is not NULL). */
int segjson_write_named(FILE *f, const char *file, uint32_t width, uint32_t height,
                        const symline_result *r);

/*
 * The same with the key "intersections" after the others when ix is not NULL:
 *   "intersections": [{"x":..,"y":..,"type":"L"|"T"|"X","rays":[deg,..],
 *                      "segments":[i,..]}, ...]
 * positions in pixels, rays in degrees (two decimals), ascending.
 */
int segjson_write_ix(FILE *f, uint32_t width, uint32_t height, const symline_result *r,
                     const symline_intersection_result *ix);
int segjson_write_named_ix(FILE *f, const char *file, uint32_t width, uint32_t height,
                           const symline_result *r, const symline_intersection_result *ix);

/* s as a JSON string: quoted, with quotes, backslashes and control characters escaped. */
void segjson_put_string(FILE *f, const char *s);

#endif

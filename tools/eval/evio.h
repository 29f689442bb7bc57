/* SPDX-License-Identifier: Apache-2.0 */
/*
 * Reading the evaluation inputs: ground-truth text files and detection JSON (as
 * printed by `symline lines`), both in the formats of docs/format.md, and PGM
 * headers. Host-only code.
 */
#ifndef SYMLINE_EVAL_EVIO_H
#define SYMLINE_EVAL_EVIO_H

#include "paths.h"

/*
 * NAME.lines.txt / NAME.dontcare.txt: one segment "x0 y0 x1 y1" per text line.
 * Appends one two-point piece per segment with the given tag. A missing file
 * counts as empty when `optional`. Returns 0, or -1 with a message on stderr.
 */
int ev_read_segments(const char *path, int tag, int optional, ev_paths *out);

/*
 * NAME.arcs.txt: polylines, one "x y" point per text line, a blank line between
 * pieces. Appends the pieces with the given tag. Same return and optional rules.
 */
int ev_read_polylines(const char *path, int tag, int optional, ev_paths *out);

/*
 * Detection JSON: {"width": W, "height": H, "segments": [{"x0"..,"y0"..,"x1"..,"y1"..,
 * "kind": "line"|"curve", "polyline": [[x,y],...], ...}, ...]}. Extra keys anywhere
 * are skipped. Each segment becomes one piece: its polyline when present (two or
 * more points), else its chord; tag from kind. *width / *height get the JSON's
 * values (0 when absent). Returns 0, or -1 with a message on stderr.
 */
int ev_read_detections(const char *path, ev_paths *out, int *width, int *height);

/* Same, from a NUL-terminated string (for tests); name is used in messages. */
int ev_parse_detections(const char *text, const char *name, ev_paths *out, int *width,
                        int *height);

/* Width and height from the header of a binary PGM. Returns 0 or -1. */
int ev_pgm_size(const char *path, int *width, int *height);

#endif

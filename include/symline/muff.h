/* SPDX-License-Identifier: Apache-2.0 */
/*
 * symline — the Muff-space line finder (the paper's first method; R.S. Wallace, "A Modified
 * Hough Transform for Lines", CVPR 1985), the paper's first method, as an
 * alternative to the tracer of symline_detect().
 *
 * A straight line through the frame is named by the two points where it
 * crosses the border rectangle of the pixel centres, (0,0)-(W-1,H-1). Each
 * is a perimeter coordinate s in [0, P), P = 2(W-1) + 2(H-1), counted
 * clockwise from the top-left corner: top edge s = x, right edge
 * s = (W-1) + y, bottom edge s = (W-1)+(H-1) + (W-1-x), left edge
 * s = 2(W-1)+(H-1) + (H-1-y). The perimeter is cut into cells of `cell`
 * pixels (cell i covers [i*cell, (i+1)*cell)); the accumulator has one
 * 16-bit counter per unordered pair of cells i < j, at index j(j-1)/2 + i.
 *
 * Every line point votes, for every cell, for the line through that cell's
 * centre and the point (the pair of that cell and the cell where the line
 * leaves the frame). Peaks that beat every pair within `nms_cells` cells at
 * both ends are lines; strongest first, each takes the line points within
 * `tol_q8` of it, along the longest run without a gap of more than `gap` px
 * (and covering at least `min_fill_pct` % of the run),
 * gets a least-squares fit, takes the points near the fit once more and is
 * reported as a segment clipped to the extent of those points (not border to
 * border). A point supports at most one segment.
 *
 * Accumulator sizes (cells of width/80 px, the default): 320x240, cell 4:
 * 279 cells, 38 781 pairs, 77 562 bytes; 640x480, cell 8: 280 cells, 39 060
 * pairs, 78 120 bytes. Halving the cell size quadruples it.
 *
 * Integer only, caller-owned memory, no allocation, no I/O. Optional module:
 * firmware that only traces does not link it.
 */
#ifndef SYMLINE_MUFF_H
#define SYMLINE_MUFF_H

#include "symline/detect.h"

#ifdef __cplusplus
extern "C" {
#endif

typedef struct symline_muff_config {
    uint32_t cell;         /* perimeter cell, px along the border, 1..64;
                            0 = auto: width/80, at least 2 (default 0) */
    uint32_t min_votes;    /* smallest accumulator peak, 1..65535; default 24 */
    uint32_t nms_cells;    /* a peak beats every pair within this many cells at
                            both ends, 0..16; default 2 */
    uint32_t max_peaks;    /* strongest peaks examined, 1..1024; default 128 */
    uint32_t tol_q8;       /* a line point supports a line within this distance,
                            Q8 px, 64..8192; 0 = auto: 3 px * width/640, at
                            least 2 px (default 0) */
    uint32_t gap;          /* largest gap between supporting points along a
                            segment, px, 1..65535; 0 = auto: width/32, at
                            least 2 tol + 2 px, the hole a crossing line
                            leaves (default 0) */
    uint32_t min_points;   /* fewest supporting points of a segment, 2..65535;
                            default 12 */
    uint32_t min_length;   /* shortest segment, px, 0..65535; default 12 */
    uint32_t min_fill_pct; /* the points of a segment cover at least this % of
                            its length, gaps up to width/160 px counting as
                            covered (coarse scales' points lie apart);
                            0..100, 0 = off; default 80 */
} symline_muff_config;

/* Fills *c with the defaults above (no-op on NULL). */
void symline_muff_config_default(symline_muff_config *c);

/* The cell size a configuration uses for a frame `width` px wide. */
uint32_t symline_muff_cell(const symline_muff_config *c, uint32_t width);

/*
 * Bytes of accumulator (uint16_t counters, see above) for a width x height
 * frame with this configuration; 0 when invalid (frames narrower or lower
 * than 3 px, a bad configuration, or a size that does not fit size_t).
 */
size_t symline_muff_accumulator_size(uint32_t width, uint32_t height, const symline_muff_config *c);

/*
 * Bytes of workspace symline_muff_find() needs besides the accumulator
 * (cell table, peak list, one row of bins along the longer side), or 0.
 */
size_t symline_muff_workspace_size(uint32_t width, uint32_t height, const symline_muff_config *c);

/*
 * Finds lines among the line points out->points[0 .. npoints-1]
 * (full-resolution pixel coordinates inside the frame; any order;
 * npoints <= out->point_cap). The points are reordered in place so that the
 * points of segment k are out->points[first .. first+count-1]; the points
 * that support no segment follow them, beyond out->point_count.
 * Segments: kind line, level 0, axis horizontal when |x1-x0| >= |y1-y0| else
 * vertical, max_dev = largest distance of their points to the chord; written
 * strongest peak first. out->truncated is set when segment_cap ran out.
 * acc: acc_size >= symline_muff_accumulator_size() bytes, uint16_t-aligned,
 * overwritten; ws: ws_size bytes, any alignment.
 * Returns SYMLINE_OK, ERR_NULL, ERR_SIZE (also: an accumulator beyond size_t),
 * ERR_CONFIG, ERR_BUFFER (acc or ws
 * too small, npoints > point_cap) or ERR_RANGE (a point outside the frame, or
 * a sub-pixel offset fx or fy outside -64..63);
 * on an error *out is unchanged apart from the order of its points.
 */
symline_status symline_muff_find(uint32_t width, uint32_t height, const symline_muff_config *c,
                                 uint16_t *acc, size_t acc_size, void *ws, size_t ws_size,
                                 uint32_t npoints, symline_result *out);

/*
 * Bytes of workspace symline_detect_muff() needs: the larger of the line
 * filter's (symline_detect_workspace_size()) and the finder's; 0 if invalid.
 */
size_t symline_detect_muff_workspace_size(uint32_t width, uint32_t height,
                                          const symline_config *cfg, const symline_muff_config *mc);

/*
 * The paper's first method end to end, next to symline_detect(): the line
 * points of the line filter (symline_line_points() with cfg: axes, scales,
 * filter and its thresholds; the tracing and merging fields are not used)
 * vote into the Muff accumulator and its peaks become segments.
 * out->points holds the line points first (give it room for all of them:
 * a few thousand in a 320x240 field view; when it runs out, the points that
 * fit are used and out->truncated is set), then is reordered as described
 * for symline_muff_find(). acc, ws as there (ws_size from
 * symline_detect_muff_workspace_size()).
 * Returns the status codes of symline_detect() and symline_muff_find().
 */
symline_status symline_detect_muff(const symline_image *img, const symline_config *cfg,
                                   const symline_muff_config *mc, uint16_t *acc, size_t acc_size,
                                   void *ws, size_t ws_size, symline_result *out);

#ifdef __cplusplus
}
#endif

#endif /* SYMLINE_MUFF_H */

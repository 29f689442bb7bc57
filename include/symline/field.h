/* SPDX-License-Identifier: Apache-2.0 */
/*
 * symline — the field boundary: where the field (the carpet) ends in a gray
 * frame, per image column, without colour.
 *
 * The carpet is taken to be the large region of homogeneous mid-gray texture
 * that fills the bottom of the frame. A coarse grid of cells (one sampled row
 * per cell) is classified against robust carpet statistics measured in the
 * lower part of the frame; every grid column is scanned upward for its
 * highest run of carpet, and the boundary is the upper convex hull of those
 * column tops: objects that cut into the carpet (legs, robots, posts) and
 * lines crossing it do not pull it down, and a field corner bends it once.
 * From gray alone the bottom of the frame is taken for carpet: a frame with
 * no carpet in view is not recognised as such.
 *
 * Wide-angle (fisheye) frames: the boundary is the top of the carpet region;
 * columns without carpet (the lens's black corners) take the level of the
 * nearest column with carpet, so the polyline still spans the frame.
 *
 *     symline_field_config fc;
 *     symline_field_config_default(&fc);
 *     size_t need = symline_field_workspace_size(w, h, &fc);  // bytes
 *     symline_field_boundary b;
 *     symline_status st = symline_field_find(&img, &fc, ws, need, &b);
 *     if (st == SYMLINE_OK && symline_field_above(&b, x, y)) { ... not on the field ... }
 *
 * Caller-owned memory, no allocation, no floating point, no I/O. The cost is
 * a fraction of an instruction per pixel: one row in every `cell` rows is read.
 *
 * Coordinates: image pixels, x right, y down, integers.
 */
#ifndef SYMLINE_FIELD_H
#define SYMLINE_FIELD_H

#include "symline/types.h"

#ifdef __cplusplus
extern "C" {
#endif

/* Most vertices of a boundary polyline. */
#define SYMLINE_FIELD_MAX_VERTICES 24u

/* One vertex of the boundary polyline, pixels. */
typedef struct symline_field_vertex {
    int32_t x; /* column, 0 .. width-1 */
    int32_t y; /* first field row at that column, 0 .. height */
} symline_field_vertex;

/*
 * The boundary: a polyline from the left image edge (v[0].x == 0) to the
 * right one (v[count-1].x == width-1), x strictly increasing (one vertex when
 * the frame is one pixel wide). Between vertices the boundary row is
 * interpolated linearly (symline_field_y()). Rows y >= boundary are field;
 * y == 0 at a column means the field reaches the top of the image there
 * (boundary at or above the image), y == height means no field in that
 * column (boundary at or below the bottom).
 */
typedef struct symline_field_boundary {
    uint32_t count;      /* vertices, 1..SYMLINE_FIELD_MAX_VERTICES; 0 = none computed */
    uint8_t carpet_mean; /* the carpet model's gray value (median of the band) */
    uint8_t carpet_tex;  /* its texture (see tex_lo_pct), Q8 */
    uint8_t cell;        /* grid step used, px */
    uint8_t reserved;
    symline_field_vertex v[SYMLINE_FIELD_MAX_VERTICES];
} symline_field_boundary;

/*
 * Settings; start from symline_field_config_default(). The defaults were
 * chosen on real NAO, humanoid and MSL frames (docs/detector.md).
 */
typedef struct symline_field_config {
    uint32_t cell;           /* grid step, px: 0 = auto (8, or 16 from 1024 px wide
                            on), else a power of two 2..64; default 0 */
    uint32_t band_pct;       /* the carpet model (median gray value and median
                            texture of the cells) comes from the lowest band_pct %
                            of the rows; cells darker than 12 (a lens's black
                            corners) are left out unless they are half the band
                            or more (a carpet clipped to black: the model is
                            black), 1..100; default 40 */
    uint32_t mean_tol;       /* a carpet cell's mean lies within this many gray
                            levels of the model, 0..255; default 16 */
    uint32_t local_tol;      /* ... or within this many of the running mean of the
                            carpet cells below it in its column (the carpet's
                            brightness drifts with distance and light), 0..255;
                            default 16 */
    uint32_t tex_lo_pct;     /* a cell's texture is the mean |difference| of
                            horizontal neighbours over its mean gray value (Q8:
                            a carpet's grain keeps that ratio in sunlight and in
                            shadow). A carpet cell's texture is at least this % of
                            the model's (walls are smooth), 0..100; default 25 */
    uint32_t tex_hi_pct;     /* ... and at most this % of it plus 4 (people, nets and
                            clutter have edges), 100..10000; default 150 */
    uint32_t miss_cost;      /* the upward column scan scores a carpet cell +1, a
                            cell brighter than the carpet below it 0 (a line
                            crossing it), a carpet-textured cell of another
                            brightness (a shadow's or a sunlit patch's edge;
                            the running mean follows the step) or of the
                            carpet's brightness without its grain -1, and any
                            other cell -miss_cost. The top of the best-scoring
                            run is the column's top. A high cost stops a column
                            at the first band that is not field (the boards, a
                            wall) rather than let it climb on to a ceiling that
                            looks like carpet: the hull bridges a column that
                            stops too low, never one that climbs too high,
                            1..16; default 10 */
    uint32_t gap_pct;        /* a column's scan ends for good after this % of the
                            grid rows in a row that are neither carpet nor
                            bright (a barrier: the boards, a wall band; what lies
                            above it is not field even where it looks like
                            carpet). When that leaves fewer than half the
                            columns with any carpet (a darkened fisheye frame,
                            its black rim taller than a barrier), the scan runs
                            again with black cells free in the lowest
                            gap_pct / 2 % of the rows below a column's first
                            carpet; 0 = never, 0..100; default 12 */
    uint32_t support;        /* a column's top counts as high as the support-th
                            highest top within `support` columns either side, so
                            narrower patches that look like carpet (a net, a
                            banner) do not lift the boundary, 1..8; default 3 */
    uint32_t restore_cells;  /* then every column's own top counts again, but no
                            higher than this many cells above that robust
                            boundary (a field corner's peak, which the support
                            rule lowers, comes back), 0..64 (0: off); default 1 */
    uint32_t col_cells;      /* grid columns lie col_cells cells apart (each reads
                            the first `cell` pixels of its span: half the cost
                            at 2), 1..4; default 2 */
    uint32_t edge_slope_pct; /* toward an image edge the boundary falls no
                            steeper than this % (rows per column) over its last
                            segment: there a robot or a person holds the outer
                            columns down with nothing beyond to bridge it,
                            0..10000 (0: off); default 50 */
} symline_field_config;

/* Fills *fc with the defaults documented above (no-op on NULL). */
void symline_field_config_default(symline_field_config *fc);

/* Bytes of workspace symline_field_find() needs, or 0 when an argument is
 * invalid. Grows with the width only: 20 bytes per grid column and about
 * 560 bytes. */
size_t symline_field_workspace_size(uint32_t width, uint32_t height,
                                    const symline_field_config *fc);

/*
 * Finds the field boundary of img. ws: ws_size bytes of scratch (any
 * alignment). Returns SYMLINE_OK, ERR_NULL, ERR_SIZE, ERR_STRIDE, ERR_CONFIG
 * or ERR_BUFFER; on an error *out is not changed.
 */
symline_status symline_field_find(const symline_image *img, const symline_field_config *fc,
                                  void *ws, size_t ws_size, symline_field_boundary *out);

/* The boundary row at column x (clamped to the polyline's x range): the
 * first field row. Returns 0 when b is NULL or empty. */
int32_t symline_field_y(const symline_field_boundary *b, int32_t x);

/* 1 when pixel (x, y) lies above the boundary (not on the field), else 0
 * (also for NULL or an empty boundary). */
int symline_field_above(const symline_field_boundary *b, int32_t x, int32_t y);

#ifdef __cplusplus
}
#endif

#endif /* SYMLINE_FIELD_H */

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
    uint8_t carpet_mean; /* the carpet's median gray value */
    uint8_t carpet_tol;  /* half-width of its accepted gray window */
    uint8_t carpet_tex;  /* its median texture (see tex_lo_pct), Q8 */
    uint8_t cell;        /* grid step used, px */
    symline_field_vertex v[SYMLINE_FIELD_MAX_VERTICES];
} symline_field_boundary;

/* Settings; start from symline_field_config_default(). */
typedef struct symline_field_config {
    uint32_t cell;       /* grid step, px: 0 = auto (the power of two nearest
                            below width/64, at least 2, at most 16), else a power
                            of two 2..64; default 0 */
    uint32_t band_pct;   /* the carpet statistics come from the lowest band_pct %
                            of the rows, 1..100; default 40 */
    uint32_t mean_tol;   /* smallest half-width of the carpet's gray window, gray
                            levels, 0..255; default 24 */
    uint32_t mad_x4;     /* the window is also at least mad_x4/4 times the median
                            absolute deviation of the band's cell means (sunlight
                            and shadow widen it), 0..64; default 12 */
    uint32_t tol_max;    /* ... and at most this, gray levels, 0..255; default 64 */
    uint32_t tex_lo_pct; /* a cell's texture is the mean |difference| of
                            horizontal neighbours over its mean gray value (Q8:
                            the grain of a carpet keeps its ratio in sunlight and
                            shadow). A carpet cell's texture is at least this % of
                            the carpet's median texture (walls are smooth),
                            0..100; default 25 */
    uint32_t tex_hi_pct; /* ... and at most this % of it, plus 4/256 (people and
                            clutter have edges), 100..10000; default 400 */
    uint32_t miss_cost;  /* penalty of a cell without carpet texture in the
                            upward column scan (carpet scores +1, a carpet-textured
                            cell of another brightness -1: a shadow, a sunlit
                            patch): the top of the best-scoring run is the
                            column's top, so gaps with enough carpet above them
                            are bridged, 1..16; default 2 */
    uint32_t local_tol;  /* a carpet cell also lies within this many gray levels
                            of the running mean of the carpet cells below it in
                            its column (the carpet's brightness drifts with
                            distance and light; a wall's edge breaks the run),
                            0..255; default 16 */
} symline_field_config;

/* Fills *fc with the defaults documented above (no-op on NULL). */
void symline_field_config_default(symline_field_config *fc);

/* Bytes of workspace symline_field_find() needs, or 0 when an argument is
 * invalid. Grows with the width only (about 12 bytes per grid column). */
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

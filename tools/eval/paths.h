/* SPDX-License-Identifier: Apache-2.0 */
/*
 * Polylines in image coordinates (pixels, x right, y down, integer values at
 * pixel centres) for the evaluation tools: ground truth, don't-care parts and
 * detections all become sets of polylines, sampled and compared the same way.
 * Host-only code: allocates, uses floating point.
 */
#ifndef SYMLINE_EVAL_PATHS_H
#define SYMLINE_EVAL_PATHS_H

#include <stddef.h>

typedef struct ev_pt {
    double x;
    double y;
} ev_pt;

/* Piece tags: what a polyline is. */
enum {
    EV_TAG_LINE = 0,  /* straight ground truth, or a detection of kind "line" */
    EV_TAG_CURVE = 1, /* centre-circle ground truth, or a detection of kind "curve" */
    EV_TAG_OTHER = 2  /* a detection whose kind is missing or unknown */
};

/* A set of polylines: piece i is pts[start[i] .. start[i+1]). */
typedef struct ev_paths {
    ev_pt *pts;
    size_t npts, cap_pts;
    size_t *start; /* npieces + 1 entries once a piece exists */
    int *tag;      /* one per piece */
    size_t npieces, cap_pieces;
} ev_paths;

void ev_paths_init(ev_paths *p);
void ev_paths_free(ev_paths *p);
/* Starts a new piece; the following ev_paths_add() calls append to it. */
void ev_paths_begin(ev_paths *p, int tag);
void ev_paths_add(ev_paths *p, double x, double y);
/* Appends all pieces of src to dst (tags kept). */
void ev_paths_append(ev_paths *dst, const ev_paths *src);
size_t ev_piece_len(const ev_paths *p, size_t piece);
const ev_pt *ev_piece_pts(const ev_paths *p, size_t piece);
/* Total length of piece in pixels. */
double ev_piece_length(const ev_paths *p, size_t piece);

/*
 * Samples every piece along its polyline every `step` pixels of arc length,
 * both ends included (a piece of length L gives ceil(L/step)+1 evenly spaced
 * samples; a single point or zero-length piece gives one sample). Returns the
 * number of samples; *out (malloc'd, free it) receives them and, when piece_of
 * is not NULL, *piece_of the piece index of each.
 */
size_t ev_sample(const ev_paths *p, double step, ev_pt **out, size_t **piece_of);

/* Distance from point q to segment a-b. */
double ev_dist_point_seg(ev_pt q, ev_pt a, ev_pt b);

/* One segment of a piece: points a and b (a == b for a single-point piece). */
typedef struct ev_seg {
    size_t a, b, piece;
} ev_seg;

/*
 * Spatial index over all segments of a path set (zero-length pieces count as
 * points) answering "is q within tol of any segment", exactly.
 */
typedef struct ev_index {
    const ev_paths *paths;
    double tol;
    double x0, y0, cell;
    int nx, ny;
    size_t *cell_start; /* nx*ny+1 */
    struct ev_seg *items;
} ev_index;

void ev_index_build(ev_index *ix, const ev_paths *p, double tol);
void ev_index_free(ev_index *ix);
/* 1 when q is within tol of a segment; *tag_out (optional) = tag of the nearest such piece. */
int ev_index_near(const ev_index *ix, ev_pt q, int *tag_out);
/* Distance from q to the nearest segment when it is within tol, else -1. */
double ev_index_dist(const ev_index *ix, ev_pt q);
/* Distance from q to the nearest segment of one piece of p. */
double ev_dist_piece(const ev_paths *p, size_t piece, ev_pt q);

#endif

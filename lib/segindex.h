/* SPDX-License-Identifier: Apache-2.0 */
/*
 * A coarse grid of the segments found so far, so that a pass asks "is this
 * point near an earlier segment?" of the few segments near the point instead
 * of every one (which made a cluttered frame's detection time grow with the
 * square of its size). Private to the library.
 */
#ifndef SYMLINE_LIB_SEGINDEX_H
#define SYMLINE_LIB_SEGINDEX_H

#include "common.h"
#include "segments.h"
#include "symline/detect.h"

/* Cells of 1 << SL_CELL_SHIFT full-resolution pixels square. */
#define SL_CELL_SHIFT 5u
/* The workspace has room for this many segment ids per cell on average; the
 * ids go to the free end of the point storage instead when that is larger.
 * Segments that fit in neither stay out of the grid and are tested one by one. */
#define SL_IDS_PER_CELL 4u
/* Marks a grid entry that is a curve piece (segindex_ids). */
#define SL_PIECE 0x80000000u

typedef struct symline_i_segindex {
    uint32_t cols, rows; /* cells across and down */
    uint32_t *end;       /* cols*rows: cell c holds ids[end[c-1] .. end[c]-1] (end[-1] = 0) */
    uint32_t *ids;       /* a line's segment id, or a run of a curve's polyline as two
                            entries: SL_PIECE | its first point's index, its last
                            point's index (segindex.c) */
    uint32_t indexed;    /* segments [0, indexed) are in the grid */
    uint32_t hit;        /* the entry a point was last found near, SL_NO_HIT: none */
} symline_i_segindex;

/* No entry (symline_i_segindex.hit). */
#define SL_NO_HIT 0xFFFFFFFFu

/* A walk over the grid cells within margin (Q8, plus the rounding slack of
 * the library's distance tests: length / 1024 + 1 px) of a chord, in pieces
 * of at most a cell; each cell is visited once per piece (a cell the
 * previous piece touched is skipped). What a visit does depends on the
 * mode: the two sweeps of symline_i_segindex_build(), or the merge's gathering of
 * the segment ends listed in the cells (merge.c). A switch rather than a
 * function pointer, so that the firmware's stack analysis can follow it. */
typedef enum symline_i_walk_mode {
    SL_WALK_COUNT, /* end[c] += width * sign (-1: a count taken back), added += width */
    SL_WALK_FILL,  /* ids[end[c]++] = seg */
    SL_WALK_GATHER /* every node of cell c's list (head, next) appended to cand */
} symline_i_walk_mode;

typedef struct symline_i_cellwalk {
    uint32_t cols, rows;
    int32_t margin; /* COUNT, FILL: the segment grid's tolerance (Q8) */
    symline_i_walk_mode mode;
    uint32_t *end, *ids, seg, added; /* COUNT, FILL */
    uint32_t sign;                   /* COUNT: 1, or UINT32_MAX (-1) */
    uint32_t piece_end, width;       /* FILL: a curve piece's second entry; 2 then, else 1 */
    const uint32_t *head, *next;     /* GATHER */
    uint32_t *cand, cand_cap, n;     /* GATHER: n found; cap + 1 when full */
#if SL_FOR_SPEED_DEEP
    /* COUNT, FILL of symline_i_segindex_build(): the cells the count visits,
     * kept for the fill, entry by entry (a line, or a curve's run; its last
     * cell marked SL_PIECE), item t at cells[-1 - t]: the first `kept`
     * (at most cell_cap; a whole entry or none of it), `used` of them read
     * so far; full: the entry being counted did not fit. */
    uint32_t *cells, cell_cap, kept, used;
    bool full;
#endif
} symline_i_cellwalk;

void symline_i_cellwalk_chord(symline_i_cellwalk *w, int32_t ax, int32_t ay, int32_t bx, int32_t by,
                              int32_t margin);

/* The grid of a width x height frame: *cols x *rows cells (returned). */
uint32_t symline_i_grid_dims(uint32_t width, uint32_t height, uint32_t *cols, uint32_t *rows);

/* The cell of a Q8 position, each coordinate clamped to the grid. */
uint32_t symline_i_cell_at(uint32_t cols, uint32_t rows, int32_t x_q8, int32_t y_q8);

/* Bytes of workspace symline_i_segindex_build() uses for a width x height frame. */
size_t symline_i_segindex_ws_size(uint32_t width, uint32_t height);

/*
 * Builds the grid of segments r->segments[0 .. nseg-1]: the cells in mem
 * (bytes from symline_i_segindex_ws_size(), aligned), the ids there or in `spare`
 * (spare_bytes, any alignment, may be NULL) when that is larger. Each
 * segment is entered in every cell within tol_q8 (plus the rounding of
 * symline_i_near_segment()) of its chord (a line) or its polyline (a curve).
 * Segments that do not fit stay out (ix->indexed).
 */
void symline_i_segindex_build(symline_i_segindex *ix, void *mem, size_t bytes, void *spare,
                              size_t spare_bytes, uint32_t width, uint32_t height,
                              const symline_result *r, uint32_t nseg, int32_t tol_q8);

/* Exactly symline_i_near_segment() of any of r->segments[0 .. nseg-1] for the
 * full-resolution point (x, y) (Q8, inside the frame); ix NULL: no grid.
 * Where the build optimises for speed, the entry the last point was found
 * near is tried first (ix->hit): a chain runs along an earlier segment for
 * many points. */
bool symline_i_segindex_near(symline_i_segindex *ix, const symline_result *r, uint32_t nseg,
                             int32_t x, int32_t y, int32_t tol_q8);

/* The first of a chain's points q .. e-1 (grid coordinates at `level` <=
 * SL_CELL_SHIFT, inside the frame) whose symline_i_segindex_near() is
 * `near`, e if none: a cell the grid lists nothing in answers false for
 * every point in it without a test (every segment in the grid: ix->indexed
 * = nseg, ix->cols != 0). Speed builds: one call per run of a chain
 * instead of one per point. */
const symline_point *symline_i_segindex_scan(symline_i_segindex *ix, const symline_result *r,
                                             uint32_t nseg, const symline_point *q,
                                             const symline_point *e, uint32_t level, int32_t tol_q8,
                                             bool near);

/* True when the grid lists nothing in cell c: symline_i_segindex_near() of
 * any point in it is then false once every segment is in the grid
 * (ix->indexed = nseg), whatever entry it would try first (a point near an
 * entry lies in a cell that lists it). */
static inline bool symline_i_segindex_cell_empty(const symline_i_segindex *ix, uint32_t c)
{
    return ix->end[c] == (c == 0u ? 0u : ix->end[c - 1u]);
}

#endif /* SYMLINE_LIB_SEGINDEX_H */

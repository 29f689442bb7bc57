/*
 * A coarse grid of segment end points for the merge: which line segments
 * have an end near a given line, without looking at every segment (the
 * all-pairs search made a cluttered frame's merge grow with the square of
 * its segment count). Lives in the caller's workspace. Private to the library.
 */
#ifndef SYMLINE_LIB_ENDGRID_H
#define SYMLINE_LIB_ENDGRID_H

#include "common.h"
#include "symline/detect.h"

typedef struct sl_endgrid {
    uint32_t cols, rows; /* cells of 1 << SL_CELL_SHIFT px (segindex.h) */
    uint32_t *head;      /* per cell: first node, or SL_END_NONE */
    uint32_t *next;      /* per node (2 per segment slot: end 0, end 1): the cell's */
    uint32_t *prev;      /*   doubly linked list */
    uint32_t *cand;      /* candidate slots found by a query */
    uint32_t cand_cap;
} sl_endgrid;

#define SL_END_NONE 0xFFFFFFFFu

/* A grid for nseg segment slots of a width x height frame, carved with its
 * lists from bytes of mem; NULL when they do not fit (or mem is NULL). */
sl_endgrid *sl_endgrid_init(void *mem, size_t bytes, uint32_t width, uint32_t height,
                            uint32_t nseg);

/* Enters or removes the two ends of segment s in slot `slot` (removal
 * before its ends change). */
void sl_endgrid_add(sl_endgrid *g, const symline_segment *s, uint32_t slot);
void sl_endgrid_remove(sl_endgrid *g, const symline_segment *s, uint32_t slot);

/*
 * The slots whose entered ends lie within `margin` (Q8) of the stretch of
 * segment a's line from at least `ext` (Q8, below 2^25) before its first end
 * to as far after its second (within margin of a's first end when a has no
 * length), in g->cand, ascending, each once. Returns their number, or -1
 * when more than g->cand_cap were found (the caller then tests every
 * segment).
 */
int32_t sl_endgrid_query(sl_endgrid *g, const symline_segment *a, uint32_t ext, int32_t margin);

#endif /* SYMLINE_LIB_ENDGRID_H */

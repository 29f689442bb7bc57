/* SPDX-License-Identifier: Apache-2.0 */
/*
 * One pass of the detector (pass.c): an axis at one scale, from the frame to
 * the pass's segments. It collects its line points (linepoints.c), traces
 * them (tracer.c), cuts, filters and fits the pieces (segments.c) and keeps
 * the points its segments use.
 */
#ifndef SYMLINE_LIB_PASS_H
#define SYMLINE_LIB_PASS_H

#include "common.h"
#include "fixed.h"
#include "linefilter.h"
#include "linepoints.h"
#include "segindex.h"
#include "tracer.h"
#include "symline/detect.h"

/* State of one detection shared by its passes. */
typedef struct symline_i_run {
    const symline_config *cfg;
    const symline_image *img; /* the frame, for the pieces' side test */
    symline_result *r;
    uint32_t nseg;               /* segments so far */
    uint32_t prev_seg;           /* segments of earlier passes: [0, prev_seg) */
    uint32_t npts;               /* points kept so far: [0, npts) */
    symline_i_frame_stats stats; /* for the adaptive thresholds (cfg->adaptive) */
    bool truncated;
    uint8_t cache_top;    /* SL_FOR_SPEED_DEEP: the coarsest scale of the grid row
                             cache at the point storage's end (linepoints.h); 0: none */
    uint16_t *field_rows; /* NULL, or width entries: line points above the field
                             boundary (d->r->field) are dropped before tracing */
} symline_i_run;

/* A point of a pass at `level` lies on an earlier segment within 2 px, plus
 * the block size of its scale (Q8). */
static inline int32_t symline_i_cover_tol_q8(uint32_t level)
{
    return (int32_t)(SL_PX_Q8(2u) + symline_i_block_q8(level));
}

/* Fills a pass from the configuration (no range checks; the adaptive
 * thresholds are the caller's: symline_i_linefilter_adapt()). */
void symline_i_pass_setup(symline_i_pass *p, const symline_config *cfg, symline_axis axis,
                          uint32_t level, uint32_t width, uint32_t height);

/* Workspace bytes of a pass: its symline_i_pass, the row index, and the line point
 * collection's rings (reused afterwards by the tracer's state and the grid
 * of earlier segments, segindex.h). Inline so that the workspace query
 * stays one call deep. */
static inline size_t symline_i_pass_ws_size(const symline_i_pass *p, uint32_t width,
                                            uint32_t height)
{
    const size_t c = symline_i_collect_ws_size(p, width);
    const size_t t = symline_i_align_up(sizeof(symline_i_tracer)) + SL_ALIGN +
                     symline_i_align_up(sizeof(symline_i_segindex)) + SL_ALIGN +
                     symline_i_segindex_ws_size(width, height);
    return symline_i_align_up(sizeof(symline_i_pass)) + SL_ALIGN +
           symline_i_align_up(((size_t)p->h + 2u) * 4u) + SL_ALIGN + (c > t ? c : t);
}

/*
 * Runs pass p over d->img: appends its segments to d->r and their points
 * after the first d->npts, and updates d (and p->field, the field boundary's
 * first kept row of each column). [ws, end): the pass workspace
 * after p itself (which the caller carved first). Returns SYMLINE_OK, or
 * SYMLINE_ERR_BUFFER when the workspace is smaller than symline_i_pass_ws_size()
 * (then d is unchanged but for d->truncated).
 */
symline_status symline_i_pass_run(symline_i_run *d, symline_i_pass *p, uint8_t *ws, uint8_t *end);

#endif /* SYMLINE_LIB_PASS_H */

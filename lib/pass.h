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
typedef struct sl_run {
    const symline_config *cfg;
    const symline_image *img; /* the frame, for the pieces' side test */
    symline_result *r;
    uint32_t nseg;        /* segments so far */
    uint32_t prev_seg;    /* segments of earlier passes: [0, prev_seg) */
    uint32_t npts;        /* points kept so far: [0, npts) */
    sl_frame_stats stats; /* for the adaptive thresholds (cfg->adaptive) */
    bool truncated;
    uint16_t *field_rows; /* NULL, or width entries: line points above the field
                             boundary (d->r->field) are dropped before tracing */
} sl_run;

/* A point of a pass at `level` lies on an earlier segment within 2 px, plus
 * the block size of its scale (Q8). */
static inline int32_t sl_cover_tol_q8(uint32_t level)
{
    return (int32_t)(SL_PX_Q8(2u) + sl_block_q8(level));
}

/* Fills a pass from the configuration (no range checks; the adaptive
 * thresholds are the caller's: sl_linefilter_adapt()). */
void sl_pass_setup(sl_pass *p, const symline_config *cfg, symline_axis axis, uint32_t level,
                   uint32_t width, uint32_t height);

/* Workspace bytes of a pass: its sl_pass, the row index, and the line point
 * collection's rings (reused afterwards by the tracer's state and the grid
 * of earlier segments, segindex.h). Inline so that the workspace query
 * stays one call deep. */
static inline size_t sl_pass_ws_size(const sl_pass *p, uint32_t width, uint32_t height)
{
    const size_t c = sl_collect_ws_size(p, width);
    const size_t t = sl_align_up(sizeof(sl_tracer)) + SL_ALIGN + sl_align_up(sizeof(sl_segindex)) +
                     SL_ALIGN + sl_segindex_ws_size(width, height);
    return sl_align_up(sizeof(sl_pass)) + SL_ALIGN + sl_align_up(((size_t)p->h + 2u) * 4u) +
           SL_ALIGN + (c > t ? c : t);
}

/*
 * Runs pass p over d->img: appends its segments to d->r and their points
 * after the first d->npts, and updates d. [ws, end): the pass workspace
 * after p itself (which the caller carved first). Returns SYMLINE_OK, or
 * SYMLINE_ERR_BUFFER when the workspace is smaller than sl_pass_ws_size()
 * (then d is unchanged but for d->truncated).
 */
symline_status sl_pass_run(sl_run *d, const sl_pass *p, uint8_t *ws, uint8_t *end);

#endif /* SYMLINE_LIB_PASS_H */

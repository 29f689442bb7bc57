/* SPDX-License-Identifier: Apache-2.0 */
/*
 * symline_muff_find(): configuration, memory, and the order of the work:
 * vote (muff_vote.c), peaks strongest first, and for each peak its segment
 * (muff_extent.c): points near the peak's line, a fit, then the points near
 * the fit, which the segment keeps.
 */
#include "muff_internal.h"

void symline_muff_config_default(symline_muff_config *c)
{
    if (c == NULL) {
        return;
    }
    c->cell = 0u;
    c->min_votes = 24u;
    c->nms_cells = 2u;
    c->max_peaks = 128u;
    c->tol_q8 = 0u;
    c->gap = 0u;
    c->min_points = 12u;
    c->min_length = 12u;
    c->min_fill_pct = 80u;
}

/* Ranges of symline_muff_config (see symline/muff.h). */
static int config_ok(const symline_muff_config *c)
{
    return c != NULL && c->cell <= 64u && c->min_votes >= 1u && c->min_votes <= 65535u &&
           c->nms_cells <= 16u && c->max_peaks >= 1u && c->max_peaks <= 1024u &&
           (c->tol_q8 == 0u || (c->tol_q8 >= 64u && c->tol_q8 <= 8192u)) && c->gap <= 65535u &&
           c->min_points >= 2u && c->min_points <= 65535u && c->min_length <= 65535u &&
           c->min_fill_pct <= 100u;
}

uint32_t symline_muff_cell(const symline_muff_config *c, uint32_t width)
{
    if (c == NULL) {
        return 0u;
    }
    if (c->cell != 0u) {
        return c->cell;
    }
    return width / 80u > 2u ? width / 80u : 2u;
}

static int frame_ok(uint32_t width, uint32_t height)
{
    return width >= 3u && height >= 3u && width <= SYMLINE_MAX_DIM && height <= SYMLINE_MAX_DIM;
}

size_t symline_muff_accumulator_size(uint32_t width, uint32_t height, const symline_muff_config *c)
{
    symline_i_perim p;
    uint64_t bytes;
    if (!frame_ok(width, height) || !config_ok(c)) {
        return 0u;
    }
    symline_i_perim_setup(&p, width, height, symline_muff_cell(c, width));
    bytes = symline_i_pair_count(&p) * sizeof(uint16_t);
    if (p.ncell > 65535u || bytes > (uint64_t)(size_t)-1) {
        return 0u;
    }
    return (size_t)bytes;
}

size_t symline_muff_workspace_size(uint32_t width, uint32_t height, const symline_muff_config *c)
{
    symline_i_perim p;
    const size_t longer = width > height ? width : height;
    if (symline_muff_accumulator_size(width, height, c) == 0u) {
        return 0u;
    }
    symline_i_perim_setup(&p, width, height, symline_muff_cell(c, width));
    return symline_i_align_up(sizeof(symline_i_extent)) +
           2u * symline_i_align_up((size_t)p.ncell * sizeof(uint16_t)) +
           symline_i_align_up((size_t)c->max_peaks * sizeof(symline_i_peak)) +
           symline_i_align_up(longer * sizeof(uint16_t)) + (size_t)5u * SL_ALIGN;
}

/* The segments of the peaks, strongest first; returns how many were written. */
SL_NOINLINE static uint32_t extract(symline_i_extent *e, const symline_i_perim *p,
                                    const uint16_t *cx, const uint16_t *cy,
                                    const symline_i_peak *peaks, uint32_t npeaks,
                                    symline_result *out)
{
    /* the peak's line runs through cell centres: up to half a cell off */
    const uint32_t coarse = e->tol_q8 + (p->cell << 7);
    uint32_t k, nseg = 0u;
    for (k = 0; k < npeaks; k++) {
        /* written in place; the spare only tells that the array is full */
        symline_segment *s = nseg < out->segment_cap ? &out->segments[nseg] : &e->spare;
        uint32_t cnt;
        symline_i_uvline_through(&e->line, cx[peaks[k].i], cy[peaks[k].i], cx[peaks[k].j],
                                 cy[peaks[k].j]);
        cnt = symline_i_extent_gather(e, &e->line, coarse);
        if (cnt == 0u) {
            continue;
        }
        /* the fit to the points near the peak's line picks the segment's own points */
        symline_i_extent_fit(e, cnt, &e->line, &e->fit1);
        cnt = symline_i_extent_gather(e, &e->fit1, e->tol_q8);
        if (cnt == 0u) {
            continue;
        }
        if (s == &e->spare) {
            out->truncated = true;
            break;
        }
        symline_i_extent_fit(e, cnt, &e->fit1, &e->fit2);
        symline_i_extent_segment(e, &e->fit2, cnt, s);
        e->used += cnt;
        nseg++;
    }
    return nseg;
}

symline_status symline_muff_find(uint32_t width, uint32_t height, const symline_muff_config *c,
                                 uint16_t *acc, size_t acc_size, void *ws, size_t ws_size,
                                 uint32_t npoints, symline_result *out)
{
    symline_i_perim p;
    uint8_t *cur, *end;
    uint16_t *cx, *cy;
    symline_i_peak *peaks;
    symline_i_extent *e;
    size_t need, i;
    uint32_t k, npeaks;
    if (acc == NULL || ws == NULL || out == NULL || c == NULL) {
        return SYMLINE_ERR_NULL;
    }
    if ((out->points == NULL && out->point_cap != 0u) ||
        (out->segments == NULL && out->segment_cap != 0u)) {
        return SYMLINE_ERR_NULL;
    }
    if (!frame_ok(width, height)) {
        return SYMLINE_ERR_SIZE;
    }
    if (!config_ok(c)) {
        return SYMLINE_ERR_CONFIG;
    }
    need = symline_muff_accumulator_size(width, height, c);
    if (need == 0u) {
        return SYMLINE_ERR_SIZE; /* the accumulator would not fit size_t */
    }
    if (acc_size < need || ws_size < symline_muff_workspace_size(width, height, c) ||
        npoints > out->point_cap) {
        return SYMLINE_ERR_BUFFER;
    }
    for (k = 0; k < npoints; k++) {
        const symline_point *q = &out->points[k];
        /* offsets beyond -64..63 would put a point's fitted coordinate below 0 */
        if (q->x >= width || q->y >= height || q->fx < -64 || q->fx > 63 || q->fy < -64 ||
            q->fy > 63) {
            return SYMLINE_ERR_RANGE;
        }
    }
    symline_i_perim_setup(&p, width, height, symline_muff_cell(c, width));
    cur = (uint8_t *)ws;
    end = cur + ws_size;
    e = (symline_i_extent *)symline_i_carve(&cur, end, sizeof(symline_i_extent));
    cx = (uint16_t *)symline_i_carve(&cur, end, (size_t)p.ncell * sizeof(uint16_t));
    cy = (uint16_t *)symline_i_carve(&cur, end, (size_t)p.ncell * sizeof(uint16_t));
    peaks =
        (symline_i_peak *)symline_i_carve(&cur, end, (size_t)c->max_peaks * sizeof(symline_i_peak));
    if (e == NULL || cx == NULL || cy == NULL || peaks == NULL) {
        return SYMLINE_ERR_BUFFER;
    }
    e->bins = (uint16_t *)symline_i_carve(
        &cur, end, (size_t)(width > height ? width : height) * sizeof(uint16_t));
    if (e->bins == NULL) {
        return SYMLINE_ERR_BUFFER;
    }
    symline_i_cell_centres(&p, cx, cy);
    for (i = 0; i < need / sizeof(uint16_t); i++) {
        acc[i] = 0u;
    }
    symline_i_muff_vote(&p, cx, cy, out->points, npoints, acc);
    npeaks = symline_i_muff_peaks(&p, acc, c->min_votes, c->nms_cells, peaks, c->max_peaks);
    e->pts = out->points;
    e->n = npoints;
    e->used = 0u;
    e->width = width;
    e->height = height;
    e->cfg = c;
    /* auto: 2 px at 320 wide, 3 px at 640 (the pixel pitch of far lines and
     * of coarse scales grows with the frame); gaps width/32, and at least the
     * hole a crossing line leaves (its points within the tolerance are taken
     * by whichever line is found first) */
    e->tol_q8 = c->tol_q8 != 0u ? c->tol_q8 : (width * 6u / 5u > 512u ? width * 6u / 5u : 512u);
    e->gap = c->gap;
    if (e->gap == 0u) {
        const uint32_t hole = 2u * ((e->tol_q8 + 255u) >> 8) + 2u;
        e->gap = width / 32u > hole ? width / 32u : hole;
    }
    out->truncated = false;
    out->segment_count = extract(e, &p, cx, cy, peaks, npeaks, out);
    out->point_count = e->used;
    return SYMLINE_OK;
}

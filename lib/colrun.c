/* SPDX-License-Identifier: Apache-2.0 */
/*
 * The column-run follower of the public API (include/symline/extrema.h):
 * extrema down the columns reported as events, with a small per-column state
 * (E of the row above, where the run began, and how the run was entered), so
 * a caller processes a frame row by row without holding more than one row of
 * energies. symline_extrema() decides the same extrema over whole rows
 * instead (symline_i_extrema_down()), the detector at its filter's
 * candidates (linepoints.c); the feature points use this.
 */
#include "common.h"
#include "symline/extrema.h"

size_t symline_colrun_buffer_size(uint32_t width)
{
    if (width == 0u || width > SYMLINE_MAX_DIM) {
        return 0u;
    }
    return symline_i_align_up((size_t)width * sizeof(uint32_t)) +
           symline_i_align_up((size_t)width * sizeof(uint16_t)) +
           symline_i_align_up((size_t)width) + SL_ALIGN;
}

symline_status symline_colrun_init(symline_colrun *cr, uint32_t width, void *buf, size_t buf_size)
{
    uint8_t *cur, *end;
    if (cr == NULL || buf == NULL) {
        return SYMLINE_ERR_NULL;
    }
    if (width == 0u || width > SYMLINE_MAX_DIM) {
        return SYMLINE_ERR_SIZE;
    }
    cur = (uint8_t *)buf;
    end = cur + buf_size;
    cr->prev_e = (uint32_t *)symline_i_carve(&cur, end, (size_t)width * sizeof(uint32_t));
    cr->run_start = (uint16_t *)symline_i_carve(&cur, end, (size_t)width * sizeof(uint16_t));
    cr->left = (int8_t *)symline_i_carve(&cur, end, (size_t)width);
    if (cr->prev_e == NULL || cr->run_start == NULL || cr->left == NULL) {
        return SYMLINE_ERR_BUFFER;
    }
    cr->width = width;
    cr->next_y = 0u;
    return SYMLINE_OK;
}

symline_status symline_colrun_push(symline_colrun *cr, const uint32_t *E, symline_extremum *events,
                                   uint32_t events_cap, uint32_t *count)
{
    uint32_t x, n = 0u, y;
    if (cr == NULL || E == NULL || events == NULL || count == NULL || cr->prev_e == NULL ||
        cr->run_start == NULL || cr->left == NULL) {
        return SYMLINE_ERR_NULL;
    }
    if (events_cap < cr->width) {
        return SYMLINE_ERR_BUFFER;
    }
    y = cr->next_y;
    if (y >= SYMLINE_MAX_DIM) {
        return SYMLINE_ERR_RANGE;
    }
    if (y == 0u) {
        for (x = 0; x < cr->width; x++) {
            cr->prev_e[x] = E[x];
            cr->run_start[x] = 0u;
            cr->left[x] = 0;
        }
    } else {
        for (x = 0; x < cr->width; x++) {
            const uint32_t e = E[x];
            const uint32_t p = cr->prev_e[x];
            int8_t right;
            if (e == p) {
                continue;
            }
            /* The run [run_start, y-1] ends here; right = +1 when the row below is larger. */
            right = (e > p) ? 1 : -1;
            if (cr->left[x] == right) {
                events[n].x = (uint16_t)x;
                events[n].y = (uint16_t)(((uint32_t)cr->run_start[x] + y - 1u) / 2u);
                events[n].kind = (uint8_t)((right > 0) ? SYMLINE_MAP_S : SYMLINE_MAP_A);
                n++;
            }
            /* The new run starts at y; the row above it (p) is larger when p > e. */
            cr->left[x] = (int8_t)-right;
            cr->run_start[x] = (uint16_t)y;
            cr->prev_e[x] = e;
        }
    }
    cr->next_y = y + 1u;
    *count = n;
    return SYMLINE_OK;
}

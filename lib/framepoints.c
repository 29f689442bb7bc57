/* SPDX-License-Identifier: Apache-2.0 */
/*
 * symline_line_points(): the line filter's output of every pass of a
 * configuration, without tracing. The Muff-space finder votes with it; a
 * module of its own so that firmware that only traces does not link it.
 */
#include "symline/detect.h"

#include "common.h"
#include "fixed.h"
#include "linefilter.h"
#include "linepoints.h"
#include "pass.h"
#include "passplan.h"
#include "subpixel.h"
#include "tracer.h"

/* Leaves out the points of a pass's raster list pts[0..n-1] that have no line
 * point among their 8 neighbours (type A in the paper's classification: neither method uses them),
 * moves the rest to the front and returns their number. */
SL_NOINLINE static uint32_t drop_isolated(const symline_i_pass *p, symline_point *pts, uint32_t n,
                                          const uint32_t *row_start)
{
    symline_i_tracer t;
    uint32_t y, i, k = 0u;
    symline_i_tracer_init(&t, pts, n, row_start, p->h);
    /* mark first (a lookup reads only x and the row index), then compact */
    for (y = 0; y < p->h; y++) {
        for (i = row_start[y]; i < row_start[y + 1u]; i++) {
            if (symline_i_neighbours(&t, pts[i].x, y) == 0u) {
                pts[i].y = SL_VISITED;
            }
        }
    }
    for (i = 0; i < n; i++) {
        if (pts[i].y != SL_VISITED) {
            pts[k].x = pts[i].x;
            pts[k].y = pts[i].y;
            k++;
        }
    }
    return k;
}

/* The passes in the order of symline_detect(), each collected into pts + n. */
SL_NOINLINE static uint32_t collect_all(const symline_image *img, const symline_config *cfg,
                                        uint8_t *ws, uint8_t *end,
                                        const symline_i_frame_stats *stats, symline_point *pts,
                                        uint32_t cap, bool *truncated)
{
    const uint32_t L = symline_i_level_count(cfg, img->width, img->height);
    uint32_t l, a, k, n = 0u;
    for (l = 0; l < L; l++) {
        for (a = 0; a < symline_i_axis_count(cfg); a++) {
            uint8_t *cur = ws;
            symline_i_pass *p =
                (symline_i_pass *)symline_i_carve(&cur, end, sizeof(symline_i_pass));
            uint32_t *row_start;
            uint32_t got = 0u;
            if (p == NULL) {
                return n; /* not reached: the workspace size was checked */
            }
            symline_i_pass_setup(p, cfg, symline_i_axis_of(cfg, a), l, img->width, img->height);
            if (cfg->adaptive) {
                symline_i_linefilter_adapt(&p->filter, cfg, stats, l);
            }
            row_start =
                (uint32_t *)symline_i_carve(&cur, end, ((size_t)p->h + 1u) * sizeof(uint32_t));
            if (row_start == NULL) {
                return n;
            }
            uint32_t dropped = 0u;
            (void)symline_i_collect(img, p, cur, (size_t)(end - cur), pts + n, cap - n, &got,
                                    row_start, &dropped);
            if (dropped != 0u) {
                *truncated = true;
            }
            got = drop_isolated(p, pts + n, got, row_start);
            /* sub-pixel offsets across the line, then full resolution (a call
             * apart from drop_isolated: the stack holds one of them at a time) */
            symline_i_subpixel(img, p, pts + n, got);
            for (k = n; k < n + got; k++) {
                symline_i_pt_to_full(&pts[k], p->level);
            }
            n += got;
        }
    }
    return n;
}

symline_status symline_line_points(const symline_image *img, const symline_config *cfg, void *ws,
                                   size_t ws_size, symline_point *pts, uint32_t cap,
                                   uint32_t *count, bool *truncated)
{
    symline_status st = symline_image_check(img);
    symline_i_frame_stats stats;
    if (st != SYMLINE_OK) {
        return st;
    }
    if (cfg == NULL || ws == NULL || count == NULL || truncated == NULL || pts == NULL) {
        return SYMLINE_ERR_NULL;
    }
    st = symline_i_config_ws_check(img, cfg, ws_size);
    if (st != SYMLINE_OK) {
        return st;
    }
    *truncated = false;
    stats.mean = 0u;
    stats.sigma_q4 = 0u;
    stats.ridge_q4 = 0u;
    if (cfg->adaptive) {
        /* The whole frame's statistics (the detector's are the field's when
         * it finds a boundary); the histograms at the workspace's start, free
         * again for the collection. */
        uint8_t *cur = (uint8_t *)ws;
        uint32_t *hist =
            (uint32_t *)symline_i_carve(&cur, (uint8_t *)ws + ws_size, SL_STATS_HIST_BYTES);
        if (hist == NULL) {
            return SYMLINE_ERR_BUFFER; /* not reached: the workspace size was checked */
        }
        symline_i_frame_stats_measure(img, NULL, hist, &stats);
    }
    *count =
        collect_all(img, cfg, (uint8_t *)ws, (uint8_t *)ws + ws_size, &stats, pts, cap, truncated);
    return SYMLINE_OK;
}

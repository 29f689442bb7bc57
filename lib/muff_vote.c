/* SPDX-License-Identifier: Apache-2.0 */
/*
 * Muff space: perimeter coordinates, voting and the accumulator's peaks.
 *
 * A point votes once per perimeter cell: for the line through the cell's
 * centre and the point, i.e. the pair (cell, cell where that line leaves
 * the frame). Of the votes a point on a true line (a, b) casts, the one from
 * the far end's cell lands well (the point is far from that centre, so the
 * direction is accurate); together the points of a line pile up on (a, b)
 * while the others spread. Cells closer to the point than two cells give a
 * poorly defined direction and do not vote.
 */
#include "muff_internal.h"

void symline_i_perim_setup(symline_i_perim *p, uint32_t width, uint32_t height, uint32_t cell)
{
    p->w1 = width - 1u;
    p->h1 = height - 1u;
    p->len = 2u * p->w1 + 2u * p->h1;
    p->cell = cell;
    p->ncell = (p->len + cell - 1u) / cell;
}

void symline_i_perim_point(const symline_i_perim *p, uint32_t s, uint32_t *x, uint32_t *y)
{
    const uint32_t w1 = p->w1, h1 = p->h1;
    if (s <= w1) {
        *x = s;
        *y = 0u;
    } else if (s <= w1 + h1) {
        *x = w1;
        *y = s - w1;
    } else if (s <= 2u * w1 + h1) {
        *x = w1 - (s - w1 - h1);
        *y = h1;
    } else {
        *x = 0u;
        *y = h1 - (s - 2u * w1 - h1);
    }
}

uint32_t symline_i_perim_coord(const symline_i_perim *p, uint32_t x, uint32_t y)
{
    const uint32_t w1 = p->w1, h1 = p->h1;
    if (y == 0u) {
        return x;
    }
    if (x == w1) {
        return w1 + y;
    }
    if (y == h1) {
        return w1 + h1 + (w1 - x);
    }
    return 2u * w1 + h1 + (h1 - y);
}

uint64_t symline_i_pair_count(const symline_i_perim *p)
{
    return (uint64_t)p->ncell * (p->ncell - 1u) / 2u;
}

void symline_i_cell_centres(const symline_i_perim *p, uint16_t *cx, uint16_t *cy)
{
    uint32_t i;
    for (i = 0; i < p->ncell; i++) {
        uint32_t s = i * p->cell + p->cell / 2u, x, y;
        if (s >= p->len) {
            s = p->len - 1u;
        }
        symline_i_perim_point(p, s, &x, &y);
        cx[i] = (uint16_t)x;
        cy[i] = (uint16_t)y;
    }
}

/* (num + den/2) / den for num, den > 0 */
static uint32_t div_round(uint64_t num, uint32_t den)
{
    return den != 0u ? (uint32_t)((num + den / 2u) / den) : 0u;
}

/* Cell where the ray from border point (ax, ay) through (px, py) leaves the frame. */
static uint32_t exit_cell(const symline_i_perim *p, uint32_t ax, uint32_t ay, int32_t dx,
                          int32_t dy)
{
    const uint32_t adx = (uint32_t)(dx < 0 ? -dx : dx), ady = (uint32_t)(dy < 0 ? -dy : dy);
    const uint32_t nx = dx > 0 ? p->w1 - ax : ax; /* room to the side the ray runs to */
    const uint32_t ny = dy > 0 ? p->h1 - ay : ay;
    uint32_t ex, ey;
    if (ady == 0u || (adx != 0u && (uint64_t)nx * ady <= (uint64_t)ny * adx)) {
        /* leaves through the left or right side */
        const uint32_t off = div_round((uint64_t)nx * ady, adx);
        ex = dx > 0 ? p->w1 : 0u;
        ey = dy >= 0 ? ay + off : ay - off;
    } else {
        const uint32_t off = div_round((uint64_t)ny * adx, ady);
        ey = dy > 0 ? p->h1 : 0u;
        ex = dx >= 0 ? ax + off : ax - off;
    }
    return symline_i_perim_coord(p, ex, ey) / p->cell;
}

void symline_i_muff_vote(const symline_i_perim *p, const uint16_t *cx, const uint16_t *cy,
                         const symline_point *pts, uint32_t n, uint16_t *acc)
{
    const int32_t near = 2 * (int32_t)p->cell;
    uint32_t k, i;
    for (k = 0; k < n; k++) {
        const int32_t px = pts[k].x, py = pts[k].y;
        for (i = 0; i < p->ncell; i++) {
            const int32_t dx = px - cx[i], dy = py - cy[i];
            uint32_t j, lo, hi;
            size_t idx;
            if ((dx < 0 ? -dx : dx) + (dy < 0 ? -dy : dy) < near) {
                continue;
            }
            j = exit_cell(p, cx[i], cy[i], dx, dy);
            if (j == i) {
                continue;
            }
            lo = i < j ? i : j;
            hi = i < j ? j : i;
            idx = (size_t)hi * (hi - 1u) / 2u + lo;
            if (acc[idx] != 0xFFFFu) {
                acc[idx]++;
            }
        }
    }
}

/* Counter of pair (a, b) of cells (any order, taken modulo ncell); 0 for a == b. */
static uint32_t pair_votes(const symline_i_perim *p, const uint16_t *acc, int32_t a, int32_t b)
{
    const int32_t nc = (int32_t)p->ncell;
    uint32_t ua = (uint32_t)((a % nc + nc) % nc), ub = (uint32_t)((b % nc + nc) % nc);
    if (ua == ub) {
        return 0u;
    }
    if (ua > ub) {
        const uint32_t t = ua;
        ua = ub;
        ub = t;
    }
    return acc[(size_t)ub * (ub - 1u) / 2u + ua];
}

/* 1 when pair (i, j) with count v beats every pair within nms cells at both
 * ends; ties go to the pair with the smaller index, so a plateau gives one peak. */
static int is_peak(const symline_i_perim *p, const uint16_t *acc, uint32_t i, uint32_t j,
                   uint32_t v, uint32_t nms)
{
    const int32_t r = (int32_t)nms;
    const size_t self = (size_t)j * (j - 1u) / 2u + i;
    int32_t di, dj;
    for (di = -r; di <= r; di++) {
        for (dj = -r; dj <= r; dj++) {
            const int32_t a = (int32_t)i + di, b = (int32_t)j + dj;
            uint32_t u;
            if (di == 0 && dj == 0) {
                continue;
            }
            u = pair_votes(p, acc, a, b);
            if (u > v) {
                return 0;
            }
            if (u == v) {
                /* the same count: the pair with the smaller index wins */
                const int32_t nc = (int32_t)p->ncell;
                uint32_t ua = (uint32_t)((a % nc + nc) % nc), ub = (uint32_t)((b % nc + nc) % nc);
                size_t other;
                if (ua > ub) {
                    const uint32_t t = ua;
                    ua = ub;
                    ub = t;
                }
                other = (size_t)ub * (ub - 1u) / 2u + ua;
                if (other < self) {
                    return 0;
                }
            }
        }
    }
    return 1;
}

uint32_t symline_i_muff_peaks(const symline_i_perim *p, const uint16_t *acc, uint32_t min_votes,
                              uint32_t nms, symline_i_peak *peaks, uint32_t cap)
{
    uint32_t i, j, n = 0u;
    size_t idx = 0u;
    for (j = 1u; j < p->ncell; j++) {
        for (i = 0; i < j; i++, idx++) {
            const uint32_t v = acc[idx];
            uint32_t k;
            if (v < min_votes || (n == cap && v <= peaks[n - 1u].votes)) {
                continue;
            }
            if (!is_peak(p, acc, i, j, v, nms)) {
                continue;
            }
            /* insert, strongest first (a full list drops its weakest) */
            k = n < cap ? n++ : cap - 1u;
            while (k > 0u && peaks[k - 1u].votes < v) {
                /* field by field: a struct copy may become a memcpy call */
                peaks[k].index = peaks[k - 1u].index;
                peaks[k].i = peaks[k - 1u].i;
                peaks[k].j = peaks[k - 1u].j;
                peaks[k].votes = peaks[k - 1u].votes;
                k--;
            }
            peaks[k].index = (uint32_t)idx;
            peaks[k].i = (uint16_t)i;
            peaks[k].j = (uint16_t)j;
            peaks[k].votes = (uint16_t)v;
        }
    }
    return n;
}

/* SPDX-License-Identifier: Apache-2.0 */
/*
 * Extrema of symmetry on the exact energies, with the plateau rule.
 *
 * Along a row the runs are found in one pass. Down the columns a small
 * per-column state (E of the row above, where the run began, and how the
 * run was entered) follows every column at once, so the frame is processed
 * row by row without ever holding more than one row of energies.
 */
#include "extrema.h"

#include "symmetry.h"

uint32_t symline_i_extrema_kinds(const uint32_t *restrict up, const uint32_t *restrict mid,
                                 const uint32_t *restrict dn, uint32_t n, uint8_t *restrict map)
{
    uint32_t x, flat = 0u;
    /* E < 2^31 for every radius (symline_emax(255) < 2^31), so the sign of
     * a difference is its top bit: mid is an S point when both up - mid and
     * dn - mid are positive (mid - up and mid - dn negative), an A point when
     * both are negative. Subtractions and shifts only: baseline SSE2 has no
     * unsigned 32-bit compare or min/max. */
    for (x = 0; x < n; x++) {
        const uint32_t a = up[x], b = mid[x], c = dn[x];
        const uint32_t s = ((b - a) & (b - c)) >> 31;
        const uint32_t l = ((a - b) & (c - b)) >> 31;
        map[x] = (uint8_t)((0u - s) | (l << 7));
        flat |= (uint32_t)(a == b) | (uint32_t)(b == c);
    }
    return flat;
}

/* The run rule over a row. Every entry with unequal neighbours is already
 * decided (symline_i_extrema_kinds()); what is left are the runs of two or
 * more equal energies: run [a, i-1] ends where E changes, and is marked at
 * its middle unless it touches either end or is longer than the plateau
 * limit allows. */
void symline_i_extrema_runs(const uint32_t *E, uint32_t n, uint32_t lag, uint8_t *map)
{
    uint32_t a, i;
    map[0] = SYMLINE_MAP_NONE;
    map[n - 1u] = SYMLINE_MAP_NONE;
    if (n < 3u || symline_i_extrema_kinds(E, E + 1, E + 2, n - 2u, map + 1) == 0u) {
        return;
    }
    for (i = 1u; i < n; i++) {
        if (E[i] != E[i - 1u]) {
            continue;
        }
        a = i - 1u;
        while (i < n && E[i] == E[a]) {
            i++;
        }
        if (a >= 1u && i < n) {
            const uint32_t mid = (a + i - 1u) / 2u;
            if (i - 1u - mid <= lag) {
                if (E[a - 1u] > E[a] && E[i] > E[a]) {
                    map[mid] = SYMLINE_MAP_S;
                } else if (E[a - 1u] < E[a] && E[i] < E[a]) {
                    map[mid] = SYMLINE_MAP_A;
                }
            }
        }
    }
}

/* The slow path of symline_i_extrema_down(): columns x .. x_end-1 where a
 * run of equal energies begins or ends at row t-1. A run begins when
 * mid == dn != up (or t = 1); left says whether the row above it is larger
 * (+1), smaller (-1) or absent (0). It ends when up == mid != dn, and is an
 * extremum at its middle row when the row below is on the same side. */
static void plateaus_down(const symline_i_coldown *cd, const uint32_t *up, const uint32_t *mid,
                          const uint32_t *dn, uint32_t t, uint32_t x, uint32_t x_end)
{
    for (; x < x_end; x++) {
        if (mid[x] == dn[x]) {
            if (up[x] != mid[x] || t == 1u) {
                cd->run_start[x] = (uint16_t)(t - 1u);
                cd->left[x] = (int8_t)((up[x] > mid[x]) - (up[x] < mid[x]));
            }
        } else if (up[x] == mid[x] && t >= 2u) {
            const int8_t right = (int8_t)((dn[x] > mid[x]) ? 1 : -1);
            const uint32_t y = ((uint32_t)cd->run_start[x] + t - 1u) / 2u;
            if (cd->left[x] == right && t - 1u - y <= cd->lag) {
                cd->map[(size_t)(y % cd->ring) * cd->stride + x] =
                    (uint8_t)((right > 0) ? SYMLINE_MAP_S : SYMLINE_MAP_A);
            }
        }
    }
}

void symline_i_extrema_down(const symline_i_coldown *cd, const uint32_t *E, uint32_t t)
{
    /* Row t-2 is row t-1 itself at t = 1: row 0 has no row above, so it is
     * never marked, and a run that starts there has no side. */
    const uint32_t w = cd->width;
    const uint32_t *mid = cd->E3 + (size_t)((t + 2u) % 3u) * w;
    const uint32_t *up = (t >= 2u) ? cd->E3 + (size_t)((t + 1u) % 3u) * w : mid;
    uint8_t *mr = cd->map + (size_t)((t - 1u) % cd->ring) * cd->stride;
    uint32_t i;
    /* In blocks, so that a plateau sends only its block down the slow path. */
    for (i = 0; i < w; i += SL_PLATEAU_BLOCK) {
        const uint32_t nb = (w - i < SL_PLATEAU_BLOCK) ? w - i : SL_PLATEAU_BLOCK;
        if (symline_i_extrema_kinds(up + i, mid + i, E + i, nb, mr + i) != 0u) {
            plateaus_down(cd, up, mid, E, t, i, i + nb);
        }
    }
}

symline_status symline_extrema_row(const uint32_t *E, uint32_t n, uint8_t *map)
{
    if (E == NULL || map == NULL) {
        return SYMLINE_ERR_NULL;
    }
    if (n == 0u || n > SYMLINE_MAX_DIM) {
        return SYMLINE_ERR_SIZE;
    }
    symline_i_extrema_runs(E, n, SL_RUN_ANY_LENGTH, map);
    return SYMLINE_OK;
}

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

size_t symline_extrema_workspace_size(uint32_t width, uint32_t height, symline_axis axis,
                                      uint32_t m)
{
    size_t n;
    if (!symline_i_query_ok(width, height, axis, m)) {
        return 0u;
    }
    n = symline_i_align_up((size_t)width * sizeof(uint32_t)) + SL_ALIGN;
    if (axis == SYMLINE_AXIS_HORIZONTAL) {
        n += symline_colrun_buffer_size(width) +
             symline_i_align_up((size_t)width * sizeof(symline_extremum)) + SL_ALIGN;
    }
    return n;
}

symline_status symline_extrema(const symline_image *img, symline_axis axis, uint32_t m,
                               uint8_t *map, uint32_t map_stride, size_t map_len, void *ws,
                               size_t ws_size)
{
    uint8_t *cur, *end;
    uint32_t *E, y, x;
    symline_colrun cr;
    symline_extremum *ev = NULL;
    symline_status st =
        symline_i_frame_begin(img, axis, m, map, map_stride, map_len, ws, ws_size, &cur, &end, &E);
    if (st != SYMLINE_OK) {
        return st;
    }
    if (axis == SYMLINE_AXIS_VERTICAL) {
        for (y = 0; y < img->height; y++) {
            (void)symline_energy_row(img->data + (size_t)y * img->stride, img->width, m, E);
            (void)symline_extrema_row(E, img->width, map + (size_t)y * map_stride);
        }
        return SYMLINE_OK;
    }
    {
        const size_t cr_bytes = symline_colrun_buffer_size(img->width);
        void *cr_buf = symline_i_carve(&cur, end, cr_bytes);
        ev = (symline_extremum *)symline_i_carve(&cur, end,
                                                 (size_t)img->width * sizeof(symline_extremum));
        if (cr_buf == NULL || ev == NULL ||
            symline_colrun_init(&cr, img->width, cr_buf, cr_bytes) != SYMLINE_OK) {
            return SYMLINE_ERR_BUFFER;
        }
    }
    for (y = 0; y < img->height; y++) {
        uint32_t count = 0u, k;
        uint8_t *row = map + (size_t)y * map_stride;
        (void)symline_energy_across_image(img, y, m, E);
        for (x = 0; x < img->width; x++) {
            row[x] = SYMLINE_MAP_NONE;
        }
        (void)symline_colrun_push(&cr, E, ev, img->width, &count);
        /* Events always lie in rows already written (y-1 and above). */
        for (k = 0; k < count; k++) {
            map[(size_t)ev[k].y * map_stride + ev[k].x] = ev[k].kind;
        }
    }
    return SYMLINE_OK;
}

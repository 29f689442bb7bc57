/* SPDX-License-Identifier: Apache-2.0 */
/*
 * Vertical symmetry histogram: S points of the vertical-axis extrema map,
 * counted per column, one row at a time (a row's extrema need only that row).
 */
#include "symline/histogram.h"

#include "symline/extrema.h"
#include "symline/symmetry.h"
#include "common.h"

size_t symline_histogram_workspace_size(uint32_t width, uint32_t m)
{
    if (width == 0u || width > SYMLINE_MAX_DIM || symline_i_check_radius(m) != SYMLINE_OK) {
        return 0u;
    }
    /* one row of energies and one row of extrema */
    return symline_i_align_up((size_t)width * sizeof(uint32_t)) +
           symline_i_align_up((size_t)width) + (size_t)2u * SL_ALIGN;
}

/* Carves the energy and map rows; arguments already checked. */
static symline_status carve_rows(uint32_t width, void *ws, size_t ws_size, uint32_t **E,
                                 uint8_t **map)
{
    uint8_t *cur = (uint8_t *)ws;
    uint8_t *const end = cur + ws_size;
    *E = (uint32_t *)symline_i_carve(&cur, end, (size_t)width * sizeof(uint32_t));
    *map = (uint8_t *)symline_i_carve(&cur, end, width);
    return (*E == NULL || *map == NULL) ? SYMLINE_ERR_BUFFER : SYMLINE_OK;
}

/* counts[x] += 1 where the map has an S point; saturating (a lane loop). */
static void add_row(const uint8_t *map, uint32_t width, uint16_t *counts)
{
    uint32_t x;
    for (x = 0; x < width; x++) {
        const uint32_t c = counts[x] + (uint32_t)(map[x] == SYMLINE_MAP_S);
        counts[x] = (uint16_t)(c > 0xFFFFu ? 0xFFFFu : c);
    }
}

symline_status symline_histogram_row(const uint8_t *row, uint32_t width, uint32_t m,
                                     uint16_t *counts, void *ws, size_t ws_size)
{
    uint32_t *E;
    uint8_t *map;
    symline_status st;
    if (row == NULL || counts == NULL || ws == NULL) {
        return SYMLINE_ERR_NULL;
    }
    if (width == 0u || width > SYMLINE_MAX_DIM) {
        return SYMLINE_ERR_SIZE;
    }
    st = symline_i_check_radius(m);
    if (st != SYMLINE_OK) {
        return st;
    }
    if (ws_size < symline_histogram_workspace_size(width, m)) {
        return SYMLINE_ERR_BUFFER;
    }
    st = carve_rows(width, ws, ws_size, &E, &map);
    if (st != SYMLINE_OK) {
        return st;
    }
    (void)symline_energy_row(row, width, m, E);
    (void)symline_extrema_row(E, width, map);
    add_row(map, width, counts);
    return SYMLINE_OK;
}

symline_status symline_histogram(const symline_image *img, uint32_t m, uint16_t *counts,
                                 uint32_t counts_len, void *ws, size_t ws_size)
{
    uint32_t *E, x, y;
    uint8_t *map;
    symline_status st = symline_image_check(img);
    if (st != SYMLINE_OK) {
        return st;
    }
    if (counts == NULL || ws == NULL) {
        return SYMLINE_ERR_NULL;
    }
    st = symline_i_check_radius(m);
    if (st != SYMLINE_OK) {
        return st;
    }
    if (counts_len < img->width || ws_size < symline_histogram_workspace_size(img->width, m)) {
        return SYMLINE_ERR_BUFFER;
    }
    st = carve_rows(img->width, ws, ws_size, &E, &map);
    if (st != SYMLINE_OK) {
        return st;
    }
    for (x = 0; x < img->width; x++) {
        counts[x] = 0u;
    }
    for (y = 0; y < img->height; y++) {
        (void)symline_energy_row(img->data + (size_t)y * img->stride, img->width, m, E);
        (void)symline_extrema_row(E, img->width, map);
        add_row(map, img->width, counts);
    }
    return SYMLINE_OK;
}

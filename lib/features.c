/* SPDX-License-Identifier: Apache-2.0 */
/*
 * Symmetry feature points: S points of both extrema maps at one radius.
 *
 * The horizontal-axis S points come from the column-run follower, row by
 * row: pushing row t reports the extrema that row t completes, at rows t-1
 * and above (a plateau of equal energies down a column reports its middle
 * row late). For every reported S point the vertical-axis extrema of its row
 * are looked up; those are row-local, so a few recent rows are kept in a
 * small cache and any older row is recomputed from the frame. Nothing is
 * approximated: plateaus of any length are followed exactly.
 *
 * Late reports make the list slightly out of raster order; one heap sort at
 * the end (in place, no extra memory) puts it in order.
 */
#include "symline/features.h"

#include "symline/extrema.h"
#include "symline/symmetry.h"
#include "common.h"

/* Rows of vertical-axis extrema kept; almost every report is for row t-1 or t-2. */
#define SL_FEAT_ROWS 4u
#define SL_FEAT_NO_ROW 0xFFFFFFFFu

typedef struct vcache {
    const symline_image *img;
    uint32_t m;
    uint32_t *E;                /* one row of energies (scratch) */
    uint8_t *rows;              /* SL_FEAT_ROWS rows of extrema */
    uint32_t tag[SL_FEAT_ROWS]; /* which image row each slot holds */
} vcache;

size_t symline_features_workspace_size(uint32_t width, uint32_t height, uint32_t m)
{
    const size_t w = width;
    if (!symline_i_query_ok(width, height, SYMLINE_AXIS_HORIZONTAL, m)) {
        return 0u;
    }
    return symline_i_align_up(sizeof(vcache)) + symline_i_align_up(sizeof(symline_colrun)) +
           2u * symline_i_align_up(w * sizeof(uint32_t)) + symline_colrun_buffer_size(width) +
           symline_i_align_up(w * sizeof(symline_extremum)) + symline_i_align_up(w * SL_FEAT_ROWS) +
           (size_t)8u * SL_ALIGN;
}

uint32_t symline_features_max_points(uint32_t width, uint32_t height)
{
    uint64_t inner;
    if (width < 3u || height < 3u || width > SYMLINE_MAX_DIM || height > SYMLINE_MAX_DIM) {
        return 0u;
    }
    inner = (uint64_t)(width - 2u) * (height - 2u);
    return (uint32_t)((inner + 1u) / 2u);
}

/* The vertical-axis extrema of image row y. */
static const uint8_t *vrow(vcache *c, uint32_t y)
{
    const uint32_t slot = y % SL_FEAT_ROWS;
    const uint32_t w = c->img->width;
    uint8_t *map = c->rows + (size_t)slot * w;
    if (c->tag[slot] != y) {
        (void)symline_energy_row(c->img->data + (size_t)y * c->img->stride, w, c->m, c->E);
        (void)symline_extrema_row(c->E, w, map);
        c->tag[slot] = y;
    }
    return map;
}

static uint32_t key(const symline_point *p)
{
    return ((uint32_t)p->y << 16) | p->x;
}

/* Moves p[i] down the max-heap p[0..n-1]. */
static void sift_down(symline_point *p, uint32_t i, uint32_t n)
{
    for (;;) {
        uint32_t big = i;
        const uint32_t l = 2u * i + 1u;
        uint16_t tx, ty;
        if (l < n && key(&p[l]) > key(&p[big])) {
            big = l;
        }
        if (l + 1u < n && key(&p[l + 1u]) > key(&p[big])) {
            big = l + 1u;
        }
        if (big == i) {
            return;
        }
        /* field by field: a struct copy may become a memcpy call */
        tx = p[i].x;
        ty = p[i].y;
        p[i].x = p[big].x;
        p[i].y = p[big].y;
        p[big].x = tx;
        p[big].y = ty;
        i = big;
    }
}

/* Raster order; keys are distinct (each pixel is reported once). */
static void sort_points(symline_point *p, uint32_t n)
{
    uint32_t i;
    for (i = 1u; i < n && key(&p[i - 1u]) < key(&p[i]); i++) {
    }
    if (i >= n) {
        return; /* already in order: the common case without plateaus */
    }
    for (i = n / 2u; i-- > 0u;) {
        sift_down(p, i, n);
    }
    for (i = n; i-- > 1u;) {
        const uint16_t tx = p[0].x, ty = p[0].y;
        p[0].x = p[i].x;
        p[0].y = p[i].y;
        p[i].x = tx;
        p[i].y = ty;
        sift_down(p, 0u, i);
    }
}

symline_status symline_features(const symline_image *img, uint32_t m, void *ws, size_t ws_size,
                                symline_point *pts, uint32_t cap, uint32_t *count)
{
    uint8_t *cur, *end;
    uint32_t *E, y, n = 0u, k;
    vcache *vc;
    symline_colrun *cr;
    symline_extremum *ev;
    void *cr_buf;
    size_t cr_bytes;
    symline_status st = symline_image_check(img);
    if (st != SYMLINE_OK) {
        return st;
    }
    if (ws == NULL || count == NULL || (pts == NULL && cap != 0u)) {
        return SYMLINE_ERR_NULL;
    }
    st = symline_i_check_radius(m);
    if (st != SYMLINE_OK) {
        return st;
    }
    if (ws_size < symline_features_workspace_size(img->width, img->height, m)) {
        return SYMLINE_ERR_BUFFER;
    }
    cur = (uint8_t *)ws;
    end = cur + ws_size;
    cr_bytes = symline_colrun_buffer_size(img->width);
    vc = (vcache *)symline_i_carve(&cur, end, sizeof(vcache));
    cr = (symline_colrun *)symline_i_carve(&cur, end, sizeof(symline_colrun));
    E = (uint32_t *)symline_i_carve(&cur, end, (size_t)img->width * sizeof(uint32_t));
    cr_buf = symline_i_carve(&cur, end, cr_bytes);
    ev = (symline_extremum *)symline_i_carve(&cur, end,
                                             (size_t)img->width * sizeof(symline_extremum));
    if (vc == NULL || cr == NULL || E == NULL || cr_buf == NULL || ev == NULL) {
        return SYMLINE_ERR_BUFFER;
    }
    vc->img = img;
    vc->m = m;
    vc->E = (uint32_t *)symline_i_carve(&cur, end, (size_t)img->width * sizeof(uint32_t));
    vc->rows = (uint8_t *)symline_i_carve(&cur, end, (size_t)img->width * SL_FEAT_ROWS);
    if (vc->E == NULL || vc->rows == NULL ||
        symline_colrun_init(cr, img->width, cr_buf, cr_bytes) != SYMLINE_OK) {
        return SYMLINE_ERR_BUFFER;
    }
    for (k = 0; k < SL_FEAT_ROWS; k++) {
        vc->tag[k] = SL_FEAT_NO_ROW;
    }
    for (y = 0; y < img->height; y++) {
        uint32_t nev = 0u;
        (void)symline_energy_across_image(img, y, m, E);
        (void)symline_colrun_push(cr, E, ev, img->width, &nev);
        for (k = 0; k < nev; k++) {
            if (ev[k].kind != SYMLINE_MAP_S || vrow(vc, ev[k].y)[ev[k].x] != SYMLINE_MAP_S) {
                continue;
            }
            if (n < cap) {
                pts[n].x = ev[k].x;
                pts[n].y = ev[k].y;
                pts[n].fx = 0; /* feature points are whole pixels */
                pts[n].fy = 0;
            }
            n++;
        }
    }
    *count = n;
    if (n > cap) {
        return SYMLINE_ERR_BUFFER;
    }
    sort_points(pts, n);
    return SYMLINE_OK;
}

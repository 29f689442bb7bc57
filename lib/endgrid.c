/*
 * The merge's grid of segment ends (endgrid.h). Every entered segment slot
 * has two nodes (2 slot + 0 and 2 slot + 1), each in the list of the cell its
 * end point lies in; a merge moves a slot's nodes in constant time.
 */
#include "endgrid.h"

#include "common.h"
#include "fixed.h"
#include "segindex.h"

static uint32_t cells_across(uint32_t n)
{
    return ((n - 1u) >> SL_CELL_SHIFT) + 1u;
}

static uint32_t cell_of(int64_t v_q8, uint32_t n)
{
    uint64_t c;
    if (v_q8 < 0) {
        return 0u;
    }
    c = ((uint64_t)v_q8 >> 8) >> SL_CELL_SHIFT;
    return c < n ? (uint32_t)c : n - 1u;
}

int sl_endgrid_init(sl_endgrid *g, void *mem, size_t bytes, uint32_t width, uint32_t height,
                    uint32_t nseg)
{
    uint8_t *cur = (uint8_t *)mem, *const lim = (uint8_t *)mem + bytes;
    const uint32_t cells = cells_across(width) * cells_across(height);
    uint32_t c;
    g->cols = 0u;
    g->head = (uint32_t *)sl_carve(&cur, lim, (size_t)cells * sizeof(uint32_t));
    g->next = (uint32_t *)sl_carve(&cur, lim, (size_t)nseg * 2u * sizeof(uint32_t));
    g->prev = (uint32_t *)sl_carve(&cur, lim, (size_t)nseg * 2u * sizeof(uint32_t));
    if (g->head == NULL || g->next == NULL || g->prev == NULL) {
        return 0;
    }
    /* The rest holds the candidates of a query: at least 64 of them. */
    cur = (uint8_t *)sl_align_up((size_t)(uintptr_t)cur);
    if (cur >= lim || (size_t)(lim - cur) / sizeof(uint32_t) < 64u) {
        return 0;
    }
    g->cand = (uint32_t *)(void *)cur;
    g->cand_cap = (uint32_t)((size_t)(lim - cur) / sizeof(uint32_t) > 0xFFFFFFu
                                 ? 0xFFFFFFu
                                 : (size_t)(lim - cur) / sizeof(uint32_t));
    for (c = 0; c < cells; c++) {
        g->head[c] = SL_END_NONE;
    }
    g->cols = cells_across(width);
    g->rows = cells_across(height);
    return 1;
}

static void link_node(sl_endgrid *g, uint32_t node, int32_t x, int32_t y)
{
    const uint32_t c = cell_of(y, g->rows) * g->cols + cell_of(x, g->cols);
    g->prev[node] = SL_END_NONE;
    g->next[node] = g->head[c];
    if (g->head[c] != SL_END_NONE) {
        g->prev[g->head[c]] = node;
    }
    g->head[c] = node;
}

void sl_endgrid_add(sl_endgrid *g, const symline_segment *s, uint32_t slot)
{
    link_node(g, 2u * slot, s->x0, s->y0);
    link_node(g, 2u * slot + 1u, s->x1, s->y1);
}

/* Unlinks a node whose end point (x, y) has not moved since it was linked. */
static void unlink_node(sl_endgrid *g, uint32_t node, int32_t x, int32_t y)
{
    const uint32_t p = g->prev[node], n = g->next[node];
    if (n != SL_END_NONE) {
        g->prev[n] = p;
    }
    if (p != SL_END_NONE) {
        g->next[p] = n;
    } else {
        g->head[cell_of(y, g->rows) * g->cols + cell_of(x, g->cols)] = n;
    }
}

void sl_endgrid_remove(sl_endgrid *g, const symline_segment *s, uint32_t slot)
{
    unlink_node(g, 2u * slot, s->x0, s->y0);
    unlink_node(g, 2u * slot + 1u, s->x1, s->y1);
}

/* Sorts v[0..n-1] ascending (heap sort: no recursion, no extra memory). */
static void sort_u32(uint32_t *v, uint32_t n)
{
    uint32_t start = n / 2u, end = n;
    while (end > 1u) {
        uint32_t root, t;
        if (start > 0u) {
            start--;
        } else {
            end--;
            t = v[0];
            v[0] = v[end];
            v[end] = t;
        }
        root = start;
        for (;;) {
            uint32_t child = 2u * root + 1u;
            if (child >= end) {
                break;
            }
            if (child + 1u < end && v[child + 1u] > v[child]) {
                child++;
            }
            if (v[root] >= v[child]) {
                break;
            }
            t = v[root];
            v[root] = v[child];
            v[child] = t;
            root = child;
        }
    }
}

int32_t sl_endgrid_query(sl_endgrid *g, const symline_segment *a, int64_t ext, int32_t margin)
{
    const int64_t dx = (int64_t)a->x1 - a->x0, dy = (int64_t)a->y1 - a->y0;
    const int64_t len = (int64_t)sl_isqrt64((uint64_t)(dx * dx + dy * dy));
    int64_t ax = a->x0, ay = a->y0, bx = a->x1, by = a->y1, cheb, pieces, k;
    uint32_t n = 0u, i, w, px0 = 1u, px1 = 0u, py0 = 0u, py1 = 0u;
    if (len > 0) {
        ax -= dx * ext / len;
        ay -= dy * ext / len;
        bx += dx * ext / len;
        by += dy * ext / len;
    }
    cheb = (bx - ax < 0 ? ax - bx : bx - ax) > (by - ay < 0 ? ay - by : by - ay)
               ? (bx - ax < 0 ? ax - bx : bx - ax)
               : (by - ay < 0 ? ay - by : by - ay);
    pieces = (cheb >> (8u + SL_CELL_SHIFT)) + 1;
    for (k = 0; k < pieces; k++) {
        /* Piece k of the stretch, its box grown by margin, in cells. */
        const int64_t qx0 = ax + (bx - ax) * k / pieces, qy0 = ay + (by - ay) * k / pieces;
        const int64_t qx1 = ax + (bx - ax) * (k + 1) / pieces,
                      qy1 = ay + (by - ay) * (k + 1) / pieces;
        const uint32_t cx0 = cell_of((qx0 < qx1 ? qx0 : qx1) - margin, g->cols);
        const uint32_t cx1 = cell_of((qx0 > qx1 ? qx0 : qx1) + margin, g->cols);
        const uint32_t cy0 = cell_of((qy0 < qy1 ? qy0 : qy1) - margin, g->rows);
        const uint32_t cy1 = cell_of((qy0 > qy1 ? qy0 : qy1) + margin, g->rows);
        uint32_t cx, cy;
        for (cy = cy0; cy <= cy1; cy++) {
            for (cx = cx0; cx <= cx1; cx++) {
                uint32_t node;
                if (cx >= px0 && cx <= px1 && cy >= py0 && cy <= py1) {
                    continue; /* the previous piece's cells: seen */
                }
                for (node = g->head[cy * g->cols + cx]; node != SL_END_NONE; node = g->next[node]) {
                    if (n == g->cand_cap) {
                        return -1;
                    }
                    g->cand[n++] = node >> 1;
                }
            }
        }
        px0 = cx0;
        px1 = cx1;
        py0 = cy0;
        py1 = cy1;
    }
    sort_u32(g->cand, n);
    for (i = 0, w = 0; i < n; i++) {
        if (w == 0u || g->cand[w - 1u] != g->cand[i]) {
            g->cand[w++] = g->cand[i];
        }
    }
    return (int32_t)w;
}

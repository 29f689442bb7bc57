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

sl_endgrid *sl_endgrid_init(void *mem, size_t bytes, uint32_t width, uint32_t height, uint32_t nseg)
{
    uint8_t *cur = (uint8_t *)mem, *lim;
    const uint32_t cells = cells_across(width) * cells_across(height);
    sl_endgrid *g;
    uint32_t c;
    if (mem == NULL) {
        return NULL;
    }
    lim = cur + bytes;
    g = (sl_endgrid *)sl_carve(&cur, lim, sizeof(sl_endgrid));
    if (g == NULL) {
        return NULL;
    }
    g->head = (uint32_t *)sl_carve(&cur, lim, (size_t)cells * sizeof(uint32_t));
    g->next = (uint32_t *)sl_carve(&cur, lim, (size_t)nseg * 2u * sizeof(uint32_t));
    g->prev = (uint32_t *)sl_carve(&cur, lim, (size_t)nseg * 2u * sizeof(uint32_t));
    if (g->head == NULL || g->next == NULL || g->prev == NULL) {
        return NULL;
    }
    /* The rest holds the candidates of a query: at least 64 of them. */
    cur = (uint8_t *)sl_align_up((size_t)(uintptr_t)cur);
    if (cur >= lim || (size_t)(lim - cur) / sizeof(uint32_t) < 64u) {
        return NULL;
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
    return g;
}

static void link_node(sl_endgrid *g, uint32_t node, int32_t x, int32_t y)
{
    const uint32_t c = sl_cell_of(y, g->rows) * g->cols + sl_cell_of(x, g->cols);
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
        g->head[sl_cell_of(y, g->rows) * g->cols + sl_cell_of(x, g->cols)] = n;
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

int32_t sl_endgrid_query(sl_endgrid *g, const symline_segment *a, uint32_t ext, int32_t margin)
{
    const int32_t dx = a->x1 - a->x0, dy = a->y1 - a->y0;
    const uint32_t ux = (uint32_t)(dx < 0 ? -dx : dx), uy = (uint32_t)(dy < 0 ? -dy : dy);
    const uint32_t cheb = ux > uy ? ux : uy;
    /* Whole multiples of a's direction, at least ext long (ext + cheb < 2^26). */
    const int32_t k = cheb > 0u ? (int32_t)(ext / cheb + 1u) : 0;
    sl_cellwalk q;
    uint32_t i, w;
    q.cols = g->cols;
    q.rows = g->rows;
    q.mode = SL_WALK_GATHER;
    q.px0 = 1u;
    q.px1 = 0u;
    q.head = g->head;
    q.next = g->next;
    q.cand = g->cand;
    q.cand_cap = g->cand_cap;
    q.n = 0u;
    sl_cellwalk_chord(&q, a->x0 - dx * k, a->y0 - dy * k, a->x1 + dx * k, a->y1 + dy * k, margin);
    if (q.n > q.cand_cap) {
        return -1;
    }
    sort_u32(g->cand, q.n);
    for (i = 0, w = 0; i < q.n; i++) {
        if (w == 0u || g->cand[w - 1u] != g->cand[i]) {
            g->cand[w++] = g->cand[i];
        }
    }
    return (int32_t)w;
}

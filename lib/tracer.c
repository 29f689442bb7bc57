/* SPDX-License-Identifier: Apache-2.0 */
/*
 * The line tracer over a raster-ordered list of line points.
 *
 * The list with its per-row index is the only "image" the tracer sees: a
 * neighbour lookup is a binary search in one row, so no full-frame map is
 * ever needed. Visited points are marked in place (y = SL_VISITED); x stays,
 * so the rows remain sorted.
 *
 * Rules (the paper's, with what it leaves open made definite):
 *  - classification by the number of line points among the 8 neighbours:
 *    0 = type A (ignored), 1 = type B (end point), 2+ = type C (inside);
 *  - phase 0 starts at every unvisited B point, in raster order;
 *  - each step searches, relative to the last step direction d: d, then
 *    d+45, d-45, then d+90, d-90 degrees (counter-clockwise first in image
 *    coordinates, y down); the first unvisited line point is taken; a point
 *    is never visited twice; no candidate left ends the chain;
 *  - at a junction the chain therefore runs straight on when it can; a branch
 *    that arrives later stops next to the visited line (T), or, when it is
 *    traced first, turns into the crossing line; the segment stage cuts chains
 *    at sharp corners and merges collinear pieces again, so a T or X yields
 *    its straight lines whatever the tracing order;
 *  - phase 1 takes what phase 0 left (closed loops without an end point,
 *    rests behind junctions): it starts at the first unvisited point in raster
 *    order that has an unvisited neighbour, traces forward, then backward
 *    from the start, and joins the two halves.
 */
#include "tracer.h"

/* The x step of direction d (0: +x, 2: +y, 4: -x, 6: -y); its
 * y step is DX[(d + 6) & 7] (90 degrees on). */
static const int8_t DX[8] = {1, 1, 0, -1, -1, -1, 0, 1};

void symline_i_tracer_init(symline_i_tracer *t, symline_point *pts, uint32_t n,
                           const uint32_t *row_start, uint32_t h)
{
    t->pts = pts;
    t->n = n;
    t->row_start = row_start;
    t->h = h;
    t->scan = 0u;
    t->phase = 0u;
    t->row = t->up = t->down = 0u;
    if (h != 0u) {
        t->down = row_start[1];
    }
}

/* Index of the first point of row y (< h) at x or right of it. off: the
 * caller's own index within its row; rows of line points are alike from one
 * row to the next, so where speed counts the search gallops out from that
 * place in row y and bisects only the bracket it finds (same index). */
#if SL_FOR_SPEED /* in each caller, as the plain search was: no call per row */
#define SL_FIRST_AT_INLINE SL_ALWAYS_INLINE
#else
#define SL_FIRST_AT_INLINE
#endif
static SL_FIRST_AT_INLINE uint32_t first_at(const symline_i_tracer *t, int32_t x, uint32_t y,
                                            uint32_t off)
{
    uint32_t lo = t->row_start[y], hi = t->row_start[y + 1];
    if (SL_FOR_SPEED) {
        const uint32_t g = off < hi - lo ? lo + off : hi;
        uint32_t s = 1u;
        if (g < hi && (int32_t)t->pts[g].x < x) { /* answer right of g */
            lo = g + 1u;
            while (s < hi - g && (int32_t)t->pts[g + s].x < x) {
                lo = g + s + 1u;
                s *= 2u;
            }
            if (s < hi - g) {
                hi = g + s;
            }
        } else { /* answer at g or left of it */
            hi = g;
            while (s <= g - lo && (int32_t)t->pts[g - s].x >= x) {
                hi = g - s;
                s *= 2u;
            }
            if (s <= g - lo) {
                lo = g - s + 1u;
            }
        }
    }
    while (lo < hi) {
        const uint32_t mid = lo + (hi - lo) / 2u;
        if ((int32_t)t->pts[mid].x < x) {
            lo = mid + 1u;
        } else {
            hi = mid;
        }
    }
    return lo;
}

/* Index of point (nx, ny), a neighbour of (x, y), or -1 (also when out of
 * range: no point has an x of -1 or 65536). lb[ny - y + 1]: where row ny's
 * points from x - 1 on start, searched once per step and row (SL_NO_ROW
 * until then), not once per direction; where speed counts, carried over
 * from the last step (carry()). */
#define SL_NO_ROW 0xFFFFFFFFu
static int32_t find(const symline_i_tracer *t, uint32_t *lb, int32_t x, int32_t y, uint32_t off,
                    int32_t nx, int32_t ny)
{
    uint32_t *k = &lb[ny - y + 1], i;
    if ((uint32_t)ny >= t->h) { /* negatives wrap: out too */
        return -1;
    }
    if (*k == SL_NO_ROW) {
        *k = first_at(t, x - 1, (uint32_t)ny, off);
    }
    for (i = *k; i < t->row_start[ny + 1] && t->pts[i].x <= nx; i++) {
        if (t->pts[i].x == nx) {
            return (int32_t)i;
        }
    }
    return -1;
}

/* off: the point's index within its row, a guess for the searches. */
static uint32_t neighbours(const symline_i_tracer *t, uint32_t x, uint32_t y, uint32_t off)
{
    /* One search per row (rows hold each x once), not one per direction. */
    uint32_t r, i, c = 0u;
    for (r = y - 1u; r != y + 2u; r++) {
        for (i = r < t->h ? first_at(t, (int32_t)x - 1, r, off) : 0u;
             r < t->h && i < t->row_start[r + 1] && t->pts[i].x <= x + 1u; i++) {
            c += r != y || t->pts[i].x != x;
        }
    }
    return c;
}

uint32_t symline_i_neighbours(const symline_i_tracer *t, uint32_t x, uint32_t y)
{
    return neighbours(t, x, y, 0u);
}

/* The points of a row from *cur on at x - 1 .. x + 1 (up to end); *cur
 * moves to the first at x - 1 or right of it. */
static uint32_t count_near(const symline_point *pts, uint32_t *cur, uint32_t end, uint32_t x,
                           uint32_t *nb)
{
    uint32_t j = *cur, c = 0u;
    while (j < end && pts[j].x + 1u < x) {
        j++;
    }
    *cur = j;
    for (; j < end && pts[j].x <= x + 1u; j++) {
        c++;
        *nb = j;
    }
    return c;
}

/* neighbours() of the scan's point i at x, for the scan in raster order:
 * cursors into the rows above and below that only move right, as the scan
 * does, so that each row is read once as the row above and once as the row
 * below, instead of three searches per point. *nb: the index of the
 * neighbour when there is one. Only saves time (SL_FOR_SPEED). */
static uint32_t scan_neighbours(symline_i_tracer *t, uint32_t i, uint32_t x, uint32_t *nb)
{
    const uint32_t *rs = t->row_start;
    uint32_t row = t->row, c;
    while (rs[row + 1u] <= i) {
        row++;
    }
    if (row != t->row) {
        t->row = row;
        t->up = rs[row - 1u]; /* row > 0: a row before it ended */
        t->down = rs[row + 1u];
    }
    c = count_near(t->pts, &t->up, rs[row], x, nb) +
        count_near(t->pts, &t->down, row + 1u < t->h ? rs[row + 2u] : rs[row + 1u], x, nb);
    /* In its own row (each x once, sorted): the points right before and after it. */
    if (i > rs[row] && t->pts[i - 1u].x + 1u == x) {
        c++;
        *nb = i - 1u;
    }
    if (i + 1u < rs[row + 1u] && t->pts[i + 1u].x == x + 1u) {
        c++;
        *nb = i + 1u;
    }
    return c;
}

static bool unvisited(const symline_i_tracer *t, int32_t idx)
{
    return idx >= 0 && t->pts[idx].y != SL_VISITED;
}

static void visit(symline_i_tracer *t, int32_t idx)
{
    t->pts[idx].y = SL_VISITED;
}

/* The direction of a start point's first step: any, in direction order 0..7. */
#define SL_ANY_DIR 8u

/* The direction of the step by (dx, dy): DIR_OF[(dy + 1) * 3 + dx + 1]. */
static const uint8_t DIR_OF[9] = {5, 6, 7, 4, SL_ANY_DIR, 0, 3, 2, 1};

/* A step's directions relative to the last one: straight, 45-degree, then
 * 90-degree turns, counter-clockwise first (0, +1, -1, +2, -2). */
static const uint8_t TURN[5] = {0, 1, 7, 2, 6};

/* Where row y's points from x - 1 on start, for point `at` at (x, y) in it:
 * the point itself, or the one before it at x - 1. */
static uint32_t own_lb(const symline_i_tracer *t, uint32_t at, int32_t x, uint32_t y)
{
    return at > t->row_start[y] && (int32_t)t->pts[at - 1u].x + 1 == x ? at - 1u : at;
}

/* lb (find()) for the step from (nx, ny) (index at), from the step from
 * (x, y) just taken: the rows both steps see keep what was searched there,
 * moved by at most one point (each x once per row), the point's own row is
 * known, and only a new row is searched again, when a direction needs it. */
static void carry(const symline_i_tracer *t, uint32_t lb[3], int32_t x, int32_t y, int32_t nx,
                  int32_t ny, uint32_t at)
{
    uint32_t k, m[3];
    for (k = 0; k < 3u; k++) {
        const uint32_t from = k + (uint32_t)(ny - y); /* -1 wraps: a new row */
        const uint32_t row = (uint32_t)(ny - 1 + (int32_t)k);
        uint32_t v = from < 3u ? lb[from] : SL_NO_ROW;
        if (v != SL_NO_ROW && nx > x && v < t->row_start[row + 1u] &&
            (int32_t)t->pts[v].x == x - 1) {
            v++; /* from x - 1 on to from x on */
        } else if (v != SL_NO_ROW && nx < x && v > t->row_start[row] &&
                   (int32_t)t->pts[v - 1u].x == x - 2) {
            v--; /* from x - 1 on to from x - 2 on */
        }
        m[k] = v;
    }
    lb[0] = m[0];
    lb[1] = own_lb(t, at, nx, (uint32_t)ny);
    lb[2] = m[2];
}

/* Follows the line from (x, y) (index at), last step direction dir (or
 * SL_ANY_DIR); appends to dst from *pos. False when a start point
 * (SL_ANY_DIR) has no unvisited neighbour. */
static bool follow(symline_i_tracer *t, uint32_t at, int32_t x, int32_t y, uint32_t dir,
                   symline_point *dst, uint32_t cap, uint32_t *pos, bool *cut)
{
    bool moved = false;
    uint32_t lb[3];
    lb[0] = lb[1] = lb[2] = SL_NO_ROW; /* not an initialiser: no memcpy call */
    if (SL_FOR_SPEED) {
        lb[1] = own_lb(t, at, x, (uint32_t)y);
    }
    for (;;) {
        const uint32_t tries = dir == SL_ANY_DIR ? 8u : 5u;
        uint32_t o;
        if (dir != SL_ANY_DIR && *pos >= cap) {
            *cut = true;
            return true;
        }
        for (o = 0; o < tries; o++) {
            const uint32_t d = dir == SL_ANY_DIR ? o : (dir + TURN[o]) & 7u;
            const int32_t nx = x + DX[d], ny = y + DX[(d + 6u) & 7u];
            const int32_t idx = find(t, lb, x, y, SL_FOR_SPEED ? at - t->row_start[y] : 0u, nx, ny);
            if (unvisited(t, idx)) {
                if (*pos >= cap) {
                    *cut = true;
                    return true;
                }
                visit(t, idx);
                dst[*pos].x = (uint16_t)nx;
                dst[*pos].y = (uint16_t)ny;
                (*pos)++;
                if (SL_FOR_SPEED) {
                    carry(t, lb, x, y, nx, ny, (uint32_t)idx);
                } else {
                    lb[0] = lb[1] = lb[2] = SL_NO_ROW;
                }
                at = (uint32_t)idx;
                x = nx;
                y = ny;
                dir = d;
                break;
            }
        }
        if (o == tries) {
            return moved;
        }
        moved = true;
    }
}

void symline_i_reverse_points(symline_point *p, uint32_t n)
{
    uint32_t i, k;
    /* Byte by byte: a struct swap may become a libc memcpy call. */
    for (i = 0; i < n / 2u; i++) {
        uint8_t *a = (uint8_t *)&p[i], *b = (uint8_t *)&p[n - 1u - i];
        for (k = 0; k < sizeof(symline_point); k++) {
            const uint8_t v = a[k];
            a[k] = b[k];
            b[k] = v;
        }
    }
}

bool symline_i_tracer_next(symline_i_tracer *t, symline_point *dst, uint32_t cap, uint32_t *count,
                           bool *cut)
{
    *count = 0u;
    if (cap == 0u) {
        *cut = true;
        return false;
    }
    while (t->phase < 2u) {
        while (t->scan < t->n) {
            /* The scan moves past i either way (a chain from i has visited it). */
            const uint32_t i = t->scan++;
            const uint32_t x = t->pts[i].x, y = t->pts[i].y;
            uint32_t pos = 1u;
            if (y == SL_VISITED) {
                continue;
            }
            uint32_t nb = 0u;
            if (t->phase == 0u) {
                const uint32_t c =
                    SL_FOR_SPEED ? scan_neighbours(t, i, x, &nb) : symline_i_neighbours(t, x, y);
                if (c != 1u) {
                    if (c == 0u) {
                        /* Type A: no chain ever reaches it, phase 1 need not try it. */
                        visit(t, (int32_t)i);
                    }
                    continue;
                }
            }
            visit(t, (int32_t)i);
            if (SL_FOR_SPEED && t->phase == 0u && pos < cap) {
                /* A B point's first step goes to its one neighbour nb, which
                 * the count found: follow() from there, as its search in
                 * every direction would have. */
                const uint32_t nx = t->pts[nb].x, ny = t->pts[nb].y;
                if (ny == SL_VISITED) {
                    continue; /* nothing left to follow from here */
                }
                visit(t, (int32_t)nb);
                dst[1].x = (uint16_t)nx;
                dst[1].y = (uint16_t)ny;
                pos = 2u;
                (void)follow(t, nb, (int32_t)nx, (int32_t)ny,
                             DIR_OF[(ny + 1u - y) * 3u + nx + 1u - x], dst, cap, &pos, cut);
            } else if (!follow(t, i, (int32_t)x, (int32_t)y, SL_ANY_DIR, dst, cap, &pos, cut)) {
                continue; /* nothing left to follow from here: a lone rest of a traced line */
            }
            dst[0].x = (uint16_t)x;
            dst[0].y = (uint16_t)y;
            if (t->phase == 1u && pos < cap) {
                /* Started inside a line: trace the other half and put it in
                 * front (nothing there: both reversals undo each other). */
                const uint32_t fwd = pos;
                (void)follow(t, i, (int32_t)x, (int32_t)y, SL_ANY_DIR, dst, cap, &pos, cut);
                symline_i_reverse_points(dst, pos);
                symline_i_reverse_points(dst + (pos - fwd), fwd);
            }
            *count = pos;
            return true;
        }
        t->phase++;
        t->scan = 0u;
    }
    return false;
}

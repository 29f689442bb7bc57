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
 *
 * Where speed counts, one merge of neighbouring rows first writes each
 * point's neighbours into its sub-pixel fields, which the sub-pixel stage
 * only fills for the chains later (in their own storage, not the list's):
 * fx the 8-neighbour mask (bit d: a point in direction d), fy where row y+1's
 * points from x - 1 on start, relative to the point's own place in its row.
 * A count is then a bit test and a step an index sum, with a row search only
 * where the list does not say (the row above, rows far from alike).
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
    if (SL_FOR_SPEED) {
        t->left = n;
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
 * until then), not once per direction. The size builds' lookup (where speed
 * counts, follow_masks() reads the neighbour masks instead). */
#define SL_NO_ROW 0xFFFFFFFFu
static int32_t find(const symline_i_tracer *t, uint32_t *lb, int32_t x, int32_t y, int32_t nx,
                    int32_t ny)
{
    uint32_t *k = &lb[ny - y + 1], i;
    if ((uint32_t)ny >= t->h) { /* negatives wrap: out too */
        return -1;
    }
    if (*k == SL_NO_ROW) {
        *k = first_at(t, x - 1, (uint32_t)ny, 0u);
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

/* A step's directions relative to the last one: straight, 45-degree, then
 * 90-degree turns, counter-clockwise first (0, +1, -1, +2, -2). */
static const uint8_t TURN[5] = {0, 1, 7, 2, 6};

/* The neighbour mask in a point's fx (a character access: all 8 bits). */
static uint32_t mask_of(const symline_point *p)
{
    return *(const uint8_t *)&p->fx;
}

static void set_mask(symline_point *p, uint32_t m)
{
    *(uint8_t *)&p->fx = (uint8_t)m;
}

/* The neighbour count of a mask as phase 0 needs it: 0, 1, or 2 for more. */
static uint32_t mask_count(uint32_t m)
{
    return m == 0u ? 0u : (m & (m - 1u)) == 0u ? 1u : 2u;
}

/* fy when row y+1's start is not said (too far, or no row y+1). */
#define SL_FAR (-128)

/* x of point q of a row that ends at e, or above every x past the end. */
static uint32_t x_or_past(const symline_point *q, const symline_point *e)
{
    return q < e ? q->x : 0x20000u;
}

/* Writes every point's mask and row-below start (file comment), row by row:
 * rows y and y+1 merged once give row y its bits 1..3 and row y+1 its bits
 * 5..7 (the last row merges with nothing). A point left without neighbours
 * (type A) is marked visited here, as phase 0 would mark it when it came to
 * it: no chain ever reaches it. Returns their number. Once per pass, not
 * inlined. The merge keeps what it read in locals: a byte store may alias
 * anything. */
SL_NOINLINE static uint32_t index_rows(symline_point *p, const uint32_t *rs, uint32_t h)
{
    symline_point *q, *qs, *qe, *re;
    uint32_t y, a = 0u;
    if (h == 0u) {
        return 0u;
    }
    re = p + rs[h];
    for (q = p + rs[0]; q < re; q++) {
        set_mask(q, 0u);
    }
    /* Row y is [qs, qe), row y+1 [qe, re): each row's bounds read once. */
    for (y = 0, qs = p + rs[0], qe = p + rs[1]; y < h; y++, qs = qe, qe = re) {
        symline_point *r = qe;
        /* q - 1's x and mask (complete but for bit 0; none: not 0) */
        uint32_t xr, last = 0x10000u, mlast = 0x100u;
        int32_t dd = 0; /* r's place in row y+1 less q's in row y */
        re = y + 1u < h ? p + rs[y + 2u] : qe;
        if (qs == qe) {
            continue;
        }
        xr = x_or_past(r, re);
        for (q = qs; q < qe; q++, dd--) {
            const uint32_t x = q->x;
            uint32_t m = mask_of(q);
            if (last + 1u == x) { /* directions 4 and, from q - 1, 0 */
                m |= 0x10u;
                set_mask(q - 1, mlast | 0x01u);
            } else if (mlast == 0u) {
                q[-1].y = SL_VISITED;
                a++;
            }
            while (xr + 1u < x) {
                r++;
                dd++;
                xr = x_or_past(r, re);
            }
            if (xr <= x + 1u) { /* (only then is fy read) */
                symline_point *s = r;
                uint32_t xs = xr;
                q->fy = (int8_t)(dd > SL_FAR && dd < -SL_FAR ? dd : SL_FAR);
                do {
                    const uint32_t dx = xs + 1u - x;         /* 0, 1, 2: at x - 1, x, x + 1 */
                    m |= 0x08u >> dx;                        /* directions 3, 2, 1 */
                    set_mask(s, mask_of(s) | (0x80u >> dx)); /* seen from s: 7, 6, 5 */
                    s++;
                    xs = x_or_past(s, re);
                } while (xs <= x + 1u);
            }
            set_mask(q, m);
            last = x;
            mlast = m;
        }
        if (mlast == 0u) {
            qe[-1].y = SL_VISITED;
            a++;
        }
    }
    return a;
}

/* The number of set bits of a 3-bit value, from a table in a constant. */
#define SL_POP3(v) ((0xE994u >> (2u * (v))) & 3u)

/* Index of the neighbour in direction d (its bit set in the mask m) of
 * point `at` in row y. A row above, or one below that the list does not
 * place (SL_FAR), is searched from x - 1 on (*up keeps the row above's). */
static uint32_t neighbour_at(const symline_i_tracer *t, uint32_t at, uint32_t y, uint32_t m,
                             uint32_t d, uint32_t *up)
{
    const symline_point *const p = t->pts;
    const uint32_t *const rs = t->row_start;
    if ((d & 3u) == 0u) { /* 0 or 4: the next or the last point */
        return at + 1u - (d >> 1);
    }
    if (d < 4u) {
        const int32_t dd = (int32_t)p[at].fy;
        const uint32_t base = dd != SL_FAR ? (uint32_t)((int32_t)(rs[y + 1u] + (at - rs[y])) + dd)
                                           : first_at(t, (int32_t)p[at].x - 1, y + 1u, at - rs[y]);
        return base + SL_POP3(((m >> 1) & 7u) >> d); /* those left of it */
    }
    if (*up == SL_NO_ROW) {
        *up = first_at(t, (int32_t)p[at].x - 1, y - 1u, at - rs[y]);
    }
    return *up + SL_POP3((m >> 5) & ((1u << (d - 5u)) - 1u));
}

/* The directions a step tries, in order, 4 bits each, 8 added to the last:
 * after a step in direction d (TURN), and for a start (SL_ANY_DIR: 0..7). */
static const uint32_t TRIES[9] = {0xE2710u, 0xF3021u, 0x84132u, 0x95243u,   0xA6354u,
                                  0xB7465u, 0xC0576u, 0xD1607u, 0xF6543210u};

/* The first unvisited neighbour of point `at` in row y (mask m) in the
 * directions seq tries (TRIES), from its first on: its index times 16 plus
 * its direction (one value: no address of a local in the step); SL_ANY_DIR
 * when there is none. Apart from the step's own first try, which is almost
 * always the one taken (not inlined: a loop round the index sums would make
 * the step set up for them every time). */
SL_NOINLINE static uint64_t next_dir(const symline_i_tracer *t, uint32_t at, uint32_t y, uint32_t m,
                                     uint32_t seq)
{
    uint32_t up = SL_NO_ROW;
    for (;;) {
        const uint32_t d = seq & 7u;
        if (((m >> d) & 1u) != 0u) {
            const uint32_t idx = neighbour_at(t, at, y, m, d, &up);
            if (t->pts[idx].y != SL_VISITED) {
                return (uint64_t)idx << 4 | d;
            }
        }
        if ((seq & 8u) != 0u) {
            return SL_ANY_DIR;
        }
        seq >>= 4;
    }
}

/* The directions of TRIES[d] as a mask. */
static const uint8_t TRIED[9] = {0xC7u, 0x8Fu, 0x1Fu, 0x3Eu, 0x7Cu, 0xF8u, 0xF1u, 0xE3u, 0xFFu};

/* follow() where speed counts: the same steps, from the masks. */
static bool follow_masks(symline_i_tracer *t, uint32_t at, uint32_t y, uint32_t dir,
                         symline_point *dst, uint32_t cap, uint32_t *pos, bool *cut)
{
    symline_point *const pts = t->pts;
    uint32_t m = mask_of(&pts[at]), k = *pos;
    for (;;) {
        uint32_t seq = TRIES[dir], d, idx = 0u, up = SL_NO_ROW;
        if (dir != SL_ANY_DIR && k >= cap) {
            break; /* cut */
        }
        /* The first direction with a point, in the order of the tries. */
        if ((m & TRIED[dir]) == 0u) {
            d = SL_ANY_DIR; /* none: the chain's usual end */
        } else {
            while (((m >> (seq & 7u)) & 1u) == 0u) {
                seq >>= 4;
            }
            d = seq & 7u;
            idx = neighbour_at(t, at, y, m, d, &up);
            if (pts[idx].y == SL_VISITED) {
                const uint64_t next =
                    (seq & 8u) != 0u ? SL_ANY_DIR : next_dir(t, at, y, m, seq >> 4);
                d = (uint32_t)next & 15u;
                idx = (uint32_t)(next >> 4);
            }
        }
        if (d == SL_ANY_DIR) { /* no direction left */
            const bool moved = k != *pos;
            *pos = k;
            return moved;
        }
        if (k >= cap) {
            break; /* cut */
        }
        pts[idx].y = SL_VISITED;
        y = (uint32_t)((int32_t)y + DX[(d + 6u) & 7u]);
        dst[k].x = pts[idx].x;
        dst[k].y = (uint16_t)y;
        k++;
        at = idx;
        m = mask_of(&pts[idx]);
        dir = d;
    }
    *pos = k;
    *cut = true;
    return true;
}

/* Follows the line from (x, y) (index at), last step direction dir (or
 * SL_ANY_DIR); appends to dst from *pos. False when a start point
 * (SL_ANY_DIR) has no unvisited neighbour. */
static bool follow(symline_i_tracer *t, uint32_t at, int32_t x, int32_t y, uint32_t dir,
                   symline_point *dst, uint32_t cap, uint32_t *pos, bool *cut)
{
    bool moved = false;
    uint32_t lb[3];
    if (SL_FOR_SPEED) {
        return follow_masks(t, at, (uint32_t)y, dir, dst, cap, pos, cut);
    }
    lb[0] = lb[1] = lb[2] = SL_NO_ROW; /* not an initialiser: no memcpy call */
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
            const int32_t idx = find(t, lb, x, y, nx, ny);
            if (unvisited(t, idx)) {
                if (*pos >= cap) {
                    *cut = true;
                    return true;
                }
                visit(t, idx);
                dst[*pos].x = (uint16_t)nx;
                dst[*pos].y = (uint16_t)ny;
                (*pos)++;
                lb[0] = lb[1] = lb[2] = SL_NO_ROW;
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
    if (SL_FOR_SPEED && t->phase == 0u && t->scan == 0u && t->n != 0u) {
        /* Nothing visited yet: the first call, or one that got no room. */
        t->left -= index_rows(t->pts, t->row_start, t->h);
    }
    while (t->phase < 2u) {
        while (t->scan < t->n) {
            if (SL_FOR_SPEED) {
                /* Most points are visited by then: skipped in a loop of their
                 * own, and all of them once none is left (phase 1, often). */
                const symline_point *const p = t->pts;
                const uint32_t n = t->left != 0u ? t->n : 0u;
                uint32_t s = t->scan;
                while (s < n && p[s].y == SL_VISITED) {
                    s++;
                }
                t->scan = s;
                if (s >= n) {
                    break;
                }
            }
            /* The scan moves past i either way (a chain from i has visited it). */
            const uint32_t i = t->scan++;
            const uint32_t x = t->pts[i].x, y = t->pts[i].y;
            uint32_t pos = 1u;
            if (y == SL_VISITED) {
                continue;
            }
            if (t->phase == 0u) {
                const uint32_t c =
                    SL_FOR_SPEED ? mask_count(mask_of(&t->pts[i])) : symline_i_neighbours(t, x, y);
                if (c != 1u) {
                    if (c == 0u) {
                        /* Type A: no chain ever reaches it, phase 1 need not try it. */
                        visit(t, (int32_t)i);
                        if (SL_FOR_SPEED) {
                            t->left--;
                        }
                    }
                    continue;
                }
            }
            visit(t, (int32_t)i);
            if (SL_FOR_SPEED) {
                t->left--;
            }
            if (!follow(t, i, (int32_t)x, (int32_t)y, SL_ANY_DIR, dst, cap, &pos, cut)) {
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
            if (SL_FOR_SPEED) {
                t->left -= pos - 1u; /* the chain's points after its start */
            }
            *count = pos;
            return true;
        }
        t->phase++;
        t->scan = 0u;
    }
    return false;
}

/* SPDX-License-Identifier: Apache-2.0 */
/*
 * Polyline sets, sampling and an exact "within tolerance" query (uniform grid).
 */
#include "paths.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

static void *xrealloc(void *p, size_t n)
{
    void *q = realloc(p, n ? n : 1);
    if (q == NULL) {
        fputs("out of memory\n", stderr);
        exit(1);
    }
    return q;
}

void ev_paths_init(ev_paths *p)
{
    memset(p, 0, sizeof(*p));
}

void ev_paths_free(ev_paths *p)
{
    free(p->pts);
    free(p->start);
    free(p->tag);
    ev_paths_init(p);
}

void ev_paths_begin(ev_paths *p, int tag)
{
    if (p->npieces + 2 > p->cap_pieces) {
        p->cap_pieces = p->cap_pieces ? 2 * p->cap_pieces : 16;
        p->start = xrealloc(p->start, p->cap_pieces * sizeof(*p->start));
        p->tag = xrealloc(p->tag, p->cap_pieces * sizeof(*p->tag));
    }
    p->start[p->npieces] = p->npts;
    p->tag[p->npieces] = tag;
    p->npieces++;
    p->start[p->npieces] = p->npts;
}

void ev_paths_add(ev_paths *p, double x, double y)
{
    if (p->npieces == 0) {
        ev_paths_begin(p, EV_TAG_OTHER);
    }
    if (p->npts + 1 > p->cap_pts) {
        p->cap_pts = p->cap_pts ? 2 * p->cap_pts : 64;
        p->pts = xrealloc(p->pts, p->cap_pts * sizeof(*p->pts));
    }
    p->pts[p->npts].x = x;
    p->pts[p->npts].y = y;
    p->npts++;
    p->start[p->npieces] = p->npts;
}

void ev_paths_append(ev_paths *dst, const ev_paths *src)
{
    size_t i, k;
    for (i = 0; i < src->npieces; i++) {
        const ev_pt *q = ev_piece_pts(src, i);
        ev_paths_begin(dst, src->tag[i]);
        for (k = 0; k < ev_piece_len(src, i); k++) {
            ev_paths_add(dst, q[k].x, q[k].y);
        }
    }
}

size_t ev_piece_len(const ev_paths *p, size_t piece)
{
    return p->start[piece + 1] - p->start[piece];
}

const ev_pt *ev_piece_pts(const ev_paths *p, size_t piece)
{
    return p->pts + p->start[piece];
}

double ev_piece_length(const ev_paths *p, size_t piece)
{
    const ev_pt *q = ev_piece_pts(p, piece);
    size_t n = ev_piece_len(p, piece), k;
    double len = 0.0;
    for (k = 1; k < n; k++) {
        len += hypot(q[k].x - q[k - 1].x, q[k].y - q[k - 1].y);
    }
    return len;
}

/* The point at arc length s along a polyline of n points (cursor keeps the walk linear). */
static ev_pt point_at(const ev_pt *q, size_t n, double s, size_t *seg, double *seg_s0)
{
    ev_pt r;
    while (*seg + 2 < n) {
        double l = hypot(q[*seg + 1].x - q[*seg].x, q[*seg + 1].y - q[*seg].y);
        if (s <= *seg_s0 + l) {
            break;
        }
        *seg_s0 += l;
        (*seg)++;
    }
    {
        const ev_pt a = q[*seg], b = q[*seg + 1];
        double l = hypot(b.x - a.x, b.y - a.y);
        double t = l > 0.0 ? (s - *seg_s0) / l : 0.0;
        if (t < 0.0) {
            t = 0.0;
        }
        if (t > 1.0) {
            t = 1.0;
        }
        r.x = a.x + t * (b.x - a.x);
        r.y = a.y + t * (b.y - a.y);
    }
    return r;
}

size_t ev_sample(const ev_paths *p, double step, ev_pt **out, size_t **piece_of)
{
    size_t i, total = 0, cap = 0;
    ev_pt *s = NULL;
    size_t *pi = NULL;
    for (i = 0; i < p->npieces; i++) {
        const ev_pt *q = ev_piece_pts(p, i);
        size_t n = ev_piece_len(p, i), k, m, seg = 0;
        double len, s0 = 0.0;
        if (n == 0) {
            continue;
        }
        len = ev_piece_length(p, i);
        m = (n == 1 || len <= 0.0) ? 1 : (size_t)ceil(len / step - 1e-9) + 1;
        if (total + m > cap) {
            cap = (total + m) * 2;
            s = xrealloc(s, cap * sizeof(*s));
            pi = xrealloc(pi, cap * sizeof(*pi));
        }
        for (k = 0; k < m; k++) {
            if (m == 1) {
                s[total] = q[0];
            } else if (k == m - 1) {
                s[total] = q[n - 1];
            } else {
                s[total] = point_at(q, n, len * (double)k / (double)(m - 1), &seg, &s0);
            }
            pi[total] = i;
            total++;
        }
    }
    *out = s;
    if (piece_of != NULL) {
        *piece_of = pi;
    } else {
        free(pi);
    }
    return total;
}

double ev_dist_point_seg(ev_pt q, ev_pt a, ev_pt b)
{
    double dx = b.x - a.x, dy = b.y - a.y;
    double l2 = dx * dx + dy * dy, t = 0.0;
    if (l2 > 0.0) {
        t = ((q.x - a.x) * dx + (q.y - a.y) * dy) / l2;
        if (t < 0.0) {
            t = 0.0;
        } else if (t > 1.0) {
            t = 1.0;
        }
    }
    return hypot(q.x - (a.x + t * dx), q.y - (a.y + t * dy));
}

static int clampi(int v, int lo, int hi)
{
    return v < lo ? lo : (v > hi ? hi : v);
}

static int cell_of(double v, double v0, double cell, int n)
{
    double c = floor((v - v0) / cell);
    if (c < 0.0) {
        return 0;
    }
    if (c > (double)(n - 1)) {
        return n - 1;
    }
    return (int)c;
}

/* Calls fn for every segment of the path set. */
static size_t for_segments(const ev_paths *p, ev_seg *out)
{
    size_t i, k, n = 0;
    for (i = 0; i < p->npieces; i++) {
        size_t len = ev_piece_len(p, i), s = p->start[i];
        if (len == 1) {
            if (out) {
                out[n].a = out[n].b = s;
                out[n].piece = i;
            }
            n++;
        }
        for (k = 0; k + 1 < len; k++) {
            if (out) {
                out[n].a = s + k;
                out[n].b = s + k + 1;
                out[n].piece = i;
            }
            n++;
        }
    }
    return n;
}

static void seg_cells(const ev_index *ix, const ev_seg *sg, int *cx0, int *cy0, int *cx1, int *cy1)
{
    const ev_pt a = ix->paths->pts[sg->a], b = ix->paths->pts[sg->b];
    double lx = fmin(a.x, b.x) - ix->tol, hx = fmax(a.x, b.x) + ix->tol;
    double ly = fmin(a.y, b.y) - ix->tol, hy = fmax(a.y, b.y) + ix->tol;
    *cx0 = cell_of(lx, ix->x0, ix->cell, ix->nx);
    *cx1 = cell_of(hx, ix->x0, ix->cell, ix->nx);
    *cy0 = cell_of(ly, ix->y0, ix->cell, ix->ny);
    *cy1 = cell_of(hy, ix->y0, ix->cell, ix->ny);
}

void ev_index_build(ev_index *ix, const ev_paths *p, double tol)
{
    size_t nseg = for_segments(p, NULL), i, *fill;
    ev_seg *segs = xrealloc(NULL, nseg * sizeof(*segs));
    double lx = 0.0, ly = 0.0, hx = 1.0, hy = 1.0;
    int cx, cy, cx0, cy0, cx1, cy1;
    memset(ix, 0, sizeof(*ix));
    ix->paths = p;
    ix->tol = tol;
    for_segments(p, segs);
    for (i = 0; i < p->npts; i++) {
        if (i == 0 || p->pts[i].x < lx) {
            lx = p->pts[i].x;
        }
        if (i == 0 || p->pts[i].x > hx) {
            hx = p->pts[i].x;
        }
        if (i == 0 || p->pts[i].y < ly) {
            ly = p->pts[i].y;
        }
        if (i == 0 || p->pts[i].y > hy) {
            hy = p->pts[i].y;
        }
    }
    /* Cells of about the tolerance keep both the lists and the scans short. */
    ix->cell = tol > 4.0 ? tol : 4.0;
    ix->x0 = lx - tol;
    ix->y0 = ly - tol;
    ix->nx = clampi((int)((hx - lx + 2.0 * tol) / ix->cell) + 1, 1, 4096);
    ix->ny = clampi((int)((hy - ly + 2.0 * tol) / ix->cell) + 1, 1, 4096);
    ix->cell_start = xrealloc(NULL, ((size_t)ix->nx * (size_t)ix->ny + 1) * sizeof(size_t));
    memset(ix->cell_start, 0, ((size_t)ix->nx * (size_t)ix->ny + 1) * sizeof(size_t));
    for (i = 0; i < nseg; i++) {
        seg_cells(ix, &segs[i], &cx0, &cy0, &cx1, &cy1);
        for (cy = cy0; cy <= cy1; cy++) {
            for (cx = cx0; cx <= cx1; cx++) {
                ix->cell_start[(size_t)cy * (size_t)ix->nx + (size_t)cx + 1]++;
            }
        }
    }
    for (i = 1; i <= (size_t)ix->nx * (size_t)ix->ny; i++) {
        ix->cell_start[i] += ix->cell_start[i - 1];
    }
    ix->items = xrealloc(NULL, ix->cell_start[(size_t)ix->nx * (size_t)ix->ny] * sizeof(ev_seg));
    fill = xrealloc(NULL, (size_t)ix->nx * (size_t)ix->ny * sizeof(size_t));
    memcpy(fill, ix->cell_start, (size_t)ix->nx * (size_t)ix->ny * sizeof(size_t));
    for (i = 0; i < nseg; i++) {
        seg_cells(ix, &segs[i], &cx0, &cy0, &cx1, &cy1);
        for (cy = cy0; cy <= cy1; cy++) {
            for (cx = cx0; cx <= cx1; cx++) {
                ix->items[fill[(size_t)cy * (size_t)ix->nx + (size_t)cx]++] = segs[i];
            }
        }
    }
    free(fill);
    free(segs);
}

void ev_index_free(ev_index *ix)
{
    free(ix->cell_start);
    free(ix->items);
    memset(ix, 0, sizeof(*ix));
}

/* The nearest segment within tol: its distance (-1 when none); *tag_out its piece's
   tag; with stop_at_first, the first segment found within tol instead. */
static double index_scan(const ev_index *ix, ev_pt q, int *tag_out, int stop_at_first)
{
    size_t c, k;
    double best = -1.0;
    if (ix->paths == NULL || ix->paths->npts == 0) {
        return -1.0;
    }
    /* Clamping is monotone, so a point outside the grid still meets every segment near it. */
    c = (size_t)cell_of(q.y, ix->y0, ix->cell, ix->ny) * (size_t)ix->nx +
        (size_t)cell_of(q.x, ix->x0, ix->cell, ix->nx);
    for (k = ix->cell_start[c]; k < ix->cell_start[c + 1]; k++) {
        const ev_seg *sg = &ix->items[k];
        double d = ev_dist_point_seg(q, ix->paths->pts[sg->a], ix->paths->pts[sg->b]);
        if (d <= ix->tol && (best < 0.0 || d < best)) {
            best = d;
            if (tag_out != NULL) {
                *tag_out = ix->paths->tag[sg->piece];
            }
            if (stop_at_first) {
                break;
            }
        }
    }
    return best;
}

int ev_index_near(const ev_index *ix, ev_pt q, int *tag_out)
{
    return index_scan(ix, q, tag_out, tag_out == NULL) >= 0.0;
}

double ev_index_dist(const ev_index *ix, ev_pt q)
{
    return index_scan(ix, q, NULL, 0);
}

double ev_dist_piece(const ev_paths *p, size_t piece, ev_pt q)
{
    const ev_pt *v = ev_piece_pts(p, piece);
    size_t n = ev_piece_len(p, piece), k;
    double best = n ? ev_dist_point_seg(q, v[0], v[0]) : -1.0;
    for (k = 0; k + 1 < n; k++) {
        double d = ev_dist_point_seg(q, v[k], v[k + 1]);
        if (d < best) {
            best = d;
        }
    }
    return best;
}

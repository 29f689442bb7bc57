/* SPDX-License-Identifier: Apache-2.0 */
/*
 * Exact ground truth: every field centre line (and the centre circle) is walked
 * in small steps (0.2 px in the image), each point classified as hidden (behind
 * the camera, outside the image, behind a cylinder), don't-care (painted width
 * in the image under 1 px or over width/16 px) or required; the borders between
 * classes are found by bisection.
 */
#include <math.h>
#include <stdlib.h>

#include "render.h"

#ifndef M_PI
#define M_PI 3.14159265358979323846
#endif

enum { ST_HIDDEN = 0, ST_DONTCARE = 1, ST_REQUIRED = 2 };

/* A field curve: straight segment i (0..RD_NSEG-1) or the circle (RD_NSEG); param in metres or radians. */
typedef struct curve {
    int id;
    double x0, y0, dx, dy; /* unit direction for straight segments */
    double len;            /* parameter range: [0, len] */
} curve;

static void curve_at(const curve *c, double s, rd_vec *p, double *tx, double *ty)
{
    if (c->id == RD_NSEG) {
        p->x = RD_CIRCLE_R * cos(s);
        p->y = RD_CIRCLE_R * sin(s);
        *tx = -sin(s);
        *ty = cos(s);
    } else {
        p->x = c->x0 + s * c->dx;
        p->y = c->y0 + s * c->dy;
        *tx = c->dx;
        *ty = c->dy;
    }
    p->z = 0.0;
}

/* Metres of field per unit of parameter. */
static double metres_per_param(const curve *c)
{
    return c->id == RD_NSEG ? RD_CIRCLE_R : 1.0;
}

static int classify(const rd_scene *s, const curve *c, double t, double *u, double *v)
{
    const rd_camera *cam = &s->cam;
    rd_vec p, a, b, q0, q1, dir;
    double tx, ty, ua, va, ub, vb, u0, v0, u1, v1, tl, ex, ey, w;
    curve_at(c, t, &p, &tx, &ty);
    if (!rd_project(cam, p, u, v)) {
        return ST_HIDDEN;
    }
    if (*u < 0.0 || *v < 0.0 || *u > cam->width - 1 || *v > cam->height - 1) {
        return ST_HIDDEN;
    }
    dir.x = p.x - cam->pos.x;
    dir.y = p.y - cam->pos.y;
    dir.z = p.z - cam->pos.z;
    if (rd_hit_cylinders(s, cam->pos, dir, 1.0 - 1e-9, NULL) > 0.0) {
        return ST_HIDDEN;
    }
    /* Painted width across the line's image direction. */
    a = p;
    b = p;
    a.x -= RD_LINE_HALF * ty;
    a.y += RD_LINE_HALF * tx;
    b.x += RD_LINE_HALF * ty;
    b.y -= RD_LINE_HALF * tx;
    q0 = p;
    q1 = p;
    q0.x -= 1e-4 * tx;
    q0.y -= 1e-4 * ty;
    q1.x += 1e-4 * tx;
    q1.y += 1e-4 * ty;
    if (!rd_project(cam, a, &ua, &va) || !rd_project(cam, b, &ub, &vb) ||
        !rd_project(cam, q0, &u0, &v0) || !rd_project(cam, q1, &u1, &v1)) {
        return ST_DONTCARE;
    }
    tl = hypot(u1 - u0, v1 - v0);
    if (tl <= 0.0) {
        return ST_DONTCARE;
    }
    ex = (u1 - u0) / tl;
    ey = (v1 - v0) / tl;
    w = fabs((ub - ua) * ey - (vb - va) * ex);
    if (w < 1.0 || w > (double)cam->width / 16.0) {
        return ST_DONTCARE;
    }
    return ST_REQUIRED;
}

/* Parameter step that moves about 0.2 px in the image here. */
static double step_at(const rd_scene *s, const curve *c, double t)
{
    rd_vec p, q;
    double tx, ty, u0, v0, u1, v1, d = 1e-5 / metres_per_param(c);
    double maxstep = 0.01 / metres_per_param(c), minstep = 1e-6 / metres_per_param(c), step;
    curve_at(c, t, &p, &tx, &ty);
    curve_at(c, t + d, &q, &tx, &ty);
    if (!rd_project(&s->cam, p, &u0, &v0) || !rd_project(&s->cam, q, &u1, &v1)) {
        return maxstep;
    }
    step = 0.2 * d / fmax(hypot(u1 - u0, v1 - v0), 1e-12);
    return step < minstep ? minstep : (step > maxstep ? maxstep : step);
}

typedef struct sample {
    double t, u, v;
    int st;
} sample;

typedef struct walk {
    sample *a;
    size_t n, cap;
} walk;

static void push(walk *w, double t, double u, double v, int st)
{
    if (w->n == w->cap) {
        w->cap = w->cap ? 2 * w->cap : 1024;
        w->a = realloc(w->a, w->cap * sizeof(sample));
        if (w->a == NULL) {
            abort();
        }
    }
    w->a[w->n].t = t;
    w->a[w->n].u = u;
    w->a[w->n].v = v;
    w->a[w->n].st = st;
    w->n++;
}

/* Walks [t0, t1]; every class change gets the exact border on both sides. */
static void walk_curve(const rd_scene *s, const curve *c, double t0, double t1, walk *w)
{
    double t = t0, u, v;
    int st = classify(s, c, t, &u, &v);
    push(w, t, u, v, st);
    while (t < t1) {
        double tn = t + step_at(s, c, t), un, vn;
        int sn;
        if (tn > t1) {
            tn = t1;
        }
        sn = classify(s, c, tn, &un, &vn);
        if (sn != st) {
            double lo = t, hi = tn, ul, vl, uh, vh;
            int k;
            for (k = 0; k < 48; k++) {
                double mid = 0.5 * (lo + hi), um, vm;
                if (classify(s, c, mid, &um, &vm) == st) {
                    lo = mid;
                } else {
                    hi = mid;
                }
            }
            classify(s, c, lo, &ul, &vl);
            push(w, lo, ul, vl, st);
            /* The far side may be a third class over a tiny interval: take it as it is. */
            sn = classify(s, c, hi, &uh, &vh);
            push(w, hi, uh, vh, sn);
            st = sn;
            t = hi;
            continue;
        }
        push(w, tn, un, vn, sn);
        t = tn;
    }
}

static double clampd(double v, double hi)
{
    return v < 0.0 ? 0.0 : (v > hi ? hi : v);
}

/* Emits the runs of one walk: required straight runs as segments, circle runs as
   polylines (~1 px apart), don't-care runs as one segment or short chords. */
static void emit_runs(const rd_scene *s, const walk *w, int circle, ev_paths *lines, ev_paths *arcs,
                      ev_paths *dontcare)
{
    const double wmax = s->cam.width - 1, hmax = s->cam.height - 1;
    size_t i = 0;
    while (i < w->n) {
        size_t j = i;
        int st = w->a[i].st;
        while (j + 1 < w->n && w->a[j + 1].st == st) {
            j++;
        }
        if (st != ST_HIDDEN && j > i) {
            const sample *a = &w->a[i], *b = &w->a[j];
            if (!circle) {
                ev_paths *dst = st == ST_REQUIRED ? lines : dontcare;
                ev_paths_begin(dst, EV_TAG_LINE);
                ev_paths_add(dst, clampd(a->u, wmax), clampd(a->v, hmax));
                ev_paths_add(dst, clampd(b->u, wmax), clampd(b->v, hmax));
            } else {
                double spacing = st == ST_REQUIRED ? 1.0 : 2.0;
                double lu = a->u, lv = a->v;
                size_t k;
                if (st == ST_REQUIRED) {
                    ev_paths_begin(arcs, EV_TAG_CURVE);
                    ev_paths_add(arcs, clampd(a->u, wmax), clampd(a->v, hmax));
                }
                for (k = i + 1; k <= j; k++) {
                    const sample *q = &w->a[k];
                    if (k == j || hypot(q->u - lu, q->v - lv) >= spacing) {
                        if (st == ST_REQUIRED) {
                            ev_paths_add(arcs, clampd(q->u, wmax), clampd(q->v, hmax));
                        } else {
                            ev_paths_begin(dontcare, EV_TAG_CURVE);
                            ev_paths_add(dontcare, clampd(lu, wmax), clampd(lv, hmax));
                            ev_paths_add(dontcare, clampd(q->u, wmax), clampd(q->v, hmax));
                        }
                        lu = q->u;
                        lv = q->v;
                    }
                }
            }
        }
        i = j + 1;
    }
}

/* Keeps the part of [*t0, *t1] where a + b*t >= 0. */
static void clip_affine(double a, double b, double *t0, double *t1)
{
    if (b == 0.0) {
        if (a < 0.0) {
            *t1 = *t0 - 1.0;
        }
    } else if (b > 0.0) {
        *t0 = fmax(*t0, -a / b);
    } else {
        *t1 = fmin(*t1, -a / b);
    }
}

/* The parameter interval of a straight field line that projects into the image (in
   front of the camera): the frustum is convex, so it is one interval; every bound is
   affine in the parameter. Empty when *t0 > *t1. */
static void frustum_interval(const rd_camera *cam, const curve *c, double *t0, double *t1)
{
    /* d(t) = P(t) - pos = d0 + t*dd; camera coordinates are dot products with the axes. */
    double d0x = c->x0 - cam->pos.x, d0y = c->y0 - cam->pos.y, d0z = -cam->pos.z;
    double z0 = d0x * cam->fwd.x + d0y * cam->fwd.y + d0z * cam->fwd.z;
    double zb = c->dx * cam->fwd.x + c->dy * cam->fwd.y;
    double x0 = d0x * cam->right.x + d0y * cam->right.y + d0z * cam->right.z;
    double xb = c->dx * cam->right.x + c->dy * cam->right.y;
    double y0 = d0x * cam->down.x + d0y * cam->down.y + d0z * cam->down.z;
    double yb = c->dx * cam->down.x + c->dy * cam->down.y;
    double umax = cam->width - 1 - cam->cx, vmax = cam->height - 1 - cam->cy;
    clip_affine(z0 - 1e-6, zb, t0, t1);                                 /* in front */
    clip_affine(cam->cx * z0 + cam->f * x0, cam->cx * zb + cam->f * xb, t0, t1); /* u >= 0 */
    clip_affine(umax * z0 - cam->f * x0, umax * zb - cam->f * xb, t0, t1);       /* u <= W-1 */
    clip_affine(cam->cy * z0 + cam->f * y0, cam->cy * zb + cam->f * yb, t0, t1); /* v >= 0 */
    clip_affine(vmax * z0 - cam->f * y0, vmax * zb - cam->f * yb, t0, t1);       /* v <= H-1 */
}

void rd_ground_truth(const rd_scene *s, ev_paths *lines, ev_paths *arcs, ev_paths *dontcare)
{
    walk w = {NULL, 0, 0};
    curve c;
    int i;
    for (i = 0; i < RD_NSEG; i++) {
        double x1, y1;
        c.id = i;
        rd_field_segment(i, &c.x0, &c.y0, &x1, &y1);
        c.len = hypot(x1 - c.x0, y1 - c.y0);
        c.dx = (x1 - c.x0) / c.len;
        c.dy = (y1 - c.y0) / c.len;
        {
            /* Only the part in the image can be visible: walk just that. */
            double t0 = 0.0, t1 = c.len;
            frustum_interval(&s->cam, &c, &t0, &t1);
            if (t0 >= t1) {
                continue;
            }
            w.n = 0;
            walk_curve(s, &c, t0, t1, &w);
            emit_runs(s, &w, 0, lines, arcs, dontcare);
        }
    }
    /* The circle is closed: start the walk at a class border so no run wraps around. */
    c.id = RD_NSEG;
    c.x0 = c.y0 = c.dx = c.dy = 0.0;
    c.len = 2.0 * M_PI;
    {
        const int n = 7200;
        double u, v, start = 0.0;
        int k, prev = classify(s, &c, -2.0 * M_PI / n, &u, &v), found = 0;
        for (k = 0; k < n && !found; k++) {
            double t = 2.0 * M_PI * k / n;
            int st = classify(s, &c, t, &u, &v);
            if (st != prev) {
                double lo = t - 2.0 * M_PI / n, hi = t;
                int it;
                for (it = 0; it < 48; it++) {
                    double mid = 0.5 * (lo + hi);
                    if (classify(s, &c, mid, &u, &v) == prev) {
                        lo = mid;
                    } else {
                        hi = mid;
                    }
                }
                start = hi;
                found = 1;
            }
            prev = st;
        }
        w.n = 0;
        if (found) {
            walk_curve(s, &c, start, start + 2.0 * M_PI - 1e-12, &w);
            emit_runs(s, &w, 1, lines, arcs, dontcare);
        } else {
            /* One class all round: a closed polyline when required. */
            walk_curve(s, &c, 0.0, 2.0 * M_PI, &w);
            emit_runs(s, &w, 1, lines, arcs, dontcare);
        }
    }
    free(w.a);
}

double rd_visible_length(const rd_scene *s)
{
    ev_paths l, a, dc;
    double len = 0.0;
    size_t i;
    ev_paths_init(&l);
    ev_paths_init(&a);
    ev_paths_init(&dc);
    rd_ground_truth(s, &l, &a, &dc);
    for (i = 0; i < l.npieces; i++) {
        len += ev_piece_length(&l, i);
    }
    for (i = 0; i < a.npieces; i++) {
        len += ev_piece_length(&a, i);
    }
    ev_paths_free(&l);
    ev_paths_free(&a);
    ev_paths_free(&dc);
    return len;
}

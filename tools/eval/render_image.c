/* SPDX-License-Identifier: Apache-2.0 */
/*
 * Image synthesis: every pixel averages 4x4 rays, each intersected exactly with
 * the ground, the walls and the cylinders; painted lines are tested in field
 * coordinates, so the image agrees with the projected ground truth. Then
 * illumination (gradient, vignetting, bright spot), blur, exposure, noise.
 */
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "render.h"

#define SS 4 /* supersamples per pixel along each axis */

/* Smooth value noise in [-1, 1] on an integer lattice, hashed from the seed. */
static double lattice(int64_t ix, int64_t iy, uint64_t seed)
{
    uint64_t h = seed ^ ((uint64_t)ix * 0x9E3779B97F4A7C15ull) ^ ((uint64_t)iy * 0xC2B2AE3D27D4EB4Full);
    uint64_t st = h;
    return (double)(rd_rand_u64(&st) >> 11) * (2.0 / 9007199254740992.0) - 1.0;
}

static double vnoise(double x, double y, uint64_t seed)
{
    double fx = floor(x), fy = floor(y);
    double tx = x - fx, ty = y - fy;
    int64_t ix = (int64_t)fx, iy = (int64_t)fy;
    double a = lattice(ix, iy, seed), b = lattice(ix + 1, iy, seed);
    double c = lattice(ix, iy + 1, seed), d = lattice(ix + 1, iy + 1, seed);
    tx = tx * tx * (3.0 - 2.0 * tx);
    ty = ty * ty * (3.0 - 2.0 * ty);
    return (a + (b - a) * tx) * (1.0 - ty) + (c + (d - c) * tx) * ty;
}

/* 1 when field point (X, Y) is painted (5 cm lines with square ends, centre circle). */
static int painted(double X, double Y)
{
    int i;
    double r;
    /* Every line lies within the touch and goal lines' outer edges. */
    if (fabs(X) > 4.5 + RD_LINE_HALF || fabs(Y) > 3.0 + RD_LINE_HALF) {
        return 0;
    }
    r = hypot(X, Y);
    if (fabs(r - RD_CIRCLE_R) <= RD_LINE_HALF) {
        return 1;
    }
    for (i = 0; i < RD_NSEG; i++) {
        double x0, y0, x1, y1, dx, dy, len, t, d;
        rd_field_segment(i, &x0, &y0, &x1, &y1);
        /* Cheap reject: outside the segment's box grown by half a line width. */
        if (X < fmin(x0, x1) - RD_LINE_HALF || X > fmax(x0, x1) + RD_LINE_HALF ||
            Y < fmin(y0, y1) - RD_LINE_HALF || Y > fmax(y0, y1) + RD_LINE_HALF) {
            continue;
        }
        dx = x1 - x0;
        dy = y1 - y0;
        len = hypot(dx, dy);
        t = ((X - x0) * dx + (Y - y0) * dy) / len;
        d = fabs((X - x0) * dy - (Y - y0) * dx) / len;
        if (d <= RD_LINE_HALF && t >= -RD_LINE_HALF && t <= len + RD_LINE_HALF) {
            return 1;
        }
    }
    return 0;
}

/* Radiance (albedo times shading) seen along one ray; *label gets the surface (RD_LABEL_*). */
static double trace(const rd_scene *s, rd_vec dir, int *label)
{
    const rd_vec p = s->cam.pos;
    double tg = dir.z < 0.0 ? -p.z / dir.z : HUGE_VAL;
    double tw = HUGE_VAL, t;
    int which = -1;
    double tc;
    if (dir.x > 0.0) {
        tw = fmin(tw, (s->wall_x - p.x) / dir.x);
    } else if (dir.x < 0.0) {
        tw = fmin(tw, (-s->wall_x - p.x) / dir.x);
    }
    if (dir.y > 0.0) {
        tw = fmin(tw, (s->wall_y - p.y) / dir.y);
    } else if (dir.y < 0.0) {
        tw = fmin(tw, (-s->wall_y - p.y) / dir.y);
    }
    t = fmin(tg, tw);
    tc = rd_hit_cylinders(s, p, dir, t, &which);
    if (tc > 0.0) {
        const rd_cylinder *c = &s->cyl[which];
        double hx = p.x + tc * dir.x - c->x, hy = p.y + tc * dir.y - c->y;
        double hz = p.z + tc * dir.z;
        double nx = hx / c->r, ny = hy / c->r, nz = 0.0, lam, alb;
        if (hz >= c->h - 1e-9 && hx * hx + hy * hy < c->r * c->r * 0.999) {
            nx = ny = 0.0;
            nz = 1.0;
        }
        lam = 0.3 * nx + 0.2 * ny + 0.93 * nz;
        alb = (hz >= c->band_z0 && hz < c->band_z1) ? c->band_albedo : c->albedo;
        *label = RD_LABEL_ROBOT;
        return alb * (0.35 + 0.65 * (lam > 0.0 ? lam : 0.0));
    }
    if (tg <= tw) {
        double X = p.x + tg * dir.x, Y = p.y + tg * dir.y;
        if (fabs(X) <= s->carpet_x && fabs(Y) <= s->carpet_y) {
            /* Fibre grain (6 mm), tufts (3 cm) and patches (25 cm) of the carpet. */
            double n = 0.35 * vnoise(X / 0.006, Y / 0.006, s->texture_seed ^ 0xAAAAu) +
                       0.4 * vnoise(X / 0.03, Y / 0.03, s->texture_seed) +
                       0.25 * vnoise(X / 0.25, Y / 0.25, s->texture_seed ^ 0x5555u);
            if (painted(X, Y)) {
                *label = RD_LABEL_PAINT;
                return s->paint * (1.0 + 0.3 * s->texture * n);
            }
            *label = RD_LABEL_CARPET;
            return s->carpet * (1.0 + s->texture * n);
        }
        *label = RD_LABEL_FLOOR;
        return s->floor * (1.0 + 0.5 * s->texture * vnoise(X / 0.1, Y / 0.1, s->texture_seed));
    }
    {
        double z = p.z + tw * dir.z;
        if (z > s->wall_h) {
            *label = RD_LABEL_CEILING;
            return s->ceiling;
        }
        *label = RD_LABEL_WALL;
        return (z >= s->wall_band_z0 && z < s->wall_band_z1) ? s->wall_band : s->wall;
    }
}

static void blur_rows(double *dst, const double *src, int w, int h, const double *k, int r,
                      int vertical)
{
    int x, y, j;
    for (y = 0; y < h; y++) {
        for (x = 0; x < w; x++) {
            double acc = 0.0;
            for (j = -r; j <= r; j++) {
                int xx = vertical ? x : x + j, yy = vertical ? y + j : y;
                xx = xx < 0 ? 0 : (xx >= w ? w - 1 : xx);
                yy = yy < 0 ? 0 : (yy >= h ? h - 1 : yy);
                acc += k[j + r] * src[(size_t)yy * (size_t)w + (size_t)xx];
            }
            dst[(size_t)y * (size_t)w + (size_t)x] = acc;
        }
    }
}

void rd_render(const rd_scene *s, uint8_t *img, uint8_t *labels)
{
    const int w = s->cam.width, h = s->cam.height;
    double *a = malloc((size_t)w * (size_t)h * sizeof(double));
    double *b = malloc((size_t)w * (size_t)h * sizeof(double));
    double k[64], ksum = 0.0, rmax2;
    int x, y, i, j, r;
    uint64_t rng = s->noise_seed;
    if (a == NULL || b == NULL) {
        abort();
    }
    rmax2 = s->cam.cx * s->cam.cx + s->cam.cy * s->cam.cy;
    for (y = 0; y < h; y++) {
        for (x = 0; x < w; x++) {
            double acc = 0.0, du = x - s->cam.cx, dv = y - s->cam.cy, illum;
            int label = 0;
            for (j = 0; j < SS; j++) {
                for (i = 0; i < SS; i++) {
                    double u = x - 0.5 + (i + 0.5) / SS, v = y - 0.5 + (j + 0.5) / SS;
                    acc += trace(s, rd_ray(&s->cam, u, v), &label);
                }
            }
            if (labels != NULL) {
                /* The surface at the pixel centre. */
                trace(s, rd_ray(&s->cam, x, y), &label);
                labels[(size_t)y * (size_t)w + (size_t)x] = (uint8_t)label;
            }
            illum = 1.0 + s->grad_x * du / (0.5 * w) + s->grad_y * dv / (0.5 * h);
            illum *= 1.0 - s->vignette * (du * du + dv * dv) / rmax2;
            if (s->spot_a > 0.0) {
                double sx = x - s->spot_x, sy = y - s->spot_y;
                illum *= 1.0 + s->spot_a * exp(-(sx * sx + sy * sy) / (2.0 * s->spot_r * s->spot_r));
            }
            if (illum < 0.2) {
                illum = 0.2;
            }
            a[(size_t)y * (size_t)w + (size_t)x] = acc / (SS * SS) * illum;
        }
    }
    r = (int)ceil(3.0 * s->blur);
    if (r > 31) {
        r = 31;
    }
    for (j = -r; j <= r; j++) {
        k[j + r] = exp(-(double)(j * j) / (2.0 * s->blur * s->blur));
        ksum += k[j + r];
    }
    for (j = 0; j <= 2 * r; j++) {
        k[j] /= ksum;
    }
    blur_rows(b, a, w, h, k, r, 0);
    blur_rows(a, b, w, h, k, r, 1);
    for (y = 0; y < h; y++) {
        for (x = 0; x < w; x++) {
            double v = 255.0 * s->gain * a[(size_t)y * (size_t)w + (size_t)x] +
                       s->noise * rd_rand_gauss(&rng);
            v = floor(v + 0.5);
            img[(size_t)y * (size_t)w + (size_t)x] = (uint8_t)(v < 0.0 ? 0.0 : (v > 255.0 ? 255.0 : v));
        }
    }
    free(a);
    free(b);
}

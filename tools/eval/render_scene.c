/* SPDX-License-Identifier: Apache-2.0 */
/*
 * Field geometry, camera, cylinders and the random choice of a scene.
 */
#include <math.h>
#include <string.h>

#include "render.h"

#ifndef M_PI
#define M_PI 3.14159265358979323846
#endif

static const char *const set_names[RD_NSETS] = {"normal", "dark", "overexposed", "occluded",
                                                "circle"};

const char *rd_set_name(rd_set s)
{
    return set_names[s];
}

int rd_set_parse(const char *name, rd_set *s)
{
    int i;
    for (i = 0; i < RD_NSETS; i++) {
        if (strcmp(name, set_names[i]) == 0) {
            *s = (rd_set)i;
            return 0;
        }
    }
    return -1;
}

/* SPL field: touch lines, goal lines, halfway line, goal areas 0.6 x 2.2 m and penalty
   areas 1.65 x 4.0 m, all as centre lines ending where centre lines cross. */
static const double field_segs[RD_NSEG][4] = {
    {-4.5, -3.0, 4.5, -3.0},  {-4.5, 3.0, 4.5, 3.0},    /* touch lines */
    {-4.5, -3.0, -4.5, 3.0},  {4.5, -3.0, 4.5, 3.0},    /* goal lines */
    {0.0, -3.0, 0.0, 3.0},                              /* halfway line */
    {-4.5, -1.1, -3.9, -1.1}, {-3.9, -1.1, -3.9, 1.1}, {-3.9, 1.1, -4.5, 1.1},
    {4.5, -1.1, 3.9, -1.1},   {3.9, -1.1, 3.9, 1.1},   {3.9, 1.1, 4.5, 1.1},
    {-4.5, -2.0, -2.85, -2.0}, {-2.85, -2.0, -2.85, 2.0}, {-2.85, 2.0, -4.5, 2.0},
    {4.5, -2.0, 2.85, -2.0},  {2.85, -2.0, 2.85, 2.0}, {2.85, 2.0, 4.5, 2.0},
};

void rd_field_segment(int i, double *x0, double *y0, double *x1, double *y1)
{
    *x0 = field_segs[i][0];
    *y0 = field_segs[i][1];
    *x1 = field_segs[i][2];
    *y1 = field_segs[i][3];
}

uint64_t rd_rand_u64(uint64_t *state)
{
    uint64_t z = (*state += 0x9E3779B97F4A7C15ull);
    z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9ull;
    z = (z ^ (z >> 27)) * 0x94D049BB133111EBull;
    return z ^ (z >> 31);
}

double rd_rand_uniform(uint64_t *state, double lo, double hi)
{
    double u = (double)(rd_rand_u64(state) >> 11) * (1.0 / 9007199254740992.0);
    return lo + (hi - lo) * u;
}

double rd_rand_gauss(uint64_t *state)
{
    double u1 = rd_rand_uniform(state, 1e-12, 1.0), u2 = rd_rand_uniform(state, 0.0, 1.0);
    return sqrt(-2.0 * log(u1)) * cos(2.0 * M_PI * u2);
}

static rd_vec v3(double x, double y, double z)
{
    rd_vec r;
    r.x = x;
    r.y = y;
    r.z = z;
    return r;
}

static double dot(rd_vec a, rd_vec b)
{
    return a.x * b.x + a.y * b.y + a.z * b.z;
}

static rd_vec cross(rd_vec a, rd_vec b)
{
    return v3(a.y * b.z - a.z * b.y, a.z * b.x - a.x * b.z, a.x * b.y - a.y * b.x);
}

void rd_camera_set(rd_camera *c, int width, int height, double x, double y, double z,
                   double yaw, double pitch, double roll, double hfov)
{
    rd_vec r0, d0;
    c->pos = v3(x, y, z);
    c->fwd = v3(cos(yaw) * cos(pitch), sin(yaw) * cos(pitch), -sin(pitch));
    r0 = v3(sin(yaw), -cos(yaw), 0.0);
    d0 = cross(c->fwd, r0);
    c->right = v3(cos(roll) * r0.x + sin(roll) * d0.x, cos(roll) * r0.y + sin(roll) * d0.y,
                  cos(roll) * r0.z + sin(roll) * d0.z);
    c->down = v3(-sin(roll) * r0.x + cos(roll) * d0.x, -sin(roll) * r0.y + cos(roll) * d0.y,
                 -sin(roll) * r0.z + cos(roll) * d0.z);
    c->width = width;
    c->height = height;
    c->f = 0.5 * (double)width / tan(0.5 * hfov);
    c->cx = 0.5 * (double)(width - 1);
    c->cy = 0.5 * (double)(height - 1);
}

int rd_project(const rd_camera *c, rd_vec p, double *u, double *v)
{
    rd_vec d = v3(p.x - c->pos.x, p.y - c->pos.y, p.z - c->pos.z);
    double zc = dot(d, c->fwd);
    if (zc <= 1e-6) {
        return 0;
    }
    *u = c->cx + c->f * dot(d, c->right) / zc;
    *v = c->cy + c->f * dot(d, c->down) / zc;
    return 1;
}

rd_vec rd_ray(const rd_camera *c, double u, double v)
{
    double a = (u - c->cx) / c->f, b = (v - c->cy) / c->f;
    return v3(c->fwd.x + a * c->right.x + b * c->down.x, c->fwd.y + a * c->right.y + b * c->down.y,
              c->fwd.z + a * c->right.z + b * c->down.z);
}

double rd_hit_cylinders(const rd_scene *s, rd_vec pos, rd_vec dir, double tmax, int *which)
{
    const double eps = 1e-9;
    double best = -1.0;
    int i;
    for (i = 0; i < s->ncyl; i++) {
        const rd_cylinder *c = &s->cyl[i];
        double ox = pos.x - c->x, oy = pos.y - c->y;
        double a = dir.x * dir.x + dir.y * dir.y;
        double b = 2.0 * (ox * dir.x + oy * dir.y);
        double cc = ox * ox + oy * oy - c->r * c->r;
        double t = -1.0;
        if (a > 0.0) {
            double disc = b * b - 4.0 * a * cc;
            if (disc >= 0.0) {
                double t1 = (-b - sqrt(disc)) / (2.0 * a);
                double z = pos.z + t1 * dir.z;
                if (t1 > eps && z >= 0.0 && z <= c->h) {
                    t = t1;
                }
            }
        }
        if (dir.z != 0.0) {
            double tc = (c->h - pos.z) / dir.z;
            double hx = ox + tc * dir.x, hy = oy + tc * dir.y;
            if (tc > eps && hx * hx + hy * hy <= c->r * c->r && (t < 0.0 || tc < t)) {
                t = tc;
            }
        }
        if (t > 0.0 && t < tmax && (best < 0.0 || t < best)) {
            best = t;
            if (which != NULL) {
                *which = i;
            }
        }
    }
    return best;
}

static double deg(double d)
{
    return d * M_PI / 180.0;
}

/* A robot-like cylinder standing on a ground point seen through a random pixel. */
static int place_cylinder(rd_scene *s, uint64_t *rng, rd_cylinder *c)
{
    const rd_camera *cam = &s->cam;
    double u = rd_rand_uniform(rng, 0.1, 0.9) * cam->width;
    double v = rd_rand_uniform(rng, 0.35, 0.95) * cam->height;
    rd_vec d = rd_ray(cam, u, v);
    double t, gx, gy, dist;
    if (d.z >= 0.0) {
        return -1;
    }
    t = -cam->pos.z / d.z;
    gx = cam->pos.x + t * d.x;
    gy = cam->pos.y + t * d.y;
    dist = hypot(gx - cam->pos.x, gy - cam->pos.y);
    c->r = rd_rand_uniform(rng, 0.08, 0.15);
    c->h = rd_rand_uniform(rng, 0.35, 0.6);
    if (dist < 0.8 + c->r || dist > 4.0) {
        return -1;
    }
    /* Stand the cylinder's axis a radius behind the ground point. */
    c->x = gx + c->r * d.x / hypot(d.x, d.y);
    c->y = gy + c->r * d.y / hypot(d.x, d.y);
    c->albedo = rd_rand_uniform(rng, 0.0, 1.0) < 0.5 ? rd_rand_uniform(rng, 0.04, 0.2)
                                                     : rd_rand_uniform(rng, 0.7, 0.92);
    c->band_albedo = c->albedo;
    c->band_z0 = c->band_z1 = 0.0;
    if (rd_rand_uniform(rng, 0.0, 1.0) < 0.5) {
        c->band_albedo = rd_rand_uniform(rng, 0.1, 0.9);
        c->band_z0 = rd_rand_uniform(rng, 0.1, 0.3);
        c->band_z1 = c->band_z0 + rd_rand_uniform(rng, 0.05, 0.15);
    }
    return 0;
}

void rd_scene_random(rd_scene *s, rd_set set, int width, int height, uint64_t seed)
{
    uint64_t rng = seed;
    int attempt;
    double need = 0.5 * (double)width;
    memset(s, 0, sizeof(*s));
    for (attempt = 0; attempt < 1000; attempt++) {
        double x, y, yaw, pitch = deg(rd_rand_uniform(&rng, 15.0, 45.0));
        double h = rd_rand_uniform(&rng, 0.4, 0.6), roll = deg(rd_rand_uniform(&rng, -3.0, 3.0));
        double hfov = deg(rd_rand_uniform(&rng, 55.0, 65.0));
        if (set == RD_CIRCLE) {
            double phi = rd_rand_uniform(&rng, 0.0, 2.0 * M_PI);
            double d = rd_rand_uniform(&rng, 1.0, 3.0);
            x = d * cos(phi);
            y = d * sin(phi);
            yaw = phi + M_PI + rd_rand_uniform(&rng, -0.25, 0.25);
            pitch = deg(rd_rand_uniform(&rng, 18.0, 40.0));
        } else {
            x = rd_rand_uniform(&rng, -5.0, 5.0);
            y = rd_rand_uniform(&rng, -3.5, 3.5);
            yaw = rd_rand_uniform(&rng, 0.0, 2.0 * M_PI);
        }
        rd_camera_set(&s->cam, width, height, x, y, h, yaw, pitch, roll, hfov);
        s->ncyl = 0;
        if (set == RD_OCCLUDED) {
            double before = rd_visible_length(s), after;
            int n = 2 + (int)(rd_rand_u64(&rng) % 4), tries = 0;
            while (s->ncyl < n && tries++ < 200) {
                rd_cylinder c;
                if (place_cylinder(s, &rng, &c) == 0) {
                    s->cyl[s->ncyl++] = c;
                }
            }
            after = rd_visible_length(s);
            /* Occluders must really hide ground truth, and leave enough in view. */
            if (before - after < 0.05 * (double)width || after < need) {
                continue;
            }
            break;
        }
        if (set == RD_CIRCLE) {
            ev_paths l, a, dc;
            double arc = 0.0;
            size_t i;
            ev_paths_init(&l);
            ev_paths_init(&a);
            ev_paths_init(&dc);
            rd_ground_truth(s, &l, &a, &dc);
            for (i = 0; i < a.npieces; i++) {
                arc += ev_piece_length(&a, i);
            }
            ev_paths_free(&l);
            ev_paths_free(&a);
            ev_paths_free(&dc);
            if (arc >= need) {
                break;
            }
            continue;
        }
        if (rd_visible_length(s) >= need) {
            break;
        }
    }

    s->carpet = rd_rand_uniform(&rng, 0.30, 0.42);
    s->paint = rd_rand_uniform(&rng, 0.78, 0.92);
    s->floor = rd_rand_uniform(&rng, 0.15, 0.6);
    s->wall = rd_rand_uniform(&rng, 0.3, 0.85);
    s->wall_band = rd_rand_uniform(&rng, 0.1, 0.95);
    s->ceiling = rd_rand_uniform(&rng, 0.2, 0.9);
    s->carpet_x = 5.2;
    s->carpet_y = 3.7;
    s->wall_x = s->carpet_x + rd_rand_uniform(&rng, 0.3, 2.5);
    s->wall_y = s->carpet_y + rd_rand_uniform(&rng, 0.3, 2.5);
    s->wall_h = rd_rand_uniform(&rng, 1.0, 3.0);
    s->wall_band_z0 = rd_rand_uniform(&rng, 0.3, 0.6);
    s->wall_band_z1 = s->wall_band_z0 + rd_rand_uniform(&rng, 0.1, 0.4);
    s->texture = rd_rand_uniform(&rng, 0.08, 0.20);
    s->texture_seed = rd_rand_u64(&rng);
    switch (set) {
    case RD_DARK:
        s->gain = rd_rand_uniform(&rng, 0.18, 0.32);
        break;
    case RD_OVEREXPOSED:
        /* Lines clip at 255 while most of the carpet stays below it. */
        s->gain = rd_rand_uniform(&rng, 1.4, 1.9);
        break;
    default:
        s->gain = rd_rand_uniform(&rng, 0.85, 1.15);
        break;
    }
    {
        /* Gentler lighting on overexposed scenes, so the carpet does not clip as well. */
        double light = set == RD_OVEREXPOSED ? 0.6 : 1.0;
        s->grad_x = light * rd_rand_uniform(&rng, -0.25, 0.25);
        s->grad_y = light * rd_rand_uniform(&rng, -0.25, 0.25);
        s->vignette = rd_rand_uniform(&rng, 0.05, 0.35);
        if (rd_rand_uniform(&rng, 0.0, 1.0) < 0.5) {
            s->spot_x = rd_rand_uniform(&rng, 0.0, 1.0) * width;
            s->spot_y = rd_rand_uniform(&rng, 0.0, 1.0) * height;
            s->spot_r = rd_rand_uniform(&rng, 0.15, 0.4) * width;
            s->spot_a = light * rd_rand_uniform(&rng, 0.1, 0.35);
        }
    }
    s->blur = rd_rand_uniform(&rng, 0.4, 1.0);
    s->noise = rd_rand_uniform(&rng, 1.5, 4.0);
    s->noise_seed = rd_rand_u64(&rng);
}

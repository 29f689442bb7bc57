/* SPDX-License-Identifier: Apache-2.0 */
/*
 * The synthetic field renderer: an SPL field seen by a pinhole camera, with exact
 * ground truth for the painted lines. Field coordinates in metres: origin at the
 * centre spot, X along the field (goal lines at X = +-4.5), Y across (touch lines
 * at Y = +-3), Z up. Image coordinates as in the shared synth README: pixels,
 * x right, y down, integer values at pixel centres. Host-only code.
 */
#ifndef SYMLINE_EVAL_RENDER_H
#define SYMLINE_EVAL_RENDER_H

#include <stdint.h>

#include "paths.h"

#define RD_LINE_HALF 0.025    /* half of the 5 cm line width */
#define RD_CIRCLE_R 0.75      /* centre circle radius (1.5 m diameter) */
#define RD_MAX_CYL 8
#define RD_NSEG 17            /* straight centre lines of the field */

typedef struct rd_vec {
    double x, y, z;
} rd_vec;

typedef struct rd_camera {
    rd_vec pos;               /* optical centre */
    rd_vec fwd, right, down;  /* unit axes: viewing direction, image x, image y */
    double f;                 /* focal length in pixels */
    double cx, cy;            /* principal point (pixels) */
    int width, height;
} rd_camera;

typedef struct rd_cylinder {
    double x, y, r, h;        /* foot centre, radius, height (m) */
    double albedo, band_albedo, band_z0, band_z1;
} rd_cylinder;

typedef struct rd_scene {
    rd_camera cam;
    int ncyl;
    rd_cylinder cyl[RD_MAX_CYL];
    /* surfaces (albedo, 0..1) */
    double carpet, paint, floor, wall, wall_band, ceiling;
    double carpet_x, carpet_y;  /* carpet half extents */
    double wall_x, wall_y, wall_h, wall_band_z0, wall_band_z1;
    double texture;             /* carpet texture strength */
    uint64_t texture_seed;
    /* image formation */
    double gain;                /* exposure: image value = 255 * gain * radiance */
    double grad_x, grad_y;      /* linear illumination gradient over the image */
    double vignette;            /* relative fall-off at the image corners */
    double spot_x, spot_y, spot_r, spot_a; /* soft bright spot (pixels, amplitude) */
    double blur;                /* Gaussian sigma, pixels */
    double noise;               /* sensor noise sigma, gray levels */
    uint64_t noise_seed;
} rd_scene;

/* Field set names. */
typedef enum { RD_NORMAL, RD_DARK, RD_OVEREXPOSED, RD_OCCLUDED, RD_CIRCLE, RD_NSETS } rd_set;
const char *rd_set_name(rd_set s);
int rd_set_parse(const char *name, rd_set *s);

/* The straight field lines (centre lines, ending where centre lines cross). */
void rd_field_segment(int i, double *x0, double *y0, double *x1, double *y1);

/* Deterministic random numbers (splitmix64). */
uint64_t rd_rand_u64(uint64_t *state);
double rd_rand_uniform(uint64_t *state, double lo, double hi);
double rd_rand_gauss(uint64_t *state);

/* Camera from pose: height, yaw (rad, 0 = +X), pitch down (rad), roll (rad), horizontal FOV. */
void rd_camera_set(rd_camera *c, int width, int height, double x, double y, double z,
                   double yaw, double pitch, double roll, double hfov);
/* Image point of a world point; 0 when it is behind the camera. */
int rd_project(const rd_camera *c, rd_vec p, double *u, double *v);
/* Ray direction (not unit) through image point (u, v). */
rd_vec rd_ray(const rd_camera *c, double u, double v);
/* Smallest t in (eps, tmax) where pos + t*dir hits a cylinder (side or top), or -1. */
double rd_hit_cylinders(const rd_scene *s, rd_vec pos, rd_vec dir, double tmax, int *which);

/* Draws a scene of the given set (retrying poses until enough lines are in view). */
void rd_scene_random(rd_scene *s, rd_set set, int width, int height, uint64_t seed);

/* Surface labels (values of the label image). */
enum {
    RD_LABEL_CARPET = 0,
    RD_LABEL_PAINT = 1,
    RD_LABEL_FLOOR = 2,
    RD_LABEL_WALL = 3,
    RD_LABEL_CEILING = 4,
    RD_LABEL_ROBOT = 5,
    RD_NLABELS = 6
};

/* Renders the 8-bit image (width*height bytes) and, when labels is not NULL, the
   surface seen at each pixel centre (RD_LABEL_*, width*height bytes). */
void rd_render(const rd_scene *s, uint8_t *img, uint8_t *labels);

/* Ground truth: straight lines, circle polylines and don't-care parts (README formats). */
void rd_ground_truth(const rd_scene *s, ev_paths *lines, ev_paths *arcs, ev_paths *dontcare);
/* Visible, required ground-truth length in pixels (for choosing poses). */
double rd_visible_length(const rd_scene *s);

#endif

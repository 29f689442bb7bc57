/* SPDX-License-Identifier: Apache-2.0 */
/*
 * Detections drawn over a frame, like the paper's Fig. 8: lines solid red,
 * curves dotted cyan along their points, on the dimmed gray frame.
 */
#include "overlay.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>

#include "imgio.h"

/* Pen half-width in pixels: 1-pixel marks vanish on large frames. */
static int32_t pen_radius(const imgio_rgb *o)
{
    return o->width >= 480u ? 1 : 0;
}

static void put_px(imgio_rgb *o, int32_t cx, int32_t cy, const uint8_t rgb[3])
{
    const int32_t r = pen_radius(o);
    int32_t x, y;
    for (y = cy - r; y <= cy + r; y++) {
        for (x = cx - r; x <= cx + r; x++) {
            if (x >= 0 && y >= 0 && (uint32_t)x < o->width && (uint32_t)y < o->height) {
                uint8_t *p = o->px + ((size_t)y * o->width + (size_t)x) * 3u;
                p[0] = rgb[0];
                p[1] = rgb[1];
                p[2] = rgb[2];
            }
        }
    }
}

/* Line from a to b (pixels); dotted: dashes as long as the gaps, 3 pen widths each. */
static void draw_line(imgio_rgb *o, int32_t x0, int32_t y0, int32_t x1, int32_t y1,
                      const uint8_t rgb[3], int dotted, uint32_t *phase)
{
    const uint32_t dash = 3u * (2u * (uint32_t)pen_radius(o) + 1u);
    const int32_t dx = abs(x1 - x0), dy = -abs(y1 - y0);
    const int32_t sx = x0 < x1 ? 1 : -1, sy = y0 < y1 ? 1 : -1;
    int32_t err = dx + dy;
    for (;;) {
        if (!dotted || (*phase / dash) % 2u == 0u) {
            put_px(o, x0, y0, rgb);
        }
        (*phase)++;
        if (x0 == x1 && y0 == y1) {
            break;
        }
        {
            const int32_t e2 = 2 * err;
            if (e2 >= dy) {
                err += dy;
                x0 += sx;
            }
            if (e2 <= dx) {
                err += dx;
                y0 += sy;
            }
        }
    }
}

static int32_t q8_round(int32_t v)
{
    return (v >= 0) ? (v + 128) >> 8 : -((-v + 128) >> 8);
}

/* An intersection: its rays as short spokes and a square around the point,
 * green for L, orange for T, magenta for X. */
static void draw_intersection(imgio_rgb *o, const symline_intersection *it)
{
    static const uint8_t COLOUR[3][3] = {{60, 255, 60}, {255, 160, 0}, {255, 60, 255}};
    const uint8_t *c = COLOUR[it->type < 3u ? it->type : 2u];
    const int32_t cx = q8_round(it->x), cy = q8_round(it->y);
    const int32_t h = 3 + 2 * pen_radius(o), spoke = 6 * h;
    uint32_t k, phase = 0u;
    for (k = 0; k < it->ray_count; k++) {
        const double a = (double)it->rays[k] / 256.0 * 3.14159265358979 / 180.0;
        draw_line(o, cx, cy, cx + (int32_t)lround(spoke * cos(a)),
                  cy + (int32_t)lround(spoke * sin(a)), c, 0, &phase);
    }
    draw_line(o, cx - h, cy - h, cx + h, cy - h, c, 0, &phase);
    draw_line(o, cx + h, cy - h, cx + h, cy + h, c, 0, &phase);
    draw_line(o, cx + h, cy + h, cx - h, cy + h, c, 0, &phase);
    draw_line(o, cx - h, cy + h, cx - h, cy - h, c, 0, &phase);
}

int overlay_write(const char *path, const uint8_t *gray, uint32_t width, uint32_t height,
                  uint32_t stride, const symline_result *r, char *err, size_t errlen)
{
    return overlay_write_ix(path, gray, width, height, stride, r, NULL, err, errlen);
}

int overlay_write_ix(const char *path, const uint8_t *gray, uint32_t width, uint32_t height,
                     uint32_t stride, const symline_result *r,
                     const symline_intersection_result *ix, char *err, size_t errlen)
{
    static const uint8_t RED[3] = {255, 40, 40};
    static const uint8_t CYAN[3] = {0, 230, 255};
    static const uint8_t YELLOW[3] = {255, 220, 0};
    imgio_rgb o;
    uint32_t i, k, x, y;
    int rc;
    o.width = width;
    o.height = height;
    o.px = (uint8_t *)malloc((size_t)width * height * 3u);
    if (o.px == NULL) {
        snprintf(err, errlen, "%s: out of memory", path);
        return -1;
    }
    for (y = 0; y < height; y++) {
        for (x = 0; x < width; x++) {
            /* Dim the frame a little so the marks stand out. */
            const uint8_t v = (uint8_t)(gray[(size_t)y * stride + x] * 3u / 4u);
            uint8_t *p = o.px + ((size_t)y * width + x) * 3u;
            p[0] = p[1] = p[2] = v;
        }
    }
    for (i = 0; i < r->segment_count; i++) {
        const symline_segment *s = &r->segments[i];
        uint32_t phase = 0u;
        if (s->kind == SYMLINE_KIND_LINE) {
            draw_line(&o, q8_round(s->x0), q8_round(s->y0), q8_round(s->x1), q8_round(s->y1), RED,
                      0, &phase);
        } else {
            const symline_point *p = r->points + s->first;
            for (k = 1; k < s->count; k++) {
                draw_line(&o, p[k - 1].x, p[k - 1].y, p[k].x, p[k].y, CYAN, 1, &phase);
            }
        }
    }
    for (k = 1; k < r->field.count && k < SYMLINE_FIELD_MAX_VERTICES; k++) {
        uint32_t phase = 0u;
        const symline_field_vertex *a = &r->field.v[k - 1u], *b = &r->field.v[k];
        draw_line(&o, a->x, a->y, b->x, b->y, YELLOW, 0, &phase);
    }
    for (i = 0; ix != NULL && i < ix->count; i++) {
        draw_intersection(&o, &ix->items[i]);
    }
    rc = imgio_write_rgb(path, &o, err, errlen);
    free(o.px);
    return rc;
}

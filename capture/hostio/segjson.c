/* SPDX-License-Identifier: Apache-2.0 */
/*
 * The JSON writer for detected segments (docs/format.md).
 */
#include "segjson.h"

/* Q8 fixed point as a decimal with two places, exact to the printed digits. */
static void put_q8(FILE *f, int32_t v)
{
    const int neg = v < 0;
    uint32_t a = (uint32_t)(neg ? -(int64_t)v : (int64_t)v);
    uint32_t hundredths = (uint32_t)(((uint64_t)a * 100u + 128u) >> 8);
    fprintf(f, "%s%u.%02u", (neg && hundredths != 0u) ? "-" : "", hundredths / 100u,
            hundredths % 100u);
}

/* Q8 degrees as degrees with two places. */
static void put_deg(FILE *f, uint32_t v)
{
    uint32_t hundredths = (uint32_t)(((uint64_t)v * 100u + 128u) >> 8);
    if (hundredths >= 36000u) {
        hundredths -= 36000u; /* 359.998 rounds to 0.00, not 360.00 */
    }
    fprintf(f, "%u.%02u", hundredths / 100u, hundredths % 100u);
}

static void put_intersections(FILE *f, const symline_intersection_result *ix)
{
    static const char TYPES[3] = {'L', 'T', 'X'};
    uint32_t i, k;
    fputs(",\n \"intersections\": [", f);
    for (i = 0; i < ix->count; i++) {
        const symline_intersection *it = &ix->items[i];
        fputs(i == 0u ? "\n  {\"x\": " : ",\n  {\"x\": ", f);
        put_q8(f, it->x);
        fputs(", \"y\": ", f);
        put_q8(f, it->y);
        fprintf(f, ", \"type\": \"%c\", \"rays\": [", TYPES[it->type < 3u ? it->type : 2u]);
        for (k = 0; k < it->ray_count; k++) {
            fputs(k == 0u ? "" : ", ", f);
            put_deg(f, it->rays[k]);
        }
        fputs("], \"segments\": [", f);
        for (k = 0; k < it->segment_count; k++) {
            fprintf(f, "%s%u", k == 0u ? "" : ", ", it->segments[k]);
        }
        fputs("]}", f);
    }
    fputs(ix->count ? "\n ]" : "]", f);
}

void segjson_put_string(FILE *f, const char *s)
{
    fputc('"', f);
    for (; *s != '\0'; s++) {
        const unsigned char c = (unsigned char)*s;
        if (c == '"' || c == '\\') {
            fputc('\\', f);
            fputc(c, f);
        } else if (c < 0x20u) {
            fprintf(f, "\\u%04x", c);
        } else {
            fputc(c, f);
        }
    }
    fputc('"', f);
}

/*
 * Polyline vertex k of a curve's n points, as "[x, y]" after `pre`: the mean
 * sub-pixel position (offsets in 1/128 px) of the points within `r` of k along
 * the chain, fewer near the ends so that the ends stay where they are. Each
 * point's offset across the line carries its own noise; a short mean keeps the
 * shape: on a circle of radius R it moves inward by sum(d^2) / (2R (2r+1)) for
 * points d px along the chain (2^level px apart): r = 2 up to scale 1, 1 beyond,
 * under 0.04 px for R >= 150 px up to scale 2 and about 0.1 px at scale 3 for
 * R = 200 px (lines that wide are near the camera, where the circle is large).
 */
static void put_vertex(FILE *f, const symline_point *p, uint32_t n, uint32_t k, uint32_t r,
                       const char *pre)
{
    uint32_t i;
    int32_t sx = 0, sy = 0, c;
    r = k < r ? k : r;
    r = n - 1u - k < r ? n - 1u - k : r;
    for (i = k - r; i <= k + r; i++) {
        sx += (int32_t)p[i].x * 256 + (int32_t)p[i].fx * 2;
        sy += (int32_t)p[i].y * 256 + (int32_t)p[i].fy * 2;
    }
    c = (int32_t)(2u * r + 1u);
    fputs(pre, f);
    put_q8(f, (sx + (sx < 0 ? -c / 2 : c / 2)) / c);
    fputs(", ", f);
    put_q8(f, (sy + (sy < 0 ? -c / 2 : c / 2)) / c);
    fputc(']', f);
}

int segjson_write(FILE *f, uint32_t width, uint32_t height, const symline_result *r)
{
    return segjson_write_named_ix(f, NULL, width, height, r, NULL);
}

int segjson_write_named(FILE *f, const char *file, uint32_t width, uint32_t height,
                        const symline_result *r)
{
    return segjson_write_named_ix(f, file, width, height, r, NULL);
}

int segjson_write_ix(FILE *f, uint32_t width, uint32_t height, const symline_result *r,
                     const symline_intersection_result *ix)
{
    return segjson_write_named_ix(f, NULL, width, height, r, ix);
}

int segjson_write_named_ix(FILE *f, const char *file, uint32_t width, uint32_t height,
                           const symline_result *r, const symline_intersection_result *ix)
{
    uint32_t i, k;
    fputc('{', f);
    if (file != NULL) {
        fputs("\"file\": ", f);
        segjson_put_string(f, file);
        fputs(", ", f);
    }
    fprintf(f, "\"width\": %u, \"height\": %u, \"truncated\": %s,\n \"segments\": [", width, height,
            r->truncated ? "true" : "false");
    for (i = 0; i < r->segment_count; i++) {
        const symline_segment *s = &r->segments[i];
        fputs(i == 0u ? "\n  {" : ",\n  {", f);
        fputs("\"x0\": ", f);
        put_q8(f, s->x0);
        fputs(", \"y0\": ", f);
        put_q8(f, s->y0);
        fputs(", \"x1\": ", f);
        put_q8(f, s->x1);
        fputs(", \"y1\": ", f);
        put_q8(f, s->y1);
        fprintf(f, ", \"points\": %u, \"max_dev\": ", s->count);
        put_q8(f, (int32_t)s->max_dev);
        fprintf(f, ", \"kind\": \"%s\", \"axis\": \"%s\", \"level\": %u",
                s->kind == SYMLINE_KIND_CURVE ? "curve" : "line",
                s->axis == SYMLINE_AXIS_VERTICAL ? "vertical" : "horizontal", s->level);
        if (s->kind == SYMLINE_KIND_CURVE && s->count >= 2u) {
            const symline_point *p = r->points + s->first;
            const uint32_t mean_r = s->level <= 1u ? 2u : 1u;
            fputs(", \"polyline\": [", f);
            for (k = 0; k < s->count; k += 4u) {
                put_vertex(f, p, s->count, k, mean_r, k == 0u ? "[" : ", [");
            }
            if ((s->count - 1u) % 4u != 0u) {
                put_vertex(f, p, s->count, s->count - 1u, mean_r, ", [");
            }
            fputc(']', f);
        }
        fputc('}', f);
    }
    fputs(r->segment_count ? "\n ]" : "]", f);
    if (r->field.count > 0u) {
        fputs(",\n \"field_boundary\": [", f);
        for (k = 0; k < r->field.count && k < SYMLINE_FIELD_MAX_VERTICES; k++) {
            fprintf(f, "%s[%ld, %ld]", k == 0u ? "" : ", ", (long)r->field.v[k].x,
                    (long)r->field.v[k].y);
        }
        fputc(']', f);
    }
    if (ix != NULL) {
        put_intersections(f, ix);
    }
    fputs("}\n", f);
    return ferror(f) ? -1 : 0;
}

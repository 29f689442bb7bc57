/* SPDX-License-Identifier: Apache-2.0 */
/* Text form of a detection result (see segprint.h). */
#include "segprint.h"

#include <stdio.h>

/* FNV-1a over the coordinates (and sub-pixel offsets) of a segment's points: one line per segment
 * instead of thousands of points, still sensitive to every coordinate. */
static uint32_t points_hash(const symline_point *p, uint32_t n)
{
    uint32_t h = 2166136261u, i;
    for (i = 0; i < n; i++) {
        const uint32_t v = ((uint32_t)p[i].x << 16) | p[i].y;
        const uint32_t f = ((uint32_t)(uint8_t)p[i].fx << 8) | (uint8_t)p[i].fy;
        uint32_t b;
        for (b = 0; b < 32u; b += 8u) {
            h = (h ^ ((v >> b) & 0xFFu)) * 16777619u;
        }
        for (b = 0; b < 16u; b += 8u) {
            h = (h ^ ((f >> b) & 0xFFu)) * 16777619u;
        }
    }
    return h;
}

void print_detection(const char *name, symline_status st, const symline_result *res)
{
    uint32_t i;
    printf("%s: status %d, %lu segments, %lu points%s\n", name, (int)st,
           (unsigned long)res->segment_count, (unsigned long)res->point_count,
           res->truncated ? ", truncated" : "");
    for (i = 0; i < res->segment_count; i++) {
        const symline_segment *s = &res->segments[i];
        printf("  %s (%ld,%ld)-(%ld,%ld) q8 dev %lu axis %u level %u points %lu+%lu %08lx\n",
               s->kind == SYMLINE_KIND_CURVE ? "curve" : "line ", (long)s->x0, (long)s->y0,
               (long)s->x1, (long)s->y1, (unsigned long)s->max_dev, (unsigned)s->axis,
               (unsigned)s->level, (unsigned long)s->first, (unsigned long)s->count,
               (unsigned long)((s->first <= res->point_count &&
                                s->count <= res->point_count - s->first)
                                   ? points_hash(res->points + s->first, s->count)
                                   : 0xFFFFFFFFu));
    }
}

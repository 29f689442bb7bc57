/* SPDX-License-Identifier: Apache-2.0 */
/*
 * Fuzz target: intersections of segments (symline/intersections.h).
 * symline_intersections() with fuzzer-made segment arrays (lines and curves,
 * ends on a small frame mostly, at and past +-65535 px now and then, kinds
 * other than line/curve, curves' point ranges inside and outside the point
 * count, counts above the capacities, NULL arrays), every configuration field
 * (default, inside, at a limit, past it, any value) and output capacities
 * (0 with NULL items too).
 * Checks: guard bytes after the items untouched, a known status, the
 * segments and points (const) unchanged, *out and its items untouched on an
 * error; on success count within the capacity (0 with capacity 0), truncated
 * 0 or 1, and every intersection well formed: type from its 2..4 rays, rays
 * ascending within a full turn, 2..6 segment indices ascending and below the
 * segment count, support at least 1.
 */
#include <stdint.h>
#include <stdlib.h>
#include <string.h>

#include "fuzz_lib.h"
#include "symline/intersections.h"

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size);

/* A coordinate, Q8 px: mostly on a 0..127 px frame, sometimes anything. */
static int32_t coord(fz_in *in)
{
    const uint32_t v = fz_u8(in);
    switch (v % 16u) {
    case 0: return (int32_t)fz_u32(in);
    case 1: return (int32_t)(65535u << 8) + (int32_t)(fz_u8(in) % 3u) - 1; /* the limit */
    case 2: return -(int32_t)(65535u << 8) - (int32_t)(fz_u8(in) % 3u) + 1;
    default: return (int32_t)((fz_u8(in) % 128u) << 8) + (int32_t)(fz_u8(in) % 8u) * 32;
    }
}

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
    fz_in in = {data, size};
    symline_intersection_config cfg, def;
    symline_result lines;
    symline_intersection_result out, before;
    const uint32_t nulls = fz_u8(&in);
    const int none = (nulls & 0xC0u) == 0xC0u;
    const uint32_t nseg = fz_u8(&in) % 24u, npt_cap = fz_u16(&in) % 512u;
    uint32_t seg_cap, i, k;
    symline_segment *segs;
    symline_point *pts;
    uint8_t *items, *seg_copy, *pt_copy;
    size_t item_bytes;
    symline_status st;

    symline_intersection_config_default(&def);
    cfg = def;
    cfg.min_angle_q8 = fz_pick(&in, def.min_angle_q8, 0, 90 * 256);
    cfg.gap_q8 = fz_pick(&in, def.gap_q8, 0, 256 * 256);
    cfg.gap_pct = fz_pick(&in, def.gap_pct, 0, 100);
    cfg.arm_q8 = fz_pick(&in, def.arm_q8, 256, 256 * 256);
    cfg.merge_q8 = fz_pick(&in, def.merge_q8, 0, 256 * 256);
    cfg.min_length_q8 = fz_pick(&in, def.min_length_q8, 0, 65535 * 256);
    if (fz_u8(&in) % 4u != 0u) {
        cfg.min_length_q8 = fz_u8(&in) % 8u * 256u; /* short fuzzed segments take part */
    }

    seg_cap = fz_u8(&in) % 16u == 0u && nseg > 0u ? nseg - 1u : nseg + fz_u8(&in) % 3u;
    segs = (symline_segment *)calloc((size_t)seg_cap + 1u, sizeof *segs);
    pts = (symline_point *)calloc((size_t)npt_cap + 1u, sizeof *pts);
    if (segs == NULL || pts == NULL) {
        abort();
    }
    for (i = 0; i < npt_cap; i++) {
        pts[i].x = (uint16_t)(fz_u8(&in) % 128u);
        pts[i].y = (uint16_t)(fz_u8(&in) % 128u);
        pts[i].fx = (int8_t)((int)(fz_u8(&in) % 128u) - 64);
        pts[i].fy = (int8_t)((int)(fz_u8(&in) % 128u) - 64);
        if (i > 0u && fz_u8(&in) % 2u) {
            /* mostly a path: the next point near the last */
            pts[i].x = (uint16_t)(pts[i - 1u].x + fz_u8(&in) % 3u);
            pts[i].y = (uint16_t)(pts[i - 1u].y + fz_u8(&in) % 3u);
        }
    }
    for (i = 0; i < seg_cap && i < nseg; i++) {
        symline_segment *s = &segs[i];
        const uint32_t kind = fz_u8(&in);
        s->x0 = coord(&in);
        s->y0 = coord(&in);
        s->x1 = coord(&in);
        s->y1 = coord(&in);
        s->kind = (uint8_t)(kind % 16u == 15u ? kind : kind % 2u);
        s->level = (uint8_t)(fz_u8(&in) % 9u);
        s->axis = (uint8_t)(fz_u8(&in) % 2u);
        s->max_dev = fz_u16(&in);
        s->first = fz_u16(&in) % (npt_cap + 2u);
        s->count = fz_u8(&in) % 16u == 0u ? fz_u32(&in) : fz_u16(&in) % 64u;
        if (s->kind == SYMLINE_KIND_CURVE && s->count >= 2u && s->first < npt_cap) {
            /* a curve's ends are its first and last points (mostly) */
            const uint32_t last =
                s->first + s->count - 1u < npt_cap ? s->first + s->count - 1u : s->first;
            s->x0 = (int32_t)pts[s->first].x << 8;
            s->y0 = (int32_t)pts[s->first].y << 8;
            s->x1 = (int32_t)pts[last].x << 8;
            s->y1 = (int32_t)pts[last].y << 8;
        }
    }
    memset(&lines, 0, sizeof lines);
    lines.segments = none && (nulls & 1u) ? NULL : segs;
    lines.segment_cap = seg_cap;
    lines.segment_count = nseg;
    lines.points = none && (nulls & 2u) ? NULL : pts;
    lines.point_cap = npt_cap;
    lines.point_count = fz_u8(&in) % 16u == 0u
                            ? npt_cap + 1u
                            : npt_cap - (npt_cap > 0u ? fz_u8(&in) % (npt_cap + 1u) : 0u);
    seg_copy = (uint8_t *)malloc(((size_t)seg_cap + 1u) * sizeof *segs);
    pt_copy = (uint8_t *)malloc(((size_t)npt_cap + 1u) * sizeof *pts);
    if (seg_copy == NULL || pt_copy == NULL) {
        abort();
    }
    memcpy(seg_copy, segs, ((size_t)seg_cap + 1u) * sizeof *segs);
    memcpy(pt_copy, pts, ((size_t)npt_cap + 1u) * sizeof *pts);

    memset(&out, 0, sizeof out);
    out.cap = fz_u8(&in) % 4u == 0u ? 0u : fz_u8(&in) % 24u;
    item_bytes = (size_t)out.cap * sizeof(symline_intersection);
    items = fz_buf(item_bytes, 0x5A);
    out.items = (none && (nulls & 4u)) || (out.cap == 0u && (nulls & 8u))
                    ? NULL
                    : (symline_intersection *)(void *)items;
    out.count = 0xDEADu;
    out.truncated = 0xEEu;
    memcpy(&before, &out, sizeof out);

    st = symline_intersections(none && (nulls & 16u) ? NULL : &lines,
                               none && (nulls & 32u) ? NULL : &cfg,
                               none && (nulls & 0x3Fu) == 0u ? NULL : &out);
    fz_check_status(st, "symline_intersections");
    fz_check_guard(items, item_bytes, "intersections");
    if (memcmp(seg_copy, segs, ((size_t)seg_cap + 1u) * sizeof *segs) != 0 ||
        memcmp(pt_copy, pts, ((size_t)npt_cap + 1u) * sizeof *pts) != 0) {
        abort(); /* the segments or points were written */
    }
    if (st != SYMLINE_OK) {
        if (memcmp(&out, &before, sizeof out) != 0) {
            abort();
        }
        fz_check_untouched(items, item_bytes, 0x5A, "intersections");
    } else {
        if (out.count > out.cap || out.truncated > 1u) {
            abort();
        }
        for (i = 0; i < out.count; i++) {
            const symline_intersection *x = &out.items[i];
            int bad = x->ray_count < 2u || x->ray_count > SYMLINE_INTERSECTION_RAYS ||
                      x->type != (uint8_t)(x->ray_count - 2u) || x->segment_count < 2u ||
                      x->segment_count > SYMLINE_INTERSECTION_SEGMENTS || x->support < 1u;
            for (k = 0; !bad && k < x->ray_count; k++) {
                bad =
                    x->rays[k] >= SYMLINE_DEG_Q8_FULL || (k > 0u && x->rays[k] <= x->rays[k - 1u]);
            }
            for (k = 0; !bad && k < x->segment_count; k++) {
                bad = x->segments[k] >= nseg || (k > 0u && x->segments[k] <= x->segments[k - 1u]);
            }
            if (bad) {
                fprintf(stderr, "intersection %u: type %u, %u rays, %u segments, support %u\n", i,
                        x->type, x->ray_count, x->segment_count, x->support);
                abort();
            }
        }
    }
    symline_intersection_config_default(NULL);
    free(segs);
    free(pts);
    free(seg_copy);
    free(pt_copy);
    free(items);
    return 0;
}

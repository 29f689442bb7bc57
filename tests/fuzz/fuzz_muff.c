/* SPDX-License-Identifier: Apache-2.0 */
/*
 * Fuzz target: the Muff-space line finder (symline/muff.h) and the line
 * filter's points (symline_line_points, symline/detect.h). Three entries:
 *  0. symline_muff_find() with fuzzer-chosen frame size, configuration (every
 *     field default, inside, at a limit, past it, or any value), line points
 *     (strokes and stray points, now and then one outside the frame or with a
 *     sub-pixel offset beyond -64..63), point
 *     count and capacity, accumulator and workspace sizes (exact, one byte
 *     short, zero, larger), segment capacity and NULL pointers;
 *  1. symline_detect_muff() with a fuzzer-chosen image, detector and finder
 *     configurations, sizes and capacities;
 *  2. symline_line_points() with a fuzzer-chosen image, configuration,
 *     workspace size and capacity.
 * Checks: no read past the image (pixels allocated to the byte), guard bytes
 * after the accumulator, workspace, segments and points untouched, a known
 * status; on an error the result struct and the segments unchanged and the
 * points the same set (symline_muff_find reorders them) or untouched; on
 * success counts within capacities, segments of kind line at level 0 inside
 * the frame, their points consecutive, stored and inside the frame, the axis
 * horizontal exactly when |x1-x0| >= |y1-y0| (muff.h), and the
 * finder's points the same set as before.
 */
#include <stdint.h>
#include <stdlib.h>
#include <string.h>

#include "fuzz_lib.h"
#include "symline/muff.h"

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size);

static void muff_config(fz_in *in, symline_muff_config *mc)
{
    symline_muff_config def;
    symline_muff_config_default(&def);
    *mc = def;
    mc->cell = fz_pick(in, def.cell, 0, 64);
    mc->min_votes = fz_pick(in, def.min_votes, 1, 65535);
    mc->nms_cells = fz_pick(in, def.nms_cells, 0, 16);
    mc->max_peaks = fz_pick(in, def.max_peaks, 1, 1024);
    mc->tol_q8 =
        fz_u8(in) % 8u == 0u ? 0u : fz_pick(in, def.tol_q8 != 0u ? def.tol_q8 : 512u, 64, 8192);
    mc->gap = fz_pick(in, def.gap, 0, 65535);
    mc->min_points = fz_pick(in, def.min_points, 2, 65535);
    mc->min_length = fz_pick(in, def.min_length, 0, 65535);
    mc->min_fill_pct = fz_pick(in, def.min_fill_pct, 0, 100);
    if (fz_u8(in) % 4u != 0u) {
        /* Mostly small thresholds, so that a few fuzzed points make lines. */
        mc->min_votes = 1u + fz_u8(in) % 16u;
        mc->min_points = 2u + fz_u8(in) % 8u;
        mc->min_length = fz_u8(in) % 16u;
    }
}

static int muff_config_ok(const symline_muff_config *c)
{
    return c->cell <= 64u && c->min_votes >= 1u && c->min_votes <= 65535u && c->nms_cells <= 16u &&
           c->max_peaks >= 1u && c->max_peaks <= 1024u &&
           (c->tol_q8 == 0u || (c->tol_q8 >= 64u && c->tol_q8 <= 8192u)) && c->gap <= 65535u &&
           c->min_points >= 2u && c->min_points <= 65535u && c->min_length <= 65535u &&
           c->min_fill_pct <= 100u;
}

static int pt_cmp(const void *a, const void *b)
{
    return memcmp(a, b, sizeof(symline_point));
}

/* Aborts unless the first n points of a and b are the same set. */
static void check_same_points(const symline_point *a, const symline_point *b, uint32_t n)
{
    symline_point *x, *y;
    if (n == 0u) {
        return;
    }
    x = (symline_point *)malloc(n * sizeof *x);
    y = (symline_point *)malloc(n * sizeof *y);
    if (x == NULL || y == NULL) {
        abort();
    }
    memcpy(x, a, n * sizeof *x);
    memcpy(y, b, n * sizeof *y);
    qsort(x, n, sizeof *x, pt_cmp);
    qsort(y, n, sizeof *y, pt_cmp);
    if (memcmp(x, y, n * sizeof *x) != 0) {
        fprintf(stderr, "the line points changed, not only their order\n");
        abort();
    }
    free(x);
    free(y);
}

static uint32_t iabs(int32_t v)
{
    return v < 0 ? 0u - (uint32_t)v : (uint32_t)v;
}

/* The result of a successful call for a w x h frame. */
static void check_result(const symline_result *r, uint32_t w, uint32_t h)
{
    uint32_t i, k, next = 0u;
    if (r->segment_count > r->segment_cap || r->point_count > r->point_cap) {
        abort();
    }
    for (i = 0; i < r->segment_count; i++) {
        const symline_segment *s = &r->segments[i];
        const uint32_t dx = iabs(s->x1 - s->x0), dy = iabs(s->y1 - s->y0);
        if (s->kind != SYMLINE_KIND_LINE || s->level != 0u || s->merged || s->first != next ||
            s->count > r->point_count - s->first || s->x0 < 0 || s->x1 < 0 || s->y0 < 0 ||
            s->y1 < 0 || s->x0 > (int32_t)((w - 1u) << 8) || s->x1 > (int32_t)((w - 1u) << 8) ||
            s->y0 > (int32_t)((h - 1u) << 8) || s->y1 > (int32_t)((h - 1u) << 8) ||
            /* muff.h: horizontal exactly when |x1-x0| >= |y1-y0| */
            s->axis != (dx >= dy ? SYMLINE_AXIS_HORIZONTAL : SYMLINE_AXIS_VERTICAL)) {
            fprintf(
                stderr,
                "segment %u: (%d,%d)-(%d,%d) axis %u kind %u level %u first %u count %u of %u\n", i,
                s->x0, s->y0, s->x1, s->y1, s->axis, s->kind, s->level, s->first, s->count,
                r->point_count);
            abort();
        }
        next = s->first + s->count; /* a point supports one segment: consecutive ranges */
        for (k = 0; k < s->count; k++) {
            const symline_point *p = &r->points[s->first + k];
            if (p->x >= w || p->y >= h) {
                abort();
            }
        }
    }
    if (next != r->point_count) {
        abort(); /* point_count: the points the segments reference */
    }
}

/* Output storage: capacities, guarded arrays, NULL arrays with capacity 0. */
typedef struct outs {
    symline_result r, before;
    uint8_t *segs, *pts;
    size_t seg_bytes, pt_bytes;
} outs;

static void outs_make(outs *o, uint32_t seg_cap, uint32_t pt_cap, uint32_t nulls)
{
    memset(&o->r, 0, sizeof o->r);
    o->r.segment_cap = seg_cap;
    o->r.point_cap = pt_cap;
    o->seg_bytes = (size_t)seg_cap * sizeof(symline_segment);
    o->pt_bytes = (size_t)pt_cap * sizeof(symline_point);
    o->segs = fz_buf(o->seg_bytes, 0x5A);
    o->pts = fz_buf(o->pt_bytes, 0x5A);
    o->r.segments = ((nulls & 1u) || (seg_cap == 0u && (nulls & 2u)))
                        ? NULL
                        : (symline_segment *)(void *)o->segs;
    o->r.points =
        ((nulls & 4u) || (pt_cap == 0u && (nulls & 8u))) ? NULL : (symline_point *)(void *)o->pts;
    o->r.segment_count = 0xDEADu;
    o->r.point_count = 0xBEEFu;
    o->r.truncated = true;
}

static void outs_free(outs *o)
{
    fz_check_guard(o->segs, o->seg_bytes, "segments");
    fz_check_guard(o->pts, o->pt_bytes, "points");
    free(o->segs);
    free(o->pts);
}

static uint32_t frame_dim(fz_in *in)
{
    const uint32_t v = fz_u8(in);
    if (v >= 250u) {
        return v == 255u ? 65536u : (v == 254u ? 65535u : v - 250u); /* 0..3, 65535, 65536 */
    }
    return 1u + v % 120u;
}

/* 0: symline_muff_find over fuzzer-made points. */
static void entry_find(fz_in *in)
{
    symline_muff_config mc;
    uint32_t w = frame_dim(in), h = frame_dim(in);
    const uint32_t nulls = fz_u8(in);
    const uint32_t npoints = fz_u16(in) % 600u;
    uint32_t cap, i, n;
    size_t accq, wsq, accn, wsn;
    uint8_t *acc, *ws;
    symline_point *pts, *copy;
    outs o;
    symline_status st;

    if (w >= 65535u && h >= 65535u) {
        h = 3u;
    }
    muff_config(in, &mc);
    accq = symline_muff_accumulator_size(w, h, &mc);
    wsq = symline_muff_workspace_size(w, h, &mc);
    if ((accq > 0u) && !(w >= 3u && h >= 3u && w <= 65535u && h <= 65535u && muff_config_ok(&mc))) {
        abort(); /* a size for invalid arguments */
    }
    if ((accq > 0u) != (wsq > 0u) || symline_muff_accumulator_size(w, h, NULL) != 0u ||
        symline_muff_cell(NULL, w) != 0u ||
        symline_muff_cell(&mc, w) != (mc.cell != 0u ? mc.cell : (w / 80u > 2u ? w / 80u : 2u))) {
        abort();
    }
    if (accq > (64u << 20)) {
        return; /* a valid but huge accumulator (cell 1 on a large frame): too slow to vote into */
    }
    accn = fz_size(in, accq > 0u ? accq : 64u);
    wsn = fz_size(in, wsq > 0u ? wsq : 64u);
    cap = fz_u8(in) % 8u == 0u ? (npoints > 0u ? npoints - 1u : 0u) : npoints + fz_u8(in) % 8u;
    outs_make(&o, fz_u8(in) % 4u == 0u ? 0u : fz_u8(in) % 24u, cap, nulls);
    acc = (nulls & 16u) && (nulls & 0xC0u) == 0xC0u ? NULL : fz_buf(accn, 0x77);
    ws = (nulls & 32u) && (nulls & 0xC0u) == 0xC0u ? NULL : fz_buf(wsn, 0x33);

    /* Strokes: n points between two ends (a line the finder should see), and
     * stray points; now and then one outside the frame or with an offset
     * beyond -64..63 (ERR_RANGE). */
    pts = (symline_point *)(void *)o.pts;
    n = 0u;
    while (n < npoints && n < cap) {
        const uint32_t kind = fz_u8(in) % 4u;
        const uint32_t x0 = fz_u16(in) % (w > 0u ? w : 1u), y0 = fz_u16(in) % (h > 0u ? h : 1u);
        if (kind == 0u) {
            pts[n].x = (uint16_t)x0;
            pts[n].y = (uint16_t)y0;
            const uint32_t odd = fz_u8(in), v = fz_u8(in);
            if (odd == 0xFFu) {
                pts[n].x = (uint16_t)(w < 65535u ? w : 65535u); /* outside */
            }
            /* an offset in -64..63, or now and then beyond it (ERR_RANGE) */
            pts[n].fx = (int8_t)(odd != 0xFEu ? (int32_t)(v % 128u) - 64
                                 : (v & 1u)   ? 64 + (int32_t)(v >> 2)
                                              : -65 - (int32_t)(v >> 2));
            pts[n].fy = 0;
            n++;
        } else {
            const uint32_t x1 = fz_u16(in) % (w > 0u ? w : 1u), y1 = fz_u16(in) % (h > 0u ? h : 1u);
            const uint32_t len = 2u + fz_u8(in) % 64u;
            for (i = 0; i < len && n < npoints && n < cap; i++, n++) {
                pts[n].x = (uint16_t)((x0 * (len - 1u - i) + x1 * i) / (len - 1u));
                pts[n].y = (uint16_t)((y0 * (len - 1u - i) + y1 * i) / (len - 1u));
                pts[n].fx = 0;
                pts[n].fy = (int8_t)(kind == 3u ? (int8_t)(i % 7u) - 3 : 0);
            }
        }
    }
    copy = (symline_point *)malloc((size_t)n * sizeof *copy + 1u);
    if (copy == NULL) {
        abort();
    }
    memcpy(copy, pts, (size_t)n * sizeof *copy);
    memcpy(&o.before, &o.r, sizeof o.r);

    st = symline_muff_find(w, h, (nulls & 0xC0u) == 0xC0u && (nulls & 8u) ? NULL : &mc,
                           (uint16_t *)(void *)acc, accn, ws, wsn, npoints > cap ? npoints : n,
                           (nulls & 0xC0u) == 0xC0u && (nulls & 1u) ? NULL : &o.r);
    fz_check_status(st, "symline_muff_find");
    if (acc != NULL) {
        fz_check_guard(acc, accn, "accumulator");
    }
    if (ws != NULL) {
        fz_check_guard(ws, wsn, "workspace");
    }
    /* Beyond the points given: never written. */
    fz_check_untouched(o.pts + (size_t)n * sizeof *pts, o.pt_bytes - (size_t)n * sizeof *pts, 0x5A,
                       "points beyond npoints");
    if (o.r.points != NULL) {
        check_same_points(copy, pts, n);
    }
    if (st != SYMLINE_OK) {
        if (memcmp(&o.r, &o.before, sizeof o.r) != 0) {
            abort();
        }
        fz_check_untouched(o.segs, o.seg_bytes, 0x5A, "segments");
        if (acc != NULL && ws != NULL && o.r.points != NULL && (nulls & 0xC0u) != 0xC0u &&
            !(o.r.segments == NULL && o.r.segment_cap != 0u) && accq > 0u && accn >= accq &&
            wsn >= wsq && npoints <= cap) {
            /* Everything valid but the points: one outside the frame or with
             * an offset beyond -64..63. */
            if (st != SYMLINE_ERR_RANGE) {
                abort();
            }
        }
    } else {
        check_result(&o.r, w, h);
    }
    free(copy);
    free(acc);
    free(ws);
    outs_free(&o);
}

/* 1: symline_detect_muff; 2: symline_line_points. */
static void entry_image(fz_in *in, int muff)
{
    symline_config cfg;
    symline_muff_config mc;
    symline_image img;
    uint32_t w = fz_dim(in), h = fz_dim(in), stride;
    const uint32_t nulls = fz_u8(in);
    size_t img_len, wsq, accq, wsn, accn;
    uint8_t *px, *ws, *acc;
    symline_status st;
    outs o;

    stride = w + (fz_u8(in) % 4u == 0u ? fz_u8(in) % 9u : 0u);
    if (fz_u8(in) % 16u == 0u && w > 0u) {
        stride = w - 1u;
    }
    fz_detect_config(in, &cfg);
    muff_config(in, &mc);
    wsq = muff ? symline_detect_muff_workspace_size(w, h, &cfg, &mc)
               : symline_detect_workspace_size(w, h, &cfg);
    accq = symline_muff_accumulator_size(w, h, &mc);
    if (accq > (64u << 20)) {
        return;
    }
    wsn = fz_size(in, wsq > 0u ? wsq : 256u);
    accn = fz_size(in, accq > 0u ? accq : 64u);
    {
        const uint32_t full = (w <= 65535u && h <= 65535u) ? 2u * w * h + 1024u : 1024u;
        const uint32_t mode = fz_u8(in) % 4u;
        const uint32_t pcap = mode == 0u ? full : (mode == 1u ? 0u : fz_u16(in) % (full + 1u));
        outs_make(&o, fz_u8(in) % 4u == 0u ? 0u : fz_u8(in) % 24u, pcap, nulls);
    }
    memcpy(&o.before, &o.r, sizeof o.r);
    ws = fz_buf(wsn, 0x33);
    acc = fz_buf(accn, 0x77);
    if (w > 65535u && h > 1u) {
        h = 1u;
    }
    px = fz_image(in, w, h, stride > w ? stride : w, &img_len);
    img.width = w;
    img.height = h;
    img.stride = stride;
    img.data = (nulls & 16u) ? NULL : px;

    if (muff) {
        const int none = (nulls & 0xC0u) == 0xC0u;
        st = symline_detect_muff(
            none && (nulls & 32u) ? NULL : &img, none && (nulls & 2u) ? NULL : &cfg,
            none && (nulls & 8u) ? NULL : &mc,
            none && (nulls & 1u) ? NULL : (uint16_t *)(void *)acc, accn,
            none && (nulls & 4u) ? NULL : ws, wsn, none && (nulls & 0x3Fu) == 0u ? NULL : &o.r);
        fz_check_status(st, "symline_detect_muff");
        if (st != SYMLINE_OK) {
            if (memcmp(&o.r, &o.before, sizeof o.r) != 0) {
                abort();
            }
            fz_check_untouched(o.segs, o.seg_bytes, 0x5A, "segments");
            fz_check_untouched(o.pts, o.pt_bytes, 0x5A, "points");
        } else {
            check_result(&o.r, w, h);
        }
    } else {
        uint32_t count = 0xDEADu, k;
        bool truncated = true;
        const int none = (nulls & 0xC0u) == 0xC0u;
        symline_point *pts = (symline_point *)(void *)o.pts;
        st = symline_line_points(
            none && (nulls & 32u) ? NULL : &img, none && (nulls & 2u) ? NULL : &cfg,
            none && (nulls & 4u) ? NULL : ws, wsn, o.r.points, o.r.point_cap,
            none && (nulls & 8u) ? NULL : &count, none && (nulls & 1u) ? NULL : &truncated);
        fz_check_status(st, "symline_line_points");
        if (st != SYMLINE_OK) {
            if (count != 0xDEADu || !truncated) {
                abort();
            }
            fz_check_untouched(o.pts, o.pt_bytes, 0x5A, "points");
        } else {
            /* (truncated with no points is possible: the points that fitted
             * may all be isolated ones, which are left out) */
            if (count > o.r.point_cap) {
                abort();
            }
            for (k = 0; k < count; k++) {
                if (pts[k].x >= w || pts[k].y >= h || pts[k].fx < -64 || pts[k].fx > 63 ||
                    pts[k].fy < -64 || pts[k].fy > 63) {
                    fprintf(stderr, "line point %u: (%u,%u) offset (%d,%d), frame %ux%u\n", k,
                            pts[k].x, pts[k].y, pts[k].fx, pts[k].fy, w, h);
                    abort();
                }
            }
        }
    }
    fz_check_guard(ws, wsn, "workspace");
    fz_check_guard(acc, accn, "accumulator");
    if (!muff) {
        fz_check_untouched(acc, accn, 0x77, "accumulator");
    }
    free(px);
    free(ws);
    free(acc);
    outs_free(&o);
}

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
    fz_in in = {data, size};
    const uint32_t entry = fz_u8(&in) % 3u;
    if (entry == 0u) {
        entry_find(&in);
    } else {
        entry_image(&in, entry == 1u);
    }
    symline_muff_config_default(NULL);
    return 0;
}

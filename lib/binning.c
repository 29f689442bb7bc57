/* SPDX-License-Identifier: Apache-2.0 */
/*
 * 2x2 binning of large frames, and their results moved back
 * (include/symline/binning.h).
 */
#include "symline/binning.h"

/* Segment coordinates (Q8) small enough to be multiplied by two in 32 bits:
 * +-2^29, far beyond any frame (SYMLINE_MAX_DIM px is below 2^24 in Q8). */
#define SL_BIN_Q8_LIMIT (INT32_C(1) << 29)

bool symline_bin2_advised(uint32_t width, uint32_t height)
{
    /* (65535^2 fits 32 bits) */
    return width <= SYMLINE_MAX_DIM && height <= SYMLINE_MAX_DIM &&
           width * height >= SYMLINE_BIN2_ADVISED_PIXELS;
}

size_t symline_bin2_size(uint32_t width, uint32_t height)
{
    if (width < 2u || height < 2u || width > SYMLINE_MAX_DIM || height > SYMLINE_MAX_DIM) {
        return 0u;
    }
    return (size_t)(width / 2u) * (height / 2u);
}

symline_status symline_bin2(const symline_image *in, uint8_t *buf, size_t size, symline_image *out)
{
    symline_status st;
    uint32_t w, h, x, y;
    if (in == NULL || buf == NULL || out == NULL) {
        return SYMLINE_ERR_NULL;
    }
    st = symline_image_check(in);
    if (st != SYMLINE_OK) {
        return st;
    }
    if (in->width < 2u || in->height < 2u) {
        return SYMLINE_ERR_SIZE;
    }
    if (size < symline_bin2_size(in->width, in->height)) {
        return SYMLINE_ERR_BUFFER;
    }
    w = in->width / 2u;
    h = in->height / 2u;
    for (y = 0; y < h; y++) {
        const uint8_t *a = in->data + (size_t)2u * y * in->stride;
        const uint8_t *b = a + in->stride;
        uint8_t *o = buf + (size_t)y * w;
        for (x = 0; x < w; x++) {
            const size_t i = (size_t)2u * x;
            const uint32_t s = (uint32_t)a[i] + a[i + 1u] + b[i] + b[i + 1u];
            o[x] = (uint8_t)((s + 2u) >> 2);
        }
    }
    out->width = w;
    out->height = h;
    out->stride = w;
    out->data = buf;
    return SYMLINE_OK;
}

/* One coordinate of a point: binned pixel p with offset f (1/128 px) lies at
 * 2 (p + f/128) + 1/2 = 2 p + (2 f + 64)/128 in the frame; v = 2 f + 64 is
 * -64..190, so the frame pixel is 2 p or 2 p + 1 and the offset stays in
 * -64..63 (exact). */
static void unbin_coord(uint16_t *p, int8_t *f)
{
    const int32_t v = 2 * (int32_t)*f + 64;
    const uint32_t q = 2u * (uint32_t)*p;
    if (v >= 64) {
        *p = (uint16_t)(q + 1u);
        *f = (int8_t)(v - 128);
    } else {
        *p = (uint16_t)q;
        *f = (int8_t)v;
    }
}

static bool q8_ok(int32_t c)
{
    return c > -SL_BIN_Q8_LIMIT && c < SL_BIN_Q8_LIMIT;
}

/* Whether everything unbin2 changes is in range: nothing is changed
 * unless all of it is. */
static symline_status unbin2_check(const symline_result *r, uint32_t w, uint32_t h)
{
    uint32_t i;
    if (r->segment_count > r->segment_cap || r->point_count > r->point_cap ||
        r->field.count > SYMLINE_FIELD_MAX_VERTICES) {
        return SYMLINE_ERR_RANGE;
    }
    if ((r->segment_count != 0u && r->segments == NULL) ||
        (r->point_count != 0u && r->points == NULL)) {
        return SYMLINE_ERR_NULL;
    }
    for (i = 0; i < r->segment_count; i++) {
        const symline_segment *s = &r->segments[i];
        if (!q8_ok(s->x0) || !q8_ok(s->y0) || !q8_ok(s->x1) || !q8_ok(s->y1) ||
            s->max_dev > 0x7FFFFFFFu || s->level == 255u) {
            return SYMLINE_ERR_RANGE;
        }
    }
    for (i = 0; i < r->point_count; i++) {
        if (r->points[i].x >= w || r->points[i].y >= h) {
            return SYMLINE_ERR_RANGE;
        }
    }
    for (i = 0; i < r->field.count; i++) {
        const symline_field_vertex *v = &r->field.v[i];
        if (v->x < 0 || (uint32_t)v->x >= w || v->y < 0 || (uint32_t)v->y > h) {
            return SYMLINE_ERR_RANGE;
        }
    }
    return SYMLINE_OK;
}

symline_status symline_result_unbin2(symline_result *r, uint32_t width, uint32_t height)
{
    const uint32_t w = width / 2u, h = height / 2u;
    symline_status st;
    uint32_t i;
    if (r == NULL) {
        return SYMLINE_ERR_NULL;
    }
    if (symline_bin2_size(width, height) == 0u) {
        return SYMLINE_ERR_SIZE;
    }
    st = unbin2_check(r, w, h);
    if (st != SYMLINE_OK) {
        return st;
    }
    for (i = 0; i < r->segment_count; i++) {
        symline_segment *s = &r->segments[i];
        s->x0 = 2 * s->x0 + 128;
        s->y0 = 2 * s->y0 + 128;
        s->x1 = 2 * s->x1 + 128;
        s->y1 = 2 * s->y1 + 128;
        s->max_dev *= 2u;
        s->level = (uint8_t)(s->level + 1u);
    }
    for (i = 0; i < r->point_count; i++) {
        unbin_coord(&r->points[i].x, &r->points[i].fx);
        unbin_coord(&r->points[i].y, &r->points[i].fy);
    }
    for (i = 0; i < r->field.count; i++) {
        symline_field_vertex *v = &r->field.v[i];
        /* The right edge stays at the edge (an odd frame's last column was
         * left out of the binned one); "no field" stays below the frame. */
        v->x = v->x != 0 && (uint32_t)v->x + 1u == w ? (int32_t)width - 1 : 2 * v->x;
        v->y = (uint32_t)v->y == h ? (int32_t)height : 2 * v->y;
    }
    if (r->field.count == 1u && width > 1u) {
        /* A binned frame one pixel wide has one vertex; the frame has two edges. */
        r->field.v[1].x = (int32_t)width - 1;
        r->field.v[1].y = r->field.v[0].y;
        r->field.count = 2u;
    }
    if (r->field.count != 0u) {
        r->field.cell = (uint8_t)(r->field.cell <= 127u ? 2u * r->field.cell : 255u);
    }
    return SYMLINE_OK;
}

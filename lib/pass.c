/*
 * One pass (an axis at one scale) of the detector. It collects its line
 * points into the caller's point storage (raster order, strip processing),
 * traces them from the storage's free tail, turns the chains into segments
 * and compacts the points it keeps down to where the pass began. Parts of a
 * chain that an earlier pass (finer scale, or the horizontal axis at the same
 * scale) already reported are left out, so one physical line is reported once.
 */
#include "detect_internal.h"
#include "stagemark.h"

static int covered(const sl_run *d, const symline_point *q, uint32_t level)
{
    const int32_t x = sl_q8(q->x, level), y = sl_q8(q->y, level);
    const int32_t tol = 512 + (int32_t)(((1u << level) - 1u) << 8);
    uint32_t i;
    for (i = 0; i < d->prev_seg; i++) {
        if (sl_near_segment(&d->r->segments[i], d->r->points, x, y, tol)) {
            return 1;
        }
    }
    return 0;
}

/*
 * The contrast filter's "sides alike" test once more, over the whole piece:
 * the gray values k grid px to either side across the line (full-resolution
 * pixels), summed along the piece, must differ by less than the summed ridge
 * over twice contrast_asym_pct. Summing averages out the carpet's texture and
 * the noise that make the test per point loose, so it can be stricter here: a
 * bright band between two different surfaces (the foot of a wall, the floor
 * beyond the carpet, the rim of a robot) lies on no carpet on one side.
 * At most 4096 points are summed, so every product stays in 32 bits.
 */
#define SL_SIDE_SAMPLES 4096u
SL_NOINLINE static int sides_differ(const sl_run *d, const sl_pass *p, const symline_point *q,
                                    uint32_t n)
{
    const symline_image *img = d->img;
    const int horiz = p->axis == SYMLINE_AXIS_HORIZONTAL;
    const uint32_t half = (1u << p->level) >> 1, off = p->k << p->level;
    const uint32_t step = n / SL_SIDE_SAMPLES + 1u;
    const size_t across = horiz ? img->stride : 1u;
    const uint32_t lim = horiz ? img->height : img->width;
    uint32_t slo = 0u, shi = 0u, sc = 0u, i, side;
    for (i = 0; i < n; i += step) {
        /* Grid points map inside the frame: (v << level) + half < size. */
        const uint32_t x = ((uint32_t)q[i].x << p->level) + half;
        const uint32_t y = ((uint32_t)q[i].y << p->level) + half;
        const uint32_t pos = horiz ? y : x;
        const uint8_t *c = img->data + (size_t)y * img->stride + x;
        sc += *c;
        slo += *(c - (size_t)(pos >= off ? off : pos) * across);
        shi += *(c + (size_t)(pos + off < lim ? off : lim - 1u - pos) * across);
    }
    side = slo > shi ? slo : shi;
    return sc <= side || (slo > shi ? slo - shi : shi - slo) * (2u * p->apct) > (sc - side) * 100u;
}

/* One piece of a chain (grid coordinates, absolute storage index `at`). */
static void emit(sl_run *d, const sl_pass *p, uint32_t at, uint32_t n)
{
    symline_point *q = d->r->points + at;
    const uint32_t half = (1u << p->level) >> 1;
    symline_segment *s;
    uint32_t i;
    if ((n << p->level) < d->cfg->min_length || n < 2u) {
        return;
    }
    if (p->filter == SYMLINE_FILTER_CONTRAST && p->apct != 0u && sides_differ(d, p, q, n)) {
        return;
    }
    if (d->nseg >= d->r->segment_cap) {
        d->truncated = 1u;
        return;
    }
    s = &d->r->segments[d->nseg++];
    sl_fit(q, n, p->level, d->cfg->curve_dev_q8, s);
    /* A flat arc stays under the deviation threshold but bends: a curve too.
     * Only at the two finest scales: coarser grids step by 4 px and more. */
    if (s->kind == SYMLINE_KIND_LINE && d->cfg->curve_bend_q8 != 0u && p->level <= 1u &&
        (n << p->level) >= 16u) {
        sl_bend_check(q, n, p->level, d->cfg->curve_bend_q8, s);
    }
    s->axis = (uint8_t)p->axis;
    s->first = at;
    s->count = n;
    for (i = 0; i < n; i++) {
        q[i].x = (uint16_t)(((uint32_t)q[i].x << p->level) + half);
        q[i].y = (uint16_t)(((uint32_t)q[i].y << p->level) + half);
    }
}

/* A traced chain at storage index `at`: drop covered parts, cut at corners, emit pieces. */
static void chain(sl_run *d, const sl_pass *p, uint32_t at, uint32_t n)
{
    const symline_point *c = d->r->points + at;
    uint32_t i = 0u;
    while (i < n) {
        uint32_t j, s;
        while (i < n && covered(d, &c[i], p->level)) {
            i++;
        }
        j = i;
        while (j < n && !covered(d, &c[j], p->level)) {
            j++;
        }
        for (s = i; s < j;) {
            const uint32_t len = sl_corner_cut(c + s, j - s);
            emit(d, p, at + s, len);
            s += len;
        }
        i = j;
    }
}

/* Traces the pass's raster list (n points at *npts) and keeps its segments'
 * points right after the earlier passes' ones. t: the tracer's state, in the
 * caller's workspace. */
void sl_trace_pass(sl_run *d, const sl_pass *p, const uint32_t *row_start, uint32_t n,
                   sl_tracer *t, uint32_t *npts)
{
    symline_result *r = d->r;
    const uint32_t base = *npts;
    const uint32_t first_seg = d->nseg;
    uint32_t tail = base + n, cnt, k, w;
    uint8_t cut = 0u;
    sl_tracer_init(t, r->points + base, n, row_start, p->h);
    SL_STAGE(TRACE);
    while (tail < r->point_cap &&
           sl_tracer_next(t, r->points + tail, r->point_cap - tail, &cnt, &cut)) {
        SL_STAGE(SEGMENTS);
        chain(d, p, tail, cnt);
        tail += cnt;
        SL_STAGE(TRACE);
    }
    SL_STAGE(SEGMENTS);
    if (cut || (tail >= r->point_cap && n > 0u)) {
        d->truncated = 1u;
    }
    /* Keep only the points the new segments use, right after the earlier ones. */
    w = base;
    for (k = first_seg; k < d->nseg; k++) {
        symline_segment *s = &r->segments[k];
        uint32_t i;
        for (i = 0; i < s->count; i++) {
            r->points[w + i].x = r->points[s->first + i].x;
            r->points[w + i].y = r->points[s->first + i].y;
        }
        s->first = w;
        w += s->count;
    }
    *npts = w;
    d->prev_seg = d->nseg;
}

/*
 * symline_detect(): configuration, workspace, the frame statistics of the
 * adaptive thresholds, the passes over axes and scales (pass.c), the final
 * merge (merge.c) and the curve continuation (curvejoin.c).
 */
#include "detect_internal.h"

void symline_config_default(symline_config *cfg)
{
    if (cfg == NULL) {
        return;
    }
    cfg->axes = SYMLINE_AXES_BOTH;
    cfg->radius = 3u;
    cfg->levels = 0u;
    cfg->filter = SYMLINE_FILTER_CONTRAST;
    cfg->illumination = 0u;
    cfg->adaptive = 1u;
    cfg->bright_sigma10 = 0;
    cfg->ridge_sigma10 = 10u;
    cfg->side_sigma10 = 15;
    cfg->a_distance = 0u;
    cfg->contrast_pct = 0u;
    cfg->contrast_min = 3u;
    cfg->contrast_asym_pct = 150u;
    cfg->min_length = 12u;
    cfg->curve_dev_q8 = 512u;
    cfg->curve_bend_q8 = 80u;
    cfg->merge_gap = 0xFFFFFFFFu;
    cfg->merge_dev_q8 = 640u;
}

#define SL_MAX_DETECT_RADIUS 32u
#define SL_MAX_LEVELS 5u

static symline_status check_config(const symline_config *c)
{
    if (c->axes != SYMLINE_AXES_HORIZONTAL && c->axes != SYMLINE_AXES_VERTICAL &&
        c->axes != SYMLINE_AXES_BOTH) {
        return SYMLINE_ERR_CONFIG;
    }
    if (c->radius < 1u || c->radius > SL_MAX_DETECT_RADIUS || c->levels > SL_MAX_LEVELS) {
        return SYMLINE_ERR_CONFIG;
    }
    if (c->filter != SYMLINE_FILTER_CONTRAST && c->filter != SYMLINE_FILTER_PAPER) {
        return SYMLINE_ERR_CONFIG;
    }
    if (c->illumination > 255u || c->adaptive > 1u || c->bright_sigma10 < -100 ||
        c->bright_sigma10 > 100 || c->ridge_sigma10 > 100u || c->side_sigma10 < -100 ||
        c->side_sigma10 > 100 || c->a_distance > 32u || c->contrast_pct > 100u ||
        c->contrast_min > 255u || c->contrast_asym_pct > 1000u || c->min_length > SYMLINE_MAX_DIM ||
        c->curve_dev_q8 > (SYMLINE_MAX_DIM << 8) || c->curve_bend_q8 > (SYMLINE_MAX_DIM << 8) ||
        c->merge_dev_q8 > (SYMLINE_MAX_DIM << 8)) {
        return SYMLINE_ERR_CONFIG;
    }
    return SYMLINE_OK;
}

/* Number of scales: as configured, or enough that the coarsest one reaches
 * lines width/16 px wide (radius m spans lines up to about 2m+1 px); never
 * a grid smaller than the operator's window. */
static uint32_t level_count(const symline_config *c, uint32_t width, uint32_t height)
{
    uint32_t L = c->levels;
    const uint32_t span = 2u * c->radius + 1u;
    if (L == 0u) {
        L = 1u;
        while (L < SL_MAX_LEVELS && (span << (L - 1u)) < width / 16u) {
            L++;
        }
    }
    while (L > 1u && ((width >> (L - 1u)) < span + 2u || (height >> (L - 1u)) < span + 2u)) {
        L--;
    }
    return L;
}

static uint32_t axis_count(const symline_config *c)
{
    return c->axes == SYMLINE_AXES_BOTH ? 2u : 1u;
}

static symline_axis axis_of(const symline_config *c, uint32_t i)
{
    if (c->axes == SYMLINE_AXES_BOTH) {
        return i == 0u ? SYMLINE_AXIS_HORIZONTAL : SYMLINE_AXIS_VERTICAL;
    }
    return c->axes == SYMLINE_AXES_VERTICAL ? SYMLINE_AXIS_VERTICAL : SYMLINE_AXIS_HORIZONTAL;
}

/* A pass's workspace: its state, the row index, and the collection's rings
 * (reused by the tracer's state afterwards). Small state lives here rather
 * than on the stack, which must stay within a firmware's budget. */
static size_t pass_ws_size(const sl_pass *p, uint32_t width)
{
    size_t c = sl_collect_ws_size(p, width);
    const size_t t = sl_align_up(sizeof(sl_tracer)) + SL_ALIGN;
    return sl_align_up(sizeof(sl_pass)) + SL_ALIGN + sl_align_up(((size_t)p->h + 1u) * 4u) +
           SL_ALIGN + (c > t ? c : t);
}

SL_NOINLINE size_t symline_detect_workspace_size(uint32_t width, uint32_t height, const symline_config *cfg)
{
    uint32_t L, l, a;
    size_t best = 0u;
    if (cfg == NULL || width == 0u || height == 0u || width > SYMLINE_MAX_DIM ||
        height > SYMLINE_MAX_DIM || check_config(cfg) != SYMLINE_OK) {
        return 0u;
    }
    L = level_count(cfg, width, height);
    for (l = 0; l < L; l++) {
        for (a = 0; a < axis_count(cfg); a++) {
            sl_pass p;
            size_t n;
            sl_pass_setup(&p, cfg, axis_of(cfg, a), l, width, height);
            n = pass_ws_size(&p, width);
            best = n > best ? n : best;
        }
    }
    return best;
}

/* Mean and standard deviation (Q4) of the frame's gray values: one read of
 * the frame, summed per row so a row's sums stay in 32 bits. */
SL_NOINLINE static void frame_stats(const symline_image *img, uint32_t *mean, uint32_t *sigma_q4)
{
    uint64_t sum = 0u, sq = 0u;
    const uint64_t n = (uint64_t)img->width * img->height;
    int64_t var_q8;
    uint32_t x, y;
    *mean = 0u;
    *sigma_q4 = 0u;
    if (n == 0u) {
        return;
    }
    for (y = 0; y < img->height; y++) {
        const uint8_t *row = img->data + (size_t)y * img->stride;
        uint32_t rs = 0u, rq = 0u; /* 255^2 * 65535 < 2^32 */
        for (x = 0; x < img->width; x++) {
            const uint32_t v = row[x];
            rs += v;
            rq += v * v;
        }
        sum += rs;
        sq += rq;
    }
    *mean = (uint32_t)((sum + n / 2u) / n);
    /* var = sq/n - (sum/n)^2, in Q8 (rounding may make it slightly negative). */
    var_q8 = (int64_t)((sq << 8) / n) - (int64_t)(((sum << 4) / n) * ((sum << 4) / n));
    *sigma_q4 = var_q8 > 0 ? (uint32_t)sl_isqrt64((uint64_t)var_q8) : 0u;
}

/* The adaptive thresholds folded into a pass. */
static void adapt(sl_pass *p, const symline_config *cfg, uint32_t mean, uint32_t sigma_q4)
{
    const int64_t t = (int64_t)mean + (int64_t)cfg->bright_sigma10 * sigma_q4 / 160;
    const uint32_t ridge = (uint32_t)(((uint64_t)cfg->ridge_sigma10 * sigma_q4 + 80u) / 160u);
    const uint32_t illum = t < 0 ? 0u : (t > 255 ? 255u : (uint32_t)t);
    if (illum > p->illum) {
        p->illum = illum;
    }
    if (ridge > p->cmin) {
        p->cmin = ridge;
    }
    if (cfg->side_sigma10 < 100) {
        const int64_t sm = (int64_t)mean + (int64_t)cfg->side_sigma10 * sigma_q4 / 160;
        p->side_max = sm < 0 ? 0u : (sm > 255 ? 255u : (uint32_t)sm);
    }
}

/* Every pass, fine scale first, horizontal before vertical; returns the
 * number of points kept. Kept apart from symline_detect() so that the pass
 * state and the merge are never on the stack together. */
SL_NOINLINE static uint32_t run_passes(const symline_image *img, const symline_config *cfg,
                                       uint8_t *ws, size_t ws_size, sl_run *d)
{
    uint32_t L, l, a, npts = 0u;
    uint8_t *cur = ws, *const end = ws + ws_size;
    sl_pass *p = (sl_pass *)sl_carve(&cur, end, sizeof(sl_pass));
    L = level_count(cfg, img->width, img->height);
    for (l = 0; l < L && p != NULL; l++) {
        for (a = 0; a < axis_count(cfg); a++) {
            uint8_t *rest = cur;
            uint32_t *row_start;
            uint32_t n = 0u;
            sl_tracer *t;
            sl_pass_setup(p, cfg, axis_of(cfg, a), l, img->width, img->height);
            if (cfg->adaptive) {
                adapt(p, cfg, d->mean, d->sigma_q4);
            }
            row_start = (uint32_t *)sl_carve(&rest, end, ((size_t)p->h + 1u) * sizeof(uint32_t));
            /* The collection's rings are free again once it returns: the tracer's
             * state takes their place. */
            (void)sl_collect(img, p, rest, (size_t)(end - rest), d->r->points + npts,
                             d->r->point_cap - npts, &n, row_start, &d->truncated);
            t = (sl_tracer *)sl_carve(&rest, end, sizeof(sl_tracer));
            if (row_start == NULL || t == NULL) {
                return npts; /* not reached: the workspace size was checked */
            }
            sl_trace_pass(d, p, row_start, n, t, &npts);
        }
    }
    return npts;
}

symline_status symline_detect(const symline_image *img, const symline_config *cfg, void *ws,
                              size_t ws_size, symline_result *out)
{
    symline_status st = symline_image_check(img);
    sl_run d;
    if (st != SYMLINE_OK) {
        return st;
    }
    if (cfg == NULL || ws == NULL || out == NULL) {
        return SYMLINE_ERR_NULL;
    }
    if ((out->segments == NULL && out->segment_cap != 0u) ||
        (out->points == NULL && out->point_cap != 0u)) {
        return SYMLINE_ERR_NULL;
    }
    st = check_config(cfg);
    if (st != SYMLINE_OK) {
        return st;
    }
    if (ws_size < symline_detect_workspace_size(img->width, img->height, cfg)) {
        return SYMLINE_ERR_BUFFER;
    }
    d.cfg = cfg;
    d.img = img;
    d.r = out;
    d.nseg = 0u;
    d.prev_seg = 0u;
    d.truncated = 0u;
    d.mean = 0u;
    d.sigma_q4 = 0u;
    if (cfg->adaptive) {
        frame_stats(img, &d.mean, &d.sigma_q4);
    }
    out->point_count = run_passes(img, cfg, (uint8_t *)ws, ws_size, &d);
    out->segment_count = d.nseg;
    if (cfg->merge_gap != 0u) {
        const uint32_t gap = cfg->merge_gap == 0xFFFFFFFFu ? img->width / 8u : cfg->merge_gap;
        sl_merge(out, gap, cfg->merge_dev_q8, cfg->curve_dev_q8);
    }
    sl_curve_join(out, cfg->curve_bend_q8 != 0u);
    out->truncated = d.truncated;
    return SYMLINE_OK;
}

/* Leaves out the points of a pass's raster list pts[0..n-1] that have no line
 * point among their 8 neighbours (type A, SPEC §4: neither method uses them),
 * moves the rest to the front at full resolution (a coarse scale's point at
 * its block's centre) and returns their number. */
SL_NOINLINE static uint32_t drop_isolated(const sl_pass *p, symline_point *pts, uint32_t n,
                                          const uint32_t *row_start, uint32_t level)
{
    sl_tracer t;
    uint32_t y, i, k = 0u;
    const uint32_t half = ((1u << level) - 1u) >> 1;
    sl_tracer_init(&t, pts, n, row_start, p->h);
    /* mark first (a lookup reads only x and the row index), then compact */
    for (y = 0; y < p->h; y++) {
        for (i = row_start[y]; i < row_start[y + 1u]; i++) {
            if (sl_neighbours(&t, pts[i].x, y) == 0u) {
                pts[i].y = SL_VISITED;
            }
        }
    }
    for (i = 0; i < n; i++) {
        if (pts[i].y != SL_VISITED) {
            pts[k].x = (uint16_t)((pts[i].x << level) + half);
            pts[k].y = (uint16_t)((pts[i].y << level) + half);
            k++;
        }
    }
    return k;
}

symline_status symline_line_points(const symline_image *img, const symline_config *cfg, void *ws,
                                   size_t ws_size, symline_point *pts, uint32_t cap,
                                   uint32_t *count, uint8_t *truncated)
{
    symline_status st = symline_image_check(img);
    uint32_t mean = 0u, sigma_q4 = 0u, L, l, a, n = 0u;
    uint8_t *end;
    if (st != SYMLINE_OK) {
        return st;
    }
    if (cfg == NULL || ws == NULL || count == NULL || truncated == NULL ||
        (pts == NULL && cap != 0u)) {
        return SYMLINE_ERR_NULL;
    }
    st = check_config(cfg);
    if (st != SYMLINE_OK) {
        return st;
    }
    if (ws_size < symline_detect_workspace_size(img->width, img->height, cfg)) {
        return SYMLINE_ERR_BUFFER;
    }
    *truncated = 0u;
    end = (uint8_t *)ws + ws_size;
    if (cfg->adaptive) {
        frame_stats(img, &mean, &sigma_q4);
    }
    L = level_count(cfg, img->width, img->height);
    for (l = 0; l < L; l++) {
        for (a = 0; a < axis_count(cfg); a++) {
            uint8_t *cur = (uint8_t *)ws;
            sl_pass *p = (sl_pass *)sl_carve(&cur, end, sizeof(sl_pass));
            uint32_t *row_start;
            uint32_t got = 0u;
            if (p == NULL) {
                return SYMLINE_ERR_BUFFER;
            }
            sl_pass_setup(p, cfg, axis_of(cfg, a), l, img->width, img->height);
            if (cfg->adaptive) {
                adapt(p, cfg, mean, sigma_q4);
            }
            row_start = (uint32_t *)sl_carve(&cur, end, ((size_t)p->h + 1u) * sizeof(uint32_t));
            if (row_start == NULL) {
                return SYMLINE_ERR_BUFFER;
            }
            (void)sl_collect(img, p, cur, (size_t)(end - cur), pts + n, cap - n, &got, row_start,
                             truncated);
            n += drop_isolated(p, pts + n, got, row_start, l);
        }
    }
    *count = n;
    return SYMLINE_OK;
}

/*
 * symline_detect(): configuration, workspace and the passes over axes and
 * scales. Each pass collects its line points into the caller's point storage
 * (raster order, strip processing), traces them from the storage's free
 * tail, turns the chains into segments and compacts the points it keeps
 * down to where the pass began. Parts of a chain that an earlier pass (finer
 * scale, or the horizontal axis at the same scale) already reported are
 * left out, so one physical line is reported once.
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
    cfg->side_sigma10 = 100;
    cfg->a_distance = 0u;
    cfg->contrast_pct = 0u;
    cfg->contrast_min = 3u;
    cfg->contrast_asym_pct = 0u;
    cfg->min_length = 12u;
    cfg->curve_dev_q8 = 512u;
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
        c->contrast_min > 255u || c->contrast_asym_pct > 1000u ||  c->min_length > SYMLINE_MAX_DIM ||
        c->curve_dev_q8 > (SYMLINE_MAX_DIM << 8) || c->merge_dev_q8 > (SYMLINE_MAX_DIM << 8)) {
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

static size_t pass_ws_size(const sl_pass *p, uint32_t width)
{
    return sl_align_up(((size_t)p->h + 1u) * sizeof(uint32_t)) + SL_ALIGN +
           sl_collect_ws_size(p, width);
}

size_t symline_detect_workspace_size(uint32_t width, uint32_t height, const symline_config *cfg)
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

/* State of one detection shared by the passes. */
typedef struct detect_run {
    const symline_config *cfg;
    symline_result *r;
    uint32_t nseg;    /* segments so far */
    uint32_t prev_seg; /* segments of earlier passes: [0, prev_seg) */
    uint8_t truncated;
} detect_run;

static int covered(const detect_run *d, const symline_point *q, uint32_t level)
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

/* One piece of a chain (grid coordinates, absolute storage index `at`). */
static void emit(detect_run *d, const sl_pass *p, uint32_t at, uint32_t n)
{
    symline_point *q = d->r->points + at;
    const uint32_t half = (1u << p->level) >> 1;
    symline_segment *s;
    uint32_t i;
    if ((n << p->level) < d->cfg->min_length || n < 2u) {
        return;
    }
    if (d->nseg >= d->r->segment_cap) {
        d->truncated = 1u;
        return;
    }
    s = &d->r->segments[d->nseg++];
    sl_fit(q, n, p->level, d->cfg->curve_dev_q8, s);
    s->axis = (uint8_t)p->axis;
    s->first = at;
    s->count = n;
    for (i = 0; i < n; i++) {
        q[i].x = (uint16_t)(((uint32_t)q[i].x << p->level) + half);
        q[i].y = (uint16_t)(((uint32_t)q[i].y << p->level) + half);
    }
}

/* A traced chain at storage index `at`: drop covered parts, cut at corners, emit pieces. */
static void chain(detect_run *d, const sl_pass *p, uint32_t at, uint32_t n)
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

/* Runs one pass; points of earlier passes occupy [0, *npts). */
static void run_pass(detect_run *d, const symline_image *img, const sl_pass *p, uint8_t *ws,
                     size_t ws_size, uint32_t *npts)
{
    symline_result *r = d->r;
    const uint32_t base = *npts;
    uint8_t *cur = ws, *end = ws + ws_size;
    uint32_t *row_start = (uint32_t *)sl_carve(&cur, end, ((size_t)p->h + 1u) * sizeof(uint32_t));
    uint32_t n = 0u, tail, cnt, k, w;
    uint8_t cut = 0u;
    sl_tracer t;
    const uint32_t first_seg = d->nseg;
    (void)sl_collect(img, p, cur, (size_t)(end - cur), r->points + base, r->point_cap - base, &n,
                     row_start, &d->truncated);
    sl_tracer_init(&t, r->points + base, n, row_start, p->h);
    tail = base + n;
    while (tail < r->point_cap &&
           sl_tracer_next(&t, r->points + tail, r->point_cap - tail, &cnt, &cut)) {
        chain(d, p, tail, cnt);
        tail += cnt;
    }
    if (cut || (tail >= r->point_cap && n > 0u)) {
        d->truncated = 1u;
    }
    /* Keep only the points the new segments use, right after the earlier ones. */
    w = base;
    for (k = first_seg; k < d->nseg; k++) {
        symline_segment *s = &r->segments[k];
        uint32_t i;
        for (i = 0; i < s->count; i++) {
            r->points[w + i] = r->points[s->first + i];
        }
        s->first = w;
        w += s->count;
    }
    *npts = w;
    d->prev_seg = d->nseg;
}

/* Mean and standard deviation (Q4) of the frame's gray values: one read of
 * the frame, summed per row so a row's sums stay in 32 bits. */
static void frame_stats(const symline_image *img, uint32_t *mean, uint32_t *sigma_q4)
{
    uint64_t sum = 0u, sq = 0u, n, var_q8;
    uint32_t x, y;
    for (y = 0; y < img->height; y++) {
        const uint8_t *row = img->data + (size_t)y * img->stride;
        uint32_t rs = 0u;
        uint64_t rq = 0u;
        for (x = 0; x < img->width; x++) {
            rs += row[x];
            rq += (uint32_t)row[x] * row[x];
        }
        sum += rs;
        sq += rq;
    }
    n = (uint64_t)img->width * img->height;
    *mean = (uint32_t)((sum + n / 2u) / n);
    /* var = sq/n - (sum/n)^2, in Q8: (256 sq n - 256 sum^2) / n^2, kept in 64 bits. */
    var_q8 = ((sq << 8) / n) - (((sum << 4) / n) * ((sum << 4) / n));
    if ((int64_t)var_q8 < 0) {
        var_q8 = 0u;
    }
    *sigma_q4 = (uint32_t)sl_isqrt64(var_q8);
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

symline_status symline_detect(const symline_image *img, const symline_config *cfg, void *ws,
                              size_t ws_size, symline_result *out)
{
    symline_status st = symline_image_check(img);
    detect_run d;
    uint32_t L, l, a, npts = 0u, mean = 0u, sigma_q4 = 0u;
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
    d.r = out;
    d.nseg = 0u;
    d.prev_seg = 0u;
    d.truncated = 0u;
    out->segment_count = 0u;
    if (cfg->adaptive) {
        frame_stats(img, &mean, &sigma_q4);
    }
    L = level_count(cfg, img->width, img->height);
    for (l = 0; l < L; l++) {
        for (a = 0; a < axis_count(cfg); a++) {
            sl_pass p;
            sl_pass_setup(&p, cfg, axis_of(cfg, a), l, img->width, img->height);
            if (cfg->adaptive) {
                adapt(&p, cfg, mean, sigma_q4);
            }
            run_pass(&d, img, &p, (uint8_t *)ws, ws_size, &npts);
        }
    }
    out->segment_count = d.nseg;
    out->point_count = npts;
    if (cfg->merge_gap != 0u) {
        const uint32_t gap = cfg->merge_gap == 0xFFFFFFFFu ? img->width / 8u : cfg->merge_gap;
        sl_merge(out, gap, cfg->merge_dev_q8, cfg->curve_dev_q8);
    }
    out->truncated = d.truncated;
    return SYMLINE_OK;
}

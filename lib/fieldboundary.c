/*
 * The field boundary from gray alone (include/symline/field.h).
 *
 * 1. Grid: cells of s x s pixels counted from the bottom of the frame; a cell
 *    is described by one row through its middle: its mean gray value and its
 *    texture (mean |difference| of horizontal neighbours over the mean, Q8,
 *    which a carpet's grain keeps in sunlight and in shadow). Reading one row
 *    in s keeps the stage at a fraction of an instruction per pixel.
 * 2. Carpet model: the median and the median absolute deviation of the cell
 *    means, and the median texture, over the lowest band of rows. Medians
 *    ignore what stands on the carpet there (lines, feet, the robot's own body,
 *    a lens's dark corners) as long as the carpet is most of the band.
 * 3. Column scan: per grid column, bottom to top. A cell with carpet texture
 *    whose brightness continues the column's carpet (a running mean follows
 *    the slow drift with distance) or fits the model scores +1; one with
 *    carpet texture but another brightness (a shadow's or a sunlit patch's
 *    edge; the running mean jumps after it) -1; any other -miss_cost. The top
 *    of the best-scoring run is the column's top (gaps such as a line crossing
 *    the carpet are bridged when enough carpet lies above them).
 * 4. A 3-column median removes single-column spikes; the upper convex hull of
 *    the column tops is the boundary (what cuts into the carpet from above
 *    stays under the hull; a field seen from inside is convex, so is its image
 *    with a barrel-distorting lens), thinned to SYMLINE_FIELD_MAX_VERTICES by
 *    dropping the vertices that move it least.
 */
#include "fieldboundary.h"

#define SL_FIELD_BINS 64u

void symline_field_config_default(symline_field_config *fc)
{
    if (fc == NULL) {
        return;
    }
    fc->cell = 0u;
    fc->band_pct = 40u;
    fc->mean_tol = 24u;
    fc->mad_x4 = 12u;
    fc->tol_max = 64u;
    fc->tex_lo_pct = 25u;
    fc->tex_hi_pct = 400u;
    fc->miss_cost = 2u;
    fc->local_tol = 16u;
}

static int config_ok(const symline_field_config *fc)
{
    const uint32_t c = fc->cell;
    return (c == 0u || (c >= 2u && c <= 64u && (c & (c - 1u)) == 0u)) && fc->band_pct >= 1u &&
           fc->band_pct <= 100u && fc->mean_tol <= 255u && fc->mad_x4 <= 64u &&
           fc->tol_max <= 255u && fc->tex_lo_pct <= 100u && fc->tex_hi_pct >= 100u &&
           fc->tex_hi_pct <= 10000u && fc->miss_cost >= 1u && fc->miss_cost <= 16u && fc->local_tol <= 255u;
}

uint32_t sl_field_cell(uint32_t width, const symline_field_config *fc)
{
    uint32_t s = 2u;
    if (fc->cell != 0u) {
        return fc->cell;
    }
    while (s < 16u && s * 2u * 64u <= width) {
        s *= 2u;
    }
    return s;
}

/* Per grid column: scan state, then the column top (pixels), then the hull. */
typedef struct sl_fcol {
    int32_t cur;  /* score of the run ending at the current row */
    int32_t best; /* best score seen */
    int32_t top;  /* its top row (grid rows from the bottom), -1 = none */
    int32_t ema;  /* running mean of the column's carpet cells, Q4 */
} sl_fcol;

typedef struct sl_fstate {
    uint32_t s, k, nc, nr;
    uint32_t lo, hi;         /* accepted cell means */
    uint32_t mid;            /* the carpet's median */
    uint32_t tex_lo, tex_hi; /* accepted cell textures, Q1 */
    uint32_t hm[SL_FIELD_BINS], ht[SL_FIELD_BINS];
} sl_fstate;

static size_t cols_bytes(uint32_t nc)
{
    return sl_align_up((size_t)nc * sizeof(sl_fcol));
}

size_t symline_field_workspace_size(uint32_t width, uint32_t height,
                                    const symline_field_config *fc)
{
    uint32_t s;
    if (fc == NULL || width == 0u || height == 0u || width > SYMLINE_MAX_DIM ||
        height > SYMLINE_MAX_DIM || !config_ok(fc)) {
        return 0u;
    }
    s = sl_field_cell(width, fc);
    return sl_align_up(sizeof(sl_fstate)) + cols_bytes((width + s - 1u) / s) + 2u * SL_ALIGN;
}

/* Middle row of grid row r (0 = the lowest). */
static uint32_t sample_row(const sl_fstate *f, uint32_t h, uint32_t r)
{
    const uint32_t bottom = h - r * f->s; /* exclusive */
    const uint32_t top = bottom > f->s ? bottom - f->s : 0u;
    return (top + bottom - 1u) / 2u;
}

/* Mean and relative texture (Q8, clamped to 255) of cell c in a row. */
static void cell_stats(const sl_fstate *f, const uint8_t *row, uint32_t w, uint32_t c,
                       uint32_t *mean, uint32_t *tex)
{
    const uint32_t x0 = c * f->s;
    const uint32_t n = (x0 + f->s <= w) ? f->s : w - x0;
    const uint8_t *p = row + x0;
    uint32_t i, sum = 0u, d = 0u, t;
    for (i = 0; i < n; i++) {
        sum += p[i];
    }
    for (i = 1; i < n; i++) {
        d += p[i] > p[i - 1] ? (uint32_t)(p[i] - p[i - 1]) : (uint32_t)(p[i - 1] - p[i]);
    }
    *mean = n == f->s ? sum >> f->k : sum / n;
    t = n > 1u ? (d << 8) / (sum + n) : 0u;
    *tex = t < 255u ? t : 255u;
}

/* Smallest bin value v with at least half the count at or below it. */
static uint32_t hist_median(const uint32_t *hist, uint32_t total)
{
    uint32_t i, acc = 0u;
    for (i = 0; i < SL_FIELD_BINS; i++) {
        acc += hist[i];
        if (2u * acc >= total) {
            return i;
        }
    }
    return SL_FIELD_BINS - 1u;
}

/* Median absolute deviation (bins) around bin m. */
static uint32_t hist_mad(const uint32_t *hist, uint32_t total, uint32_t m)
{
    uint32_t d, acc = hist[m];
    for (d = 1u; d < SL_FIELD_BINS && 2u * acc < total; d++) {
        acc += (m >= d ? hist[m - d] : 0u) + (m + d < SL_FIELD_BINS ? hist[m + d] : 0u);
        if (2u * acc >= total) {
            return d;
        }
    }
    return 0u;
}

/* The carpet model from the lowest band of grid rows. */
SL_NOINLINE static void carpet_model(const symline_image *img, const symline_field_config *fc,
                                     sl_fstate *f, symline_field_boundary *out)
{
    uint32_t r, c, i, total, mb, tb, tol, mad;
    uint32_t nb = (f->nr * fc->band_pct + 99u) / 100u;
    nb = nb < 1u ? 1u : nb;
    for (i = 0; i < SL_FIELD_BINS; i++) {
        f->hm[i] = 0u;
        f->ht[i] = 0u;
    }
    for (r = 0; r < nb; r++) {
        const uint8_t *row = img->data + (size_t)sample_row(f, img->height, r) * img->stride;
        for (c = 0; c < f->nc; c++) {
            uint32_t m, t;
            cell_stats(f, row, img->width, c, &m, &t);
            f->hm[m >> 2]++;
            f->ht[t >> 2]++;
        }
    }
    total = nb * f->nc;
    mb = hist_median(f->hm, total);
    tb = 4u * hist_median(f->ht, total) + 2u;
    mad = 4u * hist_mad(f->hm, total, mb); /* gray levels */
    tol = mad * fc->mad_x4 / 4u;
    tol = tol > fc->tol_max ? fc->tol_max : tol;
    tol = tol < fc->mean_tol ? fc->mean_tol : tol;
    {
        const uint32_t m = 4u * mb + 2u;
        f->lo = m > tol ? m - tol : 0u;
        f->hi = m + tol;
        f->mid = m;
        out->carpet_mean = (uint8_t)m;
        out->carpet_tol = (uint8_t)(tol > 255u ? 255u : tol);
    }
    f->tex_lo = tb * fc->tex_lo_pct / 100u;
    f->tex_hi = tb * fc->tex_hi_pct / 100u + 4u;
    out->carpet_tex = (uint8_t)(tb > 255u ? 255u : tb);
}

/* Upward scan of every column: the best-scoring run of carpet. */
SL_NOINLINE static void scan_columns(const symline_image *img, const symline_field_config *fc,
                                     const sl_fstate *f, sl_fcol *col)
{
    uint32_t r, c;
    const int32_t miss = -(int32_t)fc->miss_cost;
    for (c = 0; c < f->nc; c++) {
        col[c].cur = 0;
        col[c].best = 0;
        col[c].top = -1;
        col[c].ema = (int32_t)(f->mid << 4);
    }
    for (r = 0; r < f->nr; r++) {
        const uint8_t *row = img->data + (size_t)sample_row(f, img->height, r) * img->stride;
        for (c = 0; c < f->nc; c++) {
            uint32_t m, t;
            int32_t v;
            sl_fcol *q = &col[c];
            cell_stats(f, row, img->width, c, &m, &t);
            if (t < f->tex_lo || t > f->tex_hi) {
                v = miss; /* too smooth or too busy: not carpet */
            } else {
                /* Carpet texture: carpet when its brightness continues the column's
                 * carpet or fits the carpet model; else (a shadow, a sunlit patch,
                 * or something else textured) a small penalty. */
                const int32_t dm = (int32_t)(m << 4) - q->ema;
                const int32_t lt = (int32_t)(fc->local_tol << 4);
                if ((dm <= lt && dm >= -lt) || (m >= f->lo && m <= f->hi)) {
                    v = 1;
                    q->ema += dm / 4;
                } else {
                    v = -1;
                    q->ema += dm / 2; /* a step in the light: follow it */
                }
            }
            q->cur = (q->cur > 0 ? q->cur : 0) + v;
            if (q->cur > q->best) {
                q->best = q->cur;
                q->top = (int32_t)r;
            }
        }
    }
}

static int32_t med3(int32_t a, int32_t b, int32_t c)
{
    const int32_t lo = a < b ? a : b, hi = a < b ? b : a;
    return c < lo ? lo : (c > hi ? hi : c);
}

static int32_t col_x(const sl_fstate *f, uint32_t c, uint32_t w)
{
    uint32_t x = c * f->s + f->s / 2u;
    if (c == 0u) {
        return 0;
    }
    if (c + 1u == f->nc || x > w - 1u) {
        x = w - 1u;
    }
    return (int32_t)x;
}

/* Row of the chord a-b at column x (a.x < x < b.x), rounded toward the top. */
static int32_t chord_y(const symline_field_vertex *a, const symline_field_vertex *b, int32_t x)
{
    const int64_t num = (int64_t)(b->y - a->y) * (x - a->x);
    const int64_t den = b->x - a->x;
    int64_t q = num / den;
    if (num % den != 0 && num < 0) {
        q--;
    }
    return a->y + (int32_t)q;
}

/* Column tops -> boundary polyline (upper hull, thinned). tops: col[c].top
 * holds the top row in pixels. The hull is built in place over col[].cur
 * (x) and col[].best (y). */
SL_NOINLINE static void hull(const symline_image *img, const sl_fstate *f, sl_fcol *col,
                             symline_field_boundary *out)
{
    uint32_t c, n = 0u, i;
    int32_t prev = col[0].top;
    for (c = 0; c < f->nc; c++) {
        const int32_t here = col[c].top;
        const int32_t next = c + 1u < f->nc ? col[c + 1u].top : here;
        const int32_t y = med3(prev, here, next);
        const int32_t x = col_x(f, c, img->width);
        prev = here;
        if (n > 0u && x == col[n - 1u].cur) {
            if (y >= col[n - 1u].best) {
                continue; /* the same column again (a frame narrower than the grid) */
            }
            n--;
        }
        /* Andrew's monotone chain, upper part (smaller y is higher): pop while
         * the last vertex lies on or below the chord from its predecessor. */
        while (n >= 2u) {
            const int64_t x1 = col[n - 2u].cur, y1 = col[n - 2u].best;
            const int64_t x2 = col[n - 1u].cur, y2 = col[n - 1u].best;
            if ((x2 - x1) * ((int64_t)y - y1) - (y2 - y1) * ((int64_t)x - x1) > 0) {
                break;
            }
            n--;
        }
        col[n].cur = x;
        col[n].best = y;
        n++;
    }
    /* Thin: drop the interior vertex whose removal lowers the boundary least. */
    while (n > SYMLINE_FIELD_MAX_VERTICES) {
        uint32_t drop = 1u;
        int32_t least = 0x7FFFFFFF;
        for (i = 1u; i + 1u < n; i++) {
            symline_field_vertex a, b;
            int32_t d;
            a.x = col[i - 1u].cur;
            a.y = col[i - 1u].best;
            b.x = col[i + 1u].cur;
            b.y = col[i + 1u].best;
            d = chord_y(&a, &b, col[i].cur) - col[i].best;
            if (d < least) {
                least = d;
                drop = i;
            }
        }
        for (i = drop; i + 1u < n; i++) {
            col[i] = col[i + 1u];
        }
        n--;
    }
    for (i = 0; i < n; i++) {
        out->v[i].x = col[i].cur;
        out->v[i].y = col[i].best;
    }
    if (out->v[n - 1u].x != (int32_t)img->width - 1) {
        /* One grid column (a frame no wider than a cell): span the frame. */
        out->v[n].x = (int32_t)img->width - 1;
        out->v[n].y = out->v[n - 1u].y;
        n++;
    }
    out->count = n;
}

void sl_field_run(const symline_image *img, const symline_field_config *fc, uint8_t *ws,
                  size_t ws_size, symline_field_boundary *out)
{
    uint8_t *cur = ws, *const end = ws + ws_size;
    sl_fstate *f = (sl_fstate *)sl_carve(&cur, end, sizeof(sl_fstate));
    sl_fcol *col;
    uint32_t c;
    if (f == NULL) {
        return; /* not reached: the workspace size was checked */
    }
    f->s = sl_field_cell(img->width, fc);
    for (f->k = 0u; (1u << f->k) < f->s; f->k++) {
    }
    f->nc = (img->width + f->s - 1u) / f->s;
    f->nr = (img->height + f->s - 1u) / f->s;
    col = (sl_fcol *)sl_carve(&cur, end, (size_t)f->nc * sizeof(sl_fcol));
    if (col == NULL) {
        return;
    }
    out->cell = (uint8_t)f->s;
    carpet_model(img, fc, f, out);
    scan_columns(img, fc, f, col);
    for (c = 0; c < f->nc; c++) {
        /* Top row of the run's highest cell, pixels; no carpet: the bottom. */
        const int32_t r = col[c].top;
        const int64_t y = (int64_t)img->height - ((int64_t)r + 1) * f->s;
        col[c].top = r < 0 ? (int32_t)img->height : (y < 0 ? 0 : (int32_t)y);
    }
    hull(img, f, col, out);
}

symline_status symline_field_find(const symline_image *img, const symline_field_config *fc,
                                  void *ws, size_t ws_size, symline_field_boundary *out)
{
    symline_status st = symline_image_check(img);
    if (st != SYMLINE_OK) {
        return st;
    }
    if (fc == NULL || ws == NULL || out == NULL) {
        return SYMLINE_ERR_NULL;
    }
    if (!config_ok(fc)) {
        return SYMLINE_ERR_CONFIG;
    }
    if (ws_size < symline_field_workspace_size(img->width, img->height, fc)) {
        return SYMLINE_ERR_BUFFER;
    }
    sl_field_run(img, fc, (uint8_t *)ws, ws_size, out);
    return SYMLINE_OK;
}

int32_t symline_field_y(const symline_field_boundary *b, int32_t x)
{
    uint32_t i;
    if (b == NULL || b->count == 0u || b->count > SYMLINE_FIELD_MAX_VERTICES) {
        return 0;
    }
    if (x <= b->v[0].x) {
        return b->v[0].y;
    }
    for (i = 1u; i < b->count; i++) {
        if (x <= b->v[i].x) {
            return chord_y(&b->v[i - 1u], &b->v[i], x);
        }
    }
    return b->v[b->count - 1u].y;
}

int symline_field_above(const symline_field_boundary *b, int32_t x, int32_t y)
{
    return (b != NULL && b->count != 0u && y < symline_field_y(b, x)) ? 1 : 0;
}

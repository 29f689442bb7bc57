/* SPDX-License-Identifier: Apache-2.0 */
/*
 * The field boundary from gray alone (include/symline/field.h).
 *
 * 1. Grid: cells of s x s pixels counted from the bottom of the frame; a cell
 *    is described by one row through its middle: its mean gray value and its
 *    texture (mean |difference| of horizontal neighbours over the mean, Q8,
 *    which a carpet's grain keeps in sunlight and in shadow). Reading one row
 *    in s keeps the stage at a fraction of an instruction per pixel.
 * 2. Carpet model: the median cell mean and the median texture over the
 *    lowest band of rows. Medians ignore what stands on the carpet there
 *    (lines, feet, the robot's own body) as long as the carpet is most of the
 *    band; a lens's black corners are left out, unless black is half the
 *    band or more: then the carpet itself is clipped to black.
 * 3. Column scan, bottom to top: a cell with carpet texture whose brightness
 *    fits the model or continues the column's carpet (a running mean follows
 *    the drift with distance) scores +1; a brighter cell (a line) 0; a
 *    carpet-textured cell of another brightness (a shadow's or a sunlit
 *    patch's edge; the running mean follows the step), or one of the
 *    carpet's brightness without its grain, -1; any other -miss_cost (10 by
 *    default: one such cell outweighs ten of carpet, so a column stops at
 *    the boards or a wall band instead of climbing on into a ceiling whose
 *    gray and grain pass for carpet; a robot on the field stops it too low,
 *    which step 4's hull bridges). The top of the best-scoring run is the
 *    column's top. A long run of cells that
 *    are neither carpet nor bright (the boards' dark foot, people, a wall
 *    band) ends the column's scan for good, so a ceiling that looks like
 *    carpet is never reached. Where that leaves most columns without carpet
 *    (a fisheye's black rim, taller on a darkened frame), the scan runs
 *    again with the rim's black cells at the bottom free.
 * 4. Support: a column's top counts as high as the k-th highest top within k
 *    columns either side (a net or a banner that looks like carpet over a few
 *    columns does not lift the boundary); the upper convex hull of these tops
 *    is the boundary (what cuts into the carpet from above stays under it; a
 *    field seen from inside is convex, so is its image through a barrel-
 *    distorting lens), thinned to SYMLINE_FIELD_MAX_VERTICES by dropping the
 *    vertices that move it least, level to the image edges past the last
 *    columns with carpet.
 */
#include "fieldboundary.h"

#define SL_FIELD_BINS 64u
/* Cells darker than this stay out of the carpet model: a lens's black
 * corners (a carpet, even a dark one, is brighter and has grain). */
#define SL_FIELD_BLACK 12u
/* Largest support (symline_field_config.support). */
#define SL_FIELD_MAX_SUPPORT 8u

void symline_field_config_default(symline_field_config *fc)
{
    if (fc == NULL) {
        return;
    }
    fc->cell = 0u;
    fc->band_pct = 40u;
    fc->mean_tol = 16u;
    fc->tex_lo_pct = 25u;
    fc->tex_hi_pct = 150u;
    fc->miss_cost = 10u;
    fc->local_tol = 16u;
    fc->gap_pct = 12u;
    fc->support = 3u;
    fc->restore_cells = 1u;
    fc->col_cells = 2u;
    fc->edge_slope_pct = 50u;
}

bool symline_i_field_config_ok(const symline_field_config *fc)
{
    const uint32_t c = fc->cell;
    /* (two tolerances of at most 255 each: their OR is, in one compare) */
    return (c == 0u || (c >= 2u && c <= 64u && (c & (c - 1u)) == 0u)) && fc->band_pct >= 1u &&
           fc->band_pct <= 100u && (fc->mean_tol | fc->local_tol) <= 255u &&
           fc->tex_lo_pct <= 100u && fc->tex_hi_pct >= 100u && fc->tex_hi_pct <= 10000u &&
           fc->miss_cost >= 1u && fc->miss_cost <= 16u && fc->gap_pct <= 100u &&
           fc->support >= 1u && fc->support <= SL_FIELD_MAX_SUPPORT && fc->restore_cells <= 64u &&
           fc->col_cells >= 1u && fc->col_cells <= 4u && fc->edge_slope_pct <= 10000u;
}

/* Per grid column: scan state, then the column top (pixels), then the hull. */
typedef struct symline_i_fcol {
    int32_t cur;  /* score of the run ending at the current row */
    int32_t best; /* best score seen */
    int32_t top;  /* its top row, pixels (the frame's height: no carpet) */
    int32_t ema;  /* running mean of the column's carpet cells, Q4 */
    uint32_t gap; /* non-carpet cells since the last carpet cell */
} symline_i_fcol;

typedef struct symline_i_fstate {
    uint32_t s, nc, nr;
    uint32_t sx;             /* column spacing: s * col_cells */
    uint32_t lo, hi;         /* accepted cell means */
    uint32_t mid;            /* the carpet's median */
    uint32_t tex_lo, tex_hi; /* accepted cell textures, Q1 */
    uint32_t hm[SL_FIELD_BINS], ht[SL_FIELD_BINS];
    uint32_t nb;   /* grid rows of the model's band */
    uint8_t *band; /* their cells' means and textures, read once */
#if SL_FOR_SPEED_DEEP
    int16_t *lanes; /* the column scan's state in lanes (scan_lanes()) */
#endif
    const symline_field_config *fc;
    const symline_image *img;
} symline_i_fstate;

/* SYMLINE_DETECT_WORKSPACE_SIZE() (detect.h) counts 640 bytes for this state and
 * the alignment, and 24 per grid column. */
typedef char symline_i_fstate_fits_ws_budget
    [(sizeof(symline_i_fstate) <= 600u && sizeof(symline_i_fcol) <= 24u) ? 1 : -1];

static size_t cols_bytes(uint32_t nc)
{
    return symline_i_align_up((size_t)nc * sizeof(symline_i_fcol));
}

/* The column scan's lanes (scan_row_lanes()) run over the columns rounded
 * up to a multiple of this: the compiler's vector loop takes 16 columns a
 * step (its narrowest values are the cells' bytes), and no column is left
 * to its scalar remainder. */
#define SL_FIELD_BLOCK 16u

/* Columns rounded up to whole blocks. */
static uint32_t lane_cols(uint32_t nc)
{
    return (nc + SL_FIELD_BLOCK - 1u) & ~(SL_FIELD_BLOCK - 1u);
}

/* The column scan's lanes (scan_lanes()): seven 16-bit values per column
 * of the rounded count (five of state, the row's mean and texture), and the
 * band's cells read up to a block past their last column. */
static size_t lanes_bytes(uint32_t nc)
{
    return SL_FOR_SPEED_DEEP ? symline_i_align_up((size_t)lane_cols(nc) * 7u * sizeof(int16_t)) +
                                   (size_t)2u * SL_FIELD_BLOCK + SL_ALIGN
                             : 0u;
}

/* The grid of a width x height frame under fc, into f's sizes unless f is
 * NULL; returns the workspace bytes it needs. */
SL_NOINLINE static size_t field_grid(uint32_t width, uint32_t height,
                                     const symline_field_config *fc, symline_i_fstate *f)
{
    /* A cell's texture needs a few neighbour differences to be stable: at
     * least 8 px, 16 px from 1024 px wide on. */
    const uint32_t s = fc->cell != 0u ? fc->cell : width >= 1024u ? 16u : 8u;
    const uint32_t sx = s * fc->col_cells;
    const uint32_t nc = (width + sx - 1u) / sx; /* <= 65535 */
    const uint32_t nr = (height + s - 1u) / s;
    /* Grid rows of the carpet model's band; nr <= 32768: 32 bits. */
    const uint32_t nb0 = (nr * fc->band_pct + 99u) / 100u, nb = nb0 < 1u ? 1u : nb0;
    if (f != NULL) {
        f->s = s;
        f->sx = sx;
        f->nc = nc;
        f->nr = nr;
        f->nb = nb;
    }
    return symline_i_align_up(sizeof(symline_i_fstate)) + cols_bytes(nc) + 2u * (size_t)nb * nc +
           (size_t)3u * SL_ALIGN + lanes_bytes(nc);
}

size_t symline_field_workspace_size(uint32_t width, uint32_t height, const symline_field_config *fc)
{
    if (fc == NULL || width == 0u || height == 0u || width > SYMLINE_MAX_DIM ||
        height > SYMLINE_MAX_DIM || !symline_i_field_config_ok(fc)) {
        return 0u;
    }
    return field_grid(width, height, fc, NULL);
}

/* Middle row of grid row r (0 = the lowest). */
static uint32_t sample_row(const symline_i_fstate *f, uint32_t h, uint32_t r)
{
    const uint32_t bottom = h - r * f->s; /* exclusive */
    const uint32_t top = bottom > f->s ? bottom - f->s : 0u;
    return (top + bottom - 1u) / 2u;
}

static inline void cell_stats(const symline_i_fstate *f, const uint8_t *p, uint32_t left,
                              uint32_t *mean, uint32_t *tex)
{
    const uint32_t n = left < f->s ? left : f->s;
    if (SL_FOR_SPEED && n == 8u) {
        symline_i_field_cell(p, 8u, mean, tex); /* the usual cell: a constant count, unrolled */
        return;
    }
    symline_i_field_cell(p, n, mean, tex);
}

/* The cells (mean, texture) of grid row r into out, two bytes per column;
 * a column behind a barrier (col not NULL, gap > gmax), which the scan
 * is done with, is left out to save time (SL_FOR_SPEED) where the cells
 * are not taken in lanes (a port's symline_i_field_cells8()). */
static void row_cells(const symline_i_fstate *f, uint32_t r, const symline_i_fcol *col,
                      uint32_t gmax, uint8_t *out)
{
    const symline_image *img = f->img;
    const uint8_t *row = img->data + (size_t)sample_row(f, img->height, r) * img->stride;
    uint32_t c = 0u, x0 = 0u;
#ifdef SYMLINE_PORT_FIELD_CELLS
    if (SL_FOR_SPEED && f->s == 8u && img->width >= 8u) {
        /* The cells of 8 px that end inside the row, in lanes: all of them
         * (those behind a barrier cost less than skipping them) */
        const uint32_t full = (img->width - 8u) / f->sx + 1u;
        c = full < f->nc ? full : f->nc;
        symline_i_field_cells8(row, f->sx, c, out);
        x0 = c * f->sx;
        out += 2u * (size_t)c;
    }
#endif
    for (; c < f->nc; c++, x0 += f->sx, out += 2) {
        uint32_t m, t;
        if (SL_FOR_SPEED && col != NULL && col[c].gap > gmax) {
            continue;
        }
        cell_stats(f, row + x0, img->width - x0, &m, &t);
        out[0] = (uint8_t)m;
        out[1] = (uint8_t)t;
    }
}

/* Smallest bin value v with at least half the count at or below it. */
SL_NOINLINE static uint32_t hist_median(const uint32_t *hist, uint32_t total)
{
    uint32_t i = 0u, acc = hist[0];
    while (2u * acc < total) { /* total is the sum of the bins: ends by the last */
        acc += hist[++i];
    }
    return i;
}

/* The carpet model from the lowest band of grid rows. */
SL_NOINLINE static void carpet_model(symline_i_fstate *f, symline_field_boundary *out)
{
    const symline_field_config *fc = f->fc;
    uint32_t r, i, total = 0u, tb;
    for (i = 0; i < SL_FIELD_BINS; i++) {
        f->hm[i] = 0u;
        f->ht[i] = 0u;
    }
    for (r = 0; r < f->nb; r++) {
        row_cells(f, r, NULL, 0u, f->band + 2u * (size_t)r * f->nc); /* kept for the scan */
    }
    for (i = 0; i < f->nb * f->nc; i++) {
        const uint8_t *b = f->band + 2u * (size_t)i;
        const uint32_t m = b[0], t = b[1];
        if (m >= SL_FIELD_BLACK) {
            f->hm[m >> 2]++;
            f->ht[t < 2u * SL_FIELD_BINS ? t >> 1 : SL_FIELD_BINS - 1u]++;
            total++;
        }
    }
    /* Black cells are left out while they are the lesser part of the band's
     * i cells (a lens's corners or rim). A band mostly black (a dim hall, an
     * under-exposed frame clipped to black) is the carpet: total 0 makes
     * both medians bin 0, the carpet that dark. */
    total = total > i / 2u ? total : 0u;
    tb = 2u * hist_median(f->ht, total) + 1u;
    f->mid = 4u * hist_median(f->hm, total) + 2u;
    f->lo = f->mid > fc->mean_tol ? f->mid - fc->mean_tol : 0u;
    f->hi = f->mid + fc->mean_tol;
    out->carpet_mean = (uint8_t)f->mid;
    f->tex_lo = tb * fc->tex_lo_pct / 100u;
    f->tex_hi = tb * fc->tex_hi_pct / 100u + 4u;
    out->carpet_tex = (uint8_t)tb; /* <= 2 * (SL_FIELD_BINS - 1) + 1 */
}

/* The column scan's barrier: a column's scan ends after more non-carpet
 * cells in a row than this (gap_pct 0: never). */
static uint32_t gap_limit(const symline_i_fstate *f)
{
    return f->fc->gap_pct == 0u ? 0xFFFFFFFFu : f->nr * f->fc->gap_pct / 100u;
}

/* The top row of grid row r's cells, pixels (0 for the partial row at the
 * frame's top). */
static int32_t row_top(const symline_i_fstate *f, uint32_t r)
{
    const int32_t y = (int32_t)f->img->height - (int32_t)((r + 1u) * f->s);
    return y < 0 ? 0 : y;
}

#if SL_FOR_SPEED_DEEP
/* The column scan's limits in the lanes' 16 bits. */
typedef struct symline_i_flimits {
    int16_t lo, hi, tex_lo, tex_hi, lt, miss, gmax;
} symline_i_flimits;

/*
 * One grid row of scan_columns()'s column scan (the same steps, the same
 * result) over all columns at once: each field of the columns' state an
 * array (cur, best, ema, gap, then top as unsigned), the branches as masks
 * and bit operations, so that the compiler runs the columns in 16-bit
 * vector lanes (the scalar scan took some 40 instructions a cell). The
 * row's cells cells[2c] (mean), cells[2c+1] (texture), first spread into
 * mt[] (means, then textures: every lane 16 bits); top: the row's top
 * pixel; rim_row: its black cells are free. Ranges: cur -16 .. nr, best and
 * gap 0 .. nr, ema 0 .. 4080 (Q4 gray), limits below 2^15 (scan_columns()
 * asks nr < 2^14).
 */
static void scan_row_lanes(const symline_i_flimits *k, const uint8_t *cells, uint32_t nc,
                           int16_t *restrict mt, int16_t *restrict cur, int16_t *restrict best,
                           int16_t *restrict ema, int16_t *restrict gap, uint16_t *restrict top,
                           uint16_t row_top, bool rim_row)
{
    const int16_t lo = k->lo, hi = k->hi, tlo = k->tex_lo, thi = k->tex_hi, lt = k->lt;
    const int16_t miss = k->miss, gmax = k->gmax, black = (int16_t)SL_FIELD_BLACK;
    const int16_t rim = (int16_t) - (int16_t)rim_row;
    int16_t *restrict const tx = mt + nc;
    size_t c;
    for (c = 0; c < nc; c++) {
        mt[c] = cells[2u * c];
        tx[c] = cells[2u * c + 1u];
    }
    for (c = 0; c < nc; c++) {
        /* conditions as masks of all ones (-1) or 0 */
        const int16_t m = mt[c], t = tx[c];
        const int16_t e = ema[c], g = gap[c], b = best[c], u = cur[c];
        const int16_t dm = (int16_t)((m << 4) - e);
        const int16_t live = (int16_t) - (g <= gmax);
        const int16_t tex = (int16_t)(-(t >= tlo) & -(t <= thi));
        const int16_t carpet =
            (int16_t)(tex & ((-(dm <= lt) & -(dm >= -lt)) | (-(m >= lo) & -(m <= hi))));
        const int16_t free = (int16_t)(~carpet & (-(dm > lt) | (rim & -(m < black) & -(b == 0))));
        const int16_t minus = (int16_t)(tex | -(dm >= -lt)), other = (int16_t) ~(carpet | free);
        /* carpet 1, free 0, else -1 (minus) or miss */
        const int16_t v = (int16_t)((carpet & 1) | (other & (minus | (~minus & miss))));
        const int16_t half = (int16_t)(tex & (dm / 2)); /* dm / 4 = (dm / 2) / 2 */
        const int16_t ne = (int16_t)(e + ((carpet & (half / 2)) | (~carpet & half)));
        const int16_t ng = (int16_t)(~carpet & (g - other));
        const int16_t nu = (int16_t)((u & (int16_t) - (u > 0)) + v);
        const int16_t up = (int16_t)(live & -(nu > b));
        /* a column behind a barrier keeps its gap (it stays there) and its
         * best and top; its cur and ema are never read again */
        cur[c] = nu;
        ema[c] = ne;
        gap[c] = (int16_t)((live & ng) | (~live & g));
        best[c] = (int16_t)((up & nu) | (~up & b));
        top[c] = (uint16_t)((up & (int16_t)row_top) | (~up & (int16_t)top[c]));
    }
}

/* scan_columns() in lanes (scan_row_lanes()): the columns' best and top to
 * col[] (their other fields are not read after the scan). */
SL_NOINLINE static void scan_lanes(const symline_i_fstate *f, symline_i_fcol *col, uint32_t rim)
{
    const symline_image *img = f->img;
    const symline_field_config *fc = f->fc;
    const uint32_t nc = f->nc, gl = gap_limit(f), gm = gl < 0x7FFFu ? gl : 0x7FFFu;
    const uint32_t nl = lane_cols(nc);
    int16_t *const cur = f->lanes, *const best = cur + nl, *const ema = best + nl;
    int16_t *const gap = ema + nl;
    uint16_t *const top = (uint16_t *)(void *)(gap + nl);
    int16_t *const mt = (int16_t *)(void *)(top + nl);
    symline_i_flimits k;
    uint32_t r, c;
    for (c = 0; c < 2u * SL_FIELD_BLOCK; c++) {
        f->band[2u * (size_t)f->nb * nc + c] = 0u; /* read past the last column, never used */
    }
    k.lo = (int16_t)f->lo;
    k.hi = (int16_t)f->hi;
    k.tex_lo = (int16_t)f->tex_lo;
    k.tex_hi = (int16_t)(f->tex_hi < 0x7FFFu ? f->tex_hi : 0x7FFFu);
    k.lt = (int16_t)(fc->local_tol << 4);
    k.miss = (int16_t)(-(int32_t)fc->miss_cost);
    k.gmax = (int16_t)gm;
    for (c = 0; c < nl; c++) {
        cur[c] = 0;
        best[c] = 0;
        ema[c] = (int16_t)(f->mid << 4);
        gap[c] = 0;
        top[c] = (uint16_t)img->height; /* no carpet: the bottom */
    }
    for (r = 0; r < f->nr; r++) {
        const uint8_t *cells = f->band + 2u * (size_t)r * nc;
        if (r >= f->nb) {
            /* every cell, those behind a barrier too: the lanes skip none */
            cells = f->band;
            row_cells(f, r, NULL, 0u, f->band);
        }
        scan_row_lanes(&k, cells, nl, mt, cur, best, ema, gap, top, (uint16_t)row_top(f, r),
                       r < rim);
    }
    for (c = 0; c < nc; c++) {
        col[c].best = best[c];
        col[c].top = top[c];
    }
}
#endif

/* Upward scan of every column: the best-scoring run of carpet; col[].top
 * becomes its top row in pixels (the frame's height: no carpet). Black cells
 * in the lowest rim grid rows, below a column's first carpet cell, are a
 * lens's rim: free, and no part of a barrier (rim 0: none). */
SL_NOINLINE static void scan_columns(const symline_i_fstate *f, symline_i_fcol *col, uint32_t rim)
{
#if SL_FOR_SPEED_DEEP
    if (f->lanes != NULL && f->nr < 0x4000u) {
        scan_lanes(f, col, rim);
        return;
    }
#endif
    const symline_image *img = f->img;
    const symline_field_config *fc = f->fc;
    uint32_t r, c;
    const int32_t miss = -(int32_t)fc->miss_cost;
    const int32_t lt = (int32_t)(fc->local_tol << 4);
    const uint32_t gmax = gap_limit(f);
    for (c = 0; c < f->nc; c++) {
        col[c].cur = 0;
        col[c].best = 0;
        col[c].top = (int32_t)img->height; /* no carpet: the bottom */
        col[c].ema = (int32_t)(f->mid << 4);
        col[c].gap = 0u;
    }
    for (r = 0; r < f->nr; r++) {
        const int32_t top = row_top(f, r);
        /* The band's cells were kept (to save time, SL_FOR_SPEED); the other
         * rows' are read into the band's first row. */
        const uint8_t *cells = f->band + 2u * (size_t)r * f->nc;
        if (!SL_FOR_SPEED || r >= f->nb) {
            cells = f->band;
            row_cells(f, r, col, gmax, f->band);
        }
        for (c = 0; c < f->nc; c++, cells += 2) {
            const uint32_t m = cells[0], t = cells[1];
            int32_t v, dm;
            int tex_ok;
            symline_i_fcol *q = &col[c];
            if (q->gap > gmax) {
                continue; /* behind a barrier: this column is done */
            }
            tex_ok = t >= f->tex_lo && t <= f->tex_hi;
            dm = (int32_t)(m << 4) - q->ema;
            if (tex_ok && ((dm <= lt && dm >= -lt) || (m >= f->lo && m <= f->hi))) {
                /* Carpet: its grain, and a brightness that continues the column's
                 * carpet or fits the model. */
                v = 1;
                q->ema += dm / 4;
                q->gap = 0u;
            } else {
                /* Brighter than the carpet below: a line, mostly: free, and no
                 * part of a barrier. Carpet grain at another brightness (a
                 * shadow's or a sunlit patch's edge; the running mean follows
                 * the step), or the carpet's brightness without its grain: -1.
                 * Anything else: -miss_cost. */
                if (dm > lt || (r < rim && m < SL_FIELD_BLACK && q->best == 0)) {
                    v = 0;
                } else {
                    v = (tex_ok || dm >= -lt) ? -1 : miss; /* dm <= lt here */
                    q->gap++;
                }
                if (tex_ok) {
                    q->ema += dm / 2;
                }
            }
            q->cur = (q->cur > 0 ? q->cur : 0) + v;
            if (q->cur > q->best) {
                q->best = q->cur;
                q->top = top;
            }
        }
    }
}

/* Support filter: a column's top becomes the k-th highest (k = support) of
 * the tops within k columns either side, so a top that fewer than k nearby
 * columns reach (a wall patch that looks like carpet) is not a hull vertex.
 * Reads col[].top, writes col[].ema. */
SL_NOINLINE static void support_filter(const symline_i_fstate *f, uint32_t k, symline_i_fcol *col)
{
    uint32_t c, i, j;
    for (c = 0; c < f->nc; c++) {
        const uint32_t lo = c >= k ? c - k : 0u;
        const uint32_t hi = c + k < f->nc ? c + k : f->nc - 1u;
        /* A window cut by the image edge asks for proportionally fewer:
         * 1 <= rank <= the window's columns, rank <= k. */
        const uint32_t rank = (k * (hi - lo + 1u) + 2u * k) / (2u * k + 1u);
        int32_t pick = 0x7FFFFFFF;
        /* The rank-th smallest row: the smallest top with at least rank
         * tops of the window at or above it (a window of at most 17). */
        for (i = lo; i <= hi; i++) {
            const int32_t y = col[i].top;
            uint32_t le = 0u;
            if (y >= pick) {
                continue; /* cannot be smaller */
            }
            for (j = lo; j <= hi; j++) {
                le += col[j].top <= y ? 1u : 0u;
            }
            pick = le >= rank ? y : pick;
        }
        col[c].ema = pick;
    }
}

/* Pixel column of grid column c (frame w px wide): the first and the last
 * lie at the image edges, the others at their centres, inside the frame
 * ((nc - 1) * sx < w, so (nc - 2) * sx + sx / 2 < w - sx / 2). */
SL_NOINLINE static int32_t col_x(const symline_i_fstate *f, uint32_t c, uint32_t w)
{
    return c == 0u ? 0 : (int32_t)(c + 1u == f->nc ? w - 1u : c * f->sx + f->sx / 2u);
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

/* Column tops -> boundary polyline (upper hull, thinned). col[c].ema holds
 * the filtered top row in pixels. The hull is built in place over col[].cur
 * (x) and col[].best (y). */
SL_NOINLINE static void hull(const symline_i_fstate *f, symline_i_fcol *col,
                             symline_field_boundary *out)
{
    const symline_image *img = f->img;
    const uint32_t edge_pct = f->fc->edge_slope_pct;
    const int32_t h = (int32_t)img->height, xr = (int32_t)img->width - 1;
    uint32_t c, n = 0u, i, k = 0u;
    for (c = 0; c < f->nc; c++) {
        const int32_t y = col[c].ema;
        const int32_t x = col_x(f, c, img->width);
        if (y >= h) {
            continue; /* no field in this column (a lens's black corner, say) */
        }
        /* x grows strictly from column to column (col_x()). */
        /* Andrew's monotone chain, upper part (smaller y is higher): pop while
         * the last vertex lies on or below the chord from its predecessor. */
        while (n >= 2u) {
            /* x, y within [0, SYMLINE_MAX_DIM]: 32-bit differences, 64-bit products. */
            const int32_t x1 = col[n - 2u].cur, y1 = col[n - 2u].best;
            const int32_t x2 = col[n - 1u].cur, y2 = col[n - 1u].best;
            if ((int64_t)(x2 - x1) * (y - y1) > (int64_t)(y2 - y1) * (x - x1)) {
                break;
            }
            n--;
        }
        col[n].cur = x;
        col[n].best = y;
        n++;
    }
    if (n == 0u) {
        /* No field anywhere: the boundary lies at the bottom. */
        col[0].cur = 0;
        col[0].best = h;
        n = 1u;
    }
    /* Thin (leaving room for the two edge vertices): drop the interior vertex
     * whose removal lowers the boundary least. */
    while (n > SYMLINE_FIELD_MAX_VERTICES - 2u) {
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
            col[i].cur = col[i + 1u].cur; /* field by field: no memcpy call */
            col[i].best = col[i + 1u].best;
        }
        n--;
    }
    if (edge_pct != 0u && n >= 2u) {
        /* Near an image edge the columns have neighbours on one side only: a
         * robot or a person standing there holds the last columns down and
         * nothing beyond them can bridge it. The end segments fall toward
         * the edges no steeper than edge_pct % (too high only keeps clutter). */
        const int32_t l =
            col[1].best + (int32_t)((uint32_t)(col[1].cur - col[0].cur) * edge_pct / 100u);
        const int32_t r =
            col[n - 2u].best +
            (int32_t)((uint32_t)(col[n - 1u].cur - col[n - 2u].cur) * edge_pct / 100u);
        col[0].best = col[0].best > l ? l : col[0].best;
        col[n - 1u].best = col[n - 1u].best > r ? r : col[n - 1u].best;
    }
    /* Columns without field at the sides: the boundary continues level to
     * the image edges. */
    if (col[0].cur > 0) {
        out->v[k].x = 0;
        out->v[k++].y = col[0].best;
    }
    for (i = 0; i < n; i++) {
        out->v[k].x = col[i].cur;
        out->v[k++].y = col[i].best;
    }
    if (out->v[k - 1u].x < xr) {
        out->v[k].x = xr;
        out->v[k].y = out->v[k - 1u].y;
        k++;
    }
    out->count = k;
}

/* symline_i_field_run(); lanes: the column scan in lanes where the build
 * has them (SL_FOR_SPEED_DEEP). */
static void field_run(const symline_image *img, const symline_field_config *fc, uint8_t *ws,
                      size_t ws_size, symline_field_boundary *out, bool lanes)
{
    uint8_t *cur = ws, *const end = ws + ws_size;
    symline_i_fstate *f = (symline_i_fstate *)symline_i_carve(&cur, end, sizeof(symline_i_fstate));
    symline_i_fcol *col;
    if (f == NULL) {
        return; /* not reached: the workspace size was checked */
    }
    (void)field_grid(img->width, img->height, fc, f);
    col = (symline_i_fcol *)symline_i_carve(&cur, end, (size_t)f->nc * sizeof(symline_i_fcol));
    f->band = (uint8_t *)symline_i_carve(
        &cur, end,
        2u * (size_t)f->nb * f->nc + (SL_FOR_SPEED_DEEP ? (size_t)2u * SL_FIELD_BLOCK : 0u));
    if (col == NULL || f->band == NULL) {
        return;
    }
#if SL_FOR_SPEED_DEEP
    f->lanes =
        (int16_t *)symline_i_carve(&cur, end, (size_t)lane_cols(f->nc) * 7u * sizeof(int16_t));
    if (f->lanes == NULL) {
        return;
    }
    f->lanes = lanes ? f->lanes : NULL;
#else
    (void)lanes;
#endif
    out->cell = (uint8_t)f->s;
    f->fc = fc;
    f->img = img;
    carpet_model(f, out);
    scan_columns(f, col, 0u);
    {
        /* Most columns found no carpet: on a darkened frame a fisheye lens's
         * black rim and the dim carpet beside it outgrow a barrier and end
         * the columns' scans at the bottom. Again, with black cells free in
         * the lowest half barrier's rows (6 % of the rows by default; 6 to
         * 12 % give the same on the annotated frames' darker copies). Only
         * then, and only there: the rim is tallest at the image's sides,
         * whose columns would climb on into a hall's floor and walls beyond
         * the field, which the rim holds them from. */
        const uint32_t rim = f->nr * fc->gap_pct / 200u;
        uint32_t c, found = 0u;
        for (c = 0; c < f->nc; c++) {
            found += col[c].best > 0;
        }
        if (2u * found < f->nc && rim != 0u) {
            if (SL_FOR_SPEED) {
                /* the scan read its rows above the band into the band's
                 * first row, which it reads first */
                row_cells(f, 0u, NULL, 0u, f->band);
            }
            scan_columns(f, col, rim);
        }
    }
    support_filter(f, fc->support, col);
    hull(f, col, out);
    if (fc->restore_cells != 0u) {
        /* The support filter lowers peaks (a field corner) by a few columns'
         * slope: every column's own top counts again, but no higher than
         * restore_cells above the robust boundary. */
        const int32_t d = (int32_t)(fc->restore_cells * f->s);
        uint32_t c;
        for (c = 0; c < f->nc; c++) {
            const int32_t hf = symline_field_y(out, col_x(f, c, img->width));
            int32_t t = col[c].top;
            if (t < (int32_t)img->height) {
                t = t < hf - d ? hf - d : t;
                /* An edge column has neighbours on one side only: it is not
                 * taken lower than the robust boundary. */
                t = ((c == 0u || c + 1u == f->nc) && hf < t) ? hf : t;
            }
            col[c].ema = t;
        }
        hull(f, col, out);
    }
}

void symline_i_field_run(const symline_image *img, const symline_field_config *fc, uint8_t *ws,
                         size_t ws_size, symline_field_boundary *out)
{
    field_run(img, fc, ws, ws_size, out, true);
}

#if SL_FOR_SPEED_DEEP
void symline_i_field_run_scalar(const symline_image *img, const symline_field_config *fc,
                                uint8_t *ws, size_t ws_size, symline_field_boundary *out)
{
    field_run(img, fc, ws, ws_size, out, false);
}
#endif

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
    if (!symline_i_field_config_ok(fc)) {
        return SYMLINE_ERR_CONFIG;
    }
    if (ws_size < symline_field_workspace_size(img->width, img->height, fc)) {
        return SYMLINE_ERR_BUFFER;
    }
    symline_i_field_run(img, fc, (uint8_t *)ws, ws_size, out);
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

/* a / d rounded toward minus infinity (d > 0), as chord_y() rounds. */
static int64_t floor_div(int64_t a, int64_t d)
{
    const int64_t q = a / d;
    return (a % d != 0 && a < 0) ? q - 1 : q;
}

/* The first kept grid row (level, s = 2^level) under boundary row y, margin
 * plus half a block (lift) above it. */
static uint16_t kept_row(int32_t y, int32_t lift, uint32_t s, uint32_t level)
{
    y -= lift;
    /* The boundary lies at most at the frame's height: y <= 65535. */
    return (uint16_t)(y <= 0 ? 0 : (y + (int32_t)s - 1) >> level);
}

void symline_i_field_rows(const symline_field_boundary *b, uint32_t level, uint32_t w,
                          uint32_t width, uint32_t margin, uint16_t *rows)
{
    /* symline_field_y() at every grid column's centre (keep grid row y when
     * its centre y*s + s/2 >= boundary - margin); to save time
     * (SL_FOR_SPEED), along each chord by a running quotient and remainder:
     * the centres only move right, by s. */
    const uint32_t s = 1u << level, last = b->count - 1u;
    const int32_t lift = (int32_t)(margin + s / 2u);
    uint32_t x = 0u, i = 0u;
    while (x < w) {
        const int32_t xc = (int32_t)(x * s + s / 2u < width ? x * s + s / 2u : width - 1u);
        const symline_field_vertex *va, *vb;
        int32_t end, den, dy, q, r, dq, dr;
        int64_t n;
        uint32_t xe;
        if (!SL_FOR_SPEED) {
            rows[x++] = kept_row(symline_field_y(b, xc), lift, s, level);
            continue;
        }
        while (i < last && xc > b->v[i + 1u].x) {
            i++;
        }
        if (xc <= b->v[0].x || i >= last) {
            rows[x++] = kept_row(xc <= b->v[0].x ? b->v[0].y : b->v[last].y, lift, s, level);
            continue;
        }
        /* va.x < xc <= vb.x: the columns from x whose centres (x*s + s/2,
         * not clamped) stay within the chord, up to xe. */
        va = &b->v[i];
        vb = &b->v[i + 1u];
        end = vb->x < (int32_t)width - 1 ? vb->x : (int32_t)width - 1;
        xe = end >= xc ? (uint32_t)(end - (int32_t)(s / 2u)) / s + 1u : x + 1u;
        xe = xe < w ? xe : w;
        xe = xe > x ? xe : x + 1u;
        den = vb->x - va->x;
        dy = vb->y - va->y;
        n = (int64_t)dy * (xc - va->x);
        q = (int32_t)floor_div(n, den);
        r = (int32_t)(n - (int64_t)q * den);
        n = (int64_t)dy * (int32_t)s;
        dq = (int32_t)floor_div(n, den);
        dr = (int32_t)(n - (int64_t)dq * den);
        for (; x < xe; x++) {
            rows[x] = kept_row(va->y + q, lift, s, level);
            q += dq;
            r += dr;
            if (r >= den) {
                r -= den;
                q++;
            }
        }
    }
}

uint32_t symline_i_field_drop(const uint16_t *rows, uint32_t w, symline_point *pts,
                              uint32_t *row_start, uint32_t h)
{
    /* To save time (SL_FOR_SPEED): from the boundary's lowest row (hi) on the
     * rest stays where it is. (The rows wholly above it hold no points: the
     * collection leaves them out, pass.c.) */
    uint32_t y, i = 0u, k = 0u, hi = 0u;
    for (y = 0; SL_FOR_SPEED && y < w; y++) {
        hi = rows[y] > hi ? rows[y] : hi;
    }
    for (y = 0; y < h; y++) {
        const uint32_t end = row_start[y + 1u];
        if (SL_FOR_SPEED && y >= hi && k == i) {
            return row_start[h]; /* the rest is field and stays where it is */
        }
        row_start[y] = k;
        for (; i < end; i++) { /* the points of row y */
            if (pts[i].y >= rows[pts[i].x]) {
                /* Field by field (no memcpy call); the offsets fx, fy are
                 * not set before the sub-pixel stage. */
                pts[k].x = pts[i].x;
                pts[k++].y = pts[i].y;
            }
        }
    }
    row_start[h] = k;
    return k;
}

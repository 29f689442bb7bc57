/* SPDX-License-Identifier: Apache-2.0 */
/*
 * The line filter: which S points (symmetry maxima) are line points.
 *
 * A field line is a bright ridge across its direction. The contrast filter
 * asks exactly that of the S point: its gray value must stand above the gray
 * values k = m+1 pixels to both sides. k = m+1 also rejects S points inside
 * regions wider than the operator's reach (those belong to a coarser scale).
 * The ridge height needed and the minimum gray value are set per frame from
 * the frame's mean and standard deviation (`adaptive`), so scaling or
 * offsetting the brightness leaves the decision unchanged apart from
 * clipping and rounding.
 * The paper's A1-S filter only asks for an A point nearby and an absolute
 * illumination threshold.
 */
#include "linefilter.h"

#include "fixed.h"

/* The statistics read every SL_STATS_STEP-th pixel of every SL_STATS_STEP-th row. */
#define SL_STATS_STEP 4u

void symline_i_linefilter_setup(symline_i_linefilter *f, const symline_config *cfg)
{
    f->kind = cfg->filter;
    f->a_distance = 0u;
    if (cfg->filter == SYMLINE_FILTER_PAPER) {
        f->a_distance = cfg->a_distance != 0u ? cfg->a_distance : cfg->radius;
    }
    f->min_gray = cfg->illumination;
    f->ridge_pct = cfg->contrast_pct;
    f->ridge_min = cfg->contrast_min;
    f->asym_pct = cfg->contrast_asym_pct;
    f->side_max = 255u;
}

/* Adds the samples of rows y0, y0 + SL_STATS_STEP, ... to the frame's
 * bottom to hist, row by row, eight samples a step. */
static void stats_rows(const symline_image *img, uint32_t y0, uint32_t *hist)
{
    /* The columns of the eight-sample steps, then the rest one by one. */
    const size_t d = SL_STATS_STEP, span = 8u * d;
    const uint32_t steps = (img->width + SL_STATS_STEP - 1u) / (8u * SL_STATS_STEP);
    uint32_t y, x;
    for (y = y0; y < img->height; y += SL_STATS_STEP) {
        const uint8_t *p = img->data + (size_t)y * img->stride;
        const uint8_t *const send = p + steps * span;
        for (; p != send; p += span) {
            hist[p[0]]++;
            hist[p[d]]++;
            hist[p[2u * d]]++;
            hist[p[3u * d]]++;
            hist[p[4u * d]]++;
            hist[p[5u * d]]++;
            hist[p[6u * d]]++;
            hist[p[7u * d]]++;
        }
        for (x = steps * (8u * SL_STATS_STEP); x < img->width; x += SL_STATS_STEP, p += d) {
            hist[*p]++;
        }
    }
}

/* The lowest first sampled row of all sampled columns (0: top NULL), at
 * most the frame's height. */
static uint32_t stats_cut(const symline_image *img, const uint16_t *top)
{
    uint32_t x, cut = 0u;
    for (x = 0; top != NULL && x < img->width; x += SL_STATS_STEP) {
        const uint32_t y0 = ((uint32_t)top[x] + SL_STATS_STEP - 1u) & ~(SL_STATS_STEP - 1u);
        cut = y0 > cut ? y0 : cut;
    }
    return cut < img->height ? cut : img->height;
}

/* Column by column: the column's first field row is looked up once, not
 * once per sample. To save time (SL_FOR_SPEED), only down to the lowest
 * first row of all columns (cut); from there on every column is sampled,
 * row by row, which takes fewer instructions a sample. The same samples
 * either way. */
SL_NOINLINE void symline_i_frame_stats_measure(const symline_image *img, const uint16_t *top,
                                               uint32_t *hist, symline_i_frame_stats *st)
{
    const size_t step = (size_t)img->stride * SL_STATS_STEP;
    const uint32_t cut = SL_FOR_SPEED ? stats_cut(img, top) : 0u;
    uint32_t x, i, n = 0u, half, acc, med, mad, lo, hi;
    for (i = 0; i < 256u; i++) {
        hist[i] = 0u;
    }
    if (SL_FOR_SPEED && cut < img->height) {
        /* The sampled rows from cut on: every sampled column's own rows. */
        stats_rows(img, cut, hist);
        n = ((img->height - cut + SL_STATS_STEP - 1u) / SL_STATS_STEP) *
            ((img->width + SL_STATS_STEP - 1u) / SL_STATS_STEP);
    }
    for (x = 0; x < img->width; x += SL_STATS_STEP) {
        /* The first sampled row at or below top[x], and the samples from it
         * down to cut (SL_FOR_SPEED) or to the frame's bottom. */
        const uint32_t y0 =
            top == NULL ? 0u : ((uint32_t)top[x] + SL_STATS_STEP - 1u) & ~(SL_STATS_STEP - 1u);
        uint32_t cnt;
        size_t at;
        const uint32_t end = SL_FOR_SPEED ? cut : img->height;
        if (y0 >= end) {
            continue;
        }
        cnt = (end - y0 + SL_STATS_STEP - 1u) / SL_STATS_STEP;
        n += cnt;
        for (at = (size_t)y0 * img->stride + x; cnt > 0u; cnt--, at += step) {
            hist[img->data[at]]++;
        }
    }
    /* Both scans stop within the histogram: its entries sum to n >= half
     * (with no sample at once, giving 0 and 0). */
    half = (n + 1u) / 2u;
    for (med = 0u, acc = 0u; acc + hist[med] < half; med++) {
        acc += hist[med];
    }
    /* Median absolute deviation: widen a window around the median until it
     * holds half of the samples. */
    acc = hist[med];
    for (mad = 0u, lo = med, hi = med; acc < half; mad++) {
        if (lo > 0u) {
            acc += hist[--lo];
        }
        if (hi < 255u) {
            acc += hist[++hi];
        }
    }
    st->mean = (uint16_t)med;
    /* sigma = 1.4826 MAD for normal noise, Q4: MAD * 23.7. */
    st->sigma_q4 = (uint16_t)((mad * 2372u + 50u) / 100u); /* <= 255 x 23.72 */
    st->ridge_q4 = st->sigma_q4;
    st->grain_q8 = 0u; /* the caller's, where it has a carpet model */
}

/* A sigma10 / 10 * sigma_q4 / 16 multiple of sigma: the divisor 160. */
#define SL_SIGMA10_Q4_DIV 160
/* side_sigma10 of this much or more leaves the sides alone. */
#define SL_SIDE_SIGMA10_OFF 100
/* At full resolution the sides are sampled radius + 1 px from the centre,
 * inside a bright line's blur; at 2x and coarser 8 px and more away. A
 * saturated line on bright carpet lifts them over the limit there: one sigma
 * more at level 0 (docs/detector.md, the overexposed synthetic scenes). */
#define SL_SIDE_FULL_RES_SIGMA10 10

/* mean + s10 / 10 sigma, clamped to a gray value. |s10| <= 110 (a checked
 * config, plus SL_SIDE_FULL_RES_SIGMA10) and sigma_q4 <= 255 * 23.72: the
 * product fits 32 bits. */
static uint32_t sigma_gray(uint32_t mean, int32_t s10, uint32_t sigma_q4)
{
    const int32_t t = (int32_t)mean + s10 * (int32_t)sigma_q4 / SL_SIGMA10_Q4_DIV;
    return t < 0 ? 0u : (t > 255 ? 255u : (uint32_t)t);
}

void symline_i_linefilter_adapt(symline_i_linefilter *f, const symline_config *cfg,
                                const symline_i_frame_stats *st, uint32_t level)
{
    const uint32_t mean = st->mean, sigma_q4 = st->sigma_q4;
    /* ridge_sigma10 <= 100 (a checked config): 32 bits hold the product. */
    uint32_t ridge =
        (cfg->ridge_sigma10 * st->ridge_q4 + SL_SIGMA10_Q4_DIV / 2u) / SL_SIGMA10_Q4_DIV;
    /* The carpet's noise alone: a pixel stands above both sides by a grain
     * or two often, by 2.5 seldom (on a dim noisy carpet the sigma's
     * threshold lets thousands of such points through to the tracer, which
     * drops them as too short). 2.5 grains, of the grain in sixteenths of a
     * gray level: 5/2 (grain_q8 / 16) / 16 gray levels. */
    const uint32_t noise = (5u * (st->grain_q8 / 16u)) >> (5u + level);
    const uint32_t bright = sigma_gray(mean, cfg->bright_sigma10, sigma_q4);
    if (noise > ridge) {
        ridge = noise;
    }
    if (bright > f->min_gray) {
        f->min_gray = bright;
    }
    if (ridge > f->ridge_min) {
        f->ridge_min = ridge;
    }
    if (cfg->side_sigma10 < SL_SIDE_SIGMA10_OFF) {
        const int32_t s10 = cfg->side_sigma10 + (level == 0u ? SL_SIDE_FULL_RES_SIGMA10 : 0);
        f->side_max = sigma_gray(mean, s10, sigma_q4);
    }
}

/*
 * The gray values k grid px to either side across the line (full-resolution
 * pixels), summed along the piece, must differ by less than the summed ridge
 * over twice asym_pct. Summing averages out the carpet's texture and the
 * noise that make the test per point loose, so it can be stricter here: a
 * bright band between two different surfaces (the foot of a wall, the floor
 * beyond the carpet, the rim of a robot) lies on no carpet on one side.
 * At most 4096 points are summed, so every product stays in 32 bits.
 */
#define SL_SIDE_SAMPLES 4096u
/* Length (px) at which a piece's mean ridge must reach twice the per-point
 * threshold (docs/detector.md: measured on the annotated real frames and the
 * synthetic sets). */
#define SL_SHORT_PX 16u

SL_NOINLINE bool symline_i_linefilter_piece_fails(const symline_i_linefilter *f,
                                                  const symline_image *img, symline_axis axis,
                                                  uint32_t level, uint32_t k,
                                                  const symline_point *q, uint32_t n)
{
    const bool horiz = axis == SYMLINE_AXIS_HORIZONTAL;
    const uint32_t half = (1u << level) >> 1, off = k << level;
    const uint32_t step = n / SL_SIDE_SAMPLES + 1u;
    const size_t across = horiz ? img->stride : 1u;
    const uint32_t lim = horiz ? img->height : img->width;
    const uint32_t len = n << level;
    uint32_t sum_lo = 0u, sum_hi = 0u, sum_centre = 0u, i, side, ridge, cnt = 0u;
    if (SL_FOR_SPEED && 2u * off < lim) {
        /* The same sums, with the offsets across taken once: a point off or
         * more from both borders (off <= pos <= lim - 1 - off, one unsigned
         * comparison) reads its sides without clamping. */
        const size_t far = (size_t)off * across;
        const uint8_t *const data = img->data;
        for (i = 0; i < n; i += step, cnt++) {
            const uint32_t x = ((uint32_t)q[i].x << level) + half;
            const uint32_t y = ((uint32_t)q[i].y << level) + half;
            const uint32_t pos = horiz ? y : x;
            const uint8_t *c = data + (size_t)y * img->stride + x;
            sum_centre += *c;
            if (pos - off <= lim - 1u - 2u * off) {
                sum_lo += *(c - far);
                sum_hi += *(c + far);
            } else {
                sum_lo += *(c - (size_t)(pos >= off ? off : pos) * across);
                sum_hi += *(c + (size_t)(pos + off < lim ? off : lim - 1u - pos) * across);
            }
        }
    }
    for (i = SL_FOR_SPEED && 2u * off < lim ? n : 0u; i < n; i += step, cnt++) {
        /* Grid points map inside the frame: (v << level) + half < size. */
        const uint32_t x = ((uint32_t)q[i].x << level) + half;
        const uint32_t y = ((uint32_t)q[i].y << level) + half;
        const uint32_t pos = horiz ? y : x;
        const uint8_t *c = img->data + (size_t)y * img->stride + x;
        sum_centre += *c;
        sum_lo += *(c - (size_t)(pos >= off ? off : pos) * across);
        sum_hi += *(c + (size_t)(pos + off < lim ? off : lim - 1u - pos) * across);
    }
    side = sum_lo > sum_hi ? sum_lo : sum_hi;
    if (sum_centre <= side) {
        return true;
    }
    ridge = sum_centre - side;
    /* Sides alike: |lo - hi| = 2 max(lo, hi) - lo - hi. */
    if ((2u * side - sum_lo - sum_hi) * (2u * f->asym_pct) > ridge * 100u) {
        return true;
    }
    /* A short piece must stand out more than a long one: the carpet's grain
     * forms short ridges just over the per-point threshold, a faint painted
     * line runs on. Mean ridge >= ridge_min * (len + SL_SHORT_PX) / len. */
    return (uint64_t)ridge * len < (uint64_t)f->ridge_min * cnt * (len + SL_SHORT_PX);
}

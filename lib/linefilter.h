/* SPDX-License-Identifier: Apache-2.0 */
/*
 * The line filter (linefilter.c): which S points (symmetry maxima) are line
 * points. Its thresholds for one pass, the frame statistics that adapt them,
 * the per-point gray-value and A-point tests, and the whole-piece side test
 * the pass applies to a traced piece.
 */
#ifndef SYMLINE_LIB_LINEFILTER_H
#define SYMLINE_LIB_LINEFILTER_H

#include "common.h"
#include "symline/detect.h"

/* The thresholds of one pass (gray levels unless noted). */
typedef struct symline_i_linefilter {
    symline_filter kind;
    uint32_t min_gray;   /* smallest gray value of a line point (illumination) */
    uint32_t ridge_pct;  /* contrast: ridge height >= this % of the centre gray value */
    uint32_t ridge_min;  /* contrast: smallest ridge height */
    uint32_t asym_pct;   /* contrast: ridge height >= this % of |lo - hi|; 0 = off */
    uint32_t side_max;   /* contrast: largest gray value of the ridge's sides (255: any) */
    uint32_t a_distance; /* paper: A point search distance across the line, grid px; 0 otherwise */
} symline_i_linefilter;

/* Level and spread of the gray values the thresholds adapt to, robust to the
 * lines, robots and lights among them. */
typedef struct symline_i_frame_stats {
    /* 16 bits each: gray levels up to 255, sigmas up to 255 x 23.72 in Q4. */
    uint16_t mean;     /* the median, gray levels */
    uint16_t sigma_q4; /* 1.4826 x the median absolute deviation (the standard
                          deviation of normal noise), gray levels, Q4 */
    uint16_t ridge_q4; /* the sigma the ridge threshold scales: sigma_q4, or
                          less on a carpet whose spread is not its grain
                          (detect.c), gray levels, Q4 */
    uint16_t grain_q8; /* the carpet's grain: the mean |difference| of
                          neighbouring pixels on it (symline_field_boundary's
                          carpet_tex, Q8 of its gray value, times carpet_mean),
                          gray levels, Q8, <= 255 x 255; 0 without a carpet
                          model */
} symline_i_frame_stats;

/* The ridge's sigma (Q4) on a carpet of grain grain_q8 (symline_i_frame_stats),
 * whose spread is sigma_q4. Sun and shadow split a carpet into two gray
 * levels, and then their spread, not the carpet's grain, sets sigma: lines in
 * the brighter part stand less than the ridge threshold above it. The ridge's
 * sigma comes down towards five grains, never below 0.8 sigma. grain_q8 <=
 * 255 x 255: every product fits 32 bits. */
static inline uint32_t symline_i_ridge_q4(uint32_t sigma_q4, uint32_t grain_q8)
{
    const uint32_t grains = 5u * grain_q8 / 16u; /* 5 grains, Q8 to Q4 */
    const uint32_t low = sigma_q4 * 4u / 5u;
    const uint32_t r = grains > low ? grains : low;
    return r < sigma_q4 ? r : sigma_q4;
}

/* The thresholds as configured (no range checks). */
void symline_i_linefilter_setup(symline_i_linefilter *f, const symline_config *cfg);

/* Scratch of symline_i_frame_stats_measure(): a histogram of the gray values. */
#define SL_STATS_HIST_BYTES (256u * sizeof(uint32_t))

/* The statistics of the field (rows y >= top[x] of each column x; top NULL:
 * the whole frame) on every 4th pixel of every 4th row. hist:
 * SL_STATS_HIST_BYTES of scratch. Both 0 when no pixel is measured. */
void symline_i_frame_stats_measure(const symline_image *img, const uint16_t *top, uint32_t *hist,
                                   symline_i_frame_stats *st);

/* The adaptive thresholds (cfg->adaptive) for a pass at `level` folded into
 * f: each only raises the configured one (side_max: replaces it unless
 * side_sigma10 is 100; one sigma higher at level 0). The ridge height needed
 * is also at least 2.5 of the carpet's grains, halved for each level (a
 * grid pixel at level L is the mean of 4^L pixels: 2^L times less noise). */
void symline_i_linefilter_adapt(symline_i_linefilter *f, const symline_config *cfg,
                                const symline_i_frame_stats *st, uint32_t level);

/* The gray-value part of the line filter for an S point with centre value c
 * and values lo, hi at k pixels before and after it across the line (clamped
 * at the border). True for a line point (the paper filter's A-point test is
 * a_near() in linepoints.c). Inline: it runs for every candidate. */
static inline bool symline_i_linefilter_gray(const symline_i_linefilter *f, uint32_t c, uint32_t lo,
                                             uint32_t hi)
{
    uint32_t side, need;
    if (c < f->min_gray) {
        return false;
    }
    if (f->kind == SYMLINE_FILTER_PAPER) {
        return true;
    }
    side = lo > hi ? lo : hi;
    if (c <= side || side > f->side_max) {
        return false;
    }
    /* The ridge percentage is 0 by default: no product and division then (to
     * save time). */
    need = (SL_FOR_SPEED && f->ridge_pct == 0u) ? 0u : (c * f->ridge_pct + 99u) / 100u;
    if (need < f->ridge_min) {
        need = f->ridge_min;
    }
    if (f->asym_pct != 0u) {
        const uint32_t asym = ((lo > hi ? lo - hi : hi - lo) * f->asym_pct + 99u) / 100u;
        need = asym > need ? asym : need;
    }
    return c - side >= need;
}

/*
 * A byte test that rejects most pixels before the exact one: the gray value
 * c of a line point is at least min_gray and, for the contrast filter,
 * stands ridge_min above the brighter side max(lo, hi), which is at most
 * side_max. In bytes, the sum side + ridge_min saturating at 255, it keeps
 * every point symline_i_linefilter_gray() keeps (and some it drops: the
 * exact test follows). For the paper's filter give lo = hi = c (ridge_min
 * is 0 and side_max 255 then): only the gray value counts.
 */
typedef struct symline_i_prefilter {
    uint8_t min_gray;  /* c >= min_gray */
    uint8_t ridge_min; /* c >= max(lo, hi) + ridge_min, the sum clamped to 255 */
    uint8_t side_max;  /* max(lo, hi) <= side_max (the contrast filter's at most
                          255 - ridge_min: no clamped sum passes beyond) */
} symline_i_prefilter;

static inline void symline_i_prefilter_setup(const symline_i_linefilter *f, symline_i_prefilter *pf)
{
    pf->min_gray = (uint8_t)(f->min_gray < 255u ? f->min_gray : 255u);
    pf->ridge_min = 0u;
    pf->side_max = 255u;
    if (f->kind != SYMLINE_FILTER_PAPER) { /* a ridge of 0 fails the exact test too */
        const uint32_t rm = f->ridge_min < 1u ? 1u : f->ridge_min < 255u ? f->ridge_min : 255u;
        pf->ridge_min = (uint8_t)rm;
        /* c <= 255 stands rm above the side only where the side is at most
         * 255 - rm: brighter sides fail the exact test (and a saturated
         * area, c = lo = hi = 255, would pass the sum's clamp at every
         * pixel) */
        pf->side_max = (uint8_t)(f->side_max < 255u - rm ? f->side_max : 255u - rm);
    }
}

/* Most indices one call of symline_i_line_cand() reports. */
#define SL_LINE_CAND_MAX 64u

/*
 * The entries of c[x .. n-1] whose gray values c[i], lo[i], hi[i] pass the
 * byte test of pf, in order: their indices to out[0 ..], at most
 * SL_LINE_CAND_MAX; returns how many. *next: where to go on, the entry
 * after the last one reported when out is full, else n. On field frames 1
 * to 5 entries in 100 pass (docs/detector.md): the detector computes
 * energies at those alone. symline_i_line_cand_c() is the portable
 * reference; symline_i_line_cand() the build's choice: a version from port/
 * (SYMLINE_PORT_LINE_CAND, CMake option SYMLINE_SIMD) that tests 4 to 16
 * entries per instruction, with the same result, or the reference.
 */
static inline uint32_t symline_i_line_cand_c(const symline_i_prefilter *pf, const uint8_t *c,
                                             const uint8_t *lo, const uint8_t *hi, uint32_t x,
                                             uint32_t n, uint16_t *out, uint32_t *next)
{
    uint32_t k = 0u;
    for (; x < n; x++) {
        const uint32_t side = lo[x] > hi[x] ? lo[x] : hi[x];
        /* c >= min(side + ridge_min, 255): the sum or the brightest gray */
        const bool ridge = c[x] >= side + pf->ridge_min || c[x] == 255u;
        if (c[x] >= pf->min_gray && ridge && side <= pf->side_max) {
            out[k++] = (uint16_t)x;
            if (k == SL_LINE_CAND_MAX) {
                *next = x + 1u;
                return k;
            }
        }
    }
    *next = n;
    return k;
}
#ifdef SYMLINE_PORT_LINE_CAND
uint32_t symline_i_line_cand(const symline_i_prefilter *pf, const uint8_t *c, const uint8_t *lo,
                             const uint8_t *hi, uint32_t x, uint32_t n, uint16_t *out,
                             uint32_t *next);
#else
#define symline_i_line_cand symline_i_line_cand_c
#endif

/*
 * The contrast filter once more, over a whole traced piece q[0..n-1] (grid
 * coordinates at `level`; k: the pass's sample offset across the line in grid
 * px), on the gray values summed along it: true when its sides differ too
 * much for a line on the carpet ("sides alike" with 2 x asym_pct), or when
 * its mean ridge stays under ridge_min * (len + 16) / len for its length len
 * in px (the carpet's grain makes short ridges). Only for the contrast filter
 * with asym_pct != 0.
 */
bool symline_i_linefilter_piece_fails(const symline_i_linefilter *f, const symline_image *img,
                                      symline_axis axis, uint32_t level, uint32_t k,
                                      const symline_point *q, uint32_t n);

#endif /* SYMLINE_LIB_LINEFILTER_H */

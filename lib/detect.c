/* SPDX-License-Identifier: Apache-2.0 */
/*
 * symline_detect(): configuration, workspace, the loop over the passes
 * (axes and scales, pass.c), the final merge (merge.c) and the curve
 * continuation (curvejoin.c).
 */
#include "symline/detect.h"

#include <stddef.h>

#include "common.h"
#include "curvejoin.h"
#include "fieldboundary.h"
#include "fixed.h"
#include "linefilter.h"
#include "merge.h"
#include "pass.h"
#include "passplan.h"
#include "stagemark.h"

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
    cfg->adaptive = true;
    cfg->bright_sigma10 = 0;
    cfg->ridge_sigma10 = 9u;
    cfg->side_sigma10 = 30;
    cfg->a_distance = 0u;
    cfg->contrast_pct = 0u;
    cfg->contrast_min = 3u;
    cfg->contrast_asym_pct = 150u;
    cfg->min_length = 12u;
    cfg->curve_dev_q8 = SL_PX_Q8(2u);
    cfg->curve_bend_q8 = 80u; /* 0.31 px */
    cfg->merge_gap = SYMLINE_MERGE_GAP_AUTO;
    cfg->merge_dev_q8 = SL_PX_Q8(5u) / 2u; /* 2.5 px */
    cfg->field_boundary = SYMLINE_FIELD_DROP;
    cfg->field_margin = 4u;
    symline_field_config_default(&cfg->field);
}

/* The range of one field of symline_config, in declaration order (the
 * order of symline_config_field): where it lies, its largest value and how
 * to read both (SL_R_*). */
typedef struct symline_i_range {
    uint8_t off, flags;
    uint16_t max;
} symline_i_range;

#define SL_R_BYTE 1u   /* a one-byte field (an enum where enums are short, as on arm-none-eabi) */
#define SL_R_Q8 2u     /* the largest value is max << 8 */
#define SL_R_ONE 4u    /* the smallest value is 1 (else 0) */
#define SL_R_SIGNED 8u /* the smallest value is -max */

#define SL_RANGE(f, flags, max)                                                                    \
    {                                                                                              \
        (uint8_t) offsetof(symline_config, f),                                                     \
            (uint8_t)((flags) | (sizeof(((symline_config *)0)->f) == 1u ? SL_R_BYTE : 0u)), max    \
    }

static const symline_i_range RANGES[] = {
    SL_RANGE(axes, 0u, SYMLINE_AXES_BOTH),
    SL_RANGE(radius, SL_R_ONE, SYMLINE_DETECT_MAX_RADIUS),
    SL_RANGE(levels, 0u, SYMLINE_DETECT_MAX_LEVELS),
    SL_RANGE(filter, 0u, SYMLINE_FILTER_PAPER),
    SL_RANGE(illumination, 0u, 255u),
    SL_RANGE(bright_sigma10, SL_R_SIGNED, 100u),
    SL_RANGE(ridge_sigma10, 0u, 100u),
    SL_RANGE(side_sigma10, SL_R_SIGNED, 100u),
    SL_RANGE(a_distance, 0u, SYMLINE_DETECT_MAX_A_DISTANCE),
    SL_RANGE(contrast_pct, 0u, 100u),
    SL_RANGE(contrast_min, 0u, 255u),
    SL_RANGE(contrast_asym_pct, 0u, 1000u),
    SL_RANGE(min_length, 0u, SYMLINE_MAX_DIM),
    /* The Q8 lengths: up to the largest frame dimension. */
    SL_RANGE(curve_dev_q8, SL_R_Q8, SYMLINE_MAX_DIM),
    SL_RANGE(curve_bend_q8, SL_R_Q8, SYMLINE_MAX_DIM),
    /* A gap beyond any frame means nothing, and from 2^24 px its Q8 square
     * would wrap in 64 bits (a larger gap merging less); or AUTO. */
    SL_RANGE(merge_gap, 0u, SYMLINE_MAX_DIM),
    SL_RANGE(merge_dev_q8, SL_R_Q8, SYMLINE_MAX_DIM),
    SL_RANGE(field_boundary, 0u, SYMLINE_FIELD_KEEP),
    SL_RANGE(field_margin, 0u, SYMLINE_MAX_DIM),
};

/* The first field out of its range, or SYMLINE_CFG_NONE. */
static symline_config_field bad_field(const symline_config *c)
{
    uint32_t k;
    for (k = 0; k < sizeof RANGES / sizeof RANGES[0]; k++) {
        const symline_i_range *g = &RANGES[k];
        const uint8_t *at = (const uint8_t *)c + g->off;
        const int32_t max = (int32_t)g->max << ((g->flags & SL_R_Q8) != 0u ? SL_Q8_SHIFT : 0u);
        const int32_t min = (g->flags & SL_R_SIGNED) != 0u ? -max : (int32_t)(g->flags >> 2);
        /* A 4-byte field read as int32: an unsigned value of 2^31 and more
         * turns negative and fails the minimum, as it should (maxima < 2^31). */
        const int32_t v =
            (g->flags & SL_R_BYTE) != 0u ? (int32_t)*at : *(const int32_t *)(const void *)at;
        if ((v < min || v > max) &&
            !(k + 1u == SYMLINE_CFG_MERGE_GAP && c->merge_gap == SYMLINE_MERGE_GAP_AUTO)) {
            return (symline_config_field)(k + 1u);
        }
    }
    return symline_i_field_config_ok(&c->field) ? SYMLINE_CFG_NONE : SYMLINE_CFG_FIELD;
}

symline_status symline_config_check(const symline_config *cfg, symline_config_field *field)
{
    const symline_config_field bad = cfg != NULL ? bad_field(cfg) : SYMLINE_CFG_NONE;
    if (field != NULL) {
        *field = bad;
    }
    if (cfg == NULL) {
        return SYMLINE_ERR_NULL;
    }
    return bad == SYMLINE_CFG_NONE ? SYMLINE_OK : SYMLINE_ERR_CONFIG;
}

/* Number of scales (levels): as configured, or enough that the coarsest one reaches
 * lines width/16 px wide (radius m spans lines up to about 2m+1 px); never
 * a grid smaller than the operator's window. */
uint32_t symline_i_level_count(const symline_config *c, uint32_t width, uint32_t height)
{
    uint32_t levels = c->levels;
    const uint32_t span = 2u * c->radius + 1u;
    if (levels == 0u) {
        levels = 1u;
        while (levels < SYMLINE_DETECT_MAX_LEVELS && (span << (levels - 1u)) < width / 16u) {
            levels++;
        }
    }
    while (levels > 1u &&
           ((width >> (levels - 1u)) < span + 2u || (height >> (levels - 1u)) < span + 2u)) {
        levels--;
    }
    return levels;
}

/* The axes of a detection: how many, and the index-th (horizontal first). */
uint32_t symline_i_axis_count(const symline_config *c)
{
    return c->axes == SYMLINE_AXES_BOTH ? 2u : 1u;
}

symline_axis symline_i_axis_of(const symline_config *c, uint32_t index)
{
    if (c->axes == SYMLINE_AXES_BOTH) {
        return index == 0u ? SYMLINE_AXIS_HORIZONTAL : SYMLINE_AXIS_VERTICAL;
    }
    return c->axes == SYMLINE_AXES_VERTICAL ? SYMLINE_AXIS_VERTICAL : SYMLINE_AXIS_HORIZONTAL;
}

/* Sets up pass k of a detection (fine scale first, horizontal before
 * vertical at each); false after the last. */
SL_NOINLINE static bool pass_nth(symline_i_pass *p, const symline_config *cfg, uint32_t k,
                                 uint32_t width, uint32_t height)
{
    const uint32_t axes = symline_i_axis_count(cfg);
    if (k >= axes * symline_i_level_count(cfg, width, height)) {
        return false;
    }
    /* axes is 1 or 2: k's axis and level by a mask and a shift. */
    symline_i_pass_setup(p, cfg, symline_i_axis_of(cfg, k & (axes - 1u)), k >> (axes - 1u), width,
                         height);
    return true;
}

/* Workspace of the detection's own state (symline_i_run), within the fixed part of
 * SYMLINE_DETECT_WORKSPACE_SIZE() (detect.h) on every target. */
#define SL_RUN_WS_SIZE (symline_i_align_up(sizeof(symline_i_run)) + SL_ALIGN)
typedef char symline_i_run_fits_ws_budget
    [(sizeof(symline_i_run) + (size_t)2u * SL_ALIGN <= SYMLINE_DETECT_WS_RUN) ? 1 : -1];

/* Workspace of the per-column rows of the field boundary (symline_i_run.field_rows). */
static size_t field_rows_size(uint32_t width)
{
    return symline_i_align_up((size_t)width * sizeof(uint16_t)) + SL_ALIGN;
}

SL_NOINLINE size_t symline_detect_workspace_size(uint32_t width, uint32_t height,
                                                 const symline_config *cfg)
{
    symline_i_pass p;
    uint32_t k;
    size_t best = 0u;
    if (cfg == NULL || width == 0u || height == 0u || width > SYMLINE_MAX_DIM ||
        height > SYMLINE_MAX_DIM || symline_config_check(cfg, NULL) != SYMLINE_OK) {
        return 0u;
    }
    for (k = 0; pass_nth(&p, cfg, k, width, height); k++) {
        const size_t n = symline_i_pass_ws_size(&p, width, height);
        best = n > best ? n : best;
    }
    if (cfg->field_boundary != SYMLINE_FIELD_OFF) {
        /* The boundary is found first, in the same workspace. */
        const size_t f = symline_field_workspace_size(width, height, &cfg->field);
        best += field_rows_size(width); /* kept through the passes */
        best = f > best ? f : best;
    }
    if (cfg->adaptive) {
        /* Then the statistics: the field's rows and the histogram. */
        const size_t st =
            field_rows_size(width) + symline_i_align_up(SL_STATS_HIST_BYTES) + SL_ALIGN;
        best = st > best ? st : best;
    }
    /* The detection's own state comes first, for the whole call. */
    return best + SL_RUN_WS_SIZE;
}

/* The adaptive thresholds' statistics: of the field where a boundary was
 * found (lights, walls and people above it would set the thresholds for lines
 * on the carpet), else (field NULL or empty) of the whole frame. */
SL_NOINLINE static void field_stats(const symline_image *img, const symline_field_boundary *field,
                                    uint8_t *ws, size_t ws_size, symline_i_frame_stats *st)
{
    uint8_t *cur = ws;
    uint16_t *top =
        field != NULL && field->count != 0u
            ? (uint16_t *)symline_i_carve(&cur, ws + ws_size, (size_t)img->width * sizeof(uint16_t))
            : NULL;
    uint32_t *hist = (uint32_t *)symline_i_carve(&cur, ws + ws_size, SL_STATS_HIST_BYTES);
    if (hist == NULL) {
        return; /* not reached: the workspace size holds both */
    }
    if (top != NULL) {
        symline_i_field_rows(field, 0u, img->width, img->width, 0u, top);
        symline_i_frame_stats_measure(img, top, hist, st);
        st->grain_q8 = (uint16_t)((uint32_t)field->carpet_tex * field->carpet_mean);
        st->ridge_q4 = (uint16_t)symline_i_ridge_q4(st->sigma_q4, st->grain_q8);
        if (st->mean != 0u || st->sigma_q4 != 0u) {
            return;
        }
    }
    symline_i_frame_stats_measure(img, NULL, hist, st); /* no field, or none in view */
}

/* Every pass, fine scale first, horizontal before vertical. Kept apart from
 * symline_detect() so that the pass state and the merge are never on the
 * stack together. */
SL_NOINLINE static void run_passes(const symline_config *cfg, uint8_t *ws, size_t ws_size,
                                   symline_i_run *d)
{
    uint32_t k;
    uint8_t *cur = ws, *const end = ws + ws_size;
    symline_i_pass *p;
    /* The field boundary's rows stay through the passes (the boundary's own
     * workspace is free again). */
    d->field_rows =
        cfg->field_boundary == SYMLINE_FIELD_DROP
            ? (uint16_t *)symline_i_carve(&cur, end, (size_t)d->img->width * sizeof(uint16_t))
            : NULL;
    p = (symline_i_pass *)symline_i_carve(&cur, end, sizeof(symline_i_pass));
    for (k = 0; p != NULL; k++) {
        SL_STAGE(SETUP);
        if (!pass_nth(p, cfg, k, d->img->width, d->img->height)) {
            return;
        }
        if (cfg->adaptive) {
            symline_i_linefilter_adapt(&p->filter, cfg, &d->stats, p->level);
        }
        if (symline_i_pass_run(d, p, cur, end) != SYMLINE_OK) {
            return; /* not reached: the workspace size was checked */
        }
    }
}

symline_status symline_i_config_ws_check(const symline_image *img, const symline_config *cfg,
                                         size_t ws_size)
{
    const symline_status st = symline_config_check(cfg, NULL);
    if (st != SYMLINE_OK) {
        return st;
    }
    if (ws_size < symline_detect_workspace_size(img->width, img->height, cfg)) {
        return SYMLINE_ERR_BUFFER;
    }
    return SYMLINE_OK;
}

static symline_status detect(const symline_image *img, const symline_config *cfg, void *ws,
                             size_t ws_size, symline_result *out)
{
    symline_status st = symline_image_check(img);
    uint8_t *cur = (uint8_t *)ws, *end;
    symline_i_run *d;
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
    st = symline_i_config_ws_check(img, cfg, ws_size);
    if (st != SYMLINE_OK) {
        return st;
    }
    /* The run's state lives in the workspace, not on the stack: the deepest
     * path of a detection runs below this call. */
    end = cur + ws_size;
    d = (symline_i_run *)symline_i_carve(&cur, end, sizeof(symline_i_run));
    if (d == NULL) {
        return SYMLINE_ERR_BUFFER; /* not reached: the workspace size was checked */
    }
    d->cfg = cfg;
    d->img = img;
    d->r = out;
    d->nseg = 0u;
    d->prev_seg = 0u;
    d->npts = 0u;
    out->points_needed = 0u; /* raised by every pass (pass.c) */
    d->truncated = false;
    if (SL_FOR_SPEED_DEEP) { /* read nowhere else (no code in the firmware) */
        d->cache_top = 0u;
    }
    d->stats.mean = 0u;
    d->stats.sigma_q4 = 0u;
    d->stats.ridge_q4 = 0u;
    out->field.count = 0u;
    if (cfg->field_boundary != SYMLINE_FIELD_OFF) {
        SL_STAGE(FIELD);
        symline_i_field_run(img, &cfg->field, cur, (size_t)(end - cur), &out->field);
    }
    if (cfg->adaptive) {
        SL_STAGE(STATS);
        /* Detections kept above the field are measured against the whole frame. */
        field_stats(img, cfg->field_boundary == SYMLINE_FIELD_DROP ? &out->field : NULL, cur,
                    (size_t)(end - cur), &d->stats);
    }
    run_passes(cfg, cur, (size_t)(end - cur), d);
    out->point_count = d->npts;
    out->segment_count = d->nseg;
    SL_STAGE(MERGE);
    if (cfg->merge_gap != 0u) {
        symline_i_merge(d, cur, (size_t)(end - cur));
    }
    SL_STAGE(CURVEJOIN);
    if (cfg->curve_bend_q8 != 0u) {
        symline_i_curve_join(out);
    }
    out->truncated = d->truncated;
    return SYMLINE_OK;
}

symline_status symline_detect(const symline_image *img, const symline_config *cfg, void *ws,
                              size_t ws_size, symline_result *out)
{
    symline_status st;
    SL_STAGE(SETUP);
    st = detect(img, cfg, ws, ws_size, out);
    SL_STAGE(NONE);
    return st;
}

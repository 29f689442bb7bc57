/* SPDX-License-Identifier: Apache-2.0 */
/*
 * Helpers of the fuzz targets of the core library: configuration fields
 * chosen inside and outside their documented ranges, and the status check
 * every call's result goes through.
 */
#ifndef SYMLINE_FUZZ_LIB_H
#define SYMLINE_FUZZ_LIB_H

#include "fuzz_util.h"
#include "symline/detect.h"

/* Aborts unless st is one of the documented status codes with its own name. */
static inline void fz_check_status(symline_status st, const char *call)
{
    const char *name = symline_status_str(st);
    if (st > SYMLINE_OK || st < SYMLINE_ERR_CONFIG || name == NULL || name[0] == '\0' ||
        strcmp(name, "unknown status") == 0) {
        fprintf(stderr, "%s returned an unknown status %d\n", call, (int)st);
        abort();
    }
}

/* A field with documented range [lo, hi]: default, inside, just outside, at a
 * limit, or any 32-bit value. */
static inline uint32_t fz_pick(fz_in *in, uint32_t def, int64_t lo, int64_t hi)
{
    switch (fz_u8(in) % 8u) {
    case 0:
    case 1:
    case 2: return def;
    case 3: return (uint32_t)(lo + (int64_t)(fz_u32(in) % (uint64_t)(hi - lo + 1)));
    case 4: return (uint32_t)(hi + 1);
    case 5: return (uint32_t)(lo - 1);
    case 6: return (uint32_t)(fz_u8(in) & 1u ? lo : hi);
    default: return fz_u32(in);
    }
}

/* 1..96 mostly; 0 or 65536 (invalid) now and then. */
static inline uint32_t fz_dim(fz_in *in)
{
    const uint32_t v = fz_u8(in);
    if (v == 0u) {
        return 0u;
    }
    if (v == 255u) {
        return 65536u;
    }
    return 1u + v % 96u;
}

/* The fields of symline_detect()'s configuration but the field boundary's. */
static inline void fz_detect_config(fz_in *in, symline_config *cfg)
{
    symline_config def;
    symline_config_default(&def);
    *cfg = def;
    cfg->axes = (symline_axes)fz_pick(in, (uint32_t)def.axes, 0, 2);
    cfg->radius = fz_pick(in, def.radius, 1, 32);
    cfg->levels = fz_pick(in, def.levels, 0, 5);
    cfg->filter = (symline_filter)fz_pick(in, (uint32_t)def.filter, 0, 1);
    cfg->illumination = fz_pick(in, def.illumination, 0, 255);
    cfg->adaptive = fz_pick(in, def.adaptive, 0, 1);
    cfg->bright_sigma10 = (int32_t)fz_pick(in, (uint32_t)def.bright_sigma10, -100, 100);
    cfg->ridge_sigma10 = fz_pick(in, def.ridge_sigma10, 0, 100);
    cfg->side_sigma10 = (int32_t)fz_pick(in, (uint32_t)def.side_sigma10, -100, 100);
    cfg->a_distance = fz_pick(in, def.a_distance, 0, 32);
    cfg->contrast_pct = fz_pick(in, def.contrast_pct, 0, 100);
    cfg->contrast_min = fz_pick(in, def.contrast_min, 0, 255);
    cfg->contrast_asym_pct = fz_pick(in, def.contrast_asym_pct, 0, 1000);
    cfg->min_length = fz_pick(in, def.min_length, 0, 65535);
    cfg->curve_dev_q8 = fz_pick(in, def.curve_dev_q8, 0, 65535 << 8);
    cfg->curve_bend_q8 = fz_pick(in, def.curve_bend_q8, 0, 65535 << 8);
    cfg->merge_gap = fz_pick(in, def.merge_gap, 0, 65535);
    cfg->merge_dev_q8 = fz_pick(in, def.merge_dev_q8, 0, 65535 << 8);
    if (fz_u8(in) % 4u != 0u) {
        /* Mostly small line lengths, so that short fuzzed frames give segments. */
        cfg->min_length = fz_u8(in) % 16u;
    }
}

/* Every field of the field boundary's configuration (symline/field.h). */
static inline void fz_field_config(fz_in *in, symline_field_config *fc)
{
    symline_field_config def;
    symline_field_config_default(&def);
    *fc = def;
    fc->cell = fz_u8(in) % 4u == 0u ? (1u << (fz_u8(in) % 8u)) : fz_pick(in, def.cell, 0, 64);
    fc->band_pct = fz_pick(in, def.band_pct, 1, 100);
    fc->mean_tol = fz_pick(in, def.mean_tol, 0, 255);
    fc->local_tol = fz_pick(in, def.local_tol, 0, 255);
    fc->tex_lo_pct = fz_pick(in, def.tex_lo_pct, 0, 100);
    fc->tex_hi_pct = fz_pick(in, def.tex_hi_pct, 100, 10000);
    fc->miss_cost = fz_pick(in, def.miss_cost, 1, 16);
    fc->gap_pct = fz_pick(in, def.gap_pct, 0, 100);
    fc->support = fz_pick(in, def.support, 1, 8);
    fc->restore_cells = fz_pick(in, def.restore_cells, 0, 64);
    fc->col_cells = fz_pick(in, def.col_cells, 1, 4);
    fc->edge_slope_pct = fz_pick(in, def.edge_slope_pct, 0, 10000);
}

/* The documented range check of symline_field_config (symline/field.h). */
static inline int fz_field_config_ok(const symline_field_config *fc)
{
    const uint32_t c = fc->cell;
    return (c == 0u || (c >= 2u && c <= 64u && (c & (c - 1u)) == 0u)) && fc->band_pct >= 1u &&
           fc->band_pct <= 100u && fc->mean_tol <= 255u && fc->local_tol <= 255u &&
           fc->tex_lo_pct <= 100u && fc->tex_hi_pct >= 100u && fc->tex_hi_pct <= 10000u &&
           fc->miss_cost >= 1u && fc->miss_cost <= 16u && fc->gap_pct <= 100u &&
           fc->support >= 1u && fc->support <= 8u && fc->restore_cells <= 64u &&
           fc->col_cells >= 1u && fc->col_cells <= 4u && fc->edge_slope_pct <= 10000u;
}

/* Aborts unless b is a boundary as symline/field.h describes it for a
 * width x height frame. */
static inline void fz_check_boundary(const symline_field_boundary *b, uint32_t w, uint32_t h)
{
    uint32_t i;
    if (b->count < 1u || b->count > SYMLINE_FIELD_MAX_VERTICES || b->v[0].x != 0 ||
        b->v[b->count - 1u].x != (int32_t)w - 1 || (w == 1u && b->count != 1u)) {
        fprintf(stderr, "boundary: %u vertices from x=%d to x=%d, frame %ux%u\n", b->count,
                b->v[0].x, b->v[b->count > 0u ? b->count - 1u : 0u].x, w, h);
        abort();
    }
    for (i = 0; i < b->count; i++) {
        if (b->v[i].y < 0 || b->v[i].y > (int32_t)h || (i > 0u && b->v[i].x <= b->v[i - 1u].x)) {
            fprintf(stderr, "boundary vertex %u (%d, %d) out of order or range, frame %ux%u\n", i,
                    b->v[i].x, b->v[i].y, w, h);
            abort();
        }
    }
}

#endif

/* SPDX-License-Identifier: Apache-2.0 */
/*
 * symline — the line detector: from a gray frame to field-line segments (docs/detector.md).
 *
 * One call, caller-owned memory, no allocation, no floating point:
 *
 *     symline_config cfg;
 *     symline_config_default(&cfg);
 *     size_t need = symline_detect_workspace_size(w, h, &cfg);   // bytes
 *     ... ws = a static or stack buffer of `need` bytes ...
 *     symline_segment segs[64];
 *     symline_point pts[8192];
 *     symline_result res = { segs, 64, 0, pts, 8192, 0, 0, {0}, 0 };
 *     symline_status st = symline_detect(&img, &cfg, ws, need, &res);
 *
 * First the field boundary (symline/field.h, config field_boundary): where
 * the carpet ends, reported in result.field; by default line points above it
 * are dropped before they are traced. Then the pipeline, run once per axis
 * and scale ("pass"), fine scale first:
 *  1. operator + extrema over a ring of rows (the frame is processed in
 *     horizontal strips; working memory grows with width * radius, not with
 *     the frame height);
 *  2. line filter: an S point (symmetry maximum) becomes a line point when it
 *     is a bright ridge across the line (contrast filter, default) or, the
 *     paper's A1-S filter, when an A point lies near it across the line and
 *     its gray value reaches the illumination threshold;
 *  3. line points are kept as a raster-ordered list in the caller's point
 *     storage with a per-row index, and traced from their end points (paper's
 *     search order: straight ahead, then 45-degree, then 90-degree turns),
 *     closed loops included;
 *  4. chains are cut at sharp corners, parts already found by an earlier pass
 *     (other axis, finer scale) are removed, pieces are fitted, classified as
 *     line or curve by their largest distance to the chord, short ones dropped;
 *  5. collinear line pieces interrupted by occluders are merged (`merged`);
 *  6. a line piece that continues a curve smoothly becomes part of it.
 *
 * Coordinates: image pixels, x right, y down, integers at pixel centres.
 * "Q8" values are fixed point with 8 fraction bits (256 = 1 px).
 */
#ifndef SYMLINE_DETECT_H
#define SYMLINE_DETECT_H

#include <stdbool.h>

#include "symline/field.h"
#include "symline/types.h"

#ifdef __cplusplus
extern "C" {
#endif

/* Largest detector radius (config.radius), pixels. */
#define SYMLINE_DETECT_MAX_RADIUS 32u
/* Largest number of scales (config.levels). */
#define SYMLINE_DETECT_MAX_LEVELS 5u
/* Largest A point distance of the paper filter (config.a_distance), pixels. */
#define SYMLINE_DETECT_MAX_A_DISTANCE 32u
/* config.merge_gap: the gap follows the frame, width / 8 px. */
#define SYMLINE_MERGE_GAP_AUTO 0xFFFFFFFFu

/* What the detector does with the field boundary. */
typedef enum symline_field_mode {
    SYMLINE_FIELD_OFF = 0,  /* not computed (result.field.count = 0) */
    SYMLINE_FIELD_DROP = 1, /* computed, reported; line points above it dropped */
    SYMLINE_FIELD_KEEP = 2  /* computed, reported; every detection kept */
} symline_field_mode;

/* Which axes a detection runs. */
typedef enum symline_axes {
    SYMLINE_AXES_HORIZONTAL = 0, /* near-horizontal lines only (symmetry along columns) */
    SYMLINE_AXES_VERTICAL = 1,   /* near-vertical lines only (symmetry along rows) */
    SYMLINE_AXES_BOTH = 2        /* both; a line seen by both is reported once */
} symline_axes;

/* Which line filter turns S points into line points. */
typedef enum symline_filter {
    /* Bright ridge test: the S point's gray value c and the gray values lo, hi
     * at radius+1 pixels on either side across the line must satisfy
     * c - max(lo, hi) >= max(contrast_min, c * contrast_pct / 100, ridge,
     *                           |lo - hi| * contrast_asym_pct / 100)
     * (ridge: see `adaptive`).
     * With `adaptive` the ridge height is measured in units of the frame's
     * contrast, so it keeps working when the illumination changes. */
    SYMLINE_FILTER_CONTRAST = 0,
    /* The paper's A1-S pattern: an A point within a_distance pixels across
     * the line. Use with illumination = 100 for the paper's baseline. */
    SYMLINE_FILTER_PAPER = 1
} symline_filter;

/* Kind of a segment. */
typedef enum symline_kind {
    SYMLINE_KIND_LINE = 0, /* max_dev <= the curve threshold */
    SYMLINE_KIND_CURVE = 1 /* max_dev above it: follow its points, not its chord */
} symline_kind;

/*
 * Detector settings. Always start from symline_config_default(); the ranges
 * are checked by symline_detect() (SYMLINE_ERR_CONFIG when violated).
 */
/* (The field comments are laid out by hand.) */
/* clang-format off */
typedef struct symline_config {
    symline_axes axes;     /* default SYMLINE_AXES_BOTH */
    uint32_t radius;       /* symmetry radius m, 1..SYMLINE_DETECT_MAX_RADIUS (32);
                              default 3 */
    uint32_t levels;       /* scales: 1 = full resolution only, L = also 2x, 4x ..
                              2^(L-1)x box-downsampled; 0 = auto (enough scales
                              for lines width/16 px wide);
                              0..SYMLINE_DETECT_MAX_LEVELS (5), default 0 */
    symline_filter filter; /* default SYMLINE_FILTER_CONTRAST */
    uint32_t illumination; /* minimum gray value of a line point, 0..255
                              (0 disables); default 0, the paper used 100 */
    bool adaptive;         /* true: the thresholds below follow the gray values of
                              the field (below the field boundary; the whole
                              frame when there is none or detections above it
                              are kept): their median ("mean" below) and their
                              spread sigma (1.4826 x the median absolute
                              deviation), on every 4th pixel of every 4th row,
                              so a brighter, darker or lower-contrast exposure
                              of the same scene gives the same lines; false:
                              off. Default true */
    int32_t bright_sigma10; /* adaptive: a line point's gray value must reach
                              mean + bright_sigma10/10 * sigma, -100..100;
                              default 0 (the mean) */
    uint32_t ridge_sigma10; /* adaptive: contrast filter ridge height of at
                              least ridge_sigma10/10 * sigma, 0..100; default 9.
                              Where the field boundary found a carpet (field
                              drop), also at least 2.5 times its grain (the
                              mean |difference| of neighbouring pixels on it),
                              halved per scale: its noise alone */
    int32_t side_sigma10;  /* adaptive, contrast filter: both sides of the ridge
                              must stay at or below mean + side_sigma10/10 *
                              sigma (a line lies on the darker carpet, not on a
                              bright wall), one sigma more at full resolution
                              (the sides lie in a bright line's blur there),
                              -100..100; 100 = off; default 30 */
    uint32_t a_distance;   /* paper filter: largest distance (px, at the pass's
                              scale) of the A point across the line,
                              1..SYMLINE_DETECT_MAX_A_DISTANCE (32);
                              default 0 = the radius */
    uint32_t contrast_pct; /* contrast filter: relative ridge height, % of the
                              centre gray value, 0..100; default 0 */
    uint32_t contrast_min; /* contrast filter: smallest ridge height in gray
                              levels, 0..255; default 3 */
    uint32_t contrast_asym_pct; /* contrast filter: the ridge height must also reach
                              this % of |lo - hi|, so a bright band between two
                              different surfaces (a wall's edge) is not taken
                              for a line on the carpet; summed along a traced
                              piece, twice this % (0 disables both), 0..1000;
                              default 150 */
    uint32_t min_length;   /* shortest reported piece, px along its points;
                              default 12 */
    uint32_t curve_dev_q8; /* curve threshold on max_dev, Q8 px; default 512 (2 px) */
    uint32_t curve_bend_q8; /* also a curve: a piece whose middle half lies this far
                              (mean, Q8 px of the pass's grid) off the chord
                              compared with its outer quarters; tested at the
                              two finest scales; a line continuing a curve is
                              a curve too; 0 disables both; default 80 (0.31 px) */
    uint32_t merge_gap;    /* merge collinear lines whose ends are at most this
                              far apart, px, 0..65535; 0 disables; default
                              SYMLINE_MERGE_GAP_AUTO = width / 8 */
    uint32_t merge_dev_q8; /* ... and whose ends lie within this distance of the
                              other's line, Q8 px; default 640 (2.5 px) */
    symline_field_mode field_boundary; /* the field boundary (symline/field.h),
                              found before the passes and reported in
                              result.field: SYMLINE_FIELD_DROP (default) also
                              drops line points above it before they are
                              traced, SYMLINE_FIELD_KEEP keeps them,
                              SYMLINE_FIELD_OFF does not look for it */
    uint32_t field_margin; /* DROP keeps line points up to this many px above
                              the boundary, 0..SYMLINE_MAX_DIM; default 4 */
    symline_field_config field; /* the boundary's settings; default
                              symline_field_config_default() */
} symline_config;
/* clang-format on */

/* Fills *cfg with the defaults documented above (no-op on NULL). */
void symline_config_default(symline_config *cfg);

/* A field of symline_config, for symline_config_check(); in declaration order. */
typedef enum symline_config_field {
    SYMLINE_CFG_NONE = 0, /* every field within its range */
    SYMLINE_CFG_AXES,
    SYMLINE_CFG_RADIUS,
    SYMLINE_CFG_LEVELS,
    SYMLINE_CFG_FILTER,
    SYMLINE_CFG_ILLUMINATION,
    SYMLINE_CFG_BRIGHT_SIGMA10,
    SYMLINE_CFG_RIDGE_SIGMA10,
    SYMLINE_CFG_SIDE_SIGMA10,
    SYMLINE_CFG_A_DISTANCE,
    SYMLINE_CFG_CONTRAST_PCT,
    SYMLINE_CFG_CONTRAST_MIN,
    SYMLINE_CFG_CONTRAST_ASYM_PCT,
    SYMLINE_CFG_MIN_LENGTH,
    SYMLINE_CFG_CURVE_DEV_Q8,
    SYMLINE_CFG_CURVE_BEND_Q8,
    SYMLINE_CFG_MERGE_GAP, /* 0..65535 or SYMLINE_MERGE_GAP_AUTO */
    SYMLINE_CFG_MERGE_DEV_Q8,
    SYMLINE_CFG_FIELD_BOUNDARY,
    SYMLINE_CFG_FIELD_MARGIN,
    SYMLINE_CFG_FIELD /* a setting of config.field (symline/field.h) */
} symline_config_field;

/*
 * The range check symline_detect() makes, with the culprit named: returns
 * SYMLINE_OK, SYMLINE_ERR_NULL (cfg NULL) or SYMLINE_ERR_CONFIG, and when
 * field is not NULL sets *field to the first field out of its range
 * (SYMLINE_CFG_RADIUS for config.radius, ...), SYMLINE_CFG_NONE when there
 * is none. adaptive and merge_gap take any value, so they are never named.
 */
symline_status symline_config_check(const symline_config *cfg, symline_config_field *field);

/*
 * One traced point, in full-resolution pixels: the pixel (x, y) nearest to the
 * point and the point's sub-pixel offset from that pixel's centre in 1/128 px,
 * -64..63 (fx, fy): the point lies at (x + fx/128, y + fy/128). The offset is
 * taken across the line (the ridge's middle, from the symmetry energies around
 * the S point), so fy is 0 for points found along rows (vertical axis) and fx
 * for points found along columns, except at coarse scales, whose grid points
 * map to block centres between full-resolution pixels.
 */
typedef struct symline_point {
    uint16_t x;
    uint16_t y;
    int8_t fx;
    int8_t fy;
} symline_point;

/* One detected segment. */
typedef struct symline_segment {
    int32_t x0, y0, x1, y1; /* end points, Q8 px (pixel centres are multiples of 256) */
    uint32_t max_dev;       /* largest distance of its points to the chord, Q8 px */
    uint32_t first;         /* its points are result.points[first .. first+count-1], */
    uint32_t count;         /* in tracing order (for merged lines: piece after piece) */
    uint8_t kind;           /* symline_kind */
    uint8_t axis;           /* symline_axis of the pass that found it */
    uint8_t level;          /* scale: 0 full resolution, l = 2^l x downsampled */
    bool merged;            /* joined from collinear pieces by the merge (a line
                               whose points run piece after piece) */
} symline_segment;

/*
 * Output storage, owned by the caller. Set the four array fields before the
 * call; symline_detect() writes the counts, the flag and points_needed.
 *
 * The point storage also serves as scratch for the raster list of line
 * points of the pass being traced: give it room for about twice the line
 * points of one pass (a 320x240 field view has a few thousand). When either
 * array runs out, the detection still finishes with what fits and sets
 * `truncated`; nothing is ever written beyond the capacities.
 */
typedef struct symline_result {
    symline_segment *segments;
    uint32_t segment_cap;
    uint32_t segment_count;
    symline_point *points;
    uint32_t point_cap;
    uint32_t point_count;         /* points referenced by the segments, [0, point_count) */
    bool truncated;               /* true when segments or points did not fit */
    symline_field_boundary field; /* the field boundary (symline/field.h);
                                     count 0 when not computed */
    uint32_t points_needed;       /* the point_cap this frame needed: when truncated
                                     is false, exactly the smallest capacity that
                                     gives this same result (size a static array
                                     from the largest value over representative
                                     frames); when points ran out, at least enough
                                     for the pass that ran out (more than point_cap;
                                     repeat with it until truncated is false) */
} symline_result;

/*
 * Bytes of workspace symline_detect() needs for a width x height frame with
 * this configuration (the largest of its passes), or 0 when the arguments
 * are invalid. Grows with width * radius (plus 4 bytes per row for the row
 * index), never with width * height.
 */
size_t symline_detect_workspace_size(uint32_t width, uint32_t height, const symline_config *cfg);

/*
 * The same as a constant expression, for static buffers:
 *
 *     static uint8_t ws[SYMLINE_DETECT_WORKSPACE_SIZE(320, 240, 3, 0, 0)];
 *
 * At least symline_detect_workspace_size() for a width x height frame and any
 * configuration with this radius, A distance and levels (the axes, the field
 * boundary's mode and the other fields do not raise it; config.field.cell 0,
 * the default, or at least the automatic cell: 8 px, 16 px from 1024 px wide
 * on), on every target; a few hundred bytes more than
 * the query, a little more when only the vertical axis runs, and on 64-bit
 * targets up to 14 B per grid column and 290 B more (the field boundary's
 * lanes, which a library built for size does not use). a_distance is
 * the A point distance the filter uses: 0 with the contrast filter (the
 * default); with the paper filter its config.a_distance, or the radius when
 * that is 0. levels as in the config (0 = auto). Arguments are evaluated more
 * than once.
 */
#define SYMLINE_DETECT_WORKSPACE_SIZE(width, height, radius, a_distance, levels)                   \
    ((size_t)SYMLINE_DETECT_WS_RUN +                                                               \
     SYMLINE_DETECT_WS_MAX_(SYMLINE_DETECT_WS_PASSES_(width, height, radius, a_distance, levels) + \
                                2u * (size_t)(width) + 16u,                                        \
                            SYMLINE_DETECT_WS_MAX_(2u * (size_t)(width) + 1056u,                   \
                                                   SYMLINE_DETECT_WS_FIELD_(width, height))))
/* The passes over axes and scales (lib/pass.h), the largest of them: at full
 * resolution the frame's rows are read in place; a coarser scale holds its
 * grid rows (twice 2 (a_distance + 2 radius + 1) + 1 of them down the columns). */
#define SYMLINE_DETECT_WS_PASSES_(width, height, radius, a_distance, levels)                       \
    ((size_t)SYMLINE_DETECT_WS_FIXED + (size_t)4u * ((size_t)(height) + 1u) +                      \
     SYMLINE_DETECT_WS_MAX_(SYMLINE_DETECT_WS_COARSE_(width, height, radius, a_distance, levels),  \
                            SYMLINE_DETECT_WS_GRID_(width, height)))
/* The tracing's state and the grid of earlier segments (lib/segindex.h):
 * 32 px cells, 4 bytes each plus 4 segment ids of 4 bytes. */
#define SYMLINE_DETECT_WS_GRID_(width, height)                                                     \
    ((size_t)192u +                                                                                \
     (size_t)20u * (((size_t)(width) + 31u) / 32u) * (((size_t)(height) + 31u) / 32u))
/* The field boundary's search (symline/field.h) with cells of the automatic
 * size or larger: 8 px, 16 px from 1024 px wide on; on 64-bit targets also
 * its column scan's lanes. */
#define SYMLINE_DETECT_WS_FIELD_(width, height)                                                    \
    ((size_t)640u + 3u * ((size_t)(width) / SYMLINE_DETECT_WS_CELL_(width) + 1u) * 8u +            \
     2u * ((size_t)(height) / SYMLINE_DETECT_WS_CELL_(width) + 1u) *                               \
         ((size_t)(width) / SYMLINE_DETECT_WS_CELL_(width) + 1u) +                                 \
     SYMLINE_DETECT_WS_LANES_((size_t)(width) / SYMLINE_DETECT_WS_CELL_(width) + 1u))
#if UINTPTR_MAX > 0xFFFFFFFFu
/* 14 bytes per grid column, rounded up to 16 columns, and 80 (the cells
 * read past the band's end, alignment) */
#define SYMLINE_DETECT_WS_LANES_(cols) ((size_t)14u * ((size_t)(cols) + 15u) + 80u)
#else
#define SYMLINE_DETECT_WS_LANES_(cols) ((size_t)0u)
#endif
#define SYMLINE_DETECT_WS_CELL_(width) ((size_t)(width) >= 1024u ? 16u : 8u)
/* The coarser scales (2x downsampled and beyond), when the configuration and
 * the frame have them (detect.c: the number of scales). */
#define SYMLINE_DETECT_WS_COARSE_(width, height, radius, a_distance, levels)                       \
    (((levels) == 0u ? 2u * (size_t)(radius) + 1u < (size_t)(width) / 16u : (levels) >= 2u) &&     \
             (size_t)(width) / 2u >= 2u * (size_t)(radius) + 3u &&                                 \
             (size_t)(height) / 2u >= 2u * (size_t)(radius) + 3u                                   \
         ? ((size_t)(width) / 2u) * (6u + 4u * (size_t)(a_distance) + 8u * (size_t)(radius)) +     \
               2u * (size_t)(width)                                                                \
         : (size_t)0u)
/* Bytes of the detection's own state within that bound (checked when the library is compiled). */
#define SYMLINE_DETECT_WS_RUN 96u
/* Bytes of a pass's fixed state within that bound (checked when the library is compiled). */
#define SYMLINE_DETECT_WS_FIXED 512u
#define SYMLINE_DETECT_WS_MAX_(a, b) ((a) > (b) ? (a) : (b))

/*
 * Detects line segments. ws: ws_size bytes (any alignment) of scratch the
 * call may overwrite. out: caller storage as above; out->segments and
 * out->points may be NULL only with a capacity of 0.
 * Returns SYMLINE_OK (check out->truncated), ERR_NULL, ERR_SIZE, ERR_STRIDE,
 * ERR_CONFIG (a field out of range, radius included; symline_config_check()
 * names it), or ERR_BUFFER
 * (ws_size too small). On an error nothing in *out is changed.
 */
symline_status symline_detect(const symline_image *img, const symline_config *cfg, void *ws,
                              size_t ws_size, symline_result *out);

/*
 * The line filter's output alone: the line points of every pass (axes and
 * scales as configured, adaptive thresholds included), in full-resolution
 * pixels with their sub-pixel offsets across the line (fx, fy, as in the
 * segments' points), pass after pass,
 * each pass in raster order, written to pts[0 .. *count-1]. Points without a
 * line point among their 8 neighbours in their pass (type A in the paper's classification) are
 * left out, as the tracer ignores them. A pixel found by two passes is
 * listed twice. This is what symline_detect() traces and what
 * the Muff-space finder (symline/muff.h) votes with.
 * ws: ws_size >= symline_detect_workspace_size() bytes; pts: cap entries
 * (not NULL; give room for every line point: a few thousand in a 320x240
 * field view). When cap runs out,
 * the points that fit are kept and *truncated is set to true (else false).
 * Returns SYMLINE_OK, ERR_NULL, ERR_SIZE, ERR_STRIDE, ERR_CONFIG or ERR_BUFFER.
 */
symline_status symline_line_points(const symline_image *img, const symline_config *cfg, void *ws,
                                   size_t ws_size, symline_point *pts, uint32_t cap,
                                   uint32_t *count, bool *truncated);

#ifdef __cplusplus
}
#endif

#endif /* SYMLINE_DETECT_H */

/* SPDX-License-Identifier: Apache-2.0 */
/*
 * symline — stage marks for profiling a detection (optional; off by default).
 *
 * A library built with SYMLINE_PROFILE defined and lib/profile.c added (CMake
 * target symline_profiled, or -DSYMLINE_PROFILE=1 in a firmware's own build of
 * lib/) calls
 *
 *     void symline_profile_mark(symline_stage stage);
 *
 * each time symline_detect() moves on to another stage, and once with
 * SYMLINE_STAGE_NONE when it returns. The application provides this function:
 * it reads a clock or cycle counter (on a Cortex-M, DWT->CYCCNT; on a host,
 * clock_gettime) and adds the time since the previous mark to the stage that
 * was running. The marks follow the work as it happens: the strip-wise passes
 * change stage a few times per grid row (operator, extrema, filter), so a
 * profiled detection of a 640x480 frame makes some thousands of calls; keep
 * the function short and re-entrant-free (it runs on the detector's stack).
 *
 * Without SYMLINE_PROFILE the marks compile to nothing: no call, no symbol,
 * the same machine code and size as without them.
 */
#ifndef SYMLINE_PROFILE_H
#define SYMLINE_PROFILE_H

#ifdef __cplusplus
extern "C" {
#endif

/* The stages of symline_detect(), in the order they first run. */
typedef enum symline_stage {
    SYMLINE_STAGE_NONE = 0,  /* outside the detection (or between stages) */
    SYMLINE_STAGE_SETUP,     /* checks, configuration, workspace layout */
    SYMLINE_STAGE_FIELD,     /* field boundary; line points above it dropped */
    SYMLINE_STAGE_STATS,     /* the field's gray statistics (adaptive thresholds) */
    SYMLINE_STAGE_GRID,      /* box downsampling of rows for the coarser scales */
    SYMLINE_STAGE_OPERATOR,  /* symmetry energies (docs/algorithm.md) */
    SYMLINE_STAGE_EXTREMA,   /* extrema of symmetry (docs/algorithm.md) */
    SYMLINE_STAGE_FILTER,    /* line filter: S points to line points */
    SYMLINE_STAGE_TRACE,     /* tracing chains through the line points */
    SYMLINE_STAGE_SEGMENTS,  /* corner cuts, overlap with earlier passes, fits, tests */
    SYMLINE_STAGE_SUBPIXEL,  /* sub-pixel offsets of a piece's points across the line */
    SYMLINE_STAGE_MERGE,     /* merging collinear pieces */
    SYMLINE_STAGE_CURVEJOIN, /* lines that continue curves */
    SYMLINE_STAGE_COUNT      /* number of stages, not a stage */
} symline_stage;

/* A short lower-case name of a stage ("operator"); "?" outside the range.
 * In the profiled library only (lib/profile.c). */
const char *symline_stage_name(symline_stage stage);

/* Provided by the application, called only by a library built with SYMLINE_PROFILE. */
void symline_profile_mark(symline_stage stage);

#ifdef __cplusplus
}
#endif

#endif /* SYMLINE_PROFILE_H */

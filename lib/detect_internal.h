/*
 * Internal interfaces between the detector's modules (linefilter, linepoints,
 * tracer, segments, detect). Not part of the public API; the tests use them
 * to run the same stages over a full-frame path.
 */
#ifndef SYMLINE_DETECT_INTERNAL_H
#define SYMLINE_DETECT_INTERNAL_H

#include "symline/detect.h"
#include "internal.h"

/* Keeps a helper with a large frame out of its caller's frame, so the deepest
 * stack path stays short (measured by tools/firmware/check.sh). */
#if defined(__GNUC__)
#define SL_NOINLINE __attribute__((noinline))
#else
#define SL_NOINLINE
#endif

/* Marks a point of the raster list as visited by the tracer (y is never 65535). */
#define SL_VISITED 0xFFFFu

/* One pass: an axis at one scale. Coordinates of a pass are on its grid. */
typedef struct sl_pass {
    symline_axis axis;
    uint32_t level;   /* grid = frame box-downsampled by 2^level */
    uint32_t w, h;    /* grid size: width >> level, height >> level */
    uint32_t m;       /* radius */
    uint32_t k;       /* contrast sample offset across the line: m + 1 */
    uint32_t a_dist;  /* A point search distance; 0 for the contrast filter */
    uint32_t lag;     /* longest accepted plateau: end - marked index <= lag (= m) */
    symline_filter filter;
    uint32_t illum, pct, cmin, apct;
    uint32_t side_max; /* largest gray value of the ridge's sides (255: any) */
} sl_pass;

/* linefilter.c: fills a pass from the configuration (no range checks). */
void sl_pass_setup(sl_pass *p, const symline_config *cfg, symline_axis axis, uint32_t level,
                   uint32_t width, uint32_t height);

/* linefilter.c: the gray-value part of the line filter for an S point with
 * centre value c and values lo, hi at k pixels before and after it across the
 * line (clamped at the border). 1 = line point (the paper filter's A point
 * test is done by the caller). */
static inline int sl_filter_gray(const sl_pass *p, uint32_t c, uint32_t lo, uint32_t hi)
{
    uint32_t side, need;
    if (c < p->illum) {
        return 0;
    }
    if (p->filter == SYMLINE_FILTER_PAPER) {
        return 1;
    }
    side = lo > hi ? lo : hi;
    if (c <= side || side > p->side_max) {
        return 0;
    }
    need = (c * p->pct + 99u) / 100u;
    if (need < p->cmin) {
        need = p->cmin;
    }
    if (p->apct != 0u) {
        const uint32_t asym = ((lo > hi ? lo - hi : hi - lo) * p->apct + 99u) / 100u;
        need = asym > need ? asym : need;
    }
    if (c - side < need) {
        return 0;
    }
    return 1;
}

/* linepoints.c: box-downsampled row y of the pass grid into out (p->w bytes);
 * acc: scratch of img->width uint16_t. Level 0 copies the row. */
void sl_grid_row(const symline_image *img, const sl_pass *p, uint32_t y, uint16_t *acc,
                 uint8_t *out);

/* linepoints.c: workspace bytes of sl_collect() (row index excluded). */
size_t sl_collect_ws_size(const sl_pass *p, uint32_t img_width);

/*
 * linepoints.c: the line points of one pass, in raster order, grid
 * coordinates, written to pts[0 .. *n-1] (at most cap); row_start[y] is the
 * index of the first point of grid row y, row_start[h] = *n (h+1 entries).
 * Sets *truncated when cap was too small. Strip processing: only a ring of
 * rows is held.
 */
symline_status sl_collect(const symline_image *img, const sl_pass *p, void *ws, size_t ws_size,
                          symline_point *pts, uint32_t cap, uint32_t *n, uint32_t *row_start,
                          uint8_t *truncated);

/* tracer.c: iterator over the chains of a raster list. */
typedef struct sl_tracer {
    symline_point *pts; /* raster list; visited entries get y = SL_VISITED */
    uint32_t n;
    const uint32_t *row_start;
    uint32_t h;
    uint32_t scan;  /* next raster index to try as a start */
    uint32_t phase; /* 0: starts at B points, 1: everything left (loops) */
} sl_tracer;

void sl_tracer_init(sl_tracer *t, symline_point *pts, uint32_t n, const uint32_t *row_start,
                    uint32_t h);

/* Number of line points among the 8 neighbours of (x, y) (visited or not). */
uint32_t sl_neighbours(const sl_tracer *t, uint32_t x, uint32_t y);

/* Reverses n points in place (the tracer's backward half, the merge's rotations). */
void sl_reverse_points(symline_point *p, uint32_t n);

/*
 * Next chain, written to dst[0 .. *count-1] in tracing order (grid
 * coordinates). Returns 1 for a chain, 0 when none is left. A chain longer
 * than cap is cut at cap points and *cut is set.
 */
int sl_tracer_next(sl_tracer *t, symline_point *dst, uint32_t cap, uint32_t *count,
                   uint8_t *cut);

/* segments.c */
uint64_t sl_isqrt64(uint64_t v);

/* Q8 full-resolution coordinate of grid coordinate v at a level (block centre). */
static inline int32_t sl_q8(uint32_t v, uint32_t level)
{
    return (int32_t)(((v << level) << 8) + (((1u << level) - 1u) << 7));
}

/* Distance (Q8) of (px, py) to the line through a with direction (dx, dy), all Q8. */
uint32_t sl_line_dist_q8(int32_t ax, int32_t ay, int32_t dx, int32_t dy, int32_t px, int32_t py);

/* cross / len in Q8 with a 32-bit division (see segments.c). */
uint32_t sl_div_q8(uint64_t cross, uint64_t len);

/* Largest distance (Q8) of points p[0..n-1] (grid coordinates at `level`;
 * level 0 for full-resolution points) to the chord (x0,y0)-(x1,y1) (Q8). */
uint32_t sl_max_dev(const symline_point *p, uint32_t n, uint32_t level, int32_t x0, int32_t y0,
                    int32_t x1, int32_t y1);

/* Curve test: max_dev above thr and above 1/32 of the chord. */
int sl_is_curve(int32_t x0, int32_t y0, int32_t x1, int32_t y1, uint32_t max_dev, uint32_t thr);

/* Length of the first piece of chain p[0..n-1] before a sharp corner (n if none). */
uint32_t sl_corner_cut(const symline_point *p, uint32_t n);

/* Fits a segment to p[0..n-1] (grid coordinates at `level`): ends, max_dev, kind. */
void sl_fit(const symline_point *p, uint32_t n, uint32_t level, uint32_t curve_dev_q8,
            symline_segment *s);

/* Bend of p[0..n-1] (grid coordinates): mean distance to the chord of the middle
 * half minus that of the outer quarters, Q8 grid px, absolute. */
uint32_t sl_bend_q8(const symline_point *p, uint32_t n);

/* Makes line s (fitted to p[0..n-1] at `level`) a curve when its bend reaches
 * bend_thr: kind, raw chord ends and max_dev. */
void sl_bend_check(const symline_point *p, uint32_t n, uint32_t level, uint32_t bend_thr,
                   symline_segment *s);

/* Curves are followed through every SL_POLY_STEP-th point (sl_near_segment). */
#define SL_POLY_STEP 4u

/* 1 when the full-resolution point (x, y) (Q8) lies within tol_q8 of segment s
 * (its chord for lines, its points for curves). */
int sl_near_segment(const symline_segment *s, const symline_point *pts, int32_t x, int32_t y,
                    int32_t tol_q8);

/* merge.c: merges collinear line segments of r (points kept contiguous by
 * rotation); a merged segment gets reserved = 1 until sl_curve_join(). */
void sl_merge(symline_result *r, uint32_t gap_px, uint32_t dev_q8, uint32_t curve_dev_q8,
              uint32_t width, uint32_t height, void *ws, size_t ws_size);

/* curvejoin.c: with join != 0, line segments of r that continue a curve
 * smoothly (ends within 3 px, directions within 30 degrees) become curves;
 * clears every segment's reserved field. */
void sl_curve_join(symline_result *r, int join);

/* pass.c: state of one detection shared by its passes. */
typedef struct sl_run {
    const symline_config *cfg;
    const symline_image *img; /* the frame, for the pieces' side test */
    symline_result *r;
    uint32_t nseg;     /* segments so far */
    uint32_t prev_seg; /* segments of earlier passes: [0, prev_seg) */
    uint32_t mean, sigma_q4; /* frame statistics for the adaptive thresholds */
    uint8_t truncated;
    const struct sl_segindex *prev_index; /* grid of [0, prev_seg) (segindex.h) */
} sl_run;

/* pass.c: how close (Q8) to an earlier segment a point of a pass at `level`
 * counts as already found. */
static inline int32_t sl_cover_tol(uint32_t level)
{
    return 512 + (int32_t)(((1u << level) - 1u) << 8);
}

/* pass.c: traces a pass's raster list of n points, stored at *npts after the
 * points of earlier passes, makes its segments and compacts their points
 * (new total in *npts). t: tracer state in the caller's workspace. */
void sl_trace_pass(sl_run *d, const sl_pass *p, const uint32_t *row_start, uint32_t n,
                   sl_tracer *t, uint32_t *npts);

#endif /* SYMLINE_DETECT_INTERNAL_H */

/* SPDX-License-Identifier: Apache-2.0 */
/*
 * symline — intersections: where detected field lines meet (L, T, X).
 *
 * A separate stage after symline_detect(): it reads the segments of a
 * symline_result (lines by their ends, curves along their points) and never
 * looks at pixels, so it costs little and firmware that does not need it
 * leaves it out by not calling it.
 *
 *     symline_intersection_config icfg;
 *     symline_intersection_config_default(&icfg);
 *     symline_intersection items[16];
 *     symline_intersection_result ix = { items, 16, 0, 0 };
 *     symline_status st = symline_intersections(&res, &icfg, &ix);
 *
 * Model: the RoboCup community's soccer_vision_2d_msgs/MarkingIntersection:
 * a point, and the directions of the line pieces ("rays") that leave it;
 * 2 rays make an L (a corner), 3 a T, 4 an X (a crossing).
 *
 * How two segments meet: their crossing point (for a curve, where the
 * polyline through its points crosses the line) must lie on each of them, or
 * beyond an end by at most that segment's gap tolerance (the tracer stops a
 * line a few pixels short of a junction). Lines are crossed with lines and
 * with curves; two curves are not crossed (where they meet end to end is the
 * centre circle cut by the tracer, not a corner). A segment gives a ray in
 * each direction in which it goes on past the crossing by at least `arm_q8`. Pieces meeting at less than `min_angle_q8` are one line
 * continuing, or parallel lines: no intersection (pieces on one line never
 * meet, also with `min_angle_q8` 0). Crossings of several
 * pairs closer than `merge_q8` are one intersection: their rays are joined
 * (rays less than min_angle apart count once), so a bar split at a T by the
 * tracer still gives one T, and two L pieces crossing a line one X.
 *
 * Units: positions in Q8 image pixels (256 = 1 px, pixel centres at
 * multiples of 256, x right, y down); angles in Q8 degrees (256 = 1 degree),
 * directions in [0, 360 * 256): 0 along +x, 90 * 256 along +y (down).
 * No allocation, no floating point, no I/O; the caller owns every array.
 */
#ifndef SYMLINE_INTERSECTIONS_H
#define SYMLINE_INTERSECTIONS_H

#include "symline/detect.h"

#ifdef __cplusplus
extern "C" {
#endif

/* Q8 degrees in a full turn: directions lie in [0, SYMLINE_DEG_Q8_FULL). */
#define SYMLINE_DEG_Q8_FULL (360u * 256u)
/* Most rays of one intersection (an X). */
#define SYMLINE_INTERSECTION_RAYS 4u
/* Most segment indices kept per intersection (a bar and a stem split in
 * pieces, an X of four pieces and a stray one); further ones still join the
 * intersection's rays but are not listed. */
#define SYMLINE_INTERSECTION_SEGMENTS 6u

typedef enum symline_intersection_type {
    SYMLINE_INTERSECTION_L = 0, /* 2 rays: a corner */
    SYMLINE_INTERSECTION_T = 1, /* 3 rays: one line ends on another */
    SYMLINE_INTERSECTION_X = 2  /* 4 rays: two lines cross */
} symline_intersection_type;

/* One intersection. */
typedef struct symline_intersection {
    int32_t x, y;                             /* Q8 px: mean of the crossings that make it */
    uint8_t type;                             /* symline_intersection_type, from ray_count */
    uint8_t ray_count;                        /* 2..SYMLINE_INTERSECTION_RAYS */
    uint8_t segment_count;                    /* 2..SYMLINE_INTERSECTION_SEGMENTS */
    uint8_t support;                          /* segment pairs that met here, 1..255 (saturates) */
    uint32_t rays[SYMLINE_INTERSECTION_RAYS]; /* Q8 degrees, ascending */
    uint32_t segments[SYMLINE_INTERSECTION_SEGMENTS]; /* indices into the
                                                          result's segments, ascending */
} symline_intersection;

/*
 * Settings; start from symline_intersection_config_default(). Ranges are
 * checked by symline_intersections() (SYMLINE_ERR_CONFIG when violated).
 */
/* clang-format off */
typedef struct symline_intersection_config {
    uint32_t min_angle_q8;  /* smallest angle between two meeting pieces, Q8 degrees,
                               0..90*256; default 20*256 (perspective flattens right
                               angles far from the camera) */
    uint32_t gap_q8;        /* how far a segment found at full resolution may stop
                               short of a crossing met at a right angle, Q8 px,
                               0..256*256; default 2560 (10 px). Times (1 + scale
                               level) for coarser segments (wider lines), divided by
                               the sine of the angle between the two (a stem meeting
                               a bar obliquely stops further short), at most 4 times
                               that and at most gap_pct of the segment's size */
    uint32_t gap_pct;       /* ... that cap, % of the segment's size, 0..100;
                               default 50 */
    uint32_t arm_q8;        /* a segment going on at least this far past the crossing
                               (Q8 px) gives a ray that way, 256..256*256; default
                               2560 (10 px) */
    uint32_t merge_q8;      /* crossings closer than about this (within 7 %) are one
                               intersection, Q8 px, 0..256*256; default 2560 (10 px) */
    uint32_t min_length_q8; /* segments shorter than this (chord, Q8 px) take no
                               part: short pieces near junctions and at the centre
                               circle's sharpest bends give false corners;
                               0..65535*256; default 4096 (16 px) */
} symline_intersection_config;
/* clang-format on */

/* Fills *cfg with the defaults documented above (no-op on NULL). */
void symline_intersection_config_default(symline_intersection_config *cfg);

/*
 * Output storage, owned by the caller: set `items` and `cap` before the
 * call; symline_intersections() writes `count` and `truncated`.
 */
typedef struct symline_intersection_result {
    symline_intersection *items;
    uint32_t cap;
    uint32_t count;    /* intersections written, items[0 .. count-1] */
    uint8_t truncated; /* 1 when more intersections were found than fit */
} symline_intersection_result;

/*
 * Finds the intersections of the segments in *lines (as symline_detect()
 * left them, or made by hand: lines use x0..y1; curves with count >= 2 use
 * points[first .. first+count-1] with their sub-pixel offsets, others their
 * chord). Positions are computed in quarter pixels on frames up to 4095 px
 * (coarser beyond).
 * out->items may be NULL only with cap 0 (then only truncated tells that
 * there were intersections). Work: pairs of segments whose boxes (grown by
 * the gap) overlap, times the polyline vertices of curves; no pixel is read.
 * Returns SYMLINE_OK, ERR_NULL (lines, cfg or out NULL, or a NULL array with
 * a non-zero count), ERR_CONFIG, or ERR_RANGE (a curve's points outside
 * [0, lines->point_count), a kind other than line/curve, or a coordinate
 * beyond +-65535 px). On an error *out is not changed.
 */
symline_status symline_intersections(const symline_result *lines,
                                     const symline_intersection_config *cfg,
                                     symline_intersection_result *out);

#ifdef __cplusplus
}
#endif

#endif /* SYMLINE_INTERSECTIONS_H */

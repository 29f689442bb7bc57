/* SPDX-License-Identifier: Apache-2.0 */
/*
 * The scorer of docs/evaluation.md: samples every 0.5 px along detections and ground
 * truth, tolerance max(2, 3*width/640) px, precision, recall and F1 per image,
 * plus the line/curve classification counts defined in docs/evaluation.md.
 */
#ifndef SYMLINE_EVAL_SCORE_H
#define SYMLINE_EVAL_SCORE_H

#include <stddef.h>
#include <stdio.h>

#include "paths.h"

#define EV_SAMPLE_STEP 0.5
#define EV_NLABELS 8 /* label values 0..7 counted; larger ones count as 7 */
#define EV_LABEL_PAINT 1 /* the label of painted lines (symline-render --labels) */
#define EV_NWIDTHS 5
/* Fragmentation (docs/evaluation.md): straight ground-truth pieces at least this long
   count; a detected piece lies along one when at least EV_FRAG_SHARE_PCT % of its
   samples, and at least EV_FRAG_MIN_SAMPLES samples, are within tolerance of it. */
#define EV_FRAG_MIN_LEN 40.0
#define EV_FRAG_SHARE_PCT 70
#define EV_FRAG_MIN_SAMPLES 8

/* A label image (one byte per pixel, stride = width), e.g. rendered surfaces. */
typedef struct ev_labels {
    const unsigned char *px;
    int width, height;
} ev_labels;

typedef struct ev_score {
    double p, r, f1;
    size_t det_pieces;   /* detected pieces (reported segments) */
    size_t det_samples;  /* all samples of the detections */
    size_t det_counted;  /* those not ignored (not within tol of a don't-care part) */
    size_t det_hits;     /* counted samples within tol of ground truth */
    size_t gt_samples;   /* samples of the ground truth */
    size_t gt_hits;      /* ground-truth samples within tol of a detection */
    size_t line_matched, line_ok;   /* detected pieces matched to straight GT; of those, kind "line" */
    size_t curve_matched, curve_ok; /* detected pieces matched to circle GT; of those, kind "curve" */
    /* The same four counts weighted by length: samples of those pieces. */
    size_t line_matched_s, line_ok_s, curve_matched_s, curve_ok_s;
    /* With a label image: wrong detected samples by the label under them, and ground
       truth samples (and those found) by painted width across the line, in pixels
       [0,2) [2,4) [4,8) [8,16) [16,inf) (width from the paint labels, +-1 px). */
    size_t fp_label[EV_NLABELS];
    size_t gt_width_n[EV_NWIDTHS], gt_width_hits[EV_NWIDTHS];
    /* Fragmentation: straight ground-truth pieces >= EV_FRAG_MIN_LEN px (frag_pieces),
       those with at least one detected piece along them (frag_found), and the number of
       detected pieces along those (frag_segments; a detected piece may lie along two
       ground-truth pieces and then counts for both). Mean = frag_segments / frag_found. */
    size_t frag_pieces, frag_found, frag_segments;
    /* Centre error: distance of every matched detected sample (counted and within tol of
       ground truth) to the nearest ground-truth centre line, pixels: how many, the median
       and the 90th percentile (nearest rank: the value at rank ceil(q*n); 0 when n = 0). */
    size_t centre_n;
    double centre_median, centre_p90;
} ev_score;

/* max(2, 3*width/640) pixels. */
double ev_tolerance(int width);

/*
 * Scores detections against ground truth. gt pieces are tagged EV_TAG_LINE
 * (straight) or EV_TAG_CURVE (circle); dontcare may be NULL; det pieces carry
 * the tag of their kind.
 */
void ev_score_paths(const ev_paths *gt, const ev_paths *dontcare, const ev_paths *det,
                    double tol, ev_score *out);

/* Extras of one scoring run; any member may be NULL. */
typedef struct ev_extras {
    FILE *pieces;             /* one line per detected piece: samples near straight and
                                 near circle ground truth, class */
    const ev_labels *labels;  /* rendered surfaces: fp_label (wrong samples by the label at
                                 their nearest pixel) and gt_width_* are filled */
    const ev_labels *ignore;  /* nonzero pixels: samples (detected and ground truth) whose
                                 nearest pixel is nonzero are left out of P and R */
    FILE *centre;             /* the centre error of every matched detected sample, one
                                 distance in pixels per line (%.4f), to pool images */
    FILE *gt_pieces;          /* one line per straight ground-truth piece >= EV_FRAG_MIN_LEN:
                                 its length and the detected pieces along it */
} ev_extras;

/* ev_score_paths() with extras (NULL: none). */
void ev_score_paths_ex(const ev_paths *gt, const ev_paths *dontcare, const ev_paths *det,
                       double tol, ev_score *out, const ev_extras *extras);

/*
 * Binary line mask (nonzero = line pixel, width*height bytes, stride = width):
 * precision = share of detected samples within tol of a mask pixel centre,
 * recall = share of mask pixels within tol of a detection.
 */
void ev_score_mask(const unsigned char *mask, int width, int height, const ev_paths *det,
                   double tol, ev_score *out);

#endif

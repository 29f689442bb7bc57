/* SPDX-License-Identifier: Apache-2.0 */
/*
 * Precision, recall, F1 and classification counts for one image.
 */
#include "score.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

double ev_tolerance(int width)
{
    double t = 3.0 * (double)width / 640.0;
    return t > 2.0 ? t : 2.0;
}

static void finish(ev_score *s)
{
    /* Nothing claimed is nothing wrong; nothing to find is nothing missed. */
    s->p = s->det_counted ? (double)s->det_hits / (double)s->det_counted : 1.0;
    s->r = s->gt_samples ? (double)s->gt_hits / (double)s->gt_samples : 1.0;
    s->f1 = (s->p + s->r) > 0.0 ? 2.0 * s->p * s->r / (s->p + s->r) : 0.0;
}

/* Label at the pixel nearest to (x, y), or -1 outside. */
static int label_at(const ev_labels *lab, double x, double y)
{
    long xi = lround(x), yi = lround(y);
    if (xi < 0 || yi < 0 || xi >= lab->width || yi >= lab->height) {
        return -1;
    }
    return lab->px[(size_t)yi * (size_t)lab->width + (size_t)xi];
}

/* Painted width across ground-truth sample i: the run of paint-labelled pixels along
   the normal (direction from the neighbouring samples of the same piece). */
static double paint_width(const ev_labels *lab, const ev_pt *s, const size_t *piece, size_t n,
                          size_t i)
{
    size_t a = (i > 0 && piece[i - 1] == piece[i]) ? i - 1 : i;
    size_t b = (i + 1 < n && piece[i + 1] == piece[i]) ? i + 1 : i;
    double dx = s[b].x - s[a].x, dy = s[b].y - s[a].y, len = hypot(dx, dy), w = 0.0, o;
    int side;
    if (len <= 0.0 || label_at(lab, s[i].x, s[i].y) != EV_LABEL_PAINT) {
        return 0.0;
    }
    for (side = -1; side <= 1; side += 2) {
        for (o = 0.25; o < 128.0; o += 0.25) {
            if (label_at(lab, s[i].x - side * o * dy / len, s[i].y + side * o * dx / len) !=
                EV_LABEL_PAINT) {
                break;
            }
        }
        w += o;
    }
    return w;
}

static int width_bucket(double w)
{
    return w < 2.0 ? 0 : w < 4.0 ? 1 : w < 8.0 ? 2 : w < 16.0 ? 3 : 4;
}

static int cmp_double(const void *a, const void *b)
{
    double x = *(const double *)a, y = *(const double *)b;
    return (x > y) - (x < y);
}

/* Nearest-rank quantile of n sorted values: the value at rank ceil(q*n). */
static double quantile(const double *v, size_t n, double q)
{
    size_t r = (size_t)ceil(q * (double)n);
    return n == 0 ? 0.0 : v[r > 0 ? r - 1 : 0];
}

/* Median and 90th percentile of the n centre distances (sorted in place). */
static void centre_stats(double *d, size_t n, ev_score *out)
{
    qsort(d, n, sizeof(*d), cmp_double);
    out->centre_n = n;
    out->centre_median = quantile(d, n, 0.5);
    out->centre_p90 = quantile(d, n, 0.9);
}

/*
 * Fragmentation: for every straight ground-truth piece at least EV_FRAG_MIN_LEN long,
 * the detected pieces lying along it. ds/dpiece/nd are the detected samples, nsamp the
 * samples per detected piece.
 */
static void fragmentation(const ev_paths *gt, const ev_paths *det, const ev_pt *ds,
                          const size_t *dpiece, size_t nd, const size_t *nsamp, double tol,
                          ev_score *out, FILE *report)
{
    size_t *near = calloc(det->npieces + 1, sizeof(size_t));
    size_t g, i, j;
    for (g = 0; g < gt->npieces; g++) {
        const ev_pt *v = ev_piece_pts(gt, g);
        size_t n = ev_piece_len(gt, g), along = 0;
        double len = ev_piece_length(gt, g), lx = v[0].x, hx = v[0].x, ly = v[0].y, hy = v[0].y;
        if (gt->tag[g] != EV_TAG_LINE || len < EV_FRAG_MIN_LEN) {
            continue;
        }
        for (j = 1; j < n; j++) {
            lx = fmin(lx, v[j].x);
            hx = fmax(hx, v[j].x);
            ly = fmin(ly, v[j].y);
            hy = fmax(hy, v[j].y);
        }
        memset(near, 0, (det->npieces + 1) * sizeof(size_t));
        for (i = 0; i < nd; i++) {
            if (ds[i].x < lx - tol || ds[i].x > hx + tol || ds[i].y < ly - tol || ds[i].y > hy + tol) {
                continue;
            }
            if (ev_dist_piece(gt, g, ds[i]) <= tol) {
                near[dpiece[i]]++;
            }
        }
        for (j = 0; j < det->npieces; j++) {
            along += near[j] >= EV_FRAG_MIN_SAMPLES && 100 * near[j] >= EV_FRAG_SHARE_PCT * nsamp[j];
        }
        out->frag_pieces++;
        out->frag_found += along > 0;
        out->frag_segments += along;
        if (report != NULL) {
            fprintf(report, "gtpiece=%zu x0=%.1f y0=%.1f x1=%.1f y1=%.1f length=%.1f along=%zu pieces=",
                    g, v[0].x, v[0].y, v[n - 1].x, v[n - 1].y, len, along);
            for (j = 0, i = 0; j < det->npieces; j++) {
                if (near[j] >= EV_FRAG_MIN_SAMPLES && 100 * near[j] >= EV_FRAG_SHARE_PCT * nsamp[j]) {
                    fprintf(report, "%s%zu", i++ ? "," : "", j);
                }
            }
            fputs(i ? "\n" : "-\n", report);
        }
    }
    free(near);
}

void ev_score_paths(const ev_paths *gt, const ev_paths *dontcare, const ev_paths *det,
                    double tol, ev_score *out)
{
    ev_score_paths_ex(gt, dontcare, det, tol, out, NULL);
}

/* 1 when the pixel nearest to q is nonzero in the ignore image. */
static int ignored(const ev_labels *ign, ev_pt q)
{
    return ign != NULL && label_at(ign, q.x, q.y) > 0;
}

void ev_score_paths_ex(const ev_paths *gt, const ev_paths *dontcare, const ev_paths *det,
                       double tol, ev_score *out, const ev_extras *extras)
{
    FILE *pieces = extras ? extras->pieces : NULL;
    const ev_labels *labels = extras ? extras->labels : NULL;
    const ev_labels *ign = extras ? extras->ignore : NULL;
    FILE *centre = extras ? extras->centre : NULL;
    ev_index gix, dcix, dix;
    ev_pt *ds = NULL, *gs = NULL;
    size_t *dpiece = NULL, *gpiece = NULL, nd, ng, i;
    size_t *near_line = calloc(det->npieces + 1, sizeof(size_t));
    size_t *near_curve = calloc(det->npieces + 1, sizeof(size_t));
    size_t *nsamp = calloc(det->npieces + 1, sizeof(size_t));
    double *cdist;
    size_t ncentre = 0;

    memset(out, 0, sizeof(*out));
    ev_index_build(&gix, gt, tol);
    memset(&dcix, 0, sizeof(dcix));
    if (dontcare != NULL && dontcare->npts > 0) {
        ev_index_build(&dcix, dontcare, tol);
    }
    ev_index_build(&dix, det, tol);

    nd = ev_sample(det, EV_SAMPLE_STEP, &ds, &dpiece);
    out->det_samples = nd;
    out->det_pieces = det->npieces;
    cdist = malloc((nd + 1) * sizeof(double));
    for (i = 0; i < nd; i++) {
        int tag = -1;
        int near_gt = ev_index_near(&gix, ds[i], &tag);
        nsamp[dpiece[i]]++;
        if (near_gt) {
            if (tag == EV_TAG_CURVE) {
                near_curve[dpiece[i]]++;
            } else {
                near_line[dpiece[i]]++;
            }
        }
        if (dcix.paths != NULL && ev_index_near(&dcix, ds[i], NULL)) {
            continue; /* near a don't-care part: neither right nor wrong */
        }
        if (ignored(ign, ds[i])) {
            continue;
        }
        out->det_counted++;
        out->det_hits += (size_t)near_gt;
        if (near_gt) {
            cdist[ncentre] = ev_index_dist(&gix, ds[i]);
            if (centre != NULL) {
                fprintf(centre, "%.4f\n", cdist[ncentre]);
            }
            ncentre++;
        }
        if (!near_gt && labels != NULL) {
            long x = lround(ds[i].x), y = lround(ds[i].y);
            if (x >= 0 && y >= 0 && x < labels->width && y < labels->height) {
                unsigned v = labels->px[(size_t)y * (size_t)labels->width + (size_t)x];
                out->fp_label[v < EV_NLABELS ? v : EV_NLABELS - 1]++;
            }
        }
    }

    ng = ev_sample(gt, EV_SAMPLE_STEP, &gs, &gpiece);
    for (i = 0; i < ng; i++) {
        int hit;
        if (ignored(ign, gs[i])) {
            continue;
        }
        hit = ev_index_near(&dix, gs[i], NULL);
        out->gt_samples++;
        out->gt_hits += (size_t)hit;
        if (labels != NULL) {
            int b = width_bucket(paint_width(labels, gs, gpiece, ng, i));
            out->gt_width_n[b]++;
            out->gt_width_hits[b] += (size_t)hit;
        }
    }

    /* A piece is matched when at least half its samples lie near ground truth;
       its class is the kind of ground truth most of those samples are near. */
    for (i = 0; i < det->npieces; i++) {
        size_t near = near_line[i] + near_curve[i];
        if (pieces != NULL) {
            const ev_pt *q = ev_piece_pts(det, i);
            size_t n = ev_piece_len(det, i);
            fprintf(pieces,
                    "piece=%zu kind=%s x0=%.1f y0=%.1f x1=%.1f y1=%.1f length=%.1f samples=%zu "
                    "near_line=%zu near_curve=%zu class=%s\n",
                    i, det->tag[i] == EV_TAG_LINE ? "line" : det->tag[i] == EV_TAG_CURVE ? "curve" : "other",
                    q[0].x, q[0].y, q[n - 1].x, q[n - 1].y, ev_piece_length(det, i), nsamp[i],
                    near_line[i], near_curve[i],
                    (nsamp[i] == 0 || 2 * near < nsamp[i]) ? "unmatched"
                    : near_line[i] >= near_curve[i]     ? "straight"
                                                        : "circle");
        }
        if (nsamp[i] == 0 || 2 * near < nsamp[i]) {
            continue;
        }
        if (near_line[i] >= near_curve[i]) {
            out->line_matched++;
            out->line_matched_s += nsamp[i];
            if (det->tag[i] == EV_TAG_LINE) {
                out->line_ok++;
                out->line_ok_s += nsamp[i];
            }
        } else {
            out->curve_matched++;
            out->curve_matched_s += nsamp[i];
            if (det->tag[i] == EV_TAG_CURVE) {
                out->curve_ok++;
                out->curve_ok_s += nsamp[i];
            }
        }
    }
    fragmentation(gt, det, ds, dpiece, nd, nsamp, tol, out, extras ? extras->gt_pieces : NULL);
    centre_stats(cdist, ncentre, out);
    finish(out);

    free(cdist);
    free(ds);
    free(gs);
    free(dpiece);
    free(gpiece);
    free(near_line);
    free(near_curve);
    free(nsamp);
    ev_index_free(&gix);
    if (dcix.paths != NULL) {
        ev_index_free(&dcix);
    }
    ev_index_free(&dix);
}

void ev_score_mask(const unsigned char *mask, int width, int height, const ev_paths *det,
                   double tol, ev_score *out)
{
    ev_paths pix;
    int x, y;
    ev_paths_init(&pix);
    for (y = 0; y < height; y++) {
        for (x = 0; x < width; x++) {
            if (mask[(size_t)y * (size_t)width + (size_t)x]) {
                ev_paths_begin(&pix, EV_TAG_LINE);
                ev_paths_add(&pix, (double)x, (double)y);
            }
        }
    }
    ev_score_paths(&pix, NULL, det, tol, out);
    /* A mask says nothing about line or curve. */
    out->line_matched = out->line_ok = out->curve_matched = out->curve_ok = 0;
    out->line_matched_s = out->line_ok_s = out->curve_matched_s = out->curve_ok_s = 0;
    /* Nor where a line's centre is: mask pixels are not centre lines. */
    out->centre_n = 0;
    out->centre_median = out->centre_p90 = 0.0;
    ev_paths_free(&pix);
}

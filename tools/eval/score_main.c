/* SPDX-License-Identifier: Apache-2.0 */
/*
 * symline-score: scores `symline lines` detections (docs/format.md) against
 * ground truth, a binary line mask, or another detection of the same frame.
 */
#include <errno.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

#include "evio.h"
#include "hostopts.h"
#include "imgio.h"
#include "score.h"

static int g_pieces;            /* --pieces: one line per detected piece before the score (gt mode) */
static const char *g_ignore;    /* --ignore IMG: samples on its nonzero pixels are left out */
static FILE *g_centre;          /* --centre FILE: centre error of every matched sample */
static imgio_gray g_ignore_img;
static ev_labels g_ignore_lab;

/* Loads --ignore; returns NULL when not given, or exits on an unreadable image. */
static const ev_labels *ignore_image(void)
{
    char err[512];
    if (g_ignore == NULL) {
        return NULL;
    }
    if (g_ignore_lab.px == NULL) {
        if (imgio_read_gray(g_ignore, &g_ignore_img, err, sizeof(err)) != 0) {
            fprintf(stderr, "symline-score: %s\n", err);
            exit(1);
        }
        g_ignore_lab.px = g_ignore_img.px;
        g_ignore_lab.width = (int)g_ignore_img.width;
        g_ignore_lab.height = (int)g_ignore_img.height;
    }
    return &g_ignore_lab;
}

static void usage(FILE *f)
{
    fputs("usage: symline-score [--pieces] [--ignore IMG] [--centre FILE] [--tol PX] gt NAME DET.json\n"
          "       symline-score [--tol PX] mask MASK.pgm DET.json\n"
          "       symline-score [--ignore IMG] [--centre FILE] [--tol PX] pair REF.json DET.json\n"
          "       symline-score gtjson NAME\n"
          "\n"
          "gt:   ground truth NAME.lines.txt, NAME.arcs.txt, NAME.dontcare.txt (missing\n"
          "      files count as empty); image width from NAME.pgm, else from DET.json.\n"
          "mask: binary line mask (nonzero = line pixel), PGM or PNG.\n"
          "pair: REF.json taken as the ground truth (stability between two runs).\n"
          "gtjson: prints NAME's ground truth as detection JSON (lines as kind \"line\",\n"
          "      circle pieces as kind \"curve\" with a polyline): a perfect detector.\n"
          "Samples every 0.5 px; tolerance max(2, 3*width/640) px unless --tol.\n"
          "With NAME.labels.pgm (symline-render --labels), gt mode prints a second line:\n"
          "wrong detected samples by surface, fp_carpet fp_paint fp_floor fp_wall\n"
          "fp_ceiling fp_robot; and a third: ground-truth samples found / all by painted\n"
          "width in pixels, gtw_lt2 gtw_2to4 gtw_4to8 gtw_8to16 gtw_ge16.\n"
          "Prints one line of key=value pairs: f1 p r, sample counts, and the\n"
          "classification counts line_matched line_ok curve_matched curve_ok and the\n"
          "same weighted by length (samples): line_matched_s line_ok_s curve_matched_s curve_ok_s.\n"
          "det_pieces (gt, pair): the number of detected pieces (reported segments).\n"
          "Fragmentation (gt, pair): frag_pieces = straight ground-truth pieces >= 40 px,\n"
          "      frag_found = those with a detected piece along them (>= 70 % and >= 8 of the\n"
          "      piece's samples within tolerance of it), frag_segments = the detected pieces\n"
          "      along those; mean fragmentation = frag_segments / frag_found (1.0 = one piece\n"
          "      per line; sum both over images to pool).\n"
          "Centre error (gt, pair): distance of every matched detected sample (counted, within\n"
          "      tolerance of ground truth) to the nearest ground-truth centre line: centre_n,\n"
          "      centre_med, centre_p90 (nearest rank; '-' when centre_n = 0).\n"
          "--centre FILE: appends those distances to FILE, one per line (pool them over images).\n"
          "--ignore IMG (gt, pair): samples whose nearest pixel is nonzero in IMG count\n"
          "      neither for precision nor for recall (e.g. pixels a brightness change saturated).\n"
          "--pieces (gt mode): first one line per detected piece: kind, length, samples near\n"
          "      straight and near circle ground truth, class (straight, circle, unmatched);\n"
          "      then one per straight ground-truth piece >= 40 px: the detected pieces along it.\n"
          "Options take --opt VALUE or --opt=VALUE; --version prints the version.\n"
          "Exit status: 0 ok, 1 unreadable input, 2 usage.\n",
          f);
}

static void print_score(const ev_score *s, double tol, int with_labels, int with_geometry)
{
    printf("f1=%.6f p=%.6f r=%.6f tol=%.3f det_samples=%zu det_counted=%zu det_hits=%zu "
           "gt_samples=%zu gt_hits=%zu line_matched=%zu line_ok=%zu curve_matched=%zu "
           "curve_ok=%zu line_matched_s=%zu line_ok_s=%zu curve_matched_s=%zu curve_ok_s=%zu",
           s->f1, s->p, s->r, tol, s->det_samples, s->det_counted, s->det_hits, s->gt_samples,
           s->gt_hits, s->line_matched, s->line_ok, s->curve_matched, s->curve_ok,
           s->line_matched_s, s->line_ok_s, s->curve_matched_s, s->curve_ok_s);
    if (with_geometry) {
        printf(" det_pieces=%zu frag_pieces=%zu frag_found=%zu frag_segments=%zu centre_n=%zu", s->det_pieces, s->frag_pieces,
               s->frag_found, s->frag_segments, s->centre_n);
        if (s->centre_n > 0) {
            printf(" centre_med=%.4f centre_p90=%.4f", s->centre_median, s->centre_p90);
        } else {
            printf(" centre_med=- centre_p90=-");
        }
    }
    putchar('\n');
    if (with_labels) {
        /* Rendered surfaces (symline-render --labels) under the wrong samples. */
        static const char *const names[] = {"carpet", "paint", "floor", "wall", "ceiling", "robot"};
        int k;
        for (k = 0; k < (int)(sizeof(names) / sizeof(names[0])); k++) {
            printf("%sfp_%s=%zu", k ? " " : "", names[k], s->fp_label[k]);
        }
        putchar('\n');
        {
            static const char *const wn[EV_NWIDTHS] = {"lt2", "2to4", "4to8", "8to16", "ge16"};
            for (k = 0; k < EV_NWIDTHS; k++) {
                printf("%sgtw_%s=%zu/%zu", k ? " " : "", wn[k], s->gt_width_hits[k], s->gt_width_n[k]);
            }
            putchar('\n');
        }
    }
}

/* NAME.lines.txt (straight ground truth) and NAME.arcs.txt (the circle) into gt. */
static int read_ground_truth(const char *name, ev_paths *gt)
{
    char path[4096];
    snprintf(path, sizeof(path), "%s.lines.txt", name);
    if (ev_read_segments(path, EV_TAG_LINE, 1, gt) != 0) {
        return -1;
    }
    snprintf(path, sizeof(path), "%s.arcs.txt", name);
    return ev_read_polylines(path, EV_TAG_CURVE, 1, gt);
}

static int mode_gt(const char *name, const char *detpath, double tol)
{
    ev_paths gt, dc, det;
    ev_score s;
    char path[4096];
    int w = 0, h = 0, jw, jh, rc = 1, have_lab = 0;
    imgio_gray lab;
    ev_labels labels;
    ev_paths_init(&gt);
    ev_paths_init(&dc);
    ev_paths_init(&det);
    if (read_ground_truth(name, &gt) != 0) {
        goto out;
    }
    snprintf(path, sizeof(path), "%s.dontcare.txt", name);
    if (ev_read_segments(path, EV_TAG_OTHER, 1, &dc) != 0) {
        goto out;
    }
    if (ev_read_detections(detpath, &det, &jw, &jh) != 0) {
        goto out;
    }
    snprintf(path, sizeof(path), "%s.pgm", name);
    if (ev_pgm_size(path, &w, &h) != 0) {
        w = jw;
    }
    if (tol <= 0.0) {
        if (w <= 0) {
            fprintf(stderr, "symline-score: no image width (no %s, no width in %s)\n", path,
                    detpath);
            goto out;
        }
        tol = ev_tolerance(w);
    }
    snprintf(path, sizeof(path), "%s.labels.pgm", name);
    if (access(path, R_OK) == 0) {
        char err[512];
        if (imgio_read_gray(path, &lab, err, sizeof(err)) != 0) {
            fprintf(stderr, "symline-score: %s\n", err);
            goto out;
        }
        have_lab = 1;
        labels.px = lab.px;
        labels.width = (int)lab.width;
        labels.height = (int)lab.height;
    }
    {
        ev_extras ex;
        memset(&ex, 0, sizeof(ex));
        ex.pieces = g_pieces ? stdout : NULL;
        ex.labels = have_lab ? &labels : NULL;
        ex.ignore = ignore_image();
        ex.centre = g_centre;
        ex.gt_pieces = g_pieces ? stdout : NULL;
        ev_score_paths_ex(&gt, &dc, &det, tol, &s, &ex);
    }
    print_score(&s, tol, have_lab, 1);
    rc = 0;
out:
    if (have_lab) {
        imgio_free(&lab);
    }
    ev_paths_free(&gt);
    ev_paths_free(&dc);
    ev_paths_free(&det);
    return rc;
}

static int mode_mask(const char *maskpath, const char *detpath, double tol)
{
    imgio_gray m;
    ev_paths det;
    ev_score s;
    char err[512];
    int jw, jh;
    if (imgio_read_gray(maskpath, &m, err, sizeof(err)) != 0) {
        fprintf(stderr, "symline-score: %s\n", err);
        return 1;
    }
    ev_paths_init(&det);
    if (ev_read_detections(detpath, &det, &jw, &jh) != 0) {
        imgio_free(&m);
        return 1;
    }
    if (tol <= 0.0) {
        tol = ev_tolerance((int)m.width);
    }
    ev_score_mask(m.px, (int)m.width, (int)m.height, &det, tol, &s);
    print_score(&s, tol, 0, 0);
    imgio_free(&m);
    ev_paths_free(&det);
    return 0;
}

static int mode_pair(const char *refpath, const char *detpath, double tol)
{
    ev_paths ref, det;
    ev_score s;
    int rw, rh, dw, dh, rc = 1;
    ev_paths_init(&ref);
    ev_paths_init(&det);
    if (ev_read_detections(refpath, &ref, &rw, &rh) != 0 ||
        ev_read_detections(detpath, &det, &dw, &dh) != 0) {
        goto out;
    }
    if (tol <= 0.0) {
        if (rw <= 0) {
            fprintf(stderr, "symline-score: no width in %s (use --tol)\n", refpath);
            goto out;
        }
        tol = ev_tolerance(rw);
    }
    /* The reference's kinds stand for ground-truth classes. */
    {
        ev_extras ex;
        memset(&ex, 0, sizeof(ex));
        ex.ignore = ignore_image();
        ex.centre = g_centre;
        ev_score_paths_ex(&ref, NULL, &det, tol, &s, &ex);
    }
    print_score(&s, tol, 0, 1);
    rc = 0;
out:
    ev_paths_free(&ref);
    ev_paths_free(&det);
    return rc;
}

static int mode_gtjson(const char *name)
{
    ev_paths gt;
    char path[4096];
    int w = 0, h = 0, rc = 1;
    size_t i, k;
    ev_paths_init(&gt);
    if (read_ground_truth(name, &gt) != 0) {
        goto out;
    }
    snprintf(path, sizeof(path), "%s.pgm", name);
    if (ev_pgm_size(path, &w, &h) != 0) {
        fprintf(stderr, "symline-score: cannot read the size of %s\n", path);
        goto out;
    }
    printf("{\"width\": %d, \"height\": %d, \"segments\": [", w, h);
    for (i = 0; i < gt.npieces; i++) {
        const ev_pt *q = ev_piece_pts(&gt, i);
        size_t n = ev_piece_len(&gt, i);
        printf("%s\n  {\"x0\": %.3f, \"y0\": %.3f, \"x1\": %.3f, \"y1\": %.3f, \"points\": %zu, "
               "\"kind\": \"%s\"",
               i ? "," : "", q[0].x, q[0].y, q[n - 1].x, q[n - 1].y, n,
               gt.tag[i] == EV_TAG_CURVE ? "curve" : "line");
        if (gt.tag[i] == EV_TAG_CURVE) {
            printf(", \"polyline\": [");
            for (k = 0; k < n; k++) {
                printf("%s[%.3f, %.3f]", k ? ", " : "", q[k].x, q[k].y);
            }
            printf("]");
        }
        printf("}");
    }
    printf("\n]}\n");
    rc = 0;
out:
    ev_paths_free(&gt);
    return rc;
}

#define PROG "symline-score"

enum { OPT_PIECES = 0x100, OPT_IGNORE, OPT_CENTRE, OPT_TOL };

static const struct option longopts[] = {{"help", no_argument, NULL, HOSTOPTS_HELP},
                                         {"version", no_argument, NULL, HOSTOPTS_VERSION},
                                         {"pieces", no_argument, NULL, OPT_PIECES},
                                         {"ignore", required_argument, NULL, OPT_IGNORE},
                                         {"centre", required_argument, NULL, OPT_CENTRE},
                                         {"tol", required_argument, NULL, OPT_TOL},
                                         {NULL, 0, NULL, 0}};

int main(int argc, char **argv)
{
    double tol = 0.0;
    const char *centre = NULL, *mode;
    int c, n;
    while ((c = hostopts_next(argc, argv, ":h", longopts, PROG, PROG)) != -1) {
        switch (c) {
        case HOSTOPTS_HELP: usage(stdout); return 0;
        case HOSTOPTS_VERSION: hostopts_version(PROG); return 0;
        case OPT_PIECES: g_pieces = 1; break;
        case OPT_IGNORE: g_ignore = optarg; break;
        case OPT_CENTRE: centre = optarg; break;
        case OPT_TOL:
            if (hostopts_double(optarg, 0.0, 1e6, &tol) != 0 || !(tol > 0.0)) {
                return hostopts_usage_error(PROG, PROG, "--tol needs a positive number");
            }
            break;
        default: return HOSTOPTS_USAGE; /* HOSTOPTS_ERROR: reported */
        }
    }
    n = argc - optind;
    mode = n > 0 ? argv[optind] : "";
    if (!(n == 2 && strcmp(mode, "gtjson") == 0) &&
        !(n == 3 && (strcmp(mode, "gt") == 0 || strcmp(mode, "mask") == 0 || strcmp(mode, "pair") == 0))) {
        return hostopts_usage_error(PROG, PROG, "needs gt NAME DET.json, mask MASK DET.json, "
                                                "pair REF.json DET.json or gtjson NAME");
    }
    if (centre != NULL) {
        g_centre = fopen(centre, "a");
        if (g_centre == NULL) {
            fprintf(stderr, PROG ": cannot open %s: %s\n", centre, strerror(errno));
            return 1;
        }
    }
    if (strcmp(mode, "gtjson") == 0) {
        return mode_gtjson(argv[optind + 1]);
    }
    if (strcmp(mode, "gt") == 0) {
        return mode_gt(argv[optind + 1], argv[optind + 2], tol);
    }
    if (strcmp(mode, "mask") == 0) {
        return mode_mask(argv[optind + 1], argv[optind + 2], tol);
    }
    return mode_pair(argv[optind + 1], argv[optind + 2], tol);
}

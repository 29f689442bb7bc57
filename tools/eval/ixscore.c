/* SPDX-License-Identifier: Apache-2.0 */
/*
 * symline-ixscore: scores the "intersections" of a `symline lines` JSON
 * against the intersections of a scene's ground-truth segments.
 *
 * Reference: the ground truth (NAME.lines.txt straight pieces, NAME.arcs.txt
 * circle pieces as curves through their points, NAME.dontcare.txt) is handed
 * to symline_intersections() with fixed settings (those of the stage's defaults
 * when it was written, but a gap of 3 px): ground-truth pieces run exactly to
 * where centre lines cross, so the stage's rules (a corner,
 * a T, a crossing; pieces meeting at less than the minimum angle are one
 * line) decide what the reference is, not the detector's gaps. A reference
 * intersection that involves a don't-care piece is don't-care: a detection
 * near it counts neither way.
 */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "evio.h"
#include "hostopts.h"
#include "symline/intersections.h"

#define IX_MAX 1024

typedef struct ix_item {
    double x, y;
    int type; /* 0 L, 1 T, 2 X */
    int nrays;
    double rays[4];
    int dontcare;
    int matched; /* index of the partner + 1, 0 none */
} ix_item;

static void usage(FILE *f)
{
    fputs("usage: symline-ixscore [--tol PX] [--list] NAME DET.json\n"
          "Reference: intersections of NAME's ground truth (NAME.lines.txt, NAME.arcs.txt,\n"
          "NAME.dontcare.txt; missing files count as empty) by symline_intersections()\n"
          "(minimum angle 20 deg, gap 3 px, arm 10 px, merge 10 px); one that involves a don't-care piece is don't-care. Detected: the\n"
          "\"intersections\" key of DET.json. A detection matches the nearest free reference\n"
          "within the tolerance (default max(4, 8*width/640) px, width from NAME.pgm or\n"
          "DET.json), nearest pairs first.\n"
          "Prints: ref det tp fp fn (counts; detections near a don't-care reference are left\n"
          "out), p r (tp/(tp+fp), tp/(tp+fn); 1 when the denominator is 0), type_ok (matched\n"
          "with the right type), pos_err (mean distance of the matched, px), ray_err (mean\n"
          "angle from each reference ray to the nearest detected ray of the type-correct\n"
          "matches, degrees). --list adds one line per reference and detection.\n"
          "Options take --opt VALUE or --opt=VALUE; --version prints the version.\n"
          "Exit status: 0 ok, 1 unreadable input, 2 usage.\n",
          f);
}

/* ---- reference from ground truth ---- */

static int32_t q8(double v)
{
    return (int32_t)lround(v * 256.0);
}

/* Appends the pieces of p as segments of r (lines by their ends, curves through
 * their points, pixel and sub-pixel offset). */
static void add_pieces(const ev_paths *p, symline_result *r)
{
    size_t i, k;
    for (i = 0; i < p->npieces; i++) {
        const ev_pt *q = ev_piece_pts(p, i);
        const size_t n = ev_piece_len(p, i);
        symline_segment *s = &r->segments[r->segment_count++];
        memset(s, 0, sizeof *s);
        s->x0 = q8(q[0].x);
        s->y0 = q8(q[0].y);
        s->x1 = q8(q[n - 1].x);
        s->y1 = q8(q[n - 1].y);
        s->kind = (uint8_t)(p->tag[i] == EV_TAG_CURVE && n >= 2 ? SYMLINE_KIND_CURVE
                                                                 : SYMLINE_KIND_LINE);
        if (s->kind == SYMLINE_KIND_CURVE) {
            s->first = r->point_count;
            for (k = 0; k < n; k++) {
                symline_point *pt = &r->points[r->point_count++];
                const double x = q[k].x < 0 ? 0 : q[k].x, y = q[k].y < 0 ? 0 : q[k].y;
                pt->x = (uint16_t)lround(x);
                pt->y = (uint16_t)lround(y);
                pt->fx = (int8_t)fmax(-64.0, fmin(63.0, lround((x - pt->x) * 128.0)));
                pt->fy = (int8_t)fmax(-64.0, fmin(63.0, lround((y - pt->y) * 128.0)));
            }
            s->count = (uint32_t)n;
        }
    }
}

/* Don't-care parts of the circle come as short two-point pieces, one after the
 * other: chained back into polylines (curves) so that they can take part. */
static void chain_pieces(const ev_paths *in, ev_paths *out)
{
    size_t i, k;
    for (i = 0; i < in->npieces; i++) {
        const ev_pt *q = ev_piece_pts(in, i);
        const size_t n = ev_piece_len(in, i);
        size_t from = 1;
        if (i == 0 || out->npts == 0 || fabs(out->pts[out->npts - 1].x - q[0].x) > 0.01 ||
            fabs(out->pts[out->npts - 1].y - q[0].y) > 0.01) {
            ev_paths_begin(out, EV_TAG_LINE);
            from = 0;
        } else {
            out->tag[out->npieces - 1] = EV_TAG_CURVE;
        }
        for (k = from; k < n; k++) {
            ev_paths_add(out, q[k].x, q[k].y);
        }
    }
}

static int reference(const char *name, ix_item *ref, int *nref)
{
    char path[4096];
    ev_paths gt, dc, raw;
    symline_result r;
    symline_intersection_config cfg;
    symline_intersection items[IX_MAX];
    symline_intersection_result out = {items, IX_MAX, 0, 0};
    uint32_t i, k, nreq;
    int rc = -1;
    ev_paths_init(&gt);
    ev_paths_init(&dc);
    ev_paths_init(&raw);
    memset(&r, 0, sizeof r);
    snprintf(path, sizeof path, "%s.lines.txt", name);
    if (ev_read_segments(path, EV_TAG_LINE, 1, &gt) != 0) {
        goto done;
    }
    snprintf(path, sizeof path, "%s.arcs.txt", name);
    if (ev_read_polylines(path, EV_TAG_CURVE, 1, &gt) != 0) {
        goto done;
    }
    snprintf(path, sizeof path, "%s.dontcare.txt", name);
    if (ev_read_segments(path, EV_TAG_LINE, 1, &raw) != 0) {
        goto done;
    }
    chain_pieces(&raw, &dc);
    r.segment_cap = (uint32_t)(gt.npieces + dc.npieces);
    r.point_cap = (uint32_t)(gt.npts + dc.npts);
    r.segments = calloc(r.segment_cap + 1u, sizeof *r.segments);
    r.points = calloc(r.point_cap + 1u, sizeof *r.points);
    if (r.segments == NULL || r.points == NULL) {
        fprintf(stderr, "symline-ixscore: out of memory\n");
        goto done;
    }
    add_pieces(&gt, &r);
    nreq = r.segment_count;
    add_pieces(&dc, &r);
    /* fixed here, so that tuning the stage's defaults does not move the reference:
     * ground truth runs to the crossings, so a small gap (rounding) suffices */
    symline_intersection_config_default(&cfg);
    cfg.min_angle_q8 = 20u * 256u;
    cfg.gap_q8 = 3u * 256u;
    cfg.gap_pct = 50u;
    cfg.arm_q8 = 10u * 256u;
    cfg.merge_q8 = 10u * 256u;
    cfg.min_length_q8 = 0u;
    if (symline_intersections(&r, &cfg, &out) != SYMLINE_OK || out.truncated) {
        fprintf(stderr, "symline-ixscore: %s: reference intersections failed\n", name);
        goto done;
    }
    for (i = 0; i < out.count; i++) {
        ix_item *it = &ref[i];
        it->x = items[i].x / 256.0;
        it->y = items[i].y / 256.0;
        it->type = items[i].type;
        it->nrays = items[i].ray_count;
        for (k = 0; k < items[i].ray_count; k++) {
            it->rays[k] = items[i].rays[k] / 256.0;
        }
        it->dontcare = 0;
        for (k = 0; k < items[i].segment_count; k++) {
            it->dontcare |= items[i].segments[k] >= nreq;
        }
        it->matched = 0;
    }
    *nref = (int)out.count;
    rc = 0;
done:
    free(r.segments);
    free(r.points);
    ev_paths_free(&gt);
    ev_paths_free(&dc);
    ev_paths_free(&raw);
    return rc;
}

/* ---- detections from JSON ---- */

static char *read_text(const char *path)
{
    FILE *f = fopen(path, "rb");
    char *buf;
    long n;
    if (f == NULL || fseek(f, 0, SEEK_END) != 0 || (n = ftell(f)) < 0 || fseek(f, 0, SEEK_SET) != 0) {
        if (f != NULL) {
            fclose(f);
        }
        return NULL;
    }
    buf = malloc((size_t)n + 1u);
    if (buf != NULL && fread(buf, 1, (size_t)n, f) != (size_t)n) {
        free(buf);
        buf = NULL;
    }
    if (buf != NULL) {
        buf[n] = '\0';
    }
    fclose(f);
    return buf;
}

/* Value of "key": inside the object text [p, end); NULL when absent. */
static const char *key_in(const char *p, const char *end, const char *key)
{
    char pat[64];
    const char *q;
    snprintf(pat, sizeof pat, "\"%s\"", key);
    q = strstr(p, pat);
    if (q == NULL || q >= end) {
        return NULL;
    }
    q += strlen(pat);
    while (*q == ' ' || *q == ':') {
        q++;
    }
    return q;
}

/* The "intersections" array of a SPEC 7 JSON (absent: none). */
static int detections(const char *text, ix_item *det, int *ndet, int *width)
{
    const char *p = strstr(text, "\"intersections\"");
    const char *w = strstr(text, "\"width\"");
    *ndet = 0;
    if (w != NULL) {
        *width = atoi(key_in(w, w + 64, "width"));
    }
    if (p == NULL) {
        return 0;
    }
    p = strchr(p, '[');
    while (p != NULL && *ndet < IX_MAX) {
        const char *o = strchr(p, '{'), *close = strchr(p, ']'), *e, *v;
        ix_item *it = &det[*ndet];
        /* the array ends at the first ']' not inside an object (rays, segments are inside) */
        if (o == NULL || (close != NULL && close < o)) {
            break;
        }
        e = strchr(o, '}');
        if (e == NULL) {
            return -1;
        }
        memset(it, 0, sizeof *it);
        if ((v = key_in(o, e, "x")) == NULL) {
            return -1;
        }
        it->x = strtod(v, NULL);
        if ((v = key_in(o, e, "y")) == NULL) {
            return -1;
        }
        it->y = strtod(v, NULL);
        if ((v = key_in(o, e, "type")) == NULL || v[0] != '"') {
            return -1;
        }
        it->type = v[1] == 'L' ? 0 : v[1] == 'T' ? 1 : 2;
        if ((v = key_in(o, e, "rays")) != NULL && *v == '[') {
            char *q = (char *)v + 1;
            while (it->nrays < 4 && *q != ']') {
                char *nx;
                double a = strtod(q, &nx);
                if (nx == q) {
                    break;
                }
                it->rays[it->nrays++] = a;
                q = nx;
                while (*q == ',' || *q == ' ') {
                    q++;
                }
            }
        }
        (*ndet)++;
        p = e + 1;
    }
    return 0;
}

/* ---- matching ---- */

static double angle_diff(double a, double b)
{
    double d = fabs(a - b);
    return d > 180.0 ? 360.0 - d : d;
}

#define PROG "symline-ixscore"

enum { OPT_TOL = 0x100, OPT_LIST };

static const struct option longopts[] = {{"help", no_argument, NULL, HOSTOPTS_HELP},
                                         {"version", no_argument, NULL, HOSTOPTS_VERSION},
                                         {"tol", required_argument, NULL, OPT_TOL},
                                         {"list", no_argument, NULL, OPT_LIST},
                                         {NULL, 0, NULL, 0}};

int main(int argc, char **argv)
{
    static ix_item ref[IX_MAX], det[IX_MAX];
    const char *name = NULL, *json = NULL;
    double tol = -1.0, pos_sum = 0.0, ray_sum = 0.0;
    int list = 0, nref = 0, ndet = 0, width = 0, h = 0, i, j;
    int tp = 0, fp = 0, fn = 0, type_ok = 0, nray = 0, nreq = 0, ndet_counted = 0;
    char path[4096], *text;
    int c;
    while ((c = hostopts_next(argc, argv, ":h", longopts, PROG, PROG)) != -1) {
        switch (c) {
        case HOSTOPTS_HELP: usage(stdout); return 0;
        case HOSTOPTS_VERSION: hostopts_version(PROG); return 0;
        case OPT_LIST: list = 1; break;
        case OPT_TOL:
            if (hostopts_double(optarg, 0.0, 1e6, &tol) != 0) {
                return hostopts_usage_error(PROG, PROG, "--tol needs pixels >= 0");
            }
            break;
        default: return HOSTOPTS_USAGE; /* HOSTOPTS_ERROR: reported */
        }
    }
    if (argc - optind != 2) {
        return hostopts_usage_error(PROG, PROG, "needs NAME and DET.json");
    }
    name = argv[optind];
    json = argv[optind + 1];
    if (reference(name, ref, &nref) != 0) {
        return 1;
    }
    text = read_text(json);
    if (text == NULL || detections(text, det, &ndet, &width) != 0) {
        fprintf(stderr, "symline-ixscore: cannot read the intersections of %s\n", json);
        free(text);
        return 1;
    }
    free(text);
    snprintf(path, sizeof path, "%s.pgm", name);
    if (ev_pgm_size(path, &i, &h) == 0) {
        width = i;
    }
    if (tol < 0.0) {
        tol = fmax(4.0, 8.0 * width / 640.0);
    }
    /* nearest pairs first: repeat picking the closest free pair within tol */
    for (;;) {
        int bi = -1, bj = -1;
        double best = tol * tol;
        for (i = 0; i < nref; i++) {
            for (j = 0; j < ndet; j++) {
                const double dx = ref[i].x - det[j].x, dy = ref[i].y - det[j].y;
                const double d2 = dx * dx + dy * dy;
                if (!ref[i].matched && !det[j].matched && d2 <= best) {
                    best = d2;
                    bi = i;
                    bj = j;
                }
            }
        }
        if (bi < 0) {
            break;
        }
        ref[bi].matched = bj + 1;
        det[bj].matched = bi + 1;
    }
    for (i = 0; i < nref; i++) {
        const ix_item *r = &ref[i];
        if (r->dontcare) {
            continue;
        }
        nreq++;
        if (!r->matched) {
            fn++;
            continue;
        }
        tp++;
        {
            const ix_item *d = &det[r->matched - 1];
            pos_sum += hypot(r->x - d->x, r->y - d->y);
            if (d->type == r->type) {
                type_ok++;
                for (j = 0; j < r->nrays; j++) {
                    double b = 360.0;
                    int k;
                    for (k = 0; k < d->nrays; k++) {
                        b = fmin(b, angle_diff(r->rays[j], d->rays[k]));
                    }
                    ray_sum += b;
                    nray++;
                }
            }
        }
    }
    for (j = 0; j < ndet; j++) {
        if (det[j].matched && ref[det[j].matched - 1].dontcare) {
            continue;
        }
        ndet_counted++;
        if (!det[j].matched) {
            fp++;
        }
    }
    printf("ref=%d det=%d tp=%d fp=%d fn=%d p=%.4f r=%.4f type_ok=%d pos_err=%.3f ray_err=%.3f "
           "tol=%.2f\n",
           nreq, ndet_counted, tp, fp, fn, tp + fp ? (double)tp / (tp + fp) : 1.0,
           tp + fn ? (double)tp / (tp + fn) : 1.0, type_ok, tp ? pos_sum / tp : 0.0,
           nray ? ray_sum / nray : 0.0, tol);
    if (list) {
        static const char T[3] = {'L', 'T', 'X'};
        for (i = 0; i < nref; i++) {
            printf("ref %7.2f %7.2f %c%s -> %d\n", ref[i].x, ref[i].y, T[ref[i].type],
                   ref[i].dontcare ? " dontcare" : "", ref[i].matched - 1);
        }
        for (j = 0; j < ndet; j++) {
            printf("det %7.2f %7.2f %c -> %d\n", det[j].x, det[j].y, T[det[j].type],
                   det[j].matched - 1);
        }
    }
    return 0;
}

/* SPDX-License-Identifier: Apache-2.0 */
/*
 * symline-render: writes seeded synthetic field views with exact ground truth in
 * the formats of the shared synth README (NAME.pgm, NAME.lines.txt,
 * NAME.arcs.txt, NAME.dontcare.txt).
 */
#include <errno.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>

#include "hostopts.h"
#include "imgio.h"
#include "render.h"

static void usage(FILE *f)
{
    fputs("usage: symline-render --set SET [--seed N] [--count N] [--first K] [--size WxH]\n"
          "                      [--preview] [--labels] OUTDIR\n"
          "SET: normal | dark | overexposed | occluded | circle.\n"
          "Writes OUTDIR/SET_NNN.{pgm,lines.txt,arcs.txt,dontcare.txt} for NNN = K..K+N-1\n"
          "(defaults: seed 1, count 10, first 0, size 320x240); --preview adds SET_NNN.png;\n"
          "--labels adds SET_NNN.labels.pgm, the surface at each pixel centre: 0 carpet,\n"
          "1 paint, 2 floor, 3 wall, 4 ceiling, 5 robot (cylinder).\n"
          "The same seed, set, index and size always give the same files.\n"
          "Options take --opt VALUE or --opt=VALUE; --version prints the version.\n"
          "Exit status: 0 ok, 1 a file could not be written, 2 usage.\n",
          f);
}

static int write_segments(const char *path, const ev_paths *p)
{
    FILE *f = fopen(path, "w");
    size_t i;
    if (f == NULL) {
        fprintf(stderr, "symline-render: %s: %s\n", path, strerror(errno));
        return -1;
    }
    for (i = 0; i < p->npieces; i++) {
        const ev_pt *q = ev_piece_pts(p, i);
        size_t n = ev_piece_len(p, i);
        fprintf(f, "%.3f %.3f %.3f %.3f\n", q[0].x, q[0].y, q[n - 1].x, q[n - 1].y);
    }
    return fclose(f) == 0 ? 0 : -1;
}

static int write_polylines(const char *path, const ev_paths *p)
{
    FILE *f = fopen(path, "w");
    size_t i, k;
    if (f == NULL) {
        fprintf(stderr, "symline-render: %s: %s\n", path, strerror(errno));
        return -1;
    }
    for (i = 0; i < p->npieces; i++) {
        const ev_pt *q = ev_piece_pts(p, i);
        if (i > 0) {
            fputc('\n', f);
        }
        for (k = 0; k < ev_piece_len(p, i); k++) {
            fprintf(f, "%.3f %.3f\n", q[k].x, q[k].y);
        }
    }
    return fclose(f) == 0 ? 0 : -1;
}

static uint64_t image_seed(uint64_t seed, rd_set set, unsigned idx, int w, int h)
{
    uint64_t st = seed * 0x100000001B3ull ^ ((uint64_t)set << 48) ^ ((uint64_t)idx << 20) ^
                  ((uint64_t)w << 8) ^ (uint64_t)h;
    rd_rand_u64(&st);
    return rd_rand_u64(&st);
}

#define PROG "symline-render"

enum { OPT_SET = 0x100, OPT_SEED, OPT_COUNT, OPT_FIRST, OPT_SIZE, OPT_PREVIEW, OPT_LABELS };

static const struct option longopts[] = {
    {"help", no_argument, NULL, HOSTOPTS_HELP},   {"version", no_argument, NULL, HOSTOPTS_VERSION},
    {"set", required_argument, NULL, OPT_SET},     {"seed", required_argument, NULL, OPT_SEED},
    {"count", required_argument, NULL, OPT_COUNT}, {"first", required_argument, NULL, OPT_FIRST},
    {"size", required_argument, NULL, OPT_SIZE},   {"preview", no_argument, NULL, OPT_PREVIEW},
    {"labels", no_argument, NULL, OPT_LABELS},     {NULL, 0, NULL, 0}};

int main(int argc, char **argv)
{
    rd_set set = RD_NSETS;
    unsigned long seed = 1, count = 10, first = 0, k;
    int w = 320, h = 240, preview = 0, labels = 0, c;
    const char *outdir = NULL;
    long n;
    char tail;
    while ((c = hostopts_next(argc, argv, ":h", longopts, PROG, PROG)) != -1) {
        switch (c) {
        case HOSTOPTS_HELP: usage(stdout); return 0;
        case HOSTOPTS_VERSION: hostopts_version(PROG); return 0;
        case OPT_PREVIEW: preview = 1; break;
        case OPT_LABELS: labels = 1; break;
        case OPT_SET:
            if (rd_set_parse(optarg, &set) != 0) {
                return hostopts_usage_error(PROG, PROG, "unknown set '%s'", optarg);
            }
            break;
        case OPT_SEED:
        case OPT_COUNT:
        case OPT_FIRST:
            if (optarg[0] == '-' || hostopts_long(optarg, 0, 0x7fffffffL, &n) != 0) {
                return hostopts_usage_error(PROG, PROG, "%s needs a number 0..2147483647",
                                            argv[optind - 1]);
            }
            *(c == OPT_SEED ? &seed : c == OPT_COUNT ? &count : &first) = (unsigned long)n;
            break;
        case OPT_SIZE:
            if (sscanf(optarg, "%dx%d%c", &w, &h, &tail) != 2 || w < 16 || h < 16 || w > 8192 ||
                h > 8192) {
                return hostopts_usage_error(PROG, PROG, "--size needs WxH, each 16..8192");
            }
            break;
        default: return HOSTOPTS_USAGE; /* HOSTOPTS_ERROR: reported */
        }
    }
    if (optind < argc) {
        outdir = argv[optind++];
    }
    if (optind < argc) {
        return hostopts_usage_error(PROG, PROG, "unexpected argument '%s'", argv[optind]);
    }
    if (set == RD_NSETS || outdir == NULL) {
        return hostopts_usage_error(PROG, PROG, "needs --set SET and OUTDIR");
    }
    if (mkdir(outdir, 0777) != 0 && errno != EEXIST) {
        fprintf(stderr, "symline-render: %s: %s\n", outdir, strerror(errno));
        return 1;
    }
    for (k = first; k < first + count; k++) {
        rd_scene s;
        ev_paths lines, arcs, dc;
        uint8_t *img = malloc((size_t)w * (size_t)h);
        uint8_t *lab = labels ? malloc((size_t)w * (size_t)h) : NULL;
        char base[4096], path[4200], err[512];
        int rc = 0;
        if (img == NULL || (labels && lab == NULL)) {
            return 1;
        }
        snprintf(base, sizeof(base), "%s/%s_%03lu", outdir, rd_set_name(set), k);
        rd_scene_random(&s, set, w, h, image_seed(seed, set, (unsigned)k, w, h));
        rd_render(&s, img, lab);
        ev_paths_init(&lines);
        ev_paths_init(&arcs);
        ev_paths_init(&dc);
        rd_ground_truth(&s, &lines, &arcs, &dc);
        snprintf(path, sizeof(path), "%s.pgm", base);
        if (imgio_write_gray(path, img, (uint32_t)w, (uint32_t)h, (uint32_t)w, err, sizeof(err)) != 0) {
            fprintf(stderr, "symline-render: %s\n", err);
            rc = 1;
        }
        if (labels) {
            snprintf(path, sizeof(path), "%s.labels.pgm", base);
            if (imgio_write_gray(path, lab, (uint32_t)w, (uint32_t)h, (uint32_t)w, err, sizeof(err)) != 0) {
                fprintf(stderr, "symline-render: %s\n", err);
                rc = 1;
            }
        }
        if (preview) {
            snprintf(path, sizeof(path), "%s.png", base);
            if (imgio_write_gray(path, img, (uint32_t)w, (uint32_t)h, (uint32_t)w, err, sizeof(err)) != 0) {
                fprintf(stderr, "symline-render: %s\n", err);
                rc = 1;
            }
        }
        snprintf(path, sizeof(path), "%s.lines.txt", base);
        rc |= write_segments(path, &lines) != 0;
        snprintf(path, sizeof(path), "%s.arcs.txt", base);
        rc |= write_polylines(path, &arcs) != 0;
        snprintf(path, sizeof(path), "%s.dontcare.txt", base);
        rc |= write_segments(path, &dc) != 0;
        ev_paths_free(&lines);
        ev_paths_free(&arcs);
        ev_paths_free(&dc);
        free(img);
        free(lab);
        if (rc) {
            return 1;
        }
    }
    return 0;
}

/* SPDX-License-Identifier: Apache-2.0 */
/*
 * symline-bright: brightness transforms for the stability check
 * (out = clip(round(in * MUL + ADD), 0, 255)); also converts between PGM and PNG.
 */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "hostopts.h"
#include "imgio.h"

static void usage(FILE *f)
{
    fputs("usage: symline-bright [--mul K] [--add A] [--report] [--clipped MASK] IN OUT\n"
          "Writes clip(round(v*K + A), 0, 255) for every pixel v (K default 1, A default 0;\n"
          "round half up). OUT is PNG when it ends in .png, else PGM. --report prints\n"
          "\"pixels=N clipped_low=N clipped_high=N\": pixels whose value the clipping\n"
          "changed (below 0, above 255). --clipped writes those pixels as 255, others 0.\n"
          "Options take --opt VALUE or --opt=VALUE; --version prints the version.\n"
          "Exit status: 0 ok, 1 unreadable input or unwritable output, 2 usage.\n",
          f);
}

#define PROG "symline-bright"

enum { OPT_MUL = 0x100, OPT_ADD, OPT_REPORT, OPT_CLIPPED };

static const struct option longopts[] = {{"help", no_argument, NULL, HOSTOPTS_HELP},
                                         {"version", no_argument, NULL, HOSTOPTS_VERSION},
                                         {"mul", required_argument, NULL, OPT_MUL},
                                         {"add", required_argument, NULL, OPT_ADD},
                                         {"report", no_argument, NULL, OPT_REPORT},
                                         {"clipped", required_argument, NULL, OPT_CLIPPED},
                                         {NULL, 0, NULL, 0}};

int main(int argc, char **argv)
{
    double mul = 1.0, add = 0.0;
    int i, c, report = 0;
    const char *clipped = NULL;
    uint8_t *cmask = NULL;
    size_t low = 0, high = 0;
    imgio_gray img;
    char err[512];
    size_t k, n;
    while ((c = hostopts_next(argc, argv, ":h", longopts, PROG, PROG)) != -1) {
        switch (c) {
        case HOSTOPTS_HELP: usage(stdout); return 0;
        case HOSTOPTS_VERSION: hostopts_version(PROG); return 0;
        case OPT_REPORT: report = 1; break;
        case OPT_CLIPPED: clipped = optarg; break;
        case OPT_MUL:
        case OPT_ADD:
            if (hostopts_double(optarg, -1e6, 1e6, c == OPT_MUL ? &mul : &add) != 0) {
                return hostopts_usage_error(PROG, PROG, "bad number '%s' for %s", optarg,
                                            c == OPT_MUL ? "--mul" : "--add");
            }
            break;
        default: return HOSTOPTS_USAGE; /* HOSTOPTS_ERROR: reported */
        }
    }
    if (argc - optind != 2) {
        return hostopts_usage_error(PROG, PROG, "needs IN and OUT");
    }
    i = optind;
    if (imgio_read_gray(argv[i], &img, err, sizeof(err)) != 0) {
        fprintf(stderr, "symline-bright: %s\n", err);
        return 1;
    }
    n = (size_t)img.width * img.height;
    if (clipped != NULL) {
        cmask = calloc(n ? n : 1, 1);
        if (cmask == NULL) {
            imgio_free(&img);
            return 1;
        }
    }
    for (k = 0; k < n; k++) {
        double v = floor((double)img.px[k] * mul + add + 0.5);
        low += v < 0.0;
        high += v > 255.0;
        if (cmask != NULL && (v < 0.0 || v > 255.0)) {
            cmask[k] = 255;
        }
        img.px[k] = (uint8_t)(v < 0.0 ? 0.0 : (v > 255.0 ? 255.0 : v));
    }
    if (imgio_write_gray(argv[i + 1], img.px, img.width, img.height, img.width, err,
                         sizeof(err)) != 0) {
        fprintf(stderr, "symline-bright: %s\n", err);
        imgio_free(&img);
        return 1;
    }
    if (cmask != NULL) {
        int rc = imgio_write_gray(clipped, cmask, img.width, img.height, img.width, err, sizeof(err));
        free(cmask);
        if (rc != 0) {
            fprintf(stderr, "symline-bright: %s\n", err);
            imgio_free(&img);
            return 1;
        }
    }
    if (report) {
        printf("pixels=%zu clipped_low=%zu clipped_high=%zu\n", n, low, high);
    }
    imgio_free(&img);
    return 0;
}

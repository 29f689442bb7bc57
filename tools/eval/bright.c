/* SPDX-License-Identifier: Apache-2.0 */
/*
 * symline-bright: brightness transforms for the stability check
 * (out = clip(round(in * MUL + ADD), 0, 255)); also converts between PGM and PNG.
 */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "imgio.h"

static void usage(FILE *f)
{
    fputs("usage: symline-bright [--mul K] [--add A] [--report] [--clipped MASK] IN OUT\n"
          "Writes clip(round(v*K + A), 0, 255) for every pixel v (K default 1, A default 0;\n"
          "round half up). OUT is PNG when it ends in .png, else PGM. --report prints\n"
          "\"pixels=N clipped_low=N clipped_high=N\": pixels whose value the clipping\n"
          "changed (below 0, above 255). --clipped writes those pixels as 255, others 0.\n",
          f);
}

int main(int argc, char **argv)
{
    double mul = 1.0, add = 0.0;
    int i = 1, report = 0;
    const char *clipped = NULL;
    uint8_t *cmask = NULL;
    size_t low = 0, high = 0;
    imgio_gray img;
    char err[512];
    size_t k, n;
    while (i < argc && argv[i][0] == '-' && argv[i][1] == '-') {
        char *end;
        if (strcmp(argv[i], "--help") == 0) {
            usage(stdout);
            return 0;
        }
        if (strcmp(argv[i], "--report") == 0) {
            report = 1;
            i++;
            continue;
        }
        if (i + 1 >= argc) {
            usage(stderr);
            return 2;
        }
        if (strcmp(argv[i], "--clipped") == 0) {
            clipped = argv[i + 1];
            i += 2;
            continue;
        }
        if (strcmp(argv[i], "--mul") == 0) {
            mul = strtod(argv[i + 1], &end);
        } else if (strcmp(argv[i], "--add") == 0) {
            add = strtod(argv[i + 1], &end);
        } else {
            usage(stderr);
            return 2;
        }
        if (*end != '\0') {
            fprintf(stderr, "symline-bright: bad number '%s'\n", argv[i + 1]);
            return 2;
        }
        i += 2;
    }
    if (argc - i != 2) {
        usage(stderr);
        return 2;
    }
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

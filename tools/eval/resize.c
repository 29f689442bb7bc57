/* SPDX-License-Identifier: Apache-2.0 */
/*
 * symline-resize: a frame at half or double size, and its ground truth with it,
 * for the scale check of the evaluation (the same scene seen by a camera of
 * fewer or more pixels).
 */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "hostopts.h"
#include "imgio.h"
#include "symline/binning.h"

static void usage(FILE *f)
{
    fputs("usage: symline-resize (--half | --double) [--gt] IN OUT\n"
          "--half: each output pixel is the mean of a 2x2 block (round half up; an odd\n"
          "last column or row is dropped). --double: bilinear, pixel centres aligned\n"
          "(output pixel X samples the input at X/2 - 1/4; weights 3/4 and 1/4 per axis,\n"
          "round half up; the border pixels repeat). OUT is PNG when it ends in .png.\n"
          "--gt: also the ground truth: NAME.lines.txt, .arcs.txt and .dontcare.txt next\n"
          "to IN (NAME: IN without its extension) to the same names next to OUT, every\n"
          "coordinate c as (c + 1/2) s - 1/2, s the scale (pixel centres at integer\n"
          "coordinates); blank lines are kept, missing files skipped.\n"
          "Options take --opt VALUE or --opt=VALUE; --version prints the version.\n"
          "Exit status: 0 ok, 1 unreadable input or unwritable output, 2 usage.\n",
          f);
}

#define PROG "symline-resize"

enum { OPT_HALF = 0x100, OPT_DOUBLE, OPT_GT };

static const struct option longopts[] = {{"help", no_argument, NULL, HOSTOPTS_HELP},
                                         {"version", no_argument, NULL, HOSTOPTS_VERSION},
                                         {"half", no_argument, NULL, OPT_HALF},
                                         {"double", no_argument, NULL, OPT_DOUBLE},
                                         {"gt", no_argument, NULL, OPT_GT},
                                         {NULL, 0, NULL, 0}};

/* Input index and weights (of 4) of output index o along an axis of n:
 * o = 2i samples 3/4 of i and 1/4 of i - 1, o = 2i + 1 3/4 of i and 1/4
 * of i + 1, clamped at the ends. */
static void taps(uint32_t o, uint32_t n, uint32_t *near, uint32_t *far)
{
    const uint32_t i = o / 2u;
    *near = i;
    if (o % 2u == 0u) {
        *far = i > 0u ? i - 1u : 0u;
    } else {
        *far = i + 1u < n ? i + 1u : n - 1u;
    }
}

/* out: 2w x 2h. */
static void twice(const uint8_t *in, uint32_t w, uint32_t h, uint8_t *out)
{
    const uint32_t ow = 2u * w, oh = 2u * h;
    uint32_t x, y;
    for (y = 0; y < oh; y++) {
        uint32_t yn, yf;
        taps(y, h, &yn, &yf);
        for (x = 0; x < ow; x++) {
            uint32_t xn, xf, v;
            taps(x, w, &xn, &xf);
            v = 9u * in[(size_t)yn * w + xn] + 3u * in[(size_t)yn * w + xf] +
                3u * in[(size_t)yf * w + xn] + in[(size_t)yf * w + xf];
            out[(size_t)y * ow + x] = (uint8_t)((v + 8u) / 16u);
        }
    }
}

/* NAME.EXT.txt to OUTNAME.EXT.txt, every number c as (c + 0.5) s - 0.5.
 * 0 ok or no such file, 1 error (reported). */
static int scale_gt(const char *name, const char *outname, const char *ext, double s)
{
    char in_path[4096], out_path[4096], line[4096];
    FILE *in, *out;
    int rc = 0;
    if ((size_t)snprintf(in_path, sizeof in_path, "%s.%s.txt", name, ext) >= sizeof in_path ||
        (size_t)snprintf(out_path, sizeof out_path, "%s.%s.txt", outname, ext) >= sizeof out_path) {
        fprintf(stderr, "%s: path too long\n", PROG);
        return 1;
    }
    in = fopen(in_path, "r");
    if (in == NULL) {
        return 0;
    }
    out = fopen(out_path, "w");
    if (out == NULL) {
        fprintf(stderr, "%s: cannot write %s\n", PROG, out_path);
        fclose(in);
        return 1;
    }
    while (rc == 0 && fgets(line, sizeof line, in) != NULL) {
        const char *p = line;
        char *end;
        int first = 1;
        for (;;) {
            const double v = strtod(p, &end);
            if (end == p) {
                break;
            }
            fprintf(out, "%s%.2f", first ? "" : " ", (v + 0.5) * s - 0.5);
            first = 0;
            p = end;
        }
        while (*p == ' ' || *p == '\t' || *p == '\r' || *p == '\n') {
            p++;
        }
        if (*p != '\0') {
            fprintf(stderr, "%s: %s: not a list of numbers: %s", PROG, in_path, line);
            rc = 1;
        }
        fputc('\n', out);
    }
    fclose(in);
    if (fclose(out) != 0) {
        fprintf(stderr, "%s: cannot write %s\n", PROG, out_path);
        rc = 1;
    }
    return rc;
}

/* path without its extension (after the last '.' of the last component) in out. */
static int stem(const char *path, char *out, size_t cap)
{
    const char *slash = strrchr(path, '/'), *dot = strrchr(path, '.');
    const size_t n = dot != NULL && (slash == NULL || dot > slash) ? (size_t)(dot - path)
                                                                  : strlen(path);
    if (n >= cap) {
        return 1;
    }
    memcpy(out, path, n);
    out[n] = '\0';
    return 0;
}

int main(int argc, char **argv)
{
    int c, mode = 0, gt = 0;
    char name[4096], outname[4096];
    imgio_gray img;
    char err[512];
    uint8_t *out;
    uint32_t ow, oh;
    static const char *const exts[] = {"lines", "arcs", "dontcare"};
    size_t k;
    while ((c = hostopts_next(argc, argv, ":h", longopts, PROG, PROG)) != -1) {
        switch (c) {
        case HOSTOPTS_HELP: usage(stdout); return 0;
        case HOSTOPTS_VERSION: hostopts_version(PROG); return 0;
        case OPT_HALF:
        case OPT_DOUBLE: mode = c; break;
        case OPT_GT: gt = 1; break;
        default: return HOSTOPTS_USAGE; /* HOSTOPTS_ERROR: reported */
        }
    }
    if (mode == 0) {
        return hostopts_usage_error(PROG, PROG, "needs --half or --double");
    }
    if (argc - optind != 2) {
        return hostopts_usage_error(PROG, PROG, "needs IN and OUT");
    }
    if (gt && (stem(argv[optind], name, sizeof name) != 0 ||
               stem(argv[optind + 1], outname, sizeof outname) != 0)) {
        return hostopts_usage_error(PROG, PROG, "path too long");
    }
    if (imgio_read_gray(argv[optind], &img, err, sizeof(err)) != 0) {
        fprintf(stderr, "%s: %s\n", PROG, err);
        return 1;
    }
    ow = mode == OPT_HALF ? img.width / 2u : 2u * img.width;
    oh = mode == OPT_HALF ? img.height / 2u : 2u * img.height;
    if (ow == 0u || oh == 0u || ow > 65535u || oh > 65535u) {
        fprintf(stderr, "%s: %s: %ux%u cannot be resized so\n", PROG, argv[optind],
                (unsigned)img.width, (unsigned)img.height);
        imgio_free(&img);
        return 1;
    }
    out = malloc((size_t)ow * oh);
    if (out == NULL) {
        fprintf(stderr, "%s: out of memory\n", PROG);
        imgio_free(&img);
        return 1;
    }
    if (mode == OPT_HALF) {
        /* The library's 2x2 binning (symline/binning.h), as `symline lines --bin`. */
        const symline_image in = {img.width, img.height, img.width, img.px};
        symline_image half;
        const symline_status st = symline_bin2(&in, out, (size_t)ow * oh, &half);
        if (st != SYMLINE_OK) {
            fprintf(stderr, "%s: %s\n", PROG, symline_status_str(st));
            imgio_free(&img);
            free(out);
            return 1;
        }
    } else {
        twice(img.px, img.width, img.height, out);
    }
    imgio_free(&img);
    if (imgio_write_gray(argv[optind + 1], out, ow, oh, ow, err, sizeof(err)) != 0) {
        fprintf(stderr, "%s: %s\n", PROG, err);
        free(out);
        return 1;
    }
    free(out);
    for (k = 0; gt && k < sizeof exts / sizeof exts[0]; k++) {
        if (scale_gt(name, outname, exts[k], mode == OPT_HALF ? 0.5 : 2.0) != 0) {
            return 1;
        }
    }
    return 0;
}

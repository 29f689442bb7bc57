/* SPDX-License-Identifier: Apache-2.0 */
/*
 * `symline features` and `symline histogram`: the paper's symmetry feature
 * points and vertical symmetry histogram (docs/format.md) as JSON.
 */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "cli.h"
#include "detopts.h"
#include "imgio.h"
#include "symline/features.h"
#include "symline/histogram.h"

typedef struct feat_args {
    uint32_t radius;
    const char *in;
    const char *plot; /* histogram only; NULL: no plot */
} feat_args;

static void feat_usage(FILE *f, const char *cmd)
{
    if (strcmp(cmd, "features") == 0) {
        fputs("usage: symline features --radius M IN\n"
              "  prints {\"width\": W, \"height\": H, \"radius\": M, \"points\": [[x, y], ...]}:\n"
              "  the pixels that are S points (symmetry maxima) of both the horizontal- and\n"
              "  the vertical-axis extrema maps at radius M, in raster order (y, then x)\n",
              f);
    } else {
        fputs("usage: symline histogram --radius M IN [--plot OUT.png]\n"
              "  prints {\"width\": W, \"height\": H, \"radius\": M, \"counts\": [c_0, ...]}:\n"
              "  per image column, the number of S points of the vertical-axis extrema map\n"
              "  --plot OUT  also write the frame with the histogram drawn under it\n"
              "              (PNG if the name ends in .png, else PGM)\n",
              f);
    }
    fputs("  --radius  symmetry radius M, 1..255\n"
          "  IN        binary PGM (P5, maxval 255) or PNG\n"
          "Exit status: 0 ok, 1 processing error, 2 usage or input error.\n",
          f);
}

/* 0 ok, 1 --help shown, CLI_USAGE on error. */
static int parse_feat_args(int argc, char **argv, feat_args *a, int allow_plot)
{
    static const struct option longopts[] = {{"radius", required_argument, NULL, 'r'},
                                             {"plot", required_argument, NULL, 'p'},
                                             {"help", no_argument, NULL, 'h'},
                                             {NULL, 0, NULL, 0}};
    int c, have_radius = 0;
    a->in = NULL;
    a->plot = NULL;
    optind = 1;
    while ((c = cli_getopt(argc, argv, ":h", longopts)) != -1) {
        if (c == 'h') {
            feat_usage(stdout, argv[0]);
            return 1;
        } else if (c == 'r') {
            if (detopts_u32(optarg, 1, 255, &a->radius) != 0) {
                return cli_error("%s: --radius needs an integer 1..255", argv[0]);
            }
            have_radius = 1;
        } else if (c == 'p' && allow_plot) {
            a->plot = optarg;
        } else if (c == 'p') {
            return cli_error("%s: unknown option '--plot'", argv[0]);
        } else {
            return CLI_USAGE;
        }
    }
    if (optind < argc) {
        a->in = argv[optind++];
    }
    if (optind < argc) {
        return cli_error("%s: too many arguments ('%s')", argv[0], argv[optind]);
    }
    if (!have_radius || a->in == NULL) {
        feat_usage(stderr, argv[0]);
        return CLI_USAGE;
    }
    return 0;
}

/* The arguments, then the input frame and a view of it: 0, 1 (--help was
 * answered) or the exit status of a failure. */
static int load_feat(int argc, char **argv, int allow_plot, feat_args *a, imgio_gray *in,
                     symline_image *view)
{
    char err[512];
    const int rc = parse_feat_args(argc, argv, a, allow_plot);
    if (rc != 0) {
        return rc;
    }
    if (imgio_read_gray(a->in, in, err, sizeof err) != 0) {
        return cli_error("%s", err);
    }
    view->width = in->width;
    view->height = in->height;
    view->stride = in->width;
    view->data = in->px;
    return 0;
}

int cmd_features(int argc, char **argv)
{
    feat_args a;
    imgio_gray in;
    symline_image view;
    symline_point *pts;
    uint32_t cap, n = 0u, i;
    void *ws;
    size_t ws_size;
    symline_status st;
    int rc = load_feat(argc, argv, 0, &a, &in, &view);
    if (rc != 0) {
        return rc == 1 ? CLI_OK : rc;
    }
    ws_size = symline_features_workspace_size(in.width, in.height, a.radius);
    cap = symline_features_max_points(in.width, in.height);
    ws = malloc(ws_size);
    pts = (symline_point *)malloc(((size_t)cap + 1u) * sizeof(symline_point));
    if (ws == NULL || pts == NULL) {
        rc = cli_error("out of memory");
    } else {
        st = symline_features(&view, a.radius, ws, ws_size, pts, cap, &n);
        if (st != SYMLINE_OK) {
            cli_error("%s: %s", a.in, symline_status_str(st));
            rc = CLI_FAIL;
        } else {
            printf("{\"width\": %u, \"height\": %u, \"radius\": %u, \"points\": [", in.width,
                   in.height, a.radius);
            for (i = 0; i < n; i++) {
                printf(i ? ", [%u, %u]" : "[%u, %u]", (unsigned)pts[i].x, (unsigned)pts[i].y);
            }
            printf("]}\n");
            rc = fflush(stdout) == 0 ? CLI_OK : CLI_FAIL;
        }
    }
    free(ws);
    free(pts);
    imgio_free(&in);
    return rc;
}

/* The frame with a bar chart of counts under it: one bar per column, the
 * tallest one plot_h - 4 pixels high, on a black band. */
static int write_plot(const char *path, const imgio_gray *in, const uint16_t *counts, char *err,
                      size_t errlen)
{
    const uint32_t w = in->width, h = in->height;
    const uint32_t plot_h = h / 4u > 64u ? h / 4u : 64u;
    uint8_t *px = (uint8_t *)calloc((size_t)w * (h + plot_h), 1);
    uint32_t x, y, top = 1u;
    int rc;
    if (px == NULL) {
        snprintf(err, errlen, "%s: out of memory", path);
        return -1;
    }
    memcpy(px, in->px, (size_t)w * h);
    for (x = 0; x < w; x++) {
        top = counts[x] > top ? counts[x] : top;
    }
    for (x = 0; x < w; x++) {
        const uint32_t bar = (uint32_t)(((uint64_t)counts[x] * (plot_h - 4u) + top / 2u) / top);
        for (y = 0; y < bar; y++) {
            px[(size_t)(h + plot_h - 1u - y) * w + x] = 255u;
        }
    }
    rc = imgio_write_gray(path, px, w, h + plot_h, w, err, errlen);
    free(px);
    return rc;
}

int cmd_histogram(int argc, char **argv)
{
    feat_args a;
    imgio_gray in;
    symline_image view;
    char err[512];
    uint16_t *counts;
    uint32_t x;
    void *ws;
    size_t ws_size;
    symline_status st;
    int rc = load_feat(argc, argv, 1, &a, &in, &view);
    if (rc != 0) {
        return rc == 1 ? CLI_OK : rc;
    }
    ws_size = symline_histogram_workspace_size(in.width, a.radius);
    ws = malloc(ws_size);
    counts = (uint16_t *)malloc((size_t)in.width * sizeof(uint16_t));
    if (ws == NULL || counts == NULL) {
        rc = cli_error("out of memory");
    } else {
        st = symline_histogram(&view, a.radius, counts, in.width, ws, ws_size);
        if (st != SYMLINE_OK) {
            cli_error("%s: %s", a.in, symline_status_str(st));
            rc = CLI_FAIL;
        } else {
            printf("{\"width\": %u, \"height\": %u, \"radius\": %u, \"counts\": [", in.width,
                   in.height, a.radius);
            for (x = 0; x < in.width; x++) {
                printf(x ? ", %u" : "%u", (unsigned)counts[x]);
            }
            printf("]}\n");
            rc = fflush(stdout) == 0 ? CLI_OK : CLI_FAIL;
            if (rc == CLI_OK && a.plot != NULL &&
                write_plot(a.plot, &in, counts, err, sizeof err) != 0) {
                cli_error("%s", err);
                rc = CLI_FAIL;
            }
        }
    }
    free(ws);
    free(counts);
    imgio_free(&in);
    return rc;
}

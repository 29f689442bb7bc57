/*
 * `symline lines` and `symline overlay`: the line detector on one image.
 */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "../common/detopts.h"
#include "../common/imgio.h"
#include "../common/overlay.h"
#include "../common/segjson.h"
#include "cli.h"
#include "symline/detect.h"
#include "symline/intersections.h"

typedef struct lines_args {
    symline_config cfg;
    const char *in;
    const char *out;
    int intersections; /* 0 with --no-intersections */
} lines_args;

static void lines_usage(FILE *f, const char *cmd)
{
    const int ov = strcmp(cmd, "overlay") == 0;
    fprintf(f, "usage: symline %s [options] IN%s\n", cmd, ov ? " OUT.png" : "");
    detopts_help(f);
    fprintf(f,
            "  --no-intersections  leave out where lines meet (JSON key \"intersections\")\n"
            "  IN                  binary PGM or PNG (colour is converted to luma)\n"
            "%s"
            "Prints JSON (SPEC section 7) on stdout%s.\n"
            "Exit status: 0 ok, 1 processing error, 2 usage or input error.\n",
            ov ? "  OUT.png             the frame in colour with lines (solid red), curves\n"
                 "                      (dotted cyan) and intersections (a square with a spoke\n"
                 "                      per ray: L green, T orange, X magenta); PPM unless\n"
                 "                      the name ends in .png\n"
               : "",
            ov ? " as well" : "");
}

/* 0 ok, 1 --help shown, CLI_USAGE on error. */
static int parse_lines_args(int argc, char **argv, lines_args *a, int npos_want)
{
    int i, npos = 0;
    const char *pos[2] = {NULL, NULL};
    detopts d;
    char err[128];
    detopts_init(&d);
    a->intersections = 1;
    for (i = 1; i < argc; i++) {
        const char *o = argv[i];
        int rc;
        if (strcmp(o, "--help") == 0 || strcmp(o, "-h") == 0) {
            lines_usage(stdout, argv[0]);
            return 1;
        }
        if (strcmp(o, "--no-intersections") == 0) {
            a->intersections = 0;
            continue;
        }
        rc = detopts_parse(&d, argc, argv, &i, err, sizeof err);
        if (rc < 0) {
            return cli_error("%s: %s", argv[0], err);
        }
        if (rc > 0) {
            continue;
        }
        if (o[0] == '-' && o[1] != '\0') {
            return cli_error("%s: unknown option '%s'", argv[0], o);
        } else if (npos < npos_want) {
            pos[npos++] = o;
        } else {
            return cli_error("%s: too many arguments ('%s')", argv[0], o);
        }
    }
    if (npos != npos_want) {
        lines_usage(stderr, argv[0]);
        return CLI_USAGE;
    }
    detopts_finish(&d);
    a->cfg = d.cfg;
    a->in = pos[0];
    a->out = pos[1];
    return 0;
}

static int run_lines(int argc, char **argv, int overlay)
{
    lines_args a;
    imgio_gray in;
    symline_image view;
    symline_result res;
    symline_intersection_config icfg;
    symline_intersection items[256];
    symline_intersection_result ix;
    char err[512];
    void *ws;
    size_t ws_size;
    symline_status st;
    int rc = parse_lines_args(argc, argv, &a, overlay ? 2 : 1);
    if (rc != 0) {
        return rc == 1 ? CLI_OK : rc;
    }
    if (imgio_read_gray(a.in, &in, err, sizeof err) != 0) {
        return cli_error("%s", err);
    }
    view.width = in.width;
    view.height = in.height;
    view.stride = in.width;
    view.data = in.px;
    ws_size = symline_detect_workspace_size(in.width, in.height, &a.cfg);
    if (ws_size == 0u) {
        imgio_free(&in);
        return cli_error("%s: image size or configuration not supported", argv[0]);
    }
    memset(&res, 0, sizeof res);
    res.segment_cap = 8192u;
    res.point_cap = 2u * in.width * in.height + 1024u;
    ws = malloc(ws_size);
    res.segments = (symline_segment *)malloc(res.segment_cap * sizeof(symline_segment));
    res.points = (symline_point *)malloc((size_t)res.point_cap * sizeof(symline_point));
    if (ws == NULL || res.segments == NULL || res.points == NULL) {
        rc = cli_error("out of memory");
    } else {
        const symline_intersection_result *ixp = a.intersections ? &ix : NULL;
        symline_intersection_config_default(&icfg);
        ix.items = items;
        ix.cap = sizeof items / sizeof items[0];
        st = symline_detect(&view, &a.cfg, ws, ws_size, &res);
        if (st == SYMLINE_OK && a.intersections) {
            st = symline_intersections(&res, &icfg, &ix);
        }
        if (st != SYMLINE_OK) {
            cli_error("%s: %s", argv[0], symline_status_str(st));
            rc = CLI_FAIL;
        } else if (segjson_write_ix(stdout, in.width, in.height, &res, ixp) != 0) {
            rc = CLI_FAIL;
        } else if (overlay && overlay_write_ix(a.out, in.px, in.width, in.height, in.width, &res,
                                               ixp, err, sizeof err) != 0) {
            cli_error("%s", err);
            rc = CLI_FAIL;
        }
    }
    free(ws);
    free(res.segments);
    free(res.points);
    imgio_free(&in);
    return rc;
}

int cmd_lines(int argc, char **argv)
{
    return run_lines(argc, argv, 0);
}

int cmd_overlay(int argc, char **argv)
{
    return run_lines(argc, argv, 1);
}

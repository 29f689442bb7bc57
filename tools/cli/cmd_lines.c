/*
 * `symline lines` and `symline overlay`: the line detector on one image.
 */
#include <stddef.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "detopts.h"
#include "imgio.h"
#include "overlay.h"
#include "segjson.h"
#include "cli.h"
#include "muffopts.h"
#include "symline/detect.h"
#include "symline/intersections.h"

typedef struct lines_args {
    symline_config cfg;
    symline_intersection_config icfg;
    muffopts method;
    const char *in;
    const char *out;
    int intersections; /* 0 with --no-intersections */
    uint32_t repeat; /* detections run on the frame (the output is printed once) */
} lines_args;

/* Intersection options: name, range, field of symline_intersection_config. */
typedef struct ix_opt {
    const char *name;
    uint32_t lo, hi;
    size_t offset;
} ix_opt;

static const ix_opt ix_opts[] = {
    {"--ix-min-angle", 0, 90u * 256u, offsetof(symline_intersection_config, min_angle_q8)},
    {"--ix-gap", 0, 65536u, offsetof(symline_intersection_config, gap_q8)},
    {"--ix-gap-pct", 0, 100u, offsetof(symline_intersection_config, gap_pct)},
    {"--ix-arm", 256u, 65536u, offsetof(symline_intersection_config, arm_q8)},
    {"--ix-merge", 0, 65536u, offsetof(symline_intersection_config, merge_q8)},
    {"--ix-min-length", 0, 65535u << 8, offsetof(symline_intersection_config, min_length_q8)},
};

/* 1 when argv[*i] is an intersection option (value taken), 0 when not, CLI_USAGE on error. */
static int parse_ix_opt(lines_args *a, int argc, char **argv, int *i)
{
    size_t k;
    for (k = 0; k < sizeof ix_opts / sizeof ix_opts[0]; k++) {
        if (strcmp(argv[*i], ix_opts[k].name) == 0) {
            uint32_t v;
            if (*i + 1 >= argc || detopts_u32(argv[*i + 1], ix_opts[k].lo, ix_opts[k].hi, &v) != 0) {
                return cli_error("%s: %s needs a number in %u..%u", argv[0], argv[*i],
                                 ix_opts[k].lo, ix_opts[k].hi);
            }
            memcpy((char *)&a->icfg + ix_opts[k].offset, &v, sizeof v);
            (*i)++;
            return 1;
        }
    }
    return 0;
}

static void lines_usage(FILE *f, const char *cmd)
{
    const int ov = strcmp(cmd, "overlay") == 0;
    fprintf(f, "usage: symline %s [options] IN%s\n", cmd, ov ? " OUT.png" : "");
    detopts_help(f);
    muffopts_help(f);
    fprintf(f,
            "  --no-intersections  leave out where lines meet (JSON key \"intersections\")\n"
            "  --ix-min-angle Q8DEG, --ix-gap Q8PX, --ix-gap-pct PCT, --ix-arm Q8PX,\n"
            "  --ix-merge Q8PX, --ix-min-length Q8PX\n"
            "                      intersection settings (include/symline/intersections.h)\n"
            "  --repeat N          run the detection N times (1..1000000; default 1) and\n"
            "                      print it once: (cost(N=11) - cost(N=1)) / 10 is one\n"
            "                      detection (tools/bench/icount.sh)\n"
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
    symline_intersection_config_default(&a->icfg);
    a->repeat = 1u;
    muffopts_init(&a->method);
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
        rc = parse_ix_opt(a, argc, argv, &i);
        if (rc == CLI_USAGE) {
            return rc;
        }
        if (rc == 1) {
            continue;
        }
        if (strcmp(o, "--repeat") == 0) {
            if (i + 1 >= argc || detopts_u32(argv[i + 1], 1u, 1000000u, &a->repeat) != 0) {
                return cli_error("%s: --repeat needs a number 1..1000000", argv[0]);
            }
            i++;
            continue;
        }
        rc = muffopts_parse(&a->method, argc, argv, &i, err, sizeof err);
        if (rc == 0) {
            rc = detopts_parse(&d, argc, argv, &i, err, sizeof err);
        }
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

/* The tracer (symline_detect) or the Muff-space finder with its accumulator. */
static symline_status run_method(const lines_args *a, const symline_image *view, void *ws,
                                 size_t ws_size, symline_result *res)
{
    size_t acc_size;
    uint16_t *acc;
    symline_status st;
    if (!a->method.muff) {
        return symline_detect(view, &a->cfg, ws, ws_size, res);
    }
    acc_size = symline_muff_accumulator_size(view->width, view->height, &a->method.mc);
    acc = (uint16_t *)malloc(acc_size > 0u ? acc_size : 1u);
    if (acc == NULL) {
        return SYMLINE_ERR_BUFFER;
    }
    st = symline_detect_muff(view, &a->cfg, &a->method.mc, acc, acc_size, ws, ws_size, res);
    free(acc);
    return st;
}

static int run_lines(int argc, char **argv, int overlay)
{
    lines_args a;
    imgio_gray in;
    symline_image view;
    symline_result res;
    symline_intersection items[256];
    symline_intersection_result ix;
    char err[512];
    void *ws;
    size_t ws_size;
    symline_status st = SYMLINE_OK;
    uint32_t r;
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
    a.method.mc.min_length = a.cfg.min_length;
    ws_size = a.method.muff ? symline_detect_muff_workspace_size(in.width, in.height, &a.cfg,
                                                                 &a.method.mc)
                            : symline_detect_workspace_size(in.width, in.height, &a.cfg);
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
        ix.items = items;
        ix.cap = sizeof items / sizeof items[0];
        for (r = 0u; r < a.repeat && st == SYMLINE_OK; r++) {
            st = run_method(&a, &view, ws, ws_size, &res);
        }
        if (st == SYMLINE_OK && a.intersections) {
            st = symline_intersections(&res, &a.icfg, &ix);
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

/* SPDX-License-Identifier: Apache-2.0 */
/*
 * `symline lines` and `symline overlay`: the line detector on images.
 */
#include <errno.h>
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
#include "symline/binning.h"
#include "symline/detect.h"
#include "symline/intersections.h"

typedef struct lines_args {
    symline_config cfg;
    detopts_bin bin;   /* --bin */
    muffopts method;   /* the tracer (default) or the Muff-space finder */
    cli_inputs in;     /* lines: every input; overlay: exactly one */
    const char *out;   /* overlay: the image */
    const char *json;  /* where the JSON goes: lines: stdout unless -o; overlay: only with --json */
    uint32_t repeat;   /* detections run on each frame (the output is printed once) */
    symline_intersection_config icfg;
    int intersections; /* 0 with --no-intersections */
} lines_args;

/* Intersection options: name, range, field of symline_intersection_config. */
typedef struct ix_opt {
    const char *name;
    uint32_t lo, hi;
    size_t offset;
} ix_opt;

static const ix_opt ix_opts[] = {
    {"ix-min-angle", 0, 90u * 256u, offsetof(symline_intersection_config, min_angle_q8)},
    {"ix-gap", 0, 65536u, offsetof(symline_intersection_config, gap_q8)},
    {"ix-gap-pct", 0, 100u, offsetof(symline_intersection_config, gap_pct)},
    {"ix-arm", 256u, 65536u, offsetof(symline_intersection_config, arm_q8)},
    {"ix-merge", 0, 65536u, offsetof(symline_intersection_config, merge_q8)},
    {"ix-min-length", 0, 65535u << 8, offsetof(symline_intersection_config, min_length_q8)},
};
#define IX_OPTS (sizeof ix_opts / sizeof ix_opts[0])
#define IX_OPT_VAL 0x4900 /* getopt values of the intersection options: IX_OPT_VAL + index */
#define NO_IX_VAL 0x48FF  /* --no-intersections */

static void lines_usage(FILE *f, const char *cmd)
{
    const int ov = strcmp(cmd, "overlay") == 0;
    if (ov) {
        fprintf(f, "usage: symline overlay [options] [--json FILE] [-o OUT] IN [OUT]\n");
    } else {
        fprintf(f, "usage: symline lines [options] [-o FILE] IN...\n");
    }
    detopts_help(f);
    muffopts_help(f);
    if (ov) {
        fprintf(f, "  IN                  binary PGM, PNG or JPEG (colour becomes luma); - reads stdin\n"
                   "  OUT, -o OUT         the frame in colour with lines (solid red), curves\n"
                   "                      (dotted cyan) and intersections (a square with a spoke\n"
                   "                      per ray: L green, T orange, X magenta): .png, .ppm or\n"
                   "                      .pnm; - writes PPM to stdout\n"
                   "  --json FILE         also write the detection as JSON (keys: docs/format.md);\n"
                   "                      - is stdout\n");
    } else {
        fprintf(f, "  IN...               binary PGM, PNG or JPEG images (colour becomes luma), or\n"
                   "                      folders of them (name order; line masks *.mask.* are left\n"
                   "                      out); - reads stdin\n"
                   "  -o FILE             write the JSON there instead of stdout\n"
                   "Prints one JSON object per input (keys: docs/format.md); with several inputs\n"
                   "or a folder, each object starts with \"file\": its input.\n");
    }
    fprintf(f, "  --no-intersections  leave out where lines meet (JSON key \"intersections\")\n"
               "  --ix-min-angle Q8DEG, --ix-gap Q8PX, --ix-gap-pct PCT, --ix-arm Q8PX,\n"
               "  --ix-merge Q8PX, --ix-min-length Q8PX\n"
               "                      intersection settings (include/symline/intersections.h)\n");
    fprintf(f, "  --repeat N          run the detection N times (1..1000000; default 1) and\n"
               "                      print it once: (cost(N=11) - cost(N=1)) / 10 is one\n"
               "                      detection (tools/bench/icount.sh)\n"
               "Options take --opt VALUE or --opt=VALUE; -- ends the options.\n"
               "Exit status: 0 ok, 1 processing or write error, 2 usage or input error.\n");
}

/* 0 ok, 1 --help shown, CLI_USAGE on error. */
static int parse_lines_args(int argc, char **argv, lines_args *a, int overlay)
{
    struct option longopts[96];
    size_t n;
    int c;
    const char *out_opt = NULL;
    detopts d;
    char err[128];
    detopts_init(&d);
    memset(a, 0, sizeof *a);
    a->repeat = 1u;
    a->intersections = 1;
    symline_intersection_config_default(&a->icfg);
    muffopts_init(&a->method);
    n = detopts_longopts(longopts, 60);
    n += muffopts_longopts(longopts + n, 84u - n); /* room for 11 more and the end */
    longopts[n++] = (struct option){"no-intersections", no_argument, NULL, NO_IX_VAL};
    for (c = 0; c < (int)IX_OPTS; c++) {
        longopts[n++] = (struct option){ix_opts[c].name, required_argument, NULL, IX_OPT_VAL + c};
    }
    longopts[n++] = (struct option){"output", required_argument, NULL, 'o'};
    longopts[n++] = (struct option){"json", required_argument, NULL, 'j'};
    longopts[n++] = (struct option){"repeat", required_argument, NULL, 'R'};
    longopts[n++] = (struct option){"help", no_argument, NULL, 'h'};
    longopts[n] = (struct option){NULL, 0, NULL, 0};
    optind = 1;
    while ((c = cli_getopt(argc, argv, ":ho:", longopts)) != -1) {
        int rc;
        if (c == 'h') {
            lines_usage(stdout, argv[0]);
            return 1;
        } else if (c == 'o') {
            out_opt = optarg;
        } else if (c == 'R') {
            if (detopts_u32(optarg, 1u, 1000000u, &a->repeat) != 0) {
                return cli_error("%s: --repeat needs a number 1..1000000", argv[0]);
            }
        } else if (c == NO_IX_VAL) {
            a->intersections = 0;
        } else if (c >= IX_OPT_VAL && c < IX_OPT_VAL + (int)IX_OPTS) {
            const ix_opt *o = &ix_opts[c - IX_OPT_VAL];
            uint32_t v;
            if (detopts_u32(optarg, o->lo, o->hi, &v) != 0) {
                return cli_error("%s: --%s needs a number in %u..%u", argv[0], o->name, o->lo, o->hi);
            }
            memcpy((char *)&a->icfg + o->offset, &v, sizeof v);
        } else if (c == 'j' && overlay) {
            a->json = optarg;
        } else if (c == 'j') {
            return cli_error("lines: the JSON goes to stdout, or to -o FILE");
        } else if ((rc = muffopts_apply(&a->method, c, optarg, err, sizeof err)) != 0 ||
                   (rc = detopts_apply(&d, c, optarg, err, sizeof err)) != 0) {
            if (rc < 0) {
                return cli_error("%s: %s", argv[0], err);
            }
        } else {
            return CLI_USAGE;
        }
    }
    if (optind >= argc || (overlay && (argc - optind > 2 || (optind + 1 >= argc && out_opt == NULL)))) {
        lines_usage(stderr, argv[0]);
        return CLI_USAGE;
    }
    detopts_finish(&d);
    a->cfg = d.cfg;
    a->bin = d.bin;
    if (overlay) {
        if (cli_output_name(argv[0], optind + 1 < argc ? argv[optind + 1] : NULL, out_opt, &a->out) != 0 ||
            cli_inputs_add(&a->in, argv[0], argv[optind]) != 0) {
            cli_inputs_free(&a->in);
            return CLI_USAGE;
        }
        if (a->in.from_folder) {
            cli_inputs_free(&a->in);
            return cli_error("overlay: one image, not a folder");
        }
        return 0;
    }
    a->json = out_opt != NULL ? out_opt : "-";
    for (; optind < argc; optind++) {
        if (cli_inputs_add(&a->in, argv[0], argv[optind]) != 0) {
            cli_inputs_free(&a->in);
            return CLI_USAGE;
        }
    }
    return 0;
}

/* The detector's buffers, sized for the largest frame so far. */
typedef struct det_buffers {
    void *ws;
    size_t ws_size;
    uint8_t *half; /* the binned frame (--bin) */
    size_t half_size;
    symline_result res;
    symline_intersection items[256];
    symline_intersection_result ix; /* where the lines meet, unless left out */
} det_buffers;

/* The tracer (symline_detect) or the Muff-space finder with its accumulator. */
static symline_status run_method(const symline_config *cfg, const muffopts *method, const symline_image *view,
                                 void *ws, size_t ws_size, symline_result *res)
{
    size_t acc_size;
    uint16_t *acc;
    symline_status st;
    if (!method->muff) {
        return symline_detect(view, cfg, ws, ws_size, res);
    }
    acc_size = symline_muff_accumulator_size(view->width, view->height, &method->mc);
    acc = (uint16_t *)malloc(acc_size > 0u ? acc_size : 1u);
    if (acc == NULL) {
        return SYMLINE_ERR_BUFFER;
    }
    st = symline_detect_muff(view, cfg, &method->mc, acc, acc_size, ws, ws_size, res);
    free(acc);
    return st;
}

/* The detection of one frame (binned 2x2 first where `bin` says so, the
 * result moved back to the frame's coordinates), then (icfg not NULL) its
 * intersections. */
static int detect_one(const char *cmd, const imgio_gray *in, const symline_config *cfg, detopts_bin bin,
                      muffopts *method, uint32_t repeat, const symline_intersection_config *icfg,
                      det_buffers *b)
{
    uint32_t r;
    symline_image frame, view;
    symline_status st;
    size_t need;
    const int binned = detopts_bins(bin, in->width, in->height);
    const uint32_t vw = binned ? in->width / 2u : in->width, vh = binned ? in->height / 2u : in->height;
    method->mc.min_length = cfg->min_length;
    need = method->muff ? symline_detect_muff_workspace_size(vw, vh, cfg, &method->mc)
                        : symline_detect_workspace_size(vw, vh, cfg);
    const uint64_t pts = 2u * (uint64_t)in->width * in->height + 1024u;
    if (need == 0u) {
        return cli_error("%s: image size or configuration not supported", cmd);
    }
    if (need > b->ws_size) {
        free(b->ws);
        b->ws = malloc(need);
        b->ws_size = b->ws != NULL ? need : 0u;
    }
    if (pts > b->res.point_cap) {
        free(b->res.points);
        /* The byte size within 32 bits, so that it fits a 32-bit size_t too. */
        b->res.point_cap = pts > 0xFFFFFFFFu / sizeof(symline_point)
                               ? (uint32_t)(0xFFFFFFFFu / sizeof(symline_point))
                               : (uint32_t)pts;
        b->res.points = (symline_point *)malloc((size_t)b->res.point_cap * sizeof(symline_point));
    }
    if (b->res.segments == NULL) {
        b->res.segment_cap = 8192u;
        b->res.segments = (symline_segment *)malloc(b->res.segment_cap * sizeof(symline_segment));
    }
    if (binned && symline_bin2_size(in->width, in->height) > b->half_size) {
        free(b->half);
        b->half_size = symline_bin2_size(in->width, in->height);
        b->half = (uint8_t *)malloc(b->half_size);
    }
    if (b->ws == NULL || b->res.points == NULL || b->res.segments == NULL || (binned && b->half == NULL)) {
        cli_error("out of memory");
        return CLI_FAIL;
    }
    frame.width = in->width;
    frame.height = in->height;
    frame.stride = in->width;
    frame.data = in->px;
    view = frame;
    st = SYMLINE_OK;
    for (r = 0u; r < repeat && st == SYMLINE_OK; r++) {
        if (binned) {
            st = symline_bin2(&frame, b->half, b->half_size, &view);
        }
        if (st == SYMLINE_OK) {
            st = run_method(cfg, method, &view, b->ws, b->ws_size, &b->res);
        }
    }
    if (st == SYMLINE_OK && binned) {
        st = symline_result_unbin2(&b->res, in->width, in->height);
    }
    if (st == SYMLINE_OK && icfg != NULL) {
        b->ix.items = b->items;
        b->ix.cap = sizeof b->items / sizeof b->items[0];
        st = symline_intersections(&b->res, icfg, &b->ix);
    }
    if (st != SYMLINE_OK) {
        cli_error("%s: %s", cmd, symline_status_str(st));
        return CLI_FAIL;
    }
    return CLI_OK;
}

/* The JSON of one input into f; CLI_OK, or what cli_write_failed() says. */
static int write_json(FILE *f, const char *name, const char *file, const imgio_gray *in, const symline_result *r,
                      const symline_intersection_result *ix)
{
    errno = 0;
    if (segjson_write_named_ix(f, file, in->width, in->height, r, ix) != 0 || fflush(f) != 0) {
        return cli_write_failed(name);
    }
    return CLI_OK;
}

static int run_lines(int argc, char **argv, int overlay)
{
    lines_args a;
    det_buffers b;
    char err[512];
    FILE *json = NULL;
    const char *json_name = NULL;
    size_t i;
    int rc = parse_lines_args(argc, argv, &a, overlay);
    if (rc != 0) {
        return rc == 1 ? CLI_OK : rc;
    }
    if (overlay && imgio_check_output_name(a.out, 1, err, sizeof err) != 0) {
        cli_inputs_free(&a.in);
        return cli_error("%s", err);
    }
    if (overlay && a.json != NULL && strcmp(a.out, "-") == 0 && strcmp(a.json, "-") == 0) {
        cli_inputs_free(&a.in);
        return cli_error("overlay: the image and the JSON cannot both go to stdout");
    }
    if (a.json != NULL) {
        json_name = strcmp(a.json, "-") == 0 ? "stdout" : a.json;
        json = strcmp(a.json, "-") == 0 ? stdout : fopen(a.json, "w");
        if (json == NULL) {
            cli_error("%s: cannot create: %s", a.json, strerror(errno));
            cli_inputs_free(&a.in);
            return CLI_FAIL;
        }
    }
    memset(&b, 0, sizeof b);
    for (i = 0; i < a.in.count && rc == CLI_OK; i++) {
        imgio_gray in;
        const char *name = a.in.paths[i];
        /* With several inputs each object says which one it belongs to. */
        const char *file = (a.in.count > 1 || a.in.from_folder) ? name : NULL;
        if (imgio_read_gray(name, &in, err, sizeof err) != 0) {
            rc = cli_error("%s", err);
            break;
        }
        rc = detect_one(argv[0], &in, &a.cfg, a.bin, &a.method, a.repeat,
                        a.intersections ? &a.icfg : NULL, &b);
        if (rc == CLI_OK && json != NULL) {
            rc = write_json(json, json_name, file, &in, &b.res, a.intersections ? &b.ix : NULL);
            if (rc == CLI_OK && errno == EPIPE) {
                imgio_free(&in);
                break; /* closed pipe: stop quietly */
            }
        }
        errno = 0;
        if (rc == CLI_OK && overlay &&
            overlay_write_ix(a.out, in.px, in.width, in.height, in.width, &b.res,
                             a.intersections ? &b.ix : NULL, err, sizeof err) != 0) {
            rc = cli_image_write_failed(err);
        }
        imgio_free(&in);
    }
    if (json != NULL && json != stdout && fclose(json) != 0 && rc == CLI_OK) {
        rc = cli_write_failed(json_name);
    }
    free(b.ws);
    free(b.half);
    free(b.res.segments);
    free(b.res.points);
    cli_inputs_free(&a.in);
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

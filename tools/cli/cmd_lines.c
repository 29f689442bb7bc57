/*
 * `symline lines` and `symline overlay`: the line detector on one image.
 */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "../common/imgio.h"
#include "../common/overlay.h"
#include "../common/segjson.h"
#include "cli.h"
#include "symline/detect.h"

typedef struct lines_args {
    symline_config cfg;
    const char *in;
    const char *out;
} lines_args;

static void lines_usage(FILE *f, const char *cmd)
{
    fprintf(f,
            "usage: symline %s [options] IN%s\n"
            "  --axis horizontal|vertical|both   axes to run (default both)\n"
            "  --radius M          symmetry radius 1..32 (default 3)\n"
            "  --levels L          scales 1..5 (1 = full resolution only; default auto:\n"
            "                      enough 2x steps for lines width/16 px wide)\n"
            "  --filter contrast|paper   line filter (default contrast; 'paper' is the\n"
            "                      A1-S baseline and implies --illumination 100\n"
            "                      --adaptive 0)\n"
            "  --illumination G    minimum gray value of a line point, 0..255 (0 = off)\n"
            "  --adaptive 0|1      thresholds follow the frame's mean and sigma (1)\n"
            "  --bright-sigma B    adaptive: gray >= mean + (B-100)/10 sigma, 0..200 (100)\n"
            "  --ridge-sigma R     adaptive: ridge height >= R/10 sigma, 0..100 (10)\n"
            "  --side-sigma S      adaptive: both sides of a ridge <= mean + (S-100)/10\n"
            "                      sigma, 0..200; 200 = off (115)\n"
            "  --a-distance D      paper filter: A point within D px across the line\n"
            "  --contrast PCT      contrast filter: ridge height, %% of centre gray (0)\n"
            "  --contrast-min G    contrast filter: ridge height in gray levels (3)\n"
            "  --contrast-asym PCT contrast filter: ridge height >= PCT %% of |left - right|\n"
            "                      (rejects bands between two different surfaces; 150)\n"
            "  --min-length PX     shortest reported piece (12)\n"
            "  --curve-dev Q8      curve threshold on max_dev, 1/256 px (512 = 2 px)\n"
            "  --curve-bend Q8     also a curve: middle half this far off the chord\n"
            "                      against the outer quarters, 1/256 px at the pass's\n"
            "                      scale (80; 0 = off)\n"
            "  --merge-gap PX      merge collinear lines up to PX apart (default width/8,\n"
            "                      0 = no merging)\n"
            "  --merge-dev Q8      merge tolerance across the line, 1/256 px (640)\n"
            "  IN                  binary PGM or PNG (colour is converted to luma)\n"
            "%s"
            "Prints JSON (SPEC section 7) on stdout%s.\n"
            "Exit status: 0 ok, 1 processing error, 2 usage or input error.\n",
            cmd, strcmp(cmd, "overlay") == 0 ? " OUT.png" : "",
            strcmp(cmd, "overlay") == 0
                ? "  OUT.png             the frame in colour with lines (solid red) and curves\n"
                  "                      (dotted cyan); PPM unless the name ends in .png\n"
                : "",
            strcmp(cmd, "overlay") == 0 ? " as well" : "");
}

static int parse_u32_opt(int argc, char **argv, int *i, uint32_t lo, uint32_t hi, uint32_t *v)
{
    if (*i + 1 >= argc || cli_parse_u32(argv[*i + 1], lo, hi, v) != 0) {
        return cli_error("%s: %s needs an integer %u..%u", argv[0], argv[*i], lo, hi);
    }
    (*i)++;
    return 0;
}

/* 0 ok, 1 --help shown, CLI_USAGE on error. */
static int parse_lines_args(int argc, char **argv, lines_args *a, int npos_want)
{
    int i, npos = 0, have_illum = 0, have_adaptive = 0;
    const char *pos[2] = {NULL, NULL};
    symline_config *c = &a->cfg;
    symline_config_default(c);
    for (i = 1; i < argc; i++) {
        const char *o = argv[i];
        int rc = 0;
        if (strcmp(o, "--help") == 0 || strcmp(o, "-h") == 0) {
            lines_usage(stdout, argv[0]);
            return 1;
        } else if (strcmp(o, "--axis") == 0) {
            const char *v = i + 1 < argc ? argv[i + 1] : "";
            if (strcmp(v, "horizontal") == 0) {
                c->axes = SYMLINE_AXES_HORIZONTAL;
            } else if (strcmp(v, "vertical") == 0) {
                c->axes = SYMLINE_AXES_VERTICAL;
            } else if (strcmp(v, "both") == 0) {
                c->axes = SYMLINE_AXES_BOTH;
            } else {
                return cli_error("%s: --axis needs horizontal, vertical or both", argv[0]);
            }
            i++;
        } else if (strcmp(o, "--filter") == 0) {
            const char *v = i + 1 < argc ? argv[i + 1] : "";
            if (strcmp(v, "contrast") == 0) {
                c->filter = SYMLINE_FILTER_CONTRAST;
            } else if (strcmp(v, "paper") == 0) {
                c->filter = SYMLINE_FILTER_PAPER;
            } else {
                return cli_error("%s: --filter needs contrast or paper", argv[0]);
            }
            i++;
        } else if (strcmp(o, "--radius") == 0) {
            rc = parse_u32_opt(argc, argv, &i, 1, 32, &c->radius);
        } else if (strcmp(o, "--levels") == 0) {
            rc = parse_u32_opt(argc, argv, &i, 1, 5, &c->levels);
        } else if (strcmp(o, "--illumination") == 0) {
            rc = parse_u32_opt(argc, argv, &i, 0, 255, &c->illumination);
            have_illum = 1;
        } else if (strcmp(o, "--adaptive") == 0) {
            rc = parse_u32_opt(argc, argv, &i, 0, 1, &c->adaptive);
            have_adaptive = 1;
        } else if (strcmp(o, "--bright-sigma") == 0) {
            uint32_t v;
            rc = parse_u32_opt(argc, argv, &i, 0, 200, &v);
            c->bright_sigma10 = (int32_t)v - 100;
        } else if (strcmp(o, "--side-sigma") == 0) {
            uint32_t v;
            rc = parse_u32_opt(argc, argv, &i, 0, 200, &v);
            c->side_sigma10 = (int32_t)v - 100;
        } else if (strcmp(o, "--ridge-sigma") == 0) {
            rc = parse_u32_opt(argc, argv, &i, 0, 100, &c->ridge_sigma10);
        } else if (strcmp(o, "--a-distance") == 0) {
            rc = parse_u32_opt(argc, argv, &i, 1, 32, &c->a_distance);
        } else if (strcmp(o, "--contrast") == 0) {
            rc = parse_u32_opt(argc, argv, &i, 0, 100, &c->contrast_pct);
        } else if (strcmp(o, "--contrast-min") == 0) {
            rc = parse_u32_opt(argc, argv, &i, 0, 255, &c->contrast_min);
        } else if (strcmp(o, "--contrast-asym") == 0) {
            rc = parse_u32_opt(argc, argv, &i, 0, 1000, &c->contrast_asym_pct);
        } else if (strcmp(o, "--min-length") == 0) {
            rc = parse_u32_opt(argc, argv, &i, 0, 65535, &c->min_length);
        } else if (strcmp(o, "--curve-dev") == 0) {
            rc = parse_u32_opt(argc, argv, &i, 0, 65535u << 8, &c->curve_dev_q8);
        } else if (strcmp(o, "--curve-bend") == 0) {
            rc = parse_u32_opt(argc, argv, &i, 0, 65535u << 8, &c->curve_bend_q8);
        } else if (strcmp(o, "--merge-gap") == 0) {
            rc = parse_u32_opt(argc, argv, &i, 0, 65535, &c->merge_gap);
        } else if (strcmp(o, "--merge-dev") == 0) {
            rc = parse_u32_opt(argc, argv, &i, 0, 65535u << 8, &c->merge_dev_q8);
        } else if (o[0] == '-' && o[1] != '\0') {
            return cli_error("%s: unknown option '%s'", argv[0], o);
        } else if (npos < npos_want) {
            pos[npos++] = o;
        } else {
            return cli_error("%s: too many arguments ('%s')", argv[0], o);
        }
        if (rc != 0) {
            return rc;
        }
    }
    if (npos != npos_want) {
        lines_usage(stderr, argv[0]);
        return CLI_USAGE;
    }
    if (c->filter == SYMLINE_FILTER_PAPER && !have_illum) {
        c->illumination = 100u;
    }
    if (c->filter == SYMLINE_FILTER_PAPER && !have_adaptive) {
        c->adaptive = 0u;
    }
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
        st = symline_detect(&view, &a.cfg, ws, ws_size, &res);
        if (st != SYMLINE_OK) {
            cli_error("%s: %s", argv[0], symline_status_str(st));
            rc = CLI_FAIL;
        } else if (segjson_write(stdout, in.width, in.height, &res) != 0) {
            rc = CLI_FAIL;
        } else if (overlay && overlay_write(a.out, in.px, in.width, in.height, in.width, &res,
                                            err, sizeof err) != 0) {
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

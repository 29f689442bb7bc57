/* SPDX-License-Identifier: Apache-2.0 */
/*
 * `symline symmetry` and `symline extrema`: the operator and its extrema as images.
 */
#include <errno.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "detopts.h"
#include "imgio.h"
#include "cli.h"
#include "symline/extrema.h"
#include "symline/symmetry.h"

typedef struct op_args {
    symline_axis axis;
    uint32_t radius;
    const char *in;
    const char *out;
} op_args;

static void op_usage(FILE *f, const char *cmd)
{
    fprintf(f,
            "usage: symline %s --axis horizontal|vertical --radius M [-o OUT] IN [OUT]\n"
            "  --axis    horizontal: symmetry along columns (near-horizontal lines);\n"
            "            vertical: symmetry along rows (near-vertical lines)\n"
            "  --radius  symmetry radius M, 1..255\n"
            "  IN        binary PGM (P5, maxval 255), PNG or JPEG; - reads stdin\n"
            "  OUT, -o OUT  the %s;\n"
            "            format by the name: .pgm, .png, .ppm, .pnm; - writes PGM to stdout\n"
            "Options take --opt VALUE or --opt=VALUE; -- ends the options.\n",
            cmd,
            strcmp(cmd, "symmetry") == 0 ? "8-bit symmetry image (255 = perfect mirror symmetry)"
                                         : "extrema map (0 nothing, 128 A point, 255 S point)");
}

/* 0 ok, 1 --help shown, CLI_USAGE on error. */
static int parse_op_args(int argc, char **argv, op_args *a)
{
    static const struct option longopts[] = {
        {"axis", required_argument, NULL, 'a'},   {"radius", required_argument, NULL, 'r'},
        {"output", required_argument, NULL, 'o'}, {"help", no_argument, NULL, 'h'},
        {NULL, 0, NULL, 0}};
    int c, have_axis = 0, have_radius = 0;
    const char *out_opt = NULL;
    optind = 1;
    while ((c = cli_getopt(argc, argv, ":ho:", longopts)) != -1) {
        switch (c) {
        case 'h':
            op_usage(stdout, argv[0]);
            return 1;
        case 'a':
            if (cli_parse_axis(optarg, &a->axis) != 0) {
                return cli_error("%s: --axis needs 'horizontal' or 'vertical'", argv[0]);
            }
            have_axis = 1;
            break;
        case 'r':
            if (detopts_u32(optarg, 1, 255, &a->radius) != 0) {
                return cli_error("%s: --radius needs an integer 1..255", argv[0]);
            }
            have_radius = 1;
            break;
        case 'o':
            out_opt = optarg;
            break;
        default:
            return CLI_USAGE;
        }
    }
    if (!have_axis || !have_radius || optind >= argc || argc - optind > 2 ||
        (optind + 1 >= argc && out_opt == NULL)) {
        op_usage(stderr, argv[0]);
        return CLI_USAGE;
    }
    a->in = argv[optind];
    if (cli_output_name(argv[0], optind + 1 < argc ? argv[optind + 1] : NULL, out_opt, &a->out) != 0) {
        return CLI_USAGE;
    }
    return 0;
}

static int run_op(int argc, char **argv, int extrema)
{
    op_args a;
    imgio_gray in;
    symline_image view;
    char err[512];
    uint8_t *out;
    void *ws;
    size_t ws_size;
    symline_status st;
    int rc = parse_op_args(argc, argv, &a);
    if (rc != 0) {
        return rc == 1 ? CLI_OK : rc;
    }
    if (imgio_check_output_name(a.out, 0, err, sizeof err) != 0) {
        return cli_error("%s", err);
    }
    if (imgio_read_gray(a.in, &in, err, sizeof err) != 0) {
        return cli_error("%s", err);
    }
    view.width = in.width;
    view.height = in.height;
    view.stride = in.width;
    view.data = in.px;
    ws_size = extrema ? symline_extrema_workspace_size(in.width, in.height, a.axis, a.radius)
                      : symline_symmetry_workspace_size(in.width, in.height, a.axis, a.radius);
    ws = malloc(ws_size);
    out = (uint8_t *)malloc((size_t)in.width * in.height);
    if (ws == NULL || out == NULL) {
        free(ws);
        free(out);
        imgio_free(&in);
        cli_error("%s: out of memory", a.in);
        return CLI_FAIL;
    }
    st = extrema ? symline_extrema(&view, a.axis, a.radius, out, in.width,
                                   (size_t)in.width * in.height, ws, ws_size)
                 : symline_symmetry(&view, a.axis, a.radius, out, in.width,
                                    (size_t)in.width * in.height, ws, ws_size);
    rc = CLI_OK;
    errno = 0;
    if (st != SYMLINE_OK) {
        cli_error("%s: %s", a.in, symline_status_str(st));
        rc = CLI_FAIL;
    } else if (imgio_write_gray(a.out, out, in.width, in.height, in.width, err, sizeof err) != 0) {
        rc = cli_image_write_failed(err);
    }
    free(ws);
    free(out);
    imgio_free(&in);
    return rc;
}

int cmd_symmetry(int argc, char **argv)
{
    return run_op(argc, argv, 0);
}

int cmd_extrema(int argc, char **argv)
{
    return run_op(argc, argv, 1);
}

/* `symline convert IN OUT`: between PGM, PNG and JPEG input (colour becomes luma). */
int cmd_convert(int argc, char **argv)
{
    static const struct option longopts[] = {
        {"output", required_argument, NULL, 'o'}, {"help", no_argument, NULL, 'h'}, {NULL, 0, NULL, 0}};
    imgio_gray in;
    char err[512];
    const char *out_opt = NULL, *out;
    int c, rc = CLI_OK;
    optind = 1;
    while ((c = cli_getopt(argc, argv, ":ho:", longopts)) != -1) {
        if (c == 'h') {
            printf("usage: symline convert [-o OUT] IN [OUT]\n"
                   "  reads a PGM (P5), PNG or JPEG (- = stdin) and writes it as 8-bit gray;\n"
                   "  the format by OUT's name: .pgm, .png, .ppm, .pnm; - writes PGM to stdout\n");
            return CLI_OK;
        }
        if (c == 'o') {
            out_opt = optarg;
        } else {
            return CLI_USAGE;
        }
    }
    if (optind >= argc || argc - optind > 2) {
        return cli_error("convert: usage: symline convert [-o OUT] IN [OUT]");
    }
    if (cli_output_name(argv[0], optind + 1 < argc ? argv[optind + 1] : NULL, out_opt, &out) != 0) {
        return CLI_USAGE;
    }
    if (imgio_check_output_name(out, 0, err, sizeof err) != 0) {
        return cli_error("%s", err);
    }
    if (imgio_read_gray(argv[optind], &in, err, sizeof err) != 0) {
        return cli_error("%s", err);
    }
    errno = 0;
    if (imgio_write_gray(out, in.px, in.width, in.height, in.width, err, sizeof err) != 0) {
        rc = cli_image_write_failed(err);
    }
    imgio_free(&in);
    return rc;
}

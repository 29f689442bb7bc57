/*
 * `symline symmetry` and `symline extrema`: the operator and its extrema as images.
 */
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
            "usage: symline %s --axis horizontal|vertical --radius M IN OUT\n"
            "  --axis    horizontal: symmetry along columns (near-horizontal lines);\n"
            "            vertical: symmetry along rows (near-vertical lines)\n"
            "  --radius  symmetry radius M, 1..255\n"
            "  IN        binary PGM (P5, maxval 255) or PNG\n"
            "  OUT       %s; PNG if the name ends in .png, else PGM\n",
            cmd,
            strcmp(cmd, "symmetry") == 0 ? "8-bit symmetry image (255 = perfect mirror symmetry)"
                                         : "extrema map (0 nothing, 128 A point, 255 S point)");
}

/* 0 ok, 1 --help shown, CLI_USAGE on error. */
static int parse_op_args(int argc, char **argv, op_args *a)
{
    int i, have_axis = 0, have_radius = 0, npos = 0;
    const char *pos[2] = {NULL, NULL};
    for (i = 1; i < argc; i++) {
        if (strcmp(argv[i], "--help") == 0 || strcmp(argv[i], "-h") == 0) {
            op_usage(stdout, argv[0]);
            return 1;
        } else if (strcmp(argv[i], "--axis") == 0) {
            if (i + 1 >= argc || cli_parse_axis(argv[i + 1], &a->axis) != 0) {
                return cli_error("%s: --axis needs 'horizontal' or 'vertical'", argv[0]);
            }
            have_axis = 1;
            i++;
        } else if (strcmp(argv[i], "--radius") == 0) {
            if (i + 1 >= argc || detopts_u32(argv[i + 1], 1, 255, &a->radius) != 0) {
                return cli_error("%s: --radius needs an integer 1..255", argv[0]);
            }
            have_radius = 1;
            i++;
        } else if (argv[i][0] == '-' && argv[i][1] != '\0') {
            return cli_error("%s: unknown option '%s'", argv[0], argv[i]);
        } else if (npos < 2) {
            pos[npos++] = argv[i];
        } else {
            return cli_error("%s: too many arguments ('%s')", argv[0], argv[i]);
        }
    }
    if (!have_axis || !have_radius || npos != 2) {
        op_usage(stderr, argv[0]);
        return CLI_USAGE;
    }
    a->in = pos[0];
    a->out = pos[1];
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
    if (st != SYMLINE_OK) {
        cli_error("%s: %s", a.in, symline_status_str(st));
        rc = CLI_FAIL;
    } else if (imgio_write_gray(a.out, out, in.width, in.height, in.width, err, sizeof err) != 0) {
        cli_error("%s", err);
        rc = CLI_FAIL;
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

/* `symline convert IN OUT`: PGM <-> PNG (colour PNG input becomes luma). */
int cmd_convert(int argc, char **argv)
{
    imgio_gray in;
    char err[512];
    int rc = CLI_OK;
    if (argc == 2 && (strcmp(argv[1], "--help") == 0 || strcmp(argv[1], "-h") == 0)) {
        printf("usage: symline convert IN OUT\n"
               "  reads a PGM (P5) or PNG, writes 8-bit gray PNG (OUT ends in .png) or PGM\n");
        return CLI_OK;
    }
    if (argc != 3) {
        return cli_error("convert: usage: symline convert IN OUT");
    }
    if (imgio_read_gray(argv[1], &in, err, sizeof err) != 0) {
        return cli_error("%s", err);
    }
    if (imgio_write_gray(argv[2], in.px, in.width, in.height, in.width, err, sizeof err) != 0) {
        cli_error("%s", err);
        rc = CLI_FAIL;
    }
    imgio_free(&in);
    return rc;
}

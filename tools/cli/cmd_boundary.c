/*
 * `symline boundary`: the field boundary alone (include/symline/field.h).
 */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "../common/detopts.h"
#include "../common/imgio.h"
#include "../common/overlay.h"
#include "cli.h"
#include "symline/detect.h"
#include "symline/field.h"

static void boundary_usage(FILE *f)
{
    symline_field_config fc;
    symline_field_config_default(&fc);
    fprintf(f,
            "usage: symline boundary [--cell N] [--miss-cost N] IN [OUT.png]\n"
            "  --cell N        grid step in px, a power of two 2..64 (default: auto,\n"
            "                  about width/64)\n"
            "  --miss-cost N   score of a non-carpet cell in the column scan, 1..16\n"
            "                  (default %u)\n"
            "  IN              binary PGM or PNG (colour is converted to luma)\n"
            "  OUT.png         the frame with the boundary drawn in yellow\n"
            "Prints {\"width\": W, \"height\": H, \"cell\": N, \"carpet_mean\": G,\n"
            "\"field_boundary\": [[x, y], ...]} (SPEC section 7): rows at and below the\n"
            "polyline are field.\n"
            "Exit status: 0 ok, 1 processing error, 2 usage or input error.\n",
            fc.miss_cost);
}

int cmd_boundary(int argc, char **argv)
{
    symline_field_config fc;
    const char *pos[2] = {NULL, NULL};
    int i, npos = 0, rc = CLI_OK;
    imgio_gray in;
    symline_image view;
    symline_result res;
    char err[512];
    size_t need;
    void *ws;
    symline_status st;
    symline_field_config_default(&fc);
    for (i = 1; i < argc; i++) {
        const char *o = argv[i];
        if (strcmp(o, "--help") == 0 || strcmp(o, "-h") == 0) {
            boundary_usage(stdout);
            return CLI_OK;
        }
        if (strcmp(o, "--cell") == 0 || strcmp(o, "--miss-cost") == 0) {
            const int cell = strcmp(o, "--cell") == 0;
            if (i + 1 >= argc ||
                detopts_u32(argv[i + 1], cell ? 2u : 1u, cell ? 64u : 16u,
                            cell ? &fc.cell : &fc.miss_cost) != 0) {
                return cli_error("%s: %s needs a number in %s", argv[0], o,
                                 cell ? "2..64" : "1..16");
            }
            i++;
        } else if (o[0] == '-' && o[1] != '\0') {
            return cli_error("%s: unknown option '%s'", argv[0], o);
        } else if (npos < 2) {
            pos[npos++] = o;
        } else {
            return cli_error("%s: too many arguments ('%s')", argv[0], o);
        }
    }
    if (npos < 1) {
        boundary_usage(stderr);
        return CLI_USAGE;
    }
    if (imgio_read_gray(pos[0], &in, err, sizeof err) != 0) {
        return cli_error("%s", err);
    }
    view.width = in.width;
    view.height = in.height;
    view.stride = in.width;
    view.data = in.px;
    need = symline_field_workspace_size(in.width, in.height, &fc);
    if (need == 0u) {
        imgio_free(&in);
        return cli_error("%s: --cell must be a power of two", argv[0]);
    }
    memset(&res, 0, sizeof res);
    ws = malloc(need);
    if (ws == NULL) {
        imgio_free(&in);
        return cli_error("out of memory");
    }
    st = symline_field_find(&view, &fc, ws, need, &res.field);
    if (st != SYMLINE_OK) {
        cli_error("%s: %s", argv[0], symline_status_str(st));
        rc = CLI_FAIL;
    } else {
        uint32_t k;
        printf("{\"width\": %u, \"height\": %u, \"cell\": %u, \"carpet_mean\": %u,\n"
               " \"field_boundary\": [",
               in.width, in.height, res.field.cell, res.field.carpet_mean);
        for (k = 0; k < res.field.count; k++) {
            printf("%s[%ld, %ld]", k == 0u ? "" : ", ", (long)res.field.v[k].x,
                   (long)res.field.v[k].y);
        }
        printf("]}\n");
        if (fflush(stdout) != 0 || ferror(stdout)) {
            rc = CLI_FAIL;
        } else if (npos == 2 && overlay_write(pos[1], in.px, in.width, in.height, in.width,
                                              &res, err, sizeof err) != 0) {
            cli_error("%s", err);
            rc = CLI_FAIL;
        }
    }
    free(ws);
    imgio_free(&in);
    return rc;
}

/* SPDX-License-Identifier: Apache-2.0 */
/*
 * `symline boundary`: the field boundary alone (include/symline/field.h).
 */
#include <stddef.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "detopts.h"
#include "imgio.h"
#include "overlay.h"
#include "cli.h"
#include "symline/binning.h"
#include "symline/detect.h"
#include "symline/field.h"

/* The settings of symline/field.h as options. */
typedef struct fb_opt {
    const char *name;
    size_t off;
    uint32_t lo, hi;
    const char *help;
} fb_opt;

#define FB_OFF(f) offsetof(symline_field_config, f)
static const fb_opt FB_OPTS[] = {
    {"--cell", FB_OFF(cell), 0u, 64u, "grid step px, a power of two 2..64; 0 = auto (8 or 16)"},
    {"--band-pct", FB_OFF(band_pct), 1u, 100u, "carpet model from the lowest % of the rows"},
    {"--mean-tol", FB_OFF(mean_tol), 0u, 255u, "gray distance of a carpet cell to the model"},
    {"--local-tol", FB_OFF(local_tol), 0u, 255u, "... or to its column's running carpet mean"},
    {"--tex-lo-pct", FB_OFF(tex_lo_pct), 0u, 100u, "smallest texture, % of the model's"},
    {"--tex-hi-pct", FB_OFF(tex_hi_pct), 100u, 10000u, "largest texture, % of the model's"},
    {"--miss-cost", FB_OFF(miss_cost), 1u, 16u, "penalty of a non-carpet cell in the column scan"},
    {"--gap-pct", FB_OFF(gap_pct), 0u, 100u, "a column ends after this % of rows without carpet"},
    {"--support", FB_OFF(support), 1u, 8u, "columns nearby that must reach as high"},
    {"--edge-slope-pct", FB_OFF(edge_slope_pct), 0u, 10000u, "steepest fall of the end segments"},
    {"--col-cells", FB_OFF(col_cells), 1u, 4u, "grid columns lie this many cells apart"},
    {"--restore-cells", FB_OFF(restore_cells), 0u, 64u,
     "own tops count up to this many cells higher"},
};
#define FB_NOPTS (sizeof FB_OPTS / sizeof FB_OPTS[0])

static uint32_t *fb_field(symline_field_config *fc, size_t off)
{
    return (uint32_t *)(void *)((char *)fc + off);
}

static void boundary_usage(FILE *f)
{
    symline_field_config fc;
    size_t i;
    symline_field_config_default(&fc);
    fprintf(f, "usage: symline boundary [options] IN [OUT.png]\n");
    for (i = 0; i < FB_NOPTS; i++) {
        fprintf(f, "  %-14s N  %s (default %u)\n", FB_OPTS[i].name, FB_OPTS[i].help,
                *fb_field(&fc, FB_OPTS[i].off));
    }
    fprintf(f, "  --bin auto|off|on  find it at half size, each pixel the mean of a 2x2\n"
               "                    block, vertices in the frame's pixels; auto: frames of\n"
               "                    786432 pixels (1024x768) or more, as symline lines does\n"
               "                    (default)\n"
               "  IN                binary PGM or PNG (colour is converted to luma)\n"
               "  OUT.png           the frame with the boundary drawn in yellow\n"
               "Prints {\"width\": W, \"height\": H, \"cell\": N, \"carpet_mean\": G,\n"
               "\"field_boundary\": [[x, y], ...]} (docs/format.md): rows at and below the\n"
               "polyline are field. See include/symline/field.h for the settings.\n"
               "Exit status: 0 ok, 1 processing error, 2 usage or input error.\n");
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
    uint8_t *buf = NULL;
    symline_status st;
    detopts_bin bin = DETOPTS_BIN_AUTO;
    symline_field_config_default(&fc);
    {
        /* getopt_long over the table: --opt N and --opt=N, -- ends the options. */
        struct option longopts[FB_NOPTS + 3];
        int c;
        size_t k;
        for (k = 0; k < FB_NOPTS; k++) {
            longopts[k].name = FB_OPTS[k].name + 2;
            longopts[k].has_arg = required_argument;
            longopts[k].flag = NULL;
            longopts[k].val = 0x100 + (int)k;
        }
        longopts[FB_NOPTS] = (struct option){"help", no_argument, NULL, 'h'};
        longopts[FB_NOPTS + 1] = (struct option){"bin", required_argument, NULL, 'b'};
        longopts[FB_NOPTS + 2] = (struct option){NULL, 0, NULL, 0};
        optind = 1;
        while ((c = cli_getopt(argc, argv, ":h", longopts)) != -1) {
            if (c == 'h') {
                boundary_usage(stdout);
                return CLI_OK;
            }
            if (c == 'b') {
                if (detopts_bin_parse(optarg, &bin) != 0) {
                    return cli_error("%s: --bin needs auto, off or on", argv[0]);
                }
                continue;
            }
            if (c < 0x100 || c >= 0x100 + (int)FB_NOPTS) {
                return CLI_USAGE;
            }
            k = (size_t)(c - 0x100);
            if (detopts_u32(optarg, FB_OPTS[k].lo, FB_OPTS[k].hi, fb_field(&fc, FB_OPTS[k].off)) != 0) {
                return cli_error("%s: %s needs a number in %u..%u", argv[0], FB_OPTS[k].name, FB_OPTS[k].lo,
                                 FB_OPTS[k].hi);
            }
        }
        for (i = optind; i < argc; i++) {
            if (npos >= 2) {
                return cli_error("%s: too many arguments ('%s')", argv[0], argv[i]);
            }
            pos[npos++] = argv[i];
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
    if (detopts_bins(bin, in.width, in.height)) {
        /* As `symline lines`: found on the binned frame, moved back into the
         * frame's pixels, so both report the same boundary. */
        const symline_image frame = view;
        const size_t half = symline_bin2_size(in.width, in.height);
        buf = malloc(half);
        if (buf == NULL) {
            imgio_free(&in);
            return cli_error("out of memory");
        }
        st = symline_bin2(&frame, buf, half, &view);
        if (st != SYMLINE_OK) {
            cli_error("%s: %s", argv[0], symline_status_str(st));
            free(buf);
            imgio_free(&in);
            return CLI_FAIL;
        }
    }
    need = symline_field_workspace_size(view.width, view.height, &fc);
    if (need == 0u) {
        free(buf);
        imgio_free(&in);
        return cli_error("%s: --cell must be a power of two", argv[0]);
    }
    memset(&res, 0, sizeof res);
    ws = malloc(need);
    if (ws == NULL) {
        free(buf);
        imgio_free(&in);
        return cli_error("out of memory");
    }
    st = symline_field_find(&view, &fc, ws, need, &res.field);
    if (st == SYMLINE_OK && buf != NULL) {
        st = symline_result_unbin2(&res, in.width, in.height);
    }
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
        } else if (npos == 2 && overlay_write(pos[1], in.px, in.width, in.height, in.width, &res,
                                              err, sizeof err) != 0) {
            cli_error("%s", err);
            rc = CLI_FAIL;
        }
    }
    free(ws);
    free(buf);
    imgio_free(&in);
    return rc;
}

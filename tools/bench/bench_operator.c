/* SPDX-License-Identifier: Apache-2.0 */
/*
 * symline-bench-operator — runs the operator or the extrema over a frame a
 * number of times, for instruction counting under callgrind (see
 * tools/bench/operator.sh). Prints nothing but a checksum, so the work
 * cannot be optimised away.
 *
 *   symline-bench-operator symmetry|extrema horizontal|vertical M REPEAT IN
 */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "hostopts.h"
#include "imgio.h"
#include "symline/extrema.h"
#include "symline/symmetry.h"

#define PROG "symline-bench-operator"

int main(int argc, char **argv)
{
    imgio_gray in;
    symline_image img;
    char err[512];
    int extrema, rep, r;
    symline_axis axis;
    unsigned m;
    size_t ws_size, i;
    void *ws;
    uint8_t *out;
    unsigned long sum = 0;
    long v;
    r = hostopts_plain(argc, argv, PROG,
                       "usage: symline-bench-operator symmetry|extrema horizontal|vertical M REPEAT IN\n"
                       "Runs the operator (or the extrema) with radius M REPEAT times over IN and\n"
                       "prints a checksum (for instruction counts under callgrind).\n",
                       5);
    if (r >= 0) {
        return r;
    }
    argv += optind - 1; /* argv[1..5]: the arguments */
    if ((strcmp(argv[1], "symmetry") != 0 && strcmp(argv[1], "extrema") != 0) ||
        (strcmp(argv[2], "horizontal") != 0 && strcmp(argv[2], "vertical") != 0)) {
        return hostopts_usage_error(PROG, PROG, "needs symmetry|extrema horizontal|vertical");
    }
    extrema = strcmp(argv[1], "extrema") == 0;
    axis = strcmp(argv[2], "vertical") == 0 ? SYMLINE_AXIS_VERTICAL : SYMLINE_AXIS_HORIZONTAL;
    if (hostopts_long(argv[3], 1, 255, &v) != 0) {
        return hostopts_usage_error(PROG, PROG, "M must be 1..255");
    }
    m = (unsigned)v;
    if (hostopts_long(argv[4], 1, 1000000, &v) != 0) {
        return hostopts_usage_error(PROG, PROG, "REPEAT must be 1..1000000");
    }
    rep = (int)v;
    if (imgio_read_gray(argv[5], &in, err, sizeof err) != 0) {
        fprintf(stderr, "%s\n", err);
        return 2;
    }
    img.width = in.width;
    img.height = in.height;
    img.stride = in.width;
    img.data = in.px;
    ws_size = extrema ? symline_extrema_workspace_size(in.width, in.height, axis, m)
                      : symline_symmetry_workspace_size(in.width, in.height, axis, m);
    ws = malloc(ws_size);
    out = malloc((size_t)in.width * in.height);
    for (r = 0; r < rep; r++) {
        symline_status st =
            extrema ? symline_extrema(&img, axis, m, out, in.width, (size_t)in.width * in.height, ws, ws_size)
                    : symline_symmetry(&img, axis, m, out, in.width, (size_t)in.width * in.height, ws, ws_size);
        if (st != SYMLINE_OK) {
            fprintf(stderr, "%s\n", symline_status_str(st));
            return 1;
        }
        for (i = 0; i < (size_t)in.width * in.height; i += 97) {
            sum += out[i];
        }
    }
    printf("%lu\n", sum);
    free(ws);
    free(out);
    imgio_free(&in);
    return 0;
}

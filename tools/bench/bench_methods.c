/* SPDX-License-Identifier: Apache-2.0 */
/*
 * symline-bench-methods — the tracer (symline_detect) and the Muff-space
 * finder (symline_detect_muff) at default settings on one frame: time per
 * frame, working memory, line points and segments. For instruction counts
 * run it under callgrind (tools/eval/methods.sh does both).
 *
 *   symline-bench-methods tracer|muff REPEAT IN
 *
 * Prints one line of key=value pairs:
 *   method, width, height, repeat, ns_per_frame (mean wall-clock time of the
 *   detection call alone, CLOCK_MONOTONIC), workspace (bytes of ws), accumulator
 *   (bytes, Muff only), line_points (the line filter's points of the frame),
 *   kept_points (points referenced by the segments), segments.
 */
#define _POSIX_C_SOURCE 200809L
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>

#include "hostopts.h"
#include "imgio.h"
#include "symline/detect.h"
#include "symline/muff.h"

static double now_ns(void)
{
    struct timespec t;
    clock_gettime(CLOCK_MONOTONIC, &t);
    return (double)t.tv_sec * 1e9 + (double)t.tv_nsec;
}

#define PROG "symline-bench-methods"

int main(int argc, char **argv)
{
    imgio_gray in;
    symline_image img;
    symline_config cfg;
    symline_muff_config mc;
    symline_result res;
    char err[512];
    int muff, rep, r;
    size_t ws_size, acc_size = 0u;
    void *ws, *lws;
    uint16_t *acc = NULL;
    uint32_t nlp = 0u;
    bool cut = false;
    double t0, t1;
    long v;
    r = hostopts_plain(argc, argv, PROG,
                       "usage: symline-bench-methods tracer|muff REPEAT IN\n"
                       "Times REPEAT detections of IN by the tracer or the Muff-space finder at\n"
                       "default settings; prints method, width, height, repeat, ns_per_frame,\n"
                       "workspace, accumulator, line_points, kept_points, segments.\n",
                       3);
    if (r >= 0) {
        return r;
    }
    argv += optind - 1; /* argv[1..3]: the arguments */
    if (strcmp(argv[1], "tracer") != 0 && strcmp(argv[1], "muff") != 0) {
        return hostopts_usage_error(PROG, PROG, "the method is tracer or muff");
    }
    muff = strcmp(argv[1], "muff") == 0;
    if (hostopts_long(argv[2], 1, 1000000, &v) != 0) {
        return hostopts_usage_error(PROG, PROG, "REPEAT must be 1..1000000");
    }
    rep = (int)v;
    if (imgio_read_gray(argv[3], &in, err, sizeof err) != 0) {
        fprintf(stderr, "%s\n", err);
        return 2;
    }
    img.width = in.width;
    img.height = in.height;
    img.stride = in.width;
    img.data = in.px;
    symline_config_default(&cfg);
    symline_muff_config_default(&mc);
    mc.min_length = cfg.min_length;
    ws_size = muff ? symline_detect_muff_workspace_size(in.width, in.height, &cfg, &mc)
                   : symline_detect_workspace_size(in.width, in.height, &cfg);
    if (muff) {
        acc_size = symline_muff_accumulator_size(in.width, in.height, &mc);
        acc = (uint16_t *)malloc(acc_size);
    }
    memset(&res, 0, sizeof res);
    res.segment_cap = 4096u;
    res.point_cap = 2u * in.width * in.height + 1024u;
    res.segments = (symline_segment *)malloc(res.segment_cap * sizeof(symline_segment));
    res.points = (symline_point *)malloc((size_t)res.point_cap * sizeof(symline_point));
    ws = malloc(ws_size);
    if (ws == NULL || res.segments == NULL || res.points == NULL || (muff && acc == NULL)) {
        fprintf(stderr, "out of memory\n");
        return 1;
    }
    t0 = now_ns();
    for (r = 0; r < rep; r++) {
        const symline_status st =
            muff ? symline_detect_muff(&img, &cfg, &mc, acc, acc_size, ws, ws_size, &res)
                 : symline_detect(&img, &cfg, ws, ws_size, &res);
        if (st != SYMLINE_OK) {
            fprintf(stderr, "%s\n", symline_status_str(st));
            return 1;
        }
    }
    t1 = now_ns();
    /* the line filter's output alone, for the point storage either method needs */
    lws = malloc(symline_detect_workspace_size(in.width, in.height, &cfg));
    if (lws != NULL) {
        (void)symline_line_points(&img, &cfg, lws,
                                  symline_detect_workspace_size(in.width, in.height, &cfg),
                                  res.points, res.point_cap, &nlp, &cut);
    }
    printf("method=%s width=%u height=%u repeat=%d ns_per_frame=%.0f workspace=%zu "
           "accumulator=%zu line_points=%u kept_points=%u segments=%u\n",
           argv[1], in.width, in.height, rep, (t1 - t0) / rep, ws_size, acc_size, nlp,
           res.point_count, res.segment_count);
    free(lws);
    free(ws);
    free(acc);
    free(res.segments);
    free(res.points);
    imgio_free(&in);
    return 0;
}

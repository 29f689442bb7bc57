/* SPDX-License-Identifier: Apache-2.0 */
/*
 * The capture loop: frames from a source (source.h), the line detector on
 * each, one JSON record per frame on stdout, rate and latency summaries on
 * stderr, optional frame records and overlay snapshots. The front end
 * (tools/capture/) parses the command line, opens the source and owns the
 * signal handlers.
 */
#ifndef SYMLINE_CAPTURE_LOOP_H
#define SYMLINE_CAPTURE_LOOP_H

#include <signal.h>
#include <stdint.h>

#include "source.h"
#include "symline/detect.h"

typedef struct caploop_options {
    uint64_t frames;           /* 0 = until stopped or the source ends */
    int timeout_ms;            /* wait for one frame; < 0 = forever */
    uint32_t summary_s;        /* seconds between summaries on stderr; 0 = final one only */
    uint32_t snapshot_every;   /* overlay of every K-th frame into snapshot_dir; 0 = none */
    const char *snapshot_dir;  /* must exist */
    uint32_t record_every;     /* every K-th frame as PGM into record_dir; 0 = none */
    const char *record_dir;    /* must exist */
    int profile;               /* 1: time per detector stage in each record and the final
                                  summary (needs stageprof_available()) */
    uint32_t repeat;           /* detections per frame, >= 1 (a load test: the records hold
                                  one detection's output and the time of all of them) */
    const symline_config *cfg; /* detector settings */
    int bin;                   /* detopts_bin (hostio/detopts.h): 2x2 binning before the
                                  detection, results in the frame's coordinates */
} caploop_options;

/*
 * Starts src and runs until the source ends, o->frames frames were handled,
 * *stop_signal becomes nonzero (the number of the signal that asked to
 * stop) or an error; then prints the final summary. src stays open (the
 * caller closes it). Returns 0, or -1 after an error (reported on stderr).
 */
int caploop_run(capsrc *src, const caploop_options *o, const volatile sig_atomic_t *stop_signal);

#endif

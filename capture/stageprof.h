/* SPDX-License-Identifier: Apache-2.0 */
/*
 * Time per detector stage for the capture loop, from the stage marks of the
 * profiled core (symline/profile.h). The loop is linked with that core when
 * the build has it (STAGEPROF_AVAILABLE); the marks then cost one call and a
 * test per stage change, and read the clock only while profiling is on.
 * One detection at a time (the marks go to one global record).
 */
#ifndef SYMLINE_CAPTURE_STAGEPROF_H
#define SYMLINE_CAPTURE_STAGEPROF_H

#include <stdint.h>

#include "symline/profile.h"

/* 1 when this build's detector reports its stages, else 0. */
int stageprof_available(void);

/* Starts timing the next detection: per-stage totals back to 0, the clock read. */
void stageprof_begin(void);

/* Stops timing; ns[k] = time spent in stage k since stageprof_begin()
 * (ns[SYMLINE_STAGE_NONE] is time outside the detector's stages). */
void stageprof_end(int64_t ns[SYMLINE_STAGE_COUNT]);

/* The stage's name as the JSON records and summaries print it ("operator"). */
const char *stageprof_name(symline_stage stage);

#endif

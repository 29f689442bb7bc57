/* SPDX-License-Identifier: Apache-2.0 */
/*
 * Stage timing (stageprof.h): the application's side of symline/profile.h.
 */
#define _POSIX_C_SOURCE 200809L
#include "stageprof.h"

#include <string.h>
#include <time.h>

static int g_on;            /* marks are ignored unless timing */
static symline_stage g_cur; /* stage running since the last mark */
static int64_t g_t0;        /* clock at the last mark */
static int64_t g_ns[SYMLINE_STAGE_COUNT];

static int64_t now_ns(void)
{
    struct timespec ts;
    clock_gettime(CLOCK_MONOTONIC, &ts);
    return (int64_t)ts.tv_sec * 1000000000 + ts.tv_nsec;
}

/* Called by the profiled core at every change of stage; never by the plain one. */
void symline_profile_mark(symline_stage stage)
{
    int64_t t;
    if (!g_on) {
        return;
    }
    t = now_ns();
    g_ns[g_cur] += t - g_t0;
    g_t0 = t;
    g_cur = (unsigned)stage < SYMLINE_STAGE_COUNT ? stage : SYMLINE_STAGE_NONE;
}

int stageprof_available(void)
{
#ifdef STAGEPROF_AVAILABLE
    return 1;
#else
    return 0;
#endif
}

void stageprof_begin(void)
{
    memset(g_ns, 0, sizeof g_ns);
    g_cur = SYMLINE_STAGE_NONE;
    g_on = 1;
    g_t0 = now_ns();
}

void stageprof_end(int64_t ns[SYMLINE_STAGE_COUNT])
{
    symline_profile_mark(SYMLINE_STAGE_NONE);
    g_on = 0;
    memcpy(ns, g_ns, sizeof g_ns);
}

const char *stageprof_name(symline_stage stage)
{
#ifdef STAGEPROF_AVAILABLE
    return symline_stage_name(stage);
#else
    (void)stage;
    return "?";
#endif
}

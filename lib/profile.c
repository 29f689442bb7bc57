/* SPDX-License-Identifier: Apache-2.0 */
/*
 * Stage names for profiling (include/symline/profile.h), built into the
 * profiled library only, so that the plain core carries no profiling code. The
 * marks themselves are the SL_STAGE() macro of stagemark.h, empty unless
 * SYMLINE_PROFILE is set.
 */
#include "symline/profile.h"

const char *symline_stage_name(symline_stage stage)
{
    static const char *const names[SYMLINE_STAGE_COUNT] = {
        "none",   "setup", "field",    "stats",    "grid",  "operator", "extrema",
        "filter", "trace", "segments", "subpixel", "merge", "curvejoin"};
    return (unsigned)stage < (unsigned)SYMLINE_STAGE_COUNT ? names[stage] : "?";
}

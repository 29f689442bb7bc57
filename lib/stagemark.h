/* SPDX-License-Identifier: Apache-2.0 */
/*
 * SL_STAGE(s): the detection moves on to stage s (include/symline/profile.h).
 * A call of the application's symline_profile_mark() in a library built with
 * SYMLINE_PROFILE, nothing at all otherwise.
 */
#ifndef SYMLINE_STAGEMARK_H
#define SYMLINE_STAGEMARK_H

#include "symline/profile.h"

#ifdef SYMLINE_PROFILE
#define SL_STAGE(s) symline_profile_mark(SYMLINE_STAGE_##s)
#else
#define SL_STAGE(s) ((void)0)
#endif

#endif /* SYMLINE_STAGEMARK_H */

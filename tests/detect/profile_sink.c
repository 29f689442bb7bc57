/* SPDX-License-Identifier: Apache-2.0 */
/*
 * The stage-mark receiver the golden test needs when it is linked with the
 * profiled core (detect_golden_profiled): it ignores the marks, so the test
 * sees only what the marks could change, the output.
 */
#include "symline/profile.h"

void symline_profile_mark(symline_stage stage)
{
    (void)stage;
}

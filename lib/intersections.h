/* SPDX-License-Identifier: Apache-2.0 */
/*
 * Intersections stage (intersections.c): the integer helpers it shares with
 * its tests. Not part of the public API.
 */
#ifndef SYMLINE_LIB_INTERSECTIONS_H
#define SYMLINE_LIB_INTERSECTIONS_H

#include <stdint.h>

#include "symline/intersections.h"

/* Direction of the vector (dx, dy) in Q8 degrees, [0, 360*256): 0 along +x,
 * 90*256 along +y; within 0.01 degree. (0, 0) gives 0. */
uint32_t symline_i_heading_q8(int32_t dx, int32_t dy);

#endif /* SYMLINE_LIB_INTERSECTIONS_H */

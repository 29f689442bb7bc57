/* SPDX-License-Identifier: Apache-2.0 */
/*
 * Curve continuation (curvejoin.c): a line piece that continues a curve
 * smoothly becomes part of that curve.
 */
#ifndef SYMLINE_LIB_CURVEJOIN_H
#define SYMLINE_LIB_CURVEJOIN_H

#include "common.h"
#include "symline/detect.h"

/* Line segments of r that continue a curve smoothly (ends within 3 px,
 * directions within 30 degrees) become curves; merged lines stay lines. */
void symline_i_curve_join(symline_result *r);

#endif /* SYMLINE_LIB_CURVEJOIN_H */

/* SPDX-License-Identifier: Apache-2.0 */
/*
 * Tests that only a painted line on the field passes.
 */
#include "linecheck.h"

/* A piece found at a coarse scale (2x and more) must lie at least this share
 * (Q8) of the field's height below the boundary: a quarter. Measured on the
 * annotated real frames (docs/detector.md): legs, robots and goal posts just
 * below the boundary go, the painted lines there are found at full
 * resolution. */
#define SL_WIDE_REL_Q8 64u

SL_NOINLINE bool symline_i_linecheck_too_wide(const uint16_t *rows, uint32_t level, uint32_t h,
                                              const symline_point *q, uint32_t n)
{
    /* At most 256 points summed: 16-bit coordinates keep the sums in 32 bits. */
    const uint32_t step = n / 256u + 1u;
    uint32_t i, sx = 0u, sy = 0u, cnt = 0u, top;
    if (level == 0u || n == 0u) {
        return false;
    }
    for (i = 0; i < n; i += step, cnt++) {
        sx += q[i].x;
        sy += q[i].y;
    }
    sx /= cnt;
    sy /= cnt;
    top = rows[sx] < h ? rows[sx] : h;
    /* A boundary at the top of the frame says nothing of the distance: the
     * field may reach far beyond the image. */
    if (top == 0u) {
        return false;
    }
    return sy < top || (sy - top) * 256u < SL_WIDE_REL_Q8 * (h - top);
}

/*
 * Sub-pixel position of line points across the line (private to the core).
 *
 * A line point is an S point: the middle pixel of a run of equal symmetry
 * energy E that is smaller than both neighbours. A line an even number of
 * pixels wide has its ridge between two pixels, and a line at any sub-pixel
 * position has its energy minimum between pixels, so the pixel alone is up to
 * half a pixel (of the pass's grid) off the line's middle. The offset is
 * taken from E around the point: the exact middle of an equal-E run, else the
 * vertex of the parabola through E at the point and its two neighbours
 * across the line (E sums squared differences, so it is close to a parabola
 * around its minimum). Offsets are stored in the points' fx / fy fields in
 * 1/128 px of the grid they are in.
 */
#ifndef SYMLINE_SUBPIXEL_H
#define SYMLINE_SUBPIXEL_H

#include "detect_internal.h"

/*
 * Sets fx, fy of the pass's grid points q[0..n-1]: the offset across the line
 * (fx for the vertical axis, fy for the horizontal one) in 1/128 grid px,
 * -64..64, the other 0. Reads the frame (box means at coarse levels, as the
 * pass computed them); points at the grid's border get offset 0.
 */
void sl_subpixel(const symline_image *img, const sl_pass *p, symline_point *q, uint32_t n);

/* Q8 full-resolution x (y) of point q of a grid at `level`: the block centre
 * plus the point's offset (1/128 grid px). */
static inline int32_t sl_pt_q8x(const symline_point *q, uint32_t level)
{
    return sl_q8(q->x, level) + (int32_t)q->fx * (int32_t)(2u << level);
}

static inline int32_t sl_pt_q8y(const symline_point *q, uint32_t level)
{
    return sl_q8(q->y, level) + (int32_t)q->fy * (int32_t)(2u << level);
}

/* Makes grid point q at `level` a full-resolution point: the nearest pixel and
 * the remainder (1/128 px, -64..63). */
static inline void sl_pt_to_full(symline_point *q, uint32_t level)
{
    /* Q7 full-resolution coordinates: half the Q8 ones (always even). */
    const int32_t x7 = sl_pt_q8x(q, level) / 2, y7 = sl_pt_q8y(q, level) / 2;
    const int32_t x = (x7 + 64) >> 7, y = (y7 + 64) >> 7;
    q->x = (uint16_t)x;
    q->y = (uint16_t)y;
    q->fx = (int8_t)(x7 - x * 128);
    q->fy = (int8_t)(y7 - y * 128);
}

#endif /* SYMLINE_SUBPIXEL_H */

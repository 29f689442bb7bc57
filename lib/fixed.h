/* SPDX-License-Identifier: Apache-2.0 */
/*
 * Fixed-point helpers of the detector (fixed.c): Q8 pixel coordinates, the
 * scale grids' block geometry, the position of a point with its sub-pixel
 * offset, an integer square root and a 32-bit Q8 division. No floating point anywhere in the core.
 */
#ifndef SYMLINE_LIB_FIXED_H
#define SYMLINE_LIB_FIXED_H

#include "common.h"
#include "symline/detect.h"

/* Q8: 1/256 px. A pixel centre is a multiple of SL_Q8_ONE. */
#define SL_Q8_SHIFT 8u
#define SL_Q8_ONE 256u
/* n whole pixels in Q8 (n an unsigned constant). */
#define SL_PX_Q8(n) ((n) << SL_Q8_SHIFT)

/* What symline_i_div_q8() returns for a zero length (no quotient). */
#define SL_Q8_NO_QUOTIENT UINT32_MAX

/* A grid block at `level` is 2^level px wide; its centre lies
 * (2^level - 1) / 2 px after its first pixel's centre: that offset in Q8. */
static inline uint32_t symline_i_block_half_q8(uint32_t level)
{
    return ((1u << level) - 1u) << (SL_Q8_SHIFT - 1u);
}

/* (2^level - 1) px in Q8: what a position at `level` may be off by. */
static inline uint32_t symline_i_block_q8(uint32_t level)
{
    return ((1u << level) - 1u) << SL_Q8_SHIFT;
}

/* Q8 full-resolution coordinate of grid coordinate v at a level (block centre). */
static inline int32_t symline_i_q8(uint32_t v, uint32_t level)
{
    return (int32_t)(((v << level) << SL_Q8_SHIFT) + symline_i_block_half_q8(level));
}

/* Q8 full-resolution x (y) of point q of a grid at `level`: the block centre
 * plus the point's sub-pixel offset fx (fy), 1/128 px of that grid
 * (subpixel.c sets it; 0 for points never refined). */
static inline int32_t symline_i_pt_q8x(const symline_point *q, uint32_t level)
{
    return symline_i_q8(q->x, level) + (int32_t)q->fx * (int32_t)(2u << level);
}

static inline int32_t symline_i_pt_q8y(const symline_point *q, uint32_t level)
{
    return symline_i_q8(q->y, level) + (int32_t)q->fy * (int32_t)(2u << level);
}

/* (*x, *y) = the Q8 full-resolution position of grid point q at `level`
 * minus the origin (o[0], o[1]) (Q8; NULL: (0, 0)). Out of line: one copy
 * for the stages that need both. */
void symline_i_pt_off(const symline_point *q, uint32_t level, const int32_t *o, int32_t *x,
                      int32_t *y);

/* Makes grid point q at `level` a full-resolution point: the nearest pixel
 * and the remainder, 1/128 px in -64..63 (the public symline_point). What
 * the stages call: inline where the build optimises for speed (every kept
 * point), else the one copy in fixed.c. */
static inline void symline_i_pt_to_full_here(symline_point *q, uint32_t level)
{
    int32_t x8, y8, x7, y7, x, y;
    if (SL_FOR_SPEED) {
        x8 = symline_i_pt_q8x(q, level);
        y8 = symline_i_pt_q8y(q, level);
    } else {
        symline_i_pt_off(q, level, NULL, &x8, &y8);
    }
    /* Q7 full-resolution coordinates: half the Q8 ones (always even). */
    x7 = x8 >> 1;
    y7 = y8 >> 1;
    x = (x7 + 64) >> 7;
    y = (y7 + 64) >> 7;
    q->x = (uint16_t)x;
    q->y = (uint16_t)y;
    q->fx = (int8_t)(x7 - x * 128);
    q->fy = (int8_t)(y7 - y * 128);
}
#if SL_FOR_SPEED
#define symline_i_pt_to_full symline_i_pt_to_full_here
#else
void symline_i_pt_to_full(symline_point *q, uint32_t level);
#endif

/* floor(sqrt(v)), bit by bit (no multiply, no division). */
uint64_t symline_i_isqrt64(uint64_t v);

/* cross / len with a 32-bit division: both are shifted right alike until
 * cross fits 32 bits. SL_Q8_NO_QUOTIENT when len is 0. */
uint32_t symline_i_div_q8(uint64_t cross, uint64_t len);

#endif /* SYMLINE_LIB_FIXED_H */

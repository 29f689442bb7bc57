/*
 * Fixed-point helpers of the detector (fixed.c): Q8 pixel coordinates, the
 * scale grids' block geometry, an integer square root and a 32-bit Q8
 * division. No floating point anywhere in the core.
 */
#ifndef SYMLINE_LIB_FIXED_H
#define SYMLINE_LIB_FIXED_H

#include "common.h"

/* Q8: 1/256 px. A pixel centre is a multiple of SL_Q8_ONE. */
#define SL_Q8_SHIFT 8u
#define SL_Q8_ONE 256u
/* n whole pixels in Q8 (n an unsigned constant). */
#define SL_PX_Q8(n) ((n) * SL_Q8_ONE)

/* What sl_div_q8() returns for a zero length (no quotient). */
#define SL_Q8_NO_QUOTIENT UINT32_MAX

/* A grid block at `level` is 2^level px wide; its centre lies
 * (2^level - 1) / 2 px after its first pixel's centre: that offset in Q8. */
static inline uint32_t sl_block_half_q8(uint32_t level)
{
    return ((1u << level) - 1u) << (SL_Q8_SHIFT - 1u);
}

/* (2^level - 1) px in Q8: what a position at `level` may be off by. */
static inline uint32_t sl_block_q8(uint32_t level)
{
    return ((1u << level) - 1u) << SL_Q8_SHIFT;
}

/* Q8 full-resolution coordinate of grid coordinate v at a level (block centre). */
static inline int32_t sl_q8(uint32_t v, uint32_t level)
{
    return (int32_t)(((v << level) << SL_Q8_SHIFT) + sl_block_half_q8(level));
}

/* floor(sqrt(v)), bit by bit (no multiply, no division). */
uint64_t sl_isqrt64(uint64_t v);

/* cross / len with a 32-bit division: both are shifted right alike until
 * cross fits 32 bits. SL_Q8_NO_QUOTIENT when len is 0. */
uint32_t sl_div_q8(uint64_t cross, uint64_t len);

#endif /* SYMLINE_LIB_FIXED_H */

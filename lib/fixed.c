/* SPDX-License-Identifier: Apache-2.0 */
/*
 * Fixed-point helpers (fixed.h).
 */
#include "fixed.h"

uint64_t symline_i_isqrt64(uint64_t v)
{
    uint64_t r = 0u, bit = (uint64_t)1u << 62;
    /* While bit > v the loop below only shifts bit (r stays 0): where the
     * build optimises for speed it starts at the largest power of 4 not
     * above v, found at once from v's highest bit. */
#if SL_FOR_SPEED
#if defined(__GNUC__)
    if (v != 0u) {
        bit = (uint64_t)1u << ((63u - (uint32_t)__builtin_clzll(v)) & ~1u);
    }
#endif
    while (bit > v) {
        bit >>= 2;
    }
#endif
    while (bit != 0u) {
        if (v >= r + bit) {
            v -= r + bit;
            r = (r >> 1) + bit;
        } else {
            r >>= 1;
        }
        bit >>= 2;
    }
    return r;
}

uint32_t symline_i_div_q8(uint64_t cross, uint64_t len)
{
    /* A 32-bit division (no 64-bit division helper on small cores): drop the
     * same low bits of both; the quotient keeps well under 1/256 px of error
     * for any chord longer than a pixel. */
    while (cross > UINT32_MAX) {
        cross >>= 1;
        len >>= 1;
    }
    if (len == 0u) {
        return SL_Q8_NO_QUOTIENT;
    }
    return (uint32_t)cross / (uint32_t)len;
}

void symline_i_pt_off(const symline_point *q, uint32_t level, const int32_t *o, int32_t *x,
                      int32_t *y)
{
    *x = symline_i_pt_q8x(q, level) - (o != NULL ? o[0] : 0);
    *y = symline_i_pt_q8y(q, level) - (o != NULL ? o[1] : 0);
}

#if !SL_FOR_SPEED /* fixed.h: inline where the build optimises for speed */
void symline_i_pt_to_full(symline_point *q, uint32_t level)
{
    symline_i_pt_to_full_here(q, level);
}
#endif

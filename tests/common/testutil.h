/* SPDX-License-Identifier: Apache-2.0 */
/*
 * Small helpers shared by the host tests (may allocate; tests are host code).
 */
#ifndef SYMLINE_TESTUTIL_H
#define SYMLINE_TESTUTIL_H

#include <stddef.h>
#include <stdint.h>

#include "symline/detect.h"
#include "symline/types.h"

/* Deterministic pseudo-random numbers (xorshift32); state must be non-zero. */
static inline uint32_t tu_rand(uint32_t *s)
{
    uint32_t x = *s;
    x ^= x << 13;
    x ^= x >> 17;
    x ^= x << 5;
    *s = x;
    return x;
}

/*
 * A buffer with guard bytes on both sides, to catch writes outside what a
 * call was given. tu_guard_alloc() returns the usable pointer; tu_guard_ok()
 * checks that no guard byte changed.
 */
#define TU_GUARD 64u
#define TU_GUARD_BYTE 0xA5u
uint8_t *tu_guard_alloc(size_t n);
int tu_guard_ok(const uint8_t *p, size_t n);
void tu_guard_free(uint8_t *p);

/*
 * symline_detect() of img with cfg into r (its outputs set by the caller), in
 * a guarded workspace of exactly the queried size: the status, and in
 * *guards_ok whether no byte around the workspace was written (a size query
 * of 0 gives SYMLINE_ERR_BUFFER without a call).
 */
symline_status tu_detect_guarded(const symline_image *img, const symline_config *cfg,
                                 symline_result *r, int *guards_ok);

/* Direct-from-the-formula energy of index i of a sequence (used as an oracle). */
uint32_t tu_energy_direct(const uint8_t *q, size_t step, uint32_t n, uint32_t i, uint32_t m);

#endif

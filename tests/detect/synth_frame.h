/* SPDX-License-Identifier: Apache-2.0 */
/*
 * A synthetic field frame for the detector tests: noise on a gray carpet,
 * lines 2, 9 and 3 px wide (one slanted), a vertical line, a ring and a
 * saturated block (long plateaus). Deterministic.
 */
#ifndef SYMLINE_TEST_SYNTH_FRAME_H
#define SYMLINE_TEST_SYNTH_FRAME_H

#include <stdint.h>

/* A w x h frame with `stride` bytes per row; free() it. */
uint8_t *synth_frame(uint32_t w, uint32_t h, uint32_t stride);

#endif

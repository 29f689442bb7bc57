/* SPDX-License-Identifier: Apache-2.0 */
/*
 * A 64-bit tick counter from SysTick (24-bit, processor clock, wraps counted
 * in the SysTick interrupt). Under `qemu -icount shift=0` every instruction
 * advances virtual time by 1 ns, so ticks measure instructions; the ratio is
 * calibrated at run time on a loop of known length (see bench.c).
 */
#ifndef SYMLINE_SYSTICK_H
#define SYMLINE_SYSTICK_H

#include <stdint.h>

void systick_start(void);
uint64_t systick_now(void);

#endif /* SYMLINE_SYSTICK_H */

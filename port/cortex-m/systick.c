/* SPDX-License-Identifier: Apache-2.0 */
/* SysTick as a free-running 64-bit counter (see systick.h). */
#include "systick.h"

#define SYST_CSR (*(volatile uint32_t *)0xE000E010u)
#define SYST_RVR (*(volatile uint32_t *)0xE000E014u)
#define SYST_CVR (*(volatile uint32_t *)0xE000E018u)

#define RELOAD 0x00FFFFFFu

static volatile uint32_t wraps;

void SysTick_Handler(void)
{
    wraps++;
}

void systick_start(void)
{
    SYST_CSR = 0u;
    SYST_RVR = RELOAD;
    SYST_CVR = 0u;
    wraps = 0u;
    /* processor clock, interrupt on wrap, enable */
    SYST_CSR = 7u;
    /* The current value reads 0 until the first clock loads RELOAD. */
    while (SYST_CVR == 0u) {
    }
}

uint64_t systick_now(void)
{
    uint32_t w, v;
    /* Re-read when a wrap happened between the two reads. */
    do {
        w = wraps;
        v = SYST_CVR;
    } while (w != wraps);
    return (uint64_t)w * (RELOAD + 1u) + (RELOAD - v);
}

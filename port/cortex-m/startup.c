/* SPDX-License-Identifier: Apache-2.0 */
/*
 * Minimal Cortex-M start-up for the mps2-an386 examples and target tests:
 * vector table, FPU enable, and fault handlers that end the program with a
 * non-zero semihosting exit so a crash fails CI instead of hanging qemu.
 * newlib's _start (rdimon.specs) then clears .bss, opens the semihosting
 * stdio and calls main(); exit(N) becomes qemu's exit status.
 */
#include <stdint.h>

extern uint32_t __stack_top;
extern void _start(void);

void Reset_Handler(void);
void Default_Handler(void);
void NMI_Handler(void) __attribute__((weak, alias("Default_Handler")));
void HardFault_Handler(void) __attribute__((weak, alias("Default_Handler")));
void MemManage_Handler(void) __attribute__((weak, alias("Default_Handler")));
void BusFault_Handler(void) __attribute__((weak, alias("Default_Handler")));
void UsageFault_Handler(void) __attribute__((weak, alias("Default_Handler")));
void SVC_Handler(void) __attribute__((weak, alias("Default_Handler")));
void DebugMon_Handler(void) __attribute__((weak, alias("Default_Handler")));
void PendSV_Handler(void) __attribute__((weak, alias("Default_Handler")));
void SysTick_Handler(void) __attribute__((weak, alias("Default_Handler")));

__attribute__((section(".vectors"), used)) static void (*const vectors[16])(void) = {
    (void (*)(void))(uintptr_t)&__stack_top,
    Reset_Handler,
    NMI_Handler,
    HardFault_Handler,
    MemManage_Handler,
    BusFault_Handler,
    UsageFault_Handler,
    0,
    0,
    0,
    0,
    SVC_Handler,
    DebugMon_Handler,
    0,
    PendSV_Handler,
    SysTick_Handler,
};

/* Semihosting call (operation in r0, argument in r1), usable from handler mode. */
static void semihost(uint32_t op, const void *arg)
{
    register uint32_t r0 __asm__("r0") = op;
    register const void *r1 __asm__("r1") = arg;
    __asm__ volatile("bkpt 0xab" : "+r"(r0) : "r"(r1) : "memory");
}

void Default_Handler(void)
{
    /* SYS_WRITE0, then SYS_EXIT with ADP_Stopped_RunTimeErrorUnknown: qemu exits 1. */
    semihost(0x04u, "symline firmware: unexpected exception (fault), stopping\n");
    for (;;) {
        semihost(0x18u, (const void *)(uintptr_t)0x20024u);
    }
}

void Reset_Handler(void)
{
#if defined(__ARM_FP)
    /* Full access to CP10/CP11 before the first FPU instruction (newlib's may use it). */
    volatile uint32_t *const cpacr = (volatile uint32_t *)0xE000ED88u;
    *cpacr |= 0xFu << 20;
    __asm__ volatile("dsb\n\tisb" ::: "memory");
#endif
    _start();
    Default_Handler();
}

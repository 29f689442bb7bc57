/* SPDX-License-Identifier: Apache-2.0 */
/*
 * A program that crashes on purpose (permanently undefined instruction): the
 * start-up's fault handler must turn this into a non-zero exit of qemu, so a
 * crash in a target test fails CI instead of hanging it.
 */
#include <stdio.h>

int main(void)
{
    printf("symline firmware: executing an undefined instruction\n");
    __asm__ volatile("udf #0");
    printf("symline firmware: still running after the fault\n");
    return 0;
}

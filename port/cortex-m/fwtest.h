/* SPDX-License-Identifier: Apache-2.0 */
/*
 * Checks for programs that run on the target: a failed check is printed over
 * semihosting and counted; fw_test_end() exits 1 when any check failed, so
 * qemu's exit status fails CI.
 */
#ifndef SYMLINE_FWTEST_H
#define SYMLINE_FWTEST_H

#include <stdio.h>
#include <stdlib.h>

extern unsigned fw_checks, fw_failures;

#define FW_CHECK(cond, ...)                                          \
    do {                                                             \
        fw_checks++;                                                 \
        if (!(cond)) {                                               \
            fw_failures++;                                           \
            printf("FAIL %s:%d: %s: ", __FILE__, __LINE__, #cond);   \
            printf(__VA_ARGS__);                                     \
            printf("\n");                                            \
        }                                                            \
    } while (0)

static inline int fw_test_end(const char *name)
{
    printf("%s: %u checks, %u failed\n", name, fw_checks, fw_failures);
    exit(fw_failures == 0u ? 0 : 1);
}

#endif /* SYMLINE_FWTEST_H */

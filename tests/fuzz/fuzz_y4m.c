/* SPDX-License-Identifier: Apache-2.0 */
/*
 * Fuzz target: the YUV4MPEG2 reader of the capture app (y4m_open_stream,
 * y4m_read, y4m_rewind) on an in-memory stream: every frame it returns is
 * whole, a bad header or a short frame is an error.
 */
#define _POSIX_C_SOURCE 200809L
#include <stdint.h>
#include <stdio.h>
#include <string.h>

#include "imgio.h"
#include "y4m_reader.h"

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size);

/* Keeps the pixel reads (ASan checks each) from being optimised away. */
volatile uint32_t sink;

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
    char err[256];
    y4m_reader *r;
    FILE *f;
    int pass, frames = 0;
    if (size == 0) {
        return 0;
    }
    imgio_set_max_pixels(1u << 20);
    f = fmemopen((void *)(uintptr_t)data, size, "rb");
    if (f == NULL) {
        return 0;
    }
    r = y4m_open_stream(f, "fuzz.y4m", err, sizeof err);
    if (r == NULL) {
        return 0;
    }
    if (y4m_width(r) == 0 || y4m_height(r) == 0 ||
        (uint64_t)y4m_width(r) * y4m_height(r) > (1u << 20)) {
        __builtin_trap();
    }
    /* Twice through the stream: the replay loop rewinds. */
    for (pass = 0; pass < 2; pass++) {
        const uint8_t *luma;
        int got;
        while (frames < 64 && (got = y4m_read(r, &luma, err, sizeof err)) == 1) {
            uint32_t sum = 0;
            size_t i;
            for (i = 0; i < (size_t)y4m_width(r) * y4m_height(r); i++) {
                sum += luma[i];
            }
            sink = sum;
            frames++;
        }
        if (y4m_rewind(r) != 0) {
            break;
        }
    }
    y4m_close(r);
    return 0;
}

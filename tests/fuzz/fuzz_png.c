/* SPDX-License-Identifier: Apache-2.0 */
/*
 * Fuzz target: the PNG (and PGM) reader of the host tools by signature
 * (imgio_parse_image). Damaged, truncated and oversized PNGs give an error
 * message; nothing leaks after libpng's longjmp; the pixel limit holds.
 */
#include <stdint.h>
#include <string.h>

#include "imgio.h"

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size);

/* Keeps the pixel reads (ASan checks each) from being optimised away. */
volatile uint32_t sink;

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
    imgio_gray img;
    char err[256];
    imgio_set_max_pixels(1u << 20);
    if (imgio_parse_image(data, size, "fuzz.png", &img, err, sizeof err) == 0) {
        uint32_t sum = 0;
        size_t i;
        if ((uint64_t)img.width * img.height > (1u << 20)) {
            __builtin_trap(); /* the pixel limit was not applied */
        }
        for (i = 0; i < (size_t)img.width * img.height; i++) {
            sum += img.px[i];
        }
        sink = sum;
        imgio_free(&img);
    } else if (err[0] == '\0') {
        __builtin_trap();
    }
    return 0;
}

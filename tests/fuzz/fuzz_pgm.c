/* SPDX-License-Identifier: Apache-2.0 */
/*
 * Fuzz target: the PGM reader of the host tools (imgio_parse_pgm). Any input
 * gives an image or an error message, never a crash, leak or overread.
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
    if (imgio_parse_pgm(data, size, "fuzz.pgm", &img, err, sizeof err) == 0) {
        /* Every pixel was copied: touch them all. */
        uint32_t sum = 0;
        size_t i;
        for (i = 0; i < (size_t)img.width * img.height; i++) {
            sum += img.px[i];
        }
        sink = sum;
        imgio_free(&img);
    } else if (memchr(err, '\0', sizeof err) == NULL || err[0] == '\0') {
        __builtin_trap(); /* an error must come with a message */
    }
    return 0;
}

/* SPDX-License-Identifier: Apache-2.0 */
/*
 * Fuzz target: the JPEG reader of the host tools. The input, its first three
 * bytes set to a JPEG's signature, goes to imgio_parse_image() with an error
 * buffer of fuzzer-chosen length, then to the decoder underneath (jpeg_luma,
 * also the V4L2 source's Motion-JPEG path): its size, a decode with the wrong size
 * (must fail and leave the pixels alone), then one into rows of a
 * fuzzer-chosen stride, twice on one decoder (it is reused frame after
 * frame, also after a failure).
 * Checks: an accepted image within the pixel limit with every pixel readable;
 * an error with a message, the error text NUL-terminated within its buffer
 * and nothing written past it (guard bytes); the decoded rows' guard bytes
 * untouched, the bytes between rows too, both decodes equal, and the same
 * pixels as imgio_parse_image(). libjpeg-turbo itself is not instrumented:
 * the dictionary tests/fuzz/jpeg.dict (its markers) stands in for coverage.
 */
#include <stdint.h>
#include <stdlib.h>
#include <string.h>

#include "fuzz_util.h"
#include "imgio.h"
#include "jpeg_luma.h"

int LLVMFuzzerTestOneInput(const uint8_t *in, size_t size);

#define MAX_PX (1u << 20)

/* Keeps the pixel reads (ASan checks each) from being optimised away. */
volatile uint32_t sink;

static void check_err(const uint8_t *err, size_t errlen, const char *what)
{
    fz_check_guard(err, errlen, what);
    if (memchr(err, '\0', errlen) == NULL || (errlen > 1u && err[0] == '\0')) {
        fprintf(stderr, "%s: no message, or not NUL-terminated\n", what);
        abort();
    }
}

int LLVMFuzzerTestOneInput(const uint8_t *in, size_t size)
{
    /* The last byte picks the error buffer's length and the stride (not
     * part of the image, so the seeds decode as they are). */
    const uint32_t knob = size > 0u ? in[size - 1u] : 0u;
    const size_t errlen = (knob & 3u) == 0u ? 1u + knob % 24u : 256u;
    uint8_t *err = fz_buf(errlen, 0);
    imgio_gray img;
    uint8_t *ref = NULL;
    uint32_t rw = 0u, rh = 0u;
    char jerr[128];
    jpeg_luma *d;
    uint32_t w, h;
    uint8_t *data;

    /* Always a JPEG by its signature (the other readers have their own
     * targets): the first three bytes set to FF D8 FF, in a copy of the
     * input's exact size. */
    if (size < 3u) {
        free(err);
        return 0;
    }
    data = (uint8_t *)malloc(size);
    if (data == NULL) {
        abort();
    }
    memcpy(data, in, size);
    data[0] = 0xFFu;
    data[1] = 0xD8u;
    data[2] = 0xFFu;
    imgio_set_max_pixels(MAX_PX);
    if (imgio_parse_image(data, size, "fuzz.jpg", &img, (char *)err, errlen) == 0) {
        uint32_t sum = 0;
        size_t i;
        if ((uint64_t)img.width * img.height > MAX_PX || img.width == 0u || img.height == 0u) {
            abort(); /* the pixel limit was not applied */
        }
        for (i = 0; i < (size_t)img.width * img.height; i++) {
            sum += img.px[i];
        }
        sink = sum;
        ref = img.px;
        rw = img.width;
        rh = img.height;
        fz_check_guard(err, errlen, "error text");
    } else {
        check_err(err, errlen, "imgio error text");
        if (img.px != NULL) {
            abort(); /* no image on an error */
        }
    }
    free(err);

    d = jpeg_luma_open(jerr, sizeof jerr);
    if (d == NULL) {
        abort(); /* only out of memory */
    }
    if (jpeg_luma_size(d, data, size, &w, &h, jerr, sizeof jerr) == 0 &&
        (uint64_t)w * h <= MAX_PX) {
        const uint32_t stride = w + ((knob >> 2) % 4u == 0u ? 0u : (knob >> 4) % 9u);
        const size_t n = (size_t)(h - 1u) * stride + w;
        uint8_t *dst = fz_buf(n, 0x5A), *first = NULL;
        int pass, ok = 1;
        if (w == 0u || h == 0u || w > 65535u || h > 65535u) {
            abort();
        }
        /* the wrong size: an error, nothing decoded */
        if (jpeg_luma_decode(d, data, size, w + 1u, h, dst, stride + 1u, jerr, sizeof jerr) == 0) {
            abort();
        }
        fz_check_untouched(dst, n, 0x5A, "JPEG rows");
        for (pass = 0; pass < 2 && ok; pass++) {
            uint32_t y;
            ok = jpeg_luma_decode(d, data, size, w, h, dst, stride, jerr, sizeof jerr) == 0;
            fz_check_guard(dst, n, "JPEG rows");
            for (y = 0; y + 1u < h; y++) {
                fz_check_untouched(dst + (size_t)y * stride + w, stride - w, 0x5A,
                                   "bytes between rows");
            }
            if (!ok) {
                if (memchr(jerr, '\0', sizeof jerr) == NULL || jerr[0] == '\0') {
                    abort();
                }
                break;
            }
            if (first == NULL) {
                first = (uint8_t *)malloc(n);
                if (first == NULL) {
                    abort();
                }
                memcpy(first, dst, n);
            } else if (memcmp(first, dst, n) != 0) {
                abort(); /* the reused decoder gave other pixels */
            }
        }
        if (ok && ref != NULL) {
            /* imgio read the same image */
            uint32_t y;
            if (rw != w || rh != h) {
                abort();
            }
            for (y = 0; y < h; y++) {
                if (memcmp(ref + (size_t)y * w, dst + (size_t)y * stride, w) != 0) {
                    abort();
                }
            }
        }
        free(first);
        free(dst);
    }
    jpeg_luma_close(d);
    free(ref);
    free(data);
    return 0;
}

/* SPDX-License-Identifier: Apache-2.0 */
/*
 * JPEG to luma with the TurboJPEG API of libjpeg-turbo (Debian libturbojpeg0-dev).
 */
#include "jpeg_luma.h"

#include <stdio.h>
#include <stdlib.h>

#ifdef SYMLINE_HAVE_TURBOJPEG
#include <turbojpeg.h>

struct jpeg_luma {
    tjhandle tj;
};

int jpeg_luma_available(void)
{
    return 1;
}

jpeg_luma *jpeg_luma_open(char *err, size_t errlen)
{
    jpeg_luma *d = calloc(1, sizeof *d);
    if (d == NULL) {
        snprintf(err, errlen, "out of memory");
        return NULL;
    }
    d->tj = tjInitDecompress();
    if (d->tj == NULL) {
        snprintf(err, errlen, "JPEG decoder: %s", tjGetErrorStr2(NULL));
        free(d);
        return NULL;
    }
    return d;
}

void jpeg_luma_close(jpeg_luma *d)
{
    if (d != NULL) {
        if (d->tj != NULL) {
            tjDestroy(d->tj);
        }
        free(d);
    }
}

/* A header read or decode stopped half-way can leave the handle unusable for
 * the next image (seen with libjpeg-turbo 2.1): after any failure, a fresh one. */
static void renew(jpeg_luma *d)
{
    if (d->tj != NULL) {
        tjDestroy(d->tj);
    }
    d->tj = tjInitDecompress();
}

int jpeg_luma_size(jpeg_luma *d, const uint8_t *data, size_t len, uint32_t *width, uint32_t *height,
                   char *err, size_t errlen)
{
    int w = 0, h = 0, subsamp = 0, colorspace = 0;
    if (d->tj == NULL) {
        renew(d);
    }
    if (d->tj == NULL) {
        snprintf(err, errlen, "JPEG decoder: %s", tjGetErrorStr2(NULL));
        return -1;
    }
    if (len == 0 || len > (size_t)0x7fffffff) {
        snprintf(err, errlen, "JPEG: %zu bytes", len);
        return -1;
    }
    if (tjDecompressHeader3(d->tj, data, (unsigned long)len, &w, &h, &subsamp, &colorspace) != 0) {
        snprintf(err, errlen, "JPEG: %s", tjGetErrorStr2(d->tj));
        renew(d);
        return -1;
    }
    if (w <= 0 || h <= 0 || w > 65535 || h > 65535) {
        snprintf(err, errlen, "JPEG: unusable size %dx%d", w, h);
        renew(d);
        return -1;
    }
    *width = (uint32_t)w;
    *height = (uint32_t)h;
    return 0;
}

int jpeg_luma_decode(jpeg_luma *d, const uint8_t *data, size_t len, uint32_t width, uint32_t height,
                     uint8_t *dst, uint32_t dst_stride, char *err, size_t errlen)
{
    uint32_t w, h;
    if (jpeg_luma_size(d, data, len, &w, &h, err, errlen) != 0) {
        return -1;
    }
    if (w != width || h != height) {
        snprintf(err, errlen, "JPEG: %ux%u, expected %ux%u", w, h, width, height);
        return -1;
    }
    /* TJPF_GRAY: the luma component only; TJFLAG_STOPONWARNING: a damaged frame fails. */
    if (tjDecompress2(d->tj, data, (unsigned long)len, dst, (int)width, (int)dst_stride,
                      (int)height, TJPF_GRAY, TJFLAG_STOPONWARNING) != 0) {
        snprintf(err, errlen, "JPEG: %s", tjGetErrorStr2(d->tj));
        renew(d);
        return -1;
    }
    return 0;
}

#else /* built without libturbojpeg */

int jpeg_luma_available(void)
{
    return 0;
}

jpeg_luma *jpeg_luma_open(char *err, size_t errlen)
{
    snprintf(
        err, errlen,
        "this build reads no JPEG (built without libturbojpeg: apt-get install libturbojpeg0-dev)");
    return NULL;
}

void jpeg_luma_close(jpeg_luma *d)
{
    (void)d;
}

int jpeg_luma_size(jpeg_luma *d, const uint8_t *data, size_t len, uint32_t *width, uint32_t *height,
                   char *err, size_t errlen)
{
    (void)d, (void)data, (void)len, (void)width, (void)height;
    snprintf(err, errlen, "this build reads no JPEG");
    return -1;
}

int jpeg_luma_decode(jpeg_luma *d, const uint8_t *data, size_t len, uint32_t width, uint32_t height,
                     uint8_t *dst, uint32_t dst_stride, char *err, size_t errlen)
{
    (void)d, (void)data, (void)len, (void)width, (void)height, (void)dst, (void)dst_stride;
    snprintf(err, errlen, "this build reads no JPEG");
    return -1;
}

#endif

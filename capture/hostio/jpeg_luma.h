/* SPDX-License-Identifier: Apache-2.0 */
/*
 * The luma of a JPEG image in memory (a Motion-JPEG camera frame or a .jpg
 * file), decoded with libjpeg-turbo straight to 8-bit gray: for YCbCr JPEGs
 * the decoder then skips the chroma's inverse DCT and upsampling. Host-only
 * code, used by imgio and the V4L2 source; without libturbojpeg at build time
 * every call fails with a message saying so.
 */
#ifndef SYMLINE_HOST_JPEG_LUMA_H
#define SYMLINE_HOST_JPEG_LUMA_H

#include <stddef.h>
#include <stdint.h>

#ifdef __cplusplus
extern "C" {
#endif

typedef struct jpeg_luma jpeg_luma;

/* 1 when this build decodes JPEG, 0 when it was built without libturbojpeg. */
int jpeg_luma_available(void);

/* A decoder (reusable for every frame), or NULL with a message in err. */
jpeg_luma *jpeg_luma_open(char *err, size_t errlen);

/* Frees the decoder; NULL is fine. */
void jpeg_luma_close(jpeg_luma *d);

/* The image size from the JPEG header: 0, or -1 with a message in err. */
int jpeg_luma_size(jpeg_luma *d, const uint8_t *data, size_t len, uint32_t *width, uint32_t *height,
                   char *err, size_t errlen);

/*
 * Decodes the luma of a width x height JPEG into dst (dst_stride >= width
 * bytes per row). Returns 0, or -1 with a message in err when the data is
 * not a JPEG of that size or is damaged (warnings such as a truncated
 * stream count as damage: the frame would be partly gray).
 */
int jpeg_luma_decode(jpeg_luma *d, const uint8_t *data, size_t len, uint32_t width, uint32_t height,
                     uint8_t *dst, uint32_t dst_stride, char *err, size_t errlen);

#ifdef __cplusplus
}
#endif

#endif

/* SPDX-License-Identifier: Apache-2.0 */
/*
 * Pixel formats the capture sources accept, and how to get 8-bit luma out of
 * them. Host/Linux code; the core library never includes it.
 *
 * Planar and gray formats (GREY, NV12, NV21, YU12, YV12, NV16, NV61, 422P,
 * and the multi-planar NM12, NM21, YM12, YM21, NM16, NM61, YM16) start with a
 * full-resolution luma plane: the detector reads it in place, honouring the
 * driver's bytesperline. Packed 4:2:2 formats (YUYV, YVYU,
 * UYVY, VYUY) interleave luma with chroma and are deinterleaved into a
 * caller-owned buffer. Packed RGB (RGB3, BGR3, XR24, AR24, XB24, AB24; the
 * formats of vimc and of some USB cameras) is converted to luma with the
 * weights imgio uses for colour files, Y = (299 R + 587 G + 114 B + 500) / 1000.
 * 8-bit Bayer mosaics (BA81 = BGGR, GBRG, GRBG, RGGB; raw sensors) are turned
 * into full-resolution luma with the same weights (see pixfmt_unpack_luma).
 * Motion-JPEG (MJPG, JPEG; most USB webcams) is compressed: its luma is
 * decoded by jpeg_luma.h, not here.
 */
#ifndef SYMLINE_CAPTURE_PIXFMT_H
#define SYMLINE_CAPTURE_PIXFMT_H

#include <stddef.h>
#include <stdint.h>

#ifdef __cplusplus
extern "C" {
#endif

#define PIXFMT_FOURCC(a, b, c, d) \
    ((uint32_t)(a) | ((uint32_t)(b) << 8) | ((uint32_t)(c) << 16) | ((uint32_t)(d) << 24))

typedef enum pixfmt_layout {
    PIXFMT_LUMA_PLANE = 0, /* luma is the first plane: width bytes per row, no copy */
    PIXFMT_PACKED_422 = 1, /* 2 bytes per pixel, luma at byte offset luma_offset of each pair */
    PIXFMT_PACKED_RGB = 2, /* 3 or 4 bytes per pixel; luma computed as in imgio.h (BT.601) */
    PIXFMT_BAYER8 = 3,     /* 1 byte per pixel, one colour per pixel in a 2x2 pattern (cfa) */
    PIXFMT_JPEG = 4        /* compressed, a variable number of bytes per frame */
} pixfmt_layout;

typedef struct pixfmt_info {
    uint32_t fourcc;
    const char *name;     /* the fourcc as text, e.g. "YUYV" */
    pixfmt_layout layout;
    uint32_t luma_offset; /* packed 4:2:2: 0 for Y first (YUYV, YVYU), 1 for chroma first (UYVY, VYUY) */
    unsigned preference;  /* lower = preferred when the user names no format (no-copy first) */
    uint32_t bytes_per_pixel; /* of the first plane: 1, 2 (4:2:2), 3 or 4 (RGB); 0 (JPEG) */
    uint8_t r, g, b;      /* RGB: byte offsets of red, green, blue within a pixel */
    const char *cfa;      /* Bayer: colours of pixels (0,0) (1,0) (0,1) (1,1), e.g. "BGGR" */
} pixfmt_info;

/* The table entry of a fourcc, or NULL when the format is not supported. */
const pixfmt_info *pixfmt_find(uint32_t fourcc);

/* The entry named by text ("GREY", "yuyv", "YU12", "I420" ...), or NULL. */
const pixfmt_info *pixfmt_by_name(const char *name);

/* Number of supported formats and the i-th entry (0 <= i < count). */
size_t pixfmt_count(void);
const pixfmt_info *pixfmt_at(size_t i);

/* Writes the four characters of a fourcc (unprintable bytes as '?') + NUL into out[5]. */
void pixfmt_fourcc_str(uint32_t fourcc, char out[5]);

/*
 * Bytes of one row of the format's first plane for a width, used to check a
 * driver's bytesperline: bytes_per_pixel * width.
 */
uint64_t pixfmt_min_stride(const pixfmt_info *fmt, uint32_t width);

/*
 * Writes the luma of a packed 4:2:2, RGB or Bayer frame into dst (dst_stride
 * bytes per row). src_stride is the driver's bytesperline (>= pixfmt_min_stride).
 * For 4:2:2, width must be even; for Bayer, width and height at least 2.
 *
 * Bayer: each 2x2 window of the mosaic holds one red, two green and one blue
 * pixel, so it gives one luma value, (299 R + 587 (G1 + G2) / 2 + 114 B) / 1000.
 * A pixel's luma is the mean of the four windows that contain it (a 3x3
 * neighbourhood weighted 1 2 1 / 2 4 2 / 1 2 1), rounded: centred on the
 * pixel, and exactly the gray value on a uniform gray surface. Beyond the
 * border the mosaic is mirrored by two pixels, which keeps its colour phase.
 */
void pixfmt_unpack_luma(const pixfmt_info *fmt, const uint8_t *src, uint32_t src_stride,
                        uint32_t width, uint32_t height, uint8_t *dst, uint32_t dst_stride);

#ifdef __cplusplus
}
#endif

#endif

/* SPDX-License-Identifier: Apache-2.0 */
/*
 * Image files for the host programs (tools/, capture/): binary PGM and PPM
 * always, PNG when built with libpng, JPEG input when built with libturbojpeg.
 * The path "-" reads stdin or writes stdout. Host-only code (allocates, does
 * I/O); the core library never includes it.
 */
#ifndef SYMLINE_HOSTIO_IMGIO_H
#define SYMLINE_HOSTIO_IMGIO_H

#include <stddef.h>
#include <stdint.h>

typedef struct imgio_gray {
    uint32_t width;
    uint32_t height;
    uint8_t *px; /* width*height bytes, stride = width; free with imgio_free() */
} imgio_gray;

typedef struct imgio_rgb {
    uint32_t width;
    uint32_t height;
    uint8_t *px; /* width*height*3 bytes, RGB interleaved */
} imgio_rgb;

/* 1 when this build reads and writes PNG. */
int imgio_have_png(void);

/* 1 when this build reads JPEG. */
int imgio_have_jpeg(void);

/*
 * Reads an 8-bit gray image from a binary PGM (P5, maxval 255), a PNG or a
 * JPEG (by its signature, not its name; "-" reads stdin). JPEGs are decoded
 * to their luma (Y of YCbCr). Colour PNGs are converted to luma with
 * Y = (299 R + 587 G + 114 B + 500) / 1000 (ITU-R BT.601 weights); alpha is
 * ignored; 16-bit samples are reduced to 8; palettes and low bit depths are
 * expanded. Returns 0, or -1 with a message naming the file and the problem in
 * err (errlen bytes).
 */
int imgio_read_gray(const char *path, imgio_gray *img, char *err, size_t errlen);

/* Reads a P5 PGM from memory (for tests): same rules as imgio_read_gray(). */
int imgio_parse_pgm(const uint8_t *buf, size_t len, const char *name, imgio_gray *img, char *err,
                    size_t errlen);

/* Reads a PGM or PNG (by its signature) from memory: same rules as imgio_read_gray(). */
int imgio_parse_image(const uint8_t *buf, size_t len, const char *name, imgio_gray *img, char *err,
                      size_t errlen);

/*
 * Bounded resources on bad files: an image of more than imgio_max_pixels()
 * pixels is refused from its header, before any pixel memory is allocated;
 * a file is never read past what an image within the limit can need. The
 * limit is IMGIO_DEFAULT_MAX_PIXELS (4096 x 4096), or the environment
 * variable SYMLINE_MAX_PIXELS (a decimal count, 1 .. 2^32 - 1; on hosts
 * with a 32-bit size_t at most SIZE_MAX / 8), or what imgio_set_max_pixels()
 * set last (0 returns to the default and the environment).
 */
#define IMGIO_DEFAULT_MAX_PIXELS (4096u * 4096u)
uint64_t imgio_max_pixels(void);
void imgio_set_max_pixels(uint64_t n);

/*
 * The output format is chosen by the name's extension (any case): ".png" PNG,
 * ".pgm" binary PGM (gray only), ".ppm" binary PPM, ".pnm" PGM for gray and
 * PPM for colour; "-" writes PGM / PPM to stdout. Any other name is an error
 * that lists the choices (nothing is written). Write errors (a full disk, a
 * closed pipe) are reported with the reason.
 */

/* Writes gray pixels (given stride). */
int imgio_write_gray(const char *path, const uint8_t *px, uint32_t width, uint32_t height,
                     uint32_t stride, char *err, size_t errlen);

/* Writes RGB pixels (a colour image cannot be written as .pgm). */
int imgio_write_rgb(const char *path, const imgio_rgb *img, char *err, size_t errlen);

/* 0 when an output of this name can be written (colour: 1 for RGB), else -1 with the reason in err. */
int imgio_check_output_name(const char *path, int color, char *err, size_t errlen);

/* 1 when path ends in ".png" (any case). */
int imgio_is_png_name(const char *path);

void imgio_free(imgio_gray *img);
void imgio_free_rgb(imgio_rgb *img);

#endif

/* SPDX-License-Identifier: Apache-2.0 */
/*
 * PGM, PPM, PNG and JPEG reading and writing for the host tools.
 */
#include "imgio.h"

#include "jpeg_luma.h"

#include <errno.h>
#include <stdarg.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#ifdef SYMLINE_HAVE_PNG
#include <png.h>
#endif

static int fail(char *err, size_t errlen, const char *fmt, ...)
{
    va_list ap;
    if (err != NULL && errlen > 0) {
        va_start(ap, fmt);
        vsnprintf(err, errlen, fmt, ap);
        va_end(ap);
    }
    return -1;
}

static uint64_t max_pixels_set;

void imgio_set_max_pixels(uint64_t n)
{
    max_pixels_set = n;
}

uint64_t imgio_max_pixels(void)
{
    uint64_t n = max_pixels_set;
    if (n == 0u) {
        const char *e = getenv("SYMLINE_MAX_PIXELS");
        n = IMGIO_DEFAULT_MAX_PIXELS;
        if (e != NULL && e[0] >= '0' && e[0] <= '9') {
            char *end;
            unsigned long long v;
            errno = 0;
            v = strtoull(e, &end, 10);
            if (errno == 0 && *end == '\0' && v > 0u && v <= 0xFFFFFFFFull) {
                n = v;
            }
        }
    }
    /* Every buffer of an image (at most 8 bytes per pixel) must fit size_t. */
    if (n > SIZE_MAX / 8u) {
        n = SIZE_MAX / 8u;
    }
    return n;
}

/* Refuses an image larger than the pixel limit, before anything is allocated for it. */
static int check_pixels(uint64_t w, uint64_t h, const char *name, char *err, size_t errlen)
{
    const uint64_t lim = imgio_max_pixels();
    if (w * h > lim) {
        return fail(err, errlen,
                    "%s: image size %llux%llu exceeds the limit of %llu pixels "
                    "(raise it with SYMLINE_MAX_PIXELS)",
                    name, (unsigned long long)w, (unsigned long long)h, (unsigned long long)lim);
    }
    return 0;
}

int imgio_have_png(void)
{
#ifdef SYMLINE_HAVE_PNG
    return 1;
#else
    return 0;
#endif
}

int imgio_have_jpeg(void)
{
    return jpeg_luma_available();
}

int imgio_is_png_name(const char *path)
{
    size_t n = strlen(path);
    const char *ext = ".png";
    size_t i;
    if (n < 4) {
        return 0;
    }
    for (i = 0; i < 4; i++) {
        char c = path[n - 4 + i];
        if (c >= 'A' && c <= 'Z') {
            c = (char)(c - 'A' + 'a');
        }
        if (c != ext[i]) {
            return 0;
        }
    }
    return 1;
}

void imgio_free(imgio_gray *img)
{
    if (img != NULL) {
        free(img->px);
        img->px = NULL;
    }
}

void imgio_free_rgb(imgio_rgb *img)
{
    if (img != NULL) {
        free(img->px);
        img->px = NULL;
    }
}

/* Skips white space and '#' comments in a PNM header. */
static size_t skip_space(const uint8_t *buf, size_t len, size_t i)
{
    while (i < len) {
        if (buf[i] == '#') {
            while (i < len && buf[i] != '\n' && buf[i] != '\r') {
                i++;
            }
        } else if (buf[i] == ' ' || buf[i] == '\t' || buf[i] == '\n' || buf[i] == '\r' ||
                   buf[i] == '\v' || buf[i] == '\f') {
            i++;
        } else {
            break;
        }
    }
    return i;
}

static int read_uint(const uint8_t *buf, size_t len, size_t *pos, unsigned long *out)
{
    size_t i = skip_space(buf, len, *pos);
    unsigned long v = 0;
    int digits = 0;
    while (i < len && buf[i] >= '0' && buf[i] <= '9') {
        if (v > 100000000ul) {
            return -1;
        }
        v = v * 10ul + (unsigned long)(buf[i] - '0');
        i++;
        digits++;
    }
    if (digits == 0) {
        return -1;
    }
    *pos = i;
    *out = v;
    return 0;
}

int imgio_parse_pgm(const uint8_t *buf, size_t len, const char *name, imgio_gray *img, char *err,
                    size_t errlen)
{
    size_t pos = 2;
    unsigned long w, h, maxval;
    size_t need;
    if (len < 2 || buf[0] != 'P') {
        return fail(err, errlen, "%s: not a PGM or PNG file", name);
    }
    switch (buf[1]) {
    case '5': break;
    case '2':
        return fail(err, errlen, "%s: ASCII PGM (P2) is not supported; use binary PGM (P5)", name);
    case '6':
    case '3':
        return fail(err, errlen,
                    "%s: colour PPM (P%c) is not supported; use 8-bit gray PGM (P5) or PNG", name,
                    buf[1]);
    case '1':
    case '4':
        return fail(err, errlen, "%s: bitmap PBM (P%c) is not supported; use 8-bit gray PGM (P5)",
                    name, buf[1]);
    default: return fail(err, errlen, "%s: not a PGM file (magic P%c)", name, buf[1]);
    }
    if (read_uint(buf, len, &pos, &w) != 0 || read_uint(buf, len, &pos, &h) != 0 ||
        read_uint(buf, len, &pos, &maxval) != 0) {
        return fail(err, errlen, "%s: malformed PGM header", name);
    }
    if (maxval != 255ul) {
        return fail(err, errlen, "%s: PGM maxval is %lu; only 8-bit PGM (maxval 255) is supported",
                    name, maxval);
    }
    if (w == 0 || h == 0 || w > 65535ul || h > 65535ul) {
        return fail(err, errlen, "%s: image size %lux%lu outside 1..65535", name, w, h);
    }
    if (check_pixels(w, h, name, err, errlen) != 0) {
        return -1;
    }
    /* Exactly one white-space byte separates the header from the pixels. */
    if (pos >= len ||
        !(buf[pos] == ' ' || buf[pos] == '\t' || buf[pos] == '\n' || buf[pos] == '\r')) {
        return fail(err, errlen, "%s: malformed PGM header", name);
    }
    pos++;
    need = (size_t)w * (size_t)h;
    if (len - pos < need) {
        return fail(err, errlen, "%s: truncated PGM data (%zu of %zu pixel bytes)", name, len - pos,
                    need);
    }
    img->px = (uint8_t *)malloc(need);
    if (img->px == NULL) {
        return fail(err, errlen, "%s: out of memory", name);
    }
    memcpy(img->px, buf + pos, need);
    img->width = (uint32_t)w;
    img->height = (uint32_t)h;
    return 0;
}

static const uint8_t png_sig[8] = {0x89, 'P', 'N', 'G', '\r', '\n', 0x1a, '\n'};

/* The most bytes a file starting with buf[0..len-1] (len >= 16) can need for
 * an image within the pixel limit (a PNG or JPEG: 8 bytes per pixel, 16-bit
 * RGBA stored, plus 1 MiB of chunks; a PGM: the pixels plus a 64 KiB
 * header); 0 when it is none of these formats. */
static size_t file_limit(const uint8_t *buf, size_t len)
{
    const uint64_t px = imgio_max_pixels();
    uint64_t lim;
    if ((len >= 8u && memcmp(buf, png_sig, 8) == 0) ||
        (buf[0] == 0xFF && buf[1] == 0xD8 && buf[2] == 0xFF)) {
        lim = 8u * px + (1u << 20); /* PNG or JPEG */
    } else if (len >= 1u && buf[0] == 'P') {
        lim = px + (1u << 16);
    } else {
        return 0u;
    }
    return lim > SIZE_MAX ? SIZE_MAX : (size_t)lim;
}

/* Reads the file, never more than an image within the pixel limit can need
 * (a device such as /dev/zero or an endless pipe is not read to exhaustion). */
static int slurp(const char *path, uint8_t **out, size_t *outlen, char *err, size_t errlen)
{
    const int is_stdin = strcmp(path, "-") == 0;
    FILE *f = is_stdin ? stdin : fopen(path, "rb");
    uint8_t *buf = NULL;
    size_t len = 0, cap = 0, lim = 16u; /* the magic first, then the format's limit */
    int decided = 0;
    if (f == NULL) {
        return fail(err, errlen, "%s: cannot open: %s", path, strerror(errno));
    }
    for (;;) {
        size_t got;
        if (len == lim) {
            if (decided) {
                break;
            }
            decided = 1;
            lim = file_limit(buf, len);
            if (lim == 0u) {
                free(buf);
                fclose(f);
                return fail(err, errlen, "%s: not a PGM, PNG or JPEG file", path);
            }
        }
        if (len == cap) {
            size_t ncap = cap ? (cap > lim / 2u ? lim : cap * 2u) : 1u << 16;
            uint8_t *nb = (uint8_t *)realloc(buf, ncap);
            if (nb == NULL) {
                free(buf);
                if (!is_stdin) {
                    fclose(f);
                }
                return fail(err, errlen, "%s: out of memory", path);
            }
            buf = nb;
            cap = ncap;
        }
        got = fread(buf + len, 1, (cap < lim ? cap : lim) - len, f);
        len += got;
        if (got == 0) {
            break;
        }
    }
    if (ferror(f)) {
        int e = errno;
        free(buf);
        if (!is_stdin) {
            fclose(f);
        }
        return fail(err, errlen, "%s: read error: %s", path, strerror(e));
    }
    if (!is_stdin) {
        fclose(f);
    }
    *out = buf;
    *outlen = len;
    return 0;
}

#ifdef SYMLINE_HAVE_PNG
typedef struct png_mem {
    const uint8_t *buf;
    size_t len, pos;
} png_mem;

static void png_mem_read(png_structp png, png_bytep out, png_size_t n)
{
    png_mem *m = (png_mem *)png_get_io_ptr(png);
    if (m->len - m->pos < n) {
        png_error(png, "truncated PNG data");
    }
    memcpy(out, m->buf + m->pos, n);
    m->pos += n;
}

static char png_msg[200];

static void png_on_error(png_structp png, png_const_charp msg)
{
    snprintf(png_msg, sizeof png_msg, "%s", msg);
    png_longjmp(png, 1);
}

static void png_on_warning(png_structp png, png_const_charp msg)
{
    (void)png;
    (void)msg;
}

static int parse_png(const uint8_t *buf, size_t len, const char *name, imgio_gray *img, char *err,
                     size_t errlen)
{
    png_structp png;
    png_infop info;
    png_mem mem = {buf, len, 0};
    /* Set after setjmp and freed after a longjmp: volatile, or they may read
     * as their value at setjmp time (NULL) there. */
    uint8_t *volatile rgb = NULL;
    png_bytep *volatile rows = NULL;
    uint32_t w, h, x, y;
    int channels, ctype;
    volatile int ok = -1;

    png = png_create_read_struct(PNG_LIBPNG_VER_STRING, NULL, png_on_error, png_on_warning);
    if (png == NULL) {
        return fail(err, errlen, "%s: out of memory", name);
    }
    info = png_create_info_struct(png);
    if (info == NULL) {
        png_destroy_read_struct(&png, NULL, NULL);
        return fail(err, errlen, "%s: out of memory", name);
    }
    img->px = NULL;
    if (setjmp(png_jmpbuf(png))) {
        free(rows);
        free(rgb);
        imgio_free(img);
        png_destroy_read_struct(&png, &info, NULL);
        return fail(err, errlen, "%s: unsupported or damaged PNG: %s", name, png_msg);
    }
    png_set_read_fn(png, &mem, png_mem_read);
    /* No allocation bigger than the image: libpng refuses larger headers
     * itself, and ancillary chunks (text, profiles, suggested palettes) are
     * skipped unread, without allocating the size their header claims (the
     * chunk size limit alone only warns). Luma needs none of them. */
    png_set_user_limits(png, 65535u, 65535u);
    png_set_chunk_malloc_max(png, 1u << 20);
    png_set_chunk_cache_max(png, 1000u);
    png_set_keep_unknown_chunks(png, PNG_HANDLE_CHUNK_NEVER, NULL, -1);
    png_read_info(png, info);
    w = png_get_image_width(png, info);
    h = png_get_image_height(png, info);
    if (w == 0 || h == 0 || w > 65535u || h > 65535u) {
        png_destroy_read_struct(&png, &info, NULL);
        return fail(err, errlen, "%s: image size %ux%u outside 1..65535", name, w, h);
    }
    if (check_pixels(w, h, name, err, errlen) != 0) {
        png_destroy_read_struct(&png, &info, NULL);
        return -1;
    }
    ctype = png_get_color_type(png, info);
    png_set_strip_16(png);
    png_set_strip_alpha(png);
    png_set_packing(png);
    if (ctype == PNG_COLOR_TYPE_PALETTE) {
        png_set_palette_to_rgb(png);
    }
    if (ctype == PNG_COLOR_TYPE_GRAY && png_get_bit_depth(png, info) < 8) {
        png_set_expand_gray_1_2_4_to_8(png);
    }
    (void)png_set_interlace_handling(png);
    png_read_update_info(png, info);
    channels = png_get_channels(png, info);
    if (channels != 1 && channels != 3) {
        png_error(png, "unexpected channel count");
    }
    /* w * h * channels fits size_t: the pixel limit is at most SIZE_MAX / 8. */
    rgb = (uint8_t *)malloc((size_t)w * h * (size_t)channels);
    rows = (png_bytep *)malloc(sizeof(png_bytep) * h);
    img->px = (uint8_t *)malloc((size_t)w * h);
    if (rgb == NULL || rows == NULL || img->px == NULL) {
        png_error(png, "out of memory");
    }
    for (y = 0; y < h; y++) {
        rows[y] = rgb + (size_t)y * w * (size_t)channels;
    }
    png_read_image(png, (png_bytepp)rows);
    for (y = 0; y < h; y++) {
        const uint8_t *s = rows[y];
        uint8_t *d = img->px + (size_t)y * w;
        for (x = 0; x < w; x++) {
            if (channels == 1) {
                d[x] = s[x];
            } else {
                const uint32_t r = s[3 * x], g = s[3 * x + 1], b = s[3 * x + 2];
                d[x] = (uint8_t)((299u * r + 587u * g + 114u * b + 500u) / 1000u);
            }
        }
    }
    img->width = w;
    img->height = h;
    ok = 0;
    free(rows);
    free(rgb);
    png_destroy_read_struct(&png, &info, NULL);
    return ok;
}
#endif

/* A JPEG's luma. */
static int read_jpeg(const uint8_t *buf, size_t len, const char *name, imgio_gray *img, char *err,
                     size_t errlen)
{
    char jerr[256];
    uint32_t w, h;
    jpeg_luma *d;
    if (!jpeg_luma_available()) {
        return fail(
            err, errlen,
            "%s: JPEG input needs a build with libturbojpeg (libturbojpeg0-dev); use PGM or PNG",
            name);
    }
    d = jpeg_luma_open(jerr, sizeof jerr);
    if (d == NULL) {
        return fail(err, errlen, "%s: %s", name, jerr);
    }
    if (jpeg_luma_size(d, buf, len, &w, &h, jerr, sizeof jerr) != 0) {
        jpeg_luma_close(d);
        return fail(err, errlen, "%s: %s", name, jerr);
    }
    if (check_pixels(w, h, name, err, errlen) != 0) {
        jpeg_luma_close(d);
        return -1;
    }
    img->px = (uint8_t *)malloc((size_t)w * h);
    if (img->px == NULL) {
        jpeg_luma_close(d);
        return fail(err, errlen, "%s: out of memory", name);
    }
    if (jpeg_luma_decode(d, buf, len, w, h, img->px, w, jerr, sizeof jerr) != 0) {
        jpeg_luma_close(d);
        imgio_free(img);
        return fail(err, errlen, "%s: %s", name, jerr);
    }
    jpeg_luma_close(d);
    img->width = w;
    img->height = h;
    return 0;
}

int imgio_parse_image(const uint8_t *buf, size_t len, const char *name, imgio_gray *img, char *err,
                      size_t errlen)
{
    img->px = NULL;
    if (len >= 8 && memcmp(buf, png_sig, 8) == 0) {
#ifdef SYMLINE_HAVE_PNG
        return parse_png(buf, len, name, img, err, errlen);
#else
        return fail(err, errlen, "%s: PNG input needs a build with libpng; use PGM (P5)", name);
#endif
    }
    if (len >= 3 && buf[0] == 0xFF && buf[1] == 0xD8 && buf[2] == 0xFF) {
        return read_jpeg(buf, len, name, img, err, errlen);
    }
    if (len == 0) {
        return fail(err, errlen, "%s: empty file", name);
    }
    return imgio_parse_pgm(buf, len, name, img, err, errlen);
}

int imgio_read_gray(const char *path, imgio_gray *img, char *err, size_t errlen)
{
    uint8_t *buf = NULL;
    size_t len = 0;
    int rc;
    img->px = NULL;
    if (slurp(path, &buf, &len, err, errlen) != 0) {
        return -1;
    }
    rc = imgio_parse_image(buf, len, path, img, err, errlen);
    free(buf);
    return rc;
}

#ifdef SYMLINE_HAVE_PNG
static int write_png(const char *path, const uint8_t *px, uint32_t width, uint32_t height,
                     size_t stride, int color, char *err, size_t errlen)
{
    FILE *f = fopen(path, "wb");
    png_structp png;
    png_infop info;
    uint32_t y;
    if (f == NULL) {
        return fail(err, errlen, "%s: cannot create: %s", path, strerror(errno));
    }
    png = png_create_write_struct(PNG_LIBPNG_VER_STRING, NULL, png_on_error, png_on_warning);
    info = png ? png_create_info_struct(png) : NULL;
    if (png == NULL || info == NULL) {
        png_destroy_write_struct(&png, NULL);
        fclose(f);
        return fail(err, errlen, "%s: out of memory", path);
    }
    if (setjmp(png_jmpbuf(png))) {
        png_destroy_write_struct(&png, &info);
        fclose(f);
        return fail(err, errlen, "%s: cannot write PNG: %s", path, png_msg);
    }
    png_init_io(png, f);
    png_set_IHDR(png, info, width, height, 8, color ? PNG_COLOR_TYPE_RGB : PNG_COLOR_TYPE_GRAY,
                 PNG_INTERLACE_NONE, PNG_COMPRESSION_TYPE_DEFAULT, PNG_FILTER_TYPE_DEFAULT);
    png_write_info(png, info);
    for (y = 0; y < height; y++) {
        png_write_row(png, (png_const_bytep)(px + (size_t)y * stride));
    }
    png_write_end(png, NULL);
    png_destroy_write_struct(&png, &info);
    if (fclose(f) != 0) {
        return fail(err, errlen, "%s: write error: %s", path, strerror(errno));
    }
    return 0;
}
#endif

/* Output formats, chosen by the name. */
enum {
    OUT_UNKNOWN,
    OUT_PGM,
    OUT_PPM,
    OUT_PNM,
    OUT_PNG
};

static int has_ext(const char *path, const char *ext)
{
    size_t n = strlen(path), k = strlen(ext), i;
    if (n <= k) {
        return 0;
    }
    for (i = 0; i < k; i++) {
        char c = path[n - k + i];
        if (c >= 'A' && c <= 'Z') {
            c = (char)(c - 'A' + 'a');
        }
        if (c != ext[i]) {
            return 0;
        }
    }
    return 1;
}

static int out_format(const char *path)
{
    if (strcmp(path, "-") == 0 || has_ext(path, ".pnm")) {
        return OUT_PNM;
    }
    if (has_ext(path, ".pgm")) {
        return OUT_PGM;
    }
    if (has_ext(path, ".ppm")) {
        return OUT_PPM;
    }
    return has_ext(path, ".png") ? OUT_PNG : OUT_UNKNOWN;
}

int imgio_check_output_name(const char *path, int color, char *err, size_t errlen)
{
    const int fmt = out_format(path);
    if (fmt == OUT_UNKNOWN) {
        const char *dot = strrchr(path, '.');
        const char *slash = strrchr(path, '/');
        return fail(err, errlen,
                    "%s: unknown image format%s%s%s: write .pgm, .ppm, .pnm%s or - (stdout)", path,
                    dot != NULL && (slash == NULL || dot > slash) ? " '" : "",
                    dot != NULL && (slash == NULL || dot > slash) ? dot : "",
                    dot != NULL && (slash == NULL || dot > slash) ? "'" : "",
                    imgio_have_png() ? ", .png" : "");
    }
    if (fmt == OUT_PGM && color) {
        return fail(err, errlen, "%s: a colour image cannot be written as PGM: use .ppm%s", path,
                    imgio_have_png() ? " or .png" : "");
    }
    if (fmt == OUT_PNG && !imgio_have_png()) {
        return fail(err, errlen, "%s: PNG output needs a build with libpng", path);
    }
    return 0;
}

/* P5 (gray) or P6 (colour; gray pixels are repeated into R, G, B when as_rgb). */
static int write_pnm(const char *path, const uint8_t *px, uint32_t width, uint32_t height,
                     size_t stride, int color, int as_rgb, char *err, size_t errlen)
{
    const int is_stdout = strcmp(path, "-") == 0;
    FILE *f = is_stdout ? stdout : fopen(path, "wb");
    const size_t row = (size_t)width * (color ? 3u : 1u);
    uint8_t *rgb = NULL;
    uint32_t y;
    int bad;
    if (f == NULL) {
        return fail(err, errlen, "%s: cannot create: %s", path, strerror(errno));
    }
    if (as_rgb && !color) {
        rgb = (uint8_t *)malloc((size_t)width * 3u);
        if (rgb == NULL) {
            if (!is_stdout) {
                fclose(f);
            }
            return fail(err, errlen, "%s: out of memory", path);
        }
    }
    fprintf(f, "P%c\n%u %u\n255\n", color || as_rgb ? '6' : '5', width, height);
    for (y = 0; y < height; y++) {
        const uint8_t *src = px + (size_t)y * stride;
        if (rgb != NULL) {
            uint32_t x;
            for (x = 0; x < width; x++) {
                rgb[3u * x] = rgb[3u * x + 1u] = rgb[3u * x + 2u] = src[x];
            }
            if (fwrite(rgb, 1, (size_t)width * 3u, f) != (size_t)width * 3u) {
                break;
            }
        } else if (fwrite(src, 1, row, f) != row) {
            break;
        }
    }
    free(rgb);
    bad = y < height || fflush(f) != 0 || ferror(f);
    if (bad) {
        const int e = errno;
        if (!is_stdout) {
            fclose(f);
        }
        return fail(err, errlen, "%s: write error: %s", path, strerror(e));
    }
    if (!is_stdout && fclose(f) != 0) {
        return fail(err, errlen, "%s: write error: %s", path, strerror(errno));
    }
    return 0;
}

static int write_any(const char *path, const uint8_t *px, uint32_t width, uint32_t height,
                     size_t stride, int color, char *err, size_t errlen)
{
    const int fmt = out_format(path);
    if (imgio_check_output_name(path, color, err, errlen) != 0) {
        return -1;
    }
    if (fmt == OUT_PNG) {
#ifdef SYMLINE_HAVE_PNG
        return write_png(path, px, width, height, stride, color, err, errlen);
#endif
    }
    return write_pnm(path, px, width, height, stride, color, fmt == OUT_PPM, err, errlen);
}

int imgio_write_gray(const char *path, const uint8_t *px, uint32_t width, uint32_t height,
                     uint32_t stride, char *err, size_t errlen)
{
    return write_any(path, px, width, height, stride, 0, err, errlen);
}

int imgio_write_rgb(const char *path, const imgio_rgb *img, char *err, size_t errlen)
{
    return write_any(path, img->px, img->width, img->height, (size_t)img->width * 3u, 1, err,
                     errlen);
}

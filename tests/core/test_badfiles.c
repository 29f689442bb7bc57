/* SPDX-License-Identifier: Apache-2.0 */
/*
 * Bad image files and sizes in the host tools (docs/errors.md): damaged PNGs
 * leak nothing, headers larger than the pixel limit are refused before any
 * pixel memory is allocated (peak memory measured), devices are not read to
 * exhaustion, and the detector's point storage fits a 32-bit size_t.
 */
#define _POSIX_C_SOURCE 200809L
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/resource.h>

#include <cmocka.h>

#include "detopts.h"
#include "imgio.h"

static uint32_t crc_table[256];

static uint32_t crc32_of(const uint8_t *p, size_t n)
{
    uint32_t c = 0xFFFFFFFFu;
    size_t i;
    if (crc_table[1] == 0u) {
        uint32_t k, b;
        for (k = 0; k < 256u; k++) {
            uint32_t v = k;
            for (b = 0; b < 8u; b++) {
                v = (v & 1u) ? 0xEDB88320u ^ (v >> 1) : v >> 1;
            }
            crc_table[k] = v;
        }
    }
    for (i = 0; i < n; i++) {
        c = crc_table[(c ^ p[i]) & 0xFFu] ^ (c >> 8);
    }
    return c ^ 0xFFFFFFFFu;
}

static void put32(uint8_t *p, uint32_t v)
{
    p[0] = (uint8_t)(v >> 24);
    p[1] = (uint8_t)(v >> 16);
    p[2] = (uint8_t)(v >> 8);
    p[3] = (uint8_t)v;
}

/* Appends a chunk; `claimed` is the length written in its header (normally len). */
static size_t chunk(uint8_t *out, size_t at, const char *type, const uint8_t *data, uint32_t len,
                    uint32_t claimed)
{
    put32(out + at, claimed);
    memcpy(out + at + 4, type, 4);
    if (len > 0u) {
        memcpy(out + at + 8, data, len);
    }
    put32(out + at + 8 + len, crc32_of(out + at + 4, 4u + len));
    return at + 12u + len;
}

/* A PNG with the given header and one small IDAT (zlib of 8 zero bytes). */
static size_t png_with_header(uint8_t *out, uint32_t w, uint32_t h, uint8_t depth, uint8_t ctype)
{
    static const uint8_t sig[8] = {0x89, 'P', 'N', 'G', '\r', '\n', 0x1a, '\n'};
    static const uint8_t idat[11] = {0x78, 0x9c, 0x63, 0x60, 0x80, 0x00,
                                     0x00, 0x00, 0x08, 0x00, 0x01};
    uint8_t ihdr[13] = {0};
    size_t at = 8;
    memcpy(out, sig, 8);
    put32(ihdr, w);
    put32(ihdr + 4, h);
    ihdr[8] = depth;
    ihdr[9] = ctype;
    at = chunk(out, at, "IHDR", ihdr, 13, 13);
    at = chunk(out, at, "IDAT", idat, sizeof idat, sizeof idat);
    return chunk(out, at, "IEND", NULL, 0, 0);
}

static long peak_kb(void)
{
    struct rusage ru;
    getrusage(RUSAGE_SELF, &ru);
    return ru.ru_maxrss;
}

static void expect_refused(const uint8_t *buf, size_t len, const char *needle)
{
    imgio_gray img;
    char err[256] = "";
    img.px = (uint8_t *)&img; /* must come back NULL */
    assert_int_equal(imgio_parse_image(buf, len, "bad.png", &img, err, sizeof err), -1);
    assert_null(img.px);
    if (strstr(err, "bad.png") == NULL || strstr(err, needle) == NULL) {
        fail_msg("message '%s' lacks the file name or '%s'", err, needle);
    }
}

/* The 43-byte reproducer: a 1x1 gray PNG whose IDAT is cut. Its frame buffer
 * leaked after the error (ASan and valgrind runs of this test catch a leak). */
static void test_damaged_png_frees_everything(void **state)
{
    static const uint8_t damaged[43] = {
        0x89, 0x50, 0x4e, 0x47, 0x0d, 0x0a, 0x1a, 0x0a, 0x00, 0x00, 0x00, 0x0d, 0x49, 0x48, 0x44,
        0x52, 0x00, 0x00, 0x00, 0x01, 0x00, 0x00, 0x00, 0x01, 0x08, 0x00, 0x00, 0x00, 0x00, 0x3a,
        0x7e, 0x9b, 0x55, 0x00, 0x00, 0x00, 0x0a, 0x49, 0x44, 0x41, 0x54, 0x78, 0x9c};
    (void)state;
    if (!imgio_have_png()) {
        skip();
    }
    expect_refused(damaged, sizeof damaged, "damaged PNG");
}

/* Headers claiming more than the pixel limit allocate nothing for it. */
static void test_png_headers_within_limits(void **state)
{
    static uint8_t buf[256];
    const long before = peak_kb();
    size_t n;
    (void)state;
    if (!imgio_have_png()) {
        skip();
    }
    n = png_with_header(buf, 65535u, 65535u, 16, 2); /* 16-bit RGB: 25 GB decoded */
    expect_refused(buf, n, "exceeds the limit of 16777216 pixels");
    n = png_with_header(buf, 20000u, 20000u, 8, 0); /* a decompression bomb's size */
    expect_refused(buf, n, "exceeds the limit");
    n = png_with_header(buf, 70000u, 1u, 8, 0);
    expect_refused(buf, n, "damaged PNG"); /* libpng's own limit: width above 65535 */
    /* A tEXt chunk claiming 2^31 - 1 bytes: skipped, not allocated. */
    n = png_with_header(buf, 1u, 1u, 8, 0) - 12u;
    n = chunk(buf, n - 23u, "tEXt", (const uint8_t *)"a\0b", 3, 0x7FFFFFFFu);
    expect_refused(buf, n, "damaged PNG");
    /* Peak memory of all four: a few MB at most (libpng's own state). */
    if (peak_kb() - before > 16 * 1024) {
        fail_msg("peak memory grew by %ld KB", peak_kb() - before);
    }
}

static void test_pixel_limit_override(void **state)
{
    static const char pgm[] = "P5\n4 4\n255\n0123456789abcdef";
    imgio_gray img;
    char err[256];
    (void)state;
    imgio_set_max_pixels(15u);
    assert_int_equal(imgio_max_pixels(), 15u);
    assert_int_equal(
        imgio_parse_pgm((const uint8_t *)pgm, sizeof pgm - 1, "x.pgm", &img, err, sizeof err), -1);
    assert_non_null(strstr(err, "exceeds the limit of 15 pixels"));
    imgio_set_max_pixels(16u);
    assert_int_equal(
        imgio_parse_pgm((const uint8_t *)pgm, sizeof pgm - 1, "x.pgm", &img, err, sizeof err), 0);
    imgio_free(&img);
    imgio_set_max_pixels(0u);
    assert_true(imgio_max_pixels() == IMGIO_DEFAULT_MAX_PIXELS ||
                getenv("SYMLINE_MAX_PIXELS") != NULL);
    /* The limit keeps every buffer of an image (8 bytes a pixel at most) within size_t. */
    imgio_set_max_pixels(UINT64_MAX);
    assert_true(imgio_max_pixels() <= SIZE_MAX / 8u);
    imgio_set_max_pixels(0u);
}

/* Devices and folders: an error at once, not a read until memory runs out. */
static void test_devices_and_folders(void **state)
{
    imgio_gray img;
    char err[256];
    long before;
    (void)state;
    /* The error paths once before the peak is taken: the first error text
     * and, under an emulator (qemu-user: the AArch64 tests), the first
     * translation of this code may take memory of their own. */
    assert_int_equal(imgio_read_gray("/", &img, err, sizeof err), -1);
    assert_non_null(strstr(err, "/: read error"));
    before = peak_kb();
    assert_int_equal(imgio_read_gray("/dev/zero", &img, err, sizeof err), -1);
    assert_non_null(strstr(err, "/dev/zero: not a PGM, PNG or JPEG file"));
    assert_int_equal(imgio_read_gray("/dev/urandom", &img, err, sizeof err), -1);
    if (peak_kb() - before >= 4 * 1024) {
        fail_msg("peak memory grew by %ld KB", peak_kb() - before);
    }
}

/* The point storage both tools give the detector: its byte size fits a
 * 32-bit size_t for every accepted frame size (the product wrapped before). */
static void test_point_storage_fits_32_bits(void **state)
{
    const uint32_t sizes[][2] = {
        {1, 1}, {640, 480}, {32768, 32768}, {65535, 65535}, {46341, 46341}};
    size_t i;
    (void)state;
    for (i = 0; i < sizeof sizes / sizeof sizes[0]; i++) {
        const uint32_t cap = detopts_point_cap(sizes[i][0], sizes[i][1]);
        const uint64_t want = 2u * (uint64_t)sizes[i][0] * sizes[i][1] + 1024u;
        assert_true((uint64_t)cap * sizeof(symline_point) <= UINT32_MAX);
        assert_true(cap == want || cap == 0xFFFFFFFFu / sizeof(symline_point));
    }
    assert_int_equal(detopts_point_cap(640, 480), 2u * 640u * 480u + 1024u);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_damaged_png_frees_everything),
        cmocka_unit_test(test_png_headers_within_limits),
        cmocka_unit_test(test_pixel_limit_override),
        cmocka_unit_test(test_devices_and_folders),
        cmocka_unit_test(test_point_storage_fits_32_bits),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}

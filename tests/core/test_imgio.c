/* SPDX-License-Identifier: Apache-2.0 */
/*
 * The host tools' image reader and writer: PGM header rules, error messages
 * that name the file and the problem, PNG round trips and the luma formula,
 * JPEG input, and the output format chosen by the name.
 */
#define _POSIX_C_SOURCE 200809L
#include <fcntl.h>
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

#include <cmocka.h>

#ifdef SYMLINE_HAVE_TURBOJPEG
#include <turbojpeg.h>
#endif

#include "imgio.h"

static int parse(const char *text, size_t len, imgio_gray *img, char *err)
{
    return imgio_parse_pgm((const uint8_t *)text, len, "x.pgm", img, err, 256);
}

static void test_pgm_header_forms(void **state)
{
    imgio_gray img;
    char err[256];
    static const char ok1[] = "P5\n# a comment\n2 1\n# another\n255\n\x01\xff";
    static const char ok2[] = "P5 2 1 255 \x07\x08";
    (void)state;
    assert_int_equal(parse(ok1, sizeof ok1 - 1, &img, err), 0);
    assert_int_equal(img.width, 2);
    assert_int_equal(img.px[0], 1);
    assert_int_equal(img.px[1], 255);
    imgio_free(&img);
    assert_int_equal(parse(ok2, sizeof ok2 - 1, &img, err), 0);
    assert_int_equal(img.px[1], 8);
    imgio_free(&img);
}

static void expect_error(const char *text, size_t len, const char *needle)
{
    imgio_gray img;
    char err[256] = "";
    assert_int_equal(parse(text, len, &img, err), -1);
    assert_non_null(strstr(err, "x.pgm"));
    if (strstr(err, needle) == NULL) {
        fail_msg("message '%s' lacks '%s'", err, needle);
    }
}

static void test_pgm_errors(void **state)
{
    (void)state;
    expect_error("P2\n2 1\n255\n1 2\n", 14, "P2");
    expect_error("P6\n1 1\n255\nabc", 14, "P6");
    expect_error("P5\n2 2\n65535\n", 13, "maxval");
    expect_error("P5\n4 4\n255\nabc", 14, "truncated");
    expect_error("P5\n0 4\n255\n", 11, "size");
    expect_error("GIF89a", 6, "not a PGM");
    expect_error("P5\nx", 4, "header");
}

static char *tmpname(const char *suffix)
{
    static char buf[256];
    snprintf(buf, sizeof buf, "/tmp/symline_imgio_%ld%s", (long)getpid(), suffix);
    return buf;
}

static void test_unreadable_file(void **state)
{
    imgio_gray img;
    char err[256];
    (void)state;
    assert_int_equal(imgio_read_gray("/nonexistent/dir/frame.pgm", &img, err, sizeof err), -1);
    assert_non_null(strstr(err, "/nonexistent/dir/frame.pgm"));
    assert_non_null(strstr(err, "cannot open"));
}

static void test_pgm_roundtrip_with_stride(void **state)
{
    const uint8_t px[] = {1, 2, 3, 99, 4, 5, 6, 99};
    imgio_gray img;
    char err[256];
    const char *path = tmpname(".pgm");
    (void)state;
    assert_int_equal(imgio_write_gray(path, px, 3, 2, 4, err, sizeof err), 0);
    assert_int_equal(imgio_read_gray(path, &img, err, sizeof err), 0);
    assert_int_equal(img.width, 3);
    assert_int_equal(img.height, 2);
    assert_memory_equal(img.px, "\x01\x02\x03\x04\x05\x06", 6);
    imgio_free(&img);
    unlink(path);
}

static void test_png_roundtrip_and_luma(void **state)
{
    uint8_t gray[6] = {0, 50, 100, 150, 200, 255};
    uint8_t rgb_px[6] = {255, 0, 0, 10, 200, 30};
    imgio_rgb rgb = {2, 1, rgb_px};
    imgio_gray img;
    char err[256];
    const char *path = tmpname(".png");
    (void)state;
    if (!imgio_have_png()) {
        skip();
    }
    assert_int_equal(imgio_write_gray(path, gray, 3, 2, 3, err, sizeof err), 0);
    assert_int_equal(imgio_read_gray(path, &img, err, sizeof err), 0);
    assert_int_equal(img.width, 3);
    assert_memory_equal(img.px, gray, 6);
    imgio_free(&img);
    /* colour is converted with Y = (299 R + 587 G + 114 B + 500) / 1000 */
    assert_int_equal(imgio_write_rgb(path, &rgb, err, sizeof err), 0);
    assert_int_equal(imgio_read_gray(path, &img, err, sizeof err), 0);
    assert_int_equal(img.px[0], (299 * 255 + 500) / 1000);
    assert_int_equal(img.px[1], (299 * 10 + 587 * 200 + 114 * 30 + 500) / 1000);
    imgio_free(&img);
    /* a damaged PNG is reported, not crashed on */
    {
        FILE *f = fopen(path, "r+b");
        assert_non_null(f);
        assert_int_equal(fseek(f, 20, SEEK_SET), 0);
        fputs("garbagegarbage", f);
        fclose(f);
        assert_int_equal(imgio_read_gray(path, &img, err, sizeof err), -1);
        assert_non_null(strstr(err, "PNG"));
    }
    unlink(path);
}

/* JPEG input: its luma, whatever the name; a damaged one is reported. */
static void test_jpeg_input(void **state)
{
#ifdef SYMLINE_HAVE_TURBOJPEG
    /* 16x8, left half RGB (200, 100, 30), right half gray 77: colour becomes its BT.601 luma. */
    uint8_t rgb[16 * 8 * 3];
    unsigned char *jpg = NULL;
    unsigned long jlen = 0;
    imgio_gray img;
    char err[256];
    const char *path = tmpname(".data");
    tjhandle tj = tjInitCompress();
    uint32_t x, y;
    FILE *f;
    (void)state;
    assert_true(imgio_have_jpeg());
    for (y = 0; y < 8; y++) {
        for (x = 0; x < 16; x++) {
            uint8_t *p = rgb + 3u * (y * 16u + x);
            p[0] = x < 8 ? 200 : 77;
            p[1] = x < 8 ? 100 : 77;
            p[2] = x < 8 ? 30 : 77;
        }
    }
    assert_non_null(tj);
    assert_int_equal(tjCompress2(tj, rgb, 16, 0, 8, TJPF_RGB, &jpg, &jlen, TJSAMP_444, 100, 0), 0);
    f = fopen(path, "wb");
    assert_non_null(f);
    assert_int_equal(fwrite(jpg, 1, jlen, f), jlen);
    fclose(f);
    assert_int_equal(imgio_read_gray(path, &img, err, sizeof err), 0);
    assert_int_equal(img.width, 16);
    assert_int_equal(img.height, 8);
    /* quality 100, 4:4:4: within 2 of the exact luma, away from the colour edge */
    assert_in_range(img.px[3 * 16 + 2], (299 * 200 + 587 * 100 + 114 * 30 + 500) / 1000 - 2,
                    (299 * 200 + 587 * 100 + 114 * 30 + 500) / 1000 + 2);
    assert_in_range(img.px[3 * 16 + 13], 75, 79);
    imgio_free(&img);
    /* cut short: an error naming the file, not a half-gray frame */
    f = fopen(path, "wb");
    assert_non_null(f);
    assert_int_equal(fwrite(jpg, 1, jlen / 2, f), jlen / 2);
    fclose(f);
    assert_int_equal(imgio_read_gray(path, &img, err, sizeof err), -1);
    assert_non_null(strstr(err, path));
    assert_non_null(strstr(err, "JPEG"));
    tjFree(jpg);
    tjDestroy(tj);
    unlink(path);
#else
    imgio_gray img;
    char err[256];
    static const uint8_t soi[] = {0xFF, 0xD8, 0xFF, 0xE0, 0, 16};
    const char *path = tmpname(".jpg");
    FILE *f = fopen(path, "wb");
    (void)state;
    assert_false(imgio_have_jpeg());
    assert_non_null(f);
    fwrite(soi, 1, sizeof soi, f);
    fclose(f);
    assert_int_equal(imgio_read_gray(path, &img, err, sizeof err), -1);
    assert_non_null(strstr(err, "libturbojpeg"));
    unlink(path);
#endif
}

/* The name decides the output format; an unknown one is refused before anything is written. */
static void test_output_format_by_name(void **state)
{
    uint8_t gray[6] = {0, 50, 100, 150, 200, 255};
    uint8_t rgb_px[6] = {255, 0, 0, 10, 200, 30};
    imgio_rgb rgb = {2, 1, rgb_px};
    imgio_gray img;
    char err[256];
    const char *path;
    FILE *f;
    char magic[3] = {0, 0, 0};
    (void)state;
    path = tmpname(".jpg");
    unlink(path);
    assert_int_equal(imgio_write_gray(path, gray, 3, 2, 3, err, sizeof err), -1);
    assert_non_null(strstr(err, "unknown image format '.jpg'"));
    assert_int_equal(access(path, F_OK), -1); /* nothing written */
    path = tmpname("");
    assert_int_equal(imgio_write_gray(path, gray, 3, 2, 3, err, sizeof err), -1);
    assert_non_null(strstr(err, "unknown image format: write .pgm"));
    path = tmpname(".pgm");
    assert_int_equal(imgio_write_rgb(path, &rgb, err, sizeof err), -1);
    assert_non_null(strstr(err, "a colour image cannot be written as PGM"));
    assert_int_equal(imgio_check_output_name("x.PPM", 1, err, sizeof err), 0);
    assert_int_equal(imgio_check_output_name("-", 0, err, sizeof err), 0);
    /* gray into .ppm: P6 with R = G = B; read back as the same gray */
    path = tmpname(".ppm");
    assert_int_equal(imgio_write_gray(path, gray, 3, 2, 3, err, sizeof err), 0);
    f = fopen(path, "rb");
    assert_non_null(f);
    assert_int_equal(fread(magic, 1, 2, f), 2);
    fclose(f);
    assert_string_equal(magic, "P6");
    unlink(path);
    /* .pnm: PGM for gray */
    path = tmpname(".pnm");
    assert_int_equal(imgio_write_gray(path, gray, 3, 2, 3, err, sizeof err), 0);
    assert_int_equal(imgio_read_gray(path, &img, err, sizeof err), 0);
    assert_memory_equal(img.px, gray, 6);
    imgio_free(&img);
    unlink(path);
    /* "-" writes stdout; a full disk there is reported with the reason */
    {
        const int full = open("/dev/full", O_WRONLY);
        const int saved = dup(1);
        int rc;
        if (full < 0 || saved < 0) {
            skip();
        }
        fflush(stdout);
        dup2(full, 1);
        rc = imgio_write_gray("-", gray, 3, 2, 3, err, sizeof err);
        clearerr(stdout);
        dup2(saved, 1);
        close(saved);
        close(full);
        assert_int_equal(rc, -1);
        assert_non_null(strstr(err, "-: write error: No space left on device"));
    }
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_pgm_header_forms),
        cmocka_unit_test(test_pgm_errors),
        cmocka_unit_test(test_unreadable_file),
        cmocka_unit_test(test_pgm_roundtrip_with_stride),
        cmocka_unit_test(test_png_roundtrip_and_luma),
        cmocka_unit_test(test_jpeg_input),
        cmocka_unit_test(test_output_format_by_name),
    };
    return cmocka_run_group_tests_name("imgio", tests, NULL, NULL);
}

/*
 * The host tools' image reader and writer: PGM header rules, error messages
 * that name the file and the problem, PNG round trips and the luma formula.
 */
#define _POSIX_C_SOURCE 200809L
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

#include <cmocka.h>

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

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_pgm_header_forms),
        cmocka_unit_test(test_pgm_errors),
        cmocka_unit_test(test_unreadable_file),
        cmocka_unit_test(test_pgm_roundtrip_with_stride),
        cmocka_unit_test(test_png_roundtrip_and_luma),
    };
    return cmocka_run_group_tests_name("imgio", tests, NULL, NULL);
}

/* SPDX-License-Identifier: Apache-2.0 */
/*
 * Format table and luma extraction of the capture layer.
 */
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <string.h>

#include <cmocka.h>

#include "pixfmt.h"

static void test_lookup(void **state)
{
    (void)state;
    assert_non_null(pixfmt_by_name("GREY"));
    assert_ptr_equal(pixfmt_by_name("yuyv"), pixfmt_find(PIXFMT_FOURCC('Y', 'U', 'Y', 'V')));
    assert_ptr_equal(pixfmt_by_name("I420"), pixfmt_by_name("YU12"));
    assert_ptr_equal(pixfmt_by_name("bggr"), pixfmt_by_name("BA81"));
    assert_int_equal(pixfmt_by_name("RGGB")->layout, PIXFMT_BAYER8);
    assert_int_equal(pixfmt_by_name("MJPG")->layout, PIXFMT_JPEG);
    assert_null(pixfmt_by_name("BA10")); /* 10-bit Bayer: not supported */
    assert_null(pixfmt_by_name("YUYVX"));
    assert_null(pixfmt_by_name(""));
    assert_null(pixfmt_by_name(NULL));
    assert_null(pixfmt_find(0));
    assert_int_equal(pixfmt_by_name("UYVY")->luma_offset, 1);
    assert_int_equal(pixfmt_by_name("YVYU")->luma_offset, 0);
    assert_int_equal(pixfmt_by_name("NV12")->layout, PIXFMT_LUMA_PLANE);
    assert_int_equal(pixfmt_by_name("VYUY")->layout, PIXFMT_PACKED_422);
}

static void test_table_names_match_fourcc(void **state)
{
    size_t i;
    (void)state;
    assert_true(pixfmt_count() >= 12);
    for (i = 0; i < pixfmt_count(); i++) {
        char cc[5];
        const pixfmt_info *f = pixfmt_at(i);
        pixfmt_fourcc_str(f->fourcc, cc);
        assert_string_equal(cc, f->name);
        assert_ptr_equal(pixfmt_by_name(f->name), f);
    }
    assert_null(pixfmt_at(pixfmt_count()));
}

static void test_gray_preferred(void **state)
{
    size_t i;
    const pixfmt_info *grey = pixfmt_by_name("GREY");
    (void)state;
    /* Without a user choice the no-copy formats win over packed ones. */
    for (i = 0; i < pixfmt_count(); i++) {
        const pixfmt_info *f = pixfmt_at(i);
        if (f != grey) {
            assert_true(f->preference > grey->preference);
        }
        if (f->layout != PIXFMT_LUMA_PLANE) {
            assert_true(f->preference > pixfmt_by_name("422P")->preference);
        }
    }
}

static void test_fourcc_str_unprintable(void **state)
{
    char cc[5];
    (void)state;
    pixfmt_fourcc_str(PIXFMT_FOURCC('A', 0x01, 'B', 0xff), cc);
    assert_string_equal(cc, "A?B?");
}

static void test_min_stride(void **state)
{
    (void)state;
    assert_int_equal(pixfmt_min_stride(pixfmt_by_name("GREY"), 641), 641);
    assert_int_equal(pixfmt_min_stride(pixfmt_by_name("NV12"), 640), 640);
    assert_int_equal(pixfmt_min_stride(pixfmt_by_name("YUYV"), 640), 1280);
}

/* A packed 4:2:2 frame with padding: luma = 10*y + x, chroma bytes 200+, padding 0xEE. */
static void make_packed(const pixfmt_info *f, uint8_t *buf, uint32_t w, uint32_t h, uint32_t stride)
{
    uint32_t x, y;
    memset(buf, 0xEE, (size_t)stride * h);
    for (y = 0; y < h; y++) {
        for (x = 0; x < w; x++) {
            buf[y * stride + 2 * x + f->luma_offset] = (uint8_t)(10 * y + x);
            buf[y * stride + 2 * x + (1 - f->luma_offset)] = (uint8_t)(200 + (x & 1));
        }
    }
}

static void check_unpack(const char *name)
{
    enum { W = 6, H = 4, SRC_STRIDE = 2 * W + 4, DST_STRIDE = W + 3 };
    uint8_t src[SRC_STRIDE * H];
    uint8_t dst[DST_STRIDE * H];
    uint32_t x, y;
    const pixfmt_info *f = pixfmt_by_name(name);
    assert_non_null(f);
    make_packed(f, src, W, H, SRC_STRIDE);
    memset(dst, 0x55, sizeof dst);
    pixfmt_unpack_luma(f, src, SRC_STRIDE, W, H, dst, DST_STRIDE);
    for (y = 0; y < H; y++) {
        for (x = 0; x < DST_STRIDE; x++) {
            /* Luma where it belongs; the destination's padding untouched. */
            assert_int_equal(dst[y * DST_STRIDE + x], x < W ? 10 * y + x : 0x55);
        }
    }
}

static void test_unpack_yuyv(void **state)
{
    (void)state;
    check_unpack("YUYV");
    check_unpack("YVYU");
}

static void test_unpack_uyvy(void **state)
{
    (void)state;
    check_unpack("UYVY");
    check_unpack("VYUY");
}

/* BT.601 luma with imgio's rounding, from each RGB byte order. */
static void test_rgb_luma(void **state)
{
    static const struct {
        const char *name;
        uint8_t px[4];
        uint8_t y;
    } cases[] = {
        {"RGB3", {255, 0, 0, 0}, 76},    /* (299*255 + 500) / 1000 = 76 */
        {"BGR3", {0, 0, 255, 0}, 76},
        {"XR24", {0, 255, 0, 9}, 150},   /* B G R X: green, (587*255 + 500) / 1000 = 150 */
        {"AR24", {255, 0, 0, 9}, 29},    /* blue: (114*255 + 500) / 1000 = 29 */
        {"XB24", {0, 0, 255, 9}, 29},    /* R G B X: blue */
        {"AB24", {255, 255, 255, 0}, 255},
        {"RGB3", {10, 20, 30, 0}, 18},   /* (2990 + 11740 + 3420 + 500) / 1000 = 18 */
    };
    size_t i;
    (void)state;
    for (i = 0; i < sizeof cases / sizeof cases[0]; i++) {
        const pixfmt_info *f = pixfmt_by_name(cases[i].name);
        uint8_t src[2 * (8 + 4)], dst[2 * 3];
        uint32_t k;
        assert_non_null(f);
        assert_int_equal(f->layout, PIXFMT_PACKED_RGB);
        assert_int_equal(pixfmt_min_stride(f, 2), 2 * f->bytes_per_pixel);
        memset(src, 0xAA, sizeof src);
        memset(dst, 0x55, sizeof dst);
        /* Two rows of two pixels, source stride 12, destination stride 3. */
        for (k = 0; k < 4; k++) {
            memcpy(src + (k / 2) * 12 + (k % 2) * f->bytes_per_pixel, cases[i].px, f->bytes_per_pixel);
        }
        pixfmt_unpack_luma(f, src, 12, 2, 2, dst, 3);
        assert_int_equal(dst[0], cases[i].y);
        assert_int_equal(dst[1], cases[i].y);
        assert_int_equal(dst[3], cases[i].y);
        assert_int_equal(dst[4], cases[i].y);
        assert_int_equal(dst[2], 0x55);
        assert_int_equal(dst[5], 0x55);
    }
}

/* Bayer frames: W x H mosaic of the colour rgb[3] (R, G, B) with padding 0xEE in the source rows. */
enum { BW = 7, BH = 6, BSRC = BW + 3, BDST = BW + 2 };

static void make_mosaic(const pixfmt_info *f, const uint8_t rgb[3], uint8_t *src)
{
    uint32_t x, y;
    memset(src, 0xEE, (size_t)BSRC * BH);
    for (y = 0; y < BH; y++) {
        for (x = 0; x < BW; x++) {
            const char c = f->cfa[(y & 1u) * 2u + (x & 1u)];
            src[y * BSRC + x] = rgb[c == 'R' ? 0 : (c == 'G' ? 1 : 2)];
        }
    }
}

/* A uniform colour gives its BT.601 luma (imgio's rounding) everywhere, borders included. */
static void test_bayer_uniform(void **state)
{
    static const char *names[] = {"BA81", "GBRG", "GRBG", "RGGB"};
    static const uint8_t colours[][3] = {{0, 0, 0}, {255, 255, 255}, {77, 77, 77}, {200, 100, 30},
                                         {255, 0, 0}, {0, 255, 0}, {0, 0, 255}, {10, 20, 30}};
    size_t i, c;
    (void)state;
    for (i = 0; i < 4; i++) {
        const pixfmt_info *f = pixfmt_by_name(names[i]);
        assert_non_null(f);
        assert_int_equal(f->layout, PIXFMT_BAYER8);
        assert_int_equal(pixfmt_min_stride(f, BW), BW);
        for (c = 0; c < sizeof colours / sizeof colours[0]; c++) {
            uint8_t src[BSRC * BH], dst[BDST * BH];
            const uint8_t *rgb = colours[c];
            const unsigned want = (299u * rgb[0] + 587u * rgb[1] + 114u * rgb[2] + 500u) / 1000u;
            uint32_t x, y;
            make_mosaic(f, rgb, src);
            memset(dst, 0x55, sizeof dst);
            pixfmt_unpack_luma(f, src, BSRC, BW, BH, dst, BDST);
            for (y = 0; y < BH; y++) {
                for (x = 0; x < BDST; x++) {
                    assert_int_equal(dst[y * BDST + x], x < BW ? want : 0x55);
                }
            }
        }
    }
}

/* A one-pixel bright gray row or column: the luma is centred on it (equal on both sides). */
static void test_bayer_centred(void **state)
{
    static const char *names[] = {"BA81", "GBRG", "GRBG", "RGGB"};
    size_t i;
    (void)state;
    for (i = 0; i < 4; i++) {
        const pixfmt_info *f = pixfmt_by_name(names[i]);
        uint8_t src[BSRC * BH], dst[BDST * BH];
        uint32_t x, y;
        /* Row 2 at 200, the rest 40: rows 1 and 3 get the same luma, row 2 the most, row 0 none of it. */
        memset(src, 40, sizeof src);
        memset(src + 2 * BSRC, 200, BW);
        pixfmt_unpack_luma(f, src, BSRC, BW, BH, dst, BDST);
        for (x = 0; x < BW; x++) {
            assert_int_equal(dst[1 * BDST + x], dst[3 * BDST + x]);
            assert_true(dst[2 * BDST + x] > dst[1 * BDST + x]);
            assert_int_equal(dst[0 * BDST + x], 40);
        }
        /* Column 3 at 200, the rest 40: columns 2 and 4 equal. */
        memset(src, 40, sizeof src);
        for (y = 0; y < BH; y++) {
            src[y * BSRC + 3] = 200;
        }
        pixfmt_unpack_luma(f, src, BSRC, BW, BH, dst, BDST);
        for (y = 0; y < BH; y++) {
            assert_int_equal(dst[y * BDST + 2], dst[y * BDST + 4]);
            assert_true(dst[y * BDST + 3] > dst[y * BDST + 2]);
            assert_int_equal(dst[y * BDST + 1], 40);
        }
    }
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_lookup),
        cmocka_unit_test(test_table_names_match_fourcc),
        cmocka_unit_test(test_gray_preferred),
        cmocka_unit_test(test_fourcc_str_unprintable),
        cmocka_unit_test(test_min_stride),
        cmocka_unit_test(test_unpack_yuyv),
        cmocka_unit_test(test_unpack_uyvy),
        cmocka_unit_test(test_rgb_luma),
        cmocka_unit_test(test_bayer_uniform),
        cmocka_unit_test(test_bayer_centred),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}

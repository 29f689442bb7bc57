/* SPDX-License-Identifier: Apache-2.0 */
/*
 * Replay source: directories, lists, single files, looping, errors.
 */
#define _POSIX_C_SOURCE 200809L
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cmocka.h>

#include "imgio.h"
#include "replay_source.h"

static char dir[256];

static void path_in(char *out, size_t n, const char *name)
{
    snprintf(out, n, "%s/%s", dir, name);
}

/* A w x h frame whose every pixel is `value`. */
static void write_frame(const char *name, uint32_t w, uint32_t h, uint8_t value)
{
    uint8_t px[64 * 64];
    char path[512], err[256];
    memset(px, value, sizeof px);
    path_in(path, sizeof path, name);
    assert_int_equal(imgio_write_gray(path, px, w, h, w, err, sizeof err), 0);
}

static void write_text(const char *name, const char *text)
{
    char path[512];
    FILE *f;
    path_in(path, sizeof path, name);
    f = fopen(path, "w");
    assert_non_null(f);
    fputs(text, f);
    fclose(f);
}

static int setup(void **state)
{
    (void)state;
    snprintf(dir, sizeof dir, "/tmp/symline-replay-XXXXXX");
    if (mkdtemp(dir) == NULL) {
        return -1;
    }
    /* Written out of order: the source sorts by name. */
    write_frame("b.pgm", 8, 6, 20);
    write_frame("a.pgm", 8, 6, 10);
    write_frame("c.pgm", 16, 4, 30);
    write_text("notes.txt", "not a frame\n");
    /* An evaluation's line mask beside its frame: not a frame. */
    write_frame("a.mask.pgm", 8, 6, 255);
    return 0;
}

static int teardown(void **state)
{
    const char *names[] = {"a.pgm", "b.pgm", "c.pgm", "a.mask.pgm", "notes.txt", "list.txt", "empty.txt", "clip.y4m"};
    char path[512];
    size_t i;
    (void)state;
    for (i = 0; i < sizeof names / sizeof names[0]; i++) {
        path_in(path, sizeof path, names[i]);
        unlink(path);
    }
    path_in(path, sizeof path, "none");
    rmdir(path);
    rmdir(dir);
    return 0;
}

static capsrc *open_replay(const char *path, int loop)
{
    replay_options o;
    char err[256];
    capsrc *src;
    memset(&o, 0, sizeof o);
    o.path = path;
    o.loop = loop;
    src = replay_source_open(&o, err, sizeof err);
    assert_non_null(src);
    assert_int_equal(capsrc_start(src), CAPSRC_OK);
    return src;
}

static void expect_frame(capsrc *src, uint64_t number, uint32_t w, uint32_t h, uint8_t value)
{
    capsrc_frame f;
    memset(&f, 0, sizeof f);
    assert_int_equal(capsrc_next(src, &f, 1000), CAPSRC_OK);
    assert_int_equal(f.number, number);
    assert_int_equal(f.width, w);
    assert_int_equal(f.height, h);
    assert_true(f.stride >= w);
    assert_int_equal(f.luma[0], value);
    assert_int_equal(f.luma[(h - 1) * f.stride + w - 1], value);
    assert_true(f.timestamp_ns > 0);
}

/* The file of the frame just handed out ends in /name. */
static void expect_file(const capsrc_frame *f, const char *name)
{
    char want[512];
    path_in(want, sizeof want, name);
    assert_non_null(f->file);
    assert_string_equal(f->file, want);
}

static void test_directory_in_name_order(void **state)
{
    capsrc_frame f;
    capsrc *src;
    (void)state;
    src = open_replay(dir, 0);
    assert_non_null(strstr(src->description, ": 3 frame files, unpaced"));
    memset(&f, 0, sizeof f);
    assert_int_equal(capsrc_next(src, &f, 1000), CAPSRC_OK);
    expect_file(&f, "a.pgm");
    assert_int_equal(capsrc_next(src, &f, 1000), CAPSRC_OK);
    expect_file(&f, "b.pgm");
    assert_int_equal(capsrc_next(src, &f, 1000), CAPSRC_OK);
    expect_file(&f, "c.pgm"); /* a.mask.pgm was skipped */
    assert_int_equal(capsrc_next(src, &f, 1000), CAPSRC_END);
    capsrc_close(src);

    src = open_replay(dir, 0);
    expect_frame(src, 0, 8, 6, 10);
    capsrc_release(src);
    capsrc_release(src); /* a second release is harmless */
    expect_frame(src, 1, 8, 6, 20);
    /* No release: the next call gives the previous frame back itself. */
    expect_frame(src, 2, 16, 4, 30);
    assert_int_equal(capsrc_next(src, &f, 1000), CAPSRC_END);
    assert_int_equal(capsrc_next(src, &f, 1000), CAPSRC_END);
    assert_int_equal(src->stats.delivered, 3);
    capsrc_close(src);
}

static void test_loop(void **state)
{
    capsrc *src;
    (void)state;
    src = open_replay(dir, 1);
    expect_frame(src, 0, 8, 6, 10);
    expect_frame(src, 1, 8, 6, 20);
    expect_frame(src, 2, 16, 4, 30);
    expect_frame(src, 3, 8, 6, 10);
    capsrc_close(src);
}

static void test_list_file(void **state)
{
    char list[512];
    capsrc_frame f;
    capsrc *src;
    (void)state;
    write_text("list.txt", "# replay order\n  c.pgm  \n\nb.pgm\r\n");
    path_in(list, sizeof list, "list.txt");
    src = open_replay(list, 0);
    expect_frame(src, 0, 16, 4, 30);
    expect_frame(src, 1, 8, 6, 20);
    assert_int_equal(capsrc_next(src, &f, 1000), CAPSRC_END);
    capsrc_close(src);
}

static void test_single_file(void **state)
{
    char one[512];
    capsrc_frame f;
    capsrc *src;
    (void)state;
    path_in(one, sizeof one, "b.pgm");
    src = open_replay(one, 0);
    expect_frame(src, 0, 8, 6, 20);
    assert_int_equal(capsrc_next(src, &f, 1000), CAPSRC_END);
    capsrc_close(src);
}

static void test_errors(void **state)
{
    replay_options o;
    char err[256], path[512];
    capsrc_frame f;
    capsrc *src;
    (void)state;
    memset(&o, 0, sizeof o);

    path_in(path, sizeof path, "missing");
    o.path = path;
    err[0] = '\0';
    assert_null(replay_source_open(&o, err, sizeof err));
    assert_non_null(strstr(err, "missing"));

    path_in(path, sizeof path, "none");
    assert_int_equal(mkdir(path, 0700), 0);
    err[0] = '\0';
    assert_null(replay_source_open(&o, err, sizeof err));
    assert_non_null(strstr(err, "no .pgm, .png or .jpg frames"));

    write_text("empty.txt", "# nothing\n");
    path_in(path, sizeof path, "empty.txt");
    assert_null(replay_source_open(&o, err, sizeof err));

    /* A listed file that is not an image: an error naming it, at that frame. */
    write_text("list.txt", "a.pgm\nnotes.txt\n");
    path_in(path, sizeof path, "list.txt");
    src = open_replay(path, 0);
    expect_frame(src, 0, 8, 6, 10);
    assert_int_equal(capsrc_next(src, &f, 1000), CAPSRC_ERROR);
    assert_non_null(strstr(capsrc_error(src), "notes.txt"));
    capsrc_close(src);
    capsrc_close(NULL);
}

/* A 4x2 Y4M stream: frame k has luma 100+k, chroma 128. */
static void write_y4m(const char *name, const char *colour, int frames, int chroma, int truncate_last)
{
    char path[512];
    FILE *f;
    int k, i;
    path_in(path, sizeof path, name);
    f = fopen(path, "wb");
    assert_non_null(f);
    fprintf(f, "YUV4MPEG2 W4 H2 F30:1 Ip A1:1%s%s\n", colour[0] ? " C" : "", colour);
    for (k = 0; k < frames; k++) {
        fputs(k == 1 ? "FRAME Ixyz\n" : "FRAME\n", f);
        for (i = 0; i < 8 - (truncate_last && k == frames - 1 ? 3 : 0); i++) fputc(100 + k, f);
        for (i = 0; i < chroma && !(truncate_last && k == frames - 1); i++) fputc(128, f);
    }
    fclose(f);
}

static void expect_y4m_frame(capsrc *src, uint64_t number, uint8_t value)
{
    capsrc_frame f;
    uint32_t i;
    assert_int_equal(capsrc_next(src, &f, 1000), CAPSRC_OK);
    assert_int_equal(f.number, number);
    assert_int_equal(f.width, 4);
    assert_int_equal(f.height, 2);
    for (i = 0; i < 8; i++) {
        assert_int_equal(f.luma[i], value);
    }
}

static void test_y4m(void **state)
{
    char path[512], err[256];
    capsrc_frame f;
    replay_options o;
    capsrc *src;
    (void)state;
    path_in(path, sizeof path, "clip.y4m");

    write_y4m("clip.y4m", "", 3, 4, 0); /* no C tag: 4:2:0 */
    src = open_replay(path, 0);
    assert_non_null(strstr(src->description, "YUV4MPEG2 4x2"));
    expect_y4m_frame(src, 0, 100);
    expect_y4m_frame(src, 1, 101);
    expect_y4m_frame(src, 2, 102);
    assert_int_equal(capsrc_next(src, &f, 1000), CAPSRC_END);
    capsrc_close(src);

    write_y4m("clip.y4m", "mono", 2, 0, 0);
    src = open_replay(path, 1);
    expect_y4m_frame(src, 0, 100);
    expect_y4m_frame(src, 1, 101);
    expect_y4m_frame(src, 2, 100); /* looped */
    capsrc_close(src);

    write_y4m("clip.y4m", "444", 2, 16, 0);
    src = open_replay(path, 0);
    expect_y4m_frame(src, 0, 100);
    expect_y4m_frame(src, 1, 101);
    capsrc_close(src);

    write_y4m("clip.y4m", "420jpeg", 2, 4, 1);
    src = open_replay(path, 0);
    expect_y4m_frame(src, 0, 100);
    assert_int_equal(capsrc_next(src, &f, 1000), CAPSRC_ERROR);
    assert_non_null(strstr(capsrc_error(src), "frame 1 is truncated"));
    capsrc_close(src);

    memset(&o, 0, sizeof o);
    o.path = path;
    write_y4m("clip.y4m", "420p10", 1, 8, 0);
    assert_null(replay_source_open(&o, err, sizeof err));
    assert_non_null(strstr(err, "C420p10 not supported"));
    write_text("clip.y4m", "P5\n4 2\n255\n");
    assert_null(replay_source_open(&o, err, sizeof err));
    assert_non_null(strstr(err, "not a YUV4MPEG2 file"));
}

static int64_t elapsed_for_frames(capsrc *src, int n)
{
    capsrc_frame f;
    int64_t t0 = capsrc_now_ns();
    int k;
    for (k = 0; k < n; k++) {
        assert_int_equal(capsrc_next(src, &f, 2000), CAPSRC_OK);
    }
    return capsrc_now_ns() - t0;
}

/* A Y4M plays at its own frame rate unless told otherwise; each frame names its file. */
static void test_y4m_rate_and_file(void **state)
{
    char path[512], err[256];
    capsrc_frame f;
    replay_options o;
    capsrc *src;
    FILE *fp;
    int k, i;
    (void)state;
    path_in(path, sizeof path, "clip.y4m");
    fp = fopen(path, "wb");
    assert_non_null(fp);
    fputs("YUV4MPEG2 W4 H2 F20:1 Cmono\n", fp);
    for (k = 0; k < 4; k++) {
        fputs("FRAME\n", fp);
        for (i = 0; i < 8; i++) fputc(100 + k, fp);
    }
    fclose(fp);

    /* F20:1: the first frame at once, then one every 50 ms (sleeps never end early). */
    src = open_replay(path, 0);
    assert_non_null(strstr(src->description, "YUV4MPEG2 4x2, 20/1 fps"));
    assert_true(elapsed_for_frames(src, 4) >= 3 * 50000000 - 1000000);
    assert_int_equal(capsrc_next(src, &f, 1000), CAPSRC_END);
    capsrc_close(src);

    memset(&o, 0, sizeof o);
    o.path = path;
    o.fps_num = 1000;
    o.fps_den = 1;
    src = replay_source_open(&o, err, sizeof err);
    assert_non_null(src);
    assert_non_null(strstr(src->description, "1000/1 fps"));
    assert_int_equal(capsrc_start(src), CAPSRC_OK);
    memset(&f, 0, sizeof f);
    assert_int_equal(capsrc_next(src, &f, 1000), CAPSRC_OK);
    assert_string_equal(f.file, path);
    assert_int_equal(f.sequence, 0);
    capsrc_close(src);

    memset(&o, 0, sizeof o);
    o.path = path;
    o.unpaced = 1;
    src = replay_source_open(&o, err, sizeof err);
    assert_non_null(src);
    assert_non_null(strstr(src->description, "unpaced"));
    capsrc_close(src);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_directory_in_name_order),
        cmocka_unit_test(test_loop),
        cmocka_unit_test(test_list_file),
        cmocka_unit_test(test_single_file),
        cmocka_unit_test(test_errors),
        cmocka_unit_test(test_y4m),
        cmocka_unit_test(test_y4m_rate_and_file),
    };
    return cmocka_run_group_tests(tests, setup, teardown);
}

/* SPDX-License-Identifier: Apache-2.0 */
/*
 * capture-check: checks used by the integration test inside the emulated
 * machine (busybox only, so the checks are here, in C).
 *
 *   capture-check press DEVICE NAME    press the button control called NAME
 *                                      (vivid's error injection controls)
 *   capture-check set DEVICE NAME V    set the integer or menu control NAME to V
 *   capture-check bars PGM [REF.pgm] [=Y0,...,Y7]
 *                                      the frame shows vivid's 75% colour bars
 *                                      (eight uniform bars, luma falling left to
 *                                      right); with REF: same luma as REF within 2;
 *                                      with =Y0,...: each bar's luma within 3 of Yi
 *   capture-check json FILE N          FILE holds N lines, each a well-formed JSON
 *                                      object with the per-frame keys, frame
 *                                      numbers 0..N-1 and rising sequence numbers
 *   capture-check stages FILE N STAGE... the same, and each line's detect_stages_ms
 *                                      holds exactly these stages, whose times add
 *                                      up to no more than stages_ms.detect
 *
 * Exit 0 when the check holds, 1 (with a reason on stderr) when not.
 */
#define _POSIX_C_SOURCE 200809L
#include <errno.h>
#include <fcntl.h>
#include <linux/videodev2.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/ioctl.h>
#include <unistd.h>

#include "imgio.h"
#include "json_check.h"

static int fail(const char *fmt, const char *a, long b)
{
    fputs("capture-check: ", stderr);
    fprintf(stderr, fmt, a, b);
    fputc('\n', stderr);
    return 1;
}

static int set_control(const char *dev, const char *name, int button, int32_t value)
{
    struct v4l2_query_ext_ctrl q;
    int fd = open(dev, O_RDWR);
    if (fd < 0) {
        return fail("%s: cannot open (%ld)", dev, errno);
    }
    memset(&q, 0, sizeof q);
    q.id = V4L2_CTRL_FLAG_NEXT_CTRL | V4L2_CTRL_FLAG_NEXT_COMPOUND;
    while (ioctl(fd, VIDIOC_QUERY_EXT_CTRL, &q) == 0) {
        if (strcmp(q.name, name) == 0) {
            struct v4l2_control c;
            c.id = q.id;
            c.value = value;
            if (button != (q.type == V4L2_CTRL_TYPE_BUTTON)) {
                close(fd);
                return fail("control '%s' has the wrong type (%ld)", name, (long)q.type);
            }
            if (ioctl(fd, VIDIOC_S_CTRL, &c) != 0) {
                int e = errno;
                close(fd);
                return fail("setting '%s' failed (errno %ld)", name, e);
            }
            close(fd);
            return 0;
        }
        q.id |= V4L2_CTRL_FLAG_NEXT_CTRL | V4L2_CTRL_FLAG_NEXT_COMPOUND;
    }
    close(fd);
    return fail("no control named '%s' (errno %ld)", name, errno);
}

/*
 * vivid's default pattern: eight vertical bars of equal width, 75% white,
 * yellow, cyan, green, magenta, red, blue, black, so luma falls from bar to
 * bar. The on-screen text sits at the top: rows from 3/4 of the height down
 * are pure bars.
 */
static int bars(const char *path, const char *ref, const char *expect)
{
    long want[8];
    imgio_gray img, rimg;
    char err[512];
    uint32_t b, y, x;
    int prev = 256, rc = 0;
    if (expect != NULL) {
        char *end = NULL;
        for (b = 0; b < 8; b++) {
            want[b] = strtol(expect, &end, 10);
            if (end == expect || (b < 7 && *end != ',') || (b == 7 && *end != '\0')) {
                return fail("bad expected bar list '%s'%ld", expect, 0);
            }
            expect = end + 1;
        }
        expect = "";
    }
    if (imgio_read_gray(path, &img, err, sizeof err) != 0) {
        return fail("%s%ld", err, 0);
    }
    if (ref != NULL && imgio_read_gray(ref, &rimg, err, sizeof err) != 0) {
        imgio_free(&img);
        return fail("%s%ld", err, 0);
    }
    if (ref != NULL && (rimg.width != img.width || rimg.height != img.height)) {
        rc = fail("%s: size differs from the reference frame%ld", path, 0);
    }
    for (b = 0; b < 8 && rc == 0; b++) {
        /* The middle half of the bar, on rows from 3/4 of the height to the bottom. */
        uint32_t x0 = (uint32_t)((2 * b + 1) * (uint64_t)img.width / 16 - img.width / 32);
        uint32_t x1 = (uint32_t)((2 * b + 1) * (uint64_t)img.width / 16 + img.width / 32);
        int lo = 255, hi = 0, v;
        for (y = img.height * 3 / 4; y < img.height; y++) {
            for (x = x0; x <= x1; x++) {
                v = img.px[(size_t)y * img.width + x];
                lo = v < lo ? v : lo;
                hi = v > hi ? v : hi;
                if (ref != NULL) {
                    int d = v - rimg.px[(size_t)y * img.width + x];
                    if (d > 2 || d < -2) {
                        fprintf(stderr, "capture-check: %s: luma %d at (%u,%u), reference %d\n", path, v, x, y,
                                v - d);
                        rc = 1;
                        break;
                    }
                }
            }
            if (rc) {
                break;
            }
        }
        if (rc == 0 && hi - lo > 2) {
            fprintf(stderr, "capture-check: %s: bar %u not uniform (luma %d..%d)\n", path, b, lo, hi);
            rc = 1;
        }
        if (rc == 0 && expect != NULL && (lo < want[b] - 3 || hi > want[b] + 3)) {
            fprintf(stderr, "capture-check: %s: bar %u luma %d..%d, expected %ld\n", path, b, lo, hi, want[b]);
            rc = 1;
        }
        if (rc == 0 && lo >= prev) {
            fprintf(stderr, "capture-check: %s: bar %u luma %d not below bar %u (%d)\n", path, b, lo, b - 1, prev);
            rc = 1;
        }
        printf("%s%d", b ? " " : "bars ", lo);
        prev = lo;
    }
    printf("\n");
    imgio_free(&img);
    if (ref != NULL) {
        imgio_free(&rimg);
    }
    return rc;
}

/* names: NULL, or the detector's stages each line must split its detect time into (--profile). */
static int json(const char *path, const char *count, const char *const *names, size_t nnames)
{
    char line[1 << 16];
    long want = strtol(count, NULL, 10), n = 0;
    long long prev_seq = -1;
    FILE *f = fopen(path, "r");
    if (f == NULL) {
        return fail("%s: cannot open (%ld)", path, errno);
    }
    while (fgets(line, sizeof line, f) != NULL) {
        json_frame_info info;
        const char *why = json_check_frame_line(line, &info);
        if (why == NULL && names != NULL) {
            why = json_check_stages(line, names, nnames);
        }
        if (why != NULL) {
            fprintf(stderr, "capture-check: %s line %ld: %s\n", path, n + 1, why);
            fclose(f);
            return 1;
        }
        if (info.frame != n) {
            fclose(f);
            return fail("%s: frame numbers out of order at line %ld", path, n + 1);
        }
        if (info.sequence <= prev_seq) {
            fclose(f);
            return fail("%s: sequence number not rising at line %ld (a frame handed out twice?)", path, n + 1);
        }
        prev_seq = info.sequence;
        n++;
    }
    fclose(f);
    if (n != want) {
        fprintf(stderr, "capture-check: %s: %ld frame lines, expected %ld\n", path, n, want);
        return 1;
    }
    return 0;
}

int main(int argc, char **argv)
{
    if (argc == 4 && strcmp(argv[1], "press") == 0) {
        return set_control(argv[2], argv[3], 1, 1);
    }
    if (argc == 5 && strcmp(argv[1], "set") == 0) {
        return set_control(argv[2], argv[3], 0, (int32_t)strtol(argv[4], NULL, 10));
    }
    if (argc >= 3 && argc <= 5 && strcmp(argv[1], "bars") == 0) {
        const char *ref = NULL, *expect = NULL;
        int i;
        for (i = 3; i < argc; i++) {
            if (argv[i][0] == '=') {
                expect = argv[i] + 1;
            } else {
                ref = argv[i];
            }
        }
        return bars(argv[2], ref, expect);
    }
    if (argc == 4 && strcmp(argv[1], "json") == 0) {
        return json(argv[2], argv[3], NULL, 0);
    }
    if (argc >= 5 && strcmp(argv[1], "stages") == 0) {
        return json(argv[2], argv[3], (const char *const *)argv + 4, (size_t)argc - 4);
    }
    fputs("usage: capture-check press DEVICE NAME | set DEVICE NAME VALUE | bars PGM [REF.pgm] [=Y0,...,Y7] | json FILE N | stages FILE N STAGE...\n", stderr);
    return 2;
}

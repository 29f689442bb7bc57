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
 *   capture-check steady FILE N [S]    json FILE N, and every line found the same
 *                                      number (> 0) of segments (one still frame);
 *                                      with S: exactly S segments
 *   capture-check same PGM REF.pgm     same size and luma within 2 of REF everywhere
 *   capture-check jpeg IN.pgm OUT.jpg REF.pgm
 *                                      (on the build machine) compresses IN as a
 *                                      webcam does (YCbCr 4:2:2, quality 90) into
 *                                      OUT, and writes OUT's luma as libjpeg-turbo
 *                                      decodes it to REF; exit 77 without libturbojpeg
 *   capture-check feed DEVICE OUT.jpg W H
 *                                      sets DEVICE's output side (v4l2loopback) to
 *                                      Motion-JPEG WxH and writes OUT.jpg to it as
 *                                      one frame every 40 ms until killed
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
#include <time.h>
#include <unistd.h>

#include "imgio.h"
#include "json_check.h"

#ifdef SYMLINE_HAVE_TURBOJPEG
#include <turbojpeg.h>
#endif

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

/* names: NULL, or the detector's stages each line must split its detect time into (--profile).
 * steady: every line must report the same number (> 0) of segments. */
static int json(const char *path, const char *count, const char *const *names, size_t nnames, int steady,
                const char *segments)
{
    long first_segments = segments != NULL ? strtol(segments, NULL, 10) : -1;
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
        if (steady && (info.segments <= 0 || (first_segments >= 0 && info.segments != first_segments))) {
            if (first_segments < 0) {
                fprintf(stderr, "capture-check: %s line %ld: no segments\n", path, n + 1);
            } else {
                fprintf(stderr, "capture-check: %s line %ld: %ld segments, expected %ld\n", path, n + 1,
                        info.segments, first_segments);
            }
            fclose(f);
            return 1;
        }
        if (first_segments < 0) {
            first_segments = info.segments;
        }
        n++;
    }
    fclose(f);
    if (steady) {
        printf("steady: %ld lines, %ld segments each\n", n, first_segments);
    }
    if (n != want) {
        fprintf(stderr, "capture-check: %s: %ld frame lines, expected %ld\n", path, n, want);
        return 1;
    }
    return 0;
}

static int same(const char *path, const char *ref)
{
    imgio_gray img, rimg;
    char err[512];
    size_t i, worst = 0;
    int rc = 0, maxd = 0;
    if (imgio_read_gray(path, &img, err, sizeof err) != 0) {
        return fail("%s%ld", err, 0);
    }
    if (imgio_read_gray(ref, &rimg, err, sizeof err) != 0) {
        imgio_free(&img);
        return fail("%s%ld", err, 0);
    }
    if (rimg.width != img.width || rimg.height != img.height) {
        rc = fail("%s: size differs from the reference frame%ld", path, 0);
    } else {
        for (i = 0; i < (size_t)img.width * img.height; i++) {
            int d = abs((int)img.px[i] - (int)rimg.px[i]);
            if (d > maxd) {
                maxd = d;
                worst = i;
            }
        }
        printf("same: largest luma difference %d\n", maxd);
        if (maxd > 2) {
            fprintf(stderr, "capture-check: %s: luma %d at (%lu,%lu), reference %d\n", path, img.px[worst],
                    (unsigned long)(worst % img.width), (unsigned long)(worst / img.width), rimg.px[worst]);
            rc = 1;
        }
    }
    imgio_free(&img);
    imgio_free(&rimg);
    return rc;
}

static int make_jpeg(const char *in, const char *out, const char *ref)
{
#ifdef SYMLINE_HAVE_TURBOJPEG
    imgio_gray img;
    char err[512];
    unsigned char *rgb, *jpg = NULL, *luma;
    unsigned long size = 0;
    size_t i, n;
    int rc = 1;
    FILE *f;
    tjhandle c, d;
    if (imgio_read_gray(in, &img, err, sizeof err) != 0) {
        return fail("%s%ld", err, 0);
    }
    n = (size_t)img.width * img.height;
    rgb = malloc(3 * n);
    luma = malloc(n);
    c = tjInitCompress();
    d = tjInitDecompress();
    if (rgb != NULL && luma != NULL && c != NULL && d != NULL) {
        for (i = 0; i < n; i++) {
            rgb[3 * i] = rgb[3 * i + 1] = rgb[3 * i + 2] = img.px[i];
        }
        if (tjCompress2(c, rgb, (int)img.width, 0, (int)img.height, TJPF_RGB, &jpg, &size, TJSAMP_422, 90, 0) != 0) {
            fail("tjCompress2: %s%ld", tjGetErrorStr2(c), 0);
        } else if (tjDecompress2(d, jpg, size, luma, (int)img.width, 0, (int)img.height, TJPF_GRAY, 0) != 0) {
            fail("tjDecompress2: %s%ld", tjGetErrorStr2(d), 0);
        } else if ((f = fopen(out, "wb")) == NULL || fwrite(jpg, 1, size, f) != size || fclose(f) != 0) {
            fail("%s: cannot write (%ld)", out, errno);
        } else if (imgio_write_gray(ref, luma, img.width, img.height, img.width, err, sizeof err) != 0) {
            fail("%s%ld", err, 0);
        } else {
            printf("jpeg: %s %ux%u, %lu bytes\n", out, img.width, img.height, size);
            rc = 0;
        }
    }
    tjFree(jpg);
    if (c != NULL) {
        tjDestroy(c);
    }
    if (d != NULL) {
        tjDestroy(d);
    }
    free(rgb);
    free(luma);
    imgio_free(&img);
    return rc;
#else
    (void)in;
    (void)out;
    (void)ref;
    fputs("capture-check: built without libturbojpeg\n", stderr);
    return 77;
#endif
}

/* The writer of a v4l2loopback device: what a program sending a camera stream does. */
static int feed(const char *dev, const char *jpeg, const char *w, const char *h)
{
    static unsigned char buf[1 << 21];
    struct v4l2_format fmt;
    size_t len;
    FILE *f = fopen(jpeg, "rb");
    int fd;
    if (f == NULL) {
        return fail("%s: cannot open (%ld)", jpeg, errno);
    }
    len = fread(buf, 1, sizeof buf, f);
    fclose(f);
    if (len == 0 || len == sizeof buf) {
        return fail("%s: empty or larger than the buffer (%ld bytes)", jpeg, (long)len);
    }
    fd = open(dev, O_RDWR);
    if (fd < 0) {
        return fail("%s: cannot open (%ld)", dev, errno);
    }
    memset(&fmt, 0, sizeof fmt);
    fmt.type = V4L2_BUF_TYPE_VIDEO_OUTPUT;
    fmt.fmt.pix.width = (uint32_t)strtoul(w, NULL, 10);
    fmt.fmt.pix.height = (uint32_t)strtoul(h, NULL, 10);
    fmt.fmt.pix.pixelformat = V4L2_PIX_FMT_MJPEG;
    fmt.fmt.pix.field = V4L2_FIELD_NONE;
    if (ioctl(fd, VIDIOC_S_FMT, &fmt) != 0) {
        int e = errno;
        close(fd);
        return fail("%s: VIDIOC_S_FMT (output, MJPG) failed (errno %ld)", dev, e);
    }
    if (fmt.fmt.pix.pixelformat != V4L2_PIX_FMT_MJPEG || fmt.fmt.pix.sizeimage < len) {
        close(fd);
        return fail("%s: output format not taken (sizeimage %ld)", dev, (long)fmt.fmt.pix.sizeimage);
    }
    for (;;) {
        if (write(fd, buf, len) != (ssize_t)len) {
            int e = errno;
            close(fd);
            return fail("%s: write failed (errno %ld)", dev, e);
        }
        nanosleep(&(struct timespec){0, 40000000L}, NULL);
    }
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
        return json(argv[2], argv[3], NULL, 0, 0, NULL);
    }
    if ((argc == 4 || argc == 5) && strcmp(argv[1], "steady") == 0) {
        return json(argv[2], argv[3], NULL, 0, 1, argc == 5 ? argv[4] : NULL);
    }
    if (argc == 4 && strcmp(argv[1], "same") == 0) {
        return same(argv[2], argv[3]);
    }
    if (argc == 5 && strcmp(argv[1], "jpeg") == 0) {
        return make_jpeg(argv[2], argv[3], argv[4]);
    }
    if (argc == 6 && strcmp(argv[1], "feed") == 0) {
        return feed(argv[2], argv[3], argv[4], argv[5]);
    }
    if (argc >= 5 && strcmp(argv[1], "stages") == 0) {
        return json(argv[2], argv[3], (const char *const *)argv + 4, (size_t)argc - 4, 0, NULL);
    }
    fputs("usage: capture-check press DEVICE NAME | set DEVICE NAME VALUE | bars PGM [REF.pgm] [=Y0,...,Y7] | json FILE N | stages FILE N STAGE...\n"
          "       | steady FILE N [S] | same PGM REF.pgm | jpeg IN.pgm OUT.jpg REF.pgm | feed DEVICE OUT.jpg W H\n",
          stderr);
    return 2;
}

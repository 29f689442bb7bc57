/* SPDX-License-Identifier: Apache-2.0 */
/*
 * Listing V4L2 devices and their formats.
 */
#define _GNU_SOURCE
#include "v4l2_list.h"

#include <dirent.h>
#include <errno.h>
#include <fcntl.h>
#include <linux/videodev2.h>
#include <stdint.h>
#include <stdlib.h>
#include <string.h>
#include <sys/ioctl.h>
#include <unistd.h>

#include "jpeg_luma.h"
#include "pixfmt.h"

static int xioctl(int fd, unsigned long req, void *arg)
{
    int r;
    do {
        r = ioctl(fd, req, arg);
    } while (r == -1 && errno == EINTR);
    return r;
}

const char *v4l2_device_path(const char *arg, char *buf, size_t cap)
{
    size_t i, n = strlen(arg);
    int digits = n > 0 && n <= 5;
    for (i = 0; i < n && digits; i++) {
        digits = arg[i] >= '0' && arg[i] <= '9';
    }
    if ((size_t)snprintf(buf, cap, digits ? "/dev/video%s" : "%s", arg) >= cap) {
        return NULL;
    }
    return buf;
}

/* How symline gets luma out of a format, for the listings. */
static const char *how(const pixfmt_info *f)
{
    if (f == NULL) {
        return "not read by symline";
    }
    switch (f->layout) {
    case PIXFMT_LUMA_PLANE:
        return "luma read in place";
    case PIXFMT_PACKED_422:
        return "luma copied out";
    case PIXFMT_PACKED_RGB:
        return "converted to luma";
    case PIXFMT_BAYER8:
        return "Bayer mosaic converted to luma";
    case PIXFMT_JPEG:
        return jpeg_luma_available() ? "decoded to luma (libjpeg-turbo)"
                                     : "not read: this build has no JPEG decoder (libturbojpeg)";
    }
    return "not read by symline";
}

static int readable(const pixfmt_info *f)
{
    return f != NULL && (f->layout != PIXFMT_JPEG || jpeg_luma_available());
}

/* The capture buffer type of an open device, 0 when it does not capture video. */
static uint32_t capture_type(int fd, struct v4l2_capability *cap)
{
    uint32_t caps;
    memset(cap, 0, sizeof *cap);
    if (xioctl(fd, VIDIOC_QUERYCAP, cap) != 0) {
        return 0;
    }
    caps = (cap->capabilities & V4L2_CAP_DEVICE_CAPS) ? cap->device_caps : cap->capabilities;
    if (caps & V4L2_CAP_VIDEO_CAPTURE) {
        return V4L2_BUF_TYPE_VIDEO_CAPTURE;
    }
    if (caps & V4L2_CAP_VIDEO_CAPTURE_MPLANE) {
        return V4L2_BUF_TYPE_VIDEO_CAPTURE_MPLANE;
    }
    return 0;
}

static int video_number(const char *name)
{
    char *end;
    long n;
    if (strncmp(name, "video", 5) != 0 || name[5] < '0' || name[5] > '9') {
        return -1;
    }
    n = strtol(name + 5, &end, 10);
    return (*end == '\0' && n >= 0 && n < 100000) ? (int)n : -1;
}

static int cmp_int(const void *a, const void *b)
{
    const int x = *(const int *)a, y = *(const int *)b;
    return (x > y) - (x < y);
}

int v4l2_list_devices(FILE *out, const char *dir, char *err, size_t errlen)
{
    int nums[256];
    size_t n = 0, i;
    int found = 0;
    struct dirent *e;
    DIR *d = opendir(dir);
    if (d == NULL) {
        snprintf(err, errlen, "%s: %s", dir, strerror(errno));
        return -1;
    }
    while ((e = readdir(d)) != NULL && n < sizeof nums / sizeof nums[0]) {
        const int k = video_number(e->d_name);
        if (k >= 0) {
            nums[n++] = k;
        }
    }
    closedir(d);
    qsort(nums, n, sizeof nums[0], cmp_int);
    for (i = 0; i < n; i++) {
        char path[4096];
        struct v4l2_capability cap;
        uint32_t type;
        int fd;
        snprintf(path, sizeof path, "%s/video%d", dir, nums[i]);
        fd = open(path, O_RDWR | O_NONBLOCK | O_CLOEXEC);
        if (fd < 0) {
            fprintf(out, "%s: cannot open: %s\n", path, strerror(errno));
            continue;
        }
        type = capture_type(fd, &cap);
        if (cap.driver[0] == '\0') {
            fprintf(out, "%s: not a V4L2 device\n", path);
        } else if (type == 0) {
            fprintf(out, "%s: %s (%s, %s): no video capture (another node of the device)\n", path,
                     (const char *)cap.card, (const char *)cap.driver, (const char *)cap.bus_info);
        } else {
            struct v4l2_fmtdesc fd_desc;
            int any = 0;
            found++;
            fprintf(out, "%s: %s (%s, %s): video capture%s; formats symline reads:", path, (const char *)cap.card,
                    (const char *)cap.driver, (const char *)cap.bus_info,
                    type == V4L2_BUF_TYPE_VIDEO_CAPTURE_MPLANE ? " (multi-planar)" : "");
            memset(&fd_desc, 0, sizeof fd_desc);
            fd_desc.type = type;
            for (fd_desc.index = 0; xioctl(fd, VIDIOC_ENUM_FMT, &fd_desc) == 0; fd_desc.index++) {
                const pixfmt_info *f = pixfmt_find(fd_desc.pixelformat);
                if (readable(f)) {
                    fprintf(out, " %s", f->name);
                    any = 1;
                }
            }
            fputs(any ? "\n" : " none\n", out);
        }
        close(fd);
    }
    if (n == 0) {
        fprintf(out, "no video devices in %s\n", dir);
    }
    return found;
}

/* The frame rates of one frame size, appended to line. */
static void list_intervals(int fd, uint32_t fourcc, uint32_t w, uint32_t h, FILE *out)
{
    struct v4l2_frmivalenum iv;
    memset(&iv, 0, sizeof iv);
    iv.pixel_format = fourcc;
    iv.width = w;
    iv.height = h;
    for (iv.index = 0; xioctl(fd, VIDIOC_ENUM_FRAMEINTERVALS, &iv) == 0; iv.index++) {
        if (iv.type == V4L2_FRMIVAL_TYPE_DISCRETE) {
            const struct v4l2_fract *t = &iv.discrete;
            if (t->denominator % (t->numerator ? t->numerator : 1u) == 0u) {
                fprintf(out, " %u", t->denominator / (t->numerator ? t->numerator : 1u));
            } else {
                fprintf(out, " %u/%u", t->denominator, t->numerator);
            }
        } else {
            fprintf(out, " %u/%u..%u/%u", iv.stepwise.max.denominator, iv.stepwise.max.numerator,
                    iv.stepwise.min.denominator, iv.stepwise.min.numerator);
            break;
        }
    }
    if (iv.index > 0) {
        fputs(" fps", out);
    }
}

int v4l2_list_formats(FILE *out, const char *device, char *err, size_t errlen)
{
    struct v4l2_capability cap;
    struct v4l2_fmtdesc d;
    uint32_t type;
    int fd = open(device, O_RDWR | O_NONBLOCK | O_CLOEXEC);
    if (fd < 0) {
        snprintf(err, errlen, "%s: %s", device, strerror(errno));
        return -1;
    }
    type = capture_type(fd, &cap);
    if (type == 0) {
        snprintf(err, errlen, "%s: %s", device,
                 cap.driver[0] ? "not a video capture device" : "not a V4L2 device");
        close(fd);
        return -1;
    }
    fprintf(out, "%s: %s (%s, %s)\n", device, (const char *)cap.card, (const char *)cap.driver,
            (const char *)cap.bus_info);
    memset(&d, 0, sizeof d);
    d.type = type;
    for (d.index = 0; xioctl(fd, VIDIOC_ENUM_FMT, &d) == 0; d.index++) {
        struct v4l2_frmsizeenum fs;
        char cc[5];
        const pixfmt_info *f = pixfmt_find(d.pixelformat);
        pixfmt_fourcc_str(d.pixelformat, cc);
        fprintf(out, "  %s  %-28.28s %s\n", cc, (const char *)d.description, how(f));
        memset(&fs, 0, sizeof fs);
        fs.pixel_format = d.pixelformat;
        for (fs.index = 0; xioctl(fd, VIDIOC_ENUM_FRAMESIZES, &fs) == 0; fs.index++) {
            if (fs.type == V4L2_FRMSIZE_TYPE_DISCRETE) {
                fprintf(out, "        %ux%u", fs.discrete.width, fs.discrete.height);
                list_intervals(fd, d.pixelformat, fs.discrete.width, fs.discrete.height, out);
                fputc('\n', out);
            } else {
                fprintf(out, "        %ux%u .. %ux%u (steps %ux%u)\n", fs.stepwise.min_width,
                        fs.stepwise.min_height, fs.stepwise.max_width, fs.stepwise.max_height,
                        fs.stepwise.step_width, fs.stepwise.step_height);
                break;
            }
        }
    }
    if (d.index == 0) {
        fputs("  (no formats listed)\n", out);
    }
    close(fd);
    return 0;
}

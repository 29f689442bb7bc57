/* SPDX-License-Identifier: Apache-2.0 */
/*
 * V4L2 capture source with mmap streaming.
 *
 * A buffer is in exactly one place at a time: queued in the driver, held by
 * the caller (at most one), or being re-queued. Luma-plane formats are handed
 * out in place and go back to the driver on release; packed, Bayer and
 * Motion-JPEG frames are converted (decoded) into a private frame and
 * re-queued at once.
 */
#define _GNU_SOURCE
#include "v4l2_source.h"

#include <errno.h>
#include <fcntl.h>
#include <linux/videodev2.h>
#include <poll.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/ioctl.h>
#include <sys/mman.h>
#include <unistd.h>

#include "jpeg_luma.h"
#include "pixfmt.h"

#define V4L2SRC_MAX_BUFFERS 32u

typedef struct v4l2src {
    int fd;
    char device[128];
    enum v4l2_buf_type type;
    int mplane;
    const pixfmt_info *fmt;
    uint32_t width, height, stride;
    uint32_t nbuf;
    void *map[V4L2SRC_MAX_BUFFERS];
    size_t maplen[V4L2SRC_MAX_BUFFERS];
    int streaming;
    int freshest;
    int held;            /* index of the buffer the caller holds, -1 = none */
    capsrc_result pending; /* a failed re-queue on release, reported by the next capsrc_next */
    uint8_t *unpacked;   /* luma of packed, Bayer and JPEG formats, width*height */
    jpeg_luma *jpeg;     /* the decoder of Motion-JPEG frames */
    uint32_t got_bytes;  /* bytesused of the buffer drain() picked */
    char jpeg_error[128]; /* why the last damaged JPEG frame was skipped, "" when none */
    uint64_t number;
    int have_seq;
    uint32_t last_seq;
} v4l2src;

static int xioctl(int fd, unsigned long req, void *arg)
{
    int r;
    do {
        r = ioctl(fd, req, arg);
    } while (r == -1 && errno == EINTR);
    return r;
}

static int is_loss(int e)
{
    return e == ENODEV || e == EIO || e == ENXIO;
}

static capsrc_result fail_errno(capsrc *src, v4l2src *v, const char *what, int e)
{
    if (is_loss(e)) {
        capsrc_set_error(src, "%s: device lost during %s (%s); stopping", v->device, what, strerror(e));
        return CAPSRC_LOST;
    }
    capsrc_set_error(src, "%s: %s failed: %s", v->device, what, strerror(e));
    return CAPSRC_ERROR;
}

static void buf_init(v4l2src *v, struct v4l2_buffer *b, struct v4l2_plane *planes, uint32_t index)
{
    memset(b, 0, sizeof *b);
    b->type = v->type;
    b->memory = V4L2_MEMORY_MMAP;
    b->index = index;
    if (v->mplane) {
        memset(planes, 0, sizeof(struct v4l2_plane) * VIDEO_MAX_PLANES);
        b->m.planes = planes;
        b->length = VIDEO_MAX_PLANES;
    }
}

/* Gives buffer index back to the driver; one retry covers a transient refusal. */
static capsrc_result requeue(capsrc *src, v4l2src *v, uint32_t index)
{
    struct v4l2_buffer b;
    struct v4l2_plane planes[VIDEO_MAX_PLANES];
    buf_init(v, &b, planes, index);
    if (xioctl(v->fd, VIDIOC_QBUF, &b) == 0) {
        return CAPSRC_OK;
    }
    if (is_loss(errno)) {
        return fail_errno(src, v, "VIDIOC_QBUF", errno);
    }
    buf_init(v, &b, planes, index);
    if (xioctl(v->fd, VIDIOC_QBUF, &b) == 0) {
        src->stats.requeue_errors++;
        return CAPSRC_OK;
    }
    return fail_errno(src, v, "VIDIOC_QBUF", errno);
}

static void v4l2_release(capsrc *src)
{
    v4l2src *v = src->impl;
    if (v->held >= 0) {
        int idx = v->held;
        capsrc_result r;
        v->held = -1;
        r = requeue(src, v, (uint32_t)idx);
        if (r != CAPSRC_OK && v->pending == CAPSRC_OK) {
            v->pending = r; /* release has no result: the next capsrc_next reports it */
        }
    }
}

static capsrc_result v4l2_start(capsrc *src)
{
    v4l2src *v = src->impl;
    uint32_t i;
    int type = (int)v->type;
    for (i = 0; i < v->nbuf; i++) {
        struct v4l2_buffer b;
        struct v4l2_plane planes[VIDEO_MAX_PLANES];
        buf_init(v, &b, planes, i);
        if (xioctl(v->fd, VIDIOC_QBUF, &b) != 0) {
            return fail_errno(src, v, "VIDIOC_QBUF", errno);
        }
    }
    if (xioctl(v->fd, VIDIOC_STREAMON, &type) != 0) {
        return fail_errno(src, v, "VIDIOC_STREAMON", errno);
    }
    v->streaming = 1;
    return CAPSRC_OK;
}

static int64_t ts_ns(const struct v4l2_buffer *b)
{
    if ((b->flags & V4L2_BUF_FLAG_TIMESTAMP_MASK) == V4L2_BUF_FLAG_TIMESTAMP_MONOTONIC) {
        return (int64_t)b->timestamp.tv_sec * 1000000000 + (int64_t)b->timestamp.tv_usec * 1000;
    }
    return capsrc_now_ns();
}

static uint32_t bytes_used(const v4l2src *v, const struct v4l2_buffer *b)
{
    return v->mplane ? b->m.planes[0].bytesused : b->bytesused;
}

/* Dequeues everything ready (one buffer unless freshest); *got = index of the newest good one. */
static capsrc_result drain(capsrc *src, v4l2src *v, int *got, struct v4l2_buffer *out)
{
    const uint64_t need = (uint64_t)v->stride * (v->height - 1) + pixfmt_min_stride(v->fmt, v->width);
    for (;;) {
        struct v4l2_buffer b;
        struct v4l2_plane planes[VIDEO_MAX_PLANES];
        capsrc_result r;
        buf_init(v, &b, planes, 0);
        if (xioctl(v->fd, VIDIOC_DQBUF, &b) != 0) {
            if (errno == EAGAIN) {
                return CAPSRC_OK;
            }
            return fail_errno(src, v, "VIDIOC_DQBUF", errno);
        }
        if (b.index >= v->nbuf) {
            capsrc_set_error(src, "%s: driver returned buffer index %u of %u", v->device, b.index, v->nbuf);
            return CAPSRC_ERROR;
        }
        if (v->have_seq && b.sequence > v->last_seq + 1u) {
            src->stats.sequence_gaps += b.sequence - v->last_seq - 1u;
        }
        v->have_seq = 1;
        v->last_seq = b.sequence;
        /* Corrupt or short frames are never handed out. */
        if ((b.flags & V4L2_BUF_FLAG_ERROR) != 0 || (bytes_used(v, &b) != 0 && bytes_used(v, &b) < need) ||
            (v->fmt->layout == PIXFMT_JPEG && (bytes_used(v, &b) == 0 || bytes_used(v, &b) > v->maplen[b.index]))) {
            src->stats.error_buffers++;
            r = requeue(src, v, b.index);
            if (r != CAPSRC_OK) {
                return r;
            }
            continue;
        }
        if (*got >= 0) {
            /* A newer frame is ready: the older one goes back unprocessed. */
            src->stats.skipped_stale++;
            r = requeue(src, v, (uint32_t)*got);
            if (r != CAPSRC_OK) {
                *got = -1;
                return r;
            }
        }
        *got = (int)b.index;
        v->got_bytes = bytes_used(v, &b);
        *out = b;
        out->m.planes = NULL;
        if (!v->freshest) {
            return CAPSRC_OK;
        }
    }
}

static capsrc_result v4l2_next(capsrc *src, capsrc_frame *frame, int timeout_ms)
{
    v4l2src *v = src->impl;
    int64_t deadline = timeout_ms >= 0 ? capsrc_now_ns() + (int64_t)timeout_ms * 1000000 : 0;
    uint64_t skipped_before = src->stats.skipped_stale;
    v4l2_release(src);
    if (v->pending != CAPSRC_OK) {
        return v->pending;
    }
    for (;;) {
        struct pollfd p;
        struct v4l2_buffer b;
        int got = -1, wait_ms = -1, pr;
        capsrc_result r;
        if (timeout_ms >= 0) {
            int64_t left = deadline - capsrc_now_ns();
            wait_ms = left > 0 ? (int)((left + 999999) / 1000000) : 0;
        }
        p.fd = v->fd;
        p.events = POLLIN;
        p.revents = 0;
        pr = poll(&p, 1, wait_ms);
        if (pr < 0) {
            if (errno == EINTR) {
                return CAPSRC_INTERRUPTED;
            }
            return fail_errno(src, v, "poll", errno);
        }
        if (pr == 0) {
            capsrc_set_error(src, "%s: no frame within %d ms%s%s", v->device, timeout_ms,
                             v->jpeg_error[0] ? "; the last damaged frame: " : "", v->jpeg_error);
            return CAPSRC_TIMEOUT;
        }
        if ((p.revents & POLLNVAL) != 0) {
            capsrc_set_error(src, "%s: file descriptor no longer valid", v->device);
            return CAPSRC_ERROR;
        }
        /* POLLERR without a frame: DQBUF reports the reason (ENODEV, EIO ...). */
        memset(&b, 0, sizeof b);
        r = drain(src, v, &got, &b);
        if (r != CAPSRC_OK) {
            return r;
        }
        if (got < 0) {
            if ((p.revents & POLLERR) != 0 && (p.revents & POLLIN) == 0) {
                capsrc_set_error(src, "%s: device reported an error while streaming; stopping", v->device);
                return CAPSRC_LOST;
            }
            continue;
        }
        frame->width = v->width;
        frame->height = v->height;
        frame->sequence = b.sequence;
        frame->timestamp_ns = ts_ns(&b);
        frame->skipped = (uint32_t)(src->stats.skipped_stale - skipped_before);
        frame->convert_ns = 0;
        if (v->fmt->layout == PIXFMT_JPEG) {
            const int64_t t0 = capsrc_now_ns();
            char jerr[sizeof v->jpeg_error];
            const int bad = jpeg_luma_decode(v->jpeg, v->map[got], v->got_bytes, v->width, v->height, v->unpacked,
                                             v->width, jerr, sizeof jerr) != 0;
            frame->convert_ns = capsrc_now_ns() - t0;
            r = requeue(src, v, (uint32_t)got);
            if (r != CAPSRC_OK) {
                return r;
            }
            if (bad) {
                /* A damaged frame (USB cameras deliver some) is skipped like a flagged buffer. */
                memcpy(v->jpeg_error, jerr, sizeof jerr);
                src->stats.error_buffers++;
                continue;
            }
            frame->luma = v->unpacked;
            frame->stride = v->width;
        } else if (v->fmt->layout != PIXFMT_LUMA_PLANE) {
            const int64_t t0 = capsrc_now_ns();
            pixfmt_unpack_luma(v->fmt, v->map[got], v->stride, v->width, v->height, v->unpacked, v->width);
            frame->convert_ns = capsrc_now_ns() - t0;
            frame->luma = v->unpacked;
            frame->stride = v->width;
            r = requeue(src, v, (uint32_t)got);
            if (r != CAPSRC_OK) {
                return r;
            }
        } else {
            frame->luma = v->map[got];
            frame->stride = v->stride;
            v->held = got;
        }
        frame->number = v->number++;
        src->stats.delivered++;
        return CAPSRC_OK;
    }
}

static void v4l2_teardown(v4l2src *v)
{
    uint32_t i;
    if (v->fd >= 0) {
        if (v->streaming) {
            int type = (int)v->type;
            (void)xioctl(v->fd, VIDIOC_STREAMOFF, &type);
            v->streaming = 0;
        }
        v->held = -1;
    }
    for (i = 0; i < V4L2SRC_MAX_BUFFERS; i++) {
        if (v->map[i] != NULL) {
            munmap(v->map[i], v->maplen[i]);
            v->map[i] = NULL;
        }
    }
    if (v->fd >= 0) {
        if (v->nbuf > 0) {
            struct v4l2_requestbuffers rb;
            memset(&rb, 0, sizeof rb);
            rb.count = 0;
            rb.type = v->type;
            rb.memory = V4L2_MEMORY_MMAP;
            (void)xioctl(v->fd, VIDIOC_REQBUFS, &rb);
        }
        close(v->fd);
        v->fd = -1;
    }
    free(v->unpacked);
    v->unpacked = NULL;
    jpeg_luma_close(v->jpeg);
    v->jpeg = NULL;
}

static void v4l2_close(capsrc *src)
{
    v4l2src *v = src->impl;
    if (v != NULL) {
        v4l2_teardown(v);
        free(v);
        src->impl = NULL;
    }
}

static const capsrc_ops v4l2_ops = {v4l2_start, v4l2_next, v4l2_release, v4l2_close};

/* The device's most direct supported format (lowest pixfmt preference). */
static const pixfmt_info *pick_format(v4l2src *v, char *offered, size_t offlen)
{
    const pixfmt_info *best = NULL;
    struct v4l2_fmtdesc d;
    size_t used = 0;
    memset(&d, 0, sizeof d);
    d.type = v->type;
    offered[0] = '\0';
    for (d.index = 0; xioctl(v->fd, VIDIOC_ENUM_FMT, &d) == 0; d.index++) {
        const pixfmt_info *f = pixfmt_find(d.pixelformat);
        char cc[5];
        pixfmt_fourcc_str(d.pixelformat, cc);
        if (used + 6 < offlen) {
            used += (size_t)snprintf(offered + used, offlen - used, "%s%s", used ? " " : "", cc);
        }
        if (f != NULL && f->layout == PIXFMT_JPEG && !jpeg_luma_available()) {
            f = NULL; /* this build cannot decode it */
        }
        if (f != NULL && (best == NULL || f->preference < best->preference)) {
            best = f;
        }
    }
    return best;
}

static int set_ctrl(int fd, uint32_t id, int32_t value)
{
    struct v4l2_control c;
    c.id = id;
    c.value = value;
    return xioctl(fd, VIDIOC_S_CTRL, &c);
}

static int configure(v4l2src *v, const v4l2_options *opt, char *desc, size_t desclen, char *err,
                     size_t errlen)
{
    struct v4l2_capability cap;
    struct v4l2_format f;
    struct v4l2_streamparm parm;
    struct v4l2_requestbuffers rb;
    uint32_t caps, i, fps_n = 0, fps_d = 0;
    char offered[256], cc[5], expo[64] = "";
    const pixfmt_info *want;

    memset(&cap, 0, sizeof cap);
    if (xioctl(v->fd, VIDIOC_QUERYCAP, &cap) != 0) {
        snprintf(err, errlen, "%s: VIDIOC_QUERYCAP failed: %s (not a V4L2 device?)", v->device, strerror(errno));
        return -1;
    }
    caps = (cap.capabilities & V4L2_CAP_DEVICE_CAPS) ? cap.device_caps : cap.capabilities;
    if (caps & V4L2_CAP_VIDEO_CAPTURE) {
        v->type = V4L2_BUF_TYPE_VIDEO_CAPTURE;
    } else if (caps & V4L2_CAP_VIDEO_CAPTURE_MPLANE) {
        v->type = V4L2_BUF_TYPE_VIDEO_CAPTURE_MPLANE;
        v->mplane = 1;
    } else {
        snprintf(err, errlen, "%s (%s): not a video capture device", v->device, (const char *)cap.card);
        return -1;
    }
    if (!(caps & V4L2_CAP_STREAMING)) {
        snprintf(err, errlen, "%s (%s): no streaming I/O support", v->device, (const char *)cap.card);
        return -1;
    }

    want = pick_format(v, offered, sizeof offered);
    if (opt->format != NULL) {
        want = pixfmt_by_name(opt->format);
        if (want == NULL) {
            snprintf(err, errlen, "unsupported format '%s'", opt->format);
            return -1;
        }
    } else if (want == NULL) {
        snprintf(err, errlen, "%s: none of the device's formats (%s) carries 8-bit luma symline can read",
                 v->device, offered);
        return -1;
    }

    memset(&f, 0, sizeof f);
    f.type = v->type;
    if (xioctl(v->fd, VIDIOC_G_FMT, &f) != 0) {
        snprintf(err, errlen, "%s: VIDIOC_G_FMT failed: %s", v->device, strerror(errno));
        return -1;
    }
    if (v->mplane) {
        f.fmt.pix_mp.pixelformat = want->fourcc;
        f.fmt.pix_mp.field = V4L2_FIELD_NONE;
        for (i = 0; i < VIDEO_MAX_PLANES; i++) {
            f.fmt.pix_mp.plane_fmt[i].bytesperline = 0; /* the driver's own padding */
        }
        if (opt->width) f.fmt.pix_mp.width = opt->width;
        if (opt->height) f.fmt.pix_mp.height = opt->height;
    } else {
        f.fmt.pix.pixelformat = want->fourcc;
        f.fmt.pix.field = V4L2_FIELD_NONE;
        f.fmt.pix.bytesperline = 0; /* let the driver choose its padding */
        if (opt->width) f.fmt.pix.width = opt->width;
        if (opt->height) f.fmt.pix.height = opt->height;
    }
    if (xioctl(v->fd, VIDIOC_S_FMT, &f) != 0) {
        snprintf(err, errlen, "%s: VIDIOC_S_FMT %s failed: %s", v->device, want->name, strerror(errno));
        return -1;
    }
    {
        uint32_t got_fmt = v->mplane ? f.fmt.pix_mp.pixelformat : f.fmt.pix.pixelformat;
        if (got_fmt != want->fourcc) {
            pixfmt_fourcc_str(got_fmt, cc);
            snprintf(err, errlen, "%s: format %s not supported (driver offered %s; formats: %s)", v->device,
                     want->name, cc, offered);
            return -1;
        }
    }
    v->fmt = want;
    if (v->mplane) {
        v->width = f.fmt.pix_mp.width;
        v->height = f.fmt.pix_mp.height;
        v->stride = f.fmt.pix_mp.plane_fmt[0].bytesperline;
    } else {
        v->width = f.fmt.pix.width;
        v->height = f.fmt.pix.height;
        v->stride = f.fmt.pix.bytesperline;
    }
    if (v->stride == 0) {
        v->stride = (uint32_t)pixfmt_min_stride(want, v->width);
    }
    if (v->width == 0 || v->height == 0 || v->width > 65535u || v->height > 65535u ||
        v->stride < pixfmt_min_stride(want, v->width) ||
        (want->layout == PIXFMT_PACKED_422 && (v->width & 1u)) ||
        (want->layout == PIXFMT_BAYER8 && (v->width < 2u || v->height < 2u))) {
        snprintf(err, errlen, "%s: driver granted an unusable frame %ux%u, bytesperline %u", v->device, v->width,
                 v->height, v->stride);
        return -1;
    }

    /* Frame interval: request, then report what the driver really runs at. */
    memset(&parm, 0, sizeof parm);
    parm.type = v->type;
    if (opt->fps_num > 0) {
        if (xioctl(v->fd, VIDIOC_G_PARM, &parm) != 0 || !(parm.parm.capture.capability & V4L2_CAP_TIMEPERFRAME)) {
            snprintf(err, errlen, "%s: the device does not support setting the frame rate", v->device);
            return -1;
        }
        parm.parm.capture.timeperframe.numerator = opt->fps_den ? opt->fps_den : 1;
        parm.parm.capture.timeperframe.denominator = opt->fps_num;
        if (xioctl(v->fd, VIDIOC_S_PARM, &parm) != 0) {
            snprintf(err, errlen, "%s: VIDIOC_S_PARM failed: %s", v->device, strerror(errno));
            return -1;
        }
    } else if (xioctl(v->fd, VIDIOC_G_PARM, &parm) != 0) {
        memset(&parm, 0, sizeof parm);
    }
    fps_n = parm.parm.capture.timeperframe.denominator;
    fps_d = parm.parm.capture.timeperframe.numerator;

    if (opt->exposure_100us >= 0) {
        /* Manual exposure caps motion blur; not every device offers it. */
        (void)set_ctrl(v->fd, V4L2_CID_EXPOSURE_AUTO, V4L2_EXPOSURE_MANUAL);
        if (set_ctrl(v->fd, V4L2_CID_EXPOSURE_ABSOLUTE, opt->exposure_100us) != 0) {
            snprintf(expo, sizeof expo, ", exposure control not offered");
        } else {
            struct v4l2_control c;
            c.id = V4L2_CID_EXPOSURE_ABSOLUTE;
            c.value = 0;
            if (xioctl(v->fd, VIDIOC_G_CTRL, &c) == 0) {
                snprintf(expo, sizeof expo, ", exposure %d us", (int)c.value * 100);
            }
        }
    }

    memset(&rb, 0, sizeof rb);
    rb.count = opt->buffers;
    rb.type = v->type;
    rb.memory = V4L2_MEMORY_MMAP;
    if (xioctl(v->fd, VIDIOC_REQBUFS, &rb) != 0) {
        snprintf(err, errlen, "%s: VIDIOC_REQBUFS (%u mmap buffers) failed: %s", v->device, opt->buffers,
                 strerror(errno));
        return -1;
    }
    v->nbuf = rb.count; /* set before the checks so teardown frees them */
    if (rb.count < 2 || rb.count > V4L2SRC_MAX_BUFFERS) {
        snprintf(err, errlen, "%s: driver granted %u buffers (need 2..%u)", v->device, rb.count,
                 V4L2SRC_MAX_BUFFERS);
        return -1;
    }
    for (i = 0; i < v->nbuf; i++) {
        struct v4l2_buffer b;
        struct v4l2_plane planes[VIDEO_MAX_PLANES];
        uint32_t len, off;
        buf_init(v, &b, planes, i);
        if (xioctl(v->fd, VIDIOC_QUERYBUF, &b) != 0) {
            snprintf(err, errlen, "%s: VIDIOC_QUERYBUF failed: %s", v->device, strerror(errno));
            return -1;
        }
        /* Only the first plane is mapped: it holds the luma (or the packed pixels). */
        len = v->mplane ? planes[0].length : b.length;
        off = v->mplane ? planes[0].m.mem_offset : b.m.offset;
        if ((uint64_t)len < (uint64_t)v->stride * (v->height - 1) + pixfmt_min_stride(want, v->width)) {
            snprintf(err, errlen, "%s: buffer of %u bytes is too small for %ux%u, bytesperline %u", v->device, len,
                     v->width, v->height, v->stride);
            return -1;
        }
        v->map[i] = mmap(NULL, len, PROT_READ | PROT_WRITE, MAP_SHARED, v->fd, (off_t)off);
        if (v->map[i] == MAP_FAILED) {
            v->map[i] = NULL;
            snprintf(err, errlen, "%s: mmap of buffer %u failed: %s", v->device, i, strerror(errno));
            return -1;
        }
        v->maplen[i] = len;
    }
    if (want->layout != PIXFMT_LUMA_PLANE) {
        v->unpacked = malloc((size_t)v->width * v->height);
        if (v->unpacked == NULL) {
            snprintf(err, errlen, "out of memory");
            return -1;
        }
    }
    if (want->layout == PIXFMT_JPEG) {
        char jerr[128];
        v->jpeg = jpeg_luma_open(jerr, sizeof jerr);
        if (v->jpeg == NULL) {
            snprintf(err, errlen, "%s: %s: %s", v->device, want->name, jerr);
            return -1;
        }
    }
    /* Truncation is harmless: the text is for the log. */
    if (snprintf(desc, desclen, "%s (%s, %s): %s %ux%u bytesperline %u, %s%u/%u fps, %u buffers%s%s", v->device,
             (const char *)cap.card, (const char *)cap.driver, want->name, v->width, v->height, v->stride,
             fps_n && fps_d ? "" : "driver-timed ", fps_n, fps_d ? fps_d : 1u, v->nbuf,
             v->mplane ? ", multi-planar API" : "", expo) < 0) {
        desc[0] = '\0';
    }
    return 0;
}

capsrc *v4l2_source_open(const v4l2_options *opt, char *err, size_t errlen)
{
    capsrc *src;
    char desc[CAPSRC_ERRLEN];
    v4l2src *v = calloc(1, sizeof *v);
    if (v == NULL) {
        snprintf(err, errlen, "out of memory");
        return NULL;
    }
    v->held = -1;
    v->freshest = opt->freshest;
    snprintf(v->device, sizeof v->device, "%s", opt->device);
    if (opt->buffers < 2 || opt->buffers > V4L2SRC_MAX_BUFFERS) {
        snprintf(err, errlen, "buffer count %u out of range 2..%u", opt->buffers, V4L2SRC_MAX_BUFFERS);
        free(v);
        return NULL;
    }
    v->fd = open(opt->device, O_RDWR | O_NONBLOCK | O_CLOEXEC);
    if (v->fd < 0) {
        snprintf(err, errlen, "%s: %s", opt->device, strerror(errno));
        free(v);
        return NULL;
    }
    if (configure(v, opt, desc, sizeof desc, err, errlen) != 0) {
        v4l2_teardown(v);
        free(v);
        return NULL;
    }
    src = capsrc_alloc(&v4l2_ops, v);
    if (src == NULL) {
        snprintf(err, errlen, "out of memory");
        v4l2_teardown(v);
        free(v);
        return NULL;
    }
    memcpy(src->description, desc, sizeof desc);
    return src;
}

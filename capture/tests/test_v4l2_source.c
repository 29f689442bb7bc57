/* SPDX-License-Identifier: Apache-2.0 */
/*
 * The V4L2 source against a fake driver: open, ioctl, mmap, munmap, poll and
 * close are wrapped at link time (-Wl,--wrap), so buffer ownership, the
 * freshest-frame logic, error buffers, device loss and the clean-up on every
 * exit path are checked on any machine, without a camera.
 */
#define _GNU_SOURCE
#include <errno.h>
#include <fcntl.h>
#include <linux/videodev2.h>
#include <poll.h>
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/mman.h>

#include <cmocka.h>

#ifdef SYMLINE_HAVE_TURBOJPEG
#include <turbojpeg.h>
#endif

#include "jpeg_luma.h"
#include "v4l2_list.h"
#include "v4l2_source.h"

#define FAKE_PATH "/dev/fake-video"
#define FAKE_FD 4242
#define W 8
#define H 4
#define MAXBUF 8

/* The fake driver's state; the tests script it. */
static struct fake {
    int open_fds;            /* opened and not closed */
    uint32_t caps;
    uint32_t offered[4];     /* formats ENUM_FMT lists, 0-terminated */
    uint32_t fmt;            /* current pixelformat */
    uint32_t bpl_pad;        /* extra bytes per row the driver adds */
    uint32_t nbuf;
    int state[MAXBUF];       /* 0 user, 1 queued in the driver, 2 done (ready to dequeue) */
    uint32_t done[MAXBUF];   /* FIFO of done buffer indexes */
    uint32_t done_flags[MAXBUF];
    uint32_t done_seq[MAXBUF];
    int ndone;
    uint32_t seq;
    int maps;                /* mapped and not unmapped */
    int streaming;
    int qbuf_fail;           /* the next qbuf_fail QBUFs fail with EINVAL */
    int dqbuf_errno;         /* non-zero: DQBUF fails with it (after the done FIFO is empty) */
    int poll_eintr;
    int reqbufs_fail;
    int streamon_fail;
    uint32_t used[MAXBUF];   /* MJPG: bytes of the compressed frame in each buffer */
    int damage_next;         /* MJPG: the next frame produced is cut short */
    uint8_t mem[MAXBUF][2048];
} fk;

static void fake_reset(uint32_t caps)
{
    memset(&fk, 0, sizeof fk);
    fk.caps = caps;
    fk.offered[0] = V4L2_PIX_FMT_YUYV;
    fk.offered[1] = V4L2_PIX_FMT_GREY;
    fk.fmt = V4L2_PIX_FMT_YUYV;
}

static uint32_t bpp(uint32_t f)
{
    return f == V4L2_PIX_FMT_YUYV ? 2u : (f == V4L2_PIX_FMT_MJPEG ? 0u : 1u);
}

/* MJPG: a gray W x H JPEG whose every pixel is v, compressed into buffer i. */
static void produce_jpeg(uint32_t i, uint8_t v)
{
#ifdef SYMLINE_HAVE_TURBOJPEG
    uint8_t px[W * H];
    unsigned char *out = fk.mem[i];
    unsigned long size = sizeof fk.mem[i];
    tjhandle tj = tjInitCompress();
    assert_non_null(tj);
    memset(px, v, sizeof px);
    assert_int_equal(tjCompress2(tj, px, W, W, H, TJPF_GRAY, &out, &size, TJSAMP_GRAY, 95, TJFLAG_NOREALLOC), 0);
    tjDestroy(tj);
    fk.used[i] = (uint32_t)size;
    if (fk.damage_next) {
        fk.damage_next = 0;
        fk.used[i] = (uint32_t)size / 2u;
    }
#else
    (void)i, (void)v;
    fail();
#endif
}

/* The driver fills the oldest queued buffer: luma = sequence number. */
static void produce(uint32_t flags)
{
    uint32_t i, x, y;
    for (i = 0; i < fk.nbuf; i++) {
        if (fk.state[i] == 1) {
            break;
        }
    }
    assert_true(i < fk.nbuf);
    if (fk.fmt == V4L2_PIX_FMT_MJPEG) {
        produce_jpeg(i, (uint8_t)(fk.seq + 10));
    }
    for (y = 0; y < H && fk.fmt != V4L2_PIX_FMT_MJPEG; y++) {
        for (x = 0; x < W * bpp(fk.fmt); x++) {
            fk.mem[i][y * (W * bpp(fk.fmt) + fk.bpl_pad) + x] =
                (fk.fmt == V4L2_PIX_FMT_YUYV && (x & 1u)) ? 0x80 : (uint8_t)(fk.seq + 10);
        }
    }
    fk.state[i] = 2;
    fk.done[fk.ndone] = i;
    fk.done_flags[fk.ndone] = flags;
    fk.done_seq[fk.ndone] = fk.seq++;
    fk.ndone++;
}

int __real_open(const char *path, int flags, ...);
int __wrap_open(const char *path, int flags, ...)
{
    if (strcmp(path, FAKE_PATH) != 0) {
        return __real_open(path, flags, 0);
    }
    fk.open_fds++;
    return FAKE_FD;
}

int __real_close(int fd);
int __wrap_close(int fd)
{
    if (fd != FAKE_FD) {
        return __real_close(fd);
    }
    fk.open_fds--;
    return 0;
}

void *__wrap_mmap(void *addr, size_t len, int prot, int flags, int fd, off_t off)
{
    (void)addr;
    (void)len;
    (void)prot;
    (void)flags;
    assert_int_equal(fd, FAKE_FD);
    fk.maps++;
    return fk.mem[off / 4096];
}

int __wrap_munmap(void *addr, size_t len)
{
    (void)addr;
    (void)len;
    fk.maps--;
    return 0;
}

int __wrap_poll(struct pollfd *p, nfds_t n, int timeout)
{
    (void)n;
    (void)timeout;
    if (fk.poll_eintr) {
        fk.poll_eintr = 0;
        errno = EINTR;
        return -1;
    }
    if (fk.ndone > 0) {
        p->revents = POLLIN;
        return 1;
    }
    if (fk.dqbuf_errno != 0) {
        p->revents = POLLERR;
        return 1;
    }
    return 0;
}

static int fake_fail(int e)
{
    errno = e;
    return -1;
}

int __wrap_ioctl(int fd, unsigned long req, void *arg)
{
    assert_int_equal(fd, FAKE_FD);
    switch (req) {
    case VIDIOC_QUERYCAP: {
        struct v4l2_capability *c = arg;
        memset(c, 0, sizeof *c);
        strcpy((char *)c->driver, "fake");
        strcpy((char *)c->card, "Fake camera");
        c->capabilities = fk.caps | V4L2_CAP_DEVICE_CAPS;
        c->device_caps = fk.caps;
        return 0;
    }
    case VIDIOC_ENUM_FMT: {
        struct v4l2_fmtdesc *d = arg;
        if (d->index >= 4 || fk.offered[d->index] == 0) return fake_fail(EINVAL);
        d->pixelformat = fk.offered[d->index];
        return 0;
    }
    case VIDIOC_G_FMT:
    case VIDIOC_S_FMT: {
        struct v4l2_format *f = arg;
        if (req == VIDIOC_S_FMT) {
            int ok = 0, i;
            for (i = 0; i < 4; i++) ok |= fk.offered[i] == f->fmt.pix.pixelformat;
            if (ok) fk.fmt = f->fmt.pix.pixelformat;
        }
        f->fmt.pix.width = W;
        f->fmt.pix.height = H;
        f->fmt.pix.pixelformat = fk.fmt;
        f->fmt.pix.bytesperline = bpp(fk.fmt) ? W * bpp(fk.fmt) + fk.bpl_pad : 0;
        f->fmt.pix.sizeimage = bpp(fk.fmt) ? f->fmt.pix.bytesperline * H : sizeof fk.mem[0];
        return 0;
    }
    case VIDIOC_G_PARM:
    case VIDIOC_S_PARM: {
        struct v4l2_streamparm *p = arg;
        p->parm.capture.capability = V4L2_CAP_TIMEPERFRAME;
        p->parm.capture.timeperframe.numerator = 1;
        p->parm.capture.timeperframe.denominator = 30;
        return 0;
    }
    case VIDIOC_REQBUFS: {
        struct v4l2_requestbuffers *r = arg;
        if (fk.reqbufs_fail) return fake_fail(ENOMEM);
        fk.nbuf = r->count > MAXBUF ? MAXBUF : r->count;
        r->count = fk.nbuf;
        return 0;
    }
    case VIDIOC_QUERYBUF: {
        struct v4l2_buffer *b = arg;
        b->length = sizeof fk.mem[0];
        b->m.offset = b->index * 4096u;
        return 0;
    }
    case VIDIOC_QBUF: {
        struct v4l2_buffer *b = arg;
        if (fk.qbuf_fail > 0) {
            fk.qbuf_fail--;
            return fake_fail(EINVAL);
        }
        /* Queueing a buffer the driver already owns is a bug in the source. */
        assert_int_equal(fk.state[b->index], 0);
        fk.state[b->index] = 1;
        return 0;
    }
    case VIDIOC_DQBUF: {
        struct v4l2_buffer *b = arg;
        uint32_t i;
        if (fk.ndone == 0) return fake_fail(fk.dqbuf_errno ? fk.dqbuf_errno : EAGAIN);
        b->index = fk.done[0];
        b->flags = fk.done_flags[0] | V4L2_BUF_FLAG_TIMESTAMP_MONOTONIC;
        b->sequence = fk.done_seq[0];
        b->bytesused = fk.fmt == V4L2_PIX_FMT_MJPEG ? fk.used[b->index] : (W * bpp(fk.fmt) + fk.bpl_pad) * H;
        b->timestamp.tv_sec = 1;
        b->timestamp.tv_usec = (long)b->sequence;
        fk.state[b->index] = 0;
        for (i = 1; i < (uint32_t)fk.ndone; i++) {
            fk.done[i - 1] = fk.done[i];
            fk.done_flags[i - 1] = fk.done_flags[i];
            fk.done_seq[i - 1] = fk.done_seq[i];
        }
        fk.ndone--;
        return 0;
    }
    case VIDIOC_STREAMON:
        if (fk.streamon_fail) return fake_fail(EINVAL);
        fk.streaming = 1;
        return 0;
    case VIDIOC_STREAMOFF: {
        uint32_t i;
        fk.streaming = 0;
        for (i = 0; i < fk.nbuf; i++) fk.state[i] = 0;
        fk.ndone = 0;
        return 0;
    }
    case VIDIOC_S_CTRL:
    case VIDIOC_G_CTRL:
        return fake_fail(EINVAL);
    default:
        return fake_fail(ENOTTY);
    }
}

static capsrc *open_fake(const char *format, int freshest, uint32_t buffers)
{
    v4l2_options o;
    char err[256];
    capsrc *src;
    memset(&o, 0, sizeof o);
    o.device = FAKE_PATH;
    o.format = format;
    o.buffers = buffers;
    o.freshest = freshest;
    o.exposure_100us = -1;
    src = v4l2_source_open(&o, err, sizeof err);
    assert_non_null(src);
    assert_int_equal(capsrc_start(src), CAPSRC_OK);
    return src;
}

static void close_and_check(capsrc *src)
{
    capsrc_close(src);
    /* Every exit path: streaming off, nothing mapped, the device closed. */
    assert_int_equal(fk.streaming, 0);
    assert_int_equal(fk.maps, 0);
    assert_int_equal(fk.open_fds, 0);
}

static int queued(void)
{
    int i, n = 0;
    for (i = 0; i < (int)fk.nbuf; i++) n += fk.state[i] == 1;
    return n;
}

static void test_default_format_and_description(void **state)
{
    capsrc *src;
    (void)state;
    fake_reset(V4L2_CAP_VIDEO_CAPTURE | V4L2_CAP_STREAMING);
    src = open_fake(NULL, 1, 4);
    /* GREY is read in place, so it wins over YUYV although listed second. */
    assert_non_null(strstr(src->description, "GREY 8x4 bytesperline 8, 30/1 fps, 4 buffers"));
    assert_int_equal(queued(), 4);
    close_and_check(src);
}

static void test_freshest_hands_out_newest_once(void **state)
{
    capsrc_frame f;
    capsrc *src;
    (void)state;
    fake_reset(V4L2_CAP_VIDEO_CAPTURE | V4L2_CAP_STREAMING);
    fk.bpl_pad = 3;
    src = open_fake("GREY", 1, 4);
    produce(0);
    produce(0);
    produce(0);
    assert_int_equal(capsrc_next(src, &f, 100), CAPSRC_OK);
    assert_int_equal(f.sequence, 2);
    assert_int_equal(f.luma[0], 12);
    assert_int_equal(f.stride, W + 3);                 /* the driver's padding honoured */
    assert_int_equal(f.luma[(H - 1) * f.stride + W - 1], 12);
    assert_int_equal(f.skipped, 2);
    assert_int_equal(src->stats.skipped_stale, 2);
    assert_int_equal(queued(), 3);                     /* the held one stays out */
    /* Nothing new: the held frame is given back, no frame is handed out twice. */
    assert_int_equal(capsrc_next(src, &f, 100), CAPSRC_TIMEOUT);
    assert_int_equal(queued(), 4);
    produce(0);
    assert_int_equal(capsrc_next(src, &f, 100), CAPSRC_OK);
    assert_int_equal(f.sequence, 3);
    assert_int_equal(f.number, 1);
    assert_int_equal(f.skipped, 0);
    assert_int_equal(src->stats.delivered, 2);
    close_and_check(src);
}

static void test_all_frames_in_order(void **state)
{
    capsrc_frame f;
    capsrc *src;
    uint32_t k;
    (void)state;
    fake_reset(V4L2_CAP_VIDEO_CAPTURE | V4L2_CAP_STREAMING);
    src = open_fake("GREY", 0, 4);
    produce(0);
    produce(0);
    produce(0);
    for (k = 0; k < 3; k++) {
        assert_int_equal(capsrc_next(src, &f, 100), CAPSRC_OK);
        assert_int_equal(f.sequence, k);
        assert_int_equal(f.luma[0], 10 + k);
    }
    assert_int_equal(src->stats.skipped_stale, 0);
    close_and_check(src);
}

static void test_packed_converted_and_requeued(void **state)
{
    capsrc_frame f;
    capsrc *src;
    uint32_t x, y;
    (void)state;
    fake_reset(V4L2_CAP_VIDEO_CAPTURE | V4L2_CAP_STREAMING);
    fk.bpl_pad = 4;
    src = open_fake("YUYV", 1, 2);
    produce(0);
    assert_int_equal(capsrc_next(src, &f, 100), CAPSRC_OK);
    /* The buffer went back at once; the luma lives in the source's own frame. */
    assert_int_equal(queued(), 2);
    assert_int_equal(f.stride, W);
    for (y = 0; y < H; y++) {
        for (x = 0; x < W; x++) {
            assert_int_equal(f.luma[y * f.stride + x], 10);
        }
    }
    close_and_check(src);
}

static void test_error_buffers_skipped(void **state)
{
    capsrc_frame f;
    capsrc *src;
    (void)state;
    fake_reset(V4L2_CAP_VIDEO_CAPTURE | V4L2_CAP_STREAMING);
    src = open_fake("GREY", 0, 4);
    produce(V4L2_BUF_FLAG_ERROR);
    produce(0);
    assert_int_equal(capsrc_next(src, &f, 100), CAPSRC_OK);
    assert_int_equal(f.sequence, 1);
    assert_int_equal(src->stats.error_buffers, 1);
    assert_int_equal(queued(), 3);
    close_and_check(src);
}

static void test_qbuf_retry(void **state)
{
    capsrc_frame f;
    capsrc *src;
    (void)state;
    fake_reset(V4L2_CAP_VIDEO_CAPTURE | V4L2_CAP_STREAMING);
    src = open_fake("GREY", 1, 4);
    produce(0);
    assert_int_equal(capsrc_next(src, &f, 100), CAPSRC_OK);
    fk.qbuf_fail = 1;
    produce(0);
    assert_int_equal(capsrc_next(src, &f, 100), CAPSRC_OK);
    assert_int_equal(src->stats.requeue_errors, 1);
    /* Two refusals in a row: an error naming the ioctl. */
    fk.qbuf_fail = 2;
    produce(0);
    assert_int_equal(capsrc_next(src, &f, 100), CAPSRC_ERROR);
    assert_non_null(strstr(capsrc_error(src), "VIDIOC_QBUF failed"));
    close_and_check(src);
}

static void test_device_lost(void **state)
{
    capsrc_frame f;
    capsrc *src;
    (void)state;
    fake_reset(V4L2_CAP_VIDEO_CAPTURE | V4L2_CAP_STREAMING);
    src = open_fake("GREY", 1, 4);
    produce(0);
    fk.dqbuf_errno = ENODEV;
    /* The frame that made it is still handed out, then the loss is reported. */
    assert_int_equal(capsrc_next(src, &f, 100), CAPSRC_LOST);
    assert_non_null(strstr(capsrc_error(src), "device lost during VIDIOC_DQBUF (No such device)"));
    close_and_check(src);
}

static void test_interrupted_wait(void **state)
{
    capsrc_frame f;
    capsrc *src;
    (void)state;
    fake_reset(V4L2_CAP_VIDEO_CAPTURE | V4L2_CAP_STREAMING);
    src = open_fake("GREY", 1, 4);
    fk.poll_eintr = 1;
    assert_int_equal(capsrc_next(src, &f, 100), CAPSRC_INTERRUPTED);
    produce(0);
    assert_int_equal(capsrc_next(src, &f, 100), CAPSRC_OK);
    close_and_check(src);
}

static void expect_open_failure(const char *format, const char *message)
{
    v4l2_options o;
    char err[256];
    memset(&o, 0, sizeof o);
    o.device = FAKE_PATH;
    o.format = format;
    o.buffers = 4;
    o.exposure_100us = -1;
    err[0] = '\0';
    assert_null(v4l2_source_open(&o, err, sizeof err));
    assert_non_null(strstr(err, message));
    assert_int_equal(fk.maps, 0);
    assert_int_equal(fk.open_fds, 0);
}

static void test_open_failures_release_everything(void **state)
{
    capsrc *src;
    (void)state;
    fake_reset(V4L2_CAP_VIDEO_OUTPUT | V4L2_CAP_STREAMING);
    expect_open_failure(NULL, "not a video capture device");
    fake_reset(V4L2_CAP_VIDEO_CAPTURE | V4L2_CAP_READWRITE);
    expect_open_failure(NULL, "no streaming I/O support");
    fake_reset(V4L2_CAP_VIDEO_CAPTURE | V4L2_CAP_STREAMING);
    expect_open_failure("NV12", "format NV12 not supported (driver offered YUYV; formats: YUYV GREY)");
    fake_reset(V4L2_CAP_VIDEO_CAPTURE | V4L2_CAP_STREAMING);
    expect_open_failure("RGBX", "unsupported format 'RGBX'");
    fake_reset(V4L2_CAP_VIDEO_CAPTURE | V4L2_CAP_STREAMING);
    fk.reqbufs_fail = 1;
    expect_open_failure("GREY", "VIDIOC_REQBUFS (4 mmap buffers) failed: Cannot allocate memory");
    fake_reset(V4L2_CAP_VIDEO_CAPTURE | V4L2_CAP_STREAMING);
    fk.offered[0] = V4L2_PIX_FMT_H264;
    fk.offered[1] = 0;
    expect_open_failure(NULL, "none of the device's formats (H264)");
    if (!jpeg_luma_available()) {
        fake_reset(V4L2_CAP_VIDEO_CAPTURE | V4L2_CAP_STREAMING);
        fk.offered[0] = V4L2_PIX_FMT_MJPEG;
        fk.offered[1] = 0;
        expect_open_failure(NULL, "none of the device's formats (MJPG)");
        fake_reset(V4L2_CAP_VIDEO_CAPTURE | V4L2_CAP_STREAMING);
        fk.offered[0] = V4L2_PIX_FMT_MJPEG;
        expect_open_failure("MJPG", "this build reads no JPEG");
    }

    /* STREAMON refused: the error names it, and closing still releases everything. */
    fake_reset(V4L2_CAP_VIDEO_CAPTURE | V4L2_CAP_STREAMING);
    fk.streamon_fail = 1;
    {
        v4l2_options o;
        char err[256];
        memset(&o, 0, sizeof o);
        o.device = FAKE_PATH;
        o.buffers = 3;
        o.exposure_100us = -1;
        src = v4l2_source_open(&o, err, sizeof err);
        assert_non_null(src);
        assert_int_equal(capsrc_start(src), CAPSRC_ERROR);
        assert_non_null(strstr(capsrc_error(src), "VIDIOC_STREAMON failed: Invalid argument"));
        close_and_check(src);
    }
}

/*
 * Motion-JPEG: chosen when it is all the device offers, decoded to luma, the
 * buffer re-queued at once; a damaged frame is skipped and counted like a
 * flagged buffer, and the next good one is handed out.
 */
static void test_mjpeg_decoded_damaged_skipped(void **state)
{
    capsrc_frame f;
    capsrc *src;
    uint32_t x, y;
    (void)state;
    if (!jpeg_luma_available()) {
        skip();
    }
    fake_reset(V4L2_CAP_VIDEO_CAPTURE | V4L2_CAP_STREAMING);
    fk.offered[0] = V4L2_PIX_FMT_MJPEG;
    fk.offered[1] = 0;
    fk.fmt = V4L2_PIX_FMT_MJPEG;
    src = open_fake(NULL, 0, 4);
    assert_non_null(strstr(src->description, "MJPG 8x4"));
    produce(0);
    assert_int_equal(capsrc_next(src, &f, 100), CAPSRC_OK);
    assert_int_equal(f.width, W);
    assert_int_equal(f.stride, W);
    for (y = 0; y < H; y++) {
        for (x = 0; x < W; x++) {
            assert_int_equal(f.luma[y * f.stride + x], 10);
        }
    }
    assert_int_equal(queued(), 4); /* decoded, so the buffer went straight back */
    fk.damage_next = 1;
    produce(0);
    produce(0);
    assert_int_equal(capsrc_next(src, &f, 100), CAPSRC_OK);
    assert_int_equal(f.sequence, 2);
    assert_int_equal(f.number, 1);
    assert_int_equal(f.luma[0], 12);
    assert_int_equal(src->stats.error_buffers, 1);
    /* Only damaged frames: the timeout says why. */
    fk.damage_next = 1;
    produce(0);
    assert_int_equal(capsrc_next(src, &f, 100), CAPSRC_TIMEOUT);
    assert_non_null(strstr(capsrc_error(src), "the last damaged frame: JPEG"));
    assert_int_equal(src->stats.error_buffers, 2);
    close_and_check(src);
}

/* --list-formats: every format the device offers, with how symline gets its luma. */
static void test_list_formats_and_device_numbers(void **state)
{
    char *text = NULL, err[256], buf[64];
    size_t len = 0;
    FILE *out;
    (void)state;
    fake_reset(V4L2_CAP_VIDEO_CAPTURE | V4L2_CAP_STREAMING);
    fk.offered[2] = V4L2_PIX_FMT_H264;
    out = open_memstream(&text, &len);
    assert_non_null(out);
    assert_int_equal(v4l2_list_formats(out, FAKE_PATH, err, sizeof err), 0);
    fclose(out);
    assert_non_null(strstr(text, FAKE_PATH ": Fake camera (fake, "));
    assert_non_null(strstr(text, "\n  YUYV  "));
    assert_non_null(strstr(text, "luma copied out\n"));
    assert_non_null(strstr(text, "\n  GREY  "));
    assert_non_null(strstr(text, "luma read in place\n"));
    assert_non_null(strstr(text, "\n  H264  "));
    assert_non_null(strstr(text, "not read by symline\n"));
    free(text);
    assert_int_equal(fk.open_fds, 0);
    fake_reset(V4L2_CAP_VIDEO_OUTPUT | V4L2_CAP_STREAMING);
    assert_int_equal(v4l2_list_formats(stdout, FAKE_PATH, err, sizeof err), -1);
    assert_non_null(strstr(err, "not a video capture device"));
    assert_int_equal(fk.open_fds, 0);

    assert_string_equal(v4l2_device_path("0", buf, sizeof buf), "/dev/video0");
    assert_string_equal(v4l2_device_path("12", buf, sizeof buf), "/dev/video12");
    assert_string_equal(v4l2_device_path("/dev/video3", buf, sizeof buf), "/dev/video3");
    assert_string_equal(v4l2_device_path("cam0", buf, sizeof buf), "cam0");
    assert_null(v4l2_device_path("/a/very/long/path/that/does/not/fit", buf, 8));
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_default_format_and_description),
        cmocka_unit_test(test_freshest_hands_out_newest_once),
        cmocka_unit_test(test_all_frames_in_order),
        cmocka_unit_test(test_packed_converted_and_requeued),
        cmocka_unit_test(test_error_buffers_skipped),
        cmocka_unit_test(test_qbuf_retry),
        cmocka_unit_test(test_device_lost),
        cmocka_unit_test(test_interrupted_wait),
        cmocka_unit_test(test_open_failures_release_everything),
        cmocka_unit_test(test_mjpeg_decoded_damaged_skipped),
        cmocka_unit_test(test_list_formats_and_device_numbers),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}

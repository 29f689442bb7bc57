/* SPDX-License-Identifier: Apache-2.0 */
/*
 * libcamera source: a C++17 shim behind the C frame-source interface.
 *
 * libcamera completes requests on its own thread. The completion handler only
 * queues the request and writes a byte to a pipe; capsrc_next() polls that
 * pipe, so waiting for a frame is interrupted by signals exactly like the
 * V4L2 source's poll().
 */
#include "libcamera_source.h"

#include <cerrno>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <deque>
#include <memory>
#include <mutex>
#include <string>
#include <vector>

#include <fcntl.h>
#include <poll.h>
#include <sys/mman.h>
#include <unistd.h>

#include <libcamera/libcamera.h>

#include "pixfmt.h"

using namespace libcamera;

namespace {

constexpr uint32_t fourcc(char a, char b, char c, char d)
{
    return PIXFMT_FOURCC(a, b, c, d);
}

/* libcamera names formats with DRM fourccs; most match V4L2's, these do not. */
struct drm_v4l2 {
    uint32_t drm, v4l2;
};
const drm_v4l2 renamed[] = {
    {fourcc('R', '8', ' ', ' '), fourcc('G', 'R', 'E', 'Y')},
    {fourcc('R', 'G', '2', '4'), fourcc('B', 'G', 'R', '3')}, /* RGB888: bytes B, G, R */
    {fourcc('B', 'G', '2', '4'), fourcc('R', 'G', 'B', '3')}, /* BGR888: bytes R, G, B */
    {fourcc('Y', 'U', '1', '6'), fourcc('4', '2', '2', 'P')},
};

const pixfmt_info *from_drm(uint32_t drm)
{
    for (const auto &r : renamed) {
        if (r.drm == drm) return pixfmt_find(r.v4l2);
    }
    const pixfmt_info *f = pixfmt_find(drm);
    /* V4L2's multi-planar variants (NM12 ...) have no DRM name. */
    if (f != nullptr && f->name[0] != 'N' && f->name[1] == 'M') return nullptr;
    /* The shim does not decode compressed frames (V4L2 does: --device). */
    if (f != nullptr && f->layout == PIXFMT_JPEG) return nullptr;
    return f;
}

uint32_t to_drm(const pixfmt_info *f)
{
    for (const auto &r : renamed) {
        if (r.v4l2 == f->fourcc) return r.drm;
    }
    return f->fourcc;
}

struct lcsrc {
    std::unique_ptr<CameraManager> cm;
    std::shared_ptr<Camera> cam;
    std::unique_ptr<CameraConfiguration> config;
    std::unique_ptr<FrameBufferAllocator> alloc;
    Stream *stream = nullptr;
    std::vector<std::unique_ptr<Request>> requests;
    std::vector<void *> map;       /* per request: mapping of its first plane's dmabuf */
    std::vector<size_t> maplen;
    std::vector<size_t> mapoff;
    ControlList start_controls;
    const pixfmt_info *fmt = nullptr;
    uint32_t width = 0, height = 0, stride = 0;
    std::vector<uint8_t> unpacked;
    bool acquired = false, started = false, freshest = true;
    int wake[2] = {-1, -1};       /* completion -> poll() */
    std::mutex mu;                /* guards done and disconnected */
    std::deque<Request *> done;
    bool disconnected = false;
    Request *held = nullptr;
    capsrc_result pending = CAPSRC_OK; /* a failed re-queue on release, reported by the next lc_next */
    uint64_t number = 0;
    bool have_seq = false;
    uint32_t last_seq = 0;
    std::string id;

    void on_complete(Request *r)
    {
        {
            std::lock_guard<std::mutex> lock(mu);
            done.push_back(r);
        }
        notify();
    }
    void on_disconnect()
    {
        {
            std::lock_guard<std::mutex> lock(mu);
            disconnected = true;
        }
        notify();
    }
    void notify()
    {
        const char b = 1;
        /* A full pipe already wakes the reader: dropping the byte is fine. */
        ssize_t n = write(wake[1], &b, 1);
        (void)n;
    }
};

lcsrc *impl(capsrc *src)
{
    return static_cast<lcsrc *>(src->impl);
}

capsrc_result requeue(capsrc *src, lcsrc *c, Request *r)
{
    r->reuse(Request::ReuseBuffers);
    int ret = c->cam->queueRequest(r);
    if (ret == 0) return CAPSRC_OK;
    if (ret == -ENODEV) {
        capsrc_set_error(src, "camera %s: lost (%s); stopping", c->id.c_str(), std::strerror(-ret));
        return CAPSRC_LOST;
    }
    capsrc_set_error(src, "camera %s: queueing a request failed: %s", c->id.c_str(), std::strerror(-ret));
    return CAPSRC_ERROR;
}

capsrc_result lc_start(capsrc *src)
{
    lcsrc *c = impl(src);
    int ret = c->cam->start(&c->start_controls);
    if (ret != 0) {
        capsrc_set_error(src, "camera %s: start failed: %s", c->id.c_str(), std::strerror(-ret));
        return ret == -ENODEV ? CAPSRC_LOST : CAPSRC_ERROR;
    }
    c->started = true;
    for (auto &r : c->requests) {
        ret = c->cam->queueRequest(r.get());
        if (ret != 0) {
            capsrc_set_error(src, "camera %s: queueing a request failed: %s", c->id.c_str(), std::strerror(-ret));
            return ret == -ENODEV ? CAPSRC_LOST : CAPSRC_ERROR;
        }
    }
    return CAPSRC_OK;
}

void lc_release(capsrc *src)
{
    lcsrc *c = impl(src);
    if (c->held != nullptr) {
        Request *r = c->held;
        c->held = nullptr;
        const capsrc_result q = requeue(src, c, r);
        if (q != CAPSRC_OK && c->pending == CAPSRC_OK) c->pending = q;
    }
}

capsrc_result lc_next(capsrc *src, capsrc_frame *frame, int timeout_ms)
{
    lcsrc *c = impl(src);
    const int64_t deadline = timeout_ms >= 0 ? capsrc_now_ns() + int64_t(timeout_ms) * 1000000 : 0;
    const uint64_t skipped_before = src->stats.skipped_stale;
    lc_release(src);
    if (c->pending != CAPSRC_OK) return c->pending;
    for (;;) {
        std::deque<Request *> ready;
        bool lost;
        {
            std::lock_guard<std::mutex> lock(c->mu);
            ready.swap(c->done);
            lost = c->disconnected;
        }
        Request *newest = nullptr;
        FrameBuffer *newest_buf = nullptr;
        for (Request *r : ready) {
            FrameBuffer *b = r->findBuffer(c->stream);
            if (r->status() == Request::RequestCancelled || b == nullptr) {
                /* Cancelled while running: the pipeline stopped under us. */
                capsrc_set_error(src, "camera %s: request cancelled by the pipeline; stopping", c->id.c_str());
                return CAPSRC_LOST;
            }
            const FrameMetadata &md = b->metadata();
            if (c->have_seq && md.sequence > c->last_seq + 1) {
                src->stats.sequence_gaps += md.sequence - c->last_seq - 1;
            }
            c->have_seq = true;
            c->last_seq = md.sequence;
            const uint64_t need = uint64_t(c->stride) * (c->height - 1) + pixfmt_min_stride(c->fmt, c->width);
            if (md.status != FrameMetadata::FrameSuccess ||
                (!md.planes().empty() && md.planes()[0].bytesused != 0 && md.planes()[0].bytesused < need)) {
                src->stats.error_buffers++;
                capsrc_result q = requeue(src, c, r);
                if (q != CAPSRC_OK) return q;
                continue;
            }
            if (newest != nullptr) {
                src->stats.skipped_stale++;
                capsrc_result q = requeue(src, c, newest);
                if (q != CAPSRC_OK) return q;
            }
            newest = r;
            newest_buf = b;
            if (!c->freshest) {
                break;
            }
        }
        if (newest != nullptr && !c->freshest) {
            /* Put back what was not looked at, in order, for the next call. */
            std::lock_guard<std::mutex> lock(c->mu);
            bool after = false;
            std::deque<Request *> rest;
            for (Request *r : ready) {
                if (after) rest.push_back(r);
                if (r == newest) after = true;
            }
            c->done.insert(c->done.begin(), rest.begin(), rest.end());
            if (!rest.empty()) c->notify();
        }
        if (newest != nullptr) {
            const FrameMetadata &md = newest_buf->metadata();
            const size_t i = static_cast<size_t>(newest->cookie()); /* the request's buffer index */
            const uint8_t *base = static_cast<const uint8_t *>(c->map[i]) + c->mapoff[i];
            frame->width = c->width;
            frame->height = c->height;
            frame->number = c->number++;
            frame->sequence = md.sequence;
            frame->timestamp_ns = md.timestamp != 0 ? int64_t(md.timestamp) : capsrc_now_ns();
            frame->skipped = uint32_t(src->stats.skipped_stale - skipped_before);
            frame->convert_ns = 0;
            if (c->fmt->layout != PIXFMT_LUMA_PLANE) {
                const int64_t t0 = capsrc_now_ns();
                pixfmt_unpack_luma(c->fmt, base, c->stride, c->width, c->height, c->unpacked.data(), c->width);
                frame->convert_ns = capsrc_now_ns() - t0;
                frame->luma = c->unpacked.data();
                frame->stride = c->width;
                capsrc_result q = requeue(src, c, newest);
                if (q != CAPSRC_OK) return q;
            } else {
                frame->luma = base;
                frame->stride = c->stride;
                c->held = newest;
            }
            src->stats.delivered++;
            return CAPSRC_OK;
        }
        if (lost) {
            capsrc_set_error(src, "camera %s: disconnected; stopping", c->id.c_str());
            return CAPSRC_LOST;
        }
        int wait_ms = -1;
        if (timeout_ms >= 0) {
            const int64_t left = deadline - capsrc_now_ns();
            wait_ms = left > 0 ? int((left + 999999) / 1000000) : 0;
        }
        struct pollfd p;
        p.fd = c->wake[0];
        p.events = POLLIN;
        p.revents = 0;
        const int pr = poll(&p, 1, wait_ms);
        if (pr < 0) {
            if (errno == EINTR) return CAPSRC_INTERRUPTED;
            capsrc_set_error(src, "camera %s: poll failed: %s", c->id.c_str(), std::strerror(errno));
            return CAPSRC_ERROR;
        }
        if (pr == 0) {
            capsrc_set_error(src, "camera %s: no frame within %d ms", c->id.c_str(), timeout_ms);
            return CAPSRC_TIMEOUT;
        }
        char drain[64];
        while (read(c->wake[0], drain, sizeof drain) > 0) {
        }
    }
}

void teardown(lcsrc *c)
{
    if (c->cam) {
        if (c->started) {
            c->cam->stop();
            c->started = false;
        }
        c->cam->requestCompleted.disconnect(c, &lcsrc::on_complete);
        c->cam->disconnected.disconnect(c, &lcsrc::on_disconnect);
    }
    c->held = nullptr;
    c->done.clear();
    for (size_t i = 0; i < c->map.size(); i++) {
        if (c->map[i] != nullptr) munmap(c->map[i], c->maplen[i]);
    }
    c->map.clear();
    c->requests.clear();
    if (c->alloc && c->stream != nullptr) c->alloc->free(c->stream);
    c->alloc.reset();
    c->config.reset();
    if (c->cam && c->acquired) {
        c->cam->release();
        c->acquired = false;
    }
    c->cam.reset();
    if (c->cm) c->cm->stop();
    c->cm.reset();
    for (int &fd : c->wake) {
        if (fd >= 0) close(fd);
        fd = -1;
    }
}

void lc_close(capsrc *src)
{
    lcsrc *c = impl(src);
    if (c != nullptr) {
        teardown(c);
        delete c;
        src->impl = nullptr;
    }
}

const capsrc_ops lc_ops = {lc_start, lc_next, lc_release, lc_close};

bool all_digits(const char *s)
{
    if (*s == '\0') return false;
    for (; *s; s++) {
        if (*s < '0' || *s > '9') return false;
    }
    return true;
}

/* Quiet by default: libcamera's INFO lines would mix with the frame records' log. */
void quiet_logging()
{
    /* Read when libcamera logs for the first time, so set before the camera manager exists. */
    setenv("LIBCAMERA_LOG_LEVELS", "*:WARN", 0);
}

int configure(lcsrc *c, const libcamera_options *opt, char *desc, size_t desclen, char *err, size_t errlen)
{
    quiet_logging();
    if (pipe2(c->wake, O_CLOEXEC | O_NONBLOCK) != 0) {
        std::snprintf(err, errlen, "pipe: %s", std::strerror(errno));
        return -1;
    }
    c->cm = std::make_unique<CameraManager>();
    int ret = c->cm->start();
    if (ret != 0) {
        std::snprintf(err, errlen, "libcamera: camera manager failed to start: %s", std::strerror(-ret));
        c->cm.reset();
        return -1;
    }
    const auto cams = c->cm->cameras();
    if (all_digits(opt->camera)) {
        const unsigned long i = std::strtoul(opt->camera, nullptr, 10);
        if (i < cams.size()) c->cam = cams[i];
    }
    if (!c->cam) c->cam = c->cm->get(opt->camera);
    if (!c->cam) {
        std::snprintf(err, errlen, "libcamera: no camera '%s' (%zu camera%s found)", opt->camera, cams.size(),
                      cams.size() == 1 ? "" : "s");
        return -1;
    }
    c->id = c->cam->id();
    ret = c->cam->acquire();
    if (ret != 0) {
        std::snprintf(err, errlen, "camera %s: cannot acquire: %s", c->id.c_str(), std::strerror(-ret));
        return -1;
    }
    c->acquired = true;
    c->config = c->cam->generateConfiguration({StreamRole::Viewfinder});
    if (!c->config || c->config->size() != 1) {
        std::snprintf(err, errlen, "camera %s: no viewfinder configuration", c->id.c_str());
        return -1;
    }
    StreamConfiguration &sc = c->config->at(0);
    const pixfmt_info *want = nullptr;
    std::string offered;
    for (const PixelFormat &pf : sc.formats().pixelformats()) {
        const pixfmt_info *f = from_drm(pf.fourcc());
        offered += (offered.empty() ? "" : " ") + pf.toString();
        if (f != nullptr && (want == nullptr || f->preference < want->preference)) want = f;
    }
    if (opt->format != nullptr) {
        want = pixfmt_by_name(opt->format);
        if (want == nullptr || (want->name[0] != 'N' && want->name[1] == 'M') || want->layout == PIXFMT_JPEG) {
            std::snprintf(err, errlen, "unsupported format '%s' for libcamera", opt->format);
            return -1;
        }
    } else if (want == nullptr) {
        std::snprintf(err, errlen, "camera %s: none of its formats (%s) carries luma symline can read",
                      c->id.c_str(), offered.c_str());
        return -1;
    }
    sc.pixelFormat = PixelFormat(to_drm(want));
    if (opt->width) sc.size.width = opt->width;
    if (opt->height) sc.size.height = opt->height;
    sc.bufferCount = opt->buffers;
    const CameraConfiguration::Status vs = c->config->validate();
    if (vs == CameraConfiguration::Invalid) {
        std::snprintf(err, errlen, "camera %s: configuration %s invalid", c->id.c_str(), sc.toString().c_str());
        return -1;
    }
    if (sc.pixelFormat.fourcc() != to_drm(want)) {
        std::snprintf(err, errlen, "camera %s: format %s not supported (offered: %s)", c->id.c_str(), want->name,
                      offered.c_str());
        return -1;
    }
    ret = c->cam->configure(c->config.get());
    if (ret != 0) {
        std::snprintf(err, errlen, "camera %s: configure failed: %s", c->id.c_str(), std::strerror(-ret));
        return -1;
    }
    c->fmt = want;
    c->width = sc.size.width;
    c->height = sc.size.height;
    c->stride = sc.stride ? sc.stride : uint32_t(pixfmt_min_stride(want, c->width));
    if (c->width == 0 || c->height == 0 || c->width > 65535u || c->height > 65535u ||
        c->stride < pixfmt_min_stride(want, c->width) || (want->layout == PIXFMT_PACKED_422 && (c->width & 1u))) {
        std::snprintf(err, errlen, "camera %s: unusable frame %ux%u, stride %u", c->id.c_str(), c->width, c->height,
                      c->stride);
        return -1;
    }
    c->stream = sc.stream();
    c->alloc = std::make_unique<FrameBufferAllocator>(c->cam);
    ret = c->alloc->allocate(c->stream);
    if (ret < 2) {
        std::snprintf(err, errlen, "camera %s: buffer allocation failed (%d)", c->id.c_str(), ret);
        return -1;
    }
    const auto &bufs = c->alloc->buffers(c->stream);
    for (size_t i = 0; i < bufs.size(); i++) {
        const FrameBuffer::Plane &p0 = bufs[i]->planes()[0];
        const uint64_t need = uint64_t(c->stride) * (c->height - 1) + pixfmt_min_stride(want, c->width);
        if (p0.length < need) {
            std::snprintf(err, errlen, "camera %s: buffer of %u bytes too small", c->id.c_str(), p0.length);
            return -1;
        }
        /* Map from the start of the dmabuf: plane offsets need not be page aligned. */
        const size_t len = size_t(p0.offset) + p0.length;
        void *m = mmap(nullptr, len, PROT_READ, MAP_SHARED, p0.fd.get(), 0);
        if (m == MAP_FAILED) {
            std::snprintf(err, errlen, "camera %s: mmap failed: %s", c->id.c_str(), std::strerror(errno));
            return -1;
        }
        c->map.push_back(m);
        c->maplen.push_back(len);
        c->mapoff.push_back(p0.offset);
        std::unique_ptr<Request> r = c->cam->createRequest(i);
        if (!r || r->addBuffer(c->stream, bufs[i].get()) != 0) {
            std::snprintf(err, errlen, "camera %s: cannot create request %zu", c->id.c_str(), i);
            return -1;
        }
        c->requests.push_back(std::move(r));
    }
    if (want->layout != PIXFMT_LUMA_PLANE) c->unpacked.resize(size_t(c->width) * c->height);
    c->cam->requestCompleted.connect(c, &lcsrc::on_complete);
    c->cam->disconnected.connect(c, &lcsrc::on_disconnect);

    char extra[96] = "";
    if (opt->fps_num > 0) {
        const int64_t us = int64_t(1000000) * (opt->fps_den ? opt->fps_den : 1) / opt->fps_num;
        const int64_t limits[2] = {us, us};
        c->start_controls.set(controls::FrameDurationLimits, Span<const int64_t, 2>(limits));
        std::snprintf(extra, sizeof extra, ", frame duration %lld us requested", (long long)us);
    }
    if (opt->exposure_us >= 0) {
        c->start_controls.set(controls::AeEnable, false);
        c->start_controls.set(controls::ExposureTime, opt->exposure_us);
        const size_t n = std::strlen(extra);
        std::snprintf(extra + n, sizeof extra - n, ", exposure %d us requested", int(opt->exposure_us));
    }
    if (std::snprintf(desc, desclen, "libcamera camera %s: %s %ux%u stride %u, %zu requests%s%s", c->id.c_str(),
                      want->name, c->width, c->height, c->stride, c->requests.size(),
                      vs == CameraConfiguration::Adjusted ? " (adjusted by the pipeline)" : "", extra) < 0) {
        desc[0] = '\0';
    }
    return 0;
}

} // namespace

extern "C" capsrc *libcamera_source_open(const libcamera_options *opt, char *err, size_t errlen)
{
    if (opt->buffers < 2 || opt->buffers > 32) {
        std::snprintf(err, errlen, "buffer count %u out of range 2..32", opt->buffers);
        return nullptr;
    }
    lcsrc *c = new (std::nothrow) lcsrc;
    if (c == nullptr) {
        std::snprintf(err, errlen, "out of memory");
        return nullptr;
    }
    c->freshest = opt->freshest != 0;
    char desc[CAPSRC_ERRLEN];
    int ok;
    try {
        ok = configure(c, opt, desc, sizeof desc, err, errlen);
    } catch (const std::exception &e) {
        std::snprintf(err, errlen, "libcamera: %s", e.what());
        ok = -1;
    }
    if (ok != 0) {
        teardown(c);
        delete c;
        return nullptr;
    }
    capsrc *src = capsrc_alloc(&lc_ops, c);
    if (src == nullptr) {
        std::snprintf(err, errlen, "out of memory");
        teardown(c);
        delete c;
        return nullptr;
    }
    std::memcpy(src->description, desc, sizeof desc);
    return src;
}

extern "C" int libcamera_list_cameras(void *file)
{
    FILE *f = static_cast<FILE *>(file);
    quiet_logging();
    CameraManager cm;
    if (cm.start() != 0) return -1;
    int n = 0;
    for (const auto &cam : cm.cameras()) {
        std::fprintf(f, "%d: %s\n", n++, cam->id().c_str());
    }
    cm.stop();
    return n;
}

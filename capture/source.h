/* SPDX-License-Identifier: Apache-2.0 */
/*
 * A frame source: the one interface the capture loop sees, whether frames
 * come from a V4L2 device, a libcamera camera or files on disk.
 *
 * Life cycle: open (source-specific constructor) -> capsrc_start ->
 * capsrc_next / capsrc_release ... -> capsrc_close. capsrc_close stops
 * streaming, unmaps and closes everything, from any state, and is safe to
 * call after any error.
 *
 * Ownership: a frame returned by capsrc_next stays valid until
 * capsrc_release (or the next capsrc_next, which releases it first). Each
 * captured frame is handed out at most once.
 */
#ifndef SYMLINE_CAPTURE_SOURCE_H
#define SYMLINE_CAPTURE_SOURCE_H

#include <stddef.h>
#include <stdint.h>

#ifdef __cplusplus
extern "C" {
#endif

/* Results of capsrc_start / capsrc_next. Errors are negative. */
typedef enum capsrc_result {
    CAPSRC_OK = 0,
    CAPSRC_END = 1,         /* no more frames (replay finished) */
    CAPSRC_TIMEOUT = 2,     /* no frame within the timeout */
    CAPSRC_INTERRUPTED = 3, /* a signal arrived while waiting: check the stop flag, call again */
    CAPSRC_ERROR = -1,      /* an error; capsrc_error() says what */
    CAPSRC_LOST = -2        /* the device went away (unplugged, ENODEV/EIO) */
} capsrc_result;

/* One frame's 8-bit luma, row-major: pixel (x, y) at luma[y * stride + x]. */
typedef struct capsrc_frame {
    const uint8_t *luma;
    uint32_t width;
    uint32_t height;
    uint32_t stride;       /* bytes, >= width */
    uint64_t number;       /* 0, 1, 2 ... in the order frames are handed out */
    uint32_t sequence;     /* the driver's sequence number (replay: file index) */
    int64_t timestamp_ns;  /* capture time on CLOCK_MONOTONIC, nanoseconds */
    uint32_t skipped;      /* newer frames replaced older ones since the last frame (freshest mode) */
    int64_t convert_ns;    /* time spent extracting luma (packed formats; 0 when read in place) */
    const char *file;      /* replay: the file the frame came from; NULL for cameras */
} capsrc_frame;

/* Counters since capsrc_start. */
typedef struct capsrc_stats {
    uint64_t delivered;     /* frames handed out */
    uint64_t skipped_stale; /* older frames re-queued unprocessed in freshest mode */
    uint64_t error_buffers; /* buffers the driver flagged as corrupt, skipped */
    uint64_t requeue_errors;/* VIDIOC_QBUF (or request re-queue) failures recovered by a retry */
    uint64_t sequence_gaps; /* frames the driver dropped (jumps in its sequence numbers) */
} capsrc_stats;

typedef struct capsrc capsrc;

typedef struct capsrc_ops {
    capsrc_result (*start)(capsrc *src);
    capsrc_result (*next)(capsrc *src, capsrc_frame *frame, int timeout_ms);
    void (*release)(capsrc *src);
    void (*close)(capsrc *src);
} capsrc_ops;

#define CAPSRC_ERRLEN 256

struct capsrc {
    const capsrc_ops *ops;
    void *impl;                /* the source's own state */
    capsrc_stats stats;
    char error[CAPSRC_ERRLEN]; /* last error, "" when none */
    char description[CAPSRC_ERRLEN]; /* what was opened and granted, for the log */
};

/* Starts streaming. */
capsrc_result capsrc_start(capsrc *src);

/*
 * Waits up to timeout_ms (-1 = forever) for the next frame. Releases the
 * previous frame first if the caller still holds it.
 */
capsrc_result capsrc_next(capsrc *src, capsrc_frame *frame, int timeout_ms);

/* Gives the current frame's buffer back to the source (no-op when none is held). */
void capsrc_release(capsrc *src);

/* Stops streaming, releases every buffer, unmaps, closes and frees the source. NULL is fine. */
void capsrc_close(capsrc *src);

/* The last error message ("" when none). */
const char *capsrc_error(const capsrc *src);

/* For implementations: formats src->error. */
void capsrc_set_error(capsrc *src, const char *fmt, ...)
#if defined(__GNUC__)
    __attribute__((format(printf, 2, 3)))
#endif
    ;

/* For implementations: a zeroed capsrc with ops and impl set, or NULL when out of memory. */
capsrc *capsrc_alloc(const capsrc_ops *ops, void *impl);

/* CLOCK_MONOTONIC now, nanoseconds. */
int64_t capsrc_now_ns(void);

#ifdef __cplusplus
}
#endif

#endif

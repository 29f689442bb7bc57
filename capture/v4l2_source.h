/* SPDX-License-Identifier: Apache-2.0 */
/*
 * V4L2 source: a video capture device with mmap streaming I/O (single- or
 * multi-planar API), luma of GREY / planar YUV read in place, packed 4:2:2
 * deinterleaved (see pixfmt.h).
 */
#ifndef SYMLINE_CAPTURE_V4L2_SOURCE_H
#define SYMLINE_CAPTURE_V4L2_SOURCE_H

#include "source.h"

typedef struct v4l2_options {
    const char *device;   /* e.g. "/dev/video0" */
    uint32_t width;       /* requested size; 0 = keep the driver's current size */
    uint32_t height;
    const char *format;   /* fourcc name (pixfmt.h); NULL = the most direct format the device offers */
    uint32_t fps_num;     /* requested frame rate fps_num/fps_den; 0 = keep the driver's */
    uint32_t fps_den;
    uint32_t buffers;     /* mmap buffers to request (2..32); the driver may grant more */
    int freshest;         /* 1 = hand out the newest ready frame, re-queue older ones */
    int32_t exposure_100us; /* manual exposure time in 100 us units; < 0 = leave as is */
} v4l2_options;

/*
 * Opens and configures the device (QUERYCAP checks, format, size, frame
 * interval, exposure, buffers). Returns NULL with a message in err on
 * failure; on success src->description states what the driver granted.
 */
capsrc *v4l2_source_open(const v4l2_options *opt, char *err, size_t errlen);

#endif

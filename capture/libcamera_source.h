/* SPDX-License-Identifier: Apache-2.0 */
/*
 * libcamera source (built when pkg-config finds libcamera): the same frame
 * interface as the V4L2 source for cameras that libcamera drives (Raspberry
 * Pi camera modules, ISP pipelines, vimc). C interface to a small C++17 shim.
 */
#ifndef SYMLINE_CAPTURE_LIBCAMERA_SOURCE_H
#define SYMLINE_CAPTURE_LIBCAMERA_SOURCE_H

#include "source.h"

#ifdef __cplusplus
extern "C" {
#endif

typedef struct libcamera_options {
    const char *camera;   /* a camera id as libcamera lists it, or an index ("0" = first) */
    uint32_t width;       /* requested size; 0 = the pipeline's default */
    uint32_t height;
    const char *format;   /* fourcc name (pixfmt.h); NULL = the most direct one offered */
    uint32_t fps_num;     /* requested rate via FrameDurationLimits; 0 = leave */
    uint32_t fps_den;
    uint32_t buffers;     /* buffers and requests in flight, 2..32 */
    int freshest;         /* 1 = hand out the newest completed request, re-queue older ones */
    int32_t exposure_us;  /* manual exposure (AeEnable off); < 0 = automatic */
} libcamera_options;

/* Opens, acquires and configures the camera; NULL with a message in err on failure. */
capsrc *libcamera_source_open(const libcamera_options *opt, char *err, size_t errlen);

/* Writes the ids of the cameras libcamera sees to f, one per line; returns their number or -1. */
int libcamera_list_cameras(void *file);

#ifdef __cplusplus
}
#endif

#endif

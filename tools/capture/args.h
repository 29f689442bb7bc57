/* SPDX-License-Identifier: Apache-2.0 */
/*
 * Command line of symline-capture.
 */
#ifndef SYMLINE_CAPTURE_ARGS_H
#define SYMLINE_CAPTURE_ARGS_H

#include <stdint.h>

#include "symline/detect.h"

typedef struct app_options {
    const char *device;  /* V4L2 device path (a bare --device N is /dev/videoN) */
    char device_buf[64]; /* holds that path when it was made from a number */
    const char *camera;
    const char *replay;
    int list_cameras;       /* --list-cameras: print libcamera's cameras and exit */
    int list_devices;       /* --list-devices: print the V4L2 devices and exit */
    int list_formats;       /* --list-formats: print the formats of --device and exit */
    uint64_t frames;        /* 0 = until stopped or the replay ends */
    uint32_t width, height; /* 0 = the source's default */
    const char *format;
    uint32_t fps_num, fps_den;   /* 0 = the source's default */
    uint32_t rate_num, rate_den; /* replay pace; 0/0 = the recording's own rate (Y4M) or unpaced */
    int rate_max;                /* --rate max: replay as fast as frames are read */
    uint32_t buffers;
    int all_frames;      /* 1 = process every frame instead of the freshest */
    int32_t exposure_us; /* < 0 = leave the device's exposure alone */
    int timeout_ms;
    int loop;
    uint32_t summary_s;
    uint32_t snapshot_every;
    const char *snapshot_dir;
    uint32_t record_every;
    const char *record_dir;
    int profile;        /* --profile: time per detector stage */
    uint32_t repeat;    /* --repeat: detections per frame */
    symline_config cfg; /* detector settings, options as in `symline lines` */
    int bin;            /* --bin, as in `symline lines` (detopts_bin) */
} app_options;

#define APP_EXIT_OK 0
#define APP_EXIT_FAIL 1
#define APP_EXIT_USAGE 2

/* Parses argv into o. Returns 0, 1 when --help was printed, or APP_EXIT_USAGE. */
int app_parse_args(int argc, char **argv, app_options *o);

#endif

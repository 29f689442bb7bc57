/* SPDX-License-Identifier: Apache-2.0 */
/*
 * Command line of symline-capture.
 */
#include "args.h"

#include "detopts.h"
#include "hostopts.h"
#include "stageprof.h"
#include "v4l2_list.h"

#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include <stddef.h>

static int usage_error(const char *fmt, const char *arg)
{
    char msg[256];
    snprintf(msg, sizeof msg, fmt, arg);
    return hostopts_usage_error("symline-capture", "symline-capture", "%s", msg);
}

static void usage(FILE *f)
{
    fputs(
        "usage: symline-capture SOURCE [options]\n"
        "\n"
        "Source (one):\n"
        "  --device /dev/videoN   V4L2 capture device (--device N means /dev/videoN)\n"
        "  --list-devices         print the V4L2 devices and the formats symline reads, then exit\n"
        "  --list-formats         with --device: print its formats, sizes and frame rates, then "
        "exit\n"
#ifdef SYMLINE_HAVE_LIBCAMERA
        "  --camera ID|INDEX      libcamera camera, by id or by index (0 = first)\n"
        "  --list-cameras         print the cameras libcamera sees, then exit\n"
#endif
        "  --replay PATH          folder of .pgm/.png/.jpg frames (name order; *.mask.* are\n"
        "                         skipped), one image, a .y4m stream, or a text file listing\n"
        "                         one image path per line\n"
        "\n"
        "Capture:\n"
        "  --frames N             stop after N frames (0 = until stopped; default)\n"
        "  --width W --height H   requested frame size (the granted size is reported)\n"
        "  --format FOURCC        GREY NV12 NV21 YU12 YV12 NV16 NV61 422P YUYV YVYU UYVY VYUY,\n"
        "                         multi-planar NM12 NM21 YM12 YM21 NM16 NM61 YM16,\n"
        "                         packed RGB RGB3 BGR3 XR24 AR24 XB24 AB24 (converted to luma),\n"
        "                         8-bit Bayer BA81 GBRG GRBG RGGB (converted to luma),\n"
        "                         Motion-JPEG MJPG JPEG (decoded to luma)\n"
        "                         (default: the most direct one the device offers)\n"
        "  --fps F[/D]            requested frame rate of the camera\n"
        "  --rate F[/D]|max       replay pace in frames per second; default: a .y4m's own\n"
        "                         frame rate, image files as fast as they are read\n"
        "  --buffers N            mmap buffers / request queue depth, 2..32 (default 4)\n"
        "  --all-frames           process every frame in order; default is freshest-frame\n"
        "                         mode: when several frames are ready, the newest is\n"
        "                         processed and the older ones are returned unprocessed\n"
        "  --exposure US          manual exposure time in microseconds, if the device offers it\n"
        "  --timeout MS           give up when no frame arrives for MS ms (default 2000)\n"
        "  --loop                 replay: start over after the last frame\n"
        "\n"
        "Detector (as in `symline lines`):\n",
        f);
    detopts_help(f);
    fputs("\n"
          "Output:\n"
          "  --summary-every S      rate and latency summary on stderr every S seconds (default 5, "
          "0 = off)\n"

          "  --record K DIR         write the luma of every K-th frame as PGM (replayable)\n"
          "  --snapshot-every K DIR write every K-th frame with its detections drawn over it\n"
          "                         (lines solid, curves dotted) as DIR/snapNNNNNN.png\n"
          "  --profile              split each frame's detect time by the detector's stages\n"
          "                         (\"detect_stages_ms\" in the records, means in the final\n"
          "                         summary)\n"
          "  --repeat N             run the detection N times per frame, 1..1000 (default 1):\n"
          "                         a slower processor, or the detector beside other work;\n"
          "                         records hold one detection's output, the time of all N\n"
          "\n"
          "Options take --opt VALUE or --opt=VALUE. --version prints the version.\n"
          "Exit status: 0 stopped normally (frame count, end of replay, SIGINT/SIGTERM,\n"
          "stdout closed); 1 capture error (device lost, timeout, driver error); 2 usage error.\n",
          f);
}

static int parse_fps(const char *s, uint32_t *num, uint32_t *den)
{
    char buf[32];
    char *slash;
    if (s == NULL || strlen(s) >= sizeof buf) {
        return -1;
    }
    strcpy(buf, s);
    slash = strchr(buf, '/');
    *den = 1;
    if (slash != NULL) {
        *slash = '\0';
        if (detopts_u32(slash + 1, 1, 1000000, den) != 0) {
            return -1;
        }
    }
    return detopts_u32(buf, 1, 1000000, num);
}

enum {
    OPT_DEVICE = 0x100,
    OPT_LIST_DEVICES,
    OPT_LIST_FORMATS,
    OPT_CAMERA,
    OPT_LIST_CAMERAS,
    OPT_REPLAY,
    OPT_FRAMES,
    OPT_WIDTH,
    OPT_HEIGHT,
    OPT_FORMAT,
    OPT_FPS,
    OPT_RATE,
    OPT_BUFFERS,
    OPT_ALL_FRAMES,
    OPT_EXPOSURE,
    OPT_TIMEOUT,
    OPT_LOOP,
    OPT_SUMMARY,
    OPT_RECORD,
    OPT_SNAPSHOT,
    OPT_PROFILE,
    OPT_REPEAT
};

static const struct option own_options[] = {
    {"help", no_argument, NULL, 'h'},
    {"version", no_argument, NULL, 'V'},
    {"device", required_argument, NULL, OPT_DEVICE},
    {"list-devices", no_argument, NULL, OPT_LIST_DEVICES},
    {"list-formats", no_argument, NULL, OPT_LIST_FORMATS},
    {"camera", required_argument, NULL, OPT_CAMERA},
    {"list-cameras", no_argument, NULL, OPT_LIST_CAMERAS},
    {"replay", required_argument, NULL, OPT_REPLAY},
    {"frames", required_argument, NULL, OPT_FRAMES},
    {"width", required_argument, NULL, OPT_WIDTH},
    {"height", required_argument, NULL, OPT_HEIGHT},
    {"format", required_argument, NULL, OPT_FORMAT},
    {"fps", required_argument, NULL, OPT_FPS},
    {"rate", required_argument, NULL, OPT_RATE},
    {"buffers", required_argument, NULL, OPT_BUFFERS},
    {"all-frames", no_argument, NULL, OPT_ALL_FRAMES},
    {"exposure", required_argument, NULL, OPT_EXPOSURE},
    {"timeout", required_argument, NULL, OPT_TIMEOUT},
    {"loop", no_argument, NULL, OPT_LOOP},
    {"summary-every", required_argument, NULL, OPT_SUMMARY},
    {"record", required_argument, NULL, OPT_RECORD},
    {"snapshot-every", required_argument, NULL, OPT_SNAPSHOT},
    {"profile", no_argument, NULL, OPT_PROFILE},
    {"repeat", required_argument, NULL, OPT_REPEAT},
};
#define OWN_OPTIONS (sizeof own_options / sizeof own_options[0])

/* One option of symline-capture's own (not a detector option); 0 ok, else APP_EXIT_USAGE. */
static int apply_own(app_options *o, int c, const char *arg, int argc, char **argv)
{
    uint32_t v;
    switch (c) {
    case OPT_DEVICE:
        o->device = v4l2_device_path(arg, o->device_buf, sizeof o->device_buf);
        if (o->device == NULL) {
            o->device = arg;
        }
        return 0;
    case OPT_LIST_DEVICES: o->list_devices = 1; return 0;
    case OPT_LIST_FORMATS: o->list_formats = 1; return 0;
    case OPT_CAMERA: o->camera = arg; return 0;
    case OPT_LIST_CAMERAS: o->list_cameras = 1; return 0;
    case OPT_REPLAY: o->replay = arg; return 0;
    case OPT_FRAMES:
        if (detopts_u32(arg, 0, 0xffffffffu, &v) != 0) {
            return usage_error("--frames needs a count (0 = until stopped)%s", "");
        }
        o->frames = v;
        return 0;
    case OPT_WIDTH:
    case OPT_HEIGHT:
        if (detopts_u32(arg, 1, 65535, &v) != 0) {
            return usage_error("%s needs a size 1..65535", c == OPT_WIDTH ? "--width" : "--height");
        }
        *(c == OPT_WIDTH ? &o->width : &o->height) = v;
        return 0;
    case OPT_FORMAT: o->format = arg; return 0;
    case OPT_FPS:
        return parse_fps(arg, &o->fps_num, &o->fps_den) == 0
                   ? 0
                   : usage_error("--fps needs a rate F or F/D%s", "");
    case OPT_RATE:
        if (strcmp(arg, "max") == 0) {
            o->rate_max = 1;
            return 0;
        }
        return parse_fps(arg, &o->rate_num, &o->rate_den) == 0
                   ? 0
                   : usage_error("--rate needs a rate F or F/D, or 'max'%s", "");
    case OPT_BUFFERS:
        return detopts_u32(arg, 2, 32, &o->buffers) == 0
                   ? 0
                   : usage_error("--buffers needs a count 2..32%s", "");
    case OPT_ALL_FRAMES: o->all_frames = 1; return 0;
    case OPT_EXPOSURE:
        if (detopts_u32(arg, 100, 100000000, &v) != 0) {
            return usage_error("--exposure needs microseconds >= 100%s", "");
        }
        o->exposure_us = (int32_t)v;
        return 0;
    case OPT_TIMEOUT:
        if (detopts_u32(arg, 1, 3600000, &v) != 0) {
            return usage_error("--timeout needs milliseconds 1..3600000%s", "");
        }
        o->timeout_ms = (int)v;
        return 0;
    case OPT_LOOP: o->loop = 1; return 0;
    case OPT_PROFILE:
        if (!stageprof_available()) {
            return usage_error("--profile: this build's detector has no stage marks%s", "");
        }
        o->profile = 1;
        return 0;
    case OPT_REPEAT:
        return detopts_u32(arg, 1, 1000, &o->repeat) == 0
                   ? 0
                   : usage_error("--repeat needs a count 1..1000%s", "");
    case OPT_SUMMARY:
        return detopts_u32(arg, 0, 86400, &o->summary_s) == 0
                   ? 0
                   : usage_error("--summary-every needs seconds%s", "");
    case OPT_RECORD:
    case OPT_SNAPSHOT:
        /* K DIR: the folder is the next argument. */
        if (detopts_u32(arg, 1, 0xffffffffu, &v) != 0 || optind >= argc) {
            return usage_error("%s needs K DIR", c == OPT_RECORD ? "--record" : "--snapshot-every");
        }
        if (c == OPT_RECORD) {
            o->record_every = v;
            o->record_dir = argv[optind++];
        } else {
            o->snapshot_every = v;
            o->snapshot_dir = argv[optind++];
        }
        return 0;
    default: return usage_error("unknown option%s", "");
    }
}

/* 0 ok, 1 help shown, EXIT_USAGE on error. */
int app_parse_args(int argc, char **argv, app_options *o)
{
    struct option longopts[OWN_OPTIONS + 64];
    int c, nsrc, rc;
    size_t n;
    detopts det;
    char msg[128];
    memset(o, 0, sizeof *o);
    o->buffers = 4;
    o->exposure_us = -1;
    detopts_init(&det);
    o->timeout_ms = 2000;
    o->repeat = 1u;
    o->summary_s = 5;
    memcpy(longopts, own_options, sizeof own_options);
    n = OWN_OPTIONS + detopts_longopts(longopts + OWN_OPTIONS, 63);
    memset(&longopts[n], 0, sizeof longopts[n]);
    optind = 1;
    while ((c = hostopts_next(argc, argv, ":h", longopts, "symline-capture", "symline-capture")) !=
           -1) {
        if (c == HOSTOPTS_HELP) {
            usage(stdout);
            return 1;
        } else if (c == HOSTOPTS_VERSION) {
            hostopts_version("symline-capture");
            return 1;
        } else if (c == HOSTOPTS_ERROR) {
            return APP_EXIT_USAGE;
        } else if ((rc = detopts_apply(&det, c, optarg, msg, sizeof msg)) != 0) {
            if (rc < 0) {
                return usage_error("%s", msg);
            }
        } else if ((rc = apply_own(o, c, optarg, argc, argv)) != 0) {
            return rc;
        }
    }
    if (optind < argc) {
        return usage_error("unexpected argument '%s'", argv[optind]);
    }
    detopts_finish(&det);
    o->cfg = det.cfg;
    o->bin = (int)det.bin;
    if (o->list_devices) {
        return 0;
    }
    if (o->list_formats) {
        return o->device != NULL ? 0 : usage_error("--list-formats needs --device%s", "");
    }
    if (o->list_cameras) {
#ifndef SYMLINE_HAVE_LIBCAMERA
        return usage_error("--list-cameras: this build has no libcamera support%s", "");
#else
        return 0;
#endif
    }
    nsrc = (o->device != NULL) + (o->camera != NULL) + (o->replay != NULL);
    if (nsrc != 1) {
        return usage_error("give exactly one of --device, --camera, --replay%s", "");
    }
    if ((o->rate_num != 0 || o->rate_max) && o->replay == NULL) {
        return usage_error("--rate paces a replay; a camera's rate is --fps%s", "");
    }
#ifndef SYMLINE_HAVE_LIBCAMERA
    if (o->camera != NULL) {
        return usage_error("--camera: this build has no libcamera support%s", "");
    }
#endif
    return 0;
}

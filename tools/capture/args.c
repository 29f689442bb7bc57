/*
 * Command line of symline-capture.
 */
#include "args.h"

#include "detopts.h"

#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include <stddef.h>

static int usage_error(const char *fmt, const char *arg)
{
    fputs("symline-capture: ", stderr);
    fprintf(stderr, fmt, arg);
    fputs(" (try --help)\n", stderr);
    return APP_EXIT_USAGE;
}

static void usage(FILE *f)
{
    fputs("usage: symline-capture SOURCE [options]\n"
          "\n"
          "Source (one):\n"
          "  --device /dev/videoN   V4L2 capture device\n"
#ifdef SYMLINE_HAVE_LIBCAMERA
          "  --camera ID|INDEX      libcamera camera, by id or by index (0 = first)\n"
          "  --list-cameras         print the cameras libcamera sees, then exit\n"
#endif
          "  --replay PATH          folder of .pgm/.png frames (name order), one image, a\n"
          "                         .y4m stream, or a text file listing one image path per line\n"
          "\n"
          "Capture:\n"
          "  --frames N             stop after N frames (0 = until stopped; default)\n"
          "  --width W --height H   requested frame size (the granted size is reported)\n"
          "  --format FOURCC        GREY NV12 NV21 YU12 YV12 NV16 NV61 422P YUYV YVYU UYVY VYUY,\n"
          "                         multi-planar NM12 NM21 YM12 YM21 NM16 NM61 YM16,\n"
          "                         packed RGB RGB3 BGR3 XR24 AR24 XB24 AB24 (converted to luma)\n"
          "                         (default: the most direct one the device offers)\n"
          "  --fps F[/D]            requested frame rate (replay: delivery pace)\n"
          "  --buffers N            mmap buffers / request queue depth, 2..32 (default 4)\n"
          "  --all-frames           process every frame in order; default is freshest-frame\n"
          "                         mode: when several frames are ready, the newest is\n"
          "                         processed and the older ones are returned unprocessed\n"
          "  --exposure US          manual exposure time in microseconds, if the device offers it\n"
          "  --timeout MS           give up when no frame arrives for MS ms (default 2000)\n"
          "  --loop                 replay: start over after the last frame\n"
          "\n"
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
          "\n"
          "Exit status: 0 stopped normally (frame count, end of replay, SIGINT/SIGTERM);\n"
          "1 capture error (device lost, timeout, driver error); 2 usage error.\n",
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

/* 0 ok, 1 help shown, EXIT_USAGE on error. */
int app_parse_args(int argc, char **argv, app_options *o)
{
    int i, nsrc, rc;
    detopts det;
    char msg[128];
    uint32_t v;
    memset(o, 0, sizeof *o);
    o->buffers = 4;
    o->exposure_us = -1;
    detopts_init(&det);
    o->timeout_ms = 2000;
    o->summary_s = 5;
    for (i = 1; i < argc; i++) {
        const char *a = argv[i];
        const char *next = i + 1 < argc ? argv[i + 1] : NULL;
        if (strcmp(a, "--help") == 0 || strcmp(a, "-h") == 0) {
            usage(stdout);
            return 1;
        } else if (strcmp(a, "--device") == 0 && next) {
            o->device = next;
            i++;
        } else if (strcmp(a, "--camera") == 0 && next) {
            o->camera = next;
            i++;
        } else if (strcmp(a, "--list-cameras") == 0) {
            o->list_cameras = 1;
        } else if (strcmp(a, "--replay") == 0 && next) {
            o->replay = next;
            i++;
        } else if (strcmp(a, "--frames") == 0) {
            if (detopts_u32(next, 0, 0xffffffffu, &v) != 0) {
                return usage_error("--frames needs a count (0 = until stopped)%s", "");
            }
            o->frames = v;
            i++;
        } else if (strcmp(a, "--width") == 0 || strcmp(a, "--height") == 0) {
            if (detopts_u32(next, 1, 65535, &v) != 0) {
                return usage_error("%s needs a size 1..65535", a);
            }
            *(a[2] == 'w' ? &o->width : &o->height) = v;
            i++;
        } else if (strcmp(a, "--format") == 0 && next) {
            o->format = next;
            i++;
        } else if (strcmp(a, "--fps") == 0) {
            if (parse_fps(next, &o->fps_num, &o->fps_den) != 0) {
                return usage_error("--fps needs a rate F or F/D%s", "");
            }
            i++;
        } else if (strcmp(a, "--buffers") == 0) {
            if (detopts_u32(next, 2, 32, &o->buffers) != 0) {
                return usage_error("--buffers needs a count 2..32%s", "");
            }
            i++;
        } else if (strcmp(a, "--all-frames") == 0) {
            o->all_frames = 1;
        } else if (strcmp(a, "--exposure") == 0) {
            if (detopts_u32(next, 100, 100000000, &v) != 0) {
                return usage_error("--exposure needs microseconds >= 100%s", "");
            }
            o->exposure_us = (int32_t)v;
            i++;
        } else if (strcmp(a, "--timeout") == 0) {
            if (detopts_u32(next, 1, 3600000, &v) != 0) {
                return usage_error("--timeout needs milliseconds 1..3600000%s", "");
            }
            o->timeout_ms = (int)v;
            i++;
        } else if (strcmp(a, "--loop") == 0) {
            o->loop = 1;
        } else if (strcmp(a, "--summary-every") == 0) {
            if (detopts_u32(next, 0, 86400, &o->summary_s) != 0) {
                return usage_error("--summary-every needs seconds%s", "");
            }
            i++;
        } else if (strcmp(a, "--record") == 0 || strcmp(a, "--snapshot-every") == 0) {
            if (detopts_u32(next, 1, 0xffffffffu, &v) != 0 || i + 2 >= argc) {
                return usage_error("%s needs K DIR", a);
            }
            if (a[2] == 'r') {
                o->record_every = v;
                o->record_dir = argv[i + 2];
            } else {
                o->snapshot_every = v;
                o->snapshot_dir = argv[i + 2];
            }
            i += 2;
        } else if ((rc = detopts_parse(&det, argc, argv, &i, msg, sizeof msg)) != 0) {
            if (rc < 0) {
                return usage_error("%s", msg);
            }
        } else {
            return usage_error("unknown option or missing value: '%s'", a);
        }
    }
    detopts_finish(&det);
    o->cfg = det.cfg;
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
#ifndef SYMLINE_HAVE_LIBCAMERA
    if (o->camera != NULL) {
        return usage_error("--camera: this build has no libcamera support%s", "");
    }
#endif
    return 0;
}

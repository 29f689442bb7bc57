/* SPDX-License-Identifier: Apache-2.0 */
/*
 * symline-capture: the front end of the on-robot loop (capture/loop.h).
 * Frames from a V4L2 device, a libcamera camera or files; the line detector
 * on each; one JSON line per frame on stdout; a rate and latency summary on
 * stderr.
 */
#define _POSIX_C_SOURCE 200809L
#include <errno.h>
#include <signal.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>

#include "args.h"
#include "loop.h"
#include "replay_source.h"
#include "source.h"
#include "v4l2_list.h"
#include "v4l2_source.h"
#ifdef SYMLINE_HAVE_LIBCAMERA
#include "libcamera_source.h"
#endif

/* The number of the signal that asked the loop to stop; 0 while running. */
static volatile sig_atomic_t stop_signal;

static void on_stop(int sig)
{
    stop_signal = sig;
}

static capsrc *open_source(const app_options *o, char *err, size_t errlen)
{
    if (o->device != NULL) {
        v4l2_options v;
        memset(&v, 0, sizeof v);
        v.device = o->device;
        v.width = o->width;
        v.height = o->height;
        v.format = o->format;
        v.fps_num = o->fps_num;
        v.fps_den = o->fps_den;
        v.buffers = o->buffers;
        v.freshest = !o->all_frames;
        v.exposure_100us = o->exposure_us >= 0 ? o->exposure_us / 100 : -1;
        return v4l2_source_open(&v, err, errlen);
    }
#ifdef SYMLINE_HAVE_LIBCAMERA
    if (o->camera != NULL) {
        libcamera_options c;
        memset(&c, 0, sizeof c);
        c.camera = o->camera;
        c.width = o->width;
        c.height = o->height;
        c.format = o->format;
        c.fps_num = o->fps_num;
        c.fps_den = o->fps_den;
        c.buffers = o->buffers;
        c.freshest = !o->all_frames;
        c.exposure_us = o->exposure_us;
        return libcamera_source_open(&c, err, errlen);
    }
#endif
    {
        replay_options r;
        memset(&r, 0, sizeof r);
        r.path = o->replay;
        /* --rate sets the pace; --fps is accepted as before when --rate is absent. */
        r.fps_num = o->rate_num ? o->rate_num : o->fps_num;
        r.fps_den = o->rate_num ? o->rate_den : o->fps_den;
        r.unpaced = o->rate_max;
        r.loop = o->loop;
        r.stop = &stop_signal; /* a list read from a pipe gives up on a stop signal */
        return replay_source_open(&r, err, errlen);
    }
}

static int make_dir(const char *dir)
{
    if (mkdir(dir, 0777) != 0 && errno != EEXIST) {
        fprintf(stderr, "symline-capture: cannot create %s: %s\n", dir, strerror(errno));
        return -1;
    }
    return 0;
}

int main(int argc, char **argv)
{
    app_options o;
    caploop_options lo;
    capsrc *src;
    struct sigaction sa;
    char err[512];
    int rc;

    rc = app_parse_args(argc, argv, &o);
    if (rc != 0) {
        return rc == 1 ? APP_EXIT_OK : rc;
    }
    if (o.list_devices) {
        rc = v4l2_list_devices(stdout, "/dev", err, sizeof err);
        if (rc < 0) {
            fprintf(stderr, "symline-capture: %s\n", err);
        }
        return rc < 0 ? APP_EXIT_FAIL : APP_EXIT_OK;
    }
    if (o.list_formats) {
        if (v4l2_list_formats(stdout, o.device, err, sizeof err) != 0) {
            fprintf(stderr, "symline-capture: %s\n", err);
            return APP_EXIT_FAIL;
        }
        return APP_EXIT_OK;
    }
#ifdef SYMLINE_HAVE_LIBCAMERA
    if (o.list_cameras) {
        return libcamera_list_cameras(stdout) >= 0 ? APP_EXIT_OK : APP_EXIT_FAIL;
    }
#endif
    if ((o.record_dir && make_dir(o.record_dir) != 0) ||
        (o.snapshot_dir && make_dir(o.snapshot_dir) != 0)) {
        return APP_EXIT_FAIL;
    }

    /* No SA_RESTART: a stop signal must wake the wait for a frame. */
    memset(&sa, 0, sizeof sa);
    sa.sa_handler = on_stop;
    sigemptyset(&sa.sa_mask);
    sigaction(SIGINT, &sa, NULL);
    sigaction(SIGTERM, &sa, NULL);
    signal(SIGPIPE, SIG_IGN);

    src = open_source(&o, err, sizeof err);
    if (src == NULL) {
        fprintf(stderr, "symline-capture: %s\n", err);
        return APP_EXIT_FAIL;
    }
    fprintf(stderr, "symline-capture: %s\n", src->description);

    memset(&lo, 0, sizeof lo);
    lo.frames = o.frames;
    lo.timeout_ms = o.timeout_ms;
    lo.summary_s = o.summary_s;
    lo.snapshot_every = o.snapshot_every;
    lo.snapshot_dir = o.snapshot_dir;
    lo.record_every = o.record_every;
    lo.record_dir = o.record_dir;
    lo.profile = o.profile;
    lo.repeat = o.repeat;
    lo.cfg = &o.cfg;
    lo.bin = o.bin;
    rc = caploop_run(src, &lo, &stop_signal);
    capsrc_close(src);
    return rc == 0 ? APP_EXIT_OK : APP_EXIT_FAIL;
}

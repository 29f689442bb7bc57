/*
 * symline-capture: the on-robot loop. Frames from a V4L2 device, a libcamera
 * camera or files; one JSON line per frame on stdout; a rate and latency
 * summary on stderr.
 */
#define _POSIX_C_SOURCE 200809L
#include <errno.h>
#include <signal.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>

#include "imgio.h"
#include "replay_source.h"
#include "source.h"
#include "v4l2_source.h"
#ifdef SYMLINE_HAVE_LIBCAMERA
#include "libcamera_source.h"
#endif

#define EXIT_OK 0
#define EXIT_FAIL 1
#define EXIT_USAGE 2

static volatile sig_atomic_t stop_requested;
static volatile sig_atomic_t stop_signal;

static void on_stop(int sig)
{
    stop_requested = 1;
    stop_signal = sig;
}

typedef struct app_options {
    const char *device;
    const char *camera;
    const char *replay;
    uint64_t frames;        /* 0 = until stopped or the replay ends */
    uint32_t width, height;
    const char *format;
    uint32_t fps_num, fps_den;
    uint32_t buffers;
    int all_frames;         /* 1 = process every frame instead of the freshest */
    int32_t exposure_100us;
    int timeout_ms;
    int loop;
    uint32_t summary_s;
    uint32_t snapshot_every;
    const char *snapshot_dir;
    uint32_t record_every;
    const char *record_dir;
} app_options;

static int usage_error(const char *fmt, const char *arg)
{
    fputs("symline-capture: ", stderr);
    fprintf(stderr, fmt, arg);
    fputs(" (try --help)\n", stderr);
    return EXIT_USAGE;
}

static void usage(FILE *f)
{
    fputs("usage: symline-capture SOURCE [options]\n"
          "\n"
          "Source (one):\n"
          "  --device /dev/videoN   V4L2 capture device\n"
#ifdef SYMLINE_HAVE_LIBCAMERA
          "  --camera ID|INDEX      libcamera camera, by id or by index (0 = first)\n"
#endif
          "  --replay PATH          folder of .pgm/.png frames (name order), one image, or a\n"
          "                         text file listing one image path per line\n"
          "\n"
          "Capture:\n"
          "  --frames N             stop after N frames (0 = until stopped; default)\n"
          "  --width W --height H   requested frame size (the granted size is reported)\n"
          "  --format FOURCC        GREY NV12 NV21 YU12 YV12 NV16 NV61 YU16 YUYV YVYU UYVY VYUY\n"
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
          "Output:\n"
          "  --summary-every S      rate and latency summary on stderr every S seconds (default 5, 0 = off)\n"
          "  --snapshot-every K DIR write every K-th frame with the detected lines drawn over it\n"
          "  --record K DIR         write the luma of every K-th frame as PGM (replayable)\n"
          "\n"
          "Exit status: 0 stopped normally (frame count, end of replay, SIGINT/SIGTERM);\n"
          "1 capture error (device lost, timeout, driver error); 2 usage error.\n",
          f);
}

static int parse_u32(const char *s, uint32_t lo, uint32_t hi, uint32_t *out)
{
    char *end;
    unsigned long v;
    if (s == NULL || *s < '0' || *s > '9') {
        return -1;
    }
    errno = 0;
    v = strtoul(s, &end, 10);
    if (errno != 0 || *end != '\0' || v < lo || v > hi) {
        return -1;
    }
    *out = (uint32_t)v;
    return 0;
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
        if (parse_u32(slash + 1, 1, 1000000, den) != 0) {
            return -1;
        }
    }
    return parse_u32(buf, 1, 1000000, num);
}

/* 0 ok, 1 help shown, EXIT_USAGE on error. */
static int parse_args(int argc, char **argv, app_options *o)
{
    int i, nsrc;
    uint32_t v;
    memset(o, 0, sizeof *o);
    o->buffers = 4;
    o->exposure_100us = -1;
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
        } else if (strcmp(a, "--replay") == 0 && next) {
            o->replay = next;
            i++;
        } else if (strcmp(a, "--frames") == 0) {
            if (parse_u32(next, 0, 0xffffffffu, &v) != 0) {
                return usage_error("--frames needs a count (0 = until stopped)%s", "");
            }
            o->frames = v;
            i++;
        } else if (strcmp(a, "--width") == 0 || strcmp(a, "--height") == 0) {
            if (parse_u32(next, 1, 65535, &v) != 0) {
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
            if (parse_u32(next, 2, 32, &o->buffers) != 0) {
                return usage_error("--buffers needs a count 2..32%s", "");
            }
            i++;
        } else if (strcmp(a, "--all-frames") == 0) {
            o->all_frames = 1;
        } else if (strcmp(a, "--exposure") == 0) {
            if (parse_u32(next, 100, 100000000, &v) != 0) {
                return usage_error("--exposure needs microseconds >= 100%s", "");
            }
            o->exposure_100us = (int32_t)(v / 100);
            i++;
        } else if (strcmp(a, "--timeout") == 0) {
            if (parse_u32(next, 1, 3600000, &v) != 0) {
                return usage_error("--timeout needs milliseconds 1..3600000%s", "");
            }
            o->timeout_ms = (int)v;
            i++;
        } else if (strcmp(a, "--loop") == 0) {
            o->loop = 1;
        } else if (strcmp(a, "--summary-every") == 0) {
            if (parse_u32(next, 0, 86400, &o->summary_s) != 0) {
                return usage_error("--summary-every needs seconds%s", "");
            }
            i++;
        } else if (strcmp(a, "--snapshot-every") == 0 || strcmp(a, "--record") == 0) {
            const int snap = a[2] == 's';
            if (parse_u32(next, 1, 0xffffffffu, &v) != 0 || i + 2 >= argc) {
                return usage_error("%s needs K DIR", a);
            }
            if (snap) {
                o->snapshot_every = v;
                o->snapshot_dir = argv[i + 2];
            } else {
                o->record_every = v;
                o->record_dir = argv[i + 2];
            }
            i += 2;
        } else {
            return usage_error("unknown option or missing value: '%s'", a);
        }
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
        v.exposure_100us = o->exposure_100us;
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
        c.exposure_us = o->exposure_100us >= 0 ? o->exposure_100us * 100 : -1;
        return libcamera_source_open(&c, err, errlen);
    }
#endif
    {
        replay_options r;
        memset(&r, 0, sizeof r);
        r.path = o->replay;
        r.fps_num = o->fps_num;
        r.fps_den = o->fps_den;
        r.loop = o->loop;
        return replay_source_open(&r, err, errlen);
    }
}

/* Running figures for the periodic and final summaries. */
typedef struct summary {
    int64_t t0_ns;
    uint64_t frames;
    double lat_sum_ms, lat_max_ms;
    int64_t window_t0_ns;
    uint64_t window_frames;
    double window_lat_sum_ms, window_lat_max_ms;
} summary;

static void summary_add(summary *s, double lat_ms)
{
    s->frames++;
    s->lat_sum_ms += lat_ms;
    if (lat_ms > s->lat_max_ms) s->lat_max_ms = lat_ms;
    s->window_frames++;
    s->window_lat_sum_ms += lat_ms;
    if (lat_ms > s->window_lat_max_ms) s->window_lat_max_ms = lat_ms;
}

static void summary_window(summary *s, const capsrc *src, int64_t now)
{
    double secs = (double)(now - s->window_t0_ns) / 1e9;
    fprintf(stderr,
            "symline-capture: %.1f fps, latency mean %.2f ms max %.2f ms; totals: %llu frames, %llu stale "
            "skipped, %llu error buffers\n",
            secs > 0 ? (double)s->window_frames / secs : 0.0,
            s->window_frames ? s->window_lat_sum_ms / (double)s->window_frames : 0.0, s->window_lat_max_ms,
            (unsigned long long)s->frames, (unsigned long long)src->stats.skipped_stale,
            (unsigned long long)src->stats.error_buffers);
    s->window_t0_ns = now;
    s->window_frames = 0;
    s->window_lat_sum_ms = 0;
    s->window_lat_max_ms = 0;
}

static int make_dir(const char *dir)
{
    if (mkdir(dir, 0777) != 0 && errno != EEXIST) {
        fprintf(stderr, "symline-capture: cannot create %s: %s\n", dir, strerror(errno));
        return -1;
    }
    return 0;
}

static int record_frame(const char *dir, const capsrc_frame *f)
{
    char path[4096], err[512];
    snprintf(path, sizeof path, "%s/frame%06llu.pgm", dir, (unsigned long long)f->number);
    if (imgio_write_gray(path, f->luma, f->width, f->height, f->stride, err, sizeof err) != 0) {
        fprintf(stderr, "symline-capture: %s\n", err);
        return -1;
    }
    return 0;
}

int main(int argc, char **argv)
{
    app_options o;
    capsrc *src;
    capsrc_frame frame;
    summary sum;
    struct sigaction sa;
    char err[512];
    int rc, status = EXIT_OK;
    const char *stop_reason = "end of input";

    rc = parse_args(argc, argv, &o);
    if (rc != 0) {
        return rc == 1 ? EXIT_OK : rc;
    }
    if ((o.snapshot_dir && make_dir(o.snapshot_dir) != 0) || (o.record_dir && make_dir(o.record_dir) != 0)) {
        return EXIT_FAIL;
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
        return EXIT_FAIL;
    }
    fprintf(stderr, "symline-capture: %s\n", src->description);

    memset(&sum, 0, sizeof sum);
    if (capsrc_start(src) != CAPSRC_OK) {
        fprintf(stderr, "symline-capture: %s\n", capsrc_error(src));
        capsrc_close(src);
        return EXIT_FAIL;
    }
    sum.t0_ns = sum.window_t0_ns = capsrc_now_ns();

    while (!stop_requested && (o.frames == 0 || sum.frames < o.frames)) {
        int64_t t_got, t_done;
        double lat_ms;
        capsrc_result r = capsrc_next(src, &frame, o.timeout_ms);
        if (r == CAPSRC_INTERRUPTED) {
            continue;
        }
        if (r == CAPSRC_END) {
            break;
        }
        if (r != CAPSRC_OK) {
            fprintf(stderr, "symline-capture: error: %s\n", capsrc_error(src));
            stop_reason = r == CAPSRC_LOST ? "device lost" : (r == CAPSRC_TIMEOUT ? "timeout" : "capture error");
            status = EXIT_FAIL;
            break;
        }
        t_got = capsrc_now_ns();
        if (o.record_every && frame.number % o.record_every == 0 && record_frame(o.record_dir, &frame) != 0) {
            stop_reason = "write error";
            status = EXIT_FAIL;
            break;
        }
        t_done = capsrc_now_ns();
        lat_ms = (double)(t_done - frame.timestamp_ns) / 1e6;
        printf("{\"frame\": %llu, \"sequence\": %u, \"timestamp_ns\": %lld, \"width\": %u, \"height\": %u, "
               "\"skipped\": %u, \"latency_ms\": %.3f, \"stages_ms\": {\"queue\": %.3f}}\n",
               (unsigned long long)frame.number, frame.sequence, (long long)frame.timestamp_ns, frame.width,
               frame.height, frame.skipped, lat_ms, (double)(t_got - frame.timestamp_ns) / 1e6);
        fflush(stdout);
        capsrc_release(src);
        summary_add(&sum, lat_ms);
        if (o.summary_s && t_done - sum.window_t0_ns >= (int64_t)o.summary_s * 1000000000) {
            summary_window(&sum, src, t_done);
        }
    }
    if (stop_requested) {
        stop_reason = stop_signal == SIGINT ? "SIGINT" : "SIGTERM";
    } else if (status == EXIT_OK && o.frames && sum.frames >= o.frames) {
        stop_reason = "frame count reached";
    }
    {
        int64_t now = capsrc_now_ns();
        double secs = (double)(now - sum.t0_ns) / 1e9;
        fprintf(stderr,
                "symline-capture: stopped (%s): frames=%llu fps=%.1f latency_mean_ms=%.2f latency_max_ms=%.2f "
                "skipped_stale=%llu error_buffers=%llu requeue_errors=%llu sequence_gaps=%llu\n",
                stop_reason, (unsigned long long)sum.frames, secs > 0 ? (double)sum.frames / secs : 0.0,
                sum.frames ? sum.lat_sum_ms / (double)sum.frames : 0.0, sum.lat_max_ms,
                (unsigned long long)src->stats.skipped_stale, (unsigned long long)src->stats.error_buffers,
                (unsigned long long)src->stats.requeue_errors, (unsigned long long)src->stats.sequence_gaps);
    }
    capsrc_close(src);
    return status;
}

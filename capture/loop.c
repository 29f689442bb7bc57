/* SPDX-License-Identifier: Apache-2.0 */
/*
 * The capture loop (loop.h): detection, frame records and summaries.
 */
#define _POSIX_C_SOURCE 200809L
#include "loop.h"

#include <errno.h>
#include <signal.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "detopts.h"
#include "imgio.h"
#include "overlay.h"
#include "segjson.h"
#include "stageprof.h"
#include "symline/binning.h"
#include "symline/intersections.h"
#include "symline/version.h"

/* Detector memory, sized for the current frame size (sources may change it: replay). */
typedef struct detector {
    uint32_t width, height;
    int binned;    /* frames of this size are binned 2x2 (--bin) */
    uint8_t *half; /* the binned frame */
    void *ws;
    size_t ws_size;
    symline_segment *segs;
    symline_point *pts;
    symline_result res;
    symline_intersection items[256]; /* where lines meet, as `symline lines` reports them */
    symline_intersection_result ix;
} detector;

static int detector_fit(detector *d, const symline_config *cfg, int bin, uint32_t w, uint32_t h)
{
    size_t need;
    uint32_t point_cap;
    const int binned = detopts_bins((detopts_bin)bin, w, h);
    if (d->ws != NULL && d->width == w && d->height == h) {
        return 0;
    }
    need = binned ? symline_detect_workspace_size(w / 2u, h / 2u, cfg)
                  : symline_detect_workspace_size(w, h, cfg);
    if (need == 0) {
        fprintf(stderr, "symline-capture: the detector rejects a %ux%u frame with these settings\n",
                w, h);
        return -1;
    }
    /* The same storage as `symline lines`, so both report the same result for the same frame:
     * the point list doubles as scratch for a pass's line points (detect.h), which can
     * approach two per pixel with the paper's filter on textured frames. */
    point_cap = detopts_point_cap(w, h);
    free(d->ws);
    free(d->pts);
    free(d->half);
    d->ws = malloc(need);
    d->pts = malloc((size_t)point_cap * sizeof *d->pts);
    d->half = binned ? malloc(symline_bin2_size(w, h)) : NULL;
    if (d->segs == NULL) {
        d->segs = malloc(8192u * sizeof *d->segs);
    }
    if (d->ws == NULL || d->pts == NULL || d->segs == NULL || (binned && d->half == NULL)) {
        fprintf(stderr, "symline-capture: out of memory for the detector\n");
        return -1;
    }
    d->ws_size = need;
    d->binned = binned;
    d->width = w;
    d->height = h;
    d->res.segments = d->segs;
    d->res.segment_cap = 8192u;
    d->res.points = d->pts;
    d->res.point_cap = point_cap;
    d->ix.items = d->items;
    d->ix.cap = sizeof d->items / sizeof d->items[0];
    return 0;
}

/* One detection of img, binned 2x2 first when the detector was fitted so
 * (the result then in the binned frame's coordinates). */
static symline_status detect_frame(const detector *d, const symline_config *cfg,
                                   const symline_image *img, symline_result *res)
{
    symline_image half;
    symline_status st;
    if (!d->binned) {
        return symline_detect(img, cfg, d->ws, d->ws_size, res);
    }
    st = symline_bin2(img, d->half, symline_bin2_size(img->width, img->height), &half);
    return st != SYMLINE_OK ? st : symline_detect(&half, cfg, d->ws, d->ws_size, res);
}

static void detector_free(detector *d)
{
    free(d->ws);
    free(d->pts);
    free(d->segs);
    free(d->half);
    memset(d, 0, sizeof *d);
}

/*
 * One JSON object per frame on one line: the frame's own keys, then the
 * detection as the shared writer (segjson) prints it, spliced into the same
 * object and folded onto the line.
 */
typedef struct line_writer {
    char *buf;
    size_t len;
    FILE *mem;
} line_writer;

/* Every stage of the detector, in the order they first run (SYMLINE_STAGE_NONE left out). */
static void put_stages(FILE *out, const int64_t ns[SYMLINE_STAGE_COUNT], double scale, int json)
{
    int k;
    fputs(json ? "{" : "", out);
    for (k = SYMLINE_STAGE_NONE + 1; k < SYMLINE_STAGE_COUNT; k++) {
        fprintf(out, json ? "%s\"%s\": %.3f" : "%s%s=%.3f",
                k > SYMLINE_STAGE_NONE + 1 ? (json ? ", " : " ") : "",
                stageprof_name((symline_stage)k), (double)ns[k] * scale / 1e6);
    }
    fputs(json ? "}" : "", out);
}

static int emit_frame(line_writer *lw, const capsrc_frame *f, const detector *d, double latency_ms,
                      double queue_ms, double detect_ms, const int64_t *stage_ns)
{
    size_t i, n;
    rewind(lw->mem);
    if (segjson_write_ix(lw->mem, f->width, f->height, &d->res, &d->ix) != 0 ||
        fflush(lw->mem) != 0) {
        return -1;
    }
    lw->len = (size_t)ftell(lw->mem);
    if (lw->len < 2 || lw->buf[0] != '{') {
        return -1;
    }
    /* Fold the writer's line breaks and indentation into single spaces (no string holds either). */
    for (i = 0, n = 0; i < lw->len; i++) {
        if (lw->buf[i] == '\n') {
            while (i + 1 < lw->len && lw->buf[i + 1] == ' ') {
                i++;
            }
            if (n > 0 && lw->buf[n - 1] != ' ') {
                lw->buf[n++] = ' ';
            }
        } else {
            lw->buf[n++] = lw->buf[i];
        }
    }
    while (n > 0 && lw->buf[n - 1] == ' ') {
        n--;
    }
    lw->len = n;
    printf("{\"frame\": %llu, ", (unsigned long long)f->number);
    if (f->file != NULL) {
        fputs("\"file\": ", stdout);
        segjson_put_string(stdout, f->file);
        fputs(", ", stdout);
    }
    /* The version in every record: a log says which detector made it. */
    printf("\"version\": \"%s\", ", SYMLINE_VERSION_STRING);
    printf("\"sequence\": %u, \"timestamp_ns\": %lld, \"skipped\": %u, \"latency_ms\": %.3f, "
           "\"stages_ms\": {\"queue\": %.3f, \"convert\": %.3f, \"detect\": %.3f}, ",
           f->sequence, (long long)f->timestamp_ns, f->skipped, latency_ms, queue_ms,
           (double)f->convert_ns / 1e6, detect_ms);
    if (stage_ns != NULL) {
        /* --profile: the detect time split by the detector's own stages. */
        fputs("\"detect_stages_ms\": ", stdout);
        put_stages(stdout, stage_ns, 1.0, 1);
        fputs(", ", stdout);
    }
    fwrite(lw->buf + 1, 1, lw->len - 1, stdout);
    fputc('\n', stdout);
    return fflush(stdout) == 0 ? 0 : -1;
}

/* Running figures for the periodic and final summaries. */
typedef struct summary {
    int64_t t0_ns;
    uint64_t frames;
    double lat_sum_ms, lat_max_ms, det_sum_ms;
    int64_t window_t0_ns;
    uint64_t window_frames;
    double window_lat_sum_ms, window_lat_max_ms;
    int64_t stage_ns[SYMLINE_STAGE_COUNT]; /* --profile: summed over the frames */
} summary;

static void summary_add(summary *s, double lat_ms, double det_ms)
{
    s->frames++;
    s->lat_sum_ms += lat_ms;
    s->det_sum_ms += det_ms;
    if (s->frames == 1 || lat_ms > s->lat_max_ms)
        s->lat_max_ms = lat_ms;
    s->window_frames++;
    s->window_lat_sum_ms += lat_ms;
    if (s->window_frames == 1 || lat_ms > s->window_lat_max_ms)
        s->window_lat_max_ms = lat_ms;
}

static void summary_window(summary *s, const capsrc *src, int64_t now)
{
    double secs = (double)(now - s->window_t0_ns) / 1e9;
    fprintf(stderr,
            "symline-capture: %.1f fps, latency mean %.2f ms max %.2f ms; totals: %llu frames, "
            "%llu stale "
            "skipped, %llu error buffers\n",
            secs > 0 ? (double)s->window_frames / secs : 0.0,
            s->window_frames ? s->window_lat_sum_ms / (double)s->window_frames : 0.0,
            s->window_lat_max_ms, (unsigned long long)s->frames,
            (unsigned long long)src->stats.skipped_stale,
            (unsigned long long)src->stats.error_buffers);
    s->window_t0_ns = now;
    s->window_frames = 0;
    s->window_lat_sum_ms = 0;
    s->window_lat_max_ms = 0;
}

/* A recorded frame appears under its name only once complete (written
 * aside, then renamed), so a recording cut short holds no partial frame. */
static int record_frame(const char *dir, const capsrc_frame *f)
{
    char path[4096], part[4200], err[512];
    snprintf(path, sizeof path, "%s/frame%06llu.pgm", dir, (unsigned long long)f->number);
    /* Hidden (a replay of the folder skips it) and still named .pgm (the
     * writer goes by the extension). */
    snprintf(part, sizeof part, "%s/.part-frame%06llu.pgm", dir, (unsigned long long)f->number);
    if (imgio_write_gray(part, f->luma, f->width, f->height, f->stride, err, sizeof err) != 0) {
        fprintf(stderr, "symline-capture: %s\n", err);
        remove(part);
        return -1;
    }
    if (rename(part, path) != 0) {
        fprintf(stderr, "symline-capture: cannot rename %s: %s\n", part, strerror(errno));
        remove(part);
        return -1;
    }
    return 0;
}

static int snapshot_frame(const char *dir, const capsrc_frame *f, const detector *d)
{
    char path[4096], err[512];
    snprintf(path, sizeof path, "%s/snap%06llu.%s", dir, (unsigned long long)f->number,
             imgio_have_png() ? "png" : "ppm");
    if (overlay_write_ix(path, f->luma, f->width, f->height, f->stride, &d->res, &d->ix, err,
                         sizeof err) != 0) {
        fprintf(stderr, "symline-capture: %s\n", err);
        return -1;
    }
    return 0;
}

int caploop_run(capsrc *src, const caploop_options *o, const volatile sig_atomic_t *stop_signal)
{
    capsrc_frame frame;
    summary sum;
    detector det;
    line_writer lw;
    int status = 0, rc;
    const char *stop_reason = "end of input";
    sigset_t stop_set, old_set;

    sigemptyset(&stop_set);
    sigaddset(&stop_set, SIGINT);
    sigaddset(&stop_set, SIGTERM);

    memset(&det, 0, sizeof det);
    memset(&lw, 0, sizeof lw);
    lw.mem = open_memstream(&lw.buf, &lw.len);
    if (lw.mem == NULL) {
        fprintf(stderr, "symline-capture: out of memory\n");
        return -1;
    }
    memset(&sum, 0, sizeof sum);
    if (capsrc_start(src) != CAPSRC_OK) {
        fprintf(stderr, "symline-capture: error: %s\n", capsrc_error(src));
        fclose(lw.mem);
        free(lw.buf);
        return -1;
    }
    sum.t0_ns = sum.window_t0_ns = capsrc_now_ns();

    while (!*stop_signal && (o->frames == 0 || sum.frames < o->frames)) {
        int64_t t_got, t_det0, t_det1, stage_ns[SYMLINE_STAGE_COUNT];
        double lat_ms, det_ms;
        symline_image img;
        symline_status st;
        uint32_t rep;
        capsrc_result r = capsrc_next(src, &frame, o->timeout_ms);
        if (r == CAPSRC_INTERRUPTED) {
            continue;
        }
        if (r == CAPSRC_END) {
            break;
        }
        if (r != CAPSRC_OK) {
            fprintf(stderr, "symline-capture: error: %s\n", capsrc_error(src));
            stop_reason = r == CAPSRC_LOST ? "device lost"
                                           : (r == CAPSRC_TIMEOUT ? "timeout" : "capture error");
            status = -1;
            break;
        }
        t_got = capsrc_now_ns();
        if (detector_fit(&det, o->cfg, o->bin, frame.width, frame.height) != 0) {
            stop_reason = "detector setup";
            status = -1;
            break;
        }
        img.width = frame.width;
        img.height = frame.height;
        img.stride = frame.stride;
        img.data = frame.luma;
        t_det0 = capsrc_now_ns();
        if (o->profile) {
            stageprof_begin();
        }
        st = detect_frame(&det, o->cfg, &img, &det.res);
        for (rep = 1u; rep < o->repeat && st == SYMLINE_OK; rep++) {
            st = detect_frame(&det, o->cfg, &img, &det.res);
        }
        if (st == SYMLINE_OK && det.binned) {
            st = symline_result_unbin2(&det.res, img.width, img.height);
        }
        if (o->profile) {
            stageprof_end(stage_ns);
        }
        if (st == SYMLINE_OK) {
            symline_intersection_config icfg;
            symline_intersection_config_default(&icfg);
            st = symline_intersections(&det.res, &icfg, &det.ix);
        }
        t_det1 = capsrc_now_ns();
        if (st != SYMLINE_OK) {
            fprintf(stderr, "symline-capture: error: detection failed on frame %llu: %s\n",
                    (unsigned long long)frame.number, symline_status_str(st));
            stop_reason = "detector error";
            status = -1;
            break;
        }
        lat_ms = (double)(t_det1 - frame.timestamp_ns) / 1e6;
        det_ms = (double)(t_det1 - t_det0) / 1e6;
        /* A frame's files and its record are written whole: a stop signal
         * arriving meanwhile waits until they are, then ends the loop. */
        sigprocmask(SIG_BLOCK, &stop_set, &old_set);
        if ((o->record_every && frame.number % o->record_every == 0 &&
             record_frame(o->record_dir, &frame) != 0) ||
            (o->snapshot_every && frame.number % o->snapshot_every == 0 &&
             snapshot_frame(o->snapshot_dir, &frame, &det) != 0)) {
            sigprocmask(SIG_SETMASK, &old_set, NULL);
            stop_reason = "write error";
            status = -1;
            break;
        }
        capsrc_release(src);
        errno = 0;
        rc = emit_frame(&lw, &frame, &det, lat_ms,
                        (double)(t_got - frame.timestamp_ns - frame.convert_ns) / 1e6, det_ms,
                        o->profile ? stage_ns : NULL);
        {
            const int e = errno;
            sigprocmask(SIG_SETMASK, &old_set, NULL);
            errno = e;
        }
        if (rc != 0) {
            if (errno == EPIPE) {
                /* The reader went away (`| head`): a normal end, not an error. */
                stop_reason = "output closed";
            } else if (!*stop_signal) {
                fprintf(stderr, "symline-capture: error: writing the frame record failed: %s\n",
                        strerror(errno));
                stop_reason = "output error";
                status = -1;
            }
            break;
        }
        summary_add(&sum, lat_ms, det_ms);
        if (o->profile) {
            int k;
            for (k = 0; k < SYMLINE_STAGE_COUNT; k++) {
                sum.stage_ns[k] += stage_ns[k];
            }
        }
        if (o->summary_s && t_det1 - sum.window_t0_ns >= (int64_t)o->summary_s * 1000000000) {
            summary_window(&sum, src, t_det1);
        }
    }
    if (*stop_signal) {
        stop_reason = *stop_signal == SIGINT ? "SIGINT" : "SIGTERM";
    } else if (status == 0 && o->frames && sum.frames >= o->frames) {
        stop_reason = "frame count reached";
    }
    {
        int64_t now = capsrc_now_ns();
        double secs = (double)(now - sum.t0_ns) / 1e9;
        fprintf(stderr,
                "symline-capture: stopped (%s): frames=%llu fps=%.1f latency_mean_ms=%.2f "
                "latency_max_ms=%.2f "
                "detect_mean_ms=%.2f skipped_stale=%llu error_buffers=%llu requeue_errors=%llu "
                "sequence_gaps=%llu\n",
                stop_reason, (unsigned long long)sum.frames,
                secs > 0 ? (double)sum.frames / secs : 0.0,
                sum.frames ? sum.lat_sum_ms / (double)sum.frames : 0.0, sum.lat_max_ms,
                sum.frames ? sum.det_sum_ms / (double)sum.frames : 0.0,
                (unsigned long long)src->stats.skipped_stale,
                (unsigned long long)src->stats.error_buffers,
                (unsigned long long)src->stats.requeue_errors,
                (unsigned long long)src->stats.sequence_gaps);
        if (o->profile && sum.frames > 0) {
            fputs("symline-capture: detect stages, mean ms per frame: ", stderr);
            put_stages(stderr, sum.stage_ns, 1.0 / (double)sum.frames, 0);
            fputc('\n', stderr);
        }
    }
    detector_free(&det);
    fclose(lw.mem);
    free(lw.buf);
    return status;
}

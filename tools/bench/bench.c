/* SPDX-License-Identifier: Apache-2.0 */
/*
 * symline-bench — speed of symline_detect() on given frames: ms/frame, frames
 * per second, instructions per pixel (where the CPU's counters can be read)
 * and the time of every stage.
 *
 *   symline-bench [--repeat N] [detector options of symline lines] FRAME...
 *   symline-bench --callgrind-stage STAGE [--repeat N] [options] FRAME...
 *
 * Linked with the profiled library (SYMLINE_PROFILE, include/symline/profile.h).
 * Each frame is detected once to warm up, then N times with the stage marks
 * ignored (ms/frame: the median of the N, thread CPU time), then N times more
 * with every mark timed (the split by stage: each stage's median over the N,
 * less the measured cost of reading the clock in its marks; and the total
 * with the marks, what they cost). Frames are reported by size. Seconds on a shared
 * machine vary from run to run; for figures to compare across changes count
 * instructions: tools/bench/icount.sh (whole detections) and
 * tools/bench/stages.sh (by stage), both with callgrind.
 *
 * --callgrind-stage: for a run under valgrind --tool=callgrind
 * --collect-atstart=no: N detections per frame, with callgrind counting only
 * while STAGE runs (the marks toggle its collection); prints the pixels
 * detected (frames * N * width * height) for the division.
 */
#define _GNU_SOURCE 1
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>
#if defined(__linux__)
#include <linux/perf_event.h>
#include <sys/ioctl.h>
#include <sys/syscall.h>
#include <unistd.h>
#endif

#if defined(SYMLINE_HAVE_CALLGRIND)
#include <valgrind/callgrind.h>
#endif

#include "detopts.h"
#include "hostopts.h"
#include "imgio.h"
#include "symline/detect.h"
#include "symline/profile.h"

#define MAX_SIZES 16

/* ---- clock and instruction counter ---- */

/* CPU time of this thread, for whole detections: on a shared machine the
 * other processes' turns do not count. */
static uint64_t cpu_ns(void)
{
    struct timespec ts;
    clock_gettime(CLOCK_THREAD_CPUTIME_ID, &ts);
    return (uint64_t)ts.tv_sec * 1000000000u + (uint64_t)ts.tv_nsec;
}

/* The marks read the same clock, so that the turns of other processes count
 * in no stage. Reading it costs a system call; calibrate() measures that cost,
 * and each stage is charged it once per entry less (stage_ns - entries * cost). */
static uint64_t now_ns(void)
{
    return cpu_ns();
}

static double g_read_ns; /* cost of one clock read (and counter read) in a mark */

static uint64_t instructions(void);

static void calibrate(void)
{
    const int n = 20000;
    int i;
    uint64_t t0 = now_ns();
    for (i = 0; i < n; i++) {
        (void)now_ns();
        (void)instructions();
    }
    g_read_ns = (double)(now_ns() - t0) / n;
}

static int g_perf_fd = -1; /* user-space instructions of this thread, or -1 */

static void perf_open(void)
{
#if defined(__linux__) && defined(SYS_perf_event_open)
    struct perf_event_attr a;
    memset(&a, 0, sizeof a);
    a.type = PERF_TYPE_HARDWARE;
    a.size = sizeof a;
    a.config = PERF_COUNT_HW_INSTRUCTIONS;
    a.exclude_kernel = 1;
    a.exclude_hv = 1;
    g_perf_fd = (int)syscall(SYS_perf_event_open, &a, 0, -1, -1, 0);
    if (g_perf_fd >= 0) {
        uint64_t v;
        if (read(g_perf_fd, &v, sizeof v) != (ssize_t)sizeof v) {
            close(g_perf_fd);
            g_perf_fd = -1;
        }
    }
#endif
}

static uint64_t instructions(void)
{
#if defined(__linux__)
    uint64_t v = 0u;
    if (g_perf_fd >= 0 && read(g_perf_fd, &v, sizeof v) == (ssize_t)sizeof v) {
        return v;
    }
#endif
    return 0u;
}

/* ---- the stage marks ---- */

static int g_timing;        /* 0: marks are ignored */
static int g_cg_stage = -1; /* --callgrind-stage, or -1 */
static symline_stage g_cur; /* stage running since the last mark */
static uint64_t g_t0, g_i0; /* clock and counter at the last mark */
static uint64_t g_ns[SYMLINE_STAGE_COUNT], g_ins[SYMLINE_STAGE_COUNT],
    g_entries[SYMLINE_STAGE_COUNT];

void symline_profile_mark(symline_stage stage)
{
    uint64_t t, i;
#if defined(SYMLINE_HAVE_CALLGRIND)
    if (g_cg_stage >= 0) {
        /* Counting from entering the stage to leaving it (a repeated mark of
         * the same stage toggles off and on again). */
        if ((int)g_cur == g_cg_stage) {
            CALLGRIND_TOGGLE_COLLECT;
        }
        g_cur = stage;
        if ((int)stage == g_cg_stage) {
            CALLGRIND_TOGGLE_COLLECT;
        }
        return;
    }
#endif
    if (!g_timing) {
        return;
    }
    t = now_ns();
    i = instructions();
    g_ns[g_cur] += t - g_t0;
    g_ins[g_cur] += i - g_i0;
    g_t0 = t;
    g_i0 = i;
    g_cur = stage < SYMLINE_STAGE_COUNT ? stage : SYMLINE_STAGE_NONE;
    g_entries[g_cur]++;
}

/* ---- per size ---- */

typedef struct size_stats {
    uint32_t w, h, frames;
    double ms;        /* sum over frames of the median ms of one detection */
    double ms_marked; /* same with every mark timed */
    double ins;       /* sum over frames of instructions per detection (0: unknown) */
    double stage_ns[SYMLINE_STAGE_COUNT]; /* per detection, summed over frames */
    double stage_ins[SYMLINE_STAGE_COUNT];
} size_stats;

static int cmp_u64(const void *a, const void *b)
{
    const uint64_t x = *(const uint64_t *)a, y = *(const uint64_t *)b;
    return x < y ? -1 : (x > y ? 1 : 0);
}

static size_stats *stats_for(size_stats *s, uint32_t *n, uint32_t w, uint32_t h)
{
    uint32_t i;
    for (i = 0; i < *n; i++) {
        if (s[i].w == w && s[i].h == h) {
            return &s[i];
        }
    }
    if (*n == MAX_SIZES) {
        return NULL;
    }
    memset(&s[*n], 0, sizeof s[*n]);
    s[*n].w = w;
    s[*n].h = h;
    return &s[(*n)++];
}

/* Median of the n values v[0], v[stride], ... (reordered in place through tmp). */
static double median_of(const uint64_t *v, uint32_t n, uint32_t stride, uint64_t *tmp)
{
    uint32_t i;
    for (i = 0; i < n; i++) {
        tmp[i] = v[(size_t)i * stride];
    }
    qsort(tmp, n, sizeof *tmp, cmp_u64);
    return (double)tmp[n / 2u];
}

/* Detects on one frame; 0 ok. times: 2 * repeat * SYMLINE_STAGE_COUNT scratch. */
static int bench_frame(const char *path, const symline_config *cfg, uint32_t repeat,
                       size_stats *all, uint32_t *nsizes, uint64_t *times, double *cg_pixels)
{
    imgio_gray in;
    symline_image img;
    symline_result res;
    char err[512];
    void *ws;
    size_t ws_size;
    uint32_t r, k;
    int rc = 0;
    size_stats *s;
    uint64_t ins0, ins1, t0;
    uint64_t *per = times + repeat; /* [repeat][2 * SYMLINE_STAGE_COUNT]: ns, instructions */
    const uint32_t ps = 2u * SYMLINE_STAGE_COUNT;
    if (imgio_read_gray(path, &in, err, sizeof err) != 0) {
        fprintf(stderr, "symline-bench: %s\n", err);
        return 2;
    }
    s = stats_for(all, nsizes, in.width, in.height);
    img.width = in.width;
    img.height = in.height;
    img.stride = in.width;
    img.data = in.px;
    ws_size = symline_detect_workspace_size(in.width, in.height, cfg);
    memset(&res, 0, sizeof res);
    res.segment_cap = 8192u;
    res.point_cap = 2u * in.width * in.height + 1024u;
    ws = ws_size != 0u ? malloc(ws_size) : NULL;
    res.segments = (symline_segment *)malloc(res.segment_cap * sizeof(symline_segment));
    res.points = (symline_point *)malloc((size_t)res.point_cap * sizeof(symline_point));
    if (s == NULL || ws == NULL || res.segments == NULL || res.points == NULL ||
        symline_detect(&img, cfg, ws, ws_size, &res) != SYMLINE_OK) {
        fprintf(stderr, "symline-bench: %s: %s\n", path,
                s == NULL ? "too many frame sizes" : "cannot detect (size, options or memory)");
        rc = 1;
    } else if (g_cg_stage >= 0) {
        g_cur = SYMLINE_STAGE_NONE;
        for (r = 0; r < repeat; r++) {
            (void)symline_detect(&img, cfg, ws, ws_size, &res);
        }
        /* The first detection (the check above) was counted too. */
        *cg_pixels += (double)(repeat + 1u) * in.width * in.height;
    } else {
        /* Marks ignored: the detection as a user runs it. */
        g_timing = 0;
        ins0 = instructions();
        for (r = 0; r < repeat; r++) {
            t0 = cpu_ns();
            (void)symline_detect(&img, cfg, ws, ws_size, &res);
            times[r] = cpu_ns() - t0;
        }
        ins1 = instructions();
        s->ms += median_of(times, repeat, 1u, times) / 1e6;
        s->ins += (double)(ins1 - ins0) / repeat;
        /* Every mark timed: the split by stage, each stage's median (a stage
         * the scheduler interrupted in one detection does not count). */
        for (r = 0; r < repeat; r++) {
            memset(g_ns, 0, sizeof g_ns);
            memset(g_ins, 0, sizeof g_ins);
            memset(g_entries, 0, sizeof g_entries);
            g_cur = SYMLINE_STAGE_NONE;
            g_timing = 1;
            t0 = cpu_ns();
            g_t0 = now_ns();
            g_i0 = instructions();
            (void)symline_detect(&img, cfg, ws, ws_size, &res);
            symline_profile_mark(SYMLINE_STAGE_NONE);
            g_timing = 0;
            times[r] = cpu_ns() - t0;
            for (k = 0; k < SYMLINE_STAGE_COUNT; k++) {
                const double c = g_read_ns * (double)g_entries[k];
                per[(size_t)r * ps + k] = (double)g_ns[k] > c ? g_ns[k] - (uint64_t)c : 0u;
                per[(size_t)r * ps + SYMLINE_STAGE_COUNT + k] = g_ins[k];
            }
        }
        s->ms_marked += median_of(times, repeat, 1u, times) / 1e6;
        for (k = 0; k < SYMLINE_STAGE_COUNT; k++) {
            s->stage_ns[k] += median_of(per + k, repeat, ps, times);
            s->stage_ins[k] += median_of(per + SYMLINE_STAGE_COUNT + k, repeat, ps, times);
        }
        s->frames++;
    }
    free(ws);
    free(res.segments);
    free(res.points);
    imgio_free(&in);
    return rc;
}

static void report(const size_stats *s)
{
    const double n = s->frames, px = (double)s->w * s->h;
    double marked = 0.0;
    uint32_t k;
    const int have_ins = g_perf_fd >= 0;
    printf("%ux%u, %u frame%s: %.3f ms/frame, %.1f frames/s, ", s->w, s->h, s->frames,
           s->frames == 1u ? "" : "s", s->ms / n, 1000.0 * n / s->ms);
    if (have_ins) {
        printf("%.1f instructions/pixel\n", s->ins / n / px);
    } else {
        printf("instructions/pixel: no CPU counters here (tools/bench/icount.sh counts them)\n");
    }
    for (k = 1; k < SYMLINE_STAGE_COUNT; k++) {
        marked += s->stage_ns[k];
    }
    printf("  by stage, every mark timed (%.3f ms/frame with the marks; %.0f ns per clock read\n"
           "  taken off each stage per entry):\n",
           s->ms_marked / n, g_read_ns);
    printf("  %-10s %10s %7s%s\n", "stage", "ms/frame", "share", have_ins ? "   instr/pixel" : "");
    for (k = 1; k < SYMLINE_STAGE_COUNT; k++) {
        printf("  %-10s %10.3f %6.1f%%", symline_stage_name((symline_stage)k),
               s->stage_ns[k] / n / 1e6, marked > 0.0 ? 100.0 * s->stage_ns[k] / marked : 0.0);
        if (have_ins) {
            printf(" %13.1f", s->stage_ins[k] / n / px);
        }
        printf("\n");
    }
}

static void usage(FILE *f)
{
    fprintf(
        f,
        "usage: symline-bench [--callgrind-stage STAGE] [--repeat N] [detector options] FRAME...\n"
        "       symline-bench --list-stages\n"
        "  --repeat N          timed detections per frame and mode, 1..100000 (default 20)\n"
        "  --callgrind-stage STAGE  under valgrind --tool=callgrind --collect-atstart=no:\n"
        "                      count only STAGE (tools/bench/stages.sh); prints the pixels\n");
    detopts_help(f);
    fprintf(f, "Prints per frame size: ms/frame (median of N), frames/s, instructions per\n"
               "pixel (CPU counters, where readable) and the split by stage.\n");
}

#define PROG "symline-bench"

enum { OPT_LIST_STAGES = 0x100, OPT_CALLGRIND_STAGE, OPT_REPEAT };

static const struct option own_options[] = {
    {"help", no_argument, NULL, HOSTOPTS_HELP},
    {"version", no_argument, NULL, HOSTOPTS_VERSION},
    {"list-stages", no_argument, NULL, OPT_LIST_STAGES},
    {"callgrind-stage", required_argument, NULL, OPT_CALLGRIND_STAGE},
    {"repeat", required_argument, NULL, OPT_REPEAT},
};
#define OWN_OPTIONS (sizeof own_options / sizeof own_options[0])

int main(int argc, char **argv)
{
    struct option longopts[OWN_OPTIONS + 64];
    size_t n;
    int c;
    detopts d;
    char err[128];
    uint32_t repeat = 20u, nsizes = 0u, k;
    size_stats sizes[MAX_SIZES];
    uint64_t *times;
    double cg_pixels = 0.0;
    int i, nframes = 0, rc = 0;
    const char **frames = (const char **)malloc((size_t)argc * sizeof(char *));
    detopts_init(&d);
    if (frames == NULL) {
        return 1;
    }
    memcpy(longopts, own_options, sizeof own_options);
    n = OWN_OPTIONS + detopts_longopts(longopts + OWN_OPTIONS, 63);
    memset(&longopts[n], 0, sizeof longopts[n]);
    while ((c = hostopts_next(argc, argv, ":h", longopts, PROG, PROG)) != -1) {
        int r;
        uint32_t k;
        switch (c) {
        case HOSTOPTS_HELP: usage(stdout); free(frames); return 0;
        case HOSTOPTS_VERSION: hostopts_version(PROG); free(frames); return 0;
        case OPT_LIST_STAGES:
            for (k = 1; k < SYMLINE_STAGE_COUNT; k++) {
                printf("%s\n", symline_stage_name((symline_stage)k));
            }
            free(frames);
            return 0;
        case OPT_CALLGRIND_STAGE:
            for (k = 1; k < SYMLINE_STAGE_COUNT; k++) {
                if (strcmp(optarg, symline_stage_name((symline_stage)k)) == 0) {
                    g_cg_stage = (int)k;
                }
            }
#if !defined(SYMLINE_HAVE_CALLGRIND)
            fprintf(stderr, PROG ": built without valgrind/callgrind.h\n");
            free(frames);
            return 2;
#endif
            if (g_cg_stage < 0) {
                free(frames);
                return hostopts_usage_error(PROG, PROG, "no stage '%s' (--list-stages)", optarg);
            }
            break;
        case OPT_REPEAT:
            if (detopts_u32(optarg, 1u, 100000u, &repeat) != 0) {
                free(frames);
                return hostopts_usage_error(PROG, PROG, "--repeat needs a number 1..100000");
            }
            break;
        default:
            r = c == HOSTOPTS_ERROR ? 0 : detopts_apply(&d, c, optarg, err, sizeof err);
            if (r <= 0) {
                if (r < 0) {
                    hostopts_usage_error(PROG, PROG, "%s", err);
                }
                free(frames);
                return HOSTOPTS_USAGE;
            }
        }
    }
    for (i = optind; i < argc; i++) {
        frames[nframes++] = argv[i];
    }
    if (nframes == 0) {
        free(frames);
        return hostopts_usage_error(PROG, PROG, "no FRAME given");
    }
    detopts_finish(&d);
    times = (uint64_t *)malloc((size_t)repeat * (1u + 2u * SYMLINE_STAGE_COUNT) * sizeof *times);
    if (times == NULL) {
        free(frames);
        return 1;
    }
    perf_open();
    calibrate();
    for (i = 0; i < nframes && rc == 0; i++) {
        rc = bench_frame(frames[i], &d.cfg, repeat, sizes, &nsizes, times, &cg_pixels);
    }
    if (g_cg_stage >= 0) {
        if (rc == 0) {
            printf("pixels %.0f\n", cg_pixels);
        }
        free(times);
        free(frames);
        return rc;
    }
    for (k = 0; k < nsizes && rc == 0; k++) {
        report(&sizes[k]);
    }
    free(times);
    free(frames);
    return rc;
}

/* SPDX-License-Identifier: Apache-2.0 */
/*
 * Replay source: reads one file per frame with imgio (or one frame of a Y4M
 * stream), on demand, so a long recording needs the memory of one frame.
 */
#define _POSIX_C_SOURCE 200809L
#include "replay_source.h"

#include <dirent.h>
#include <errno.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <strings.h>
#include <sys/stat.h>
#include <time.h>

#include "imgio.h"
#include "y4m_reader.h"

typedef struct replay {
    char **files;
    size_t count;
    size_t next;        /* index of the next file to read */
    int loop;
    int64_t period_ns;  /* 0 = unpaced */
    uint32_t rate_num, rate_den; /* the pace, for the description */
    int64_t due_ns;     /* when the next frame may be delivered */
    imgio_gray img;     /* the frame currently handed out */
    int holding;
    uint64_t number;
    y4m_reader *y4m;    /* set when replaying a .y4m stream instead of image files */
    uint32_t y4m_index; /* frame index within the stream */
} replay;

static int has_suffix(const char *name, const char *suffix)
{
    size_t n = strlen(name), k = strlen(suffix);
    return n > k && strcasecmp(name + n - k, suffix) == 0;
}

static int has_image_suffix(const char *name)
{
    return has_suffix(name, ".pgm") || has_suffix(name, ".png") || has_suffix(name, ".jpg") ||
           has_suffix(name, ".jpeg");
}

/* NAME.mask.pgm / .png: an evaluation's line mask next to its frame, not a frame. */
static int is_mask(const char *name)
{
    return has_suffix(name, ".mask.pgm") || has_suffix(name, ".mask.png");
}

static int add_file(replay *r, size_t *cap, const char *dir, const char *name)
{
    size_t len;
    char *p;
    if (r->count == *cap) {
        size_t ncap = *cap ? 2 * *cap : 64;
        char **nf = realloc(r->files, ncap * sizeof *nf);
        if (nf == NULL) {
            return -1;
        }
        r->files = nf;
        *cap = ncap;
    }
    len = (dir ? strlen(dir) + 1 : 0) + strlen(name) + 1;
    p = malloc(len);
    if (p == NULL) {
        return -1;
    }
    if (dir != NULL) {
        snprintf(p, len, "%s/%s", dir, name);
    } else {
        snprintf(p, len, "%s", name);
    }
    r->files[r->count++] = p;
    return 0;
}

static int cmp_str(const void *a, const void *b)
{
    return strcmp(*(char *const *)a, *(char *const *)b);
}

static int scan_dir(replay *r, const char *path, char *err, size_t errlen)
{
    size_t cap = 0;
    struct dirent *e;
    DIR *d = opendir(path);
    if (d == NULL) {
        snprintf(err, errlen, "%s: %s", path, strerror(errno));
        return -1;
    }
    while ((e = readdir(d)) != NULL) {
        if (e->d_name[0] != '.' && has_image_suffix(e->d_name) && !is_mask(e->d_name)) {
            if (add_file(r, &cap, path, e->d_name) != 0) {
                closedir(d);
                snprintf(err, errlen, "out of memory");
                return -1;
            }
        }
    }
    closedir(d);
    if (r->count > 1) {
        qsort(r->files, r->count, sizeof r->files[0], cmp_str);
    }
    return 0;
}

static int read_list(replay *r, const replay_options *opt, char *err, size_t errlen)
{
    size_t cap = 0;
    unsigned long lineno = 0;
    char line[4096];
    char dir[4096];
    const char *path = opt->path;
    const char *slash = strrchr(path, '/');
    FILE *f = fopen(path, "r");
    int rc = 0;
    if (f == NULL) {
        snprintf(err, errlen, "%s: %s", path, strerror(errno));
        return -1;
    }
    if (slash != NULL && (size_t)(slash - path) < sizeof dir) {
        memcpy(dir, path, (size_t)(slash - path));
        dir[slash - path] = '\0';
    } else {
        strcpy(dir, ".");
    }
    while (rc == 0 && fgets(line, sizeof line, f) != NULL) {
        char *s = line;
        size_t n = strlen(line);
        lineno++;
        /* A text list has no NUL byte and ends its lines within the buffer. */
        if (n == 0u || (n + 1u < sizeof line && !feof(f) && line[n - 1u] != '\n')) {
            snprintf(err, errlen, "%s: line %lu holds a NUL byte: not a list of frame files", path, lineno);
            rc = -1;
            break;
        }
        if (n + 1u == sizeof line && line[n - 1u] != '\n') {
            snprintf(err, errlen, "%s: line %lu is longer than %zu bytes: not a list of frame files", path,
                     lineno, sizeof line - 1u);
            rc = -1;
            break;
        }
        if (opt->stop != NULL && *opt->stop) {
            snprintf(err, errlen, "%s: interrupted while reading the list", path);
            rc = -1;
            break;
        }
        while (*s == ' ' || *s == '\t') {
            s++;
        }
        n = strcspn(s, "\r\n");
        s[n] = '\0';
        while (n > 0 && (s[n - 1] == ' ' || s[n - 1] == '\t')) {
            s[--n] = '\0';
        }
        if (n == 0 || s[0] == '#') {
            continue;
        }
        if (r->count >= REPLAY_MAX_LIST_ENTRIES) {
            snprintf(err, errlen, "%s: more than %u entries", path, REPLAY_MAX_LIST_ENTRIES);
            rc = -1;
        } else if (add_file(r, &cap, s[0] == '/' ? NULL : dir, s) != 0) {
            snprintf(err, errlen, "out of memory");
            rc = -1;
        }
    }
    if (rc == 0 && ferror(f)) {
        /* A stop signal interrupts a read from a pipe or a terminal. */
        if (opt->stop != NULL && *opt->stop) {
            snprintf(err, errlen, "%s: interrupted while reading the list", path);
        } else {
            snprintf(err, errlen, "%s: read error: %s", path, strerror(errno));
        }
        rc = -1;
    }
    fclose(f);
    return rc;
}

static capsrc_result replay_start(capsrc *src)
{
    replay *r = src->impl;
    r->next = 0;
    r->due_ns = capsrc_now_ns();
    return CAPSRC_OK;
}

static void replay_release(capsrc *src)
{
    replay *r = src->impl;
    if (r->holding) {
        imgio_free(&r->img);
        r->holding = 0;
    }
}

/* The next frame of a Y4M stream (pacing already done by the caller). */
static capsrc_result y4m_next(capsrc *src, replay *r, capsrc_frame *frame)
{
    char err[512];
    const uint8_t *luma = NULL;
    const int64_t t0 = capsrc_now_ns();
    int got = y4m_read(r->y4m, &luma, err, sizeof err);
    if (got == 0 && r->loop && r->y4m_index > 0) {
        if (y4m_rewind(r->y4m) != 0) {
            capsrc_set_error(src, "replay: cannot rewind the Y4M stream");
            return CAPSRC_ERROR;
        }
        r->y4m_index = 0;
        got = y4m_read(r->y4m, &luma, err, sizeof err);
    }
    if (got == 0) {
        return CAPSRC_END;
    }
    if (got < 0) {
        capsrc_set_error(src, "replay: %s", err);
        return CAPSRC_ERROR;
    }
    frame->luma = luma;
    frame->width = y4m_width(r->y4m);
    frame->height = y4m_height(r->y4m);
    frame->stride = frame->width;
    frame->number = r->number++;
    frame->sequence = r->y4m_index++;
    frame->timestamp_ns = t0;
    frame->skipped = 0;
    frame->convert_ns = 0;
    frame->file = y4m_path(r->y4m);
    src->stats.delivered++;
    return CAPSRC_OK;
}

static capsrc_result replay_next(capsrc *src, capsrc_frame *frame, int timeout_ms)
{
    replay *r = src->impl;
    char err[512];
    const char *file;
    int64_t t0;
    replay_release(src);
    if (r->y4m == NULL && r->next >= r->count) {
        if (!r->loop) {
            return CAPSRC_END;
        }
        r->next = 0;
    }
    if (r->period_ns > 0) {
        int64_t now = capsrc_now_ns();
        int64_t wait = r->due_ns - now;
        if (wait > 0) {
            struct timespec ts;
            if (timeout_ms >= 0 && wait > (int64_t)timeout_ms * 1000000) {
                ts.tv_sec = timeout_ms / 1000;
                ts.tv_nsec = (long)(timeout_ms % 1000) * 1000000L;
                nanosleep(&ts, NULL);
                return CAPSRC_TIMEOUT;
            }
            ts.tv_sec = (time_t)(wait / 1000000000);
            ts.tv_nsec = (long)(wait % 1000000000);
            if (nanosleep(&ts, NULL) != 0 && errno == EINTR) {
                return CAPSRC_INTERRUPTED;
            }
        }
        /* Fixed cadence; after a stall, restart it from now instead of bursting. */
        r->due_ns += r->period_ns;
        if (r->due_ns < capsrc_now_ns()) {
            r->due_ns = capsrc_now_ns() + r->period_ns;
        }
    }
    if (r->y4m != NULL) {
        return y4m_next(src, r, frame);
    }
    file = r->files[r->next];
    t0 = capsrc_now_ns();
    if (imgio_read_gray(file, &r->img, err, sizeof err) != 0) {
        capsrc_set_error(src, "replay: %s", err);
        return CAPSRC_ERROR;
    }
    r->holding = 1;
    frame->luma = r->img.px;
    frame->width = r->img.width;
    frame->height = r->img.height;
    frame->stride = r->img.width;
    frame->number = r->number++;
    frame->sequence = (uint32_t)r->next;
    frame->timestamp_ns = t0; /* the file read stands for the exposure */
    frame->skipped = 0;
    frame->convert_ns = 0;
    frame->file = file;
    r->next++;
    src->stats.delivered++;
    return CAPSRC_OK;
}

static void replay_free(replay *r)
{
    size_t i;
    y4m_close(r->y4m);
    for (i = 0; i < r->count; i++) {
        free(r->files[i]);
    }
    free(r->files);
    free(r);
}

static void replay_close(capsrc *src)
{
    replay *r = src->impl;
    replay_release(src);
    replay_free(r);
    src->impl = NULL;
}

static const capsrc_ops replay_ops = {replay_start, replay_next, replay_release, replay_close};

capsrc *replay_source_open(const replay_options *opt, char *err, size_t errlen)
{
    struct stat st;
    capsrc *src;
    replay *r = calloc(1, sizeof *r);
    if (r == NULL) {
        snprintf(err, errlen, "out of memory");
        return NULL;
    }
    if (opt->path == NULL || stat(opt->path, &st) != 0) {
        snprintf(err, errlen, "%s: %s", opt->path ? opt->path : "(null)", strerror(errno));
        replay_free(r);
        return NULL;
    }
    if (has_suffix(opt->path, ".y4m")) {
        r->y4m = y4m_open(opt->path, err, errlen);
        if (r->y4m == NULL) {
            replay_free(r);
            return NULL;
        }
    } else if (S_ISDIR(st.st_mode)) {
        if (scan_dir(r, opt->path, err, errlen) != 0) {
            replay_free(r);
            return NULL;
        }
    } else if (has_image_suffix(opt->path)) {
        size_t cap = 0;
        if (add_file(r, &cap, NULL, opt->path) != 0) {
            snprintf(err, errlen, "out of memory");
            replay_free(r);
            return NULL;
        }
    } else if (read_list(r, opt, err, errlen) != 0) {
        replay_free(r);
        return NULL;
    }
    if (r->y4m == NULL && r->count == 0) {
        snprintf(err, errlen, "%s: no .pgm, .png or .jpg frames found", opt->path);
        replay_free(r);
        return NULL;
    }
    r->loop = opt->loop;
    {
        /* An explicit pace, else a recording's own frame rate, else as fast as read. */
        uint32_t num = opt->fps_num, den = opt->fps_den ? opt->fps_den : 1u;
        if (num == 0 && r->y4m != NULL && y4m_rate(r->y4m, &num, &den) != 0) {
            num = 0;
        }
        if (num > 0 && !opt->unpaced) {
            r->period_ns = (int64_t)((uint64_t)1000000000u * den / num);
            r->rate_num = num;
            r->rate_den = den;
        }
    }
    src = capsrc_alloc(&replay_ops, r);
    if (src == NULL) {
        snprintf(err, errlen, "out of memory");
        replay_free(r);
        return NULL;
    }
    {
        char pace[64] = ", unpaced";
        if (r->period_ns > 0) {
            snprintf(pace, sizeof pace, ", %u/%u fps", r->rate_num, r->rate_den);
        }
        if (r->y4m != NULL) {
            snprintf(src->description, sizeof src->description, "replay %s: YUV4MPEG2 %ux%u%s%s", opt->path,
                     y4m_width(r->y4m), y4m_height(r->y4m), pace, r->loop ? ", looping" : "");
        } else {
            snprintf(src->description, sizeof src->description, "replay %s: %zu frame file%s%s%s", opt->path,
                     r->count, r->count == 1 ? "" : "s", pace, r->loop ? ", looping" : "");
        }
    }
    return src;
}

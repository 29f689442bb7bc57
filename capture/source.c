/* SPDX-License-Identifier: Apache-2.0 */
/*
 * The frame-source interface: dispatch and small shared helpers.
 */
#define _POSIX_C_SOURCE 200809L
#include "source.h"

#include <stdarg.h>
#include <stdio.h>
#include <stdlib.h>
#include <time.h>

capsrc_result capsrc_start(capsrc *src)
{
    return src->ops->start(src);
}

capsrc_result capsrc_next(capsrc *src, capsrc_frame *frame, int timeout_ms)
{
    frame->file = NULL; /* only file sources set it */
    return src->ops->next(src, frame, timeout_ms);
}

void capsrc_release(capsrc *src)
{
    src->ops->release(src);
}

void capsrc_close(capsrc *src)
{
    if (src != NULL) {
        src->ops->close(src);
        free(src);
    }
}

const char *capsrc_error(const capsrc *src)
{
    return src->error;
}

void capsrc_set_error(capsrc *src, const char *fmt, ...)
{
    va_list ap;
    va_start(ap, fmt);
    vsnprintf(src->error, sizeof src->error, fmt, ap);
    va_end(ap);
}

capsrc *capsrc_alloc(const capsrc_ops *ops, void *impl)
{
    capsrc *src = calloc(1, sizeof *src);
    if (src != NULL) {
        src->ops = ops;
        src->impl = impl;
    }
    return src;
}

int64_t capsrc_now_ns(void)
{
    struct timespec ts;
    clock_gettime(CLOCK_MONOTONIC, &ts);
    return (int64_t)ts.tv_sec * 1000000000 + ts.tv_nsec;
}

/* SPDX-License-Identifier: Apache-2.0 */
/*
 * A strict JSON validator for the per-frame lines of symline-capture (RFC 8259
 * grammar, nesting up to 32 levels), used by the tests.
 */
#ifndef SYMLINE_CAPTURE_JSON_CHECK_H
#define SYMLINE_CAPTURE_JSON_CHECK_H

typedef struct json_frame_info {
    long long frame;
    long long sequence;
    long segments; /* entries of "segments" */
} json_frame_info;

/*
 * Checks one line: a single well-formed JSON object (trailing newline allowed)
 * with the numeric keys frame, sequence, timestamp_ns, latency_ms, the object
 * stages_ms and the array segments, whose entries are objects with numeric
 * x0, y0, x1, y1. Returns NULL when it holds, else a static reason.
 */
const char *json_check_frame_line(const char *line, json_frame_info *info);

/*
 * Checks a --profile line (already accepted by json_check_frame_line): the
 * object detect_stages_ms holds exactly the n stage names, each a time >= 0,
 * and together no more than stages_ms.detect. NULL when it holds.
 */
#include <stddef.h>
const char *json_check_stages(const char *line, const char *const *names, size_t n);

/* Checks that text is exactly one well-formed JSON value (surrounding white space allowed). */
const char *json_check_value(const char *text);

#endif

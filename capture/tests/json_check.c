/* SPDX-License-Identifier: Apache-2.0 */
/*
 * Strict JSON grammar check with a little knowledge of the frame record.
 */
#include "json_check.h"

#include <stdlib.h>
#include <string.h>

typedef struct jp {
    const char *s;
    const char *why;
    int depth;
} jp;

static void ws(jp *p)
{
    while (*p->s == ' ' || *p->s == '\t' || *p->s == '\n' || *p->s == '\r') {
        p->s++;
    }
}

static int bad(jp *p, const char *why)
{
    if (p->why == NULL) {
        p->why = why;
    }
    return -1;
}

static int value(jp *p);

static int string(jp *p, const char **start, size_t *len)
{
    if (*p->s != '"') {
        return bad(p, "expected a string");
    }
    p->s++;
    if (start) *start = p->s;
    while (*p->s != '"') {
        unsigned char c = (unsigned char)*p->s;
        if (c == '\0') return bad(p, "unterminated string");
        if (c < 0x20) return bad(p, "control character in string");
        if (c == '\\') {
            p->s++;
            if (*p->s == 'u') {
                int i;
                for (i = 1; i <= 4; i++) {
                    if (strchr("0123456789abcdefABCDEF", p->s[i]) == NULL || p->s[i] == '\0') {
                        return bad(p, "bad \\u escape");
                    }
                }
                p->s += 4;
            } else if (*p->s == '\0' || strchr("\"\\/bfnrt", *p->s) == NULL) {
                return bad(p, "bad escape");
            }
        }
        p->s++;
    }
    if (len) *len = (size_t)(p->s - *start);
    p->s++;
    return 0;
}

static int number(jp *p)
{
    const char *s = p->s;
    if (*s == '-') s++;
    if (*s == '0') {
        s++;
    } else if (*s >= '1' && *s <= '9') {
        while (*s >= '0' && *s <= '9') s++;
    } else {
        return bad(p, "bad number");
    }
    if (*s == '.') {
        s++;
        if (!(*s >= '0' && *s <= '9')) return bad(p, "bad fraction");
        while (*s >= '0' && *s <= '9') s++;
    }
    if (*s == 'e' || *s == 'E') {
        s++;
        if (*s == '+' || *s == '-') s++;
        if (!(*s >= '0' && *s <= '9')) return bad(p, "bad exponent");
        while (*s >= '0' && *s <= '9') s++;
    }
    p->s = s;
    return 0;
}

static int object(jp *p)
{
    p->s++;
    ws(p);
    if (*p->s == '}') {
        p->s++;
        return 0;
    }
    for (;;) {
        ws(p);
        if (string(p, NULL, NULL) != 0) return -1;
        ws(p);
        if (*p->s != ':') return bad(p, "expected ':'");
        p->s++;
        if (value(p) != 0) return -1;
        ws(p);
        if (*p->s == ',') {
            p->s++;
            continue;
        }
        if (*p->s == '}') {
            p->s++;
            return 0;
        }
        return bad(p, "expected ',' or '}'");
    }
}

static int array(jp *p)
{
    p->s++;
    ws(p);
    if (*p->s == ']') {
        p->s++;
        return 0;
    }
    for (;;) {
        if (value(p) != 0) return -1;
        ws(p);
        if (*p->s == ',') {
            p->s++;
            continue;
        }
        if (*p->s == ']') {
            p->s++;
            return 0;
        }
        return bad(p, "expected ',' or ']'");
    }
}

static int value(jp *p)
{
    int r;
    ws(p);
    if (++p->depth > 32) return bad(p, "nested too deeply");
    switch (*p->s) {
    case '{': r = object(p); break;
    case '[': r = array(p); break;
    case '"': r = string(p, NULL, NULL); break;
    case 't': r = strncmp(p->s, "true", 4) == 0 ? (p->s += 4, 0) : bad(p, "bad literal"); break;
    case 'f': r = strncmp(p->s, "false", 5) == 0 ? (p->s += 5, 0) : bad(p, "bad literal"); break;
    case 'n': r = strncmp(p->s, "null", 4) == 0 ? (p->s += 4, 0) : bad(p, "bad literal"); break;
    default: r = number(p); break;
    }
    p->depth--;
    return r;
}

const char *json_check_value(const char *text)
{
    jp p;
    p.s = text;
    p.why = NULL;
    p.depth = 0;
    if (value(&p) != 0) return p.why;
    ws(&p);
    if (*p.s != '\0') return "text after the JSON value";
    return NULL;
}

/* Finds top-level key k of the object at s (already validated); returns its value or NULL. */
static const char *member(const char *obj, const char *k)
{
    jp p;
    size_t klen = strlen(k);
    p.s = obj + 1;
    p.why = NULL;
    p.depth = 0;
    for (;;) {
        const char *name;
        size_t len;
        ws(&p);
        if (*p.s != '"' || string(&p, &name, &len) != 0) return NULL;
        ws(&p);
        p.s++; /* ':' */
        ws(&p);
        if (len == klen && strncmp(name, k, len) == 0) return p.s;
        if (value(&p) != 0) return NULL;
        ws(&p);
        if (*p.s != ',') return NULL;
        p.s++;
    }
}

static int is_number(const char *v)
{
    return v != NULL && (*v == '-' || (*v >= '0' && *v <= '9'));
}

const char *json_check_frame_line(const char *line, json_frame_info *info)
{
    static const char *const numeric[] = {"frame", "sequence", "timestamp_ns", "latency_ms"};
    const char *why, *v;
    size_t i;
    jp p;
    while (*line == ' ' || *line == '\t') line++;
    why = json_check_value(line);
    if (why != NULL) return why;
    if (*line != '{') return "not a JSON object";
    for (i = 0; i < sizeof numeric / sizeof numeric[0]; i++) {
        if (!is_number(member(line, numeric[i]))) return "a numeric key (frame, sequence, timestamp_ns, latency_ms) is missing";
    }
    v = member(line, "stages_ms");
    if (v == NULL || *v != '{') return "stages_ms object missing";
    v = member(line, "segments");
    if (v == NULL || *v != '[') return "segments array missing";
    info->frame = strtoll(member(line, "frame"), NULL, 10);
    info->sequence = strtoll(member(line, "sequence"), NULL, 10);
    info->segments = 0;
    /* Each segment: an object with numeric end points. */
    p.s = v + 1;
    p.why = NULL;
    p.depth = 0;
    ws(&p);
    if (*p.s == ']') return NULL;
    for (;;) {
        const char *seg;
        ws(&p);
        seg = p.s;
        if (*seg != '{') return "a segment is not an object";
        if (!is_number(member(seg, "x0")) || !is_number(member(seg, "y0")) || !is_number(member(seg, "x1")) ||
            !is_number(member(seg, "y1"))) {
            return "a segment lacks numeric x0, y0, x1, y1";
        }
        if (value(&p) != 0) return p.why;
        info->segments++;
        ws(&p);
        if (*p.s == ']') return NULL;
        p.s++;
    }
}

const char *json_check_stages(const char *line, const char *const *names, size_t n)
{
    const char *stages = member(line, "detect_stages_ms"), *times = member(line, "stages_ms"), *v;
    double sum = 0.0, detect;
    size_t i, keys = 0;
    if (stages == NULL || *stages != '{') return "detect_stages_ms object missing";
    if (times == NULL || *times != '{' || !is_number(v = member(times, "detect"))) return "stages_ms.detect missing";
    detect = strtod(v, NULL);
    for (i = 0; i < n; i++) {
        double t;
        v = member(stages, names[i]);
        if (!is_number(v)) return "a detector stage is missing from detect_stages_ms";
        t = strtod(v, NULL);
        if (t < 0.0) return "a negative stage time";
        sum += t;
    }
    for (v = stages; *v != '}'; v++) {
        keys += *v == ':'; /* the values are numbers: every colon is a key's */
    }
    if (keys != n) return "detect_stages_ms holds other keys than the detector's stages";
    /* Each figure is rounded to 0.001 ms. */
    if (sum > detect + 0.0005 * (double)(n + 1)) return "the stage times add up to more than the detect time";
    return NULL;
}

/* SPDX-License-Identifier: Apache-2.0 */
/*
 * Readers for ground truth text files, detection JSON and PGM headers.
 */
#include "evio.h"

#include <ctype.h>
#include <errno.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

int ev_read_segments(const char *path, int tag, int optional, ev_paths *out)
{
    char line[512];
    int lineno = 0;
    FILE *f = fopen(path, "r");
    if (f == NULL) {
        if (optional && errno == ENOENT) {
            return 0;
        }
        fprintf(stderr, "%s: %s\n", path, strerror(errno));
        return -1;
    }
    while (fgets(line, sizeof(line), f) != NULL) {
        double v[4];
        char extra;
        lineno++;
        if (strspn(line, " \t\r\n") == strlen(line)) {
            continue;
        }
        if (sscanf(line, "%lf %lf %lf %lf %c", &v[0], &v[1], &v[2], &v[3], &extra) != 4) {
            fprintf(stderr, "%s:%d: expected 'x0 y0 x1 y1'\n", path, lineno);
            fclose(f);
            return -1;
        }
        ev_paths_begin(out, tag);
        ev_paths_add(out, v[0], v[1]);
        ev_paths_add(out, v[2], v[3]);
    }
    fclose(f);
    return 0;
}

int ev_read_polylines(const char *path, int tag, int optional, ev_paths *out)
{
    char line[512];
    int lineno = 0, open_piece = 0;
    FILE *f = fopen(path, "r");
    if (f == NULL) {
        if (optional && errno == ENOENT) {
            return 0;
        }
        fprintf(stderr, "%s: %s\n", path, strerror(errno));
        return -1;
    }
    while (fgets(line, sizeof(line), f) != NULL) {
        double x, y;
        char extra;
        lineno++;
        if (strspn(line, " \t\r\n") == strlen(line)) {
            open_piece = 0;
            continue;
        }
        if (sscanf(line, "%lf %lf %c", &x, &y, &extra) != 2) {
            fprintf(stderr, "%s:%d: expected 'x y'\n", path, lineno);
            fclose(f);
            return -1;
        }
        if (!open_piece) {
            ev_paths_begin(out, tag);
            open_piece = 1;
        }
        ev_paths_add(out, x, y);
    }
    fclose(f);
    return 0;
}

/* ---- a small JSON reader: just enough for docs/format.md, skipping anything else ---- */

typedef struct jp {
    const char *s;
    const char *name;
    int err;
} jp;

static void jfail(jp *p, const char *what)
{
    if (!p->err) {
        fprintf(stderr, "%s: JSON: %s near '%.20s'\n", p->name, what, p->s);
    }
    p->err = 1;
}

static void jws(jp *p)
{
    while (*p->s == ' ' || *p->s == '\t' || *p->s == '\n' || *p->s == '\r') {
        p->s++;
    }
}

static int jlit(jp *p, char c)
{
    jws(p);
    if (*p->s == c) {
        p->s++;
        return 1;
    }
    return 0;
}

/* Reads a string into buf (escapes are kept only as their letter: keys and kinds are ASCII). */
static void jstring(jp *p, char *buf, size_t n)
{
    size_t k = 0;
    jws(p);
    if (*p->s != '"') {
        jfail(p, "string expected");
        return;
    }
    p->s++;
    while (*p->s != '"') {
        char c = *p->s;
        if (c == '\0') {
            jfail(p, "unterminated string");
            return;
        }
        if (c == '\\') {
            p->s++;
            if (*p->s == '\0') {
                jfail(p, "unterminated string");
                return;
            }
            c = *p->s;
        }
        if (k + 1 < n) {
            buf[k++] = c;
        }
        p->s++;
    }
    p->s++;
    if (n > 0) {
        buf[k] = '\0';
    }
}

static double jnumber(jp *p)
{
    char *end;
    double v;
    jws(p);
    v = strtod(p->s, &end);
    if (end == p->s) {
        jfail(p, "number expected");
        return 0.0;
    }
    p->s = end;
    return v;
}

static void jskip(jp *p, int depth)
{
    char tmp[8];
    if (depth > 64) {
        jfail(p, "nested too deeply");
        return;
    }
    jws(p);
    if (*p->s == '"') {
        jstring(p, tmp, sizeof(tmp));
    } else if (*p->s == '{' || *p->s == '[') {
        char close = *p->s == '{' ? '}' : ']';
        int obj = *p->s == '{';
        p->s++;
        if (jlit(p, close)) {
            return;
        }
        do {
            if (obj) {
                jstring(p, tmp, sizeof(tmp));
                if (!jlit(p, ':')) {
                    jfail(p, "':' expected");
                }
            }
            jskip(p, depth + 1);
        } while (!p->err && jlit(p, ','));
        if (!p->err && !jlit(p, close)) {
            jfail(p, "',' or closing bracket expected");
        }
    } else if (strncmp(p->s, "true", 4) == 0) {
        p->s += 4;
    } else if (strncmp(p->s, "false", 5) == 0) {
        p->s += 5;
    } else if (strncmp(p->s, "null", 4) == 0) {
        p->s += 4;
    } else {
        jnumber(p);
    }
}

/* [[x, y], ...] into a temporary piece. */
static void jpolyline(jp *p, ev_paths *poly)
{
    if (!jlit(p, '[')) {
        jfail(p, "polyline: '[' expected");
        return;
    }
    if (jlit(p, ']')) {
        return;
    }
    do {
        double x, y;
        if (!jlit(p, '[')) {
            jfail(p, "polyline point: '[' expected");
            return;
        }
        x = jnumber(p);
        if (!jlit(p, ',')) {
            jfail(p, "polyline point: ',' expected");
            return;
        }
        y = jnumber(p);
        if (!jlit(p, ']')) {
            jfail(p, "polyline point: ']' expected");
            return;
        }
        ev_paths_add(poly, x, y);
    } while (!p->err && jlit(p, ','));
    if (!p->err && !jlit(p, ']')) {
        jfail(p, "polyline: ']' expected");
    }
}

static void jsegment(jp *p, ev_paths *out)
{
    char key[32], kind[16] = "";
    double c[4] = {0, 0, 0, 0};
    int have = 0, k;
    ev_paths poly;
    if (!jlit(p, '{')) {
        jfail(p, "segment: '{' expected");
        return;
    }
    ev_paths_init(&poly);
    ev_paths_begin(&poly, EV_TAG_OTHER);
    if (!jlit(p, '}')) {
        do {
            jstring(p, key, sizeof(key));
            if (!jlit(p, ':')) {
                jfail(p, "':' expected");
                break;
            }
            if (strcmp(key, "x0") == 0 || strcmp(key, "y0") == 0 || strcmp(key, "x1") == 0 ||
                strcmp(key, "y1") == 0) {
                k = (key[0] == 'y') + 2 * (key[1] == '1');
                c[k] = jnumber(p);
                have |= 1 << k;
            } else if (strcmp(key, "kind") == 0) {
                jstring(p, kind, sizeof(kind));
            } else if (strcmp(key, "polyline") == 0) {
                jpolyline(p, &poly);
            } else {
                jskip(p, 0);
            }
        } while (!p->err && jlit(p, ','));
        if (!p->err && !jlit(p, '}')) {
            jfail(p, "segment: '}' expected");
        }
    }
    if (!p->err && have != 15) {
        jfail(p, "segment without x0, y0, x1 and y1");
    }
    if (!p->err) {
        int tag = strcmp(kind, "line") == 0 ? EV_TAG_LINE
                  : strcmp(kind, "curve") == 0 ? EV_TAG_CURVE
                                               : EV_TAG_OTHER;
        size_t n = poly.npts, i;
        ev_paths_begin(out, tag);
        if (n >= 2) {
            for (i = 0; i < n; i++) {
                ev_paths_add(out, poly.pts[i].x, poly.pts[i].y);
            }
        } else {
            ev_paths_add(out, c[0], c[1]);
            ev_paths_add(out, c[2], c[3]);
        }
    }
    ev_paths_free(&poly);
}

int ev_parse_detections(const char *text, const char *name, ev_paths *out, int *width,
                        int *height)
{
    jp p;
    char key[32];
    p.s = text;
    p.name = name;
    p.err = 0;
    *width = 0;
    *height = 0;
    if (!jlit(&p, '{')) {
        jfail(&p, "'{' expected");
        return -1;
    }
    if (!jlit(&p, '}')) {
        do {
            jstring(&p, key, sizeof(key));
            if (!jlit(&p, ':')) {
                jfail(&p, "':' expected");
                break;
            }
            if (strcmp(key, "width") == 0) {
                *width = (int)jnumber(&p);
            } else if (strcmp(key, "height") == 0) {
                *height = (int)jnumber(&p);
            } else if (strcmp(key, "segments") == 0) {
                if (!jlit(&p, '[')) {
                    jfail(&p, "segments: '[' expected");
                    break;
                }
                if (!jlit(&p, ']')) {
                    do {
                        jsegment(&p, out);
                    } while (!p.err && jlit(&p, ','));
                    if (!p.err && !jlit(&p, ']')) {
                        jfail(&p, "segments: ']' expected");
                    }
                }
            } else {
                jskip(&p, 0);
            }
        } while (!p.err && jlit(&p, ','));
        if (!p.err && !jlit(&p, '}')) {
            jfail(&p, "'}' expected");
        }
    }
    jws(&p);
    if (!p.err && *p.s != '\0') {
        jfail(&p, "trailing text");
    }
    return p.err ? -1 : 0;
}

int ev_read_detections(const char *path, ev_paths *out, int *width, int *height)
{
    FILE *f = fopen(path, "rb");
    char *buf = NULL;
    size_t len = 0, cap = 0, got;
    int rc;
    if (f == NULL) {
        fprintf(stderr, "%s: %s\n", path, strerror(errno));
        return -1;
    }
    do {
        if (len + 4096 + 1 > cap) {
            cap = (len + 4096 + 1) * 2;
            buf = realloc(buf, cap);
            if (buf == NULL) {
                fclose(f);
                fputs("out of memory\n", stderr);
                return -1;
            }
        }
        got = fread(buf + len, 1, 4096, f);
        len += got;
    } while (got > 0);
    fclose(f);
    buf[len] = '\0';
    if (strlen(buf) != len) {
        fprintf(stderr, "%s: NUL byte in JSON\n", path);
        free(buf);
        return -1;
    }
    rc = ev_parse_detections(buf, path, out, width, height);
    free(buf);
    return rc;
}

int ev_pgm_size(const char *path, int *width, int *height)
{
    FILE *f = fopen(path, "rb");
    int c, v[3], i;
    if (f == NULL) {
        return -1;
    }
    if (fgetc(f) != 'P' || fgetc(f) != '5') {
        fclose(f);
        return -1;
    }
    for (i = 0; i < 3; i++) {
        do {
            c = fgetc(f);
            if (c == '#') {
                while (c != '\n' && c != EOF) {
                    c = fgetc(f);
                }
            }
        } while (c != EOF && isspace(c));
        if (c == EOF || !isdigit(c)) {
            fclose(f);
            return -1;
        }
        v[i] = 0;
        while (c != EOF && isdigit(c)) {
            if (v[i] > 10000000) {
                fclose(f);
                return -1;
            }
            v[i] = v[i] * 10 + (c - '0');
            c = fgetc(f);
        }
    }
    fclose(f);
    *width = v[0];
    *height = v[1];
    return 0;
}

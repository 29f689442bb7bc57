/* SPDX-License-Identifier: Apache-2.0 */
/*
 * YUV4MPEG2 reader: header "YUV4MPEG2 W<w> H<h> [C<tag>] ...", then per frame
 * "FRAME[ params]\n" followed by the planes.
 */
#define _POSIX_C_SOURCE 200809L
#include "y4m_reader.h"

#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "imgio.h"

struct y4m_reader {
    FILE *f;
    char path[256];
    uint32_t width, height;
    uint32_t rate_num, rate_den; /* F<num>:<den>; 0:0 when the header has none */
    uint64_t chroma;   /* bytes after the luma plane of each frame */
    long data_start;   /* file offset of the first FRAME */
    uint8_t *luma;
    uint64_t frames;   /* frames read since the start (for messages) */
};

/* A header's W or H value: digits only, 1..65535; 0 when malformed. */
static uint32_t parse_dim(const char *s)
{
    uint32_t v = 0;
    if (*s == '\0') {
        return 0;
    }
    for (; *s != '\0'; s++) {
        if (*s < '0' || *s > '9' || v > 65535u) {
            return 0; /* 4294967360 must not wrap to 64 */
        }
        v = v * 10u + (uint32_t)(*s - '0');
    }
    return v > 65535u ? 0 : v;
}

/* Reads one header line (without '\n') of at most cap-1 bytes; -1 at EOF or when too long. */
static int read_line(FILE *f, char *buf, size_t cap)
{
    size_t n = 0;
    int c;
    while ((c = fgetc(f)) != EOF && c != '\n') {
        if (n + 1 >= cap) {
            return -1;
        }
        buf[n++] = (char)c;
    }
    buf[n] = '\0';
    return (c == EOF && n == 0) ? -1 : (c == EOF ? -2 : 0);
}

static uint64_t chroma_bytes(const char *tag, uint32_t w, uint32_t h)
{
    const uint64_t cw = (w + 1u) / 2u, ch = (h + 1u) / 2u;
    if (strcmp(tag, "420jpeg") == 0 || strcmp(tag, "420paldv") == 0 || strcmp(tag, "420mpeg2") == 0 ||
        strcmp(tag, "420") == 0) {
        return 2u * cw * ch;
    }
    if (strcmp(tag, "422") == 0) {
        return 2u * cw * h;
    }
    if (strcmp(tag, "444") == 0) {
        return 2u * (uint64_t)w * h;
    }
    if (strcmp(tag, "mono") == 0) {
        return 0;
    }
    return UINT64_MAX;
}

y4m_reader *y4m_open(const char *path, char *err, size_t errlen)
{
    FILE *f = fopen(path, "rb");
    if (f == NULL) {
        snprintf(err, errlen, "%s: cannot open", path);
        return NULL;
    }
    return y4m_open_stream(f, path, err, errlen);
}

y4m_reader *y4m_open_stream(FILE *f, const char *path, char *err, size_t errlen)
{
    char line[512], tag[32] = "420jpeg";
    char *tok, *save = NULL;
    y4m_reader *r = calloc(1, sizeof *r);
    if (r == NULL) {
        fclose(f);
        snprintf(err, errlen, "out of memory");
        return NULL;
    }
    snprintf(r->path, sizeof r->path, "%s", path);
    r->f = f;
    if (read_line(r->f, line, sizeof line) != 0 || strncmp(line, "YUV4MPEG2 ", 10) != 0) {
        snprintf(err, errlen, "%s: not a YUV4MPEG2 file", path);
        y4m_close(r);
        return NULL;
    }
    for (tok = strtok_r(line + 10, " ", &save); tok != NULL; tok = strtok_r(NULL, " ", &save)) {
        if (tok[0] == 'W') {
            r->width = parse_dim(tok + 1);
        } else if (tok[0] == 'H') {
            r->height = parse_dim(tok + 1);
        } else if (tok[0] == 'C') {
            snprintf(tag, sizeof tag, "%s", tok + 1);
        } else if (tok[0] == 'F') {
            /* Frame rate as a ratio; 0:0 means unknown. */
            char *colon = NULL;
            unsigned long num = strtoul(tok + 1, &colon, 10), den = 0;
            if (colon != NULL && *colon == ':') {
                den = strtoul(colon + 1, NULL, 10);
            }
            if (num > 0 && den > 0 && num <= 0xffffffffu && den <= 0xffffffffu) {
                r->rate_num = (uint32_t)num;
                r->rate_den = (uint32_t)den;
            }
        }
    }
    if (r->width == 0 || r->height == 0 || r->width > 65535u || r->height > 65535u) {
        snprintf(err, errlen, "%s: bad frame size in the header (W and H 1..65535)", path);
        y4m_close(r);
        return NULL;
    }
    if ((uint64_t)r->width * r->height > imgio_max_pixels()) {
        snprintf(err, errlen, "%s: frame size %ux%u exceeds the limit of %llu pixels (raise it with "
                 "SYMLINE_MAX_PIXELS)", path, r->width, r->height, (unsigned long long)imgio_max_pixels());
        y4m_close(r);
        return NULL;
    }
    r->chroma = chroma_bytes(tag, r->width, r->height);
    if (r->chroma == UINT64_MAX) {
        snprintf(err, errlen, "%s: colour space C%s not supported (8-bit 420, 422, 444 or mono)", path, tag);
        y4m_close(r);
        return NULL;
    }
    r->data_start = ftell(r->f);
    r->luma = malloc((size_t)r->width * r->height);
    if (r->luma == NULL) {
        snprintf(err, errlen, "out of memory");
        y4m_close(r);
        return NULL;
    }
    return r;
}

int y4m_rate(const y4m_reader *r, uint32_t *num, uint32_t *den)
{
    if (r->rate_num == 0 || r->rate_den == 0) {
        return -1;
    }
    *num = r->rate_num;
    *den = r->rate_den;
    return 0;
}

const char *y4m_path(const y4m_reader *r)
{
    return r->path;
}

uint32_t y4m_width(const y4m_reader *r)
{
    return r->width;
}

uint32_t y4m_height(const y4m_reader *r)
{
    return r->height;
}

/* Reads and drops n bytes: a seek would pass the end of a truncated last frame. */
static int skip_bytes(FILE *f, uint64_t n)
{
    uint8_t buf[4096];
    while (n > 0u) {
        const size_t k = n < sizeof buf ? (size_t)n : sizeof buf;
        if (fread(buf, 1, k, f) != k) {
            return -1;
        }
        n -= k;
    }
    return 0;
}

int y4m_read(y4m_reader *r, const uint8_t **luma, char *err, size_t errlen)
{
    char line[512];
    const size_t n = (size_t)r->width * r->height;
    int lr = read_line(r->f, line, sizeof line);
    if (lr == -1 && feof(r->f)) {
        return 0;
    }
    if (lr != 0 || strncmp(line, "FRAME", 5) != 0 || (line[5] != '\0' && line[5] != ' ')) {
        snprintf(err, errlen, "%s: frame %llu: expected a FRAME header", r->path, (unsigned long long)r->frames);
        return -1;
    }
    if (fread(r->luma, 1, n, r->f) != n || skip_bytes(r->f, r->chroma) != 0) {
        snprintf(err, errlen, "%s: frame %llu is truncated", r->path, (unsigned long long)r->frames);
        return -1;
    }
    r->frames++;
    *luma = r->luma;
    return 1;
}

int y4m_rewind(y4m_reader *r)
{
    r->frames = 0;
    return fseek(r->f, r->data_start, SEEK_SET) == 0 ? 0 : -1;
}

void y4m_close(y4m_reader *r)
{
    if (r != NULL) {
        if (r->f != NULL) {
            fclose(r->f);
        }
        free(r->luma);
        free(r);
    }
}

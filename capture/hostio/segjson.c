/*
 * The JSON writer for detected segments (docs/format.md).
 */
#include "segjson.h"

/* Q8 fixed point as a decimal with two places, exact to the printed digits. */
static void put_q8(FILE *f, int32_t v)
{
    const int neg = v < 0;
    uint32_t a = (uint32_t)(neg ? -(int64_t)v : (int64_t)v);
    uint32_t hundredths = (uint32_t)(((uint64_t)a * 100u + 128u) >> 8);
    fprintf(f, "%s%u.%02u", (neg && hundredths != 0u) ? "-" : "", hundredths / 100u,
            hundredths % 100u);
}

void segjson_put_string(FILE *f, const char *s)
{
    fputc('"', f);
    for (; *s != '\0'; s++) {
        const unsigned char c = (unsigned char)*s;
        if (c == '"' || c == '\\') {
            fputc('\\', f);
            fputc(c, f);
        } else if (c < 0x20u) {
            fprintf(f, "\\u%04x", c);
        } else {
            fputc(c, f);
        }
    }
    fputc('"', f);
}

int segjson_write(FILE *f, uint32_t width, uint32_t height, const symline_result *r)
{
    return segjson_write_named(f, NULL, width, height, r);
}

int segjson_write_named(FILE *f, const char *file, uint32_t width, uint32_t height, const symline_result *r)
{
    uint32_t i, k;
    fputc('{', f);
    if (file != NULL) {
        fputs("\"file\": ", f);
        segjson_put_string(f, file);
        fputs(", ", f);
    }
    fprintf(f, "\"width\": %u, \"height\": %u, \"truncated\": %s,\n \"segments\": [", width, height,
            r->truncated ? "true" : "false");
    for (i = 0; i < r->segment_count; i++) {
        const symline_segment *s = &r->segments[i];
        fputs(i == 0u ? "\n  {" : ",\n  {", f);
        fputs("\"x0\": ", f);
        put_q8(f, s->x0);
        fputs(", \"y0\": ", f);
        put_q8(f, s->y0);
        fputs(", \"x1\": ", f);
        put_q8(f, s->x1);
        fputs(", \"y1\": ", f);
        put_q8(f, s->y1);
        fprintf(f, ", \"points\": %u, \"max_dev\": ", s->count);
        put_q8(f, (int32_t)s->max_dev);
        fprintf(f, ", \"kind\": \"%s\", \"axis\": \"%s\", \"level\": %u",
                s->kind == SYMLINE_KIND_CURVE ? "curve" : "line",
                s->axis == SYMLINE_AXIS_VERTICAL ? "vertical" : "horizontal", s->level);
        if (s->kind == SYMLINE_KIND_CURVE && s->count >= 2u) {
            const symline_point *p = r->points + s->first;
            fputs(", \"polyline\": [", f);
            for (k = 0; k < s->count; k += 4u) {
                fprintf(f, "%s[%u, %u]", k == 0u ? "" : ", ", p[k].x, p[k].y);
            }
            if ((s->count - 1u) % 4u != 0u) {
                fprintf(f, ", [%u, %u]", p[s->count - 1u].x, p[s->count - 1u].y);
            }
            fputc(']', f);
        }
        fputc('}', f);
    }
    fputs(r->segment_count ? "\n ]}\n" : "]}\n", f);
    return ferror(f) ? -1 : 0;
}

/* SPDX-License-Identifier: Apache-2.0 */
/*
 * symline-ref — a deliberately plain reference of the operator and its extrema
 * (docs/algorithm.md), written straight
 * from the formulas for clarity, never for speed. The golden files under
 * tests/golden/ are produced by it, and the tests compare the optimised core
 * against it bit for bit.
 *
 *   symline-ref symmetry|extrema|energy horizontal|vertical M IN.pgm OUT
 *   symline-ref features|histogram M IN.pgm OUT.json
 *
 * OUT is a P5 PGM for symmetry and extrema; for energy it is a text file with
 * one line per image row of decimal E values. features and histogram
 * (docs/format.md) write the JSON of `symline features` / `symline histogram`, taken from
 * the two whole extrema maps.
 * It shares no code with lib/: even the PGM reader is its own.
 */
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

typedef struct {
    int w, h;
    unsigned char *px;
} gray;

static int read_pgm(const char *path, gray *g)
{
    FILE *f = fopen(path, "rb");
    int maxval, c;
    if (!f) {
        return -1;
    }
    if (fgetc(f) != 'P' || fgetc(f) != '5') {
        fclose(f);
        return -1;
    }
    /* header: three numbers with optional comments, then one white-space byte */
    int vals[3], n = 0;
    while (n < 3) {
        c = fgetc(f);
        if (c == EOF) {
            fclose(f);
            return -1;
        }
        if (c == '#') {
            while (c != '\n' && c != EOF) {
                c = fgetc(f);
            }
        } else if (c >= '0' && c <= '9') {
            int v = 0;
            while (c >= '0' && c <= '9') {
                v = v * 10 + (c - '0');
                c = fgetc(f);
            }
            vals[n++] = v;
            if (n == 3) {
                break; /* c is the single white-space byte */
            }
            ungetc(c, f);
        }
    }
    g->w = vals[0];
    g->h = vals[1];
    maxval = vals[2];
    if (maxval != 255 || g->w <= 0 || g->h <= 0) {
        fclose(f);
        return -1;
    }
    g->px = malloc((size_t)g->w * g->h);
    if (fread(g->px, 1, (size_t)g->w * g->h, f) != (size_t)g->w * g->h) {
        fclose(f);
        return -1;
    }
    fclose(f);
    return 0;
}

/* The sequence q of length n through pixel index `line` along the axis. */
static int seq_len(const gray *g, int vertical)
{
    return vertical ? g->w : g->h;
}

static int seq_at(const gray *g, int vertical, int line, int i)
{
    return vertical ? g->px[(size_t)line * g->w + i] : g->px[(size_t)i * g->w + line];
}

/* E(i) = sum_{j=1..m} (m+1-j) * d_j^2, d_j = |q[i-j]-q[i+j]| or 255 outside. */
static uint64_t energy(const gray *g, int vertical, int line, int i, int m)
{
    int n = seq_len(g, vertical);
    uint64_t e = 0;
    for (int j = 1; j <= m; j++) {
        int d;
        if (i - j >= 0 && i + j <= n - 1) {
            d = abs(seq_at(g, vertical, line, i - j) - seq_at(g, vertical, line, i + j));
        } else {
            d = 255;
        }
        e += (uint64_t)(m + 1 - j) * (uint64_t)d * (uint64_t)d;
    }
    return e;
}

static void put(unsigned char *out, const gray *g, int vertical, int line, int i, int v)
{
    if (vertical) {
        out[(size_t)line * g->w + i] = (unsigned char)v;
    } else {
        out[(size_t)i * g->w + line] = (unsigned char)v;
    }
}

/* The whole extrema map of one axis (0, 128, 255 per pixel), straight from docs/algorithm.md. */
static unsigned char *extrema_map(const gray *g, int vertical, int m)
{
    int n = seq_len(g, vertical), lines = vertical ? g->h : g->w;
    uint64_t *E = malloc(sizeof(uint64_t) * (size_t)n);
    unsigned char *out = calloc((size_t)g->w * g->h, 1);
    for (int line = 0; line < lines; line++) {
        for (int i = 0; i < n; i++) {
            E[i] = energy(g, vertical, line, i, m);
        }
        int a = 0;
        while (a < n) {
            int b = a;
            while (b + 1 < n && E[b + 1] == E[a]) {
                b++;
            }
            if (a >= 1 && b <= n - 2) {
                if (E[a - 1] > E[a] && E[b + 1] > E[b]) {
                    put(out, g, vertical, line, (a + b) / 2, 255);
                } else if (E[a - 1] < E[a] && E[b + 1] < E[b]) {
                    put(out, g, vertical, line, (a + b) / 2, 128);
                }
            }
            a = b + 1;
        }
    }
    free(E);
    return out;
}

/* docs/format.md: feature points (S in both maps, raster order) or the vertical histogram. */
static int paper_features(const char *cmd, int m, const char *in, const char *outpath)
{
    gray g;
    if (read_pgm(in, &g) != 0) {
        fprintf(stderr, "symline-ref: cannot read %s\n", in);
        return 2;
    }
    FILE *f = fopen(outpath, "w");
    if (!f) {
        fprintf(stderr, "symline-ref: cannot write %s\n", outpath);
        return 2;
    }
    unsigned char *v = extrema_map(&g, 1, m);
    fprintf(f, "{\"width\": %d, \"height\": %d, \"radius\": %d, ", g.w, g.h, m);
    if (strcmp(cmd, "features") == 0) {
        unsigned char *h = extrema_map(&g, 0, m);
        int first = 1;
        fprintf(f, "\"points\": [");
        for (int y = 0; y < g.h; y++) {
            for (int x = 0; x < g.w; x++) {
                size_t i = (size_t)y * g.w + x;
                if (v[i] == 255 && h[i] == 255) {
                    fprintf(f, first ? "[%d, %d]" : ", [%d, %d]", x, y);
                    first = 0;
                }
            }
        }
        free(h);
    } else {
        fprintf(f, "\"counts\": [");
        for (int x = 0; x < g.w; x++) {
            int c = 0;
            for (int y = 0; y < g.h; y++) {
                c += v[(size_t)y * g.w + x] == 255;
            }
            fprintf(f, x ? ", %d" : "%d", c);
        }
    }
    fprintf(f, "]}\n");
    fclose(f);
    free(v);
    free(g.px);
    return 0;
}

int main(int argc, char **argv)
{
    if (argc == 5 && (strcmp(argv[1], "features") == 0 || strcmp(argv[1], "histogram") == 0)) {
        int r = atoi(argv[2]);
        if (r < 1 || r > 255) {
            fprintf(stderr, "symline-ref: bad radius %s\n", argv[2]);
            return 2;
        }
        return paper_features(argv[1], r, argv[3], argv[4]);
    }

    gray g;
    int vertical, m, lines, n;
    if (argc != 6) {
        fprintf(stderr, "usage: symline-ref symmetry|extrema|energy horizontal|vertical M IN.pgm OUT\n"
                        "       symline-ref features|histogram M IN.pgm OUT.json\n");
        return 2;
    }
    vertical = strcmp(argv[2], "vertical") == 0;
    if (!vertical && strcmp(argv[2], "horizontal") != 0) {
        fprintf(stderr, "symline-ref: bad axis %s\n", argv[2]);
        return 2;
    }
    m = atoi(argv[3]);
    if (m < 1 || m > 255) {
        fprintf(stderr, "symline-ref: bad radius %s\n", argv[3]);
        return 2;
    }
    if (read_pgm(argv[4], &g) != 0) {
        fprintf(stderr, "symline-ref: cannot read %s\n", argv[4]);
        return 2;
    }
    n = seq_len(&g, vertical);
    lines = vertical ? g.h : g.w;
    uint64_t emax = 65025ull * (uint64_t)(m * (m + 1) / 2);
    uint64_t *E = malloc(sizeof(uint64_t) * (size_t)n);
    unsigned char *out = calloc((size_t)g.w * g.h, 1);

    if (strcmp(argv[1], "energy") == 0) {
        /* one text line per image row, E values separated by spaces */
        uint64_t *all = malloc(sizeof(uint64_t) * (size_t)g.w * g.h);
        FILE *f = fopen(argv[5], "w");
        for (int line = 0; line < lines; line++) {
            for (int i = 0; i < n; i++) {
                uint64_t e = energy(&g, vertical, line, i, m);
                if (vertical) {
                    all[(size_t)line * g.w + i] = e;
                } else {
                    all[(size_t)i * g.w + line] = e;
                }
            }
        }
        for (int y = 0; y < g.h; y++) {
            for (int x = 0; x < g.w; x++) {
                fprintf(f, x ? " %llu" : "%llu", (unsigned long long)all[(size_t)y * g.w + x]);
            }
            fputc('\n', f);
        }
        fclose(f);
        return 0;
    }

    for (int line = 0; line < lines; line++) {
        for (int i = 0; i < n; i++) {
            E[i] = energy(&g, vertical, line, i, m);
        }
        if (strcmp(argv[1], "symmetry") == 0) {
            for (int i = 0; i < n; i++) {
                uint64_t s8 = (510 * (emax - E[i]) + emax) / (2 * emax);
                put(out, &g, vertical, line, i, (int)s8);
            }
        } else if (strcmp(argv[1], "extrema") == 0) {
            /* every maximal run [a, b] of equal E */
            int a = 0;
            while (a < n) {
                int b = a;
                while (b + 1 < n && E[b + 1] == E[a]) {
                    b++;
                }
                if (a >= 1 && b <= n - 2) {
                    if (E[a - 1] > E[a] && E[b + 1] > E[b]) {
                        put(out, &g, vertical, line, (a + b) / 2, 255);
                    } else if (E[a - 1] < E[a] && E[b + 1] < E[b]) {
                        put(out, &g, vertical, line, (a + b) / 2, 128);
                    }
                }
                a = b + 1;
            }
        } else {
            fprintf(stderr, "symline-ref: unknown command %s\n", argv[1]);
            return 2;
        }
    }
    FILE *f = fopen(argv[5], "wb");
    if (!f) {
        fprintf(stderr, "symline-ref: cannot write %s\n", argv[5]);
        return 2;
    }
    fprintf(f, "P5\n%d %d\n255\n", g.w, g.h);
    fwrite(out, 1, (size_t)g.w * g.h, f);
    fclose(f);
    free(E);
    free(out);
    free(g.px);
    return 0;
}

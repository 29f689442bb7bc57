/* SPDX-License-Identifier: Apache-2.0 */
/*
 * symline-advframes — writes adversarial frames for the detector's time
 * benchmark (tools/bench/adversarial.sh): patterns that give many line points
 * and many short segments, the worst case for anything that compares
 * segments with segments.
 *
 *   symline-advframes rings|noise|dashes|checker WIDTH HEIGHT OUT.pgm
 *
 * rings:   concentric 1 px bright rings every 4 px around the centre
 * noise:   uniform gray noise (xorshift32, fixed seed)
 * dashes:  8 px bright dashes with 8 px gaps, rows 6 px apart, every other
 *          64 px block turned by 90 degrees
 * checker: 8 px squares of gray 40 and 200
 */
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "hostopts.h"
#include "imgio.h"

static uint32_t isqrt32(uint32_t v)
{
    uint32_t r = 0, b = 1u << 30;
    while (b > v) {
        b >>= 2;
    }
    while (b != 0u) {
        if (v >= r + b) {
            v -= r + b;
            r = (r >> 1) + b;
        } else {
            r >>= 1;
        }
        b >>= 2;
    }
    return r;
}

int main(int argc, char **argv)
{
    uint32_t w, h, x, y, seed = 2463534242u;
    uint8_t *px;
    char err[512];
    const char *kind;
    long v;
    int rc = hostopts_plain(argc, argv, "symline-advframes",
                            "usage: symline-advframes rings|noise|dashes|checker WIDTH HEIGHT OUT.pgm\n"
                            "Writes an adversarial frame (WIDTH, HEIGHT 1..65535) as PGM.\n",
                            4);
    if (rc >= 0) {
        return rc;
    }
    argv += optind - 1; /* argv[1..4]: the arguments */
    if (hostopts_long(argv[2], 1, 65535, &v) != 0) {
        return hostopts_usage_error("symline-advframes", "symline-advframes", "WIDTH must be 1..65535");
    }
    w = (uint32_t)v;
    if (hostopts_long(argv[3], 1, 65535, &v) != 0) {
        return hostopts_usage_error("symline-advframes", "symline-advframes", "HEIGHT must be 1..65535");
    }
    h = (uint32_t)v;
    kind = argv[1];
    px = (uint8_t *)malloc((size_t)w * h);
    if (px == NULL) {
        fprintf(stderr, "symline-advframes: out of memory\n");
        return 1;
    }
    for (y = 0; y < h; y++) {
        for (x = 0; x < w; x++) {
            uint8_t v;
            if (strcmp(kind, "rings") == 0) {
                const int32_t dx = (int32_t)x - (int32_t)(w / 2u), dy = (int32_t)y - (int32_t)(h / 2u);
                v = isqrt32((uint32_t)(dx * dx + dy * dy)) % 4u == 0u ? 200u : 60u;
            } else if (strcmp(kind, "noise") == 0) {
                seed ^= seed << 13;
                seed ^= seed >> 17;
                seed ^= seed << 5;
                v = (uint8_t)(seed >> 24);
            } else if (strcmp(kind, "dashes") == 0) {
                const int turn = ((x / 64u) + (y / 64u)) % 2u == 1u;
                const uint32_t a = turn ? y : x, b = turn ? x : y;
                v = (b % 6u == 0u && ((a + 4u * (b / 6u)) / 8u) % 2u == 0u) ? 200u : 60u;
            } else if (strcmp(kind, "checker") == 0) {
                v = ((x / 8u) + (y / 8u)) % 2u ? 200u : 40u;
            } else {
                fprintf(stderr, "symline-advframes: unknown pattern '%s'\n", kind);
                free(px);
                return 2;
            }
            px[(size_t)y * w + x] = v;
        }
    }
    if (imgio_write_gray(argv[4], px, w, h, w, err, sizeof err) != 0) {
        fprintf(stderr, "symline-advframes: %s\n", err);
        free(px);
        return 1;
    }
    free(px);
    return 0;
}

/* SPDX-License-Identifier: Apache-2.0 */
/*
 * The synthetic field frame of the detector tests (synth_frame.h).
 */
#include "synth_frame.h"

#include <stdlib.h>

#include "testutil.h"

static void draw_disc(uint8_t *px, uint32_t w, uint32_t h, uint32_t stride, int32_t cx, int32_t cy,
                      int32_t r2_in, int32_t r2_out, uint8_t v)
{
    uint32_t x, y;
    for (y = 0; y < h; y++) {
        for (x = 0; x < w; x++) {
            const int32_t dx = (int32_t)x - cx, dy = (int32_t)y - cy;
            const int32_t d2 = dx * dx + dy * dy;
            if (d2 >= r2_in && d2 <= r2_out) {
                px[y * stride + x] = v;
            }
        }
    }
}

uint8_t *synth_frame(uint32_t w, uint32_t h, uint32_t stride)
{
    uint8_t *px = (uint8_t *)malloc((size_t)stride * h);
    uint32_t x, y, s = 12345u;
    for (y = 0; y < h; y++) {
        for (x = 0; x < stride; x++) {
            px[y * stride + x] = (uint8_t)(60u + tu_rand(&s) % 24u);
        }
    }
    for (x = 0; x < w; x++) {
        /* a 2 px horizontal line, a 9 px one, a slanted 3 px one */
        for (y = 20; y < 22; y++) {
            px[y * stride + x] = 200;
        }
        for (y = 60; y < 69; y++) {
            px[y * stride + x] = 190;
        }
        for (y = 0; y < 3; y++) {
            const uint32_t yy = 90u + x / 3u + y;
            if (yy < h) {
                px[yy * stride + x] = 180;
            }
        }
    }
    for (y = 0; y < h; y++) { /* a vertical line */
        px[y * stride + w / 2u] = 210;
        px[y * stride + w / 2u + 1u] = 205;
    }
    draw_disc(px, w, h, stride, (int32_t)w / 4, (int32_t)h * 2 / 3, 400, 484, 220);
    for (y = 100; y < 130 && y < h; y++) { /* a saturated block: long plateaus */
        for (x = 10; x < 40 && x < w; x++) {
            px[y * stride + x] = 255;
        }
    }
    return px;
}

/* SPDX-License-Identifier: Apache-2.0 */
/* Embeds symline through FetchContent: detects one bright horizontal line with static
 * buffers sized at compile time. */
#include <stdio.h>
#include <string.h>

#include "symline/detect.h"

#define W 64u
#define H 48u

static uint8_t frame[H][W];
static uint8_t ws[SYMLINE_DETECT_WORKSPACE_SIZE(W, H, 3u, 0u, 0u)]; /* radius 3, contrast filter */
static symline_segment segs[16];
static symline_point pts[1024];

int main(void)
{
    symline_config cfg;
    symline_image img = {W, H, W, &frame[0][0]};
    symline_result res = {segs, 16, 0, pts, 1024, 0, 0, {0}, 0};
    size_t need;
    uint32_t y;
    memset(frame, 40, sizeof frame);
    for (y = 23; y <= 25; y++) {
        memset(&frame[y][4], y == 24 ? 220 : 150, W - 8u);
    }
    symline_config_default(&cfg);
    need = symline_detect_workspace_size(W, H, &cfg);
    if (need == 0u || need > sizeof ws) {
        fprintf(stderr, "workspace: %zu bytes needed, %zu available\n", need, sizeof ws);
        return 1;
    }
    if (symline_detect(&img, &cfg, ws, sizeof ws, &res) != SYMLINE_OK || res.segment_count < 1u) {
        fprintf(stderr, "no segment found\n");
        return 1;
    }
    printf("segments: %u, first from (%.1f, %.1f) to (%.1f, %.1f)\n", res.segment_count,
           segs[0].x0 / 256.0, segs[0].y0 / 256.0, segs[0].x1 / 256.0, segs[0].y1 / 256.0);
    return segs[0].y0 / 256 == 24 ? 0 : 1;
}

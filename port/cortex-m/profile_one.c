/* SPDX-License-Identifier: Apache-2.0 */
/*
 * One default detection (radius 3) of the benchmark's 320x240 frame and
 * nothing else, for counting where the target's instructions go
 * (tools/firmware/insnprof.sh runs it under qemu with its execution trace
 * and sums the instructions per function). Prints the status and the number
 * of segments.
 */
#include <stdint.h>
#include <stdio.h>

#include "symline/detect.h"

#include "fwdata.h"

extern const fw_frame fw_bench_320x240;

static uint64_t ws[65536u / 8u];
static symline_segment segs[256];
static symline_point pts[16384];

int main(void)
{
    const fw_frame *f = &fw_bench_320x240;
    const symline_image img = {f->width, f->height, f->width, f->px};
    symline_result res = {segs, 256u, 0u, pts, 16384u, 0u, 0u, {0}, 0u};
    symline_config cfg;
    size_t need;
    symline_status st = SYMLINE_ERR_BUFFER;
    symline_config_default(&cfg);
    cfg.radius = 3u;
    need = symline_detect_workspace_size(f->width, f->height, &cfg);
    if (need > 0u && need <= sizeof ws) {
        st = symline_detect(&img, &cfg, ws, need, &res);
    }
    printf("profile %lux%lu default: status %d, %lu segments\n", (unsigned long)f->width,
           (unsigned long)f->height, (int)st, (unsigned long)res.segment_count);
    return st != SYMLINE_OK;
}

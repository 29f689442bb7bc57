/* SPDX-License-Identifier: Apache-2.0 */
/*
 * symline in a firmware: one 320x240 camera frame (here a window of a real
 * RoboCup MSL frame, stored in flash) through the line detector, with every
 * buffer static, and the segments printed over semihosting.
 *
 * On a robot, `frame` is the camera's DMA buffer and the loop body runs once
 * per frame; nothing else is needed: no heap, no FPU, no OS.
 *
 *   qemu-system-arm -M mps2-an386 -nographic -monitor none -serial none \
 *       -semihosting-config enable=on,target=native -kernel symline_fw_example.elf
 */
#include <stdint.h>
#include <stdio.h>

#include "symline/detect.h"

#include "fwdata.h"

extern const fw_frame fw_bench_320x240;

#define WIDTH 320u
#define HEIGHT 240u
/* Working memory of the detector (32 KiB: the budget at 320x240), checked against
 * symline_detect_workspace_size() at start-up (see docs/porting.md). */
#define WS_BYTES (32u * 1024u)
#define MAX_SEGMENTS 64u
#define MAX_POINTS 8192u

static uint64_t workspace[WS_BYTES / sizeof(uint64_t)]; /* any alignment works */
static symline_segment segments[MAX_SEGMENTS];
static symline_point points[MAX_POINTS];

/* Prints a Q8 coordinate (256 = 1 pixel) with two decimals, integers only. */
static void print_q8(int32_t v)
{
    const uint32_t a = (uint32_t)(v < 0 ? -v : v);
    const uint32_t hundredths = (a * 100u + 128u) / 256u;
    printf("%s%lu.%02lu", v < 0 ? "-" : "", (unsigned long)(hundredths / 100u),
           (unsigned long)(hundredths % 100u));
}

int main(void)
{
    const symline_image frame = {WIDTH, HEIGHT, WIDTH, fw_bench_320x240.px};
    symline_config cfg;
    symline_result res = {segments, MAX_SEGMENTS, 0u, points, MAX_POINTS, 0u, 0u, {0}, 0u};
    size_t need;
    symline_status st;
    uint32_t i;

    symline_config_default(&cfg);
    need = symline_detect_workspace_size(WIDTH, HEIGHT, &cfg);
    if (need == 0u || need > sizeof workspace) {
        printf("workspace: need %lu bytes, have %lu\n", (unsigned long)need,
               (unsigned long)sizeof workspace);
        return 1;
    }

    /* --- per frame: the result arrays are reused, the counts rewritten --- */
    st = symline_detect(&frame, &cfg, workspace, need, &res);
    if (st != SYMLINE_OK) {
        printf("symline_detect: %s\n", symline_status_str(st));
        return 1;
    }

    printf("%lux%lu frame: %lu segments (workspace %lu bytes)%s\n", (unsigned long)WIDTH,
           (unsigned long)HEIGHT, (unsigned long)res.segment_count, (unsigned long)need,
           res.truncated ? ", truncated" : "");
    for (i = 0; i < res.segment_count; i++) {
        const symline_segment *s = &segments[i];
        printf("  %2lu %s (", (unsigned long)i, s->kind == SYMLINE_KIND_LINE ? "line " : "curve");
        print_q8(s->x0);
        printf(", ");
        print_q8(s->y0);
        printf(") - (");
        print_q8(s->x1);
        printf(", ");
        print_q8(s->y1);
        printf(")  %s  max dev ", s->axis == SYMLINE_AXIS_HORIZONTAL ? "horizontal" : "vertical");
        print_q8((int32_t)s->max_dev);
        printf(" px, %lu points\n", (unsigned long)s->count);
    }
    return 0;
}

/* SPDX-License-Identifier: Apache-2.0 */
/*
 * Stack actually used by the core's main entry points on the target, to
 * cross-check the static bounds of tools/firmware/stack.awk (a measured value
 * above its bound would mean the analysis missed something).
 *
 * The region below the current stack pointer is filled with a pattern, the
 * call is made, and the lowest overwritten word gives the depth. The filling
 * and scanning run inline in main(), never in a called function whose own
 * frame would lie in the region.
 */
#include <stdint.h>
#include <stdio.h>

#include "symline/detect.h"
#include "symline/extrema.h"
#include "symline/intersections.h"
#include "symline/symmetry.h"

#include "fwdata.h"

extern const fw_frame fw_bench_320x240;

#define REGION 4096u
#define PATTERN 0xA5C3E1F7u

static uint64_t ws[65536u / 8u];
static uint8_t out[320u * 240u];
static symline_segment segs[256];
static symline_point pts[16384];
static symline_intersection items[64];

static inline uintptr_t stack_pointer(void)
{
    uintptr_t sp;
    __asm__ volatile("mov %0, sp" : "=r"(sp));
    return sp;
}

#define MEASURE(name, call)                                                                        \
    do {                                                                                           \
        volatile uint32_t *lo = (volatile uint32_t *)(stack_pointer() - REGION);                   \
        volatile uint32_t *p;                                                                      \
        uintptr_t sp = stack_pointer();                                                            \
        symline_status st;                                                                         \
        for (p = lo; (uintptr_t)p < sp - 16u; p++) {                                               \
            *p = PATTERN;                                                                          \
        }                                                                                          \
        st = (call);                                                                               \
        for (p = lo; (uintptr_t)p < sp && *p == PATTERN; p++) {                                    \
        }                                                                                          \
        printf("stack %-14s %4lu B used%s\n", name, (unsigned long)(sp - (uintptr_t)p),            \
               st == SYMLINE_OK ? "" : " (call FAILED)");                                          \
        bad |= st != SYMLINE_OK;                                                                   \
    } while (0)

int main(void)
{
    const fw_frame *f = &fw_bench_320x240;
    const symline_image img = {f->width, f->height, f->width, f->px};
    const uint32_t n = f->width * f->height;
    symline_config def, paper;
    symline_intersection_config icfg;
    symline_intersection_result ix = {items, 64u, 0u, 0u};
    symline_result r1 = {segs, 256u, 0u, pts, 16384u, 0u, 0u, {0}, 0u};
    symline_result r2 = {segs, 256u, 0u, pts, 16384u, 0u, 0u, {0}, 0u};
    int bad = 0;
    symline_config_default(&def);
    paper = def;
    paper.filter = SYMLINE_FILTER_PAPER;
    paper.illumination = 100u;
    MEASURE("symline_symmetry",
            symline_symmetry(&img, SYMLINE_AXIS_HORIZONTAL, 3u, out, f->width, n, ws, sizeof ws));
    MEASURE("symline_extrema",
            symline_extrema(&img, SYMLINE_AXIS_HORIZONTAL, 3u, out, f->width, n, ws, sizeof ws));
    MEASURE("symline_detect", symline_detect(&img, &def, ws, sizeof ws, &r1));
    MEASURE("symline_detect", symline_detect(&img, &paper, ws, sizeof ws, &r2));
    symline_intersection_config_default(&icfg);
    MEASURE("symline_intersections", symline_intersections(&r2, &icfg, &ix));
    return bad;
}

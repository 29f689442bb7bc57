/* SPDX-License-Identifier: Apache-2.0 */
/*
 * Instructions per pixel of the core on the target, for two real frame
 * windows (160x120 and 320x240, cut from a bundled MSL frame) at m = 3.
 *
 * Run under `qemu-system-arm -M mps2-an386 -icount shift=0 ...`: each
 * instruction then takes 1 ns of virtual time and SysTick counts the
 * processor clock, so a tick is a fixed number of instructions. That number
 * is not assumed but measured first on a loop of known length (2 instructions
 * per iteration); the remaining uncertainty is a few ticks per measurement
 * (tens of instructions), negligible for whole frames.
 */
#include <stdint.h>
#include <stdio.h>

#include "symline/extrema.h"
#ifdef SYMLINE_FW_HAVE_DETECT
#include "symline/detect.h"
#endif
#include "symline/symmetry.h"

#include "fwdata.h"
#include "systick.h"

extern const fw_frame fw_bench_160x120, fw_bench_320x240;

#define M 3u
#define SPIN 1000000u

static uint8_t out[320u * 240u];
static uint64_t ws[16384u / 8u];

/* Exactly 2 instructions per iteration (a flag-setting subtract, bne). GCC
 * writes ARMv6-M code in the divided assembler syntax, where the 16-bit
 * `sub rN, #1` sets the flags. */
static void spin(uint32_t n)
{
#if defined(__thumb2__)
    __asm__ volatile("1:\n\tsubs %0, %0, #1\n\tbne 1b" : "+l"(n) : : "cc");
#else
    __asm__ volatile("1:\n\tsub %0, #1\n\tbne 1b" : "+l"(n) : : "cc");
#endif
}

static uint64_t cal_ticks, empty_ticks;

static uint64_t to_instructions(uint64_t ticks)
{
    ticks = (ticks > empty_ticks) ? ticks - empty_ticks : 0u;
    return (ticks * 2u * SPIN + cal_ticks / 2u) / cal_ticks;
}

static void report(const fw_frame *f, const char *what, const char *axis, uint64_t ticks,
                   symline_status st)
{
    const uint64_t insn = to_instructions(ticks);
    const uint64_t px = (uint64_t)f->width * f->height;
    const uint64_t ipp100 = (insn * 100u + px / 2u) / px;
    printf("icount %lux%lu m=%u %-10s %-9s %9lu instructions %4lu.%02lu per pixel%s\n",
           (unsigned long)f->width, (unsigned long)f->height, M, axis, what, (unsigned long)insn,
           (unsigned long)(ipp100 / 100u), (unsigned long)(ipp100 % 100u),
           st == SYMLINE_OK ? "" : "  (call FAILED)");
}

static int run(const fw_frame *f)
{
    static const symline_axis axes[2] = {SYMLINE_AXIS_HORIZONTAL, SYMLINE_AXIS_VERTICAL};
    static const char *const names[2] = {"horizontal", "vertical"};
    const symline_image img = {f->width, f->height, f->width, f->px};
    const uint32_t n = f->width * f->height;
    int bad = 0;
    unsigned a;
    for (a = 0; a < 2u; a++) {
        uint64_t t0;
        symline_status st;
        t0 = systick_now();
        st = symline_symmetry(&img, axes[a], M, out, f->width, n, ws, sizeof ws);
        report(f, "symmetry", names[a], systick_now() - t0, st);
        bad |= st != SYMLINE_OK;
        t0 = systick_now();
        st = symline_extrema(&img, axes[a], M, out, f->width, n, ws, sizeof ws);
        report(f, "extrema", names[a], systick_now() - t0, st);
        bad |= st != SYMLINE_OK;
    }
    return bad;
}

#ifdef SYMLINE_FW_HAVE_DETECT
static uint64_t det_ws[65536u / 8u];
static symline_segment segs[256];
static symline_point pts[16384];

static int run_detect(const fw_frame *f, const symline_config *cfg, const char *what)
{
    const symline_image img = {f->width, f->height, f->width, f->px};
    symline_result res = {segs, 256u, 0u, pts, 16384u, 0u, 0u, {0}, 0u};
    const size_t need = symline_detect_workspace_size(f->width, f->height, cfg);
    uint64_t t0;
    symline_status st = SYMLINE_ERR_BUFFER;
    t0 = systick_now();
    if (need > 0u && need <= sizeof det_ws) {
        st = symline_detect(&img, cfg, det_ws, need, &res);
    }
    report(f, what, "detect", systick_now() - t0, st);
    return st != SYMLINE_OK;
}

/* Smallest point storage with which a detection is not truncated (bisection;
 * the detector reports truncation whenever the storage runs out, including
 * its use as scratch for a pass's raster list of line points), which must be
 * what the detector reports as points_needed. Returns 1 when they differ. */
static int point_storage(const fw_frame *f, const symline_config *cfg, const char *what)
{
    const symline_image img = {f->width, f->height, f->width, f->px};
    const size_t need = symline_detect_workspace_size(f->width, f->height, cfg);
    uint32_t lo = 0u, hi = 16384u, used = 0u, reported = 0u;
    {
        symline_result res = {segs, 256u, 0u, pts, 16384u, 0u, 0u, {0}, 0u};
        if (symline_detect(&img, cfg, det_ws, need, &res) == SYMLINE_OK) {
            reported = res.points_needed;
        }
    }
    while (lo < hi) {
        const uint32_t mid = (lo + hi) / 2u;
        symline_result res = {segs, 256u, 0u, pts, mid, 0u, 0u, {0}, 0u};
        if (symline_detect(&img, cfg, det_ws, need, &res) == SYMLINE_OK && !res.truncated) {
            hi = mid;
            used = res.point_count;
        } else {
            lo = mid + 1u;
        }
    }
    printf("point storage %lux%lu m=%u %s: %lu points (%lu bytes) needed, %lu kept in the result; "
           "points_needed %s\n",
           (unsigned long)f->width, (unsigned long)f->height, M, what, (unsigned long)lo,
           (unsigned long)(lo * sizeof(symline_point)), (unsigned long)used,
           reported == lo ? "agrees" : "DIFFERS");
    return reported != lo;
}

/* Workspace of the detector (the frame and the result arrays excluded). */
static void workspace_sizes(void)
{
    static const uint32_t dims[3][2] = {{160u, 120u}, {320u, 240u}, {640u, 480u}};
    static const uint32_t radii[2] = {3u, 10u};
    unsigned d, r;
    for (r = 0; r < 2u; r++) {
        for (d = 0; d < 3u; d++) {
            symline_config one, def;
            symline_config_default(&def);
            def.radius = radii[r];
            one = def;
            one.axes = SYMLINE_AXES_HORIZONTAL;
            one.levels = 1u;
            printf("workspace %lux%lu m=%lu: one axis, one scale %lu bytes; default config %lu "
                   "bytes\n",
                   (unsigned long)dims[d][0], (unsigned long)dims[d][1], (unsigned long)radii[r],
                   (unsigned long)symline_detect_workspace_size(dims[d][0], dims[d][1], &one),
                   (unsigned long)symline_detect_workspace_size(dims[d][0], dims[d][1], &def));
        }
    }
}
#endif

int main(void)
{
    uint64_t t0;
    int bad;
    systick_start();
    t0 = systick_now();
    empty_ticks = systick_now() - t0;
    t0 = systick_now();
    spin(SPIN);
    cal_ticks = systick_now() - t0 - empty_ticks;
    printf("calibration: %lu-instruction loop = %lu ticks (%lu.%02lu instructions per tick)\n",
           (unsigned long)(2u * SPIN), (unsigned long)cal_ticks,
           (unsigned long)(2u * SPIN / cal_ticks),
           (unsigned long)((2u * SPIN * 100u / cal_ticks) % 100u));
    bad = run(&fw_bench_160x120);
    bad |= run(&fw_bench_320x240);
#ifdef SYMLINE_FW_HAVE_DETECT
    {
        symline_config def, one;
        symline_config_default(&def);
        def.radius = M;
        one = def;
        one.axes = SYMLINE_AXES_HORIZONTAL;
        one.levels = 1u;
        bad |= run_detect(&fw_bench_160x120, &one, "1axis1lvl");
        bad |= run_detect(&fw_bench_160x120, &def, "default");
        bad |= run_detect(&fw_bench_320x240, &one, "1axis1lvl");
        bad |= run_detect(&fw_bench_320x240, &def, "default");
        bad |= point_storage(&fw_bench_320x240, &one, "1axis1lvl");
        bad |= point_storage(&fw_bench_320x240, &def, "default");
    }
    workspace_sizes();
#endif
    return bad;
}

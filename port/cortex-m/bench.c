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
#include "symline/symmetry.h"

#include "fwdata.h"
#include "systick.h"

extern const fw_frame fw_bench_160x120, fw_bench_320x240;

#define M 3u
#define SPIN 1000000u

static uint8_t out[320u * 240u];
static uint64_t ws[16384u / 8u];

/* Exactly 2 instructions per iteration (subs, bne). */
static void spin(uint32_t n)
{
    __asm__ volatile("1:\n\tsubs %0, %0, #1\n\tbne 1b" : "+l"(n) : : "cc");
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
           (unsigned long)f->width, (unsigned long)f->height, M, axis, what,
           (unsigned long)insn, (unsigned long)(ipp100 / 100u), (unsigned long)(ipp100 % 100u),
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
    return bad;
}

/* SPDX-License-Identifier: Apache-2.0 */
/*
 * The detector over the embedded frames (the golden crops and two windows of
 * a bundled MSL frame) with the default and the paper configuration, printed
 * exactly (segprint.c). The same source runs on the target (qemu) and on the
 * host; tools/firmware/check.sh requires the two outputs to be identical.
 * Exit status 1 when a call fails or a result is truncated.
 */
#include <stdint.h>
#include <stdio.h>

#include "symline/detect.h"

#include "fwdata.h"
#include "segprint.h"

extern const fw_frame in_crops_centreline, in_crops_circle, in_crops_goalarea;
extern const fw_frame fw_bench_160x120, fw_bench_320x240;

#define WS_BYTES (64u * 1024u)
#define SEG_CAP 256u
#define PT_CAP 16384u

static uint64_t ws[WS_BYTES / 8u];
static symline_segment segs[SEG_CAP];
static symline_point pts[PT_CAP];

static int detect(const char *name, const fw_frame *f, const symline_config *cfg)
{
    const symline_image img = {f->width, f->height, f->width, f->px};
    symline_result res = {segs, SEG_CAP, 0u, pts, PT_CAP, 0u, 0u, {0}, 0u};
    const size_t need = symline_detect_workspace_size(f->width, f->height, cfg);
    symline_status st;
    if (need == 0u || need > sizeof ws) {
        printf("%s: workspace %lu bytes does not fit the %lu-byte buffer\n", name,
               (unsigned long)need, (unsigned long)sizeof ws);
        return 1;
    }
    st = symline_detect(&img, cfg, ws, need, &res);
    print_detection(name, st, &res);
    return st != SYMLINE_OK || res.truncated;
}

int main(void)
{
    static const struct {
        const char *name;
        const fw_frame *f;
    } frames[] = {
        {"crop centreline 96x72", &in_crops_centreline}, {"crop circle 96x72", &in_crops_circle},
        {"crop goalarea 96x72", &in_crops_goalarea},     {"msl window 160x120", &fw_bench_160x120},
        {"msl window 320x240", &fw_bench_320x240},
    };
    symline_config def, paper;
    char name[64];
    unsigned i;
    int bad = 0;
    symline_config_default(&def);
    symline_config_default(&paper);
    paper.filter = SYMLINE_FILTER_PAPER;
    paper.illumination = 100u;
    for (i = 0; i < sizeof frames / sizeof frames[0]; i++) {
        snprintf(name, sizeof name, "%s default", frames[i].name);
        bad |= detect(name, frames[i].f, &def);
        snprintf(name, sizeof name, "%s paper", frames[i].name);
        bad |= detect(name, frames[i].f, &paper);
    }
    printf("detector check: %s\n", bad ? "FAILED" : "done");
    return bad;
}

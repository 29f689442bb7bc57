/* SPDX-License-Identifier: Apache-2.0 */
/*
 * The detector's golden JSON (tests/golden/lines/) reproduced on the target:
 * every bundled real frame (608x800, in flash) through symline_detect() with
 * the default configuration, one with the paper filter and two darkened by
 * 40 gray levels (a copy in RAM), then
 * symline_intersections() with its defaults, written with the host
 * programs' JSON writer (capture/hostio/segjson.c) over semihosting.
 * tools/firmware/check.sh splits the output at the "=== NAME" lines and
 * compares each part byte for byte with the golden file.
 */
#include <stdint.h>
#include <stdio.h>

#include "segjson.h"
#include "symline/detect.h"
#include "symline/intersections.h"

#include "fwdata.h"

extern const fw_frame fw_msl_20190606_r2_cam0_20190606_204340;
extern const fw_frame fw_msl_20240719_r5_cam3_20240719_090755;
extern const fw_frame fw_msl_20250403_r4_cam3_20250403_221433;

#define WS_BYTES (64u * 1024u)
#define SEG_CAP 2048u
#define PT_CAP 65536u
#define IX_CAP 256u

static uint64_t ws[WS_BYTES / 8u];
static symline_segment segs[SEG_CAP];
static symline_point pts[PT_CAP];
static symline_intersection items[IX_CAP];
/* A frame darkened by 40 (tests/detect/test_golden_lines.c). */
#define DARK_BYTES (608u * 800u)
static uint8_t dark[DARK_BYTES];

/* What a frame goes through before the detection, and its golden file's suffix. */
enum variant {
    AS_IS,
    PAPER,
    DARK40
};
static const char *const SUFFIX[3] = {"", ".paper", ".m40"};

static int run(const char *name, const fw_frame *f, enum variant v)
{
    symline_image img = {f->width, f->height, f->width, f->px};
    symline_result res = {segs, SEG_CAP, 0u, pts, PT_CAP, 0u, 0u, {0}, 0u};
    symline_intersection_result ix = {items, IX_CAP, 0u, 0u};
    symline_intersection_config icfg;
    symline_config cfg;
    size_t need;
    symline_status st;
    symline_config_default(&cfg);
    if (v == DARK40) {
        uint32_t i;
        if ((size_t)f->width * f->height > sizeof dark) {
            printf("=== %s%s\nframe larger than %lu bytes\n", name, SUFFIX[v],
                   (unsigned long)sizeof dark);
            return 1;
        }
        for (i = 0; i < f->width * f->height; i++) {
            dark[i] = (uint8_t)(f->px[i] > 40u ? f->px[i] - 40u : 0u);
        }
        img.data = dark;
    }
    if (v == PAPER) { /* what `symline lines --filter paper` sets */
        cfg.filter = SYMLINE_FILTER_PAPER;
        cfg.illumination = 100u;
        cfg.adaptive = false;
    }
    need = symline_detect_workspace_size(f->width, f->height, &cfg);
    printf("=== %s%s\n", name, SUFFIX[v]);
    if (need == 0u || need > sizeof ws) {
        printf("workspace %lu bytes does not fit %lu\n", (unsigned long)need,
               (unsigned long)sizeof ws);
        return 1;
    }
    st = symline_detect(&img, &cfg, ws, need, &res);
    if (st != SYMLINE_OK) {
        printf("symline_detect: %s\n", symline_status_str(st));
        return 1;
    }
    symline_intersection_config_default(&icfg);
    st = symline_intersections(&res, &icfg, &ix);
    if (st != SYMLINE_OK) {
        printf("symline_intersections: %s\n", symline_status_str(st));
        return 1;
    }
    return segjson_write_ix(stdout, f->width, f->height, &res, &ix) != 0 || res.truncated ||
           ix.truncated;
}

int main(void)
{
    int bad = 0;
    bad |= run("msl_20190606_r2_cam0_20190606_204340", &fw_msl_20190606_r2_cam0_20190606_204340, AS_IS);
    bad |= run("msl_20240719_r5_cam3_20240719_090755", &fw_msl_20240719_r5_cam3_20240719_090755, AS_IS);
    bad |= run("msl_20240719_r5_cam3_20240719_090755", &fw_msl_20240719_r5_cam3_20240719_090755, DARK40);
    bad |= run("msl_20250403_r4_cam3_20250403_221433", &fw_msl_20250403_r4_cam3_20250403_221433, AS_IS);
    bad |= run("msl_20250403_r4_cam3_20250403_221433", &fw_msl_20250403_r4_cam3_20250403_221433, DARK40);
    bad |= run("msl_20250403_r4_cam3_20250403_221433", &fw_msl_20250403_r4_cam3_20250403_221433, PAPER);
    printf("=== end\n");
    return bad;
}

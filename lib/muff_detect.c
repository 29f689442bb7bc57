/* SPDX-License-Identifier: Apache-2.0 */
/*
 * symline_detect_muff(): the line filter's points into the Muff-space finder.
 * A file of its own so that a caller who brings its own points links the
 * finder without the detector.
 */
#include "symline/muff.h"

size_t symline_detect_muff_workspace_size(uint32_t width, uint32_t height,
                                          const symline_config *cfg, const symline_muff_config *mc)
{
    const size_t a = symline_detect_workspace_size(width, height, cfg);
    const size_t b = symline_muff_workspace_size(width, height, mc);
    if (a == 0u || b == 0u) {
        return 0u;
    }
    return a > b ? a : b;
}

symline_status symline_detect_muff(const symline_image *img, const symline_config *cfg,
                                   const symline_muff_config *mc, uint16_t *acc, size_t acc_size,
                                   void *ws, size_t ws_size, symline_result *out)
{
    uint32_t n = 0u;
    bool cut = false;
    symline_status st = symline_image_check(img);
    if (st != SYMLINE_OK) {
        return st;
    }
    if (cfg == NULL || mc == NULL || acc == NULL || ws == NULL || out == NULL) {
        return SYMLINE_ERR_NULL;
    }
    if ((out->points == NULL && out->point_cap != 0u) ||
        (out->segments == NULL && out->segment_cap != 0u)) {
        return SYMLINE_ERR_NULL;
    }
    if (symline_muff_accumulator_size(img->width, img->height, mc) == 0u) {
        return img->width < 3u || img->height < 3u ? SYMLINE_ERR_SIZE : SYMLINE_ERR_CONFIG;
    }
    if (ws_size < symline_detect_muff_workspace_size(img->width, img->height, cfg, mc)) {
        return symline_detect_workspace_size(img->width, img->height, cfg) == 0u
                   ? SYMLINE_ERR_CONFIG
                   : SYMLINE_ERR_BUFFER;
    }
    if (acc_size < symline_muff_accumulator_size(img->width, img->height, mc)) {
        return SYMLINE_ERR_BUFFER;
    }
    st = symline_line_points(img, cfg, ws, ws_size, out->points, out->point_cap, &n, &cut);
    if (st != SYMLINE_OK) {
        return st;
    }
    st = symline_muff_find(img->width, img->height, mc, acc, acc_size, ws, ws_size, n, out);
    if (st == SYMLINE_OK && cut) {
        out->truncated = true;
    }
    return st;
}

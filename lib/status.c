/* SPDX-License-Identifier: Apache-2.0 */
/*
 * Status names and the image view check.
 */
#include "common.h"

const char *symline_status_str(symline_status st)
{
    switch (st) {
    case SYMLINE_OK: return "ok";
    case SYMLINE_ERR_NULL: return "NULL pointer";
    case SYMLINE_ERR_SIZE: return "width or height is 0 or larger than 65535";
    case SYMLINE_ERR_STRIDE: return "stride smaller than the row length";
    case SYMLINE_ERR_RADIUS: return "radius outside 1..255";
    case SYMLINE_ERR_AXIS: return "unknown axis";
    case SYMLINE_ERR_BUFFER: return "buffer or workspace too small";
    case SYMLINE_ERR_RANGE: return "index or value out of range";
    case SYMLINE_ERR_CONFIG: return "configuration value out of range";
    }
    return "unknown status";
}

symline_status symline_image_check(const symline_image *img)
{
    if (img == NULL || img->data == NULL) {
        return SYMLINE_ERR_NULL;
    }
    if (img->width == 0u || img->height == 0u || img->width > SYMLINE_MAX_DIM ||
        img->height > SYMLINE_MAX_DIM) {
        return SYMLINE_ERR_SIZE;
    }
    if (img->stride < img->width) {
        return SYMLINE_ERR_STRIDE;
    }
    return SYMLINE_OK;
}

/* SPDX-License-Identifier: Apache-2.0 */
/*
 * Status names, the image view check and workspace carving.
 */
#include "common.h"

/* The names of SYMLINE_OK (0) down to SYMLINE_ERR_CONFIG (-8), then of
 * anything else, in one string: the i-th follows the i-th NUL. */
static const char NAMES[] = "ok\0"
                            "NULL pointer\0"
                            "width or height is 0 or larger than 65535\0"
                            "stride smaller than the row length\0"
                            "radius outside 1..255\0"
                            "unknown axis\0"
                            "buffer or workspace too small\0"
                            "index or value out of range\0"
                            "configuration value out of range\0"
                            "unknown status";

const char *symline_status_str(symline_status st)
{
    /* -st for the codes, 9 (unknown) for anything else a caller may pass. */
    uint32_t i = 0u - (uint32_t)st;
    const char *s = NAMES;
    /* cppcheck-suppress knownConditionTrueFalse */
    for (i = i <= 8u ? i : 9u; i > 0u; i--) {
        while (*s++ != '\0') {
        }
    }
    return s;
}

symline_status symline_image_check(const symline_image *img)
{
    if (img == NULL || img->data == NULL) {
        return SYMLINE_ERR_NULL;
    }
    /* 0 wraps: one compare per dimension for 1 .. SYMLINE_MAX_DIM. */
    if (img->width - 1u >= SYMLINE_MAX_DIM || img->height - 1u >= SYMLINE_MAX_DIM) {
        return SYMLINE_ERR_SIZE;
    }
    if (img->stride < img->width) {
        return SYMLINE_ERR_STRIDE;
    }
    return SYMLINE_OK;
}

void *symline_i_carve_shared(uint8_t **cur, uint8_t *end, size_t bytes)
{
    return symline_i_carve_here(cur, end, bytes);
}

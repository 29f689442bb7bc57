/* SPDX-License-Identifier: Apache-2.0 */
/*
 * Status names, the image view check and workspace carving.
 */
#include "common.h"

/* The names of SYMLINE_OK (0) down to SYMLINE_ERR_CONFIG (-8) in one string,
 * and where each begins: a byte per name instead of a pointer. */
#define SL_S0 "ok"
#define SL_S1 "NULL pointer"
#define SL_S2 "width or height is 0 or larger than 65535"
#define SL_S3 "stride smaller than the row length"
#define SL_S4 "radius outside 1..255"
#define SL_S5 "unknown axis"
#define SL_S6 "buffer or workspace too small"
#define SL_S7 "index or value out of range"
#define SL_S8 "configuration value out of range"
#define SL_S9 "unknown status"
static const char NAMES[] = SL_S0 "\0" SL_S1 "\0" SL_S2 "\0" SL_S3 "\0" SL_S4 "\0" SL_S5 "\0" SL_S6
                                  "\0" SL_S7 "\0" SL_S8 "\0" SL_S9;
#define SL_O1 sizeof(SL_S0)
#define SL_O2 (SL_O1 + sizeof(SL_S1))
#define SL_O3 (SL_O2 + sizeof(SL_S2))
#define SL_O4 (SL_O3 + sizeof(SL_S3))
#define SL_O5 (SL_O4 + sizeof(SL_S4))
#define SL_O6 (SL_O5 + sizeof(SL_S5))
#define SL_O7 (SL_O6 + sizeof(SL_S6))
#define SL_O8 (SL_O7 + sizeof(SL_S7))
#define SL_O9 (SL_O8 + sizeof(SL_S8))
static const uint8_t AT[10] = {0u, SL_O1, SL_O2, SL_O3, SL_O4, SL_O5, SL_O6, SL_O7, SL_O8, SL_O9};

const char *symline_status_str(symline_status st)
{
    /* -st for the codes, 9 (unknown) for anything else a caller may pass. */
    const uint32_t i = 0u - (uint32_t)st;
    /* cppcheck-suppress knownConditionTrueFalse */
    return NAMES + AT[i <= 8u ? i : 9u];
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

void *symline_i_carve_shared(uint8_t **cur, uint8_t *end, size_t bytes)
{
    return symline_i_carve_here(cur, end, bytes);
}

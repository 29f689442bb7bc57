/* SPDX-License-Identifier: Apache-2.0 */
/*
 * Frames embedded in flash by tools/firmware/pgm2c.c (generated at build
 * time from the repository's PGM files).
 */
#ifndef SYMLINE_FWDATA_H
#define SYMLINE_FWDATA_H

#include <stdint.h>

typedef struct fw_frame {
    uint32_t width;
    uint32_t height;
    const uint8_t *px; /* width*height bytes, row-major, stride = width */
} fw_frame;

/* One golden case: the input, the axis, the radius and the reference outputs. */
typedef struct fw_golden {
    const char *name;
    const fw_frame *in;
    uint8_t axis; /* symline_axis */
    uint8_t m;
    const fw_frame *s8;  /* symmetry image S8 */
    const fw_frame *ext; /* extrema map */
} fw_golden;

#endif /* SYMLINE_FWDATA_H */

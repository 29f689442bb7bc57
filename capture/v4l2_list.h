/* SPDX-License-Identifier: Apache-2.0 */
/*
 * What V4L2 devices there are and what they offer, for `symline-capture
 * --list-devices` and `--list-formats` (the questions a user has before the
 * first capture). Host/Linux code.
 */
#ifndef SYMLINE_CAPTURE_V4L2_LIST_H
#define SYMLINE_CAPTURE_V4L2_LIST_H

#include <stddef.h>
#include <stdio.h>

/*
 * Prints one line per video device node DIR/videoN (N ascending): its name,
 * driver and bus, whether it captures video, and the formats symline reads.
 * Returns the number of capture devices found (0 when none), -1 with a
 * message in err when DIR cannot be read.
 */
int v4l2_list_devices(FILE *out, const char *dir, char *err, size_t errlen);

/*
 * Prints the capture formats of device, each with how symline gets its
 * luma, its frame sizes and frame rates. 0, or -1 with a message in err.
 */
int v4l2_list_formats(FILE *out, const char *device, char *err, size_t errlen);

/*
 * The device path for a --device argument: a bare number N means
 * /dev/videoN, anything else is taken as a path. Writes into buf (cap bytes)
 * and returns buf, or NULL when it does not fit.
 */
const char *v4l2_device_path(const char *arg, char *buf, size_t cap);

#endif

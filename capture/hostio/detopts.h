/* SPDX-License-Identifier: Apache-2.0 */
/*
 * Detector options of the host programs: one parser and one help text for
 * `symline lines|overlay` and `symline-capture`, so both accept exactly the
 * same options with the same ranges and defaults.
 */
#ifndef SYMLINE_HOSTIO_DETOPTS_H
#define SYMLINE_HOSTIO_DETOPTS_H

#include <getopt.h>
#include <stddef.h>
#include <stdint.h>
#include <stdio.h>

#include "symline/detect.h"

/* --bin: 2x2 binning before the detection (symline/binning.h). */
typedef enum detopts_bin {
    DETOPTS_BIN_AUTO = 0, /* where symline_bin2_advised() says so (default) */
    DETOPTS_BIN_OFF = 1,
    DETOPTS_BIN_ON = 2
} detopts_bin;

typedef struct detopts {
    symline_config cfg; /* starts at symline_config_default() */
    uint32_t seen;      /* which table options were given (for implied defaults) */
    detopts_bin bin;    /* --bin */
} detopts;

/*
 * A decimal argument in [lo, hi] (digits only, no sign, no trailing text).
 * 0 on success. Shared by every option parser of the host tools.
 */
int detopts_u32(const char *s, uint32_t lo, uint32_t hi, uint32_t *out);

void detopts_init(detopts *d);

/*
 * The detector options for getopt_long: appends one `struct option` per detector
 * option to out (at most cap; each takes a value, val = DETOPTS_VAL + k) and
 * returns how many it wrote.
 */
#define DETOPTS_VAL 0x4000
size_t detopts_longopts(struct option *out, size_t cap);

/*
 * Applies what getopt_long returned (code, optarg). Returns 1 when code was a
 * detector option, 0 when it was not, -1 on a bad value (a message in err).
 */
int detopts_apply(detopts *d, int code, const char *arg, char *err, size_t errlen);

/* After parsing: --filter paper implies --illumination 100 --adaptive 0 unless given. */
void detopts_finish(detopts *d);

/*
 * Point storage both tools give the detector for a width x height frame: two
 * points per pixel plus 1024 (the storage also holds a pass's raster list of
 * line points, detect.h), at most what keeps the byte size within 32 bits,
 * so that it fits a 32-bit size_t; both tools hence report the same result
 * for the same frame.
 */
uint32_t detopts_point_cap(uint32_t width, uint32_t height);

/* Whether a width x height frame is detected binned 2x2 under `bin`. */
int detopts_bins(detopts_bin bin, uint32_t width, uint32_t height);

/* --bin's value ("auto", "off", "on") into *bin; 0, or -1 (NULL or another
 * word: *bin unchanged). */
int detopts_bin_parse(const char *value, detopts_bin *bin);

/* The option lines of a --help text, with the defaults of this build. */
void detopts_help(FILE *f);

#endif

/*
 * Detector options of the host programs: one parser and one help text for
 * `symline lines|overlay` and `symline-capture`, so both accept exactly the
 * same options with the same ranges and defaults.
 */
#ifndef SYMLINE_HOSTIO_DETOPTS_H
#define SYMLINE_HOSTIO_DETOPTS_H

#include <stddef.h>
#include <stdint.h>
#include <stdio.h>

#include "symline/detect.h"

typedef struct detopts {
    symline_config cfg; /* starts at symline_config_default() */
    uint32_t seen;      /* which table options were given (for implied defaults) */
} detopts;

/*
 * A decimal argument in [lo, hi] (digits only, no sign, no trailing text).
 * 0 on success. Shared by every option parser of the host tools.
 */
int detopts_u32(const char *s, uint32_t lo, uint32_t hi, uint32_t *out);

void detopts_init(detopts *d);

/*
 * Tries argv[*i] (and its value argv[*i+1]) as a detector option.
 * Returns 1 when it was one (then *i is advanced to its value), 0 when
 * argv[*i] is not a detector option, -1 on a missing or bad value (a message
 * in err).
 */
int detopts_parse(detopts *d, int argc, char **argv, int *i, char *err, size_t errlen);

/* After parsing: --filter paper implies --illumination 100 --adaptive 0 unless given. */
void detopts_finish(detopts *d);

/* The option lines of a --help text, with the defaults of this build. */
void detopts_help(FILE *f);

#endif

/* SPDX-License-Identifier: Apache-2.0 */
/*
 * `symline lines|overlay --method muff|tracer` and the Muff-space finder's
 * options (symline/muff.h).
 */
#ifndef SYMLINE_CLI_MUFFOPTS_H
#define SYMLINE_CLI_MUFFOPTS_H

#include <getopt.h>
#include <stddef.h>
#include <stdio.h>

#include "symline/muff.h"

typedef struct muffopts {
    int muff;                 /* 0: tracer (symline_detect), 1: Muff space */
    symline_muff_config mc;   /* starts at symline_muff_config_default() */
} muffopts;

void muffopts_init(muffopts *m);

/*
 * The same options for getopt_long (as detopts_longopts(): each takes a
 * value, val = MUFFOPTS_VAL + k): appends at most cap entries, returns how many.
 */
#define MUFFOPTS_VAL 0x4800
size_t muffopts_longopts(struct option *out, size_t cap);

/* Applies what getopt_long returned: 1 when code was one of these options, 0 when not, -1 on a bad value. */
int muffopts_apply(muffopts *m, int code, const char *arg, char *err, size_t errlen);

/* The option lines of a --help text. */
void muffopts_help(FILE *f);

#endif

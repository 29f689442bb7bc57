/*
 * `symline lines|overlay --method muff|tracer` and the Muff-space finder's
 * options (symline/muff.h).
 */
#ifndef SYMLINE_CLI_MUFFOPTS_H
#define SYMLINE_CLI_MUFFOPTS_H

#include <stddef.h>
#include <stdio.h>

#include "symline/muff.h"

typedef struct muffopts {
    int muff;                 /* 0: tracer (symline_detect), 1: Muff space */
    symline_muff_config mc;   /* starts at symline_muff_config_default() */
} muffopts;

void muffopts_init(muffopts *m);

/* Like detopts_parse(): 1 when argv[*i] was one of these options (value
 * consumed), 0 when not, -1 on a bad value (message in err). */
int muffopts_parse(muffopts *m, int argc, char **argv, int *i, char *err, size_t errlen);

/* The option lines of a --help text. */
void muffopts_help(FILE *f);

#endif

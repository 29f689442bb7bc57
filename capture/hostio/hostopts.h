/* SPDX-License-Identifier: Apache-2.0 */
/*
 * The option conventions of every host program (symline, symline-capture,
 * the evaluation and benchmark tools): getopt_long, so --opt value,
 * --opt=value, -- (end of options) and '-' as an argument all work; --help
 * on stdout with exit 0; --version; usage errors as one line on stderr that
 * names the program and points to --help, exit status 2.
 */
#ifndef SYMLINE_HOSTIO_HOSTOPTS_H
#define SYMLINE_HOSTIO_HOSTOPTS_H

#include <getopt.h>

#ifdef __cplusplus
extern "C" {
#endif

#define HOSTOPTS_USAGE 2     /* exit status of a usage error */
#define HOSTOPTS_ERROR (-2)  /* hostopts_next(): a usage error was reported */
#define HOSTOPTS_HELP 'h'    /* the codes hostopts_next() returns for --help / -h */
#define HOSTOPTS_VERSION 'V' /* and --version; give them in longopts as these */

/*
 * getopt_long over argv (start with optind = 1). Returns the option's code,
 * -1 after the last option, or HOSTOPTS_ERROR after printing "WHO: unknown
 * option 'X' (try 'HELP --help')" or "WHO: --opt needs a value (try ...)". who names
 * the program in messages ("symline-score"; "symline: lines"); help is the
 * command that shows its help ("symline-score"; "symline lines"). shortopts
 * should start with ':'.
 */
int hostopts_next(int argc, char **argv, const char *shortopts, const struct option *longopts,
                  const char *who, const char *help);

/* Prints "WHO: " + the message + " (try 'HELP --help')" on stderr; returns HOSTOPTS_USAGE. */
int hostopts_usage_error(const char *who, const char *help, const char *fmt, ...)
#if defined(__GNUC__)
    __attribute__((format(printf, 3, 4)))
#endif
    ;

/*
 * The whole command line of a program with no options of its own besides
 * --help and --version, and exactly npos arguments (from argv[optind] on).
 * usage is its help text (printed on stdout for --help). Returns -1 when the
 * program should go on, else the exit status to return at once.
 */
int hostopts_plain(int argc, char **argv, const char *program, const char *usage, int npos);

/* Prints "PROGRAM VERSION" (symline/version.h) on stdout. */
void hostopts_version(const char *program);

/* A decimal number in [lo, hi] with nothing after it; 0 on success. */
int hostopts_double(const char *s, double lo, double hi, double *out);

/* A decimal integer in [lo, hi] (an optional '-' sign, digits only); 0 on success. */
int hostopts_long(const char *s, long lo, long hi, long *out);

#ifdef __cplusplus
}
#endif

#endif

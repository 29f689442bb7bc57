/* SPDX-License-Identifier: Apache-2.0 */
/*
 * Option conventions of the host programs (hostopts.h).
 */
#include "hostopts.h"

#include <errno.h>
#include <stdarg.h>
#include <stdio.h>
#include <stdlib.h>

#include "symline/version.h"

int hostopts_usage_error(const char *who, const char *help, const char *fmt, ...)
{
    va_list ap;
    fprintf(stderr, "%s: ", who);
    va_start(ap, fmt);
    vfprintf(stderr, fmt, ap);
    va_end(ap);
    fprintf(stderr, " (try '%s --help')\n", help);
    return HOSTOPTS_USAGE;
}

int hostopts_next(int argc, char **argv, const char *shortopts, const struct option *longopts,
                  const char *who, const char *help)
{
    int c;
    opterr = 0; /* the messages below name the program */
    c = getopt_long(argc, argv, shortopts, longopts, NULL);
    if (c == '?') {
        if (optopt != 0) {
            hostopts_usage_error(who, help, "unknown option '-%c'", optopt);
        } else {
            hostopts_usage_error(who, help, "unknown option '%s'", argv[optind - 1]);
        }
        return HOSTOPTS_ERROR;
    }
    if (c == ':') {
        hostopts_usage_error(who, help, "%s needs a value", argv[optind - 1]);
        return HOSTOPTS_ERROR;
    }
    return c;
}

int hostopts_plain(int argc, char **argv, const char *program, const char *usage, int npos)
{
    static const struct option longopts[] = {{"help", no_argument, NULL, HOSTOPTS_HELP},
                                             {"version", no_argument, NULL, HOSTOPTS_VERSION},
                                             {NULL, 0, NULL, 0}};
    int c;
    optind = 1;
    while ((c = hostopts_next(argc, argv, ":h", longopts, program, program)) != -1) {
        if (c == HOSTOPTS_HELP) {
            fputs(usage, stdout);
            return 0;
        }
        if (c == HOSTOPTS_VERSION) {
            hostopts_version(program);
            return 0;
        }
        return HOSTOPTS_USAGE;
    }
    if (argc - optind != npos) {
        return hostopts_usage_error(program, program, "needs %d arguments, got %d", npos,
                                    argc - optind);
    }
    return -1;
}

void hostopts_version(const char *program)
{
    printf("%s %s\n", program, SYMLINE_VERSION_STRING);
}

int hostopts_double(const char *s, double lo, double hi, double *out)
{
    char *end;
    double v;
    if (s == NULL || *s == '\0') {
        return -1;
    }
    errno = 0;
    v = strtod(s, &end);
    if (*end != '\0' || errno != 0 || !(v >= lo && v <= hi)) {
        return -1;
    }
    *out = v;
    return 0;
}

int hostopts_long(const char *s, long lo, long hi, long *out)
{
    const char *p = s;
    char *end;
    long v;
    if (s == NULL) {
        return -1;
    }
    if (*p == '-') {
        p++;
    }
    if (*p < '0' || *p > '9') {
        return -1;
    }
    errno = 0;
    v = strtol(s, &end, 10);
    if (*end != '\0' || errno != 0 || v < lo || v > hi) {
        return -1;
    }
    *out = v;
    return 0;
}

/*
 * The host CLI `symline`: shared helpers of the subcommands.
 */
#ifndef SYMLINE_CLI_H
#define SYMLINE_CLI_H

#include <stdint.h>

#include "symline/types.h"

/* Exit codes. */
#define CLI_OK 0
#define CLI_FAIL 1  /* a processing error after the input was accepted */
#define CLI_USAGE 2 /* usage or input error */

/* Prints "symline: " + message to stderr; returns CLI_USAGE. */
int cli_error(const char *fmt, ...);


/* Parses "horizontal" / "vertical"; 0 on success. */
int cli_parse_axis(const char *s, symline_axis *axis);

const char *cli_axis_name(symline_axis axis);

/* Subcommands: argc/argv start at the subcommand name. */
int cmd_symmetry(int argc, char **argv);
int cmd_extrema(int argc, char **argv);
int cmd_lines(int argc, char **argv);   /* symline lines */
int cmd_overlay(int argc, char **argv); /* symline overlay */
int cmd_convert(int argc, char **argv);
int cmd_features(int argc, char **argv);  /* symline features */
int cmd_histogram(int argc, char **argv); /* symline histogram */
int cmd_boundary(int argc, char **argv); /* symline boundary */

#endif

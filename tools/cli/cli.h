/* SPDX-License-Identifier: Apache-2.0 */
/*
 * The host CLI `symline`: shared helpers of the subcommands.
 */
#ifndef SYMLINE_CLI_H
#define SYMLINE_CLI_H

#include <getopt.h>
#include <stddef.h>
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

/*
 * getopt_long over a command's argv (argv[0] = the command name; reset optind
 * to 1 first): --opt=value, --opt value, -- and '-' as an argument all work.
 * Returns the option code, -1 at the end, or CLI_GETOPT_ERROR after printing
 * "unknown option" / "needs a value". Start shortopts with ':'.
 */
#define CLI_GETOPT_ERROR (-2)
int cli_getopt(int argc, char **argv, const char *shortopts, const struct option *longopts);

/* OUT given as an argument or with -o (not both): 0 with *out set, else CLI_USAGE. */
int cli_output_name(const char *cmd, const char *positional, const char *option, const char **out);

/* Input names; a folder stands for its .pgm/.png/.jpg images in name order (line masks *.mask.* left out). */
typedef struct cli_inputs {
    char **paths;
    size_t count, cap;
    int from_folder; /* 1 when a folder was given */
} cli_inputs;

/* Adds arg ("-" = stdin, a file, or a folder); 0, or CLI_USAGE with a message. */
int cli_inputs_add(cli_inputs *in, const char *cmd, const char *arg);
void cli_inputs_free(cli_inputs *in);

/*
 * After a failed write to `what`: a closed pipe (EPIPE) is a quiet normal end
 * (returns CLI_OK); anything else is reported with its reason (CLI_FAIL).
 */
int cli_write_failed(const char *what);

/* The same after imgio failed to write an image (its message in err). */
int cli_image_write_failed(const char *err);

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

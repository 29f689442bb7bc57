/* SPDX-License-Identifier: Apache-2.0 */
/*
 * symline — host command line tool.
 */
#include <signal.h>
#include <stdarg.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "cli.h"
#include "symline/version.h"

int cli_error(const char *fmt, ...)
{
    va_list ap;
    fputs("symline: ", stderr);
    va_start(ap, fmt);
    vfprintf(stderr, fmt, ap);
    va_end(ap);
    fputc('\n', stderr);
    return CLI_USAGE;
}

int cli_parse_axis(const char *s, symline_axis *axis)
{
    if (s != NULL && strcmp(s, "horizontal") == 0) {
        *axis = SYMLINE_AXIS_HORIZONTAL;
        return 0;
    }
    if (s != NULL && strcmp(s, "vertical") == 0) {
        *axis = SYMLINE_AXIS_VERTICAL;
        return 0;
    }
    return -1;
}

const char *cli_axis_name(symline_axis axis)
{
    return axis == SYMLINE_AXIS_VERTICAL ? "vertical" : "horizontal";
}

static void usage(FILE *f)
{
    fputs("usage: symline COMMAND [options] ...\n"
          "\n"
          "Commands:\n"
          "  symmetry --axis horizontal|vertical --radius M IN OUT\n"
          "      write the 8-bit symmetry image S8 (255 = perfect mirror symmetry)\n"
          "  extrema  --axis horizontal|vertical --radius M IN OUT\n"
          "      write the extrema map: 0 nothing, 128 A point (asymmetry), 255 S point\n"
          "  convert  IN OUT\n"
          "      convert PGM, PNG or JPEG into 8-bit gray PGM or PNG (colour becomes luma)\n"
          "  features --radius M IN\n"
          "      print the symmetry feature points (S points of both axes) as JSON\n"
          "  histogram --radius M IN [--plot OUT.png]\n"
          "      print the vertical symmetry histogram (S points per column) as JSON\n"
#ifdef SYMLINE_CLI_LINES
          "  lines    [--axis horizontal|vertical|both] [--radius M] [options] IN...\n"
          "      print the detected line segments as JSON on stdout (or -o FILE); IN may\n"
          "      be several images or folders: one JSON object per image\n"
          "  overlay  [same options as lines] [--json FILE] IN OUT.png\n"
          "      draw lines (solid) and curves (dotted) over the frame\n"
          "  boundary [--cell N] IN [OUT.png]\n"
          "      print the field boundary as JSON (and draw it)\n"
#endif
          "\n"
          "Axis: 'horizontal' = symmetry about a horizontal axis, computed along columns\n"
          "(finds near-horizontal lines); 'vertical' = about a vertical axis, along rows.\n"
          "Radius M: 1..255. Images: binary PGM (P5, maxval 255); PNG when built with\n"
          "libpng, JPEG input when built with libturbojpeg (colour is converted to luma\n"
          "Y = (299R + 587G + 114B + 500) / 1000). IN '-' reads stdin. OUT: by its\n"
          "name, .pgm, .png, .ppm or .pnm ('-': PGM/PPM on stdout); OUT may also be\n"
          "given as -o OUT. Options take --opt VALUE or --opt=VALUE; -- ends them.\n"
          "Run 'symline COMMAND --help' for a command's options, 'symline --version'\n"
          "for the version.\n"
          "\n"
          "Exit status: 0 ok, 1 processing error, 2 usage or input error.\n",
          f);
}

int main(int argc, char **argv)
{
    /* A closed output pipe shows up as EPIPE on the write, handled where it happens. */
    signal(SIGPIPE, SIG_IGN);
    if (argc < 2) {
        usage(stderr);
        return CLI_USAGE;
    }
    if (strcmp(argv[1], "--help") == 0 || strcmp(argv[1], "-h") == 0 ||
        strcmp(argv[1], "help") == 0) {
        usage(stdout);
        return CLI_OK;
    }
    if (strcmp(argv[1], "--version") == 0) {
        printf("symline %s\n", SYMLINE_VERSION_STRING);
        return CLI_OK;
    }
    if (strcmp(argv[1], "symmetry") == 0) {
        return cmd_symmetry(argc - 1, argv + 1);
    }
    if (strcmp(argv[1], "extrema") == 0) {
        return cmd_extrema(argc - 1, argv + 1);
    }
    if (strcmp(argv[1], "convert") == 0) {
        return cmd_convert(argc - 1, argv + 1);
    }
    if (strcmp(argv[1], "features") == 0) {
        return cmd_features(argc - 1, argv + 1);
    }
    if (strcmp(argv[1], "histogram") == 0) {
        return cmd_histogram(argc - 1, argv + 1);
    }
#ifdef SYMLINE_CLI_LINES
    if (strcmp(argv[1], "lines") == 0) {
        return cmd_lines(argc - 1, argv + 1);
    }
    if (strcmp(argv[1], "overlay") == 0) {
        return cmd_overlay(argc - 1, argv + 1);
    }
    if (strcmp(argv[1], "boundary") == 0) {
        return cmd_boundary(argc - 1, argv + 1);
    }
#endif
    cli_error("unknown command '%s' (try 'symline --help')", argv[1]);
    return CLI_USAGE;
}

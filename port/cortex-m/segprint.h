/* SPDX-License-Identifier: Apache-2.0 */
/*
 * Prints a detection result as plain text, every field as the exact integer
 * the core produced, so a target run and a host run of the same program can
 * be compared with diff.
 */
#ifndef SYMLINE_SEGPRINT_H
#define SYMLINE_SEGPRINT_H

#include "symline/detect.h"

void print_detection(const char *name, symline_status st, const symline_result *res);

#endif /* SYMLINE_SEGPRINT_H */

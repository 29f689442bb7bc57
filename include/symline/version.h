/* SPDX-License-Identifier: Apache-2.0 */
/*
 * symline — the library's version (semantic versioning). The build takes its
 * version from here (CMakeLists.txt), so the numbers exist once.
 */
#ifndef SYMLINE_VERSION_H
#define SYMLINE_VERSION_H

#define SYMLINE_VERSION_MAJOR 0
#define SYMLINE_VERSION_MINOR 1
#define SYMLINE_VERSION_PATCH 0
/* "MAJOR.MINOR.PATCH" */
#define SYMLINE_VERSION_STRING "0.1.0"

#endif /* SYMLINE_VERSION_H */

/* SPDX-License-Identifier: Apache-2.0 */
/*
 * Replay source: frames from PGM/PNG files, for the demo and for machines
 * without a camera.
 */
#ifndef SYMLINE_CAPTURE_REPLAY_SOURCE_H
#define SYMLINE_CAPTURE_REPLAY_SOURCE_H

#include <signal.h>

#include "source.h"

typedef struct replay_options {
    const char *path; /* a directory (its *.pgm / *.png / *.jpg files in name order, without
                         the evaluation's line masks *.mask.pgm / *.mask.png), one image
                         file, a YUV4MPEG2 stream (*.y4m, luma of each frame), or a text
                         file listing one image path per line (relative paths are taken
                         from the list's folder; '#' starts a comment) */
    uint32_t fps_num; /* pace delivery at fps_num/fps_den frames per second; 0 = the Y4M
                         stream's own frame rate, image files as fast as they are read */
    uint32_t fps_den;
    int unpaced;      /* 1 = as fast as frames are read, whatever the recording says */
    int loop;         /* 1 = start over after the last frame */
    const volatile sig_atomic_t *stop; /* optional: reading a list gives up when *stop
                                          becomes non-zero (a stop signal's flag) */
} replay_options;

/* A list file: at most this many entries, lines of at most 4095 bytes, no NUL
 * bytes (anything else, /dev/zero or /dev/urandom say, is not a list). */
#define REPLAY_MAX_LIST_ENTRIES 1000000u

/* Opens a replay source; NULL with a message in err when the path holds no frames. */
capsrc *replay_source_open(const replay_options *opt, char *err, size_t errlen);

#endif

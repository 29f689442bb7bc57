/* SPDX-License-Identifier: Apache-2.0 */
/*
 * YUV4MPEG2 (.y4m) reader: the luma plane of each frame of a recording
 * (e.g. `ffmpeg -i clip.mp4 -pix_fmt gray clip.y4m`). 8-bit 4:2:0, 4:2:2,
 * 4:4:4 and mono; chroma is skipped. Host-only code.
 */
#ifndef SYMLINE_CAPTURE_Y4M_READER_H
#define SYMLINE_CAPTURE_Y4M_READER_H

#include <stddef.h>
#include <stdint.h>
#include <stdio.h>

typedef struct y4m_reader y4m_reader;

/* Opens path and reads its stream header; NULL with a message in err on failure. */
y4m_reader *y4m_open(const char *path, char *err, size_t errlen);

/* The same on an open stream (it must support fseek/ftell; the reader
 * closes it, also on failure); name is used in messages. */
y4m_reader *y4m_open_stream(FILE *f, const char *name, char *err, size_t errlen);

uint32_t y4m_width(const y4m_reader *r);
uint32_t y4m_height(const y4m_reader *r);

/* The frame rate of the header's F<num>:<den> tag: 0 with num and den set, -1 when it has none. */
int y4m_rate(const y4m_reader *r, uint32_t *num, uint32_t *den);

/* The path the reader was opened with. */
const char *y4m_path(const y4m_reader *r);

/*
 * Reads the next frame's luma into the reader's buffer (width*height bytes,
 * stride = width, valid until the next call). Returns 1 with *luma set, 0 at
 * the end of the stream, -1 with a message in err on a malformed or short frame.
 */
int y4m_read(y4m_reader *r, const uint8_t **luma, char *err, size_t errlen);

/* Goes back to the first frame; 0 or -1. */
int y4m_rewind(y4m_reader *r);

/* Closes the file and frees the reader (NULL is fine). */
void y4m_close(y4m_reader *r);

#endif

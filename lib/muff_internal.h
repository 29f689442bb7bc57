/* SPDX-License-Identifier: Apache-2.0 */
/*
 * Internal interfaces of the Muff-space line finder (muff.c, muff_vote.c,
 * muff_extent.c). Not part of the public API.
 */
#ifndef SYMLINE_MUFF_INTERNAL_H
#define SYMLINE_MUFF_INTERNAL_H

#include "symline/muff.h"
#include "common.h"

/* The frame's border as a perimeter cut into cells. */
typedef struct symline_i_perim {
    uint32_t w1, h1; /* width-1, height-1 */
    uint32_t len;    /* P = 2 w1 + 2 h1 */
    uint32_t cell;   /* px per cell */
    uint32_t ncell;  /* ceil(P / cell) */
} symline_i_perim;

/* One accumulator peak. */
typedef struct symline_i_peak {
    uint32_t index; /* j(j-1)/2 + i */
    uint16_t i, j;  /* cells, i < j */
    uint16_t votes;
} symline_i_peak;

/* A candidate line in its dominant-axis frame: u is x (horizontal-ish lines)
 * or y (vertical-ish), v the other coordinate, v(u) = v0 + slope16 * (u - u0) / 65536
 * with u0, v0 in Q8 px and u in Q8 px. */
typedef struct symline_i_uvline {
    int32_t u0, v0;
    int32_t slope16; /* dv/du in Q16, |slope16| <= 2^17 */
    uint8_t u_is_y;  /* 0: u = x, 1: u = y */
    uint32_t sec16;  /* sqrt(1 + slope^2) in Q16: perpendicular distance = |dv| / sec */
} symline_i_uvline;

/* muff_vote.c */
void symline_i_perim_setup(symline_i_perim *p, uint32_t width, uint32_t height, uint32_t cell);
/* Border point at perimeter coordinate s (0 <= s < len). */
void symline_i_perim_point(const symline_i_perim *p, uint32_t s, uint32_t *x, uint32_t *y);
/* Perimeter coordinate of a border point. */
uint32_t symline_i_perim_coord(const symline_i_perim *p, uint32_t x, uint32_t y);
/* Number of accumulator counters: ncell (ncell - 1) / 2 (as uint64_t). */
uint64_t symline_i_pair_count(const symline_i_perim *p);
/* Centre of every cell into cx[], cy[] (ncell entries each). */
void symline_i_cell_centres(const symline_i_perim *p, uint16_t *cx, uint16_t *cy);
/* Adds the votes of points pts[0..n-1] to acc (zeroed by the caller). */
void symline_i_muff_vote(const symline_i_perim *p, const uint16_t *cx, const uint16_t *cy,
                         const symline_point *pts, uint32_t n, uint16_t *acc);
/* The peaks (votes >= min_votes, beating their neighbourhood), strongest
 * first, at most cap of them; returns their number. */
uint32_t symline_i_muff_peaks(const symline_i_perim *p, const uint16_t *acc, uint32_t min_votes,
                              uint32_t nms, symline_i_peak *peaks, uint32_t cap);

/* muff_extent.c */
/* The line through two border points (full pixels). */
void symline_i_uvline_through(symline_i_uvline *l, uint32_t ax, uint32_t ay, uint32_t bx,
                              uint32_t by);

/* State of the segment extraction over the caller's point list. */
typedef struct symline_i_extent {
    symline_point *pts;
    uint32_t n;     /* points in the list */
    uint32_t used;  /* points [0, used) belong to segments already made */
    uint16_t *bins; /* one counter per u, max(width, height) of them */
    uint32_t width, height;
    const symline_muff_config *cfg;
    uint32_t tol_q8, gap; /* support distance and gap in use (auto resolved) */
    /* scratch of one peak, here rather than on the stack (firmware budget) */
    symline_i_uvline line, fit1, fit2;
    symline_segment spare; /* a segment that no longer fits the caller's array */
    uint32_t lo, hi;       /* u extent of the last gather */
} symline_i_extent;

/*
 * Gathers the unclaimed points within tol_q8 of line l along its longest run
 * without a gap above cfg->gap px: moves them to pts[used .. used+k-1] (not
 * claimed: used is unchanged), their u extent to e->lo, e->hi. Returns k, or
 * 0 when they are fewer than cfg->min_points or shorter than cfg->min_length.
 */
uint32_t symline_i_extent_gather(symline_i_extent *e, const symline_i_uvline *l, uint32_t tol_q8);

/* Least-squares fit (in l's frame) of the k gathered points. */
void symline_i_extent_fit(const symline_i_extent *e, uint32_t k, const symline_i_uvline *l,
                          symline_i_uvline *fit);

/* The segment of the k gathered points on line ft (ends at e->lo, e->hi). */
void symline_i_extent_segment(const symline_i_extent *e, const symline_i_uvline *ft, uint32_t k,
                              symline_segment *s);

#endif /* SYMLINE_MUFF_INTERNAL_H */

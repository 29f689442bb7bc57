/* SPDX-License-Identifier: Apache-2.0 */
/*
 * Line points of one pass (linepoints.c): the scale grid's rows (grid.c), the
 * line filter's byte test over each row, and at its few candidates the exact
 * filter, symmetry energies and the extremum with the plateau limit, streamed
 * over a ring of rows into a raster-ordered point list.
 */
#ifndef SYMLINE_LIB_LINEPOINTS_H
#define SYMLINE_LIB_LINEPOINTS_H

#include "common.h"
#include "grid.h"
#include "linefilter.h"
#include "symline/detect.h"

/* One pass: an axis at one scale. Coordinates of a pass are on its grid.
 * Filled by symline_i_pass_setup() (pass.c). */
typedef struct symline_i_pass {
    symline_axis axis;
    uint32_t level;        /* grid = frame box-downsampled by 2^level */
    uint32_t w, h;         /* grid size: width >> level, height >> level */
    uint32_t m;            /* radius */
    uint32_t k;            /* contrast sample offset across the line: m + 1 */
    uint32_t lag;          /* longest accepted plateau: end - marked index <= lag (= m) */
    uint32_t cache;        /* SL_CACHE_*: the grid rows' cache at the point storage's end */
    const uint16_t *field; /* NULL, or the first grid row each column keeps below
                              the field boundary (w entries, fieldboundary.h) */
    symline_i_linefilter filter;
#if SL_FOR_SPEED_DEEP
    symline_point *cache_end; /* where cache is not SL_CACHE_OFF: the storage's end */
#endif
} symline_i_pass;

/*
 * The grid row cache (SL_FOR_SPEED_DEEP: 64-bit speed builds). Every coarse
 * pass reads whole grid rows: both axes of a scale the same ones, and each
 * scale's rows follow from the sums of the scale below (grid.h). So, where
 * the point storage given to symline_i_collect() has the room, the coarse
 * scales' rows live at its end (pts + cap), each scale's rows one after the
 * other, at the scale's row stride w:
 *
 *   ... points ... | level 1 rows | level 2 rows | ... | level top rows | head
 *
 * head: SL_CACHE_HEAD bytes, from[level] (uint16_t) the first row of each
 * scale held (rows from[level] .. h-1 are; h: none yet). A pass reads its
 * rows there and builds the ones it needs that are not, in order, into
 * their place; the first coarse pass (level 1) folds the sums of the rows it
 * builds into the coarser scales' rows up to level `fold` as well. The
 * caller (pass.c) asks for it only where no point can reach those bytes
 * while they are needed: during a pass at level l the storage holds the
 * bytes of levels l .. top and the head (symline_i_cache_bytes()) above
 * twice w * h points after the points kept so far (a pass lists at most
 * w * h points and traces at most as many), and the grid of earlier segments
 * keeps below them. Where the storage is smaller (sized by points_needed,
 * say) each pass builds its rows from the frame into its ring as the size
 * builds do: the result is the same.
 *
 * symline_i_pass.cache: SL_CACHE_OFF, or top | fold << 4 (fold: 0, or the
 * coarsest level the pass's folding reaches, <= SL_CACHE_FOLD_MAX).
 */
#define SL_CACHE_OFF 0u
#define SL_CACHE_FOLD_MAX 4u /* level 4's sums fill 16 bits (256 * 255) */
#define SL_CACHE_HEAD ((SYMLINE_DETECT_MAX_LEVELS + 1u) * sizeof(uint16_t))
#define SL_CACHE_TOP(cache) ((cache)&15u)   /* the coarsest level held */
#define SL_CACHE_FOLD(cache) ((cache) >> 4) /* the coarsest level folded into; 0: none */

/* Bytes at the storage's end that levels `level` .. top of a width x height
 * frame take, with the head. */
static inline uint64_t symline_i_cache_bytes(uint32_t width, uint32_t height, uint32_t level,
                                             uint32_t top)
{
    uint64_t n = SL_CACHE_HEAD;
    for (; level <= top; level++) {
        n += (uint64_t)(width >> level) * (height >> level);
    }
    return n;
}

/* The head of the cache whose storage ends at end (2-byte aligned: points). */
static inline uint16_t *symline_i_cache_head(symline_point *end)
{
    return (uint16_t *)(void *)((uint8_t *)(void *)end - SL_CACHE_HEAD);
}

/* Level `level`'s rows in the cache of levels .. top whose storage ends at end. */
static inline uint8_t *symline_i_cache_rows(symline_point *end, uint32_t width, uint32_t height,
                                            uint32_t level, uint32_t top)
{
    return (uint8_t *)(void *)end - (size_t)symline_i_cache_bytes(width, height, level, top);
}

/* Workspace bytes of symline_i_collect() (row index excluded). */
size_t symline_i_collect_ws_size(const symline_i_pass *p, uint32_t img_width);

/*
 * The line points of one pass, in raster order, grid coordinates, written to
 * pts[0 .. *n-1] (at most cap); row_start[y] is the index of the first point
 * of grid row y, row_start[h] = *n (h+1 entries). Where p->field is set, row
 * y is decided only from the first to the last column that keeps it (the
 * caller drops the points above the field boundary), the rows above every
 * column's first kept row not at all; grid rows are still read as the rows
 * below them need. Adds to *dropped the line points that did not fit (cap
 * too small). Strip processing: only a ring of rows is held.
 * Returns SYMLINE_OK, SYMLINE_ERR_SIZE (empty grid) or SYMLINE_ERR_BUFFER
 * (ws_size below symline_i_collect_ws_size()).
 */
symline_status symline_i_collect(const symline_image *img, const symline_i_pass *p, void *ws,
                                 size_t ws_size, symline_point *pts, uint32_t cap, uint32_t *n,
                                 uint32_t *row_start, uint32_t *dropped);

/*
 * The decision of a block of SL_LANES_DOWN neighbouring entries of a
 * row down the columns at radius m = 3 (k = 4), for the candidates of the
 * byte test (linefilter.h) among them: the rest of the exact gray test, the
 * energies E(y-1), E(y), E(y+1) and the S decision (linepoints.c, speed
 * builds with vector lanes): sixteen, the compiler vectorises the byte
 * lanes of the portable loop at 16.
 */
#define SL_LANES_DOWN 16u

/* What symline_i_linefilter_gray() asks beyond the byte test, for 16-bit
 * lanes. The byte test is exact on min_gray <= 255 and side_max; of the
 * contrast it keeps c >= side + max(ridge_min, 1) only up to 255; the
 * percent tests c - side >= ceil(v * pct / 100) are, for integers,
 * 100 (c - side) >= v * pct: no division. */
typedef struct symline_i_lane_gray {
    int16_t ridge_min;  /* c - side >= this, 1 .. 256 (256: never) */
    uint16_t ridge_pct; /* <= 100 */
    uint16_t asym_pct;  /* <= 257: |lo - hi| * asym_pct fits 16 bits */
    uint16_t paper;     /* 1: the byte test is all */
} symline_i_lane_gray;

static inline uint16_t symline_i_lane_absdiff(uint8_t a, uint8_t b)
{
    const uint8_t hi = a > b ? a : b, lo = a > b ? b : a;
    return (uint8_t)(hi - lo);
}

/* The energy at m = 3 from the pairs' differences: 3 d1^2 + 2 d2^2 + d3^2
 * (the sum of partial sums of docs/algorithm.md), in 16 x 16 -> 32-bit
 * products, which SSE2 and NEON have (a 32-bit lane multiply SSE2 has not). */
static inline uint32_t symline_i_lane_energy(uint16_t d1, uint16_t d2, uint16_t d3)
{
    return (uint32_t)d1 * (uint16_t)(3u * d1) + (uint32_t)d2 * (uint16_t)(d2 + d2) +
           (uint32_t)d3 * d3;
}

/* 1 when an entry with gray values c, lo, hi that passed the byte test
 * passes the exact gray test, else 0. */
static inline uint16_t symline_i_lane_gray_ok(const symline_i_lane_gray *g, uint8_t c, uint8_t lo,
                                              uint8_t hi)
{
    const uint16_t side = lo > hi ? lo : hi;
    const int16_t t = (int16_t)(c - side); /* the ridge */
    const uint16_t t100 = (uint16_t)(100u * (uint16_t)t);
    return (uint16_t)(g->paper | ((uint16_t)(t >= g->ridge_min) &
                                  (uint16_t)(t100 >= (uint16_t)(c * g->ridge_pct)) &
                                  (uint16_t)(t100 >= (uint16_t)(symline_i_lane_absdiff(lo, hi) *
                                                                g->asym_pct))));
}

/* The code of an entry from its energies E(i-1), E(i), E(i+1) (< 2^31:
 * differences in signed 32 bits) and gray values c, lo, hi: 0 when it fails
 * the rest of the gray test or is no S point, 1 for an S point, 2 for a
 * plateau beside it that may still make one (the caller decides). Exact for
 * entries that passed the byte test; for the others only defined. */
static inline uint8_t symline_i_lane_code(int32_t up, int32_t e, int32_t dn, uint8_t c, uint8_t lo,
                                          uint8_t hi, const symline_i_lane_gray *g)
{
    const int32_t du = up - e, dd = dn - e;
    const uint16_t gray = symline_i_lane_gray_ok(g, c, lo, hi);
    /* both neighbours at least E(i): maybe S (g); both above: S; 2 g - (g & S)
     * without a 32-bit lane multiply */
    const uint8_t g8 = (uint8_t)(gray & (uint16_t)((du | dd) >= 0));
    const uint8_t s8 = (uint8_t)(((du - 1) | (dd - 1)) >= 0);
    return (uint8_t)(g8 + g8 - (g8 & s8));
}

/*
 * The codes (symline_i_lane_code()) of the SL_LANES_DOWN entries r[0 ..]
 * of a row whose columns run down r[i + j st], j = -4 .. 4, to code[0 ..]:
 * three energies per entry in a loop over the entries that the compiler
 * vectorises: the detector's speed builds with vector lanes and no
 * symline_i_cand_down() of a port use it (linepoints.c).
 */
static inline void symline_i_lanes_down_c(const uint8_t *r, ptrdiff_t st,
                                          const symline_i_lane_gray *g, uint8_t *restrict code)
{
    const uint8_t *restrict m4 = r - 4 * st, *restrict m3 = r - 3 * st, *restrict m2 = r - 2 * st;
    const uint8_t *restrict m1 = r - st, *restrict p0 = r, *restrict p1 = r + st;
    const uint8_t *restrict p2 = r + 2 * st, *restrict p3 = r + 3 * st, *restrict p4 = r + 4 * st;
    const symline_i_lane_gray gl = *g;
    uint32_t i;
    for (i = 0; i < SL_LANES_DOWN; i++) {
        const int32_t up = (int32_t)symline_i_lane_energy(symline_i_lane_absdiff(m2[i], p0[i]),
                                                          symline_i_lane_absdiff(m3[i], p1[i]),
                                                          symline_i_lane_absdiff(m4[i], p2[i]));
        const int32_t e = (int32_t)symline_i_lane_energy(symline_i_lane_absdiff(m1[i], p1[i]),
                                                         symline_i_lane_absdiff(m2[i], p2[i]),
                                                         symline_i_lane_absdiff(m3[i], p3[i]));
        const int32_t dn = (int32_t)symline_i_lane_energy(symline_i_lane_absdiff(p0[i], p2[i]),
                                                          symline_i_lane_absdiff(m1[i], p3[i]),
                                                          symline_i_lane_absdiff(m2[i], p4[i]));
        code[i] = symline_i_lane_code(up, e, dn, p0[i], m4[i], p4[i], &gl);
    }
}
/* The S decision of entry p[0] down its column at m = 3 (rows p[j st],
 * j = -4 .. 4), past its gray test: 1 an S point, 2 a plateau (the run rule
 * decides), 0 neither. The energies from the nine values' signed
 * differences, once each: for candidates decided one at a time. */
static inline uint32_t symline_i_s3_down(const uint8_t *p, ptrdiff_t st)
{
    const int32_t m4 = p[-4 * st], m3 = p[-3 * st], m2 = p[-2 * st], m1 = p[-st], c0 = p[0];
    const int32_t p1 = p[st], p2 = p[2 * st], p3 = p[3 * st], p4 = p[4 * st];
    const int32_t u1 = m2 - c0, u2 = m3 - p1, u3 = m4 - p2;
    const int32_t e1 = m1 - p1, e2 = m2 - p2, e3 = m3 - p3;
    const int32_t d1 = c0 - p2, d2 = m1 - p3, d3 = m2 - p4;
    const int32_t up = 3 * u1 * u1 + 2 * u2 * u2 + u3 * u3;
    const int32_t e = 3 * e1 * e1 + 2 * e2 * e2 + e3 * e3;
    const int32_t dn = 3 * d1 * d1 + 2 * d2 * d2 + d3 * d3;
    return up < e || dn < e ? 0u : (up > e && dn > e ? 1u : 2u);
}

/* The code (symline_i_lane_code()) of entry r[0] of a row whose column runs
 * down r[j st], j = -4 .. 4: one entry of symline_i_lanes_down_c(). */
static inline uint32_t symline_i_lane_code_down(const uint8_t *r, ptrdiff_t st,
                                                const symline_i_lane_gray *g)
{
    return symline_i_lane_gray_ok(g, r[0], r[-4 * st], r[4 * st]) != 0u ? symline_i_s3_down(r, st)
                                                                        : 0u;
}

/*
 * The byte test (symline_i_line_cand_c(), linefilter.h) and the codes of
 * the entries that pass it, in one call, for a row whose columns run down
 * c[x + j st], j = -4 .. 4 (each entry that passes the byte test, rows
 * y - 4 .. y + 4 in the frame), sides lo[], hi[] as for the byte test: of
 * entries x .. n-1, those that pass and whose code (symline_i_lane_code())
 * is not 0 go to out[0 ..] in order (at most SL_LINE_CAND_MAX), returns
 * how many; bit i of *plateau set where kept entry i has code 2; *next:
 * where to go on (n: the row is done; the call stops early when out may
 * fill). symline_i_cand_down_c() is the portable reference (test only);
 * a port's version (SYMLINE_PORT_CAND_DOWN, CMake option SYMLINE_SIMD)
 * decides the byte test's entries in groups from its masks, with no list
 * of candidates in between, and the detector's speed builds with it use it
 * down the columns (linepoints.c).
 */
static inline uint32_t symline_i_cand_down_c(const symline_i_prefilter *pf,
                                             const symline_i_lane_gray *g, const uint8_t *c,
                                             const uint8_t *lo, const uint8_t *hi, ptrdiff_t st,
                                             uint32_t x, uint32_t n, uint16_t *out,
                                             uint64_t *plateau, uint32_t *next)
{
    const uint32_t k = symline_i_line_cand_c(pf, c, lo, hi, x, n, out, next);
    uint32_t i, kept = 0u;
    uint64_t pl = 0u;
    for (i = 0; i < k; i++) {
        const uint32_t code = symline_i_lane_code_down(c + out[i], st, g);
        out[kept] = out[i];
        pl |= (uint64_t)(code >> 1) << kept;
        kept += code != 0u ? 1u : 0u;
    }
    *plateau = pl;
    return kept;
}
#ifdef SYMLINE_PORT_CAND_DOWN
uint32_t symline_i_cand_down(const symline_i_prefilter *pf, const symline_i_lane_gray *g,
                             const uint8_t *c, const uint8_t *lo, const uint8_t *hi, ptrdiff_t st,
                             uint32_t x, uint32_t n, uint16_t *out, uint64_t *plateau,
                             uint32_t *next);
#endif

/*
 * The S decision of a candidate along a row at radius m = 3 (k = 4), from
 * the energies E(i-1), E(i), E(i+1) of entry p[0], which reads p[-4 .. 4]:
 * 1 where both neighbours' energies exceed E(i) (an S point), 2 where
 * neither is below it and one equals it (a plateau: the run rule of
 * linepoints.c decides), else 0 (one is below: no run of equal energies
 * through i can make it a minimum).
 */
static inline uint32_t symline_i_s_along3_c(const uint8_t *p)
{
    const uint32_t up = symline_i_lane_energy(symline_i_lane_absdiff(p[-2], p[0]),
                                              symline_i_lane_absdiff(p[-3], p[1]),
                                              symline_i_lane_absdiff(p[-4], p[2]));
    const uint32_t e = symline_i_lane_energy(symline_i_lane_absdiff(p[-1], p[1]),
                                             symline_i_lane_absdiff(p[-2], p[2]),
                                             symline_i_lane_absdiff(p[-3], p[3]));
    const uint32_t dn = symline_i_lane_energy(symline_i_lane_absdiff(p[0], p[2]),
                                              symline_i_lane_absdiff(p[-1], p[3]),
                                              symline_i_lane_absdiff(p[-2], p[4]));
    return up < e || dn < e ? 0u : (up > e && dn > e ? 1u : 2u);
}

/*
 * The candidates x = cand[0 .. k-1] (k <= SL_LINE_CAND_MAX, each with
 * row[x - 4 .. x + 4] in the row) whose code symline_i_s_along3_c(row + x)
 * is not 0, kept in cand[0 ..] in order; returns how many, and sets bit i
 * of *plateau where kept entry i has code 2. symline_i_s_along3_keep_c()
 * is the portable reference; a port's version (SYMLINE_PORT_S_ALONG3, CMake
 * option SYMLINE_SIMD) does the same with the three energies in vector
 * lanes, where the scalar ones take nine products and eighteen loads; the
 * detector's speed builds with such a port use it (linepoints.c), the
 * others compute the energies one candidate at a time.
 */
static inline uint32_t symline_i_s_along3_keep_c(const uint8_t *row, uint16_t *cand, uint32_t k,
                                                 uint64_t *plateau)
{
    uint32_t i, ks = 0u;
    uint64_t pl = 0u;
    for (i = 0; i < k; i++) {
        const uint32_t x = cand[i], code = symline_i_s_along3_c(row + x);
        cand[ks] = (uint16_t)x;
        pl |= (uint64_t)(code >> 1) << ks;
        ks += code != 0u ? 1u : 0u;
    }
    *plateau = pl;
    return ks;
}
#ifdef SYMLINE_PORT_S_ALONG3
uint32_t symline_i_s_along3_keep(const uint8_t *row, uint16_t *cand, uint32_t k, uint64_t *plateau);
#else
#define symline_i_s_along3_keep symline_i_s_along3_keep_c
#endif

#endif /* SYMLINE_LIB_LINEPOINTS_H */

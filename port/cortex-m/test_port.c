/* SPDX-License-Identifier: Apache-2.0 */
/*
 * The optional SIMD versions of hot loops in port/ (on Cortex-M4/M7, the
 * ARMv7E-M DSP versions of port/armv7em/) against the portable references
 * of lib/, on the target: the same output for random and extreme gray
 * values, every alignment of the rows, radii and widths around the blocks
 * of the SIMD loops. Built into the target tests (test_core.c); without port
 * versions in the build it checks nothing and says so.
 */
#include <stdint.h>
#include <string.h>

#include "fwtest.h"
#include "test_port.h"

#ifdef SYMLINE_PORT_ENERGY
#include "symmetry.h"
#endif
#ifdef SYMLINE_PORT_GRID
#include "linepoints.h"
#endif
#ifdef SYMLINE_PORT_EXTREMA_ROWS
#include "extrema.h"
#endif
#ifdef SYMLINE_PORT_LINE_CAND
#include "linefilter.h"
#endif

#if defined(SYMLINE_PORT_ENERGY) || defined(SYMLINE_PORT_GRID) ||                                  \
    defined(SYMLINE_PORT_EXTREMA_ROWS) || defined(SYMLINE_PORT_LINE_CAND)
static uint32_t rng_state = 12345u;

static uint8_t rnd8(void)
{
    rng_state = rng_state * 1664525u + 1013904223u;
    return (uint8_t)(rng_state >> 24);
}

/* Random gray values; every fourth fill only 0 and 255 (largest differences). */
static void fill_gray(uint8_t *g, uint32_t n, unsigned round)
{
    uint32_t i;
    for (i = 0; i < n; i++) {
        const uint8_t v = rnd8();
        g[i] = (round % 4u == 3u) ? (uint8_t)((v & 1u) ? 255u : 0u) : v;
    }
}
#endif

#ifdef SYMLINE_PORT_ENERGY
#define PT_ROW 400u
static uint8_t pt_gray[PT_ROW + 8u];
static uint8_t pt_rows[2u * 130u + 1u][72u];
static uint32_t pt_e1[PT_ROW], pt_e2[PT_ROW];

static void energy_checks(void)
{
    static const uint32_t radii[] = {1u, 2u, 3u, 4u, 5u, 7u, 10u, 32u, 128u, 129u, 255u};
    static const uint32_t lens[] = {1u,  2u,  3u,  5u,  7u,  8u,  9u,   15u,  16u, 17u,
                                    22u, 23u, 24u, 25u, 40u, 67u, 161u, 320u, 400u};
    unsigned r, l, off, round = 0u;
    const uint8_t *rows[2u * 130u + 1u];
    for (r = 0; r < sizeof radii / sizeof radii[0]; r++) {
        const uint32_t m = radii[r];
        for (l = 0; l < sizeof lens / sizeof lens[0]; l++) {
            const uint32_t n = lens[l];
            for (off = 0; off < 4u; off++, round++) {
                uint32_t i, j;
                fill_gray(pt_gray, PT_ROW + 8u, round);
                symline_i_energy_row(pt_gray + off, n, m, pt_e1);
                symline_i_energy_row_c(pt_gray + off, n, m, pt_e2);
                FW_CHECK(memcmp(pt_e1, pt_e2, n * sizeof(uint32_t)) == 0,
                         "energy row m=%lu n=%lu offset %u", (unsigned long)m, (unsigned long)n,
                         off);
                if (m > 130u || n > 64u) {
                    continue;
                }
                /* Across: a window of 2m+1 rows, the first `off` rows and,
                 * every other round, the last ones outside the image. */
                for (j = 0; j <= 2u * m; j++) {
                    fill_gray(pt_rows[j], 72u, round);
                    rows[j] = pt_rows[j] + off;
                }
                for (i = 0; i < off && i < m; i++) {
                    rows[i] = NULL;
                    if (round % 2u == 1u) {
                        rows[2u * m - i] = NULL;
                    }
                }
                symline_i_energy_across(rows, m, n, pt_e1);
                symline_i_energy_across_c(rows, m, n, pt_e2);
                FW_CHECK(memcmp(pt_e1, pt_e2, n * sizeof(uint32_t)) == 0,
                         "energy across m=%lu width=%lu offset %u", (unsigned long)m,
                         (unsigned long)n, off);
            }
        }
    }
}
#endif

#ifdef SYMLINE_PORT_GRID
#define PT_W 83u
#define PT_H 70u
#define PT_STRIDE 88u
static uint8_t pt_img[PT_STRIDE * PT_H + 4u];
static uint16_t pt_acc[PT_W];
static uint8_t pt_g1[PT_W], pt_g2[PT_W], pt_t1[PT_W];

static void grid_checks(void)
{
    unsigned level, round, off;
    for (round = 0; round < 8u; round++) {
        for (off = 0; off < 4u; off++) {
            for (level = 1u; level <= 4u; level++) {
                /* widths cut the rows at every remainder of the 4-output steps */
                const uint32_t width = PT_W - off - 3u * (round % 4u);
                const symline_image img = {width, PT_H, PT_STRIDE, pt_img + off};
                symline_i_pass p;
                uint32_t y;
                memset(&p, 0, sizeof p);
                p.level = level;
                p.w = width >> level;
                p.h = PT_H >> level;
                fill_gray(pt_img, sizeof pt_img, round);
                for (y = 0; y < p.h; y++) {
                    symline_i_grid_row(&img, &p, y, pt_acc, pt_g1, NULL);
                    symline_i_grid_row_c(&img, &p, y, pt_acc, pt_g2, NULL);
                    FW_CHECK(memcmp(pt_g1, pt_g2, p.w) == 0, "grid row %lu level %u width %lu",
                             (unsigned long)y, level, (unsigned long)width);
                    /* written twice (the ring down the columns) */
                    memset(pt_g1, 0, sizeof pt_g1);
                    memset(pt_t1, 0, sizeof pt_t1);
                    symline_i_grid_row(&img, &p, y, pt_acc, pt_g1, pt_t1);
                    FW_CHECK(memcmp(pt_g1, pt_g2, p.w) == 0 && memcmp(pt_t1, pt_g2, p.w) == 0,
                             "grid row twice %lu level %u width %lu", (unsigned long)y, level,
                             (unsigned long)width);
                }
            }
        }
    }
}
#endif

#ifdef SYMLINE_PORT_EXTREMA_ROWS
#define PT_N 150u
static uint32_t pt_mid[PT_N + 2u], pt_dn[PT_N];
static uint8_t pt_k1[PT_N], pt_k2[PT_N];
static int8_t pt_s1[PT_N], pt_s2[PT_N];
static uint32_t pt_w1[SL_KINDS_WORDS], pt_w2[SL_KINDS_WORDS];

/* Energies from a few values only (plateaus everywhere) or from the whole
 * range below 2^31 (differences of either sign up to 2^31 - 1). */
static uint32_t rnd_energy(unsigned round)
{
    uint32_t v = (uint32_t)rnd8() << 23 | (uint32_t)rnd8() << 15 | (uint32_t)rnd8() << 7 | rnd8();
    v &= 0x7fffffffu;
    return (round % 3u == 0u) ? v % 3u : (round % 3u == 1u) ? v % 40u : v;
}

/* Along a row and down the columns (signs -1, 0, +1 to the row above), the
 * maps, the plateau masks, their OR and the next row's signs. */
static void rows_checks(void)
{
    unsigned round;
    for (round = 0; round < 60u; round++) {
        uint32_t n, i;
        for (i = 0; i < PT_N; i++) {
            pt_dn[i] = rnd_energy(round);
            pt_mid[i] = rnd_energy(round);
            pt_s1[i] = pt_s2[i] = (int8_t)(rnd8() % 3u) - 1;
        }
        pt_mid[PT_N] = rnd_energy(round);
        pt_mid[PT_N + 1u] = rnd_energy(round);
        for (n = 1u; n <= PT_N && n <= SL_KINDS_MAX; n += 1u + n / 8u) {
            uint32_t f1, f2;
            memset(pt_w1, 0xa5, sizeof pt_w1);
            memset(pt_w2, 0xa5, sizeof pt_w2);
            f1 = symline_i_extrema_along(pt_mid + 1, n, pt_k1, pt_w1);
            f2 = symline_i_extrema_along_c(pt_mid + 1, n, pt_k2, pt_w2);
            FW_CHECK(memcmp(pt_k1, pt_k2, n) == 0 && f1 == f2 &&
                         memcmp(pt_w1, pt_w2, 4u * ((n + 31u) / 32u)) == 0,
                     "extrema along a row, n=%lu round %u", (unsigned long)n, round);
            f1 = symline_i_extrema_across(pt_mid, pt_dn, pt_s1, n, pt_k1, pt_w1);
            f2 = symline_i_extrema_across_c(pt_mid, pt_dn, pt_s2, n, pt_k2, pt_w2);
            FW_CHECK(memcmp(pt_k1, pt_k2, n) == 0 && f1 == f2 &&
                         memcmp(pt_w1, pt_w2, 4u * ((n + 31u) / 32u)) == 0 &&
                         memcmp(pt_s1, pt_s2, n) == 0,
                     "extrema down the columns, n=%lu round %u", (unsigned long)n, round);
        }
    }
}
#endif

#ifdef SYMLINE_PORT_LINE_CAND
#define PT_M 100u
static uint8_t pt_c[PT_M + 4u], pt_lo[PT_M + 4u], pt_hi[PT_M + 4u];

/* Rows of gray values near each other (every test a close call), anywhere,
 * or only 0 and 255. */
static void fill_rows(unsigned round)
{
    const uint32_t base = rnd8(), spread = 1u + rnd8() % 48u;
    uint32_t i;
    for (i = 0; i < PT_M + 4u; i++) {
        uint8_t *g[3] = {pt_c, pt_lo, pt_hi};
        unsigned j;
        for (j = 0; j < 3u; j++) {
            const uint32_t v = round % 3u == 0u   ? rnd8()
                               : round % 3u == 1u ? ((rnd8() & 1u) ? 255u : 0u)
                                                  : base + rnd8() % spread;
            g[j][i] = (uint8_t)(v < 255u ? v : 255u);
        }
    }
}

/* Both filters' thresholds as symline_i_prefilter_setup() makes them, from
 * 0 to beyond a byte's range. */
static void pick_prefilter(symline_i_prefilter *pf, unsigned round)
{
    static const uint32_t limits[] = {0u, 1u, 2u, 17u, 100u, 200u, 254u, 255u, 256u, 1000u};
    symline_i_linefilter f;
    memset(&f, 0, sizeof f);
    f.kind = (round % 4u == 0u) ? SYMLINE_FILTER_PAPER : SYMLINE_FILTER_CONTRAST;
    f.min_gray = rnd8() % 2u ? limits[rnd8() % 10u] : rnd8() % 160u;
    f.ridge_min = rnd8() % 2u ? limits[rnd8() % 10u] : rnd8() % 24u;
    f.side_max = rnd8() % 2u ? limits[rnd8() % 10u] : 255u - rnd8() % 64u;
    symline_i_prefilter_setup(&f, pf);
}

/* The same count, indices and resumption point as the reference for every
 * start x of rows of every length up to PT_M at every alignment, and no
 * write past the count. The paper filter gets lo = hi = c, as the detector
 * calls it. */
static void line_cand_checks(void)
{
    unsigned round;
    for (round = 0; round < 24u; round++) {
        const uint32_t off = round % 4u;
        const int paper = round % 4u == 0u;
        const uint8_t *c = pt_c + off, *lo = paper ? c : pt_lo + (round / 4u) % 4u,
                      *hi = paper ? c : pt_hi + 3u - off;
        symline_i_prefilter pf;
        uint32_t n, x;
        pick_prefilter(&pf, round);
        fill_rows(round);
        for (n = 0; n <= PT_M; n++) {
            unsigned bad = 0u;
            for (x = 0; x <= n; x++) {
                uint16_t a[SL_LINE_CAND_MAX + 1u], b[SL_LINE_CAND_MAX + 1u];
                uint32_t na = 0xfffu, nb = 0xeeeu, ka, kb;
                memset(a, 0x5a, sizeof a);
                memset(b, 0x5a, sizeof b);
                ka = symline_i_line_cand(&pf, c, lo, hi, x, n, a, &na);
                kb = symline_i_line_cand_c(&pf, c, lo, hi, x, n, b, &nb);
                bad += ka != kb || na != nb || memcmp(a, b, sizeof a) != 0;
            }
            FW_CHECK(bad == 0u, "line candidates n=%lu round %u: %u starts differ",
                     (unsigned long)n, round, bad);
        }
    }
}
#endif

void fw_port_checks(void)
{
    const unsigned before = fw_checks;
#ifdef SYMLINE_PORT_ENERGY
    energy_checks();
#endif
#ifdef SYMLINE_PORT_GRID
    grid_checks();
#endif
#ifdef SYMLINE_PORT_EXTREMA_ROWS
    rows_checks();
#endif
#ifdef SYMLINE_PORT_LINE_CAND
    line_cand_checks();
#endif
    printf("port versions against the portable references: %u checks\n", fw_checks - before);
}

/* SPDX-License-Identifier: Apache-2.0 */
/*
 * What the operator's SIMD row bodies (symline_i_energy_row() and
 * symline_i_energy_across(), lib/symmetry.h) share whatever the instruction
 * set: the pairs of offsets each pass over a row sums in registers, the
 * entries at the row's ends, and the scalar tail. Included once by each SIMD
 * version (x86/symmetry_sse2.c, arm/symmetry_neon.c), which defines
 * SL_PORT_RADIUS_MAX before it (larger radii take the portable reference)
 * and run_pass() after it.
 */
#ifndef SYMLINE_PORT_SYMMETRY_ROWS_H
#define SYMLINE_PORT_SYMMETRY_ROWS_H

#include <stddef.h>

#include "symmetry.h"

/* 255^2: the squared difference counted for a pair that leaves the image. */
#define SL_DMAX2 65025u
/* Pairs summed in registers per pass over a row: the detector's radius 3
 * needs one pass; larger radii add further passes onto the stored sums. Four
 * keep the eight row pointers in registers. */
#define SL_PASS_PAIRS 4u

/* The pairs of one pass: pair p compares lo[p][x] with hi[p][x] at weight w[p]. */
typedef struct sl_pass {
    const uint8_t *lo[SL_PASS_PAIRS];
    const uint8_t *hi[SL_PASS_PAIRS];
    uint32_t w[SL_PASS_PAIRS];
    uint32_t n; /* pairs, 1..SL_PASS_PAIRS */
} sl_pass;

/*
 * One pass over a row, defined by the SIMD version: E[x] = base[x] + the sum
 * of the first np pairs of ps for x < count, base[x] = init on the first
 * pass over a row (add 0), E[x] itself on later ones (add 1). np and add are
 * constants where it is inlined (do_pass()).
 */
static inline __attribute__((always_inline)) void
run_pass(const sl_pass *ps, uint32_t np, uint32_t count, uint32_t init, int add, uint32_t *E);

/* Entries x0 .. count-1 of a pass one at a time (a row's last few). */
static inline void pass_tail(const sl_pass *ps, uint32_t np, size_t x0, uint32_t count,
                             uint32_t init, int add, uint32_t *E)
{
    size_t x;
    uint32_t p;
    for (x = x0; x < count; x++) {
        uint32_t e = add ? E[x] : init;
        for (p = 0; p < np; p++) {
            const int32_t d = (int32_t)ps->lo[p][x] - (int32_t)ps->hi[p][x];
            e += ps->w[p] * (uint32_t)(d * d);
        }
        E[x] = e;
    }
}

/* One pass with its pair count and mode as constants. */
static void do_pass(const sl_pass *ps, uint32_t count, uint32_t init, int add, uint32_t *E)
{
    switch (ps->n * 2u + (add ? 1u : 0u)) {
    case 2: run_pass(ps, 1u, count, init, 0, E); break;
    case 3: run_pass(ps, 1u, count, init, 1, E); break;
    case 4: run_pass(ps, 2u, count, init, 0, E); break;
    case 5: run_pass(ps, 2u, count, init, 1, E); break;
    case 6: run_pass(ps, 3u, count, init, 0, E); break;
    case 7: run_pass(ps, 3u, count, init, 1, E); break;
    case 8: run_pass(ps, 4u, count, init, 0, E); break;
    default: run_pass(ps, 4u, count, init, 1, E); break;
    }
}

/* Adds pair (a, b) at weight w to the pass; runs it over E when full. */
static void push_pair(sl_pass *ps, const uint8_t *a, const uint8_t *b, uint32_t w, uint32_t count,
                      uint32_t init, int *add, uint32_t *E)
{
    ps->lo[ps->n] = a;
    ps->hi[ps->n] = b;
    ps->w[ps->n] = w;
    if (++ps->n == SL_PASS_PAIRS) {
        do_pass(ps, count, init, *add, E);
        ps->n = 0u;
        *add = 1;
    }
}

/* Runs what is left of the pass; a row without any pair is init throughout. */
static void finish(const sl_pass *ps, uint32_t count, uint32_t init, int add, uint32_t *E)
{
    uint32_t x;
    if (ps->n > 0u) {
        do_pass(ps, count, init, add, E);
    } else if (!add) {
        for (x = 0; x < count; x++) {
            E[x] = init;
        }
    }
}

/* The m entries at either end of a row of n >= 2m, where pairs leave the
 * row: each beyond-the-end pair counts 255^2 (lib/symmetry.c). Both ends in
 * one loop: entry k and its mirror n-1-k share the pairs' weights. */
static void row_ends(const uint8_t *q, uint32_t n, uint32_t m, uint32_t *E)
{
    uint32_t k, j;
    for (k = 0; k < m; k++) {
        const uint32_t t = m - k;
        const uint8_t *ql = q + k, *qr = q + (n - 1u - k);
        uint32_t el = SL_DMAX2 * (t * (t + 1u) / 2u), er = el;
        for (j = 1u; j <= k; j++) {
            const int32_t dl = (int32_t)ql[-(ptrdiff_t)j] - (int32_t)ql[j];
            const int32_t dr = (int32_t)qr[-(ptrdiff_t)j] - (int32_t)qr[j];
            el += (m + 1u - j) * (uint32_t)(dl * dl);
            er += (m + 1u - j) * (uint32_t)(dr * dr);
        }
        E[k] = el;
        E[n - 1u - k] = er;
    }
}

void symline_i_energy_row(const uint8_t *q, uint32_t n, uint32_t m, uint32_t *E)
{
    sl_pass ps;
    int add = 0;
    uint32_t j;
    const uint8_t *c;
    if (m > SL_PORT_RADIUS_MAX || n < 2u * m + 16u) {
        symline_i_energy_row_c(q, n, m, E);
        return;
    }
    row_ends(q, n, m, E);
    /* The interior m .. n-1-m, where every pair lies in the row. */
    c = q + m;
    ps.n = 0u;
    for (j = 1u; j <= m; j++) {
        push_pair(&ps, c - j, c + j, m + 1u - j, n - 2u * m, 0u, &add, E + m);
    }
    finish(&ps, n - 2u * m, 0u, add, E + m);
}

void symline_i_energy_across(const uint8_t *const *rows, uint32_t m, uint32_t width, uint32_t *E)
{
    sl_pass ps;
    int add = 0;
    uint32_t j, border = 0u;
    if (m > SL_PORT_RADIUS_MAX) {
        symline_i_energy_across_c(rows, m, width, E);
        return;
    }
    /* A pair with a partner outside the image adds the same 255^2 to every column. */
    for (j = 1u; j <= m; j++) {
        if (rows[m - j] == NULL || rows[m + j] == NULL) {
            border += (m + 1u - j) * SL_DMAX2;
        }
    }
    ps.n = 0u;
    for (j = 1u; j <= m; j++) {
        if (rows[m - j] != NULL && rows[m + j] != NULL) {
            push_pair(&ps, rows[m - j], rows[m + j], m + 1u - j, width, border, &add, E);
        }
    }
    finish(&ps, width, border, add, E);
}

#endif /* SYMLINE_PORT_SYMMETRY_ROWS_H */

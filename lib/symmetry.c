/* SPDX-License-Identifier: Apache-2.0 */
/*
 * The reflective symmetry operator: exact energies E and the 8-bit image S8.
 *
 * Loops run over whole rows with the pair offset j outside, so the inner
 * loop is a plain lane-wise multiply-accumulate the compiler vectorises
 * (uint8 loads widened to 32-bit lanes).
 */
#include "symmetry.h"

/*
 * The row bodies of symline_energy_row() and symline_energy_across(). With a
 * SIMD version from port/ (SYMLINE_PORT_ENERGY) the portable ones are the
 * exported references symline_i_energy_*_c() and the SIMD ones are called;
 * otherwise they are static, called once and inlined, so scalar cores build
 * exactly the code they had.
 */
#ifdef SYMLINE_PORT_ENERGY
#define SL_ENERGY_REF
#define SL_ENERGY_ROW_REF symline_i_energy_row_c
#define SL_ENERGY_ACROSS_REF symline_i_energy_across_c
#define SL_ENERGY_ROW symline_i_energy_row
#define SL_ENERGY_ACROSS symline_i_energy_across
#else
#define SL_ENERGY_REF static
#define SL_ENERGY_ROW_REF energy_row
#define SL_ENERGY_ACROSS_REF energy_across
#define SL_ENERGY_ROW energy_row
#define SL_ENERGY_ACROSS energy_across
#endif

/* 255^2: the squared difference counted for a pair that leaves the image. */
#define SL_DMAX2 65025u

/* sum_{j=1..t} j * 255^2: the energy of t pairs of weights 1..t that differ
 * by 255 (a pair that leaves the image counts as such): Emax for t = m, and
 * what the pairs beyond the border add at m - t pixels from the nearer end. */
static uint32_t border_energy(uint32_t t)
{
    return SL_DMAX2 * (t * (t + 1u) / 2u);
}

uint32_t symline_emax(uint32_t m)
{
    if (symline_i_check_radius(m) != SYMLINE_OK) {
        return 0u;
    }
    return border_energy(m);
}

/* Distance of index i to the nearer end of 0..n-1. */
static uint32_t edge_distance(uint32_t i, uint32_t n)
{
    return i < n - 1u - i ? i : n - 1u - i;
}

/* E[x] += w * (a[x] - b[x])^2 over a row; the vectorised hot loop. Where the
 * compiler has vector lanes (SSE2, NEON) in 16-bit lanes up to the last
 * multiply: |d| and w * |d| <= 255 * 255 fit 16 bits, and |d| * (w * |d|) is a
 * widening 16 x 16 -> 32-bit multiply, which SSE2 and NEON have (a 32-bit
 * lane multiply SSE2 has not). Scalar cores (Cortex-M) keep the plain form,
 * which is shorter there. Out of line: the row and the two across sums share
 * one copy; the call is per pair offset, not per pixel. */
SL_NOINLINE static void add_pair(const uint8_t *a, const uint8_t *b, uint32_t w, uint32_t count,
                                 uint32_t *E)
{
    uint32_t x;
#if defined(__SSE2__) || defined(__ARM_NEON) || defined(__ARM_NEON__)
    const uint16_t w16 = (uint16_t)w; /* pair weight m + 1 - j <= 255 */
    for (x = 0; x < count; x++) {
        const uint16_t d = (uint16_t)(a[x] > b[x] ? a[x] - b[x] : b[x] - a[x]);
        const uint16_t wd = (uint16_t)(w16 * d);
        E[x] += (uint32_t)d * wd;
    }
#else
    for (x = 0; x < count; x++) {
        int32_t d = (int32_t)a[x] - (int32_t)b[x];
        E[x] += w * (uint32_t)(d * d);
    }
#endif
}

static void fill(uint32_t *E, uint32_t count, uint32_t value)
{
    uint32_t x;
    for (x = 0; x < count; x++) {
        E[x] = value;
    }
}

/* The portable body of symline_energy_row(), on checked arguments. */
SL_ENERGY_REF void SL_ENERGY_ROW_REF(const uint8_t *q, uint32_t n, uint32_t m, uint32_t *E)
{
    uint32_t i, j;
    /*
     * Border term: pairs j > min(i, n-1-i) leave the row, so it is nonzero only
     * within m pixels of either end; the middle starts at 0. Index i and its
     * mirror n-1-i share the distance i up to the middle (2i < n).
     */
    fill(E, n, 0u);
    for (i = 0; i < m && 2u * i < n; i++) {
        E[i] = E[n - 1u - i] = border_energy(m - i);
    }
    /* In-image pairs: for offset j, indices j .. n-1-j have both partners. */
    for (j = 1u; j <= m && 2u * j < n; j++) {
        add_pair(q, q + (size_t)2u * j, m + 1u - j, n - 2u * j, E + j);
    }
}

symline_status symline_energy_row(const uint8_t *q, uint32_t n, uint32_t m, uint32_t *E)
{
    if (q == NULL || E == NULL) {
        return SYMLINE_ERR_NULL;
    }
    if (n == 0u || n > SYMLINE_MAX_DIM) {
        return SYMLINE_ERR_SIZE;
    }
    if (symline_i_check_radius(m) != SYMLINE_OK) {
        return SYMLINE_ERR_RADIUS;
    }
    SL_ENERGY_ROW(q, n, m, E);
    return SYMLINE_OK;
}

/*
 * The rows a and b of pair j (1..m) of a sum across: from the window
 * rows[0..2m] (NULL outside the image), or, rows NULL, from the frame img
 * around its row y. False when a partner lies outside the image.
 */
static bool pair_rows(const uint8_t *const *rows, const symline_image *img, uint32_t y, uint32_t m,
                      uint32_t j, const uint8_t **a, const uint8_t **b)
{
    if (rows != NULL) {
        *a = rows[m - j];
        *b = rows[m + j];
        return *a != NULL && *b != NULL;
    }
    if (j > edge_distance(y, img->height)) {
        return false;
    }
    *a = img->data + (size_t)(y - j) * img->stride;
    *b = img->data + (size_t)(y + j) * img->stride;
    return true;
}

/* The sum across, with the rows as pair_rows() takes them: the body of
 * symline_energy_across() and symline_energy_across_image(). */
static void across(const uint8_t *const *rows, const symline_image *img, uint32_t y, uint32_t m,
                   uint32_t width, uint32_t *E)
{
    uint32_t j, border = 0u;
    const uint8_t *a, *b;
    fill(E, width, 0u);
    for (j = 1u; j <= m; j++) {
        if (pair_rows(rows, img, y, m, j, &a, &b)) {
            add_pair(a, b, m + 1u - j, width, E);
        } else {
            border += (m + 1u - j) * SL_DMAX2;
        }
    }
    /* A pair with a partner outside the image adds the same 255^2 to every
     * column; only rows within m of the top or bottom have such pairs. */
    if (border != 0u) {
        uint32_t x;
        for (x = 0; x < width; x++) {
            E[x] += border;
        }
    }
}

/* The portable body of symline_energy_across(), on checked arguments. */
SL_ENERGY_REF void SL_ENERGY_ACROSS_REF(const uint8_t *const *rows, uint32_t m, uint32_t width,
                                        uint32_t *E)
{
    across(rows, NULL, 0u, m, width, E);
}

symline_status symline_energy_across(const uint8_t *const *rows, uint32_t m, uint32_t width,
                                     uint32_t *E)
{
    if (rows == NULL || E == NULL) {
        return SYMLINE_ERR_NULL;
    }
    if (symline_i_check_radius(m) != SYMLINE_OK) {
        return SYMLINE_ERR_RADIUS;
    }
    if (rows[m] == NULL) {
        return SYMLINE_ERR_NULL;
    }
    if (width == 0u || width > SYMLINE_MAX_DIM) {
        return SYMLINE_ERR_SIZE;
    }
    SL_ENERGY_ACROSS(rows, m, width, E);
    return SYMLINE_OK;
}

symline_status symline_energy_across_image(const symline_image *img, uint32_t y, uint32_t m,
                                           uint32_t *E)
{
    symline_status st = symline_image_check(img);
    if (st != SYMLINE_OK) {
        return st;
    }
    if (E == NULL) {
        return SYMLINE_ERR_NULL;
    }
    if (symline_i_check_radius(m) != SYMLINE_OK) {
        return SYMLINE_ERR_RADIUS;
    }
    if (y >= img->height) {
        return SYMLINE_ERR_RANGE;
    }
    /* Same sum as symline_energy_across(), with the rows taken from the frame
     * directly so no pointer window (up to 511 entries) has to live on the stack. */
    across(NULL, img, y, m, img->width, E);
    return SYMLINE_OK;
}

symline_status symline_s8_row(const uint32_t *E, uint32_t n, uint32_t m, uint8_t *out)
{
    uint32_t i, r;
    const uint32_t emax = symline_emax(m);
    if (E == NULL || out == NULL) {
        return SYMLINE_ERR_NULL;
    }
    if (emax == 0u) {
        return SYMLINE_ERR_RADIUS;
    }
    if (n == 0u || n > SYMLINE_MAX_DIM) {
        return SYMLINE_ERR_SIZE;
    }
    for (i = 0; i < n; i++) {
        if (E[i] > emax) {
            return SYMLINE_ERR_RANGE;
        }
    }
    /*
     * S8 = floor((510 d + emax) / (2 emax)), d = emax - E, without a division
     * per pixel (there is no divide instruction on Cortex-M0+). It equals
     * floor(255 d / emax + 1/2), estimated as the high word of d R + 2^31
     * with R = floor(255 * 2^32 / emax) < 2^24: low by at most one (d < 2^31,
     * so the error is below d / 2^32 < 1/2), fixed by one compare. The
     * compare uses the halved numerator 255 d + floor(emax / 2) (the same
     * quotient by emax), whose remainder, below 2 emax < 2^32, is exact in
     * 32-bit arithmetic. R is a 32-bit division: emax = 255 * 255 T, so
     * R = floor(2^32 / (255 T)), and 255 T never divides 2^32.
     */
    r = UINT32_MAX / (emax / 255u);
    for (i = 0; i < n; i++) {
        const uint32_t d = emax - E[i];
        uint32_t q = (uint32_t)(((uint64_t)d * r + 0x80000000u) >> 32);
        q += (uint32_t)(255u * d + (emax >> 1) - q * emax >= emax);
        out[i] = (uint8_t)q;
    }
    return SYMLINE_OK;
}

/* Energies of row y for either axis into E (width elements). */
static symline_status energy_of_row(const symline_image *img, symline_axis axis, uint32_t m,
                                    uint32_t y, uint32_t *E)
{
    if (axis == SYMLINE_AXIS_VERTICAL) {
        return symline_energy_row(img->data + (size_t)y * img->stride, img->width, m, E);
    }
    return symline_energy_across_image(img, y, m, E);
}

/* The checks every whole-frame call starts with: the image, axis and radius,
 * the caller's pointers a and b, and an output plane of height rows of width
 * elements (out_stride, out_len). */
static symline_status check_frame(const symline_image *img, symline_axis axis, uint32_t m,
                                  const void *a, const void *b, uint32_t out_stride, size_t out_len)
{
    symline_status st = symline_image_check(img);
    if (st == SYMLINE_OK) {
        st = symline_i_check_axis(axis);
    }
    if (st == SYMLINE_OK) {
        st = symline_i_check_radius(m);
    }
    if (st != SYMLINE_OK) {
        return st;
    }
    if (a == NULL || b == NULL) {
        return SYMLINE_ERR_NULL;
    }
    return symline_i_check_plane(img->width, img->height, out_stride, out_len);
}

symline_status symline_i_frame_begin(const symline_image *img, symline_axis axis, uint32_t m,
                                     const void *out, uint32_t out_stride, size_t out_len, void *ws,
                                     size_t ws_size, uint8_t **cur, uint8_t **end, uint32_t **E)
{
    const symline_status st = check_frame(img, axis, m, out, ws, out_stride, out_len);
    if (st != SYMLINE_OK) {
        return st;
    }
    *cur = (uint8_t *)ws;
    *end = *cur + ws_size;
    *E = (uint32_t *)symline_i_carve(cur, *end, (size_t)img->width * sizeof(uint32_t));
    return (*E == NULL) ? SYMLINE_ERR_BUFFER : SYMLINE_OK;
}

symline_status symline_energy_frame(const symline_image *img, symline_axis axis, uint32_t m,
                                    uint32_t *E, uint32_t e_stride, size_t e_len)
{
    uint32_t y;
    symline_status st = check_frame(img, axis, m, E, E, e_stride, e_len);
    for (y = 0; st == SYMLINE_OK && y < img->height; y++) {
        st = energy_of_row(img, axis, m, y, E + (size_t)y * e_stride);
    }
    return st;
}

size_t symline_symmetry_workspace_size(uint32_t width, uint32_t height, symline_axis axis,
                                       uint32_t m)
{
    if (!symline_i_query_ok(width, height, axis, m)) {
        return 0u;
    }
    return symline_i_align_up((size_t)width * sizeof(uint32_t)) + SL_ALIGN;
}

symline_status symline_symmetry(const symline_image *img, symline_axis axis, uint32_t m,
                                uint8_t *out, uint32_t out_stride, size_t out_len, void *ws,
                                size_t ws_size)
{
    uint8_t *cur, *end;
    uint32_t *E, y;
    symline_status st =
        symline_i_frame_begin(img, axis, m, out, out_stride, out_len, ws, ws_size, &cur, &end, &E);
    if (st != SYMLINE_OK) {
        return st;
    }
    for (y = 0; y < img->height; y++) {
        st = energy_of_row(img, axis, m, y, E);
        if (st == SYMLINE_OK) {
            st = symline_s8_row(E, img->width, m, out + (size_t)y * out_stride);
        }
        if (st != SYMLINE_OK) {
            return st;
        }
    }
    return SYMLINE_OK;
}

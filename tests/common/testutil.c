/* SPDX-License-Identifier: Apache-2.0 */
#include "testutil.h"

#include <stdlib.h>
#include <string.h>

uint8_t *tu_guard_alloc(size_t n)
{
    uint8_t *p = (uint8_t *)malloc(n + 2u * TU_GUARD);
    if (p == NULL) {
        return NULL;
    }
    memset(p, TU_GUARD_BYTE, n + 2u * TU_GUARD);
    return p + TU_GUARD;
}

int tu_guard_ok(const uint8_t *p, size_t n)
{
    size_t i;
    for (i = 0; i < TU_GUARD; i++) {
        if (p[-1 - (ptrdiff_t)i] != TU_GUARD_BYTE || p[n + i] != TU_GUARD_BYTE) {
            return 0;
        }
    }
    return 1;
}

void tu_guard_free(uint8_t *p)
{
    if (p != NULL) {
        free(p - TU_GUARD);
    }
}

uint32_t tu_energy_direct(const uint8_t *q, size_t step, uint32_t n, uint32_t i, uint32_t m)
{
    uint32_t j, e = 0;
    for (j = 1; j <= m; j++) {
        uint32_t d = 255;
        if (i >= j && i + j <= n - 1) {
            int a = q[(i - j) * step], b = q[(i + j) * step];
            d = (uint32_t)(a > b ? a - b : b - a);
        }
        e += (m + 1 - j) * d * d;
    }
    return e;
}

symline_status tu_detect_guarded(const symline_image *img, const symline_config *cfg,
                                 symline_result *r, int *guards_ok)
{
    const size_t need = symline_detect_workspace_size(img->width, img->height, cfg);
    uint8_t *ws = need > 0u ? tu_guard_alloc(need) : NULL;
    symline_status st;
    if (ws == NULL) { /* a zero size query fails the caller's status check */
        *guards_ok = 0;
        return SYMLINE_ERR_BUFFER;
    }
    st = symline_detect(img, cfg, ws, need, r);
    *guards_ok = tu_guard_ok(ws, need);
    tu_guard_free(ws);
    return st;
}

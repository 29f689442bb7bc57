/* SPDX-License-Identifier: Apache-2.0 */
/* Uses the installed headers and library: one symmetry row with static buffers. */
#include <stdio.h>

#include "symline/symmetry.h"

int main(void)
{
    static const uint8_t row[7] = {10, 40, 90, 200, 90, 40, 10};
    static uint32_t E[7];
    static uint8_t s8[7];
    if (symline_energy_row(row, 7, 3, E) != SYMLINE_OK || symline_s8_row(E, 7, 3, s8) != SYMLINE_OK) {
        return 1;
    }
    printf("centre S8 = %u\n", s8[3]);
    return s8[3] == 255 ? 0 : 1;
}

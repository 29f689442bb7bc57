#!/bin/sh
# SPDX-License-Identifier: Apache-2.0
# Writes the inputs of the golden tests: hand-made cases (tests/data/cases/) and
# 96x72 cut-outs of the bundled real frames (tests/data/crops/). Deterministic;
# the outputs are committed, so this only needs to run when a case is added.
case ${1:-} in -h | --help) sed -n '2,/^[^#]/{/SPDX-License-Identifier/d;s/^# \{0,1\}//p;}' "$0"; exit 0 ;; esac
set -eu
here=$(cd "$(dirname "$0")" && pwd)
data="$here/../data"
mkdir -p "$data/cases" "$data/crops"
export LC_ALL=C

# case NAME W H AWK-EXPRESSION-OF-x,y  (values taken modulo 256)
case_pgm() {
    name=$1 w=$2 h=$3 expr=$4
    {
        printf 'P5\n# symline golden case %s\n%d %d\n255\n' "$name" "$w" "$h"
        awk -v w="$w" -v h="$h" "BEGIN { s = 12345; for (y = 0; y < h; y++) for (x = 0; x < w; x++) {
            s = (s * 1103515245 + 12345) % 2147483648; r = int(s / 65536) % 256;
            v = ($expr); v = int(v) % 256; if (v < 0) v += 256; printf \"%c\", v } }"
    } > "$data/cases/$name.pgm"
}

case_pgm one_1x1        1  1 '77'
case_pgm row_9x1        9  1 'x * 29 + 3'
case_pgm col_1x9        1  9 '200 - y * 21'
case_pgm narrow_5x4     5  4 'r'
case_pgm tiny_2x2       2  2 'x * 255'
case_pgm const_16x12   16 12 '100'
case_pgm ramp_x_20x10  20 10 'x * 12'
case_pgm ramp_y_10x20  10 20 'y * 12 + 5'
case_pgm mirror_21x5   21  5 '(x < 10 ? x : 20 - x) * 20 + y * 7'
case_pgm stripes_24x16 24 16 '((x % 8) == 3 || (x % 8) == 4) ? 230 : 40'
case_pgm lines_16x24   16 24 '((y % 7) == 2) ? 220 : 60 + (x % 3)'
case_pgm steps_30x6    30  6 'int(x / 4) % 2 ? 180 : 20'
case_pgm extreme_13x11 13 11 '((x + y) % 2) ? 255 : 0'
case_pgm noise_17x13   17 13 'r'
case_pgm blobs_40x30   40 30 '128 + 100 * (((x - 20) * (x - 20) + (y - 15) * (y - 15)) < 60) - 60 * ((x + 2 * y) % 11 == 0)'

# crop SRC X0 Y0 -> 96x72 cut-out
crop() {
    src=$1 x0=$2 y0=$3 out=$4
    w=$(sed -n 2p "$src" | cut -d' ' -f1)
    hdr=$(head -c 64 "$src" | awk 'BEGIN{n=0; b=0} { b += length($0) + 1; n++; if (n == 3) { print b; exit } }')
    {
        printf 'P5\n96 72\n255\n'
        y=0
        while [ $y -lt 72 ]; do
            off=$((hdr + (y0 + y) * w + x0))
            tail -c +$((off + 1)) "$src" | head -c 96
            y=$((y + 1))
        done
    } > "$data/crops/$out.pgm"
}

crop "$data/msl_20190606_r2_cam0_20190606_204340.pgm" 256 380 circle
crop "$data/msl_20250403_r4_cam3_20250403_221433.pgm" 256 300 centreline
crop "$data/msl_20240719_r5_cam3_20240719_090755.pgm" 200 420 goalarea
echo "inputs written to $data/cases and $data/crops"

#!/bin/sh
# SPDX-License-Identifier: Apache-2.0
# Instructions per pixel of the operator and the extrema on the host, counted by
# callgrind (deterministic, unlike seconds on a shared machine): inclusive cost of
# symline_symmetry() / symline_extrema() divided by the pixels processed.
# Usage: tools/bench/operator.sh [BUILD_DIR] [FRAME.pgm]
case ${1:-} in -h | --help) sed -n '2,/^[^#]/{/SPDX-License-Identifier/d;s/^# \{0,1\}//p;}' "$0"; exit 0 ;; esac
set -eu
here=$(cd "$(dirname "$0")" && pwd)
build=${1:-$here/../../build}
frame=${2:-$here/../../tests/data/msl_20250403_r4_cam3_20250403_221433.pgm}
bench="$build/bin/symline-bench-operator"
command -v valgrind >/dev/null || { echo "valgrind is needed: apt-get install valgrind" >&2; exit 2; }
[ -x "$bench" ] || { echo "build first: cmake --build $build" >&2; exit 2; }
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
px=$(sed -n 2p "$frame" | awk '{print $1 * $2}')
printf '%s (%s pixels), %s\n' "$(basename "$frame")" "$px" "$(gcc --version | head -n 1)"
printf '%-9s %-10s %4s %14s\n' "stage" "axis" "m" "instr/pixel"
for what in symmetry extrema; do
    for axis in horizontal vertical; do
        for m in 3 10; do
            valgrind --tool=callgrind --callgrind-out-file="$tmp/cg" "$bench" $what $axis $m 1 "$frame" >/dev/null 2>&1
            ir=$(callgrind_annotate --inclusive=yes "$tmp/cg" 2>/dev/null | grep -E "symline_$what " | head -n 1 | awk '{gsub(",", "", $1); print $1}')
            printf '%-9s %-10s %4s %14s\n' $what $axis $m "$(echo "$ir $px" | awk '{printf "%.1f", $1 / $2}')"
        done
    done
done

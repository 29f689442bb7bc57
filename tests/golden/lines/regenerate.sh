#!/bin/sh
# SPDX-License-Identifier: Apache-2.0
# Regenerates the golden line-detector JSON: `symline lines` with default
# settings (and the paper filter baseline) on every bundled frame, and on two
# of them darkened by 40 gray levels.
# Usage: tests/golden/lines/regenerate.sh [BUILD_DIR]
# (also: cmake --build BUILD_DIR --target golden-lines). Review the diff before
# committing: a change here means the detector's output changed.
case ${1:-} in -h | --help) sed -n '2,/^[^#]/{/SPDX-License-Identifier/d;s/^# \{0,1\}//p;}' "$0"; exit 0 ;; esac
set -eu
here=$(cd "$(dirname "$0")" && pwd)
build=${1:-$here/../../../build}
cli="$build/bin/symline"
[ -x "$cli" ] || { echo "regenerate.sh: $cli not built (cmake --build $build --target symline_cli)" >&2; exit 2; }
n=0
for src in "$here"/../../data/*.pgm; do
    base=$(basename "$src" .pgm)
    "$cli" lines "$src" > "$here/$base.json"
    n=$((n + 1))
done
# The paper's A1-S filter as a baseline, on one frame (its output is large).
base=msl_20250403_r4_cam3_20250403_221433
"$cli" lines --filter paper "$here/../../data/$base.pgm" > "$here/$base.paper.json"
n=$((n + 1))
# Two frames darkened by 40 gray levels: the field boundary scans again above
# the fisheye's black rim (tests/detect/test_golden_lines.c).
bright="$build/bin/symline-bright"
[ -x "$bright" ] || { echo "regenerate.sh: $bright not built (cmake --build $build --target symline-bright)" >&2; exit 2; }
for base in msl_20240719_r5_cam3_20240719_090755 msl_20250403_r4_cam3_20250403_221433; do
    "$bright" --add -40 "$here/../../data/$base.pgm" - | "$cli" lines - > "$here/$base.m40.json"
    n=$((n + 1))
done
echo "wrote $n golden JSON files to $here"

#!/bin/sh
# SPDX-License-Identifier: Apache-2.0
# Regenerates the golden operator and extrema images, feature points and
# histograms (tests/golden/features/) from the plain reference
# (tools/reference/symref.c). Usage: tests/golden/regenerate.sh [BUILD_DIR]
# (also: cmake --build BUILD_DIR --target golden). Review the diff before committing:
# a change here means the contract's outputs changed.
case ${1:-} in -h | --help) sed -n '2,/^[^#]/{/SPDX-License-Identifier/d;s/^# \{0,1\}//p;}' "$0"; exit 0 ;; esac
set -eu
here=$(cd "$(dirname "$0")" && pwd)
build=${1:-$here/../../build}
ref="$build/bin/symline-ref"
[ -x "$ref" ] || { echo "regenerate.sh: $ref not built (cmake --build $build --target symline_ref)" >&2; exit 2; }
out="$here/core"
rm -rf "$out"
mkdir -p "$out"
n=0
for src in "$here"/../data/cases/*.pgm "$here"/../data/crops/*.pgm; do
    base=$(basename "$src" .pgm)
    set_name=$(basename "$(dirname "$src")")
    for axis in horizontal vertical; do
        for m in 1 2 3 5 10 50; do
            "$ref" symmetry "$axis" "$m" "$src" "$out/${set_name}_$base.$axis.m$m.s8.pgm"
            "$ref" extrema "$axis" "$m" "$src" "$out/${set_name}_$base.$axis.m$m.ext.pgm"
            n=$((n + 2))
        done
    done
done
echo "wrote $n golden images to $out"

# Symmetry feature points and vertical symmetry histograms (docs/format.md), radii 1, 3, 10.
fout="$here/features"
rm -rf "$fout"
mkdir -p "$fout"
n=0
for src in "$here"/../data/cases/*.pgm "$here"/../data/crops/*.pgm; do
    base=$(basename "$src" .pgm)
    set_name=$(basename "$(dirname "$src")")
    for m in 1 3 10; do
        for cmd in features histogram; do
            "$ref" $cmd "$m" "$src" "$fout/${set_name}_$base.m$m.$cmd.json"
            n=$((n + 1))
        done
    done
done
echo "wrote $n golden JSON files to $fout"

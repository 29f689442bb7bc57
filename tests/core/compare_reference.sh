#!/bin/sh
# SPDX-License-Identifier: Apache-2.0
# The CLI against the plain reference, byte for byte, on every bundled real frame,
# both axes, the golden radii, symmetry and extrema.
# Usage: compare_reference.sh SYMLINE SYMLINE_REF DATA_DIR
case ${1:-} in -h | --help) sed -n '2,/^[^#]/{/SPDX-License-Identifier/d;s/^# \{0,1\}//p;}' "$0"; exit 0 ;; esac
set -eu
cli=$1 ref=$2 data=$3
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
n=0 bad=0
for src in "$data"/*.pgm; do
    for axis in horizontal vertical; do
        for m in 1 2 3 5 10 50; do
            for cmd in symmetry extrema; do
                "$cli" $cmd --axis $axis --radius $m "$src" "$tmp/a.pgm"
                "$ref" $cmd $axis $m "$src" "$tmp/b.pgm"
                n=$((n + 1))
                if ! cmp -s "$tmp/a.pgm" "$tmp/b.pgm"; then
                    echo "MISMATCH: $cmd --axis $axis --radius $m $(basename "$src")"
                    bad=$((bad + 1))
                fi
            done
        done
    done
done
[ $n -ge 72 ] || { echo "only $n comparisons ran"; exit 1; }
echo "$((n - bad)) passed, $bad failed"
[ $bad -eq 0 ]

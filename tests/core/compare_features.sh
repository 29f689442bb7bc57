#!/bin/sh
# SPDX-License-Identifier: Apache-2.0
# `symline features` and `symline histogram` against the plain reference, byte
# for byte, on every bundled real frame at radii 1, 3 and 10.
# Usage: compare_features.sh SYMLINE SYMLINE_REF DATA_DIR
case ${1:-} in -h | --help) sed -n '2,/^[^#]/{/SPDX-License-Identifier/d;s/^# \{0,1\}//p;}' "$0"; exit 0 ;; esac
set -eu
cli=$1 ref=$2 data=$3
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
n=0 bad=0
for src in "$data"/*.pgm; do
    for m in 1 3 10; do
        for cmd in features histogram; do
            "$cli" $cmd --radius $m "$src" > "$tmp/a.json"
            "$ref" $cmd $m "$src" "$tmp/b.json"
            n=$((n + 1))
            if ! cmp -s "$tmp/a.json" "$tmp/b.json"; then
                echo "MISMATCH: $cmd --radius $m $(basename "$src")"
                bad=$((bad + 1))
            fi
        done
    done
done
[ $n -ge 18 ] || { echo "only $n comparisons ran"; exit 1; }
echo "$((n - bad)) passed, $bad failed"
[ $bad -eq 0 ]

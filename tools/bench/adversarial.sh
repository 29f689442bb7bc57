#!/bin/sh
# SPDX-License-Identifier: Apache-2.0
# Detection cost on adversarial frames (symline-advframes: rings, noise,
# dashes, checker) from 640x480 to 2560x1920: instructions of symline_detect()
# counted by callgrind (deterministic; default configuration), the segments
# found, and CPU seconds of `symline lines` with a permissive configuration
# (--filter paper --illumination 0 --min-length 2: every S point a line
# point, pieces from 2 px; the worst case we know). Fails when the 2560x1920
# ring frame costs more than 20x the 640x480 one (linear: 16x).
# Usage: tools/bench/adversarial.sh [BUILD_DIR] [OUT_DIR]
case "${1:-}" in -h | --help) sed -n '3,/^[^#]/{/^#/s/^# \{0,1\}//p}' "$0"; exit 0 ;; esac
set -eu
here=$(cd "$(dirname "$0")" && pwd)
build=${1:-$here/../../build}
out=${2:-$(mktemp -d)}
cli="$build/bin/symline"
gen="$build/bin/symline-advframes"
command -v valgrind >/dev/null || { echo "valgrind is needed: apt-get install valgrind" >&2; exit 2; }
[ -x "$cli" ] && [ -x "$gen" ] || { echo "build first: cmake --build $build" >&2; exit 2; }
mkdir -p "$out"
permissive="--filter paper --illumination 0 --min-length 2"
cpu() { # user+sys seconds of one run
    /usr/bin/env time -f '%U %S' "$@" 2>&1 >/dev/null | tail -n 1 | awk '{printf "%.2f", $1 + $2}'
}
printf '%-8s %-10s %14s %10s %9s %16s\n' pattern size "instructions" "per pixel" segments "permissive CPU s"
for kind in rings noise dashes checker; do
    for size in 640x480 1280x960 2560x1920; do
        w=${size%x*} h=${size#*x}
        f="$out/$kind-$size.pgm"
        [ -f "$f" ] || "$gen" "$kind" "$w" "$h" "$f"
        valgrind --tool=callgrind --toggle-collect=symline_detect --callgrind-out-file="$out/cg" \
            "$cli" lines "$f" >"$out/lines.json" 2>/dev/null
        ir=$(sed -n 's/^summary: *//p' "$out/cg")
        segs=$(grep -c '"x0"' "$out/lines.json" || true)
        t=$(cpu "$cli" lines $permissive "$f")
        printf '%-8s %-10s %14s %10s %9s %16s\n' "$kind" "$size" "$ir" \
            "$(echo "$ir $w $h" | awk '{printf "%.0f", $1 / ($2 * $3)}')" "$segs" "$t"
        echo "$kind $size $ir" >>"$out/ir.txt"
    done
done
small=$(awk '$1 == "rings" && $2 == "640x480" {print $3}' "$out/ir.txt")
large=$(awk '$1 == "rings" && $2 == "2560x1920" {print $3}' "$out/ir.txt")
ratio=$(echo "$large $small" | awk '{printf "%.1f", $1 / $2}')
echo "rings 2560x1920 / 640x480: ${ratio}x the instructions (16x is linear; at most 20x allowed)"
echo "$large $small" | awk '{exit !($1 <= 20 * $2)}'

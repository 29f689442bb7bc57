#!/bin/sh
# SPDX-License-Identifier: Apache-2.0
# Detection cost on adversarial frames (symline-advframes: rings, noise,
# dashes, checker) from 640x480 to 2560x1920: instructions of symline_detect()
# counted by callgrind (deterministic), the segments found, and CPU seconds of
# `symline lines` with a permissive configuration (--filter paper
# --illumination 0 --min-length 2: every S point a line point, pieces from
# 2 px; the worst case we know).
# Instructions are counted twice: with the default configuration, and with
# `--field keep` (the field boundary is estimated but nothing is dropped), so
# that frames of the same content are compared on the same work: the boundary
# is a decision about the content, and it can keep a different share of the
# same pattern at another size (the 640x480 ring frame's boundary, on 8 px
# cells, keeps its lowest 23 %; the larger ones, on 16 px cells, all of it).
# Fails when the 2560x1920 ring frame costs more than 20x the 640x480 one
# with the whole frame detected (--field keep; linear: 16x).
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
: >"$out/ir.txt"
permissive="--filter paper --illumination 0 --min-length 2"
cpu() { # user+sys seconds of one run
    /usr/bin/env time -f '%U %S' "$@" 2>&1 >/dev/null | tail -n 1 | awk '{printf "%.2f", $1 + $2}'
}
count() { # instructions of symline_detect() for: FRAME [OPTIONS...]
    f=$1
    shift
    valgrind --tool=callgrind --toggle-collect=symline_detect --callgrind-out-file="$out/cg" \
        "$cli" lines "$@" "$f" >"$out/lines.json" 2>/dev/null
    sed -n 's/^summary: *//p' "$out/cg"
}
printf '%-8s %-10s %14s %8s %9s %14s %8s %9s %16s\n' pattern size "default instr" "per px" segments \
    "keep instr" "per px" segments "permissive CPU s"
for kind in rings noise dashes checker; do
    for size in 640x480 1280x960 2560x1920; do
        w=${size%x*} h=${size#*x}
        f="$out/$kind-$size.pgm"
        [ -f "$f" ] || "$gen" "$kind" "$w" "$h" "$f"
        ir=$(count "$f")
        segs=$(grep -c '"x0"' "$out/lines.json" || true)
        irk=$(count "$f" --field keep)
        segsk=$(grep -c '"x0"' "$out/lines.json" || true)
        t=$(cpu "$cli" lines $permissive "$f")
        printf '%-8s %-10s %14s %8s %9s %14s %8s %9s %16s\n' "$kind" "$size" \
            "$ir" "$(echo "$ir $w $h" | awk '{printf "%.0f", $1 / ($2 * $3)}')" "$segs" \
            "$irk" "$(echo "$irk $w $h" | awk '{printf "%.0f", $1 / ($2 * $3)}')" "$segsk" "$t"
        echo "$kind $size $ir $irk" >>"$out/ir.txt"
    done
done
ratio() { # pattern column -> 2560x1920 / 640x480
    awk -v k="$1" -v c="$2" '$1 == k && $2 == "640x480" { s = $c } $1 == k && $2 == "2560x1920" { l = $c }
        END { printf "%.1f", l / s }' "$out/ir.txt"
}
for kind in rings noise dashes checker; do
    echo "$kind 2560x1920 / 640x480: default $(ratio "$kind" 3)x, --field keep $(ratio "$kind" 4)x"
done
r=$(ratio rings 4)
echo "rings, whole frame detected (--field keep): ${r}x the instructions (16x is linear; at most 20x allowed)"
echo "$r" | awk '{exit !($1 <= 20)}'

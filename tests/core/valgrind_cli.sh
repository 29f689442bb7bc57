#!/bin/sh
# SPDX-License-Identifier: Apache-2.0
# The CLI and the capture app under valgrind (memcheck) on the bundled frames
# and on damaged files: any invalid read or write, use of uninitialised
# memory or definite leak fails (valgrind --error-exitcode=1).
# usage: valgrind_cli.sh SYMLINE SYMLINE-CAPTURE|- DATA-DIR   (exit 77: valgrind missing)
case "${1:-}" in -h | --help) sed -n '3,/^[^#]/{/^#/s/^# \{0,1\}//p}' "$0"; exit 0 ;; esac
set -u
cli=$1 app=$2 data=$3
command -v valgrind >/dev/null 2>&1 || { echo "SKIPPED: valgrind not installed"; exit 77; }
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
pass=0 fail=0
vg() {
    want=$1
    shift
    valgrind -q --error-exitcode=99 --leak-check=full --errors-for-leak-kinds=definite,indirect \
        --show-leak-kinds=definite,indirect "$@" >"$tmp/out" 2>"$tmp/err"
    got=$?
    if [ $got -ne "$want" ]; then
        echo "FAIL: valgrind $* exited $got (want $want; 99 = valgrind found errors)"
        grep -v '^symline' "$tmp/err" | head -n 30
        fail=$((fail + 1))
    else
        pass=$((pass + 1))
    fi
}
for f in "$data"/*.pgm; do
    vg 0 "$cli" lines "$f"
    vg 0 "$cli" overlay --filter paper "$f" "$tmp/o.png"
    vg 0 "$cli" symmetry --axis horizontal --radius 3 "$f" "$tmp/s.png"
    vg 0 "$cli" extrema --axis vertical --radius 5 "$f" "$tmp/e.pgm"
done
for f in "$data"/cases/*.pgm; do
    vg 0 "$cli" lines --radius 1 "$f"
done
# 2x2 binning (--bin on: the default from 1024x768 on), one frame and a folder
# of frames of different sizes.
vg 0 "$cli" overlay --bin on "$data/msl_20190606_r2_cam0_20190606_204340.pgm" "$tmp/b.png"
vg 0 "$cli" lines --bin on "$data"/cases
# Damaged input takes the error paths (the PNG one leaked).
echo iVBORw0KGgoAAAANSUhEUgAAAAEAAAABCAAAAAA6fptVAAAACklEQVR4nA== | base64 -d >"$tmp/damaged.png"
printf 'P5\n8 8\n255\nabc' >"$tmp/short.pgm"
vg 2 "$cli" lines "$tmp/damaged.png"
vg 2 "$cli" lines "$tmp/short.pgm"
vg 2 "$cli" lines /dev/zero
if [ "$app" != "-" ]; then
    vg 0 "$app" --replay "$data" --summary-every 0 --record 2 "$tmp/rec"
    vg 0 "$app" --replay "$data" --summary-every 0 --bin on
fi
echo "$pass passed, $fail failed"
[ $fail -eq 0 ]

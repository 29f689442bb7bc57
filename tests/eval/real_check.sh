#!/bin/sh
# SPDX-License-Identifier: Apache-2.0
# Accuracy on the bundled real frames with hand ground truth (tests/data: NAME.pgm
# with NAME.lines.txt, .arcs.txt, .dontcare.txt): `symline lines` with the
# defaults, scored by `symline-score gt` against the ground truth, on each frame,
# on its copy at half the brightness and on its copy darkened by 40 gray levels
# (clipped at 0), must keep F1 at or above the floors below. The golden tests pin
# the output byte for byte; this test says whether a deliberate change of the
# output kept the accuracy: lower a floor only with the accuracy re-measured over
# the whole evaluation (tools/eval/evaluate.sh).
# usage: real_check.sh SYMLINE SYMLINE-SCORE SYMLINE-BRIGHT DATA_DIR WORKDIR
case ${1:-} in -h | --help) sed -n '2,/^[^#]/{/SPDX-License-Identifier/d;s/^# \{0,1\}//p;}' "$0"; exit 0 ;; esac
set -eu
symline=$1
score=$2
bright=$3
data=$4
work=$5
rm -rf "$work"
mkdir -p "$work"
fail=0

# NAME, F1 floor on the frame, at half brightness, darkened by 40 (measured once
# a cell that is not field cost the boundary's column scan ten carpet cells:
# 0.928 / 0.914 and 0.905 / 0.547; darkened, once the column scan runs again
# past a fisheye's black rim where most columns found no carpet: 0.928 and
# 0.969, 0.824 before; floors 0.02 below).
floors="msl_20190606_r2_cam0_20190606_204340 0.908 0.894 0.908
msl_20250403_r4_cam3_20250403_221433 0.885 0.527 0.949"

# f1 NAME DET.json: the F1 of a detection against NAME's ground truth.
f1() { "$score" gt "$data/$1" "$2" | head -n 1 | tr ' ' '\n' | sed -n 's/^f1=//p'; }
# copy_f1 NAME TAG ARGS...: the F1 on NAME's copy made by `symline-bright ARGS`.
copy_f1() {
    n=$1 t=$2
    shift 2
    "$bright" "$@" "$data/$n.pgm" "$work/$n.$t.pgm"
    "$symline" lines "$work/$n.$t.pgm" > "$work/$n.$t.json"
    f1 "$n" "$work/$n.$t.json"
}
# at_least A B: A >= B (decimal fractions).
at_least() { awk -v a="$1" -v b="$2" 'BEGIN { exit !(a + 0 >= b + 0) }'; }

echo "$floors" | while read -r name floor half_floor dark_floor; do
    [ -f "$data/$name.lines.txt" ] || { echo "FAIL: $data/$name.lines.txt missing" >&2; exit 1; }
    "$symline" lines "$data/$name.pgm" > "$work/$name.json"
    a=$(f1 "$name" "$work/$name.json")
    b=$(copy_f1 "$name" half --mul 0.5)
    c=$(copy_f1 "$name" dark --add -40)
    [ -n "$a" ] && [ -n "$b" ] && [ -n "$c" ] || { echo "FAIL: $name: no score" >&2; exit 1; }
    echo "$name: F1 $a (floor $floor), at half brightness $b (floor $half_floor), darkened by 40 $c (floor $dark_floor)"
    at_least "$a" "$floor" || { echo "FAIL: $name: F1 $a < $floor" >&2; exit 1; }
    at_least "$b" "$half_floor" || { echo "FAIL: $name: F1 at half brightness $b < $half_floor" >&2; exit 1; }
    at_least "$c" "$dark_floor" || { echo "FAIL: $name: F1 darkened by 40 $c < $dark_floor" >&2; exit 1; }
done || fail=1

# Every frame with ground truth here has a floor above.
n=0
for gt in "$data"/*.lines.txt; do
    name=$(basename "$gt" .lines.txt)
    n=$((n + 1))
    echo "$floors" | grep -q "^$name " || { echo "FAIL: $name has ground truth but no floor" >&2; fail=1; }
done
[ "$n" -ge 2 ] || { echo "FAIL: expected ground truth for at least 2 frames in $data, found $n" >&2; fail=1; }
[ "$fail" -eq 0 ] && echo "real_check: every floor held"
exit "$fail"

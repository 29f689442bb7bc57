#!/bin/sh
# SPDX-License-Identifier: Apache-2.0
# The renderer is deterministic for a seed, different seeds give different scenes,
# ground-truth points lie inside the image, and the ground truth scored against
# itself (as a detection) is perfect.
# usage: render_check.sh SYMLINE-RENDER SYMLINE-SCORE WORKDIR
case ${1:-} in -h | --help) sed -n '2,/^[^#]/{/SPDX-License-Identifier/d;s/^# \{0,1\}//p;}' "$0"; exit 0 ;; esac
set -eu
render=$1
score=$2
work=$3
rm -rf "$work"
mkdir -p "$work"
fail() { echo "FAIL: $*" >&2; exit 1; }

for set in normal dark overexposed occluded circle; do
    "$render" --set $set --seed 5 --count 2 --size 160x120 "$work/a"
    "$render" --set $set --seed 5 --count 2 --size 160x120 "$work/b"
    "$render" --set $set --seed 6 --count 2 --size 160x120 "$work/c"
done
n=0
for f in "$work"/a/*; do
    cmp -s "$f" "$work/b/$(basename "$f")" || fail "$(basename "$f") differs between two runs with one seed"
    n=$((n + 1))
done
[ "$n" -eq 40 ] || fail "expected 40 files, got $n"
for set in normal dark overexposed occluded circle; do
    cmp -s "$work/a/${set}_000.pgm" "$work/c/${set}_000.pgm" && fail "$set: seeds 5 and 6 give the same image"
done

for f in "$work"/a/*.pgm; do
    name=${f%.pgm}
    # Every ground-truth coordinate inside [0, 159] x [0, 119].
    cat "$name.lines.txt" "$name.dontcare.txt" |
        awk '{ if ($1 < 0 || $1 > 159 || $3 < 0 || $3 > 159 || $2 < 0 || $2 > 119 || $4 < 0 || $4 > 119) bad = 1 }
             END { exit bad }' || fail "$name: segment outside the image"
    awk 'NF { if ($1 < 0 || $1 > 159 || $2 < 0 || $2 > 119) bad = 1 } END { exit bad }' "$name.arcs.txt" ||
        fail "$name: arc point outside the image"
    [ -s "$name.lines.txt" ] || [ -s "$name.arcs.txt" ] || fail "$name: no ground truth at all"
    "$score" gtjson "$name" > "$name.json"
    "$score" gt "$name" "$name.json" | grep -q '^f1=1.000000 ' || fail "$name: ground truth against itself is not perfect"
done
echo "ok: $n files, deterministic"

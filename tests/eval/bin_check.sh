#!/bin/sh
# SPDX-License-Identifier: Apache-2.0
# 2x2 binning of large frames (`symline lines --bin`): the bundled annotated
# real frames at twice their size (1216x1600, symline-resize --double --gt)
# score clearly better binned (the default there) than at full size, and
# their binned detections lie on the doubled ground truth; below the advised
# size the default output is the unbinned one, byte for byte; the capture
# loop (CAPTURE: symline-capture, or - where it is not built) bins as the
# CLI does: the same segments, boundary and intersections; `symline
# boundary` bins as `symline lines` does and reports the same boundary.
#   bin_check.sh SYMLINE SYMLINE_RESIZE SYMLINE_SCORE DATA WORKDIR [CAPTURE]
set -eu
case ${1:-} in
-h | --help)
    sed -n '3,/^set -eu/p' "$0" | sed -e '/^set -eu/d' -e 's/^# \{0,1\}//'
    exit 0
    ;;
esac
[ $# -eq 5 ] || [ $# -eq 6 ] || { echo "usage: bin_check.sh SYMLINE SYMLINE_RESIZE SYMLINE_SCORE DATA WORKDIR [CAPTURE]" >&2; exit 2; }
symline=$1 rs=$2 score=$3 data=$4 d=$5 capture=${6:--}
rm -rf "$d"
mkdir -p "$d"
fail() { echo "FAIL: $*"; exit 1; }
f1() { "$score" gt "$1" "$2" | head -n 1 | tr ' ' '\n' | sed -n 's/^f1=//p'; }
# detection JSON: from the first "segments" key on, without blanks (the
# capture records fold the same writer's output onto one line).
detection() { tr -d ' \n' < "$1" | awk '{ i = index($0, "\"segments\":"); print substr($0, i) }'; }
# the field boundary's vertices of either command's JSON.
boundary() { tr -d ' \n' < "$1" | sed -n 's/.*"field_boundary":\(\[[][0-9,-]*\]\).*/\1/p'; }

n=0
for gt in "$data"/*.lines.txt; do
    name=$(basename "$gt" .lines.txt)
    n=$((n + 1))
    # Below 1024x768 pixels: the default is no binning.
    "$symline" lines "$data/$name.pgm" > "$d/$name.auto.json"
    "$symline" lines --bin off "$data/$name.pgm" > "$d/$name.off.json"
    cmp -s "$d/$name.auto.json" "$d/$name.off.json" || fail "$name: the default bins a frame below the advised size"
    "$rs" --double --gt "$data/$name.pgm" "$d/$name.pgm"
    "$symline" lines "$d/$name.pgm" > "$d/$name.x2.json"
    "$symline" lines --bin on "$d/$name.pgm" > "$d/$name.x2on.json"
    cmp -s "$d/$name.x2.json" "$d/$name.x2on.json" || fail "$name: the default does not bin a 1216x1600 frame"
    "$symline" lines --bin off "$d/$name.pgm" > "$d/$name.x2off.json"
    for b in auto off; do
        "$symline" boundary --bin "$b" "$d/$name.pgm" > "$d/$name.b$b.json"
        json=$d/$name.x2.json
        [ "$b" = auto ] || json=$d/$name.x2off.json
        v=$(boundary "$d/$name.b$b.json")
        [ -n "$v" ] || fail "$name: no field_boundary from symline boundary --bin $b"
        [ "$v" = "$(boundary "$json")" ] ||
            fail "$name: symline boundary --bin $b and symline lines differ on the 1216x1600 frame"
    done
    on=$(f1 "$d/$name" "$d/$name.x2.json")
    off=$(f1 "$d/$name" "$d/$name.x2off.json")
    echo "$name at twice its size: F1 binned $on, unbinned $off"
    awk -v a="$on" -v b="$off" 'BEGIN { exit !(a + 0 >= b + 0.1 && a + 0 >= 0.5) }' ||
        fail "$name: binned F1 $on against $off unbinned"
    if [ "$capture" != - ]; then
        "$capture" --replay "$d/$name.pgm" --frames 1 > "$d/$name.cap.json" 2>/dev/null
        [ "$(detection "$d/$name.cap.json")" = "$(detection "$d/$name.x2.json")" ] ||
            fail "$name: symline-capture and symline lines differ on the binned frame"
    fi
done
[ "$n" -ge 2 ] || fail "only $n annotated frames in $data"
if "$symline" lines --bin sometimes "$data/$name.pgm" >/dev/null 2>&1; then fail "--bin took a bad value"; fi
if "$symline" boundary --bin sometimes "$data/$name.pgm" >/dev/null 2>&1; then fail "boundary --bin took a bad value"; fi
echo "bin_check: ok"

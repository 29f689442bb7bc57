#!/bin/sh
# SPDX-License-Identifier: Apache-2.0
# symline-resize on hand-made frames: the exact pixels of --half and --double,
# the ground truth moved with the pixel centres, and a rendered scene whose
# resized frame and ground truth still agree: the detector finds its lines
# there (a frame and a ground truth of different scales score F1 about 0.1).
#   resize_check.sh SYMLINE_RESIZE SYMLINE_RENDER SYMLINE_SCORE SYMLINE WORKDIR
set -eu
case ${1:-} in
-h | --help)
    sed -n '3,/^set -eu/p' "$0" | sed -e '/^set -eu/d' -e 's/^# \{0,1\}//'
    exit 0
    ;;
esac
[ $# -eq 5 ] || { echo "usage: resize_check.sh SYMLINE_RESIZE SYMLINE_RENDER SYMLINE_SCORE SYMLINE WORKDIR" >&2; exit 2; }
rs=$1 render=$2 score=$3 symline=$4 d=$5
rm -rf "$d"
mkdir -p "$d"
fail() { echo "FAIL: $*"; exit 1; }
# bytes FILE: the pixel values of a PGM written by the tool (header "P5\nW H\n255\n").
bytes() { tail -c +"$(($(head -n 3 "$1" | wc -c) + 1))" "$1" | od -An -v -tu1 | tr -s ' \n' ' ' | sed 's/^ //;s/ $//'; }

# 5x3: the odd last column and row are dropped; (a + b + c + d + 2) / 4.
printf 'P5\n5 3\n255\n' > "$d/a.pgm"
printf '\000\001\002\003\377\004\005\006\007\377\377\377\377\377\377' >> "$d/a.pgm"
"$rs" --half "$d/a.pgm" "$d/h.pgm"
[ "$(head -n 2 "$d/h.pgm" | tail -n 1)" = "2 1" ] || fail "--half size"
[ "$(bytes "$d/h.pgm")" = "3 5" ] || fail "--half pixels: $(bytes "$d/h.pgm")"

# 2x1 [0 160]: weights 3/4 and 1/4 per axis, the border pixel repeated:
# 0, 0.75*0 + 0.25*160 = 40, 120, 160 on both rows.
printf 'P5\n2 1\n255\n\000\240' > "$d/b.pgm"
"$rs" --double "$d/b.pgm" "$d/t.pgm"
[ "$(head -n 2 "$d/t.pgm" | tail -n 1)" = "4 2" ] || fail "--double size"
[ "$(bytes "$d/t.pgm")" = "0 40 120 160 0 40 120 160" ] || fail "--double pixels: $(bytes "$d/t.pgm")"

# The ground truth: c -> (c + 1/2) s - 1/2, blank lines kept, missing files skipped.
printf '0 0 9 1.5\n' > "$d/a.lines.txt"
printf '1 1\n2 2\n\n3 3\n' > "$d/a.arcs.txt"
"$rs" --half --gt "$d/a.pgm" "$d/g.pgm"
[ "$(cat "$d/g.lines.txt")" = "-0.25 -0.25 4.25 0.50" ] || fail "--gt lines: $(cat "$d/g.lines.txt")"
[ "$(cat "$d/g.arcs.txt")" = "$(printf '0.25 0.25\n0.75 0.75\n\n1.25 1.25')" ] || fail "--gt arcs"
[ ! -e "$d/g.dontcare.txt" ] || fail "--gt wrote a missing file"
"$rs" --double --gt "$d/a.pgm" "$d/G.pgm"
[ "$(cat "$d/G.lines.txt")" = "0.50 0.50 18.50 3.50" ] || fail "--gt lines at double size"

# A rendered scene at 640x480: at half and at double size the detector's lines
# on the resized frame match its resized ground truth.
"$render" --set normal --count 1 --size 640x480 "$d/r" >/dev/null
for m in half double; do
    "$rs" --$m --gt "$d/r/normal_000.pgm" "$d/r/$m.pgm"
    "$symline" lines "$d/r/$m.pgm" > "$d/r/$m.json"
    f1=$("$score" gt "$d/r/$m" "$d/r/$m.json" | head -n 1 | tr ' ' '\n' | sed -n 's/^f1=//p')
    awk -v f="$f1" 'BEGIN { exit !(f + 0 >= 0.7) }' || fail "$m: F1 $f1 of the detections against the resized ground truth"
done
printf 'P5\n1 1\n255\n\000' > "$d/one.pgm"
if "$rs" --half "$d/one.pgm" "$d/none.pgm" 2>/dev/null; then fail "--half of 1x1 succeeded"; fi
printf '0 0 x 1\n' > "$d/one.lines.txt"
if "$rs" --double --gt "$d/one.pgm" "$d/bad.pgm" 2>/dev/null; then fail "--gt took a line that is not numbers"; fi
echo "resize_check: ok"

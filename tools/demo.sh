#!/bin/sh
# The main job on a bundled real frame: builds symline (installing what it needs
# when missing), detects the field lines, and writes
#   out/lines.json     the segments (JSON of docs/format.md, as printed by `symline lines`)
#   out/overlay.png    lines drawn solid, curves dotted, over the frame
#   out/symmetry.png   the 8-bit symmetry image (horizontal axis, radius 3)
#   out/extrema.png    its extrema map (255 S points, 128 A points)
#   out/capture.jsonl  the on-robot capture loop replaying the bundled frames
#                      (one JSON line per frame; no camera needed)
# then prints a short summary.
#   tools/demo.sh [FRAME.pgm|FRAME.png]
set -eu
cd "$(dirname "$0")/.."
frame=${1:-tests/data/msl_20190606_r2_cam0_20190606_204340.pgm}
tools/deps.sh build
cmake --preset default >/dev/null
cmake --build --preset default -j "$(nproc 2>/dev/null || echo 2)" >/dev/null
bin=build/bin/symline
mkdir -p out
"$bin" convert "$frame" out/frame.png
"$bin" symmetry --axis horizontal --radius 3 "$frame" out/symmetry.png
"$bin" extrema --axis horizontal --radius 3 "$frame" out/extrema.png
"$bin" lines "$frame" > out/lines.json
"$bin" overlay "$frame" out/overlay.png >/dev/null
build/bin/symline-capture --replay tests/data --frames 3 --summary-every 0 \
    > out/capture.jsonl 2> out/capture.log
lines=$(grep -o '"kind": *"line"' out/lines.json | wc -l)
curves=$(grep -o '"kind": *"curve"' out/lines.json | wc -l)
size=$(grep -o '"width": *[0-9]*, *"height": *[0-9]*' out/lines.json | head -n 1 | tr -dc '0-9 ,' | awk -F, '{gsub(/ /, ""); print $1 "x" $2}')
echo "$(basename "$frame") ($size): $((lines + curves)) segments, $lines lines and $curves curves"
echo "  out/lines.json     segments as JSON"
echo "  out/overlay.png    lines solid, curves dotted, over the frame"
echo "  out/symmetry.png   symmetry image (horizontal axis, radius 3)"
echo "  out/extrema.png    extrema map (white: S points, gray: A points)"
echo "capture loop, replay of the bundled frames (out/capture.jsonl):"
sed -n 's/^symline-capture: stopped/  stopped/p' out/capture.log

#!/bin/sh
# SPDX-License-Identifier: Apache-2.0
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
usage() {
    cat <<'EOF'
usage: tools/demo.sh [FRAME]
Builds symline in build/ (tools/deps.sh installs or names what is missing),
detects the field lines of FRAME (a PGM or PNG; default: a bundled real frame)
and writes into out/:
  lines.json     the segments, as printed by 'symline lines' (docs/format.md)
  overlay.png    lines solid, curves dotted, over the frame
  symmetry.png   the 8-bit symmetry image (horizontal axis, radius 3)
  extrema.png    its extrema map (255 S points, 128 A points)
  capture.jsonl  the capture loop replaying the bundled frames (no camera)
then prints a short summary. Needs cmake >= 3.16, a C compiler, pkg-config and
libpng; on Debian they are installed with apt-get when missing.
EOF
}
case ${1:-} in
-h | --help) usage; exit 0 ;;
--) shift ;;
-?*) echo "tools/demo.sh: unknown option '$1'" >&2; usage >&2; exit 2 ;;
esac
[ $# -le 1 ] || { echo "tools/demo.sh: one frame at most" >&2; usage >&2; exit 2; }
frame=${1:-}
case $frame in
'' | /*) ;;
*) frame=$(pwd)/$frame ;;
esac
cd "$(dirname "$0")/.."
frame=${frame:-tests/data/msl_20190606_r2_cam0_20190606_204340.pgm}
[ -f "$frame" ] || { echo "tools/demo.sh: no such file: $frame" >&2; exit 2; }
tools/deps.sh build
# Plain CMake (no preset) so that CMake 3.16 is enough; the same build/ as the default preset.
cmake -S . -B build -DCMAKE_BUILD_TYPE=Release >/dev/null
cmake --build build -j "$(nproc 2>/dev/null || echo 2)" >/dev/null
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

#!/bin/sh
# SPDX-License-Identifier: Apache-2.0
# symline beside OpenCV's line detectors (EDLines, FastLineDetector, LSD, Canny +
# HoughLinesP) in one run on the same synthetic frames: the time of the detection
# call (one thread, image in memory; symline-peers, tools/bench/peers.cpp) and the
# F1 of each detector's segments by the same scorer (symline-score gt,
# docs/evaluation.md) on DATA_DIR/synth and on the rendered sets of tools/eval/evaluate.sh
# (normal, dark, overexposed, occluded, circle; 320x240 and 640x480; same seed).
# Installs what it needs (Debian: g++, libopencv-dev, libopencv-contrib-dev, ...).
#
# usage: tools/bench/peers.sh DATA_DIR [options]
#   --build DIR    build directory (default: REPO/build; configured and built when needed)
#   --out DIR      work folder for renders and detections (default: REPO/out/peers)
#   --count N      images per rendered set and size (default 20)
#   --seed N       renderer seed (default 2026)
#   --repeat N     timed calls per frame and detector (default 5; the fastest counts)
# Prints the table: detector, ms/frame at 320x240 and 640x480 (mean over the
# frames of that size of the fastest of N calls, thread CPU time), time relative
# to symline's default, mean per-image F1 over all synthetic frames of each size.
set -eu

# shellcheck source=../args.sh
. "$(dirname "$0")/../args.sh"
args_data "$@"
shift
BUILD=$REPO/build
OUT=$REPO/out/peers
COUNT=20
SEED=2026
REPEAT=5
ARGS_COMMON="build out count seed repeat"
while [ $# -gt 0 ]; do
    args_common "$@"
    shift "$ARGS_SHIFT"
done
args_dirs

# ---- tools: Debian packages, then the three binaries ----
# shellcheck source=../../capture/tests/pkgs.sh
. "$REPO/capture/tests/pkgs.sh"
if command -v dpkg >/dev/null 2>&1; then
    need_pkgs cmake make gcc g++ libc6-dev pkg-config libpng-dev libopencv-dev libopencv-contrib-dev
fi
if [ ! -f "$BUILD/CMakeCache.txt" ] || ! grep -q '^OpenCV_DIR:PATH=/' "$BUILD/CMakeCache.txt"; then
    # (Re)configure: a build configured before OpenCV was installed has no symline-peers.
    cmake -S "$REPO" -B "$BUILD" -DCMAKE_BUILD_TYPE=Release >&2
fi
cmake --build "$BUILD" -j2 --target symline_peers symline-render symline-score >&2
BIN=$BUILD/bin
for b in symline-peers symline-render symline-score; do
    [ -x "$BIN/$b" ] || { echo "peers.sh: $BIN/$b missing after the build" >&2; exit 1; }
done

# ---- the frames: the given scenes and the rendered sets (cached by renderer, seed, count) ----
SETS="normal dark overexposed occluded circle"
SIZES="320x240 640x480"
RSUM=$(cksum < "$BIN/symline-render" | cut -d' ' -f1)
mkdir -p "$OUT/render"
for size in $SIZES; do
    for set in $SETS; do
        d=$OUT/render/$set-$size
        if [ ! -f "$d/.stamp" ] || [ "$(cat "$d/.stamp")" != "$RSUM $SEED $COUNT" ]; then
            rm -rf "$d"
            echo "peers.sh: rendering $set $size" >&2
            "$BIN/symline-render" --set "$set" --seed "$SEED" --count "$COUNT" --size "$size" "$d" >&2
            echo "$RSUM $SEED $COUNT" > "$d/.stamp"
        fi
    done
done
set_dirs=
[ -d "$DATA/synth" ] && set_dirs="given:$DATA/synth"
for size in $SIZES; do
    for set in $SETS; do set_dirs="$set_dirs $set-${size%%x*}:$OUT/render/$set-$size"; done
done

# ---- detection and timing, one set at a time ----
rm -rf "$OUT/det"
: > "$OUT/times.txt"
: > "$OUT/scores.txt"
for sd in $set_dirs; do
    label=${sd%%:*}
    dir=${sd#*:}
    frames=
    for img in "$dir"/*.pgm; do
        [ -f "$dir/$(basename "$img" .pgm).lines.txt" ] && frames="$frames $img"
    done
    [ -n "$frames" ] || continue
    echo "peers.sh: $label" >&2
    mkdir -p "$OUT/det/$label"
    # shellcheck disable=SC2086
    "$BIN/symline-peers" --repeat "$REPEAT" "$OUT/det/$label" $frames | sed "s|^|$label |" >> "$OUT/times.txt"
    for det in "$OUT/det/$label"/*/; do
        det=$(basename "$det")
        for img in $frames; do
            name=$(basename "$img" .pgm)
            s=$("$BIN/symline-score" gt "$dir/$name" "$OUT/det/$label/$det/$name.json" | head -n 1)
            size=$(awk -v l="$label" -v d="$det" -v n="$name" '$1 == l && $2 == d && $4 == n { print $3 }' "$OUT/times.txt" | tail -n 1)
            echo "$label $det $size $name $s" >> "$OUT/scores.txt"
        done
    done
done

# ---- the table ----
echo "| detector | ms/frame 320x240 | ms/frame 640x480 | time / symline 320x240 | time / symline 640x480 | F1 320x240 | F1 640x480 |"
echo "|---|---:|---:|---:|---:|---:|---:|"
awk -v times="$OUT/times.txt" '
    FILENAME == times { ms[$2, $3] += $5; n[$2, $3]++; if (!($2 in seen)) { seen[$2] = 1; order[++nd] = $2 }; next }
    { for (i = 5; i <= NF; i++) if ($i ~ /^f1=/) { f1[$2, $3] += substr($i, 4); nf[$2, $3]++ } }
    END {
        split("320x240 640x480", sz, " ")
        for (k = 1; k <= nd; k++) {
            d = order[k]
            row = "| " d " |"
            for (j = 1; j <= 2; j++) { s = sz[j]; row = row (n[d, s] ? sprintf(" %.2f |", ms[d, s] / n[d, s]) : " - |") }
            for (j = 1; j <= 2; j++) {
                s = sz[j]
                row = row ((n[d, s] && ms["symline", s] > 0) ? sprintf(" %.2f |", (ms[d, s] / n[d, s]) / (ms["symline", s] / n["symline", s])) : " - |")
            }
            for (j = 1; j <= 2; j++) { s = sz[j]; row = row (nf[d, s] ? sprintf(" %.3f |", f1[d, s] / nf[d, s]) : " - |") }
            print row
        }
    }' "$OUT/times.txt" "$OUT/scores.txt"
echo
nf=$(awk '$2 == "symline" { n[$3]++ } END { printf "%d at 320x240, %d at 640x480", n["320x240"], n["640x480"] }' "$OUT/times.txt")
echo "Frames: $nf ($DATA/synth and the rendered sets $SETS, seed $SEED, $COUNT per set and size)."
echo "Time: thread CPU time of the detection call, the fastest of $REPEAT interleaved calls per frame,"
echo "mean over the frames; one thread (cv::setNumThreads(1)). symline = default configuration,"
echo "symline-h1 = horizontal axis at one scale. OpenCV $(pkg-config --modversion opencv4 2>/dev/null || echo '?'),"
echo "$(gcc --version | head -n 1), $(uname -m); load average at the end: $(cut -d' ' -f1-3 /proc/loadavg 2>/dev/null || echo '?')."
echo "Per frame: $OUT/times.txt (set detector size frame fastest_ms median_ms), $OUT/scores.txt."

#!/bin/sh
# SPDX-License-Identifier: Apache-2.0
# Instructions per pixel of every stage of the detection, counted by callgrind:
# symline-bench --callgrind-stage STAGE runs the detections with callgrind
# counting only while that stage runs (the profiled core's stage marks toggle
# the counting, include/symline/profile.h). Deterministic for a binary and its
# input; the stages add up to the whole detection (tools/bench/icount.sh) up to
# the few instructions of the marks themselves.
#
# usage: tools/bench/stages.sh [--build DIR] [--opts "OPTIONS"]... FRAME...
#   --build DIR    build directory with bin/symline-bench (default: REPO/build)
#   --opts "..."   detector options (as for `symline lines`) of one column;
#                  repeat for more columns (default: the default detection)
# Prints one table per frame: stage, then per column instructions per pixel.
set -eu

# shellcheck source=../args.sh
. "$(dirname "$0")/../args.sh"
BUILD=$REPO/build
ARGS_COMMON="build columns"
while [ $# -gt 0 ]; do
    case $1 in
        --) shift; break ;;
        -*) args_common "$@"; shift "$ARGS_SHIFT" ;;
        *) break ;;
    esac
done
[ $# -ge 1 ] || args_error "no FRAME given"
args_dirs
args_columns
BENCH=$BUILD/bin/symline-bench
command -v valgrind >/dev/null || { echo "stages.sh: valgrind is needed (apt-get install -y valgrind)" >&2; exit 2; }
[ -x "$BENCH" ] || { echo "stages.sh: no $BENCH (build first: cmake --build --preset default)" >&2; exit 2; }
STAGES=$("$BENCH" --list-stages)
TMP=$(mktemp -d)
trap 'rm -rf "$TMP"' EXIT

# Instructions per pixel of STAGE: STAGE FRAME OPTS
per_pixel() {
    # shellcheck disable=SC2086
    valgrind --tool=callgrind --collect-atstart=no --callgrind-out-file="$TMP/cg" \
        "$BENCH" --callgrind-stage "$1" --repeat 2 $3 "$2" > "$TMP/out" 2> "$TMP/vg" ||
        { cat "$TMP/vg" >&2; exit 1; }
    ir=$(sed -n 's/^totals: *\([0-9]*\).*/\1/p' "$TMP/cg")
    px=$(sed -n 's/^pixels //p' "$TMP/out")
    awk -v ir="${ir:-0}" -v px="$px" 'BEGIN { printf "%.2f", ir / px }'
}

for frame in "$@"; do
    [ -f "$frame" ] || { echo "stages.sh: no frame '$frame'" >&2; exit 2; }
    echo "$(basename "$frame"):"
    echo
    hdr="| stage |"
    sep="|---|"
    i=1
    while [ "$i" -le "$NOPTS" ]; do
        eval "o=\$OPTS_$i"
        hdr="$hdr ${o:-default} instr/px |"
        sep="$sep---:|"
        i=$((i + 1))
    done
    echo "$hdr"
    echo "$sep"
    : > "$TMP/sum"
    for st in $STAGES; do
        row="| $st |"
        i=1
        while [ "$i" -le "$NOPTS" ]; do
            eval "o=\$OPTS_$i"
            v=$(per_pixel "$st" "$frame" "$o")
            echo "$i $v" >> "$TMP/sum"
            row="$row $v |"
            i=$((i + 1))
        done
        echo "$row"
    done
    row="| all stages |"
    i=1
    while [ "$i" -le "$NOPTS" ]; do
        row="$row $(awk -v c="$i" '$1 == c { s += $2 } END { printf "%.1f", s }' "$TMP/sum") |"
        i=$((i + 1))
    done
    echo "$row"
    echo
done
echo "valgrind --tool=callgrind, $BENCH --callgrind-stage; $(gcc --version | head -n 1)"

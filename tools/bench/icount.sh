#!/bin/sh
# SPDX-License-Identifier: Apache-2.0
# Instructions per pixel of one full detection (`symline lines`), counted by
# callgrind: deterministic for a binary and its input, unlike seconds on a shared
# machine. Reading the frame, allocating and printing JSON cost the same at every
# repeat count, so one detection is (count(--repeat 11) - count(--repeat 1)) / 10.
#
# usage: tools/bench/icount.sh [--build DIR] [--opts "OPTIONS"]... [--within T]... FRAME...
#   --build DIR    build directory with bin/symline (default: REPO/build)
#   --opts "..."   `symline lines` options of one column; repeat for more
#                  columns (default: one column, the default detection)
#   --within T     with two frames or more, also count per column the frames
#                  of at most T instructions per pixel; repeat for more T
# Prints one row per frame: name, size, then per column the instructions of one
# detection per pixel (and in millions per frame); with two frames or more,
# their mean and largest per pixel (and in millions per frame) below.
set -eu

# shellcheck source=../args.sh
. "$(dirname "$0")/../args.sh"
BUILD=$REPO/build
ARGS_COMMON="build columns"
WITHIN=
while [ $# -gt 0 ]; do
    case $1 in
        --within | --within=*)
            args_value "$@"
            case $ARGS_VALUE in '' | .* | *.*.* | *[!0-9.]*) args_error "--within needs a number" ;; esac
            WITHIN="$WITHIN $ARGS_VALUE"
            shift "$ARGS_SHIFT" ;;
        --) shift; break ;;
        -*) args_common "$@"; shift "$ARGS_SHIFT" ;;
        *) break ;;
    esac
done
[ $# -ge 1 ] || args_error "no FRAME given"
args_dirs
args_columns
BIN=$BUILD/bin/symline
command -v valgrind >/dev/null || { echo "icount.sh: valgrind is needed (apt-get install -y valgrind)" >&2; exit 2; }
[ -x "$BIN" ] || { echo "icount.sh: no $BIN (build first: cmake --preset default && cmake --build --preset default)" >&2; exit 2; }
TMP=$(mktemp -d)
trap 'rm -rf "$TMP"' EXIT

# Instructions of `symline lines OPTS --repeat N FRAME` (callgrind's total).
count() { # N FRAME OPTS
    # shellcheck disable=SC2086
    valgrind --tool=callgrind --callgrind-out-file="$TMP/cg" "$BIN" lines $3 --repeat "$1" "$2" \
        > "$TMP/out.json" 2> "$TMP/vg.txt" || { cat "$TMP/vg.txt" >&2; exit 1; }
    sed -n 's/^totals: *\([0-9]*\).*/\1/p' "$TMP/cg"
}

hdr="| frame | size |"
sep="|---|---|"
i=1
while [ "$i" -le "$NOPTS" ]; do
    eval "o=\$OPTS_$i"
    hdr="$hdr ${o:-default} instr/px (M/frame) |"
    sep="$sep---:|"
    i=$((i + 1))
done
echo "$hdr"
echo "$sep"
for frame in "$@"; do
    [ -f "$frame" ] || { echo "icount.sh: no frame '$frame'" >&2; exit 2; }
    row=
    i=1
    while [ "$i" -le "$NOPTS" ]; do
        eval "o=\$OPTS_$i"
        c1=$(count 1 "$frame" "$o")
        c11=$(count 11 "$frame" "$o")
        # The frame's size from the detection's own JSON (any format imgio reads).
        wh=$(tr ',{}' '\n\n\n' < "$TMP/out.json" | sed -n 's/^ *"\(width\|height\)": *\([0-9]*\).*/\2/p' | head -n 2 | tr '\n' ' ')
        px=$(echo "$wh" | awk '{print $1 * $2}')
        [ -n "$row" ] || row="| $(basename "$frame") | $(echo "$wh" | awk '{print $1 "x" $2}') |"
        # the cell, and column, per pixel, per frame exact for the summary rows
        row="$row $(awk -v a="$c1" -v b="$c11" -v px="$px" -v c="$i" -v sum="$TMP/sum" \
            'BEGIN { d = (b - a) / 10; printf "%d %.17g %.17g\n", c, d / px, d >> sum
                     printf "%.1f (%.2f)", d / px, d / 1e6 }') |"
        i=$((i + 1))
    done
    echo "$row"
done
if [ $# -ge 2 ]; then
    # Means of the exact counts, so they can differ from means of the rounded
    # rows in the last digit.
    awk -v ncol="$NOPTS" -v nf="$#" -v within="$WITHIN" '
        BEGIN { nt = split(within, t, " ") }
        { s[$1] += $2; m[$1] += $3; if ($2 > mx[$1]) { mx[$1] = $2; mm[$1] = $3 }
          for (k = 1; k <= nt; k++) if ($2 <= t[k] + 0) w[$1, k]++ }
        END {
            r1 = "| mean of " nf " frames | |"; r2 = "| largest | |"
            for (c = 1; c <= ncol; c++) {
                r1 = r1 sprintf(" %.2f (%.2f) |", s[c] / nf, m[c] / nf / 1e6)
                r2 = r2 sprintf(" %.1f (%.2f) |", mx[c], mm[c] / 1e6)
            }
            print r1; print r2
            for (k = 1; k <= nt; k++) {
                r = "| frames within " t[k] " | |"
                for (c = 1; c <= ncol; c++) r = r sprintf(" %d |", w[c, k] + 0)
                print r
            }
        }' "$TMP/sum"
fi
echo
echo "valgrind --tool=callgrind, $BIN; $(gcc --version | head -n 1)"

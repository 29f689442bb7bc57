#!/bin/sh
# SPDX-License-Identifier: Apache-2.0
# Scores the intersections `symline lines` reports (JSON key "intersections")
# against those of the ground-truth segments (symline-ixscore), per set:
#   - the given synthetic scenes DATA_DIR/synth,
#   - rendered sets normal, occluded, circle at 320x240 and 640x480
#     (symline-render, fixed seed),
#   - the annotated real frames DATA_DIR/field (those with NAME.lines.txt).
# Prints one table: reference and detected intersections, true and false
# positives, misses, precision, recall, share of matches with the right type,
# mean position error (px) of the matches and mean ray error (degrees) of the
# type-correct ones. Matching: see `symline-ixscore --help`.
#
# usage: tools/eval/intersections.sh DATA_DIR [options]
#   --build DIR   build directory (default: REPO/build; built when needed)
#   --out DIR     work folder (default: REPO/out/ixeval)
#   --count N     images per rendered set and size (default 20)
#   --seed N      renderer seed (default 2026)
#   --opts "..."  extra options for every `symline lines` run
#   --per-image   also print one line per image
#   --jobs N      parallel jobs (default 2)
set -eu

# shellcheck source=../args.sh
. "$(dirname "$0")/../args.sh"
args_data "$@"
shift
BUILD=$REPO/build
OUT=$REPO/out/ixeval
COUNT=20
SEED=2026
OPTS=
PER_IMAGE=0
JOBS=2
ARGS_COMMON="build out count seed opts jobs"
while [ $# -gt 0 ]; do
    case $1 in
        --per-image) PER_IMAGE=1; shift ;;
        *) args_common "$@"; shift "$ARGS_SHIFT" ;;
    esac
done
args_dirs

if [ ! -f "$BUILD/CMakeCache.txt" ]; then
    cmake -S "$REPO" -B "$BUILD" -DCMAKE_BUILD_TYPE=Release >&2
fi
cmake --build "$BUILD" -j2 --target symline_cli symline-render symline-ixscore >&2
BIN=$BUILD/bin
mkdir -p "$OUT/render" "$OUT/det"

# rendered sets (kept while the renderer, seed and count stay the same)
RSUM=$(cksum < "$BIN/symline-render" | cut -d' ' -f1)
SETS=
for size in 320x240 640x480; do
    for set in normal occluded circle; do
        d=$OUT/render/$set-$size
        if [ ! -f "$d/.stamp" ] || [ "$(cat "$d/.stamp")" != "$RSUM $SEED $COUNT" ]; then
            rm -rf "$d"
            "$BIN/symline-render" --set "$set" --seed "$SEED" --count "$COUNT" --size "$size" "$d" >/dev/null
            echo "$RSUM $SEED $COUNT" > "$d/.stamp"
        fi
        SETS="$SETS $set-$size:$d"
    done
done
SETS="synth:$DATA/synth $SETS field:$DATA/field"

# one detection per image: "NAME JSON" pairs, run in parallel
: > "$OUT/todo"
for sd in $SETS; do
    label=${sd%%:*}
    dir=${sd#*:}
    [ -d "$dir" ] || continue
    for gt in "$dir"/*.lines.txt; do
        [ -f "$gt" ] || continue
        name=${gt%.lines.txt}
        echo "$name $OUT/det/$label.$(basename "$name").json" >> "$OUT/todo"
    done
done
# shellcheck disable=SC2016
SYMLINE="$BIN/symline" LINES_OPTS="$OPTS" xargs -P "$JOBS" -n 2 sh -c '
    # shellcheck disable=SC2086
    "$SYMLINE" lines $LINES_OPTS "$0.pgm" > "$1" 2>/dev/null || echo "{\"segments\": []}" > "$1"
' < "$OUT/todo"

: > "$OUT/scores"
while read -r name json; do
    label=$(basename "$json")
    label=${label%%.*}
    echo "$label $(basename "$name") $("$BIN/symline-ixscore" "$name" "$json")" >> "$OUT/scores"
done < "$OUT/todo"

[ "$PER_IMAGE" -eq 0 ] || cat "$OUT/scores"
echo "# intersections: detected against those of the ground truth (symline-ixscore)"
echo
echo "Data: $DATA; rendered sets: seed $SEED, $COUNT images per set and size; build: $BIN"
echo
awk '
function kv(s, k,    i, n, a, b) { n = split(s, a, " "); for (i = 1; i <= n; i++) { split(a[i], b, "="); if (b[1] == k) return b[2] + 0 } return 0 }
{
    s = $1; line = $0
    if (!(s in seen)) { seen[s] = 1; order[++ns] = s }
    ref[s] += kv(line, "ref"); det[s] += kv(line, "det"); tp[s] += kv(line, "tp")
    fp[s] += kv(line, "fp"); fn[s] += kv(line, "fn"); tok[s] += kv(line, "type_ok")
    pos[s] += kv(line, "pos_err") * kv(line, "tp"); ray[s] += kv(line, "ray_err") * kv(line, "type_ok")
}
function row(name, r, d, t, f, m, o, pe, re) {
    printf "| %s | %d | %d | %d | %d | %d | %.3f | %.3f | %.3f | %.2f | %.2f |\n", name, r, d, t, f, m,
        (t + f) ? t / (t + f) : 1, (t + m) ? t / (t + m) : 1, t ? o / t : 0, t ? pe / t : 0, o ? re / o : 0
}
END {
    print "| set | ref | det | TP | FP | FN | P | R | type | pos err px | ray err deg |"
    print "|---|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|"
    for (i = 1; i <= ns; i++) {
        s = order[i]
        row(s, ref[s], det[s], tp[s], fp[s], fn[s], tok[s], pos[s], ray[s])
        if (s != "field") { R += ref[s]; D += det[s]; T += tp[s]; F += fp[s]; M += fn[s]; O += tok[s]; P += pos[s]; Y += ray[s] }
    }
    row("all synthetic", R, D, T, F, M, O, P, Y)
}' "$OUT/scores"

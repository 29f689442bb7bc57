#!/bin/sh
# SPDX-License-Identifier: Apache-2.0
# The tracer against the Muff-space line finder, as the paper compared them:
# accuracy (mean F1 per synthetic set and on the annotated real frames),
# time per frame, instructions per pixel (callgrind), working memory and code
# size (Cortex-M4 -Os, per module). Prints a Markdown report on stdout.
#
# usage: tools/eval/methods.sh DATA_DIR [options]
#   --build DIR   host build directory (default: REPO/build; configured and built when needed)
#   --out DIR     work folder (default: REPO/out/methods)
#   --count N     images per rendered set and size (default 20)
#   --seed N      renderer seed (default 2026, as tools/eval/evaluate.sh)
#   --repeat N    detections per frame for the time per frame (default 20)
#   --jobs N      parallel jobs (default 2)
# DATA_DIR/synth: the given synthetic scenes; DATA_DIR/field: real frames, those
# with NAME.lines.txt are scored (line-free ones, with empty ground truth, by
# their number of segments). Both methods run at default settings with
# --axis both (the default); the Muff finder with `symline lines --method muff`.
set -eu

# shellcheck source=../args.sh
. "$(dirname "$0")/../args.sh"
args_data "$@"
shift
BUILD=$REPO/build
OUT=$REPO/out/methods
COUNT=20
SEED=2026
REPEAT=20
JOBS=2
ARGS_COMMON="build out count seed repeat jobs"
while [ $# -gt 0 ]; do
    args_common "$@"
    shift "$ARGS_SHIFT"
done
args_dirs
command -v valgrind >/dev/null || { echo "methods.sh: valgrind is needed (apt-get install valgrind)" >&2; exit 2; }

if [ ! -f "$BUILD/CMakeCache.txt" ]; then
    cmake -S "$REPO" -B "$BUILD" -DCMAKE_BUILD_TYPE=Release >&2
fi
cmake --build "$BUILD" -j2 --target symline_cli symline-render symline-score symline_bench_methods >&2
BIN=$BUILD/bin
METHODS="tracer muff"
mkdir -p "$OUT"

# ---- rendered sets (as evaluate.sh: same sets, sizes, seed and count) ----
SETS="normal dark overexposed occluded circle"
set_dirs=
[ -d "$DATA/synth" ] && set_dirs="given:$DATA/synth"
: > "$OUT/render.todo"
for size in 320x240 640x480; do
    for set in $SETS; do
        d=$OUT/render/$set-$size
        set_dirs="$set_dirs $set-${size%%x*}:$d"
        if [ ! -f "$d/.stamp" ] || [ "$(cat "$d/.stamp")" != "$SEED $COUNT" ]; then
            rm -rf "$d"
            mkdir -p "$d"
            echo "--set $set --seed $SEED --count $COUNT --size $size $d" >> "$OUT/render.todo"
        fi
    done
done
if [ -s "$OUT/render.todo" ]; then
    xargs -P "$JOBS" -n 9 "$BIN/symline-render" < "$OUT/render.todo" >&2
    while read -r _ _ _ _ _ _ _ _ d; do echo "$SEED $COUNT" > "$d/.stamp"; done < "$OUT/render.todo"
fi
[ -d "$DATA/field" ] && set_dirs="$set_dirs field:$DATA/field"

# ---- detections and scores ----
rm -rf "$OUT/det"
: > "$OUT/detect.todo"
for sd in $set_dirs; do
    label=${sd%%:*}
    dir=${sd#*:}
    for img in "$dir"/*.pgm; do
        name=$(basename "$img" .pgm)
        [ -f "$dir/$name.lines.txt" ] || continue
        for m in $METHODS; do echo "$m $img $OUT/det/$m/$label/$name.json" >> "$OUT/detect.todo"; done
    done
done
# shellcheck disable=SC2016
SYMLINE="$BIN/symline" xargs -P "$JOBS" -n 3 sh -c '
    mkdir -p "$(dirname "$2")"
    "$SYMLINE" lines --method "$0" "$1" > "$2" 2> "$2.err" || echo "{\"segments\": []}" > "$2"' < "$OUT/detect.todo"
: > "$OUT/scores.txt"
: > "$OUT/linefree.txt"
while read -r m img json; do
    label=$(basename "$(dirname "$json")")
    name=${img%.pgm}
    if [ ! -s "$name.lines.txt" ] && [ ! -s "$name.arcs.txt" ]; then
        # a line-free frame: F1 is 0 or 1 there, so it is reported as a segment count
        echo "$m $(tr '{' '\n' < "$json" | grep -c '"x0"' || true) $(basename "$name")" >> "$OUT/linefree.txt"
        continue
    fi
    s=$("$BIN/symline-score" gt "$name" "$json" | head -n 1)
    echo "$m $label $s" >> "$OUT/scores.txt"
done < "$OUT/detect.todo"

# mean KEY of method M over set L (all synthetic sets: L = synth)
mean() {
    awk -v m="$1" -v l="$2" -v k="$3" '$1 == m && ($2 == l || (l == "synth" && $2 != "field")) {
            for (i = 3; i <= NF; i++) { split($i, kv, "="); if (kv[1] == k) { s += kv[2]; n++ } } }
        END { if (n) printf "%.3f", s / n; else printf "-" }' "$OUT/scores.txt"
}
setmean() { # mean over the synthetic sets of the per-set mean F1
    for sd in $set_dirs; do
        l=${sd%%:*}
        [ "$l" = field ] || mean "$1" "$l" f1 && echo
    done | awk 'NF { s += $1; n++ } END { printf "%.3f", s / n }'
}

echo "# Tracer and Muff-space line finder"
echo
echo "Data: $DATA; rendered sets: seed $SEED, $COUNT images per set and size; build: $BIN."
echo "F1, precision P and recall R: mean per image (the scoring of docs/evaluation.md, symline-score gt)."
echo
echo "| set | n | tracer F1 | P | R | muff F1 | P | R |"
echo "|---|---:|---:|---:|---:|---:|---:|---:|"
for sd in $set_dirs; do
    l=${sd%%:*}
    n=$(awk -v l="$l" '$1 == "tracer" && $2 == l' "$OUT/scores.txt" | wc -l)
    row="| $l | $n |"
    for m in $METHODS; do row="$row $(mean $m "$l" f1) | $(mean $m "$l" p) | $(mean $m "$l" r) |"; done
    echo "$row"
done
echo "| mean of the synthetic sets | | $(setmean tracer) | | | $(setmean muff) | | |"
if [ -s "$OUT/linefree.txt" ]; then
    echo
    echo "Line-free real frames (empty ground truth), segments reported:"
    echo
    echo "| frame | tracer | muff |"
    echo "|---|---:|---:|"
    awk '{ seg[$3, $1] = $2; if (!($3 in seen)) { seen[$3] = 1; order[++n] = $3 } }
         END { for (k = 1; k <= n; k++) printf "| %s | %s | %s |\n", order[k], seg[order[k], "tracer"], seg[order[k], "muff"] }' "$OUT/linefree.txt"
fi
echo

# ---- time, instructions, memory ----
echo "| frame | method | time per frame | instructions per pixel | workspace | accumulator | line points (4 B each) | segments |"
echo "|---|---|---:|---:|---:|---:|---:|---:|"
for size in 320 640; do
    frame=$OUT/render/normal-${size}x$((size * 3 / 4))/normal_000.pgm
    for m in $METHODS; do
        b=$("$BIN/symline-bench-methods" "$m" "$REPEAT" "$frame")
        fn=symline_detect
        [ "$m" = muff ] && fn=symline_detect_muff
        valgrind --tool=callgrind --callgrind-out-file="$OUT/cg.$m.$size" --toggle-collect="$fn" \
            "$BIN/symline-bench-methods" "$m" 1 "$frame" >/dev/null 2>&1
        ir=$(callgrind_annotate "$OUT/cg.$m.$size" 2>/dev/null | awk '/PROGRAM TOTALS/ { gsub(",", "", $1); print $1; exit }')
        echo "$b" | awk -v ir="$ir" -v f="normal_000 ${size}" '{
            for (i = 1; i <= NF; i++) { split($i, kv, "="); v[kv[1]] = kv[2] }
            printf "| %s | %s | %.2f ms | %.0f | %d B | %d B | %d | %d |\n", f, v["method"],
                   v["ns_per_frame"] / 1e6, ir / (v["width"] * v["height"]), v["workspace"],
                   v["accumulator"], v["line_points"], v["segments"] }'
    done
done
echo
echo "Time: mean of $REPEAT calls on this machine (shared; the instruction counts are the"
echo "stable figure): callgrind, inclusive cost of the detection call, per pixel."

# ---- code size, Cortex-M4 -Os ----
if command -v arm-none-eabi-gcc >/dev/null; then
    fw=$OUT/fw-m4-os
    cmake -S "$REPO" -B "$fw" -DCMAKE_TOOLCHAIN_FILE="$REPO/port/toolchains/arm-none-eabi.cmake" \
        -DCMAKE_BUILD_TYPE=MinSizeRel -DSYMLINE_CPU=cortex-m4 >/dev/null
    cmake --build "$fw" --target symline -j "$JOBS" >/dev/null
    for o in $(find "$fw/lib" -name '*.obj' | sort); do
        arm-none-eabi-size -A "$o" | awk -v f="$(basename "$o" .c.obj)" \
            '$1 ~ /^\.(text|rodata)/ { s += $2 } END { printf "%s %d\n", f, s }'
    done > "$OUT/sizes.txt"
    echo
    echo "Code size, Cortex-M4 -Os (.text + .rodata, arm-none-eabi-gcc $(arm-none-eabi-gcc -dumpversion)),"
    echo "per module of libsymline.a:"
    echo
    echo "| part | modules | bytes |"
    echo "|---|---|---:|"
    awk 'BEGIN {
            g["status"] = "shared"; g["fixed"] = "shared"; g["symmetry"] = "shared"; g["extrema"] = "shared";
            g["linefilter"] = "shared"; g["linepoints"] = "shared"; g["subpixel"] = "shared";
            g["tracer"] = "tracer"; g["segments"] = "tracer"; g["merge"] = "tracer";
            g["curvejoin"] = "tracer"; g["pass"] = "tracer"; g["detect"] = "tracer";
            g["framepoints"] = "muff"; g["muff"] = "muff"; g["muff_vote"] = "muff";
            g["muff_extent"] = "muff"; g["muff_detect"] = "muff" }
        ($1 in g) { s[g[$1]] += $2; mods[g[$1]] = mods[g[$1]] (mods[g[$1]] ? ", " : "") $1 }
        END {
            printf "| operator, extrema, line filter (both methods) | %s | %d |\n", mods["shared"], s["shared"]
            printf "| tracer: passes, tracing, segments, merge | %s | %d |\n", mods["tracer"], s["tracer"]
            printf "| Muff space: line points, voting, peaks, extents | %s | %d |\n", mods["muff"], s["muff"] }' "$OUT/sizes.txt"
    echo
    echo "What a firmware calling only one entry point links (-Wl,--gc-sections, .text + .rodata;"
    echo "the Muff finder reuses the tracer pass's setup and neighbour lookup):"
    echo
    echo "| entry point | bytes |"
    echo "|---|---:|"
    for e in symline_detect symline_detect_muff symline_muff_find symline_features symline_histogram; do
        arm-none-eabi-gcc -mcpu=cortex-m4 -mthumb -mfloat-abi=hard -mfpu=fpv4-sp-d16 -nostartfiles \
            -nostdlib -Wl,--gc-sections -Wl,--entry="$e" -Wl,-u,"$e" "$fw/lib/libsymline.a" -lgcc \
            -o "$OUT/link.$e.elf"
        echo "| $e | $(arm-none-eabi-size -A "$OUT/link.$e.elf" | awk '$1 ~ /^\.(text|rodata)/ { s += $2 } END { print s }') |"
    done
fi

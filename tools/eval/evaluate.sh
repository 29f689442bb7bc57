#!/bin/sh
# SPDX-License-Identifier: Apache-2.0
# Evaluates `symline lines` on every set and prints one table per set kind:
#   - the given synthetic scenes DATA_DIR/synth (ground truth in the synth README formats),
#   - the rendered sets normal, dark, overexposed, occluded, circle at 320x240 and
#     640x480 (symline-render, fixed seeds),
#   - the real frames DATA_DIR/field: against hand ground truth where NAME.lines.txt
#     exists (P, R, F1, segments, fragmentation, centre error; line-free frames: their
#     segment count), F1 against a line mask where one exists, stability F1 against
#     the same frame with brightness x0.5, +40 and -40, and the annotated frames' F1
#     against ground truth at those brightnesses and at half and twice the size.
# Every set is run with each filter side by side (default: the paper's A1-S filter
# and the shipped default). Scoring: see docs/evaluation.md.
#
# usage: tools/eval/evaluate.sh DATA_DIR [options]
#   --build DIR      build directory (default: REPO/build; configured and built when needed)
#   --out DIR        work folder for renders and detections (default: REPO/out/eval)
#   --filter NAME    a column to compare: "default" (no --filter option) or a value of
#                    `symline lines --filter`; repeat for several (default: paper, default)
#   --count N        images per rendered set and size (default 20)
#   --seed N         renderer seed (default 2026)
#   --sizes "WxH .." rendered sizes (default "320x240 640x480")
#   --opts "..."     extra options for every `symline lines` run
#   --per-image      also print one row per image
#   --overlays       also draw the detections on every real frame (OUT/overlay/FILTER/NAME.png)
#   --jobs N         parallel jobs (default 2)
#   --real-only      only the table of the annotated real frames (fast; default --out
#                    REPO/out/eval-real)
set -eu

# shellcheck source=../args.sh
. "$(dirname "$0")/../args.sh"
args_data "$@"
shift
BUILD=$REPO/build
OUT=$REPO/out/eval
FILTERS=
COUNT=20
SEED=2026
SIZES="320x240 640x480"
OPTS=
PER_IMAGE=0
OVERLAYS=0
JOBS=2
REAL_ONLY=0
OUT_SET=0
ARGS_COMMON="build out count seed opts jobs"
while [ $# -gt 0 ]; do
    case $1 in
        --filter | --filter=*) args_value "$@"; FILTERS="$FILTERS $ARGS_VALUE"; shift "$ARGS_SHIFT" ;;
        --sizes | --sizes=*) args_value "$@"; SIZES=$ARGS_VALUE; shift "$ARGS_SHIFT" ;;
        --per-image) PER_IMAGE=1; shift ;;
        --overlays) OVERLAYS=1; shift ;;
        --real-only) REAL_ONLY=1; shift ;;
        *)
            case $1 in --out | --out=*) OUT_SET=1 ;; esac
            args_common "$@"
            shift "$ARGS_SHIFT" ;;
    esac
done
[ -n "$FILTERS" ] || FILTERS="paper default"
[ "$REAL_ONLY" -eq 0 ] || [ "$OUT_SET" -eq 1 ] || OUT=$REPO/out/eval-real
args_dirs

# ---- tools: Debian packages, then an incremental build of the four binaries ----
# shellcheck source=../../capture/tests/pkgs.sh
. "$REPO/capture/tests/pkgs.sh"
if command -v dpkg >/dev/null 2>&1; then
    need_pkgs cmake make gcc libc6-dev pkg-config libpng-dev libcmocka-dev
fi
if [ ! -f "$BUILD/CMakeCache.txt" ]; then
    cmake -S "$REPO" -B "$BUILD" -DCMAKE_BUILD_TYPE=Release >&2
fi
cmake --build "$BUILD" -j2 --target symline_cli symline-render symline-score symline-bright symline-resize >&2
BIN=$BUILD/bin
for b in symline symline-render symline-score symline-bright symline-resize; do
    [ -x "$BIN/$b" ] || { echo "evaluate.sh: $BIN/$b missing after the build" >&2; exit 1; }
done
"$BIN/symline" lines --help >/dev/null 2>&1 || { echo "evaluate.sh: this symline has no 'lines' command" >&2; exit 1; }

mkdir -p "$OUT"
START=$(date +%s)

# ---- rendered sets (cached: the renderer is deterministic for its binary and arguments) ----
SETS="normal dark overexposed occluded circle"
[ "$REAL_ONLY" -eq 0 ] || { SETS=; SIZES=; }
RSUM=$(cksum < "$BIN/symline-render" | cut -d' ' -f1)
mkdir -p "$OUT/render"
: > "$OUT/render.todo"
for size in $SIZES; do
    for set in $SETS; do
        d=$OUT/render/$set-$size
        if [ ! -f "$d/.stamp" ] || [ "$(cat "$d/.stamp")" != "$RSUM $SEED $COUNT" ]; then
            rm -rf "$d"
            echo "--set $set --seed $SEED --count $COUNT --size $size --labels $d" >> "$OUT/render.todo"
        fi
    done
done
if [ -s "$OUT/render.todo" ]; then
    echo "evaluate.sh: rendering $(wc -l < "$OUT/render.todo") sets of $COUNT images" >&2
    xargs -P "$JOBS" -n 10 "$BIN/symline-render" < "$OUT/render.todo"
    while read -r _ _ _ _ _ _ _ _ _ d; do
        echo "$RSUM $SEED $COUNT" > "$d/.stamp"
    done < "$OUT/render.todo"
fi

# ---- detection: one JSON per image and filter (pairs "IMAGE JSON" per filter) ----
rm -rf "$OUT/det"
for f in $FILTERS; do : > "$OUT/detect.$f.todo"; done
add_job() { # IMAGE JSON FILTER [BINNING]: BINNING --bin=off, else the default
    echo "$1 $2 ${4:---bin=auto}" >> "$OUT/detect.$3.todo"
}
GIVEN=$DATA/synth
set_dirs=
[ -d "$GIVEN" ] && [ "$REAL_ONLY" -eq 0 ] && set_dirs="given:$GIVEN"
for size in $SIZES; do
    for set in $SETS; do set_dirs="$set_dirs $set-${size%%x*}:$OUT/render/$set-$size"; done
done
for sd in $set_dirs; do
    label=${sd%%:*}
    dir=${sd#*:}
    for img in "$dir"/*.pgm; do
        [ -f "$img" ] || continue
        name=$(basename "$img" .pgm)
        [ -f "$dir/$name.lines.txt" ] || continue
        for f in $FILTERS; do add_job "$img" "$OUT/det/$f/$label/$name.json" "$f"; done
    done
done

# Real frames and their brightness variants (--real-only: the annotated frames alone).
FIELD=$DATA/field
TR=$OUT/field-variants
mkdir -p "$TR"
FRAMES=
ANNOTATED=
if [ -d "$FIELD" ]; then
    for img in "$FIELD"/*.pgm; do
        case $img in *.mask.pgm) continue ;; esac
        [ -f "$img" ] || continue
        name=$(basename "$img" .pgm)
        [ -f "$FIELD/$name.lines.txt" ] && ANNOTATED="$ANNOTATED $name"
        if [ "$REAL_ONLY" -eq 1 ]; then
            [ -f "$FIELD/$name.lines.txt" ] || continue
            for f in $FILTERS; do add_job "$img" "$OUT/det/$f/field/$name.json" "$f"; done
            continue
        fi
        FRAMES="$FRAMES $name"
        if [ -f "$FIELD/$name.lines.txt" ]; then
            # The same scene through a camera of half and of twice the pixels,
            # with the ground truth moved along (the scale table).
            "$BIN/symline-resize" --half --gt "$img" "$TR/$name.half.pgm"
            "$BIN/symline-resize" --double --gt "$img" "$TR/$name.double.pgm"
            # The double size also without the 2x2 binning that is its default.
            for k in lines arcs dontcare; do
                [ -f "$TR/$name.double.$k.txt" ] && cp "$TR/$name.double.$k.txt" "$TR/$name.double-nobin.$k.txt"
            done
            for f in $FILTERS; do
                for v in half double; do
                    add_job "$TR/$name.$v.pgm" "$OUT/det/$f/field/$name.$v.json" "$f"
                done
                add_job "$TR/$name.double.pgm" "$OUT/det/$f/field/$name.double-nobin.json" "$f" --bin=off
            done
        fi
        "$BIN/symline-bright" --mul 0.5 "$img" "$TR/$name.x0.5.pgm"
        "$BIN/symline-bright" --report --clipped "$TR/$name.p40.sat.pgm" --add 40 "$img" "$TR/$name.p40.pgm" > "$TR/$name.p40.clip"
        "$BIN/symline-bright" --report --clipped "$TR/$name.m40.sat.pgm" --add -40 "$img" "$TR/$name.m40.pgm" > "$TR/$name.m40.clip"
        for f in $FILTERS; do
            add_job "$img" "$OUT/det/$f/field/$name.json" "$f"
            for v in x0.5 p40 m40; do
                add_job "$TR/$name.$v.pgm" "$OUT/det/$f/field/$name.$v.json" "$f"
            done
        done
    done
fi
NRUNS=$(cat "$OUT"/detect.*.todo | wc -l)
echo "evaluate.sh: $NRUNS detection runs" >&2
for f in $FILTERS; do
    fo=
    [ "$f" = default ] || fo="--filter $f"
    # A failed run is scored as "no detections" and counted below.
    # shellcheck disable=SC2016
    SYMLINE="$BIN/symline" LINES_OPTS="$fo $OPTS" xargs -P "$JOBS" -n 3 sh -c '
        mkdir -p "$(dirname "$1")"
        # shellcheck disable=SC2086
        if "$SYMLINE" lines "$2" $LINES_OPTS "$0" > "$1.tmp" 2> "$1.err"; then
            mv "$1.tmp" "$1"
        else
            echo "{\"segments\": []}" > "$1"
            echo failed >> "$1.err"
        fi' < "$OUT/detect.$f.todo"
done
OVL_FRAMES=$FRAMES
[ "$REAL_ONLY" -eq 0 ] || OVL_FRAMES=$ANNOTATED
if [ "$OVERLAYS" -eq 1 ] && [ -n "$OVL_FRAMES" ]; then
    for f in $FILTERS; do
        fo=
        [ "$f" = default ] || fo="--filter $f"
        mkdir -p "$OUT/overlay/$f"
        for name in $OVL_FRAMES; do
            # shellcheck disable=SC2086
            "$BIN/symline" overlay $fo $OPTS "$FIELD/$name.pgm" "$OUT/overlay/$f/$name.png" ||
                echo "evaluate.sh: overlay of $name failed" >&2
        done
    done
fi
FAILS=$(find "$OUT/det" -name '*.err' -exec grep -l '^failed$' {} + 2>/dev/null | wc -l)

# ---- scoring and tables ----
# kv KEY LINE: value of KEY=... in a symline-score line
kv() { printf '%s\n' "$2" | tr ' ' '\n' | sed -n "s/^$1=//p"; }

# copies_table VARIANTS TITLES ALIGNS: per annotated frame with lines and filter, F1
# against ground truth on the frame and on each copy ($TR/NAME.VARIANT.pgm; scored
# against the copy's own ground truth where symline-resize moved it there, else
# the frame's), then the means; TITLES and ALIGNS are the copies' header cells.
copies_table() {
    hdr="| frame |"
    sep="|---|"
    for f in $FILTERS; do
        hdr="$hdr $f | $2"
        sep="$sep---:|$3"
    done
    echo "$hdr"
    echo "$sep"
    : > "$OUT/copiesgt.tmp"
    for name in $ANNOTATED; do
        # the line-free frames (three empty files) as in the table of the annotated frames
        [ -s "$FIELD/$name.lines.txt" ] || [ -s "$FIELD/$name.arcs.txt" ] ||
            [ -s "$FIELD/$name.dontcare.txt" ] || continue
        row=
        for f in $FILTERS; do
            for v in frame $1; do
                json=$OUT/det/$f/field/$name.$v.json gt=$FIELD/$name
                [ "$v" = frame ] && json=$OUT/det/$f/field/$name.json
                [ -f "$TR/$name.$v.lines.txt" ] && gt=$TR/$name.$v
                f1=$(kv f1 "$("$BIN/symline-score" gt "$gt" "$json" | head -n 1)")
                echo "$f $v $f1" >> "$OUT/copiesgt.tmp"
                row="$row $(printf '%.3f' "$f1") |"
            done
        done
        echo "| $name |$row"
    done
    row="| mean |"
    for f in $FILTERS; do
        for v in frame $1; do
            row="$row $(awk -v f="$f" -v v="$v" '$1 == f && $2 == v { n++; s += $3 }
                                            END { if (n) printf "%.3f", s / n; else printf "-" }' "$OUT/copiesgt.tmp") |"
        done
    done
    echo "$row"
    echo
}
PER=$OUT/per-image.txt
: > "$PER"

# Nearest-rank quantiles of a file of numbers, one per line: "median p90" ("- -" if empty).
quantiles() {
    sort -g "$1" | awk '{ v[NR] = $1 }
        function rank(q,  r) { r = int(q * NR); if (r < q * NR) r++; return r < 1 ? 1 : r }
        END { if (NR == 0) print "- -"; else printf "%.2f %.2f\n", v[rank(0.5)], v[rank(0.9)] }'
}

# The annotated real frames (NAME.lines.txt in DATA_DIR/field), one table per filter.
real_frames_table() {
    [ -n "$ANNOTATED" ] || return 0
    echo "## Real frames against hand ground truth ($FIELD)"
    echo
    echo "The frames with NAME.lines.txt (hand annotations, SOURCES.md there). P, R, F1: the"
    echo "scoring against NAME.lines.txt, .arcs.txt, .dontcare.txt. segs = reported segments."
    echo "frag = fragmentation: reported segments along each straight ground-truth piece of at"
    echo "least 40 px (a segment lies along one when at least 70 % and at least 8 of its samples"
    echo "are within tolerance of it), mean over the pieces with at least one (pieces found / all"
    echo "in brackets); 1.00 = one segment per painted line. centre = distance of the matched"
    echo "detected samples (within tolerance of ground truth, not don't-care) to the ground-truth"
    echo "centre line, median / 90th percentile in px. Line-free frames (three empty files) show"
    echo "their segment count only. Means over the frames with lines: P, R, F1 per frame;"
    echo "frag pooled (all segments along found pieces / all found pieces); centre pooled over"
    echo "the matched samples of all frames."
    for f in $FILTERS; do
        d=$OUT/det/$f/field
        cfile=$OUT/centre.$f.txt
        rows=$OUT/real.$f.tmp
        : > "$cfile"
        : > "$rows"
        echo
        echo "### Filter $f${OPTS:+, options $OPTS}"
        echo
        echo "| frame | P | R | F1 | segs | frag | centre med / p90 |"
        echo "|---|---:|---:|---:|---:|---:|---:|"
        for name in $ANNOTATED; do
            if [ ! -s "$FIELD/$name.lines.txt" ] && [ ! -s "$FIELD/$name.arcs.txt" ] &&
                [ ! -s "$FIELD/$name.dontcare.txt" ]; then
                s=$("$BIN/symline-score" gt "$FIELD/$name" "$d/$name.json" | head -n 1)
                echo "$f real-free $name $s" >> "$PER"
                echo "free $s" >> "$rows"
                echo "| $name (line-free) | | | | $(kv det_pieces "$s") | | |"
                continue
            fi
            : > "$OUT/centre.one.tmp"
            s=$("$BIN/symline-score" --centre "$OUT/centre.one.tmp" gt "$FIELD/$name" "$d/$name.json" | head -n 1)
            cat "$OUT/centre.one.tmp" >> "$cfile"
            echo "$f real $name $s" >> "$PER"
            echo "lines $s" >> "$rows"
            printf '%s\n' "$s" | awk -v name="$name" -v q="$(quantiles "$OUT/centre.one.tmp")" '
                { for (i = 1; i <= NF; i++) { split($i, kv, "="); v[kv[1]] = kv[2] } }
                END { split(q, c, " ")
                      frag = v["frag_found"] ? sprintf("%.2f (%d/%d)", v["frag_segments"] / v["frag_found"],
                                                      v["frag_found"], v["frag_pieces"]) : sprintf("- (0/%d)", v["frag_pieces"])
                      printf "| %s | %.3f | %.3f | %.3f | %d | %s | %s / %s |\n", name, v["p"], v["r"], v["f1"],
                             v["det_pieces"], frag, c[1], c[2] }'
        done
        awk -v q="$(quantiles "$cfile")" '
            { for (i = 2; i <= NF; i++) { split($i, kv, "="); v[kv[1]] = kv[2] } }
            $1 == "lines" { n++; p += v["p"]; r += v["r"]; f1 += v["f1"]; segs += v["det_pieces"]
                            fs += v["frag_segments"]; ff += v["frag_found"]; fp += v["frag_pieces"] }
            $1 == "free" { nfree++; free += v["det_pieces"] }
            END { split(q, c, " ")
                  if (n) printf "| mean of %d frames with lines | %.3f | %.3f | %.3f | %.1f | %s | %s / %s |\n",
                                n, p / n, r / n, f1 / n, segs / n,
                                ff ? sprintf("%.2f (%d/%d)", fs / ff, ff, fp) : "-", c[1], c[2]
                  if (nfree) printf "| line-free frames: %d | | | | %d | | |\n", nfree, free }' "$rows"
    done
    echo
}

finish() {
    echo "Detection runs: $NRUNS, failed: $FAILS; wall time $(($(date +%s) - START)) s."
    echo "Per-image scores: $PER; detections: $OUT/det/FILTER/SET/NAME.json."
}

if [ "$REAL_ONLY" -eq 1 ]; then
    echo "# symline line detection: annotated real frames"
    echo
    echo "Data: $DATA; build: $BIN; filters: $FILTERS."
    echo
    real_frames_table
    finish
    exit 0
fi

echo "# symline line detection: evaluation"
echo
echo "Data: $DATA; rendered sets: seed $SEED, $COUNT images per set and size; build: $BIN"
echo "Columns per filter: mean per-image F1, precision P, recall R (samples every"
echo "0.5 px, tolerance max(2, 3*width/640) px); classification of the detected pieces"
echo "matched to ground truth: line = straight ground truth reported as kind line, curve ="
echo "circle ground truth reported as kind curve, each as share of pieces / share weighted"
echo "by length (number of matched pieces). Set 'given' = DATA_DIR/synth; the others are"
echo "rendered, NAME-WIDTH. Filters: $FILTERS."
echo

hdr="| set | n |"
sep="|---|---:|"
for f in $FILTERS; do
    hdr="$hdr $f F1 | P | R | line | curve |"
    sep="$sep---:|---:|---:|---:|---:|"
done
echo "## Synthetic scenes"
echo
echo "$hdr"
echo "$sep"
: > "$OUT/setf1.tmp"
: > "$OUT/stab.tmp"
for sd in $set_dirs; do
    label=${sd%%:*}
    dir=${sd#*:}
    row=
    n=0
    for f in $FILTERS; do
        : > "$OUT/scores.tmp"
        for img in "$dir"/*.pgm; do
            [ -f "$img" ] || continue
            name=$(basename "$img" .pgm)
            [ -f "$dir/$name.lines.txt" ] || continue
            s=$("$BIN/symline-score" gt "$dir/$name" "$OUT/det/$f/$label/$name.json" | tr '\n' ' ')
            echo "$s" >> "$OUT/scores.tmp"
            echo "$f $label/$name $s" >> "$PER"
        done
        cell=$(awk 'function share(ok, m, oks, ms) {
                        return m ? sprintf("%.3f / %.3f (%d)", ok / m, oks / ms, m) : "- (0)" }
                    { for (i = 1; i <= NF; i++) { split($i, kv, "="); v[kv[1]] = kv[2] }
                      n++; f1 += v["f1"]; p += v["p"]; r += v["r"]
                      lm += v["line_matched"]; lo += v["line_ok"]; cm += v["curve_matched"]; co += v["curve_ok"]
                      lms += v["line_matched_s"]; los += v["line_ok_s"]; cms += v["curve_matched_s"]; cos_ += v["curve_ok_s"] }
                    END { if (n == 0) { print "0 | - | - | - | - | - |"; exit }
                          printf "%d | %.3f | %.3f | %.3f | %s | %s |\n", n, f1 / n, p / n, r / n,
                                 share(lo, lm, los, lms), share(co, cm, cos_, cms) }' "$OUT/scores.tmp")
        n=${cell%% *}
        row="$row ${cell#* | }"
        echo "$f $label $(echo "$cell" | cut -d'|' -f2)" >> "$OUT/setf1.tmp"
    done
    echo "| $label | $n |$row"
done
echo

real_frames_table

if [ -n "$FRAMES" ]; then
    echo "## Real frames ($FIELD)"
    echo
    echo "mask = F1 against NAME.mask.pgm where one exists (precision: detected samples within"
    echo "tolerance of a mask pixel; recall: mask pixels within tolerance of a detection)."
    echo "x0.5, +40, -40 = stability F1 between the detections on the frame and on the frame"
    echo "with that brightness change (clipped); target >= 0.95. segs = segments on the frame."
    echo "clip = share of pixels that +40 / -40 saturate (value changed by clipping): there the"
    echo "transformed frame has lost the structure, so even a perfect detector may differ."
    echo
    hdr="| frame | clip +40 | clip -40 |"
    sep="|---|---:|---:|"
    for f in $FILTERS; do
        hdr="$hdr $f segs | mask | x0.5 | +40 | -40 |"
        sep="$sep---:|---:|---:|---:|---:|"
    done
    echo "$hdr"
    echo "$sep"
    for name in $FRAMES; do
        clip=$(awk '{ for (i = 1; i <= NF; i++) { split($i, kv, "="); v[kv[1]] = kv[2] } }
                    END { printf "%.1f %%", 100 * v["clipped_high"] / v["pixels"] }' "$TR/$name.p40.clip")
        clip="$clip | $(awk '{ for (i = 1; i <= NF; i++) { split($i, kv, "="); v[kv[1]] = kv[2] } }
                    END { printf "%.1f %%", 100 * v["clipped_low"] / v["pixels"] }' "$TR/$name.m40.clip")"
        row=" $clip |"
        for f in $FILTERS; do
            d=$OUT/det/$f/field
            segs=$(tr '{' '\n' < "$d/$name.json" | grep -c '"x0"' || true)
            mask=-
            if [ -f "$FIELD/$name.mask.pgm" ]; then
                s=$("$BIN/symline-score" mask "$FIELD/$name.mask.pgm" "$d/$name.json")
                mask=$(printf '%.3f' "$(kv f1 "$s")")
                echo "$f mask $name $s" >> "$PER"
            fi
            row="$row $segs | $mask |"
            for v in x0.5 p40 m40; do
                s=$("$BIN/symline-score" pair "$d/$name.json" "$d/$name.$v.json")
                f1=$(kv f1 "$s")
                echo "$f $v $f1 $name" >> "$OUT/stab.tmp"
                echo "$f stability-$v $name $s" >> "$PER"
                row="$row $(printf '%.3f' "$f1") |"
            done
        done
        echo "| $name |$row"
    done
    row="| mean / min | | |"
    for f in $FILTERS; do
        row="$row |$(awk -v f="$f" '$1 == f && $2 == "x0.5" { n++; s += $3; if (n == 1 || $3 < m) m = $3 }
                                   END { printf " |" }' "$OUT/stab.tmp")"
        for v in x0.5 p40 m40; do
            row="$row $(awk -v f="$f" -v v="$v" '$1 == f && $2 == v { n++; s += $3; if (n == 1 || $3 < m) m = $3 }
                                            END { if (n) printf "%.3f / %.3f", s / n, m; else printf "-" }' "$OUT/stab.tmp") |"
        done
    done
    echo "$row"
    echo
    echo "### Stability outside saturated pixels"
    echo
    echo "As above, but samples (of both runs) on pixels that the change saturated are left"
    echo "out (symline-score --ignore): how stable the detector is where the transformed frame"
    echo "still holds the structure."
    echo
    hdr="| frame |"
    sep="|---|"
    for f in $FILTERS; do
        hdr="$hdr $f +40 | -40 |"
        sep="$sep---:|---:|"
    done
    echo "$hdr"
    echo "$sep"
    : > "$OUT/stabsat.tmp"
    for name in $FRAMES; do
        row=
        for f in $FILTERS; do
            d=$OUT/det/$f/field
            for v in p40 m40; do
                s=$("$BIN/symline-score" --ignore "$TR/$name.$v.sat.pgm" pair "$d/$name.json" "$d/$name.$v.json")
                f1=$(kv f1 "$s")
                echo "$f $v $f1 $name" >> "$OUT/stabsat.tmp"
                row="$row $(printf '%.3f' "$f1") |"
            done
        done
        echo "| $name |$row"
    done
    row="| mean / min |"
    for f in $FILTERS; do
        for v in p40 m40; do
            row="$row $(awk -v f="$f" -v v="$v" '$1 == f && $2 == v { n++; s += $3; if (n == 1 || $3 < m) m = $3 }
                                            END { if (n) printf "%.3f / %.3f", s / n, m; else printf "-" }' "$OUT/stabsat.tmp") |"
        done
    done
    echo "$row"
    echo
    if [ -n "$ANNOTATED" ]; then
        echo "### The brightness changes against ground truth"
        echo
        echo "The annotated frames with lines, scored against their hand ground truth as above:"
        echo "F1 on the frame and on the frame with each brightness change. A change to the"
        echo "detector that finds more on the frame and as much as before on the changed frames"
        echo "lowers the stability F1 above, not these."
        echo
        copies_table "x0.5 p40 m40" "x0.5 | +40 | -40 |" "---:|---:|---:|"
        echo "### The scale changes against ground truth"
        echo
        echo "The same frames at half and at twice their size (\`symline-resize --half\` and"
        echo "\`--double\`: 2x2 means, bilinear), the ground truth moved along; the scorer's"
        echo "tolerance follows the width. The defaults were chosen on frames 608-800 px wide;"
        echo "frames of 1024x768 pixels and more are detected binned 2x2 by default (\`--bin\`),"
        echo "the last column without."
        echo
        copies_table "half double double-nobin" "half | double | double, --bin off |" "---:|---:|---:|"
    fi
fi

# Wrong detections by rendered surface (the rendered sets carry label images).
for f in $FILTERS; do
    echo "## Where the wrong detections lie: $f"
    echo
    echo "Share of the wrong detected samples (counted, not within tolerance of ground truth)"
    echo "by the surface under them; paint = on a painted line but off its centre line"
    echo "(for example on a too-wide part, or an edge of a wide line). wrong = all wrong samples."
    echo
    echo "| set | wrong | carpet | paint | floor | wall | ceiling | robot |"
    echo "|---|---:|---:|---:|---:|---:|---:|---:|"
    grep "^$f " "$PER" | awk '/fp_carpet=/ {
            split($2, a, "/"); set = a[1]
            for (i = 3; i <= NF; i++) { split($i, kv, "="); if (kv[1] ~ /^fp_/) { v[set, kv[1]] += kv[2]; tot[set] += kv[2] } }
            if (!(set in seen)) { seen[set] = 1; order[++n] = set }
        }
        END {
            for (k = 1; k <= n; k++) {
                s = order[k]; t = tot[s]
                printf "| %s | %d |", s, t
                split("fp_carpet fp_paint fp_floor fp_wall fp_ceiling fp_robot", names, " ")
                for (j = 1; j <= 6; j++) printf " %s |", t ? sprintf("%.0f %%", 100 * v[s, names[j]] / t) : "-"
                printf "\n"
            }
        }'
    echo
done

# Recall by painted line width (from the rendered label images).
for f in $FILTERS; do
    echo "## Recall by painted line width: $f"
    echo
    echo "Share of ground-truth samples found, by the painted width across the line (pixels,"
    echo "measured on the rendered labels, +-1 px), with the number of samples."
    echo
    echo "| set | < 2 px | 2-4 px | 4-8 px | 8-16 px | >= 16 px |"
    echo "|---|---:|---:|---:|---:|---:|"
    grep "^$f " "$PER" | awk '/gtw_lt2=/ {
            split($2, a, "/"); set = a[1]
            for (i = 3; i <= NF; i++) {
                split($i, kv, "=")
                if (kv[1] ~ /^gtw_/) { split(kv[2], hn, "/"); hit[set, kv[1]] += hn[1]; num[set, kv[1]] += hn[2] }
            }
            if (!(set in seen)) { seen[set] = 1; order[++n] = set }
        }
        END {
            split("gtw_lt2 gtw_2to4 gtw_4to8 gtw_8to16 gtw_ge16", names, " ")
            for (k = 1; k <= n; k++) {
                s = order[k]
                printf "| %s |", s
                for (j = 1; j <= 5; j++) {
                    t = num[s, names[j]]
                    printf " %s |", t ? sprintf("%.3f (%d)", hit[s, names[j]] / t, t) : "-"
                }
                printf "\n"
            }
        }'
    echo
done

echo "## Targets"
echo
echo "| filter | synthetic sets with mean F1 >= 0.90 | frames with all three stability F1 >= 0.95 |"
echo "|---|---|---|"
for f in $FILTERS; do
    syn=$(awk -v f="$f" '$1 == f { n++; if ($3 >= 0.90) ok++; else bad = bad (bad ? ", " : "") $2 " " $3 }
                         END { printf "%d of %d%s", ok, n, bad ? " (below: " bad ")" : "" }' "$OUT/setf1.tmp")
    stab=$(awk -v f="$f" '$1 == f { seen[$4] = 1; if ($3 < 0.95) low[$4] = 1 }
                          END { for (k in seen) { n++; if (!(k in low)) ok++ } printf "%d of %d", ok, n }' "$OUT/stab.tmp")
    echo "| $f | $syn | $stab |"
done
echo

if [ "$PER_IMAGE" -eq 1 ]; then
    echo "## Per image"
    echo
    echo '```'
    cat "$PER"
    echo '```'
    echo
fi
finish

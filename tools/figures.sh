#!/bin/sh
# SPDX-License-Identifier: Apache-2.0
# Prints the figures the documentation quotes that this repository's own
# commands produce, each next to where README.md and docs/ quote it, and flags
# every quote that differs from the measurement:
#   - code size of the core and of each module on Cortex-M4 -Os (.text +
#     .rodata, as tools/firmware/check.sh counts it);
#   - worst-case stack per public entry point on Cortex-M0+ -Os and M4 -O3
#     (call graph and -fstack-usage, tools/firmware/stack.awk);
#   - the detector's workspace at 160x120, 320x240 and 640x480 on Cortex-M4
#     and on the 64-bit host, points_needed and instructions per pixel on the
#     emulated Cortex-M4 (port/cortex-m/bench.c: windows of a bundled frame);
#   - with DATA_DIR (the shared data folder, not part of a clone): the scores
#     on the annotated real frames (tools/eval/evaluate.sh --real-only).
# Figures that take long runs (callgrind counts, the OpenCV comparison, the
# synthetic sets) come from their own scripts: tools/bench/icount.sh,
# stages.sh, peers.sh, tools/eval/evaluate.sh.
#
# usage: tools/figures.sh [--build DIR] [--fw-build PREFIX] [DATA_DIR]
#   --build DIR        host build directory (default: REPO/build; built as needed)
#   --fw-build PREFIX  Cortex-M build directories PREFIX-m4-os, -m0plus-os, -m4
#                      (default: REPO/build-fw, those of tools/firmware/check.sh)
# Needs cmake, a host C compiler, arm-none-eabi-gcc and qemu-system-arm.
# Exit status: 0 when every quote matches, 1 when one differs, 2 on a usage
# error or a failed build.
case ${1:-} in -h | --help) sed -n '2,/^[^#]/{/SPDX-License-Identifier/d;s/^# \{0,1\}//p;}' "$0"; exit 0 ;; esac
set -u
REPO=$(cd "$(dirname "$0")/.." && pwd)
BUILD=$REPO/build
FW=$REPO/build-fw
DATA=
usage_error() { echo "figures.sh: $* (try '$0 --help')" >&2; exit 2; }
while [ $# -gt 0 ]; do
    case $1 in
    --build=* | --fw-build=*) v=${1#*=} o=${1%%=*} ;;
    --build | --fw-build) [ $# -ge 2 ] || usage_error "$1 needs a value"; o=$1 v=$2; shift ;;
    --) shift; break ;;
    -*) usage_error "unknown option '$1'" ;;
    *) break ;;
    esac
    case $o in --build) BUILD=$v ;; --fw-build) FW=$v ;; esac
    shift
done
[ $# -le 1 ] || usage_error "one DATA_DIR at most"
if [ $# -eq 1 ]; then
    [ -d "$1" ] || usage_error "no data folder '$1'"
    DATA=$(cd "$1" && pwd)
fi
case $BUILD in /*) ;; *) BUILD=$(pwd)/$BUILD ;; esac
case $FW in /*) ;; *) FW=$(pwd)/$FW ;; esac
for t in cmake arm-none-eabi-gcc arm-none-eabi-size qemu-system-arm; do
    command -v "$t" >/dev/null || { echo "figures.sh: $t is needed (tools/firmware/check.sh installs it)" >&2; exit 2; }
done
TMP=$(mktemp -d)
trap 'rm -rf "$TMP"' EXIT
cd "$REPO" || exit 2

# ---- builds (quiet; the output of a failed one is shown) ----
quiet() { "$@" >"$TMP/log" 2>&1 || { tail -n 30 "$TMP/log" >&2; echo "figures.sh: failed: $*" >&2; exit 2; }; }
[ -f "$BUILD/CMakeCache.txt" ] || quiet cmake -S "$REPO" -B "$BUILD" -DCMAKE_BUILD_TYPE=Release
quiet cmake --build "$BUILD" -j2 --target symline
# cross NAME BUILD_TYPE TARGET CMAKE_ARGS...: the configurations of tools/firmware/check.sh.
cross() {
    d=$FW-$1 bt=$2 t=$3
    shift 3
    [ -f "$d/CMakeCache.txt" ] || CFLAGS="-fcallgraph-info=su" quiet cmake -S "$REPO" -B "$d" \
        -DCMAKE_TOOLCHAIN_FILE="$REPO/port/toolchains/arm-none-eabi.cmake" -DCMAKE_BUILD_TYPE="$bt" "$@"
    quiet cmake --build "$d" -j2 --target "$t"
}
cross m4-os MinSizeRel symline -DSYMLINE_CPU=cortex-m4
cross m0plus-os MinSizeRel symline -DSYMLINE_CPU=cortex-m0plus -DSYMLINE_BUILD_FIRMWARE=ON
cross m4 Release symline_fw_bench -DSYMLINE_CPU=cortex-m4 -DSYMLINE_BUILD_FIRMWARE=ON

# ---- measurements ----
# The optional modules, as the firmware check lists them (not in the core's budget).
optional=" $(sed -n 's/^optional="\(.*\)"$/\1/p' "$REPO/tools/firmware/check.sh") "
for o in $(find "$FW-m4-os/lib" -name '*.obj' | sort); do
    arm-none-eabi-size -A "$o" | awk -v f="$(basename "$o" .c.obj)" '$1 ~ /^\.(text|rodata)/ { s += $2 } END { print f, s }'
done >"$TMP/size"
core=$(awk -v opt="$optional" 'index(opt, " " $1 " ") == 0 { t += $2 } END { print t + 0 }' "$TMP/size")
module() { awk -v m="$1" '$1 == m { print $2 }' "$TMP/size"; }
for c in m0plus-os m4; do
    case $c in
    m0plus-os) arch="-mcpu=cortex-m0plus -mthumb -mfloat-abi=soft" ;;
    *) arch="-mcpu=cortex-m4 -mthumb -mfpu=fpv4-sp-d16 -mfloat-abi=hard" ;;
    esac
    # shellcheck disable=SC2086 # the words of the architecture flags
    arm-none-eabi-objdump -dt "$(arm-none-eabi-gcc $arch -print-libgcc-file-name)" |
        awk -f tools/firmware/helpers.awk >"$TMP/libgcc-$c.txt"
    # shellcheck disable=SC2046 # one argument per call-graph file
    awk -v budget=512 -f tools/firmware/stack.awk "$TMP/libgcc-$c.txt" $(find "$FW-$c/lib" -name '*.ci' | sort) \
        >"$TMP/stack-$c" || true
done
stack() { awk -v f="$2" '$1 == f { print $2 }' "$TMP/stack-$1"; }
stack_max() { sed -n 's/.*worst entry point: \([0-9]*\) B.*/\1/p' "$TMP/stack-$1"; }
timeout 300 qemu-system-arm -M mps2-an386 -nographic -monitor none -serial none \
    -semihosting-config enable=on,target=native -icount shift=0 -kernel "$FW-m4/bin/symline_fw_bench.elf" \
    >"$TMP/bench" 2>&1 || { cat "$TMP/bench" >&2; echo "figures.sh: the Cortex-M4 benchmark failed" >&2; exit 2; }
ws_m4() { # WxH M default|one
    awk -v s="$1" -v m="m=$2:" -v which="$3" '$1 == "workspace" && $2 == s && $3 == m {
        if (which == "one") print $8; else print $12 }' "$TMP/bench"
}
per_px() { # SIZE CONFIG: instructions per pixel, rounded
    awk -v s="$1" -v c="$2" '$1 == "icount" && $2 == s && $4 == "detect" && $5 == c { printf "%.0f", $8 }' "$TMP/bench"
}
points() { # default|1axis1lvl FIELD: needed, bytes or kept
    sed -n "s/^point storage 320x240 m=3 $1: \([0-9]*\) points (\([0-9]*\) bytes) needed, \([0-9]*\) kept.*/\1 \2 \3/p" \
        "$TMP/bench" | awk -v f="$2" '{ print (f == "needed" ? $1 : (f == "bytes" ? $2 : $3)) }'
}
# The host's workspace query (64-bit size_t), from a few lines of C against the host build.
cat >"$TMP/ws.c" <<'EOF_C'
#include <stdio.h>
#include "symline/detect.h"
int main(void)
{
    static const unsigned dims[3][2] = {{160u, 120u}, {320u, 240u}, {640u, 480u}}, radii[2] = {3u, 10u};
    unsigned d, r;
    for (r = 0; r < 2u; r++) {
        for (d = 0; d < 3u; d++) {
            symline_config def, one, paper;
            symline_config_default(&def);
            def.radius = radii[r];
            one = paper = def;
            one.axes = SYMLINE_AXES_HORIZONTAL;
            one.levels = 1u;
            paper.filter = SYMLINE_FILTER_PAPER;
            printf("%ux%u m=%u %lu %lu %lu\n", dims[d][0], dims[d][1], radii[r],
                   (unsigned long)symline_detect_workspace_size(dims[d][0], dims[d][1], &one),
                   (unsigned long)symline_detect_workspace_size(dims[d][0], dims[d][1], &def),
                   (unsigned long)symline_detect_workspace_size(dims[d][0], dims[d][1], &paper));
        }
    }
    return 0;
}
EOF_C
quiet cc -std=c99 -I"$REPO/include" -o "$TMP/ws" "$TMP/ws.c" "$BUILD/lib/libsymline.a"
"$TMP/ws" >"$TMP/ws.txt"
ws_host() { # WxH M one|default|paper
    awk -v s="$1" -v m="m=$2" -v w="$3" '$1 == s && $2 == m { print (w == "one" ? $3 : (w == "default" ? $4 : $5)) }' "$TMP/ws.txt"
}

# ---- quotes ----
# figure LABEL VALUE UNIT: a measured figure (UNIT: B or empty).
nquote=0 ndiff=0
figure() {
    label=$1 value=$2 unit=$3
    if [ -z "$value" ]; then
        printf '\n%s: NOT MEASURED\n' "$label"
        ndiff=$((ndiff + 1))
        return
    fi
    shown="$value${unit:+ $unit}"
    printf '\n%s: %s\n' "$label" "$shown"
}
# quote FILE BRE [KiB]: the number the BRE's one group catches on the first
# line it matches in FILE, against the last figure(): to 0.1 KiB with KiB,
# else to the quoted precision (thousands separators ignored).
quote() {
    file=$1 re=$2 qunit=${3:-}
    line=$(grep -n -e "$re" "$file" | head -n 1 | cut -d: -f1)
    if [ -z "$line" ]; then
        printf '  %-6s %s: no quote matches /%s/\n' "GONE" "$file" "$re"
        ndiff=$((ndiff + 1))
        return
    fi
    case $re in ^*) full=$re ;; *) full=".*$re" ;; esac
    case $re in *\$) ;; *) full="$full.*" ;; esac
    q=$(sed -n "${line}s/$full/\\1/p" "$file" | tr -d ', ')
    case $qunit in
    KiB) want=$(awk -v v="$value" 'BEGIN { printf "%.1f", v / 1024 }') ;;
    *) case $q in
       *.*) d=${q#*.}; want=$(awk -v v="$value" -v n="${#d}" 'BEGIN { printf "%.*f", n, v }') ;;
       *) want=$value ;;
       esac ;;
    esac
    nquote=$((nquote + 1))
    if [ "$q" = "$want" ]; then
        printf '  %-6s %s:%s quotes %s\n' "ok" "$file" "$line" "$q"
    else
        printf '  %-6s %s:%s quotes %s, measured %s\n' "DIFFER" "$file" "$line" "$q" "$want"
        ndiff=$((ndiff + 1))
    fi
}

echo "# Figures the documentation quotes (tools/figures.sh)"
echo
echo "Code size, Cortex-M4 -Os (.text + .rodata), per module:"
awk -v opt="$optional" '{ printf "  %-14s %6d B%s\n", $1, $2, index(opt, " " $1 " ") ? "  (optional)" : "" }' "$TMP/size"

figure "core code (Cortex-M4 -Os, without the optional modules)" "$core" B
quote README.md '\*\*Small:\*\* \([0-9.]*\) KiB of code' KiB
quote docs/porting.md '^ *\([0-9,]*\) B measured, the field boundary'
quote docs/detector.md '^\([0-9,]*\) B of code (docs.RESULTS.md'
figure "field boundary code (fieldboundary.c)" "$(module fieldboundary)" B
quote README.md '(the field boundary \([0-9.]*\) KiB of it' KiB
quote docs/porting.md 'the field boundary \([0-9.]*\) KiB of it, the index' KiB
# shellcheck disable=SC2016 # backquotes of Markdown, not commands
quote docs/detector.md '`fieldboundary.c` \([0-9,]*\) B'
figure "index of earlier segments code (segindex.c)" "$(module segindex)" B
quote docs/porting.md '^ *segments \([0-9.]*\) KiB, the merge' KiB
figure "intersections code (intersections.c, optional)" "$(module intersections)" B
quote README.md 'intersections \([0-9.]*\) KiB and the paper' KiB
quote docs/detector.md '): \([0-9,]*\) B of code on Cortex-M4 -Os, listed with the'

figure "worst-case stack of any public entry point, Cortex-M0+ -Os" "$(stack_max m0plus-os)" B
quote README.md 'at most \([0-9]*\) bytes of'
figure "worst-case stack of any public entry point, Cortex-M4 -O3" "$(stack_max m4)" B
quote README.md 'stack per call on Cortex-M0+ `-Os`, \([0-9]*\) on Cortex-M4'
figure "stack of symline_detect, Cortex-M0+ -Os" "$(stack m0plus-os symline_detect)" B
figure "stack of symline_detect, Cortex-M4 -O3" "$(stack m4 symline_detect)" B
figure "stack of symline_field_find, Cortex-M0+ -Os" "$(stack m0plus-os symline_field_find)" B
# shellcheck disable=SC2016 # backquotes of Markdown, not commands
quote docs/detector.md 'stack of `symline_field_find()` \([0-9]*\) B on Cortex-M0+'
figure "stack of symline_field_find, Cortex-M4 -O3" "$(stack m4 symline_field_find)" B
quote docs/detector.md '^\([0-9]*\) B on M4 -O3 (static bound of the firmware check'
figure "stack of symline_intersections, Cortex-M0+ -Os" "$(stack m0plus-os symline_intersections)" B
quote docs/detector.md '^\([0-9]*\) B on Cortex-M0+ -Os and [0-9]* B on Cortex-M4 -O3 (static bound'
figure "stack of symline_intersections, Cortex-M4 -O3" "$(stack m4 symline_intersections)" B
quote docs/detector.md '^[0-9]* B on Cortex-M0+ -Os and \([0-9]*\) B on Cortex-M4 -O3 (static bound'

for s in 160x120 320x240 640x480; do
    figure "workspace $s m=3, default configuration, Cortex-M4" "$(ws_m4 $s 3 default)" B
    quote docs/porting.md "^| $s | \\([0-9]*\\) B | [0-9]* B |"
    case $s in
    320x240)
        quote docs/detector.md 'ws\[[0-9]*\]; *\/\* \([0-9]*\) B at 320x240'
        quote docs/detector.md '^\([0-9,]*\) B at 320x240 and [0-9,]* B at 640x480 (the line'
        quote README.md '; \([0-9.]*\) KiB of working memory for a 320x240' KiB ;;
    640x480) quote docs/detector.md '^[0-9,]* B at 320x240 and \([0-9,]*\) B at 640x480 (the line' ;;
    esac
    figure "workspace $s m=10, default configuration, Cortex-M4" "$(ws_m4 $s 10 default)" B
    quote docs/porting.md "^| $s | [0-9]* B | \\([0-9]*\\) B |"
done
for s in 160x120 320x240 640x480; do
    figure "workspace $s m=3, one axis, one scale, 64-bit host" "$(ws_host $s 3 one)" B
    quote docs/detector.md "^| $s | \\([0-9]*\\) | [0-9]* | [0-9]* | [0-9]* | [0-9]* |"
    [ "$s" != 320x240 ] || quote docs/detector.md '(320x240, m = 3, one axis: \([0-9.]*\) KiB' KiB
    figure "workspace $s m=3, default, 64-bit host" "$(ws_host $s 3 default)" B
    quote docs/detector.md "^| $s | [0-9]* | \\([0-9]*\\) | [0-9]* | [0-9]* | [0-9]* |"
    figure "workspace $s m=3, paper filter, 64-bit host" "$(ws_host $s 3 paper)" B
    quote docs/detector.md "^| $s | [0-9]* | [0-9]* | \\([0-9]*\\) | [0-9]* | [0-9]* |"
    figure "workspace $s m=10, one axis, one scale, 64-bit host" "$(ws_host $s 10 one)" B
    quote docs/detector.md "^| $s | [0-9]* | [0-9]* | [0-9]* | \\([0-9]*\\) | [0-9]* |"
    figure "workspace $s m=10, default, 64-bit host" "$(ws_host $s 10 default)" B
    quote docs/detector.md "^| $s | [0-9]* | [0-9]* | [0-9]* | [0-9]* | \\([0-9]*\\) |"
done

figure "points_needed, 320x240 window of a bundled frame, default configuration" "$(points default needed)" ""
quote docs/porting.md 'not truncate is \([0-9]*\) points'
figure "  the same in bytes" "$(points default bytes)" B
quote docs/porting.md 'points (\([0-9]*\) bytes) while the result'
figure "  points the result keeps" "$(points default kept)" ""
quote docs/porting.md 'while the result keeps \([0-9]*\)'
figure "instructions per pixel on Cortex-M4 -O3, 320x240, one axis, one scale" "$(per_px 320x240 1axis1lvl)" ""
quote README.md 'check.sh`) \([0-9]*\) instructions per pixel for one axis'
figure "instructions per pixel on Cortex-M4 -O3, 320x240, default configuration" "$(per_px 320x240 default)" ""
quote README.md '^ *\([0-9]*\) for the default (both axes'

if [ -n "$DATA" ]; then
    sh tools/eval/evaluate.sh "$DATA" --real-only --build "$BUILD" --out "$TMP/eval" >"$TMP/eval.md" 2>"$TMP/eval.err" ||
        { cat "$TMP/eval.err" >&2; echo "figures.sh: tools/eval/evaluate.sh failed" >&2; exit 2; }
    # The default filter's table: its mean row and the line-free frames' segments.
    sed -n '/^### Filter default/,/^### \|^## /p' "$TMP/eval.md" >"$TMP/default.md"
    mean() { awk -F'|' -v c="$1" '/^\| mean of/ { gsub(/ /, "", $c); print $c }' "$TMP/default.md"; }
    echo
    echo "Annotated real frames (tools/eval/evaluate.sh $DATA --real-only), default filter:"
    figure "mean precision" "$(mean 3)" ""
    quote README.md 'mean precision \([0-9.]*\), recall'
    figure "mean recall" "$(mean 4)" ""
    quote README.md '^ *\([0-9.]*\), F1 [0-9.]* ([0-9.]* \/'
    figure "mean F1" "$(mean 5)" ""
    quote README.md ', F1 \([0-9.]*\) ([0-9.]* \/'
    figure "segments along a painted line (fragmentation)" "$(mean 7 | sed 's/(.*//')" ""
    quote README.md 'line-free frame; \([0-9.]*\) segments per painted line'
    figure "centre error, median px" "$(mean 8 | cut -d/ -f1)" ""
    quote README.md 'detected centre lies a median \([0-9.]*\) px'
    figure "centre error, 90th percentile px" "$(mean 8 | cut -d/ -f2)" ""
    quote README.md 'a 90th percentile \([0-9.]*\) px'
fi

echo
echo "$nquote quotes checked, $ndiff differ or are missing."
[ "$ndiff" -eq 0 ]

#!/bin/sh
# SPDX-License-Identifier: Apache-2.0
# Where the instructions of one default detection go on the emulated
# Cortex-M4: runs port/cortex-m/profile_one.c (the benchmark's 320x240 frame,
# radius 3) under qemu-system-arm -M mps2-an386 with its execution trace
# (-d in_asm,exec,nochain: every translated block once, every execution of
# one), and sums instructions per function: count, instructions per frame
# pixel, name, largest first, and the total. qemu counts instructions, not
# cycles. The trace is a temporary file of about 100 MB.
#
#   tools/firmware/insnprof.sh [BUILD_DIR] [LINES]
#
# BUILD_DIR: a Cortex-M firmware build (default build-fw-m4, as
# tools/firmware/check.sh makes it: -DSYMLINE_CPU=cortex-m4
# -DSYMLINE_BUILD_FIRMWARE=ON, Release); LINES: functions listed (default 25).
case ${1:-} in -h | --help) sed -n '2,/^[^#]/{/SPDX-License-Identifier/d;s/^# \{0,1\}//p;}' "$0"; exit 0 ;; esac
set -eu
cd "$(dirname "$0")/../.."
dir=${1:-build-fw-m4}
lines=${2:-25}
cmake --build "$dir" --target symline_fw_profile -j 2 >/dev/null
trace=$(mktemp)
trap 'rm -f "$trace"' EXIT
timeout 300 qemu-system-arm -M mps2-an386 -nographic -monitor none -serial none \
    -semihosting-config enable=on,target=native -d in_asm,exec,nochain -D "$trace" \
    -kernel "$dir/bin/symline_fw_profile.elf"
# A block's instructions are the lines after its "IN: function" header; an
# execution is a "Trace" line naming the block's start address.
awk -v px=76800 -v lines="$lines" '
/^IN: / { fn = $2; cur = ""; next }
/^0x[0-9a-f]+:/ { a = $1; sub(":", "", a); if (cur == "") { cur = a; n[cur] = 0; f[cur] = fn } n[cur]++; next }
/^$/ { cur = ""; next }
/^Trace / { m = $0; sub(/.*\[/, "", m); split(m, p, "/"); cnt["0x" p[2]]++; next }
END {
    for (pc in cnt) { tot[f[pc]] += cnt[pc] * n[pc]; all += cnt[pc] * n[pc] }
    for (fn in tot) printf "%12d %8.2f  %s\n", tot[fn], tot[fn] / px, fn | "sort -rn | head -" lines
    close("sort -rn | head -" lines)
    printf "%12d %8.2f  total (instructions, per pixel of the 320x240 frame)\n", all, all / px
}' "$trace"

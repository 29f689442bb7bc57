#!/bin/sh
# SPDX-License-Identifier: Apache-2.0
# Firmware readiness of the core (lib/), as CI runs it:
#   1. cross builds of libsymline.a: Cortex-M0+ (soft float), M4 and M7 (hard
#      float), RV32IMAC (freestanding compile-and-link check);
#   2. the M0+ symbol table: no floating-point helper, no malloc/free, no
#      stdio, nothing from libc at all; the M4/M7 code: no FPU instruction;
#   3. worst-case stack of every public entry point (call graph + -fstack-usage)
#      <= 512 bytes, on M0+ -Os and M4 -O3;
#   4. code size (.text + .rodata) on Cortex-M4 -Os <= 16 KiB for the core
#      detector (see size_budget below); the optional modules (feature points,
#      histogram, Muff-space finder, intersections) are listed apart;
#   5. cppcheck and clang-tidy (tools/firmware/clang-tidy.yaml) clean on lib/;
#   6. on an emulated Cortex-M4 (qemu mps2-an386, port/cortex-m/): the core's
#      golden and argument tests (M4 -O3 and M0+ -Os code), a deliberately
#      failing variant and a crashing program that must fail, the firmware
#      example, the detector's output against the same program on the host and
#      against the golden JSON of tests/golden/lines/, the measured stack
#      against the static bound, and instructions per pixel (qemu -icount).
# Prints one line per check, continues after a failure and exits 1 if any
# check failed. Installs its Debian packages when missing (apt-get, as root).
#
#   tools/firmware/check.sh            build dirs ./build-fw-*
#   SYMLINE_FW_BUILD=/tmp/fw tools/firmware/check.sh   build dirs /tmp/fw-*
case ${1:-} in -h | --help) sed -n '2,/^[^#]/{/SPDX-License-Identifier/d;s/^# \{0,1\}//p;}' "$0"; exit 0 ;; esac
set -u
cd "$(dirname "$0")/../.." || exit 2
root=$(pwd)
prefix=${SYMLINE_FW_BUILD:-$root/build-fw}
jobs=2
stack_budget=512
# 12 KiB before the field-line stages, which were allowed to take it to 16 KiB;
# the whole core fits (field boundary, sub-pixel offsets, the bounded-time
# indexes and all).
size_budget=16384
qemu_timeout=120
failed=0
log=$(mktemp)
trap 'rm -f "$log"' EXIT

ok() { printf '  [ok]   %s\n' "$*"; }
failures=""
bad() { printf '  [FAIL] %s\n' "$*"; failed=1; failures="$failures
  - $*"; }
step() { printf '\n== %s\n' "$*"; }
# run DESCRIPTION CMD...: quiet on success, the command's output on failure.
run() {
    d=$1; shift
    if "$@" >"$log" 2>&1; then return 0; fi
    bad "$d"; sed 's/^/         /' "$log" | tail -40; return 1
}

step "packages"
need=""
for p in cmake make gcc libc6-dev binutils gcc-arm-none-eabi libnewlib-arm-none-eabi \
         qemu-system-arm gcc-riscv64-unknown-elf cppcheck clang-tidy; do
    dpkg-query -W -f='${Status}\n' "$p" 2>/dev/null | grep -q '^install ok installed$' || need="$need $p"
done
if [ -n "$need" ]; then
    echo "  installing:$need"
    if [ "$(id -u)" -ne 0 ]; then
        echo "  missing packages:$need (run as root or: sudo apt-get install$need)"; exit 1
    fi
    export DEBIAN_FRONTEND=noninteractive
    # shellcheck disable=SC2086
    apt-get install -y -q $need >/dev/null 2>&1 ||
        { apt-get update -q >/dev/null && apt-get install -y -q $need >/dev/null; } ||
        { echo "  apt-get install$need failed"; exit 1; }
fi
ok "toolchains: $(arm-none-eabi-gcc -dumpversion) (arm-none-eabi), $(riscv64-unknown-elf-gcc -dumpversion) (riscv64-unknown-elf), $(qemu-system-arm --version | head -1)"

# cross NAME TOOLCHAIN BUILD_TYPE [cmake args...]: configure and build libsymline.a
cross() {
    name=$1 tc=$2 bt=$3; shift 3
    dir=$prefix-$name
    # CFLAGS adds to the toolchain's flags (-DCMAKE_C_FLAGS would replace them).
    run "configure $name" env CFLAGS="-fcallgraph-info=su" cmake -S "$root" -B "$dir" \
        -DCMAKE_TOOLCHAIN_FILE="$root/port/toolchains/$tc" -DCMAKE_BUILD_TYPE="$bt" "$@" || return 1
    run "build $name" cmake --build "$dir" --target symline -j "$jobs" || return 1
    ok "$name: $(basename "$dir")/lib/libsymline.a ($bt)"
}

step "cross builds of libsymline.a"
cross m0plus-os arm-none-eabi.cmake MinSizeRel -DSYMLINE_CPU=cortex-m0plus -DSYMLINE_BUILD_FIRMWARE=ON
cross m4-os arm-none-eabi.cmake MinSizeRel -DSYMLINE_CPU=cortex-m4
cross m7 arm-none-eabi.cmake Release -DSYMLINE_CPU=cortex-m7
cross rv32 riscv32.cmake MinSizeRel
cross m4 arm-none-eabi.cmake Release -DSYMLINE_CPU=cortex-m4 -DSYMLINE_BUILD_FIRMWARE=ON

step "RV32IMAC: the freestanding core links with -nostdlib -lgcc"
lib=$prefix-rv32/lib/libsymline.a
if [ -f "$lib" ] && run "rv32 link with -nostdlib -lgcc (undefined references)" riscv64-unknown-elf-gcc -march=rv32imac -mabi=ilp32 -nostdlib \
        -Wl,--entry=symline_status_str -Wl,--whole-archive "$lib" -Wl,--no-whole-archive -lgcc \
        -o "$prefix-rv32/linkcheck.elf"; then
    ok "every object of libsymline.a resolved ($(riscv64-unknown-elf-size "$prefix-rv32/linkcheck.elf" | awk 'NR==2{print $1 " bytes text"}'))"
fi

step "Cortex-M0+ symbol table: no float, no allocation, no stdio, no libc"
# Every undefined symbol must be defined in the archive itself or be one of
# libgcc's integer helpers; anything else is named and classified.
lib=$prefix-m0plus-os/lib/libsymline.a
if [ -f "$lib" ]; then
    arm-none-eabi-nm --defined-only "$lib" | awk 'NF==3{print $3}' | sort -u >"$log.def"
    arm-none-eabi-nm -u "$lib" | awk 'NF==2{print $2}' | sort -u | comm -23 - "$log.def" >"$log.undef"
    outside=$(grep -Ev '^__(aeabi_(uidiv|uidivmod|idiv|idivmod|ldivmod|uldivmod|lmul|llsl|llsr|lasr|lcmp|ulcmp)|(u?(div|mod|divmod)di[34])|muldi3|clz[sd]i2|ctz[sd]i2)$' "$log.undef")
    helpers=$(grep -Ev "^($(echo "$outside" | paste -sd'|' -))\$" "$log.undef" | paste -sd' ' -)
    if [ -z "$outside" ]; then
        ok "undefined symbols outside the core: only libgcc integer helpers (${helpers:-none})"
    else
        for s in $outside; do
            case $s in
            __aeabi_f* | __aeabi_d* | __aeabi_*2f | __aeabi_*2d | __*sf* | __*df* | __*tf*)
                bad "floating-point helper referenced: $s" ;;
            malloc | calloc | realloc | free | _malloc_r | _free_r | _calloc_r | _realloc_r | aligned_alloc)
                bad "allocation referenced: $s" ;;
            *printf* | puts | putchar | fputs | fputc | fwrite | fopen | fclose | fread | stdin | stdout | stderr | _impure_ptr)
                bad "stdio referenced: $s" ;;
            *) bad "libc/other symbol referenced: $s" ;;
            esac
        done
    fi
    rm -f "$log.def" "$log.undef"
fi
# No writable static data: all RAM is the caller's, and calls are reentrant.
lib=$prefix-m0plus-os/lib/libsymline.a
if [ -f "$lib" ]; then
    rw=$(arm-none-eabi-size -A "$lib" | awk '$1 ~ /^\.(data|bss)/ || $1 == "COMMON" { s += $2 } END { print s + 0 }')
    if [ "$rw" -eq 0 ]; then ok "no static RAM (.data + .bss = 0 B): every byte of RAM is the caller's"
    else bad "libsymline.a has $rw bytes of .data/.bss (static state)"; fi
fi
for c in m4-os m7; do
    lib=$prefix-$c/lib/libsymline.a
    [ -f "$lib" ] || continue
    n=$(arm-none-eabi-objdump -d "$lib" | grep -cE '^ +[0-9a-f]+:	[0-9a-f ]+	v[a-z0-9.]+	' )
    if [ "$n" -eq 0 ]; then ok "$c: no FPU instruction in libsymline.a (hard-float ABI, -mgeneral-regs-only)"
    else bad "$c: $n FPU instructions in libsymline.a:"; arm-none-eabi-objdump -d "$lib" | grep -E '	v[a-z0-9.]+	' | head -5; fi
done

step "worst-case stack per public entry point (budget $stack_budget B)"
for c in m0plus-os m4; do
    cis=$(find "$prefix-$c/lib" -name '*.ci' 2>/dev/null | sort)
    if [ -z "$cis" ]; then bad "$c: no call-graph files (-fcallgraph-info)"; continue; fi
    case $c in
    m0plus*) arch="-mcpu=cortex-m0plus -mthumb -mfloat-abi=soft" ;;
    *) arch="-mcpu=cortex-m4 -mthumb -mfpu=fpv4-sp-d16 -mfloat-abi=hard" ;;
    esac
    # shellcheck disable=SC2086
    libgcc=$(arm-none-eabi-gcc $arch -print-libgcc-file-name)
    arm-none-eabi-objdump -dt "$libgcc" | awk -f tools/firmware/helpers.awk >"$prefix-$c/libgcc-stack.txt"
    echo "  $c (libgcc helpers: bounds from $(echo "$libgcc" | sed 's|.*/arm-none-eabi/||')):"
    # shellcheck disable=SC2086
    if awk -v budget="$stack_budget" -f tools/firmware/stack.awk "$prefix-$c/libgcc-stack.txt" $cis >"$log"; then
        cp "$log" "$prefix-$c/stack.txt"
        cat "$log"
        ok "$c: every entry point within $stack_budget B"
    else
        cp "$log" "$prefix-$c/stack.txt"
        cat "$log"
        bad "$c stack: $(grep -c ' OVER ' "$log") entry point(s) over $stack_budget B ($(grep ' OVER ' "$log" | awk '{printf "%s%s %s B", sep, $1, $2; sep=", "}'))$(grep -q 'problem:' "$log" && printf '; %s' "$(grep 'problem:' "$log" | sed 's/ *problem: //' | paste -sd';' -)")"
    fi
done

step "code size on Cortex-M4 -Os (.text + .rodata, target <= $size_budget B)"
# Optional modules (the paper's other methods, the intersections stage, the
# binning of large frames) are reported on their own and not counted against
# the budget: firmware that does not call them does not link them (one object
# per module in the static library). tools/figures.sh reads this line.
optional="colrun features histogram framepoints muff muff_vote muff_extent muff_detect intersections binning"
objs=$(find "$prefix-m4-os/lib" -name '*.obj' | sort)
if [ -n "$objs" ]; then
    for o in $objs; do
        arm-none-eabi-size -A "$o" | awk -v f="$(basename "$o" .c.obj)" \
            '$1 ~ /^\.(text|rodata)/ { s += $2 } END { printf "%s %d\n", f, s }'
    done >"$log"
    awk -v opt=" $optional " 'index(opt, " " $1 " ") == 0 { printf "    %-14s %6d B\n", $1, $2 }' "$log"
    total=$(awk -v opt=" $optional " 'index(opt, " " $1 " ") == 0 { t += $2 } END { print t + 0 }' "$log")
    if [ "$total" -le "$size_budget" ]; then ok "core: $total B (.text + .rodata) <= $size_budget B"
    else bad "core: $total B (.text + .rodata) > $size_budget B"; fi
    echo "  optional modules (not in the budget):"
    awk -v opt=" $optional " 'index(opt, " " $1 " ") > 0 { printf "    %-14s %6d B\n", $1, $2 }' "$log"
    awk -v opt=" $optional " 'index(opt, " " $1 " ") > 0 { t += $2; if ($1 ~ /^(muff|framepoints)/) m += $2; if ($1 == "intersections") x += $2; if ($1 == "binning") b += $2 }
        END { printf "    feature points + histogram %d B, Muff-space finder %d B, intersections %d B, binning %d B\n", t - m - x - b, m, x, b }' "$log"
else
    bad "no Cortex-M4 -Os objects"
fi

step "static analysis of lib/"
# shellcheck disable=SC2046
if run "cppcheck" cppcheck --enable=warning,style,performance,portability --std=c99 \
        --error-exitcode=1 --inline-suppr --quiet -I include -I lib $(ls lib/*.c); then
    ok "cppcheck $(cppcheck --version | cut -d' ' -f2): clean (warning, style, performance, portability)"
fi
# shellcheck disable=SC2046
if clang-tidy --config-file=tools/firmware/clang-tidy.yaml --quiet $(ls lib/*.c) \
        -- -std=c99 -Iinclude -Ilib >"$log" 2>&1; then
    ok "clang-tidy $(clang-tidy --version | sed -n 's/.*version \([0-9.]*\).*/\1/p' | head -1): clean (tools/firmware/clang-tidy.yaml)"
else
    bad "clang-tidy (tools/firmware/clang-tidy.yaml): $(grep -c ': error:' "$log") findings"
    grep ': error:' "$log" | sed "s|$root/||; s/^/         /" | sort -u | head -30
fi

step "on an emulated Cortex-M4 (qemu-system-arm -M mps2-an386, semihosting)"
dir=$prefix-m4
qemu() {
    timeout "$qemu_timeout" qemu-system-arm -M mps2-an386 -nographic -monitor none -serial none \
        -semihosting-config enable=on,target=native "$@"
}
# golden_lines BUILD_DIR LABEL: the golden JSON of tests/golden/lines/ reproduced on the target.
golden_lines() {
    gdir=$1
    [ -f "$gdir/bin/symline_fw_lines.elf" ] || return 0
    rm -f "$gdir"/lines.*.json
    qemu -kernel "$gdir/bin/symline_fw_lines.elf" >"$log" 2>&1
    grc=$?
    awk -v d="$gdir/lines" '/^=== / { if (f != "") close(f); f = ($2 == "end") ? "" : d "." $2 ".json"; next }
                            f != "" { print > f }' "$log"
    nsame=0
    for want in tests/golden/lines/*.json; do
        got=$gdir/lines.$(basename "$want")
        if [ -f "$got" ] && cmp -s "$got" "$want"; then
            nsame=$((nsame + 1))
        else
            bad "$2: golden JSON $(basename "$want") differs on the target (exit $grc)"
            diff "$want" "$got" 2>&1 | head -6 | sed 's/^/         /'
        fi
    done
    [ "$grc" -eq 0 ] || bad "$2: golden JSON program exit $grc"
    [ "$nsame" -gt 0 ] && ok "$2: golden JSON of the bundled 608x800 frames reproduced on the target ($nsame of $(find tests/golden/lines -name "*.json" | wc -l) files identical)"
    return 0
}
if run "build target programs" cmake --build "$dir" -j "$jobs"; then
    if qemu -kernel "$dir/bin/symline_fw_tests.elf" >"$log" 2>&1; then
        ok "$(tail -1 "$log")"
    else
        bad "target tests (exit $?):"; sed 's/^/         /' "$log" | tail -20
    fi
    # ARMv6-M is a subset of ARMv7E-M: the M0+ build's code runs on the M4 model too.
    if run "build Cortex-M0+ target tests" cmake --build "$prefix-m0plus-os" --target symline_fw_tests -j "$jobs"; then
        if qemu -kernel "$prefix-m0plus-os/bin/symline_fw_tests.elf" >"$log" 2>&1; then
            ok "Cortex-M0+ -Os build (ARMv6-M code, soft float) on the same model: $(tail -1 "$log")"
        else
            bad "Cortex-M0+ target tests (exit $?):"; sed 's/^/         /' "$log" | tail -20
        fi
    fi
    qemu -kernel "$dir/bin/symline_fw_tests_fail.elf" >"$log" 2>&1
    rc=$?
    if [ "$rc" -ne 0 ] && [ "$rc" -ne 124 ] && grep -q '^FAIL' "$log"; then
        ok "a corrupted output byte fails the target run (exit $rc): $(grep -m1 '^FAIL' "$log" | cut -c1-90)"
    else
        bad "the deliberately failing variant did not fail (exit $rc)"
    fi
    qemu -kernel "$dir/bin/symline_fw_fault.elf" >"$log" 2>&1
    rc=$?
    if [ "$rc" -ne 0 ] && [ "$rc" -ne 124 ]; then
        ok "a crash on the target fails the run instead of hanging (exit $rc)"
    else
        bad "the crashing program did not fail (exit $rc)"
    fi
    if [ -f "$dir/bin/symline_fw_example.elf" ]; then
        if qemu -kernel "$dir/bin/symline_fw_example.elf" >"$log" 2>&1; then
            ok "example: $(grep -m1 -i 'segments' "$log")"
            sed 's/^/         /' "$log" | head -12
        else
            bad "example (exit $?):"; sed 's/^/         /' "$log" | tail -20
        fi
    fi
    if [ -f "$dir/bin/symline_fw_detect.elf" ]; then
        # The same program built for the host: results must be identical.
        host=$prefix-host
        gen=$dir/port/cortex-m/gen
        if run "host build of the core" cmake -S "$root" -B "$host" -DSYMLINE_BUILD_TOOLS=OFF \
                -DSYMLINE_BUILD_TESTS=OFF -DSYMLINE_BUILD_CAPTURE=OFF &&
           run "host build of the core" cmake --build "$host" --target symline -j "$jobs" &&
           run "host build of detect_check" cc -std=c99 -O2 -Iinclude -Iport/cortex-m \
                port/cortex-m/detect_check.c port/cortex-m/segprint.c "$gen/detect_frames.c" \
                "$gen/bench_frames.c" "$host/lib/libsymline.a" -o "$host/detect_check"; then
            qemu -kernel "$dir/bin/symline_fw_detect.elf" >"$prefix-m4/detect.target.txt" 2>&1
            rc=$?
            "$host/detect_check" >"$host/detect.host.txt" 2>&1
            hrc=$?
            if [ "$rc" -eq 0 ] && [ "$hrc" -eq 0 ] &&
               cmp -s "$prefix-m4/detect.target.txt" "$host/detect.host.txt"; then
                ok "detector on the target = on the host ($(grep -c '^  ' "$host/detect.host.txt") segments over $(grep -c ': status' "$host/detect.host.txt") runs, identical output)"
            else
                bad "detector: target exit $rc, host exit $hrc, outputs differ or failed:"
                diff "$host/detect.host.txt" "$prefix-m4/detect.target.txt" | head -20 | sed 's/^/         /'
            fi
        fi
    fi
    golden_lines "$dir" "Cortex-M4 -O3"
    if run "build Cortex-M0+ golden JSON program" cmake --build "$prefix-m0plus-os" --target symline_fw_lines -j "$jobs"; then
        golden_lines "$prefix-m0plus-os" "Cortex-M0+ -Os"
    fi
    if [ -f "$dir/bin/symline_fw_stackuse.elf" ] && [ -f "$dir/stack.txt" ]; then
        # Measured stack (painted region) must stay within the static bound.
        if qemu -kernel "$dir/bin/symline_fw_stackuse.elf" >"$log" 2>&1; then
            while read -r _ name used _; do
                bound=$(awk -v n="$name" '$1 == n { print $2 }' "$dir/stack.txt")
                if [ -n "$bound" ] && [ "$used" -le "$bound" ]; then
                    ok "stack measured on the target: $name $used B <= static bound $bound B"
                else
                    bad "stack measured on the target: $name $used B > static bound ${bound:-?} B (the analysis misses something)"
                fi
            done <"$log"
        else
            bad "stack measurement (exit $?):"; sed 's/^/         /' "$log" | tail -10
        fi
    fi
    echo "  instructions per pixel (qemu -icount shift=0, SysTick), Cortex-M4 -O3 build:"
    if qemu -icount shift=0 -kernel "$dir/bin/symline_fw_bench.elf" >"$log" 2>&1; then
        sed 's/^/    /' "$log"
        ok "benchmark ran (Cortex-M4 -O3)"
    else
        bad "benchmark (exit $?):"; sed 's/^/         /' "$log" | tail -20
    fi
    # The M0+ build's instructions (ARMv6-M code, libgcc division calls) counted
    # on the same model: the instruction count an M0+ executes, not its cycles.
    echo "  instructions per pixel, Cortex-M0+ -Os build (ARMv6-M code on the M4 model):"
    if run "build Cortex-M0+ benchmark" cmake --build "$prefix-m0plus-os" --target symline_fw_bench -j "$jobs"; then
        if qemu -icount shift=0 -kernel "$prefix-m0plus-os/bin/symline_fw_bench.elf" >"$log" 2>&1; then
            grep -E '^(calibration|icount)' "$log" | sed 's/^/    /'
            ok "benchmark ran (Cortex-M0+ -Os)"
        else
            bad "Cortex-M0+ benchmark (exit $?):"; sed 's/^/         /' "$log" | tail -20
        fi
    fi
fi

echo
if [ "$failed" -eq 0 ]; then echo "firmware checks: all passed"; else echo "firmware checks: FAILED:$failures"; fi
exit "$failed"

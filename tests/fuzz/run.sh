#!/bin/sh
# SPDX-License-Identifier: Apache-2.0
# Builds the libFuzzer targets (clang, ASan + UBSan, preset "fuzz") and runs
# each for SECONDS (default 20), one after the other on one core, starting
# from the seed corpus in tests/fuzz/corpus/ (copied: the repository stays
# clean), with the dictionary tests/fuzz/NAME.dict when there is one. Fails
# on any crash, leak, timeout (10 s per input), out-of-memory (2 GB) or
# sanitizer report; prints the executions per target and in all.
#   tests/fuzz/run.sh [SECONDS] [TARGET...]
# Exit status: 0 all ran clean, 1 a finding or a build error, 77 skipped
# (clang or its fuzzer runtime missing and not installable).
# Findings are kept in build-fuzz/findings/TARGET/ (reproduce: build-fuzz/fuzz/TARGET FILE).
case "${1:-}" in -h | --help) sed -n '3,/^[^#]/{/^#/s/^# \{0,1\}//p}' "$0"; exit 0 ;; esac
set -u
cd "$(dirname "$0")/../.." || exit 1
secs=${1:-20}
[ $# -gt 0 ] && shift
targets=${*:-fuzz_pgm fuzz_png fuzz_jpeg fuzz_y4m fuzz_operator fuzz_detect fuzz_field fuzz_muff fuzz_features fuzz_histogram fuzz_intersections fuzz_binning}

have_fuzzer() {
    command -v clang >/dev/null 2>&1 &&
        printf 'int LLVMFuzzerTestOneInput(const char *d, unsigned long n){(void)d;(void)n;return 0;}\n' |
        clang -x c -fsanitize=fuzzer,address,undefined -o /dev/null - >/dev/null 2>&1
}
if ! have_fuzzer; then
    need="clang libclang-rt-14-dev"
    if [ "$(id -u)" -eq 0 ] && command -v apt-get >/dev/null 2>&1; then
        echo "installing: $need"
        # shellcheck disable=SC2086
        DEBIAN_FRONTEND=noninteractive apt-get install -y -q $need >/dev/null 2>&1 ||
            { apt-get update -q >/dev/null && DEBIAN_FRONTEND=noninteractive apt-get install -y -q $need >/dev/null; }
    fi
    if ! have_fuzzer; then
        echo "SKIPPED: fuzzing needs clang with libFuzzer (apt-get install $need)"
        exit 77
    fi
fi

{ cmake --preset fuzz >/dev/null && cmake --build --preset fuzz -j 2 --target $targets >/dev/null; } || {
    echo "tests/fuzz/run.sh: build failed"; cmake --build --preset fuzz --target $targets 2>&1 | tail -20; exit 1; }

failed=""
total=0
count=0
for t in $targets; do
    seeds=tests/fuzz/corpus/${t#fuzz_}
    work=build-fuzz/corpus/$t
    found=build-fuzz/findings/$t
    log=build-fuzz/$t.log
    mkdir -p "$work" "$found"
    [ -d "$seeds" ] && cp -n "$seeds"/* "$work"/ 2>/dev/null
    dict=tests/fuzz/${t#fuzz_}.dict
    set --
    if [ -f "$dict" ]; then set -- -dict="$dict"; fi
    build-fuzz/fuzz/$t "$@" -max_total_time="$secs" -timeout=10 -rss_limit_mb=2048 -print_final_stats=1 \
        -artifact_prefix="$found/" "$work" >"$log" 2>&1
    rc=$?
    execs=$(sed -n 's/^stat::number_of_executed_units: *//p' "$log" | tail -n 1)
    cov=$(grep -o 'cov: [0-9]*' "$log" | tail -n 1)
    if [ $rc -ne 0 ]; then
        echo "$t: FAILED after ${execs:-?} executions (exit $rc); see $log and $found/"
        grep -E '^(==[0-9]+==ERROR|SUMMARY|.*runtime error|guard byte|.*written by a call)' "$log" | head -n 5
        failed="$failed $t"
    else
        echo "$t: ${execs:-?} executions in ${secs} s, ${cov:-cov: ?} edges, corpus $(ls "$work" | wc -l) inputs, nothing found"
    fi
    total=$((total + ${execs:-0}))
    count=$((count + 1))
done
echo "tests/fuzz/run.sh: $count targets, $total executions in all"
if [ -n "$failed" ]; then
    echo "tests/fuzz/run.sh: findings in:$failed"
    exit 1
fi

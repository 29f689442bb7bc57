#!/bin/sh
# The whole test suite, as CI runs it: host build + every CTest test, the same
# suite under AddressSanitizer + UndefinedBehaviorSanitizer, and the firmware
# and capture integration steps when their scripts are present in this checkout.
# Installs what it needs (apt-get, as root) when missing.
#   tools/test.sh          everything
#   tools/test.sh --host   host build and CTest only (fast)
set -eu
cd "$(dirname "$0")/.."
mode=${1:-all}
jobs=$(nproc 2>/dev/null || echo 2)

step() { printf '\n==== %s ====\n' "$*"; }

tools/deps.sh test

step "host build and tests (preset default)"
cmake --preset default >/dev/null
cmake --build --preset default -j "$jobs"
ctest --preset default -j "$jobs" -LE integration

[ "$mode" = "--host" ] && exit 0

step "sanitizers (preset asan: ASan + UBSan)"
cmake --preset asan >/dev/null
cmake --build --preset asan -j "$jobs"
ctest --preset asan -j "$jobs"

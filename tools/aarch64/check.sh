#!/bin/sh
# SPDX-License-Identifier: Apache-2.0
# 64-bit Arm Linux (Raspberry Pi class single-board computers): a cross build
# with Debian's gcc-aarch64-linux-gnu (port/toolchains/aarch64-linux-gnu.cmake)
# and the host suite's cmocka tests, the golden ones among them, run under
# qemu-user. The tests driven by shell scripts (CLI against the reference, CLI
# errors, core rules, render, install) call the binaries directly and need the
# host; they run in the host steps of tools/test.sh.
# Installs what it needs (apt-get, as root): gcc-aarch64-linux-gnu,
# qemu-user-static, libcmocka-dev:arm64 and libpng-dev:arm64 (Debian multiarch:
# adds the arm64 architecture to dpkg first when it is missing).
#
# usage: tools/aarch64/check.sh [--build DIR] [--vec]
#   --build DIR  build directory (default: REPO/build-aarch64)
#   --vec        only report which loops of lib/ GCC vectorises for AArch64's
#                SIMD (NEON/ASIMD) at the Release optimisation (-O3), with
#                -fopt-info-vec-optimized; no build, no tests
# Exit status: 0 passed, 1 failed, 77 SKIPPED (a package could not be installed).
set -u

usage() { sed -n '3,/^set -u/p' "$0" | sed -e '/^set -u/d' -e 's/^# \{0,1\}//'; }

REPO=$(cd "$(dirname "$0")/../.." && pwd)
BUILD=$REPO/build-aarch64
VEC=0
while [ $# -gt 0 ]; do
    case $1 in
        -h|--help) usage; exit 0 ;;
        --build) BUILD=$2; shift 2 ;;
        --vec) VEC=1; shift ;;
        *) echo "aarch64/check.sh: unknown option '$1'" >&2; usage >&2; exit 2 ;;
    esac
done
jobs=$(nproc 2>/dev/null || echo 2)

skip() {
    echo "SKIPPED: aarch64 check: $*"
    exit 77
}

# ---- packages ----
# dpkg-query -W, not dpkg -s: once arm64 is added, a package installed for both
# architectures has an ambiguous name that dpkg -s rejects.
installed() { dpkg-query -W -f='${Status}\n' "$1" 2>/dev/null | grep -q "ok installed"; }
missing=
for p in gcc-aarch64-linux-gnu qemu-user-static cmake make pkg-config; do
    installed "$p" || missing="$missing $p"
done
if [ "$VEC" -eq 0 ]; then
    for p in libcmocka-dev:arm64 libpng-dev:arm64; do
        installed "$p" || missing="$missing $p"
    done
fi
if [ -n "$missing" ]; then
    [ "$(id -u)" -eq 0 ] || skip "missing packages:$missing (run as root, or install them)"
    echo "installing:$missing"
    export DEBIAN_FRONTEND=noninteractive
    case $missing in
        *:arm64*)
            if ! dpkg --print-foreign-architectures | grep -qx arm64; then
                dpkg --add-architecture arm64 || skip "dpkg --add-architecture arm64 failed"
                apt-get update -q >/dev/null || skip "apt-get update failed after adding arm64"
            fi
            ;;
    esac
    # shellcheck disable=SC2086
    apt-get install -y -q $missing >/dev/null 2>&1 ||
        { apt-get update -q >/dev/null 2>&1 && apt-get install -y -q $missing >/dev/null; } ||
        skip "could not install:$missing"
fi

# ---- vectorisation report ----
if [ "$VEC" -eq 1 ]; then
    cc=aarch64-linux-gnu-gcc
    echo "Loops of lib/ vectorised by $($cc --version | head -n 1), -std=c99 -O3 (Release):"
    for f in "$REPO"/lib/*.c; do
        $cc -std=c99 -O3 -DNDEBUG -I"$REPO/include" -I"$REPO/lib" -fopt-info-vec-optimized \
            -c "$f" -o /dev/null 2>&1 | grep 'optimized: loop vectorized' |
            sed "s|^$REPO/||" | sort -t: -k1,1 -k2,2n -u | while IFS=: read -r file line _ rest; do
                printf '%s:%s: %s\n    %s\n' "$file" "$line" "${rest# optimized: }" \
                    "$(sed -n "${line}p" "$REPO/$file" | sed 's/^ *//')"
            done
    done
    exit 0
fi

# ---- cross build and tests under qemu-user ----
command -v qemu-aarch64-static >/dev/null || skip "no qemu-aarch64-static"
cmake -S "$REPO" -B "$BUILD" -DCMAKE_TOOLCHAIN_FILE="$REPO/port/toolchains/aarch64-linux-gnu.cmake" \
    -DCMAKE_BUILD_TYPE=Release -DSYMLINE_BUILD_TOOLS=ON -DSYMLINE_BUILD_TESTS=ON >/dev/null || exit 1
grep -q '^CMOCKA_FOUND:INTERNAL=1' "$BUILD/CMakeCache.txt" || { echo "aarch64: cmocka for arm64 not found"; exit 1; }
cmake --build "$BUILD" -j "$jobs" || exit 1
# Every test that is a cmocka program (label unit); CTest starts each under qemu-user.
ctest --test-dir "$BUILD" -L unit -j "$jobs" --output-on-failure --no-tests=error || exit 1
echo "aarch64: the cmocka tests passed under $(qemu-aarch64-static --version | head -n 1)"

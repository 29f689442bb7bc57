#!/bin/sh
# SPDX-License-Identifier: Apache-2.0
# Builds tests/install/fetch, a project embedding symline with FetchContent
# from this checkout (no network), then runs it. Its configure step fails
# when the embedded symline defines more than the library target.
# Usage: fetch_test.sh SOURCE_DIR [CFLAGS]
case ${1:-} in -h | --help) sed -n '2,/^[^#]/{/SPDX-License-Identifier/d;s/^# \{0,1\}//p;}' "$0"; exit 0 ;; esac
set -eu
src=$1 cflags=${2:-}
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
cmake -S "$src/tests/install/fetch" -B "$tmp/b" -DSYMLINE_SOURCE="$src" \
      -DCMAKE_C_FLAGS="$cflags" -DCMAKE_EXE_LINKER_FLAGS="$cflags" > "$tmp/configure.log" ||
    { cat "$tmp/configure.log"; exit 1; }
grep 'symline targets when embedded' "$tmp/configure.log"
cmake --build "$tmp/b" > "$tmp/build.log" || { cat "$tmp/build.log"; exit 1; }
# What was built: the library and the consumer, nothing else of symline.
built=$(find "$tmp/b" -type f \( -name '*.a' -o -perm -u+x \) ! -path '*/CMakeFiles/*' | sed "s|$tmp/b/||" | sort)
echo "built: $(echo "$built" | tr '\n' ' ')"
[ "$(echo "$built" | wc -l)" -eq 2 ] || { echo "expected 2 build products (libsymline.a, fetch_consumer)"; exit 1; }
"$tmp/b/fetch_consumer"
echo "FetchContent consumer: builds only the library, runs"

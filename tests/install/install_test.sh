#!/bin/sh
# SPDX-License-Identifier: Apache-2.0
# Installs the library component ("dev") of the built tree into a temporary
# prefix, checks that it holds only what a consumer needs (library, headers,
# CMake package, pkg-config file), then builds a consumer with
# find_package(symline) and another with pkg-config, and runs both.
# Usage: install_test.sh BUILD_DIR SOURCE_DIR CC [CFLAGS]
# CFLAGS are the flags the library was built with (e.g. sanitizers), which the
# consumers need too.
case ${1:-} in -h | --help) sed -n '2,/^[^#]/{/SPDX-License-Identifier/d;s/^# \{0,1\}//p;}' "$0"; exit 0 ;; esac
set -eu
build=$1 src=$2 cc=$3 cflags=${4:-}
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
cmake --install "$build" --prefix "$tmp/prefix" --component dev >/dev/null
extra=$(cd "$tmp/prefix" && find . -type f | sed 's|^\./||' | grep -Ev \
    '^include/symline/[a-z_]+\.h$|^lib.*/libsymline\.a$|^lib.*/cmake/symline/symline[A-Za-z-]*\.cmake$|^lib.*/pkgconfig/symline\.pc$' || true)
if [ -n "$extra" ]; then
    echo "the dev component installs more than a consumer needs:"; echo "$extra"; exit 1
fi
cmake -S "$src/tests/install/consumer" -B "$tmp/b" -DCMAKE_PREFIX_PATH="$tmp/prefix" \
      -DCMAKE_C_FLAGS="$cflags" -DCMAKE_EXE_LINKER_FLAGS="$cflags" >/dev/null
cmake --build "$tmp/b" >/dev/null
"$tmp/b/consumer"
libdir=$(ls -d "$tmp"/prefix/lib*/pkgconfig | head -n 1)
flags=$(PKG_CONFIG_PATH="$libdir" pkg-config --cflags --libs symline)
# shellcheck disable=SC2086
$cc -std=c99 $cflags "$src/tests/install/consumer/main.c" $flags -o "$tmp/pc"
"$tmp/pc"
echo "find_package and pkg-config consumers: 2 passed, 0 failed"

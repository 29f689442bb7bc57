#!/bin/sh
# The core's rules, checked twice: in the sources (grep) and in what the
# compiler produced (undefined symbols of the built library, and a build of
# lib/ with the FPU registers forbidden, which fails on any float arithmetic).
# Usage: check_core_rules.sh SOURCE_DIR LIBSYMLINE_A CC
case ${1:-} in -h | --help) sed -n '2,/^[^#]/{/SPDX-License-Identifier/d;s/^# \{0,1\}//p;}' "$0"; exit 0 ;; esac
set -u
src=$1 lib=$2 cc=$3
fail=0 pass=0
ok() { pass=$((pass + 1)); }
bad() { echo "FAIL: $*"; fail=$((fail + 1)); }

# 1. grep-level: no allocation, float, stdio or other I/O headers in lib/ or the public headers
hits=$(grep -rnE '\b(malloc|calloc|realloc|free|alloca)[[:space:]]*\(|\b(float|double)\b|#include[[:space:]]*<(stdio|stdlib|math|fcntl|unistd|time|signal)\.h>' \
       --include='*.c' --include='*.h' "$src/lib" "$src/include" | grep -vE '^[^:]+:[0-9]+:[[:space:]]*(/?\*|//)')
[ -z "$hits" ] && ok || bad "lib/ or include/ uses allocation, floating point or I/O headers:
$hits"

# 2. symbol-level: nothing the library calls out to may allocate, print or do float maths
undef=$(nm -u "$lib" 2>/dev/null | awk '{print $NF}' | sort -u)
deny=$(echo "$undef" | grep -E '^(malloc|calloc|realloc|free|aligned_alloc|posix_memalign|printf|fprintf|sprintf|snprintf|vprintf|vfprintf|puts|fputs|putchar|fputc|fwrite|fread|fopen|fclose|write|read|open|close|stdin|stdout|stderr|__stack_chk_fail_local_dummy|sqrt.*|floor.*|ceil.*|pow.*|exp.*|log.*|sin.*|cos.*|atan.*|round.*|lround.*|__.*(sf|df|tf)[0-9]*)$')
[ -z "$deny" ] && ok || bad "libsymline.a references: $deny"
[ -n "$(nm "$lib" 2>/dev/null | grep ' T symline_')" ] && ok || bad "no symline_ symbols found in $lib"

# 3. compiler-level: lib/ builds with general registers only (no x87/SSE float use possible)
case "$($cc -dumpmachine 2>/dev/null)" in
x86_64*|i?86*)
    tmp=$(mktemp -d)
    for f in "$src"/lib/*.c; do
        if ! $cc -std=c99 -O2 -mgeneral-regs-only -ffreestanding -fno-builtin -I"$src/include" \
             -c "$f" -o "$tmp/o.o" 2>"$tmp/err"; then
            bad "$(basename "$f") does not build without FPU registers:"; cat "$tmp/err"
        else
            ok
        fi
    done
    rm -rf "$tmp"
    ;;
*) echo "note: register-level float check runs on x86 hosts only" ;;
esac

echo "$pass passed, $fail failed"
[ $fail -eq 0 ]

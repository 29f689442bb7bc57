#!/bin/sh
# SPDX-License-Identifier: Apache-2.0
# The core's rules, checked twice: in the sources (grep) and in what the
# compiler produced (undefined and defined symbols of the built library, and a build of
# lib/ with the FPU registers forbidden, which fails on any float arithmetic);
# and the layering of the tree: lib/ includes only lib/ and include/,
# capture/ and port/ nothing from tools/, and lib/'s includes form no cycle.
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
# every global the library defines carries the project's prefix (symline_ for
# the API, symline_i_ for internals), so it cannot clash with a vendor SDK
foreign=$(nm -g --defined-only "$lib" 2>/dev/null | awk 'NF == 3 {print $3}' | grep -v '^symline_' | sort -u)
[ -z "$foreign" ] && ok || bad "libsymline.a defines globals without the symline_ prefix: $foreign"

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

# 4. layering: arrows run tools -> capture -> lib -> include, never back.
# Quoted includes resolve against the including file's folder first, then the
# include path; a name is taken as "outside" when no allowed folder holds it.
# includes FILE: the quoted include names of FILE, one per line.
includes() { sed -n 's/^[[:space:]]*#[[:space:]]*include[[:space:]]*"\([^"]*\)".*/\1/p' "$1"; }
# 4a. lib/ includes only lib/ and include/ (and the C library's <...> headers).
bad_inc=""
for f in $(find "$src/lib" "$src/include" -name '*.[ch]'); do
    for h in $(includes "$f"); do
        case "$h" in *..*) bad_inc="$bad_inc
  $f: \"$h\""; continue ;; esac
        [ -f "$(dirname "$f")/$h" ] || [ -f "$src/lib/$h" ] || [ -f "$src/include/$h" ] ||
            bad_inc="$bad_inc
  $f: \"$h\""
    done
done
[ -z "$bad_inc" ] && ok || bad "lib/ or include/ includes a file from outside lib/ and include/:$bad_inc"

# 4b. capture/ and port/ include nothing from tools/: no include names tools/,
# and no quoted include is found only in tools/.
bad_inc=""
for f in $(find "$src/capture" "$src/port" -name '*.[ch]' -o -name '*.cpp' -o -name '*.hpp'); do
    for h in $(includes "$f"); do
        case "$h" in *tools/*) bad_inc="$bad_inc
  $f: \"$h\""; continue ;; esac
        [ -f "$(dirname "$f")/$h" ] && continue
        if [ -n "$(find "$src/tools" -path "*/$h" 2>/dev/null | head -1)" ] &&
           [ -z "$(find "$src/capture" "$src/port" "$src/lib" "$src/include" -path "*/$h" 2>/dev/null | head -1)" ]; then
            bad_inc="$bad_inc
  $f: \"$h\" (only in tools/)"
        fi
    done
done
[ -z "$bad_inc" ] && ok || bad "capture/ or port/ includes from tools/:$bad_inc"
# ... nor do their build files compile or include anything under tools/ (build
# tools such as tools/firmware/pgm2c.c run on the host and are not linked in).
bad_inc=$(grep -nE 'tools/(common|cli|capture|eval|bench|reference)' \
          $(find "$src/capture" "$src/port" -name CMakeLists.txt) 2>/dev/null |
          grep -vE '^[^:]+:[0-9]+:[[:space:]]*#')
[ -z "$bad_inc" ] && ok || bad "capture/ or port/ build files use tools/ sources:
$bad_inc"

# 4c. lib/ has no include cycle, counted per module: foo.c and its private
# header foo.h are one node, so two stages that include each other's header
# form a cycle even when no header includes itself (tsort reports it).
edges=$(for f in "$src"/lib/*.[ch]; do
    b=$(basename "$f"); b=${b%.*}
    echo "$b $b"
    for h in $(includes "$f"); do
        [ -f "$src/lib/$h" ] && [ "${h%.h}" != "$b" ] && echo "$b ${h%.h}"
    done
done)
if cycle=$(echo "$edges" | tsort 2>&1 >/dev/null) && [ -z "$cycle" ]; then
    ok
else
    bad "lib/ has an include cycle:
$cycle"
fi

echo "$pass passed, $fail failed"
[ $fail -eq 0 ]

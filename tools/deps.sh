#!/bin/sh
# SPDX-License-Identifier: Apache-2.0
# Makes sure what a step needs is there.
#  - On Debian and derivatives (dpkg present): installs the missing packages
#    with apt-get (as root; otherwise prints the apt-get command).
#  - Elsewhere (Yocto, Buildroot, Fedora, ...): checks for the tools and
#    libraries themselves and names exactly what is missing.
usage() {
    cat <<'EOF'
usage: tools/deps.sh [build|test] [--check]
  build    what building symline needs: cmake (>= 3.16), make or ninja, a C99
           compiler with the C library headers, pkg-config, libpng (PNG files)
           and libturbojpeg (JPEG files, MJPEG cameras; optional)
  test     build, plus cmocka (the test suite), binutils (nm, size) and
           clang-format (the format test; optional without dpkg)
  --check  only check, install nothing (also the behaviour without dpkg)
Exit status: 0 everything required is there (or was installed), 1 something
required is missing, 2 usage error.
EOF
}
set -eu
step=build check=0
for a in "$@"; do
    case $a in
    -h | --help) usage; exit 0 ;;
    build | test) step=$a ;;
    --check) check=1 ;;
    *) echo "tools/deps.sh: unknown argument '$a'" >&2; usage >&2; exit 2 ;;
    esac
done

# Debian packages of each step; the optional ones are installed, never required.
pkgs="cmake make gcc libc6-dev pkg-config libpng-dev"
optional="libturbojpeg0-dev"
[ "$step" = test ] && pkgs="$pkgs libcmocka-dev binutils clang-format valgrind"

if [ "$check" -eq 0 ] && command -v dpkg >/dev/null 2>&1; then
    need="" want=""
    for p in $pkgs; do dpkg-query -W -f='${Status}\n' "$p" 2>/dev/null | grep -q '^install ok installed$' || need="$need $p"; done
    for p in $optional; do dpkg-query -W -f='${Status}\n' "$p" 2>/dev/null | grep -q '^install ok installed$' || want="$want $p"; done
    [ -z "$need$want" ] && exit 0
    if [ "$(id -u)" -ne 0 ]; then
        [ -z "$want" ] || echo "tools/deps.sh: optional packages missing:$want (sudo apt-get install$want)" >&2
        [ -z "$need" ] && exit 0
        echo "tools/deps.sh: missing packages:$need; run as root or: sudo apt-get install$need" >&2
        exit 1
    fi
    export DEBIAN_FRONTEND=noninteractive
    install() {
        # shellcheck disable=SC2086
        apt-get install -y -q "$@" >/dev/null 2>&1 ||
            { apt-get update -q >/dev/null && apt-get install -y -q "$@" >/dev/null; }
    }
    if [ -n "$need" ]; then
        echo "installing:$need"
        # shellcheck disable=SC2086
        install $need
    fi
    if [ -n "$want" ]; then
        echo "installing (optional):$want"
        # shellcheck disable=SC2086
        install $want || echo "tools/deps.sh: could not install$want (optional: JPEG input is not built)" >&2
    fi
    exit 0
fi

# No dpkg (or --check): look for the things themselves.
missing="" warn=""
miss() { missing="$missing
  - $1"; }
have() { command -v "$1" >/dev/null 2>&1; }

if have cmake; then
    v=$(cmake --version | sed -n 's/^cmake version \([0-9]*\)\.\([0-9]*\).*/\1 \2/p')
    # shellcheck disable=SC2086
    set -- $v
    if [ "${1:-0}" -lt 3 ] || { [ "${1:-0}" -eq 3 ] && [ "${2:-0}" -lt 16 ]; }; then
        miss "cmake >= 3.16 (found $(cmake --version | head -n 1))"
    elif [ "${1:-0}" -eq 3 ] && [ "${2:-0}" -lt 25 ]; then
        warn="$warn
  - cmake $1.$2 has no presets (needs 3.25): use cmake -S . -B build && cmake --build build"
    fi
else
    miss "cmake (>= 3.16)"
fi
have make || have ninja || miss "make (or ninja)"
cc=${CC:-}
if [ -z "$cc" ]; then
    for c in cc gcc clang; do
        if have "$c"; then cc=$c; break; fi
    done
fi
if [ -z "$cc" ]; then
    miss "a C compiler (cc, gcc or clang)"
else
    tmp=$(mktemp -d)
    printf '#include <stdio.h>\n#include <stdint.h>\nint main(void) { return printf("%%u", (unsigned)UINT8_MAX) < 0; }\n' > "$tmp/t.c"
    "$cc" -std=c99 "$tmp/t.c" -o "$tmp/t" >/dev/null 2>&1 ||
        miss "a working C toolchain: $cc cannot build a hello-world program (C library headers, e.g. glibc-devel or libc6-dev, or the assembler and linker, binutils)"
    rm -rf "$tmp"
fi
pc=""
if have pkg-config; then pc=pkg-config; elif have pkgconf; then pc=pkgconf; fi
if [ -z "$pc" ]; then
    miss "pkg-config (or pkgconf)"
    miss "libpng development files: cannot be checked without pkg-config"
else
    "$pc" --exists libpng || miss "libpng development files (libpng.pc; e.g. libpng-devel, libpng-dev)"
    "$pc" --exists libturbojpeg ||
        warn="$warn
  - libturbojpeg (libturbojpeg.pc; e.g. turbojpeg-devel, libturbojpeg0-dev): optional, without it JPEG files and MJPEG cameras are not read"
    if [ "$step" = test ]; then
        "$pc" --exists cmocka || miss "cmocka (cmocka.pc; e.g. libcmocka-devel, libcmocka-dev): the test suite"
    fi
fi
if [ "$step" = test ]; then
    have nm || miss "nm (binutils)"
    have size || miss "size (binutils)"
    have clang-format || warn="$warn
  - clang-format: optional, without it the format test of lib/ is skipped"
fi

[ -z "$warn" ] || echo "tools/deps.sh: note:$warn" >&2
if [ -n "$missing" ]; then
    echo "tools/deps.sh: missing for '$step':$missing" >&2
    exit 1
fi
exit 0

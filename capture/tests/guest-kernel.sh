#!/bin/sh
# SPDX-License-Identifier: Apache-2.0
# Fetches Debian's amd64 kernel package (the one linux-image-amd64 depends on
# today), extracts it into CACHE/kernel-ABI and builds its modules.dep.
# Prints the extracted tree's path. Reruns reuse the cache.
# usage: guest-kernel.sh CACHE_DIR
case ${1:-} in -h | --help) sed -n '2,/^[^#]/{/SPDX-License-Identifier/d;s/^# \{0,1\}//p;}' "$0"; exit 0 ;; esac
set -eu
cache=${1:?usage: guest-kernel.sh CACHE_DIR}
mkdir -p "$cache"
cache=$(cd "$cache" && pwd)

# shellcheck source=pkgs.sh
. "$(dirname "$0")/pkgs.sh"
need_pkgs kmod

# The ABI number changes with security updates: resolve it now.
pkg=$(apt-cache depends linux-image-amd64 2>/dev/null | sed -n 's/^ *Depends: \(linux-image-[0-9].*-amd64\)$/\1/p' | head -n 1)
if [ -z "$pkg" ]; then
    apt-get update >&2
    pkg=$(apt-cache depends linux-image-amd64 | sed -n 's/^ *Depends: \(linux-image-[0-9].*-amd64\)$/\1/p' | head -n 1)
fi
[ -n "$pkg" ] || { echo "guest-kernel: cannot resolve the kernel package of linux-image-amd64" >&2; exit 1; }
kver=${pkg#linux-image-}
tree=$cache/kernel-$kver
if [ ! -f "$tree/.done" ]; then
    # A new ABI replaces the trees (and the vimc and v4l2loopback builds) of older ones.
    rm -rf "$cache"/kernel-* "$cache"/kbuild-* "$cache"/vimc-* "$cache"/kheaders-* "$cache"/loopback-*
    mkdir -p "$tree"
    (cd "$cache" && rm -f "$pkg"_*.deb && apt-get download "$pkg" >&2)
    dpkg-deb -x "$cache/$pkg"_*.deb "$tree"
    rm -f "$cache/$pkg"_*.deb
    # The package ships no modules.dep: build it for the extracted tree.
    depmod -b "$tree" "$kver"
    touch "$tree/.done"
fi
echo "$tree $kver"

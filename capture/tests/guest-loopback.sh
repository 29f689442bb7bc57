#!/bin/sh
# SPDX-License-Identifier: Apache-2.0
# Builds the v4l2loopback driver (not part of the kernel) out of tree for the
# guest kernel: sources from Debian's v4l2loopback-dkms package (fetched with
# apt-get download, never installed), the build tree of guest-kheaders.sh.
# Prints the path of v4l2loopback.ko. Reruns reuse the cache.
# usage: guest-loopback.sh CACHE_DIR KERNEL_VERSION
case ${1:-} in -h | --help) sed -n '2,/^[^#]/{/SPDX-License-Identifier/d;s/^# \{0,1\}//p;}' "$0"; exit 0 ;; esac
set -eu
cache=${1:?usage: guest-loopback.sh CACHE_DIR KERNEL_VERSION}
kver=${2:?usage: guest-loopback.sh CACHE_DIR KERNEL_VERSION}
mkdir -p "$cache"
cache=$(cd "$cache" && pwd)
out=$cache/loopback-$kver
if [ -f "$out/v4l2loopback.ko" ]; then
    echo "$out/v4l2loopback.ko"
    exit 0
fi
here=$(dirname "$0")
hdr=$(sh "$here/guest-kheaders.sh" "$cache" "$kver")
pkg=$cache/loopback-src
if [ ! -f "$pkg/.done" ]; then
    rm -rf "$pkg"
    sh "$here/guest-debs.sh" "$cache" "$pkg" v4l2loopback-dkms
    touch "$pkg/.done"
fi
lsrc=
for d in "$pkg"/usr/src/v4l2loopback-*; do
    [ -f "$d/v4l2loopback.c" ] && lsrc=$d
done
[ -n "$lsrc" ] || { echo "guest-loopback: no v4l2loopback source in the v4l2loopback-dkms package" >&2; exit 1; }
rm -rf "$out"
mkdir -p "$out"
cp -r "$lsrc"/. "$out/"
make -s -C "$hdr" M="$out" modules >&2
[ -f "$out/v4l2loopback.ko" ] || { echo "guest-loopback: build produced no v4l2loopback.ko" >&2; exit 1; }
echo "$out/v4l2loopback.ko"

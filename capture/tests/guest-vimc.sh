#!/bin/sh
# SPDX-License-Identifier: Apache-2.0
# Builds the vimc driver (which Debian's kernel does not ship) out of tree for
# the guest kernel: sources from linux-source-6.1, the build tree of
# guest-kheaders.sh. Prints the path of vimc.ko. Reruns reuse the cache.
# usage: guest-vimc.sh CACHE_DIR KERNEL_VERSION
case ${1:-} in -h | --help) sed -n '2,/^[^#]/{/SPDX-License-Identifier/d;s/^# \{0,1\}//p;}' "$0"; exit 0 ;; esac
set -eu
cache=${1:?usage: guest-vimc.sh CACHE_DIR KERNEL_VERSION}
kver=${2:?usage: guest-vimc.sh CACHE_DIR KERNEL_VERSION}
mkdir -p "$cache"
cache=$(cd "$cache" && pwd)
out=$cache/vimc-$kver
if [ -f "$out/vimc.ko" ]; then
    echo "$out/vimc.ko"
    exit 0
fi
here=$(dirname "$0")
hdr=$(sh "$here/guest-kheaders.sh" "$cache" "$kver")
# The source package of the same kernel series as the headers.
series=$(echo "$kver" | sed 's/^\([0-9]*\.[0-9]*\).*/\1/')
src=$cache/vimc-src
if [ ! -f "$src/.done" ]; then
    rm -rf "$src" "$cache/linux-source"
    mkdir -p "$src"
    sh "$here/guest-debs.sh" "$cache" "$cache/linux-source" "linux-source-$series"
    tarball=$(ls "$cache"/linux-source/usr/src/linux-source-"$series".tar.* | head -n 1)
    tar -xf "$tarball" -C "$src" --strip-components=5 "linux-source-$series/drivers/media/test-drivers/vimc"
    rm -rf "$cache/linux-source"
    touch "$src/.done"
fi
rm -rf "$out"
mkdir -p "$out"
cp -r "$src"/. "$out/"
rm -f "$out/.done"
make -s -C "$hdr" M="$out" CONFIG_VIDEO_VIMC=m modules >&2
[ -f "$out/vimc.ko" ] || { echo "guest-vimc: build produced no vimc.ko" >&2; exit 1; }
echo "$out/vimc.ko"

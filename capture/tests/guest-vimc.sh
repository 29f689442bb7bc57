#!/bin/sh
# SPDX-License-Identifier: Apache-2.0
# Builds the vimc driver (which Debian's kernel does not ship) out of tree for
# the guest kernel: sources from linux-source-6.1, the matching
# linux-headers-ABI tree. Prints the path of vimc.ko. Reruns reuse the cache.
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

# shellcheck source=pkgs.sh
. "$(dirname "$0")/pkgs.sh"
need_pkgs make gcc xz-utils

root=$cache/kbuild-$kver
common=linux-headers-${kver%-amd64}-common
# The kbuild and source packages of the same kernel series as the headers.
series=$(echo "$kver" | sed 's/^\([0-9]*\.[0-9]*\).*/\1/')
if [ ! -f "$root/.done" ]; then
    rm -rf "$root" "$cache/vimc-src"
    mkdir -p "$root" "$cache/debs" "$cache/vimc-src"
    (cd "$cache/debs" && rm -f ./*.deb &&
        apt-get download "linux-headers-$kver" "$common" "linux-kbuild-$series" "linux-source-$series" >&2)
    for d in "$cache"/debs/*.deb; do
        dpkg-deb -x "$d" "$root"
    done
    rm -f "$cache"/debs/*.deb
    tarball=$(ls "$root"/usr/src/linux-source-"$series".tar.* | head -n 1)
    tar -xf "$tarball" -C "$cache/vimc-src" --strip-components=5 "linux-source-$series/drivers/media/test-drivers/vimc"
    rm -f "$tarball"
    touch "$root/.done"
fi
rm -rf "$out"
mkdir -p "$out"
cp -r "$cache"/vimc-src/. "$out/"
# The headers package refers to its other halves by absolute paths: point them into this tree.
hdr=$root/usr/src/linux-headers-$kver
sed -i "s|^include /usr/src/|include $root/usr/src/|" "$hdr/Makefile"
for l in "$hdr"/scripts "$hdr"/tools "$root/usr/src/$common/scripts" "$root/usr/src/$common/tools"; do
    if [ -L "$l" ]; then
        t=$(readlink "$l")
        case $t in /*) ln -sfn "$root$t" "$l" ;; esac
    fi
done
make -s -C "$hdr" M="$out" CONFIG_VIDEO_VIMC=m modules >&2
[ -f "$out/vimc.ko" ] || { echo "guest-vimc: build produced no vimc.ko" >&2; exit 1; }
echo "$out/vimc.ko"

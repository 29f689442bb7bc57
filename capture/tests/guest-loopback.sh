#!/bin/sh
# SPDX-License-Identifier: Apache-2.0
# Builds the v4l2loopback driver (not part of the kernel) out of tree for the
# guest kernel: sources from Debian's v4l2loopback-dkms package, the matching
# linux-headers-ABI tree with its -common half and linux-kbuild. The packages
# are fetched with apt-get download, never installed. Prints the path of
# v4l2loopback.ko. Reruns reuse the cache.
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

# shellcheck source=pkgs.sh
. "$(dirname "$0")/pkgs.sh"
need_pkgs make gcc xz-utils

root=$cache/kheaders-$kver
common=linux-headers-${kver%-amd64}-common
series=$(echo "$kver" | sed 's/^\([0-9]*\.[0-9]*\).*/\1/')
download() {
    (cd "$cache/debs" && rm -f ./*.deb &&
        { apt-get download "$@" >&2 || { apt-get update >&2 && apt-get download "$@" >&2; }; })
}
if [ ! -f "$root/.done" ]; then
    rm -rf "$root"
    mkdir -p "$root" "$cache/debs"
    download "linux-headers-$kver" "$common" "linux-kbuild-$series" v4l2loopback-dkms
    for d in "$cache"/debs/*.deb; do
        dpkg-deb -x "$d" "$root"
    done
    rm -f "$cache"/debs/*.deb
    # The headers package refers to its other halves by absolute paths: point them into this tree.
    hdr=$root/usr/src/linux-headers-$kver
    sed -i "s|^include /usr/src/|include $root/usr/src/|" "$hdr/Makefile"
    for l in "$hdr"/scripts "$hdr"/tools "$root/usr/src/$common/scripts" "$root/usr/src/$common/tools"; do
        if [ -L "$l" ]; then
            t=$(readlink "$l")
            case $t in /*) ln -sfn "$root$t" "$l" ;; esac
        fi
    done
    touch "$root/.done"
fi
lsrc=
for d in "$root"/usr/src/v4l2loopback-*; do
    [ -f "$d/v4l2loopback.c" ] && lsrc=$d
done
[ -n "$lsrc" ] || { echo "guest-loopback: no v4l2loopback source in the v4l2loopback-dkms package" >&2; exit 1; }
rm -rf "$out"
mkdir -p "$out"
cp -r "$lsrc"/. "$out/"
make -s -C "$root/usr/src/linux-headers-$kver" M="$out" modules >&2
[ -f "$out/v4l2loopback.ko" ] || { echo "guest-loopback: build produced no v4l2loopback.ko" >&2; exit 1; }
echo "$out/v4l2loopback.ko"

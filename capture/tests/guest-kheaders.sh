#!/bin/sh
# SPDX-License-Identifier: Apache-2.0
# The guest kernel's build tree for out-of-tree modules: Debian's
# linux-headers-ABI package with its -common half and linux-kbuild, fetched
# with apt-get download (never installed) and unpacked into the cache, their
# absolute paths pointed into it. Prints the headers folder (make -C it
# M=... modules). Reruns reuse the cache.
# usage: guest-kheaders.sh CACHE_DIR KERNEL_VERSION
case ${1:-} in -h | --help) sed -n '2,/^[^#]/{/SPDX-License-Identifier/d;s/^# \{0,1\}//p;}' "$0"; exit 0 ;; esac
set -eu
cache=${1:?usage: guest-kheaders.sh CACHE_DIR KERNEL_VERSION}
kver=${2:?usage: guest-kheaders.sh CACHE_DIR KERNEL_VERSION}
mkdir -p "$cache"
cache=$(cd "$cache" && pwd)
root=$cache/kheaders-$kver
hdr=$root/usr/src/linux-headers-$kver
if [ ! -f "$root/.done" ]; then
    # shellcheck source=pkgs.sh
    . "$(dirname "$0")/pkgs.sh"
    need_pkgs make gcc xz-utils
    common=linux-headers-${kver%-amd64}-common
    series=$(echo "$kver" | sed 's/^\([0-9]*\.[0-9]*\).*/\1/')
    rm -rf "$root"
    mkdir -p "$root"
    sh "$(dirname "$0")/guest-debs.sh" "$cache" "$root" "linux-headers-$kver" "$common" \
        "linux-kbuild-$series"
    # The headers package refers to its other halves by absolute paths: point them into this tree.
    sed -i "s|^include /usr/src/|include $root/usr/src/|" "$hdr/Makefile"
    for l in "$hdr"/scripts "$hdr"/tools "$root/usr/src/$common/scripts" "$root/usr/src/$common/tools"; do
        if [ -L "$l" ]; then
            t=$(readlink "$l")
            case $t in /*) ln -sfn "$root$t" "$l" ;; esac
        fi
    done
    touch "$root/.done"
fi
echo "$hdr"

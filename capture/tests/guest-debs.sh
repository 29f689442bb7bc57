#!/bin/sh
# SPDX-License-Identifier: Apache-2.0
# Unpacks Debian packages into a folder without installing them: apt-get
# download into CACHE_DIR/debs (after an apt-get update when the lists are
# missing or stale), dpkg-deb -x into DEST, the .deb files removed again.
# usage: guest-debs.sh CACHE_DIR DEST PACKAGE...
case ${1:-} in -h | --help) sed -n '2,/^[^#]/{/SPDX-License-Identifier/d;s/^# \{0,1\}//p;}' "$0"; exit 0 ;; esac
set -eu
cache=${1:?usage: guest-debs.sh CACHE_DIR DEST PACKAGE...}
dest=${2:?usage: guest-debs.sh CACHE_DIR DEST PACKAGE...}
shift 2
mkdir -p "$cache/debs" "$dest"
(cd "$cache/debs" && rm -f ./*.deb &&
    { apt-get download "$@" >&2 || { apt-get update >&2 && apt-get download "$@" >&2; }; })
for d in "$cache"/debs/*.deb; do
    dpkg-deb -x "$d" "$dest"
done
rm -f "$cache"/debs/*.deb

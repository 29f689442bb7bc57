#!/bin/sh
# SPDX-License-Identifier: Apache-2.0
# tools/deps.sh on a system without dpkg: it checks for the tools themselves and
# names exactly what is missing. Runs it with a PATH that has every program of
# this machine but dpkg (and, in a second run, but pkg-config and make too).
# Usage: deps_check.sh SOURCE_DIR
case ${1:-} in -h | --help) sed -n '2,/^[^#]/{/SPDX-License-Identifier/d;s/^# \{0,1\}//p;}' "$0"; exit 0 ;; esac
set -u
src=$1
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
pass=0 fail=0
# fakepath DIR EXCLUDED...: DIR holds links to every program on PATH except the excluded ones.
fakepath() {
    d=$1
    shift
    mkdir -p "$d"
    seen=:
    old_ifs=$IFS
    IFS=:
    for p in $PATH; do
        IFS=$old_ifs
        r=$(cd "$p" 2>/dev/null && pwd -P) || continue
        case $seen in *":$r:"*) continue ;; esac # /bin and /usr/bin are often one folder
        seen="$seen$r:"
        for f in "$p"/*; do
            b=${f##*/}
            [ -x "$f" ] && [ ! -e "$d/$b" ] || continue
            skip=0
            for x in "$@"; do [ "$b" = "$x" ] && skip=1; done
            [ $skip -eq 1 ] || ln -s "$f" "$d/$b"
        done
    done
    IFS=$old_ifs
}
fakepath "$tmp/nodpkg" dpkg dpkg-query
if PATH=$tmp/nodpkg sh "$src/tools/deps.sh" build >"$tmp/out" 2>&1; then
    pass=$((pass + 1))
else
    echo "FAIL: without dpkg but with everything else, deps.sh build failed:"; cat "$tmp/out"; fail=$((fail + 1))
fi
fakepath "$tmp/bare" dpkg dpkg-query pkg-config pkgconf make ninja
PATH=$tmp/bare sh "$src/tools/deps.sh" build >"$tmp/out" 2>&1
rc=$?
if [ $rc -eq 1 ] && grep -q -- "- pkg-config (or pkgconf)" "$tmp/out" && grep -q -- "- make (or ninja)" "$tmp/out" &&
    ! grep -q -- "- cmake" "$tmp/out"; then
    pass=$((pass + 1))
else
    echo "FAIL: deps.sh without pkg-config and make (exit $rc):"; cat "$tmp/out"; fail=$((fail + 1))
fi
echo "$pass passed, $fail failed"
[ $fail -eq 0 ]

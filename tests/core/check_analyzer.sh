#!/bin/sh
# SPDX-License-Identifier: Apache-2.0
# GCC's static analyzer (-fanalyzer) over every file of lib/: no warning
# (docs/hardening.md). Exit 77 (skipped) when the compiler is not GCC >= 10.
# usage: check_analyzer.sh SOURCE-DIR [CC]
case "${1:-}" in -h | --help) sed -n '3,/^[^#]/{/^#/s/^# \{0,1\}//p}' "$0"; exit 0 ;; esac
set -u
src=$1 cc=${2:-gcc}
"$cc" -fanalyzer -x c -c -o /dev/null /dev/null 2>/dev/null || { echo "SKIPPED: $cc has no -fanalyzer"; exit 77; }
bad=0
for f in "$src"/lib/*.c; do
    out=$("$cc" -std=c99 -O1 -fanalyzer -Werror -I"$src/include" -I"$src/lib" -c "$f" -o /dev/null 2>&1) || {
        echo "$out" | grep -E 'warning|error' | head -n 5
        bad=1
    }
done
[ $bad -eq 0 ] && echo "gcc -fanalyzer: lib/ clean"
exit $bad

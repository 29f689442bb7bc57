#!/bin/sh
# SPDX-License-Identifier: Apache-2.0
# The evaluation and benchmark programs follow the command-line conventions of
# `symline` (one parser, capture/hostio/hostopts.h): --help on stdout with exit
# 0, --version, --opt=value as --opt value, -- ends the options, and a usage
# error is one line naming the program, exit status 2.
# Usage: tool_conventions.sh BIN_DIR DATA_DIR
case ${1:-} in -h | --help) sed -n '2,/^[^#]/{/SPDX-License-Identifier/d;s/^# \{0,1\}//p;}' "$0"; exit 0 ;; esac
set -u
bin=$1 data=$2
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
pass=0 fail=0
ok() { pass=$((pass + 1)); }
bad() { echo "FAIL: $*"; fail=$((fail + 1)); }
version=$("$bin/symline" --version | sed 's/^symline //')

for t in symline-score symline-render symline-bright symline-resize symline-ixscore symline-bench symline-bench-methods \
    symline-bench-operator symline-advframes symline-peers; do
    p=$bin/$t
    [ -x "$p" ] || [ $t = symline-peers ] || { bad "$t not built"; continue; }
    [ -x "$p" ] || continue # built only where OpenCV is installed
    "$p" --help >"$tmp/out" 2>"$tmp/err"
    if [ $? -eq 0 ] && grep -q "^usage: $t" "$tmp/out" && [ ! -s "$tmp/err" ]; then ok; else bad "$t --help"; fi
    if [ "$("$p" --version)" = "$t $version" ]; then ok; else bad "$t --version"; fi
    "$p" --bogus >"$tmp/out" 2>"$tmp/err"
    if [ $? -eq 2 ] && [ ! -s "$tmp/out" ] && [ "$(wc -l <"$tmp/err")" -eq 1 ] &&
        grep -q "^$t: unknown option '--bogus' (try '$t --help')$" "$tmp/err"; then ok; else bad "$t --bogus"; cat "$tmp/err"; fi
    "$p" >"$tmp/out" 2>"$tmp/err"
    if [ $? -eq 2 ] && grep -q "^$t: .*(try '$t --help')$" "$tmp/err"; then ok; else bad "$t without arguments"; cat "$tmp/err"; fi
done

# A value that is missing or out of range is a usage error.
for cmd in "symline-score --tol" "symline-score --tol 0 gtjson x" "symline-render --set normal --count x $tmp/r" \
    "symline-render --set nosuchset $tmp/r" "symline-bright --mul 2x a b" "symline-ixscore --tol -1 a b" \
    "symline-bench --repeat 0 x" "symline-bench --radius 0 x" "symline-bench-operator symmetry diagonal 3 1 x" \
    "symline-advframes rings 0 10 x"; do
    # shellcheck disable=SC2086 # the command's words
    $bin/$cmd >/dev/null 2>"$tmp/err"
    rc=$?
    t=${cmd%% *}
    if [ $rc -eq 2 ] && [ "$(wc -l <"$tmp/err")" -eq 1 ] && grep -q "^$t: " "$tmp/err"; then ok; else bad "$cmd (exit $rc)"; cat "$tmp/err"; fi
done

# --opt=value is --opt value; -- ends the options; options may follow the arguments.
frame=$data/crops/circle.pgm
"$bin/symline-bright" --mul 0.5 --add -20 "$frame" "$tmp/a.pgm" &&
    "$bin/symline-bright" --mul=0.5 --add=-20 -- "$frame" "$tmp/b.pgm" &&
    "$bin/symline-bright" "$frame" "$tmp/c.pgm" --add -20 --mul 0.5
if [ $? -eq 0 ] && cmp -s "$tmp/a.pgm" "$tmp/b.pgm" && cmp -s "$tmp/a.pgm" "$tmp/c.pgm"; then ok; else bad "symline-bright --opt=value, --"; fi
"$bin/symline-render" --set normal --count 1 --size 64x48 "$tmp/r1" &&
    "$bin/symline-render" --set=normal --count=1 --size=64x48 -- "$tmp/r2"
if [ $? -eq 0 ] && cmp -s "$tmp/r1/normal_000.pgm" "$tmp/r2/normal_000.pgm" &&
    cmp -s "$tmp/r1/normal_000.lines.txt" "$tmp/r2/normal_000.lines.txt"; then ok; else bad "symline-render --opt=value, --"; fi
"$bin/symline-score" gtjson "$tmp/r1/normal_000" >"$tmp/gt.json"
"$bin/symline-score" --tol 3 gt "$tmp/r1/normal_000" "$tmp/gt.json" >"$tmp/s1" &&
    "$bin/symline-score" --tol=3 -- gt "$tmp/r1/normal_000" "$tmp/gt.json" >"$tmp/s2"
if [ $? -eq 0 ] && cmp -s "$tmp/s1" "$tmp/s2" && grep -q '^f1=1' "$tmp/s1"; then ok; else bad "symline-score --tol=3, --"; fi
"$bin/symline-ixscore" --tol 5 "$tmp/r1/normal_000" "$tmp/gt.json" >"$tmp/i1" &&
    "$bin/symline-ixscore" --tol=5 -- "$tmp/r1/normal_000" "$tmp/gt.json" >"$tmp/i2"
if [ $? -eq 0 ] && cmp -s "$tmp/i1" "$tmp/i2" && grep -q 'tol=5.00' "$tmp/i1"; then ok; else bad "symline-ixscore --tol=5, --"; fi

echo "$pass passed, $fail failed"
[ $fail -eq 0 ]

#!/bin/sh
# The CLI's exit codes and messages: 0 ok, 2 usage or input error, and
# messages that name the file and the problem.
# Usage: cli_errors.sh SYMLINE DATA_DIR
case ${1:-} in -h | --help) sed -n '2,/^[^#]/{/SPDX-License-Identifier/d;s/^# \{0,1\}//p;}' "$0"; exit 0 ;; esac
set -u
cli=$1 data=$2
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
pass=0 fail=0

# expect CODE PATTERN -- ARGS...
expect() {
    code=$1 pattern=$2
    shift 3
    "$cli" "$@" >"$tmp/out" 2>"$tmp/err"
    got=$?
    if [ $got -ne "$code" ]; then
        echo "FAIL: symline $* exited $got, expected $code"; cat "$tmp/err"; fail=$((fail + 1)); return
    fi
    if [ -n "$pattern" ] && ! grep -q -- "$pattern" "$tmp/err" "$tmp/out"; then
        echo "FAIL: symline $*: output lacks '$pattern':"; cat "$tmp/err"; fail=$((fail + 1)); return
    fi
    pass=$((pass + 1))
}

printf 'P2\n2 1\n255\n1 2\n' > "$tmp/ascii.pgm"
printf 'P6\n1 1\n255\nabc' > "$tmp/colour.ppm"
printf 'P5\n2 2\n65535\n12345678' > "$tmp/deep.pgm"
printf 'P5\n8 8\n255\nabc' > "$tmp/short.pgm"
printf '\211PNG\r\n\032\n garbage' > "$tmp/bad.png"
good=$(ls "$data"/cases/*.pgm | head -n 1)

expect 0 "usage" -- --help
expect 0 "--radius" -- symmetry --help
expect 2 "usage" --
expect 2 "unknown command" -- frobnicate
expect 2 "--axis" -- symmetry --axis diagonal --radius 3 "$good" "$tmp/o.pgm"
expect 2 "--radius" -- extrema --axis vertical --radius 0 "$good" "$tmp/o.pgm"
expect 2 "--radius" -- extrema --axis vertical --radius 256 "$good" "$tmp/o.pgm"
expect 2 "usage" -- extrema --axis vertical --radius 3 "$good"
expect 2 "unknown option" -- extrema --axis vertical --radius 3 --bogus "$good" "$tmp/o.pgm"
expect 2 "ascii.pgm: ASCII PGM (P2)" -- symmetry --axis vertical --radius 3 "$tmp/ascii.pgm" "$tmp/o.pgm"
expect 2 "colour.ppm: colour PPM (P6)" -- symmetry --axis vertical --radius 3 "$tmp/colour.ppm" "$tmp/o.pgm"
expect 2 "deep.pgm: PGM maxval is 65535" -- symmetry --axis vertical --radius 3 "$tmp/deep.pgm" "$tmp/o.pgm"
expect 2 "short.pgm: truncated PGM data" -- symmetry --axis vertical --radius 3 "$tmp/short.pgm" "$tmp/o.pgm"
expect 2 "missing.pgm: cannot open" -- symmetry --axis vertical --radius 3 "$tmp/missing.pgm" "$tmp/o.pgm"
expect 2 "bad.png: " -- symmetry --axis vertical --radius 3 "$tmp/bad.png" "$tmp/o.pgm"
expect 1 "cannot create" -- symmetry --axis vertical --radius 3 "$good" "$tmp/no/such/dir/o.pgm"
expect 0 "" -- extrema --axis horizontal --radius 3 "$good" "$tmp/o.png"
expect 0 "" -- symmetry --axis horizontal --radius 3 "$tmp/o.png" "$tmp/o2.pgm"

expect 0 "" -- convert "$good" "$tmp/c.png"
expect 2 "convert" -- convert "$good"

expect 0 "--cell" -- boundary --help
expect 0 "field_boundary" -- boundary "$good"
expect 0 "field_boundary" -- boundary "$good" "$tmp/b.png"
expect 2 "usage" -- boundary
expect 2 "--cell needs a number" -- boundary --cell 99 "$good"
expect 2 "power of two" -- boundary --cell 3 "$good"
expect 2 "unknown option" -- boundary --bogus "$good"
expect 2 "missing.pgm: cannot open" -- boundary "$tmp/missing.pgm"
expect 2 "--field needs" -- lines --field sideways "$good"

# Feature points and histograms (docs/format.md), the line method option.
expect 0 "--radius" -- features --help
expect 0 "--plot" -- histogram --help
expect 2 "usage" -- features "$good"
expect 2 "--radius" -- histogram --radius 0 "$good"
expect 2 "unknown option" -- features --radius 3 --plot "$tmp/p.png" "$good"
expect 2 "missing.pgm: cannot open" -- features --radius 3 "$tmp/missing.pgm"
expect 0 "\"points\": \[" -- features --radius 3 "$good"
expect 0 "\"counts\": \[" -- histogram --radius 3 --plot "$tmp/h.pgm" "$good"
expect 1 "cannot create" -- histogram --radius 3 --plot "$tmp/no/such/dir/h.pgm" "$good"
expect 2 "--method" -- lines --method hough "$good"
expect 0 "\"segments\"" -- lines --method muff "$good"
echo "$pass passed, $fail failed"
[ $fail -eq 0 ]

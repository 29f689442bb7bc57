#!/bin/sh
# SPDX-License-Identifier: Apache-2.0
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
    out="$tmp/out"
    # A last argument ">FILE" sends standard output there.
    for last in "$@"; do :; done
    case "$last" in
    ">"*) out=${last#>}
          n=$#; i=1; for a in "$@"; do [ $i -lt $n ] && set -- "$@" "$a"; i=$((i + 1)); done
          shift $n ;;
    esac
    : >"$tmp/out"
    timeout 20 "$cli" "$@" >"$out" 2>"$tmp/err"
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

# Bad files: refused with exit 2 and a message, in bounded time and memory.
# damaged.png: 1x1 gray whose IDAT is cut (leaked the frame buffer after the
# error, found under ASan and valgrind); huge.png: a 65535x65535 16-bit RGB
# header (17 GB if allocated); big.png: 20000x20000 gray; text.png: a tEXt
# chunk claiming 2^31 - 1 bytes.
echo iVBORw0KGgoAAAANSUhEUgAAAAEAAAABCAAAAAA6fptVAAAACklEQVR4nA== | base64 -d >"$tmp/damaged.png"
echo iVBORw0KGgoAAAANSUhEUgAA//8AAP//EAIAAABp95JEAAAAC0lEQVR4nGNggAAAAAgAAbdYc5UAAAAASUVORK5CYII= | base64 -d >"$tmp/huge.png"
echo iVBORw0KGgoAAAANSUhEUgAATiAAAE4gCAAAAADGGxnlAAAAC0lEQVR4nGNggAAAAAgAAbdYc5UAAAAASUVORK5CYII= | base64 -d >"$tmp/big.png"
echo iVBORw0KGgoAAAANSUhEUgAAAAEAAAABCAAAAAA6fptVf////3RFWHRhAGI= | base64 -d >"$tmp/text.png"
printf 'P5\n100000 100000\n255\n' >"$tmp/wide.pgm"
printf 'P5\n20000 20000\n255\n' >"$tmp/big.pgm"
expect 2 "damaged.png: unsupported or damaged PNG" -- lines "$tmp/damaged.png"
expect 2 "huge.png: image size 65535x65535 exceeds the limit" -- lines "$tmp/huge.png"
expect 2 "big.png: image size 20000x20000 exceeds the limit" -- lines "$tmp/big.png"
expect 2 "text.png: unsupported or damaged PNG" -- lines "$tmp/text.png"
expect 2 "wide.pgm: image size 100000x100000 outside 1..65535" -- lines "$tmp/wide.pgm"
expect 2 "big.pgm: image size 20000x20000 exceeds the limit" -- lines "$tmp/big.pgm"
: >"$tmp/empty.pgm"
expect 2 "empty.pgm: empty file" -- lines "$tmp/empty.pgm"
expect 2 "/dev/zero: not a PGM, PNG or JPEG file" -- lines /dev/zero
expect 2 "/dev/urandom: not a PGM, PNG or JPEG file" -- lines /dev/urandom
expect 2 "read error: Is a directory" -- symmetry --axis vertical --radius 3 "$data" "$tmp/o.pgm"
# The pixel limit is the caller's to change.
SYMLINE_MAX_PIXELS=100 expect 2 "exceeds the limit of 100 pixels" -- lines "$good"
SYMLINE_MAX_PIXELS=1000000 expect 0 "" -- lines "$good"

# Output that cannot be written is an error (exit 1), not an empty success.
if [ -w /dev/full ]; then
    expect 1 "writing stdout: No space left on device" -- lines "$good" ">/dev/full"
fi
expect 1 "cannot create" -- overlay "$good" "$tmp/no/such/dir/o.png"

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

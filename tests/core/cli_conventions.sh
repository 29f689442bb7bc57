#!/bin/sh
# SPDX-License-Identifier: Apache-2.0
# The command-line conventions of `symline`: --opt=value, --, '-' for stdin and
# stdout, -o FILE, several inputs or a folder (one JSON object each, with its
# file), the output format by the name, JSON only where asked for, write errors
# with their reason, and a quiet end on a closed pipe.
# Usage: cli_conventions.sh SYMLINE DATA_DIR
case ${1:-} in -h | --help) sed -n '2,/^[^#]/{/SPDX-License-Identifier/d;s/^# \{0,1\}//p;}' "$0"; exit 0 ;; esac
set -u
cli=$1 data=$2
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
pass=0 fail=0
ok() { pass=$((pass + 1)); }
bad() { echo "FAIL: $*"; fail=$((fail + 1)); }
check() { # check DESCRIPTION COMMAND...: the command must succeed
    d=$1
    shift
    if "$@" >"$tmp/out" 2>"$tmp/err"; then ok; else bad "$d"; cat "$tmp/err"; fi
}

frame=$data/crops/circle.pgm
other=$data/crops/goalarea.pgm

# --opt=value is --opt value; -- ends the options.
"$cli" lines --radius 4 --min-length 20 "$frame" >"$tmp/a.json"
"$cli" lines --radius=4 --min-length=20 -- "$frame" >"$tmp/b.json"
if cmp -s "$tmp/a.json" "$tmp/b.json" && grep -q '"segments"' "$tmp/a.json"; then ok; else bad "--opt=value differs from --opt value"; fi

# '-' reads stdin; -o FILE writes there instead of stdout.
"$cli" lines - <"$frame" >"$tmp/c.json"
"$cli" lines "$frame" >"$tmp/d.json"
if cmp -s "$tmp/c.json" "$tmp/d.json"; then ok; else bad "lines - (stdin) differs from the file"; fi
"$cli" lines -o "$tmp/e.json" "$frame" >"$tmp/stdout"
if cmp -s "$tmp/e.json" "$tmp/d.json" && [ ! -s "$tmp/stdout" ]; then ok; else bad "lines -o FILE"; fi

# Images to stdout with '-'; OUT or -o OUT, not both.
"$cli" symmetry --axis horizontal --radius 3 "$frame" "$tmp/s.pgm"
"$cli" symmetry --axis=horizontal --radius=3 "$frame" - >"$tmp/s2.pgm"
"$cli" symmetry --axis horizontal --radius 3 -o "$tmp/s3.pgm" "$frame"
if cmp -s "$tmp/s.pgm" "$tmp/s2.pgm" && cmp -s "$tmp/s.pgm" "$tmp/s3.pgm"; then ok; else bad "symmetry OUT, - and -o OUT differ"; fi
if ! "$cli" symmetry --axis horizontal --radius 3 -o "$tmp/x.pgm" "$frame" "$tmp/y.pgm" 2>"$tmp/err" &&
    grep -q "not both" "$tmp/err"; then ok; else bad "OUT and -o OUT together accepted"; fi

# Several inputs and folders: one object per image, each with its file; masks are not images.
mkdir "$tmp/dir"
cp "$frame" "$tmp/dir/b.pgm"
cp "$other" "$tmp/dir/a.pgm"
cp "$frame" "$tmp/dir/a.mask.pgm"
"$cli" lines "$frame" "$other" >"$tmp/two.json"
if [ "$(grep -c '^{"file": ' "$tmp/two.json")" -eq 2 ] && grep -q "^{\"file\": \"$other\", " "$tmp/two.json"; then
    ok
else
    bad "two inputs: two objects with their files"
fi
"$cli" lines "$tmp/dir" >"$tmp/dir.json"
if [ "$(grep -c '^{"file": ' "$tmp/dir.json")" -eq 2 ] && head -n 1 "$tmp/dir.json" | grep -q "\"$tmp/dir/a.pgm\"" &&
    ! grep -q 'mask' "$tmp/dir.json"; then
    ok
else
    bad "a folder: its images in name order, the mask left out"
fi
if ! grep -q '"file"' "$tmp/d.json"; then ok; else bad "one input: no file key expected"; fi

# The output format follows the name; unknown names are refused, nothing is written.
if ! "$cli" overlay "$frame" "$tmp/o.jpg" 2>"$tmp/err" && grep -q "unknown image format '.jpg'" "$tmp/err" &&
    [ ! -e "$tmp/o.jpg" ]; then ok; else bad "overlay to .jpg"; fi
if ! "$cli" overlay "$frame" "$tmp/o.pgm" 2>"$tmp/err" && grep -q "colour image cannot be written as PGM" "$tmp/err"; then
    ok
else
    bad "overlay to .pgm"
fi
check "overlay to .ppm" "$cli" overlay "$frame" "$tmp/o.ppm"
if [ "$(head -c 2 "$tmp/o.ppm")" = P6 ]; then ok; else bad "overlay .ppm is not P6"; fi

# overlay prints JSON only when asked for.
"$cli" overlay "$frame" "$tmp/o.ppm" >"$tmp/stdout"
if [ ! -s "$tmp/stdout" ]; then ok; else bad "overlay printed to stdout without --json"; fi
"$cli" overlay --json - "$frame" -o "$tmp/o.ppm" >"$tmp/j.json"
if cmp -s "$tmp/j.json" "$tmp/d.json"; then ok; else bad "overlay --json - differs from lines"; fi

# Write errors name the reason; a closed pipe ends quietly with status 0.
if [ -w /dev/full ]; then
    if ! "$cli" lines "$frame" >/dev/full 2>"$tmp/err" && grep -q "No space left on device" "$tmp/err"; then
        ok
    else
        bad "a full disk is not reported"
    fi
fi
big=$data/msl_20190606_r2_cam0_20190606_204340.pgm
{ "$cli" lines "$big" "$big" "$big" 2>"$tmp/err"; echo $? >"$tmp/rc"; } | head -c 10 >/dev/null
if [ "$(cat "$tmp/rc")" -eq 0 ] && [ ! -s "$tmp/err" ]; then ok; else bad "closed pipe: status $(cat "$tmp/rc")"; cat "$tmp/err"; fi

# The options take the library's units (tests/core/test_detopts.c checks the values).
"$cli" lines --side-sigma=-100 "$frame" >/dev/null 2>&1 && ok || bad "--side-sigma -100 refused"
"$cli" lines --side-sigma 101 "$frame" >/dev/null 2>"$tmp/err"
if [ $? -eq 2 ] && grep -q -- "--side-sigma needs an integer -100..100" "$tmp/err"; then ok; else bad "--side-sigma 101 accepted"; fi
"$cli" lines --curve-dev 2.5x "$frame" >/dev/null 2>"$tmp/err"
if [ $? -eq 2 ] && grep -q -- "--curve-dev needs pixels" "$tmp/err"; then ok; else bad "--curve-dev 2.5x accepted"; fi

# --version names the version of the headers (symline/version.h).
v=$(sed -n 's/^#define SYMLINE_VERSION_STRING "\(.*\)"$/\1/p' "$(dirname "$0")/../../include/symline/version.h")
if [ -n "$v" ] && [ "$("$cli" --version)" = "symline $v" ]; then ok; else bad "--version"; fi

# Unknown options and missing values are usage errors naming the option.
"$cli" lines --bogus=1 "$frame" >/dev/null 2>"$tmp/err"
if [ $? -eq 2 ] && grep -q "unknown option '--bogus=1'" "$tmp/err"; then ok; else bad "unknown option"; fi
"$cli" lines "$frame" --radius >/dev/null 2>"$tmp/err"
if [ $? -eq 2 ] && grep -q -- "--radius needs a value" "$tmp/err"; then ok; else bad "missing value"; fi

echo "$pass passed, $fail failed"
[ $fail -eq 0 ]

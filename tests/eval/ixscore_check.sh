#!/bin/sh
# SPDX-License-Identifier: Apache-2.0
# symline-ixscore on a hand-made scene: an L of two ground-truth lines and a T
# (a line ending on another's middle), scored against detections that match,
# have the wrong type, lie too far away, or are missing.
#   ixscore_check.sh SYMLINE_IXSCORE WORKDIR
set -eu
case ${1:-} in
-h | --help)
    sed -n '3,/^set -eu/p' "$0" | sed -e '/^set -eu/d' -e 's/^# \{0,1\}//'
    exit 0
    ;;
esac
[ $# -eq 2 ] || { echo "usage: ixscore_check.sh SYMLINE_IXSCORE WORKDIR" >&2; exit 2; }
ix=$1
d=$2
rm -rf "$d"
mkdir -p "$d"
printf '100 100 300 100\n100 100 100 300\n400 100 600 100\n500 100 500 300\n' > "$d/s.lines.txt"
: > "$d/s.arcs.txt"
: > "$d/s.dontcare.txt"
det() { # FILE INTERSECTIONS...
    f=$1
    shift
    printf '{"width": 640, "height": 480, "segments": [], "intersections": [%s]}\n' "$*" > "$f"
}
expect() { # WHAT LINE KEY=VALUE...
    what=$1 line=$2
    shift 2
    for kv in "$@"; do
        case " $line " in *" $kv "*) ;; *) echo "FAIL $what: want $kv in: $line"; exit 1 ;; esac
    done
}
det "$d/good.json" '{"x": 101.0, "y": 99.0, "type": "L", "rays": [0.00, 90.00], "segments": [0, 1]},
  {"x": 500.5, "y": 100.5, "type": "T", "rays": [0.00, 90.00, 180.00], "segments": [2, 3]}'
expect "both right" "$("$ix" "$d/s" "$d/good.json")" ref=2 det=2 tp=2 fp=0 fn=0 type_ok=2 ray_err=0.000
det "$d/type.json" '{"x": 100.0, "y": 100.0, "type": "X", "rays": [0.00, 90.00, 180.00, 270.00], "segments": [0, 1]}'
expect "wrong type, one missing" "$("$ix" "$d/s" "$d/type.json")" ref=2 det=1 tp=1 fp=0 fn=1 type_ok=0
det "$d/far.json" '{"x": 120.0, "y": 100.0, "type": "L", "rays": [0.00, 90.00], "segments": [0, 1]}'
expect "20 px off (tolerance 8 px at 640)" "$("$ix" "$d/s" "$d/far.json")" tp=0 fp=1 fn=2 p=0.0000 r=0.0000
printf '{"width": 640, "height": 480, "segments": []}\n' > "$d/none.json"
expect "no key" "$("$ix" "$d/s" "$d/none.json")" ref=2 det=0 tp=0 fn=2 p=1.0000 r=0.0000
echo "ixscore: 4 cases ok"

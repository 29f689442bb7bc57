#!/bin/sh
# SPDX-License-Identifier: Apache-2.0
# symline-capture on bad input and stop signals (docs/errors.md):
#   - a replay path that is a device (/dev/zero, /dev/urandom) is refused at
#     once instead of read forever;
#   - a list read from a pipe stops on SIGINT;
#   - a Y4M header with a width that would wrap, and a last frame with
#     truncated chroma, are errors;
#   - a --record recording cut by SIGINT or SIGTERM holds every frame the
#     records report, each complete, and no partial file.
#   - with SYMLINE-ADVFRAMES: SIGTERM in the middle of slow, cluttered
#     frames (2560x1920 rings) ends the loop within one frame time.
# usage: hardening.sh SYMLINE-CAPTURE CAPTURE-CHECK SYMLINE DATA-DIR [SYMLINE-ADVFRAMES]
case "${1:-}" in -h | --help) sed -n '3,/^[^#]/{/^#/s/^# \{0,1\}//p}' "$0"; exit 0 ;; esac
set -u
app=$1 check=$2 cli=$3 data=$(cd "$4" && pwd) adv=${5:-}
tmp=$(mktemp -d)
writer=""
trap '[ -n "$writer" ] && kill "$writer" 2>/dev/null; rm -rf "$tmp"' EXIT
pass=0 fail=0
ok() { pass=$((pass + 1)); }
bad() { echo "FAIL: $*"; fail=$((fail + 1)); }

# expect_fast CODE PATTERN -- ARGS...: exits with CODE within 10 s, stderr has PATTERN.
expect_fast() {
    code=$1 pattern=$2
    shift 3
    timeout 10 "$app" "$@" >"$tmp/out" 2>"$tmp/err"
    got=$?
    if [ $got -ne "$code" ]; then
        bad "symline-capture $* exited $got, expected $code"; cat "$tmp/err"; return
    fi
    if ! grep -q -- "$pattern" "$tmp/err"; then
        bad "symline-capture $*: stderr lacks '$pattern'"; cat "$tmp/err"; return
    fi
    ok
}

# 1. Devices are not lists of frame files.
expect_fast 1 "not a list of frame files" -- --replay /dev/zero --summary-every 0
expect_fast 1 "not a list of frame files" -- --replay /dev/urandom --summary-every 0

# 2. A list from a pipe that never ends: SIGINT stops the reading within a second.
mkfifo "$tmp/list.fifo"
( while :; do echo "frame.pgm"; sleep 0.01; done ) >"$tmp/list.fifo" 2>/dev/null &
writer=$!
"$app" --replay "$tmp/list.fifo" --summary-every 0 >/dev/null 2>"$tmp/err" &
pid=$!
sleep 1
t0=$(date +%s%N)
kill -INT $pid
wait $pid
got=$?
t1=$(date +%s%N)
kill "$writer" 2>/dev/null; wait "$writer" 2>/dev/null; writer=""
ms=$(( (t1 - t0) / 1000000 ))
if [ $got -ne 1 ] || ! grep -q "interrupted" "$tmp/err" || [ $ms -gt 1000 ]; then
    bad "list from a pipe: exit $got after SIGINT in $ms ms (want 1 within 1000 ms)"; cat "$tmp/err"
else
    ok
fi

# 3. Y4M: a width that wraps in 32 bits (4294967360 = 2^32 + 64); a truncated last frame.
printf 'YUV4MPEG2 W4294967360 H2 Cmono\nFRAME\n' >"$tmp/wrap.y4m"
head -c 128 /dev/zero >>"$tmp/wrap.y4m"
expect_fast 1 "bad frame size" -- --replay "$tmp/wrap.y4m" --summary-every 0
{ printf 'YUV4MPEG2 W4 H2 C420jpeg\nFRAME\n'; head -c 12 /dev/zero
  printf 'FRAME\n'; head -c 10 /dev/zero; } >"$tmp/short.y4m"
expect_fast 1 "frame 1 is truncated" -- --replay "$tmp/short.y4m" --summary-every 0
if [ "$(grep -c '"frame"' "$tmp/out")" -ne 1 ]; then
    bad "truncated Y4M: want exactly the complete first frame reported"; cat "$tmp/out"
else
    ok
fi

# A record folder that cannot be made.
expect_fast 1 "cannot create /dev/null/rec" -- --replay "$data" --record 1 /dev/null/rec --summary-every 0

# 4. Recordings cut by a signal: every frame a record reports is recorded whole.
# Long enough that the signal comes first: at about 400 frames a second (the
# bundled frames with recording) 200 rounds ended before it.
i=0
: >"$tmp/frames.txt"
while [ $i -lt 2000 ]; do
    for f in "$data"/*.pgm; do echo "$f" >>"$tmp/frames.txt"; done
    i=$((i + 1))
done
for sig in INT TERM; do
    rec="$tmp/rec-$sig"
    "$app" --replay "$tmp/frames.txt" --record 1 "$rec" --summary-every 0 >"$tmp/rec.jsonl" 2>"$tmp/err" &
    pid=$!
    sleep 1.5
    kill -$sig $pid
    wait $pid
    got=$?
    n=$(grep -c . "$tmp/rec.jsonl")
    if [ $got -ne 0 ] || ! grep -q "stopped (SIG$sig)" "$tmp/err" || [ "$n" -lt 1 ]; then
        bad "record, SIG$sig: exit $got, $n records"; cat "$tmp/err"; continue
    fi
    # The record stream is whole: n well-formed lines, frames 0..n-1.
    if ! "$check" json "$tmp/rec.jsonl" "$n" >/dev/null; then
        bad "record, SIG$sig: the records are not well formed"; continue
    fi
    missing=0 k=0
    while [ $k -lt "$n" ]; do
        f=$(printf '%s/frame%06d.pgm' "$rec" $k)
        if ! "$cli" convert "$f" "$tmp/copy.pgm" 2>/dev/null; then
            missing=$((missing + 1))
        fi
        k=$((k + 1))
    done
    parts=$(find "$rec" -name '.part-*' | wc -l)
    if [ $missing -ne 0 ] || [ "$parts" -ne 0 ]; then
        bad "record, SIG$sig: $missing of $n reported frames missing or damaged, $parts partial files"
    else
        ok
    fi
done

# 5. A stop signal in the middle of cluttered frames: the loop ends within about
#    one frame time (the detection time is bounded; the signal is seen after it).
#    Allowed: two median frames + 500 ms, since other processes on a loaded
#    machine may slow the frame in flight beyond the median; the rest of the
#    list (tens of frames) would take far longer.
if [ -n "$adv" ]; then
    "$adv" rings 2560 1920 "$tmp/rings.pgm"
    i=0
    : >"$tmp/rings.txt"
    while [ $i -lt 50 ]; do echo "$tmp/rings.pgm" >>"$tmp/rings.txt"; i=$((i + 1)); done
    "$app" --replay "$tmp/rings.txt" --summary-every 0 >"$tmp/rings.jsonl" 2>"$tmp/err" &
    pid=$!
    sleep 3
    t0=$(date +%s%N)
    kill -TERM $pid
    wait $pid
    got=$?
    t1=$(date +%s%N)
    ms=$(( (t1 - t0) / 1000000 ))
    # One frame's time: the median latency (read + detection), ms.
    frame_ms=$(sed -n 's/.*"latency_ms": \([0-9.]*\).*/\1/p' "$tmp/rings.jsonl" | sort -n |
        awk '{a[NR] = $1} END {if (NR) print a[int((NR + 1) / 2)]}')
    frame_ms=${frame_ms%.*}
    if [ $got -ne 0 ] || [ -z "$frame_ms" ] || [ $ms -gt $((2 * frame_ms + 500)) ]; then
        bad "SIGTERM mid-frame: exit $got after $ms ms; a frame takes ${frame_ms:-?} ms (allowed: two frames + 500 ms)"
        cat "$tmp/err"
    else
        echo "SIGTERM mid-frame: stopped after $ms ms; a frame takes $frame_ms ms"
        ok
    fi
fi

echo "$pass passed, $fail failed"
[ $fail -eq 0 ]

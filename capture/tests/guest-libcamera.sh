# SPDX-License-Identifier: Apache-2.0
# Sourced by the guest's /init after the vivid checks when the image holds a
# libcamera build: loads vimc and runs symline-capture through libcamera.
# (The vivid module chain already loaded everything vimc depends on.)
insmod /modules/vimc.ko || echo "insmod vimc.ko failed"
i=0
while [ ! -e /sys/bus/platform/drivers/vimc ] && [ $i -lt 50 ]; do sleep 0.1; i=$((i + 1)); done
sleep 1
# No udev daemon here: mark the device nodes initialised so libcamera's udev
# enumerator accepts them.
mkdir -p /run/udev/data
for d in /sys/class/video4linux/* /sys/bus/media/devices/*; do
    [ -f "$d/dev" ] && echo "I:1" >"/run/udev/data/c$(cat "$d/dev")"
done

lc_list() {
    symline-capture-lc --list-cameras >/tmp/lc.list 2>&1
    rc=$?; cat /tmp/lc.list; [ $rc -eq 0 ] && grep -q "Sensor B" /tmp/lc.list
}
check libcamera-list-vimc lc_list

lc_capture() {
    local fmt=$1 out
    out=/tmp/lc-$fmt
    symline-capture-lc --summary-every 0 --timeout 10000 --camera 0 --format "$fmt" --width 640 --height 480 \
        --frames 5 --all-frames --record 4 "$out" >"$out.json" 2>"$out.err"
    rc=$?; cat "$out.err"; [ $rc -eq 0 ] || return 1
    # vimc rounds the width (636x480); the granted size is what counts.
    grep -q "libcamera camera .*Sensor B: $fmt [0-9]*x[0-9]* stride" "$out.err" && capture-check json "$out.json" 5 &&
        capture-check bars "$out/frame000004.pgm"
}
# vimc's capture offers packed RGB: libcamera's RGB888 and BGR888.
check libcamera-vimc-BGR3 lc_capture BGR3
check libcamera-vimc-RGB3 lc_capture RGB3

lc_sigterm() {
    symline-capture-lc --summary-every 0 --timeout 10000 --camera 0 --width 640 --height 480 --frames 0 \
        >/tmp/lcs.json 2>/tmp/lcs.err &
    pid=$!
    sleep 3
    kill -TERM $pid
    wait $pid
    rc=$?
    cat /tmp/lcs.err
    [ $rc -eq 0 ] && grep -q "stopped (SIGTERM)" /tmp/lcs.err && capture-check json /tmp/lcs.json "$(wc -l </tmp/lcs.json)"
}
check libcamera-sigterm-exit-0 lc_sigterm

lc_nocamera() {
    symline-capture-lc --camera "no such camera" --frames 1 >/dev/null 2>/tmp/lcn.err
    rc=$?; cat /tmp/lcn.err
    [ $rc -eq 1 ] && grep -q "no camera 'no such camera'" /tmp/lcn.err
}
check libcamera-unknown-camera lc_nocamera
sed -n 's/^symline-capture: stopped/SYMLINE-INFO libcamera-vimc: stopped/p' /tmp/lc-BGR3.err

#!/bin/sh
# SPDX-License-Identifier: Apache-2.0
# /init of the emulated machine: loads vivid with error injection enabled and
# runs symline-capture against it. Every check prints one marker line,
#   SYMLINE-CHECK <name> PASS|FAIL
# and the run ends with SYMLINE-RESULT PASS|FAIL <passed>/<total>.
export PATH=/bin
mount -t proc proc /proc
mount -t sysfs sysfs /sys
mount -t devtmpfs devtmpfs /dev
mount -t tmpfs tmpfs /tmp

pass=0
fail=0
check() {
    local name=$1
    shift
    if "$@" >/tmp/check.log 2>&1; then
        echo "SYMLINE-CHECK $name PASS"
        pass=$((pass + 1))
    else
        echo "SYMLINE-CHECK $name FAIL"
        sed 's/^/    | /' /tmp/check.log | head -n 20
        fail=$((fail + 1))
    fi
}

# Dependency order was resolved on the build machine (modprobe --show-depends).
for m in $(cat /modules/order); do
    insmod "/modules/$m" || echo "insmod $m failed"
done
# Two instances: video0 single-planar, video1 multi-planar; error injection controls on.
insmod /modules/vivid.ko n_devs=2 multiplanar=1,2 node_types=0x1,0x1 vid_cap_nr=0,1 no_error_inj=0
i=0
while [ ! -e /dev/video1 ] && [ $i -lt 50 ]; do sleep 0.1; i=$((i + 1)); done
echo "guest: $(cat /sys/class/video4linux/video0/name) $(cat /sys/class/video4linux/video1/name)"
# Stamp frames at the start of exposure, as camera sensors do (vivid's default is
# the nominal end of the frame, which it delivers before that time).
for d in /dev/video0 /dev/video1; do
    capture-check set $d "Timestamp Source" 1 || echo "guest: cannot set the timestamp source of $d"
done

cap() { symline-capture --summary-every 0 --timeout 3000 "$@"; }

# One format: 5 frames arrive, JSON well-formed, the luma shows vivid's 75%
# colour bars at the expected levels and matches the reference capture of the
# same kind pixel for pixel (within 2).
format_check() {
    local dev=$1 fmt=$2 expect=$3 ref=$4 out
    out=/tmp/$fmt-${dev#/dev/}
    cap --device "$dev" --format "$fmt" --width 640 --height 360 --frames 5 --all-frames \
        --record 4 "$out" >"$out.json" 2>"$out.err" || { cat "$out.err"; return 1; }
    cat "$out.err"
    grep -q " $fmt 640x360 " "$out.err" || { echo "format $fmt 640x360 not reported"; return 1; }
    capture-check json "$out.json" 5 || return 1
    capture-check bars "$out/frame000004.pgm" "=$expect" $ref
}
# Expected bar levels, from the bars' R, G, B in {0, 190} (75% of full scale):
# vivid's GREY is full-range BT.709 luma; its YUV formats are limited-range
# BT.601, 16 + 219/255 * (0.299 R + 0.587 G + 0.114 B); RGB formats are
# converted by symline-capture with the BT.601 weights imgio uses.
grey_levels=190,176,150,136,54,40,14,0
yuv_levels=179,161,130,112,83,65,35,16
rgb_levels=190,168,133,112,78,57,22,0
check format-GREY format_check /dev/video0 GREY $grey_levels
echo "SYMLINE-INFO GREY $(capture-check bars /tmp/GREY-video0/frame000004.pgm)"
check format-NV12 format_check /dev/video0 NV12 $yuv_levels
echo "SYMLINE-INFO NV12 $(capture-check bars /tmp/NV12-video0/frame000004.pgm)"
yuv_ref=/tmp/NV12-video0/frame000004.pgm
for f in NV21 YU12 YV12 NV16 NV61 422P YUYV YVYU UYVY VYUY; do
    check format-$f format_check /dev/video0 $f $yuv_levels $yuv_ref
done
check format-RGB3 format_check /dev/video0 RGB3 $rgb_levels
echo "SYMLINE-INFO RGB3 $(capture-check bars /tmp/RGB3-video0/frame000004.pgm)"
for f in BGR3 XR24 AR24 XB24 AB24; do
    check format-$f format_check /dev/video0 $f $rgb_levels /tmp/RGB3-video0/frame000004.pgm
done
# 8-bit Bayer: vivid lays the bars' R, G, B out as the mosaic, so inside a bar
# symline-capture's luma equals the RGB formula (the RGB levels, and RGB3 exactly
# within 2); every colour phase once. (vivid has no Motion-JPEG format: that is
# checked on v4l2loopback below.)
for f in BA81 GBRG GRBG RGGB; do
    check format-$f format_check /dev/video0 $f $rgb_levels /tmp/RGB3-video0/frame000004.pgm
done
check mplane-GREY format_check /dev/video1 GREY $grey_levels /tmp/GREY-video0/frame000004.pgm
# NM16 is left out: vivid (6.1) fills its luma plane wrongly (the white bar reads
# 16..34 at the bottom); NM61 takes the same path through symline-capture.
for f in NV12 NM12 NM21 YM12 YM21 NM61 YM16 YUYV UYVY; do
    check mplane-$f format_check /dev/video1 $f $yuv_levels $yuv_ref
done
check mplane-BA81 format_check /dev/video1 BA81 $rgb_levels /tmp/RGB3-video0/frame000004.pgm

# What a user asks first: which devices, which formats; --device N is /dev/videoN.
list_devices() {
    symline-capture --list-devices >/tmp/ld.out 2>&1
    rc=$?; cat /tmp/ld.out; [ $rc -eq 0 ] || return 1
    grep -q '^/dev/video0: .*vivid.*: video capture; formats symline reads:.* GREY.* BA81' /tmp/ld.out &&
        grep -q '^/dev/video1: .*vivid.*: video capture (multi-planar); formats symline reads:.* NM12' /tmp/ld.out
}
check list-devices list_devices
list_formats() {
    symline-capture --device 0 --list-formats >/tmp/lf.out 2>&1
    rc=$?; cat /tmp/lf.out; [ $rc -eq 0 ] || return 1
    grep -q '^/dev/video0: ' /tmp/lf.out && grep -q '^  BA81 .*Bayer mosaic converted to luma$' /tmp/lf.out &&
        grep -q '^  NV12 .*luma read in place$' /tmp/lf.out && grep -q '^  YUYV .*luma copied out$' /tmp/lf.out &&
        grep -q '^        640x360 .* fps$' /tmp/lf.out
}
check list-formats list_formats
device_number() {
    cap --device 1 --format GREY --frames 2 >/tmp/dn.json 2>/tmp/dn.err
    rc=$?; cat /tmp/dn.err; [ $rc -eq 0 ] && grep -q '^symline-capture: /dev/video1 (' /tmp/dn.err &&
        capture-check json /tmp/dn.json 2
}
check device-number device_number

# Size and frame interval requests: the granted values are reported.
granted() {
    cap --device /dev/video0 --format YUYV --width 1280 --height 720 --fps 10 --frames 3 >/tmp/g.json 2>/tmp/g.err
    rc=$?; cat /tmp/g.err; [ $rc -eq 0 ] || return 1
    grep -q " YUYV 1280x720 bytesperline 2560, 10/1 fps" /tmp/g.err && capture-check json /tmp/g.json 3
}
check size-and-rate granted
# --profile on a live camera: each record splits its detect time by the detector's stages.
profiled() {
    cap --device /dev/video0 --format YUYV --frames 3 --profile >/tmp/p.json 2>/tmp/p.err
    rc=$?; cat /tmp/p.err; [ $rc -eq 0 ] && grep -q 'detect stages, mean ms per frame: setup=' /tmp/p.err &&
        capture-check stages /tmp/p.json 3 setup field stats grid operator extrema filter trace segments subpixel merge curvejoin
}
check profile profiled
# A size the webcam input does not offer: the driver's nearest size is used,
# reported, and matches the frames' own size; the buffer count is honoured.
odd_size() {
    cap --device /dev/video0 --format GREY --width 1000 --height 700 --buffers 8 --frames 2 >/tmp/o.json 2>/tmp/o.err
    rc=$?; cat /tmp/o.err; [ $rc -eq 0 ] || return 1
    size=$(sed -n 's/.* GREY \([0-9]*\)x\([0-9]*\) bytesperline.*/"width": \1, "height": \2,/p' /tmp/o.err)
    echo "granted: $size"
    [ -n "$size" ] && ! grep -q '"width": 1000, ' /tmp/o.json && grep -q "$size" /tmp/o.json &&
        grep -q ", 8 buffers" /tmp/o.err && capture-check json /tmp/o.json 2
}
check odd-size-nearest odd_size
# vivid has no exposure control: said so, and capture goes on.
no_exposure() {
    cap --device /dev/video0 --format GREY --exposure 2000 --frames 2 >/tmp/e.json 2>/tmp/e.err
    rc=$?; cat /tmp/e.err; [ $rc -eq 0 ] && grep -q "exposure control not offered" /tmp/e.err &&
        capture-check json /tmp/e.json 2
}
check exposure-not-offered no_exposure

# Freshest-frame mode when detection is slower than the camera: vivid grants
# 12.5 fps at 1280x720 (80 ms a frame); the default detection takes a fraction
# of that under emulation, so each frame is detected 40 times (--repeat), at
# full size (--bin off; binned it costs about half), and frames queue up.
# Older frames are re-queued unprocessed, frames keep rising, none is handed
# out twice.
freshest() {
    cap --device /dev/video0 --format NV12 --width 1280 --height 720 --fps 30 --buffers 4 --frames 10 --repeat 40 --bin off \
        >/tmp/f.json 2>/tmp/f.err
    rc=$?; cat /tmp/f.err; [ $rc -eq 0 ] || return 1
    ! grep -q "skipped_stale=0 " /tmp/f.err && grep -q '"skipped": [1-9]' /tmp/f.json && capture-check json /tmp/f.json 10
}
check freshest-frames freshest
# The same with --all-frames: every frame in order, none skipped.
all_frames() {
    cap --device /dev/video0 --format NV12 --width 1280 --height 720 --fps 30 --buffers 4 --frames 10 --repeat 40 --all-frames --bin off \
        >/tmp/a.json 2>/tmp/a.err
    rc=$?; cat /tmp/a.err; [ $rc -eq 0 ] && grep -q "skipped_stale=0 " /tmp/a.err && capture-check json /tmp/a.json 10
}
check all-frames all_frames
# Figures for docs/capture.md (emulated machine: TCG, no KVM).
sed -n 's/^symline-capture: stopped/SYMLINE-INFO freshest: stopped/p' /tmp/f.err
sed -n 's/^symline-capture: stopped/SYMLINE-INFO all-frames: stopped/p' /tmp/a.err
sed -n 's/^symline-capture: stopped/SYMLINE-INFO 5fps-GREY: stopped/p' /tmp/GREY-video0.err

# Runs symline-capture in the background, presses a vivid control after 1 s,
# stops it with a signal after 2 s; the exit status is in $rc, stderr in /tmp/bg.err.
background() {
    local dev=$1 control=$2 sig=$3
    # Started directly (not through a shell function) so that $! is its own pid.
    symline-capture --summary-every 1 --timeout 3000 --device "$dev" --format GREY --width 640 --height 360 \
        --frames 0 --all-frames >/tmp/bg.json 2>/tmp/bg.err &
    pid=$!
    sleep 1
    if [ -n "$control" ]; then capture-check press "$dev" "$control" || echo "press failed"; fi
    sleep 1
    kill -"$sig" $pid 2>/dev/null
    wait $pid
    rc=$?
    cat /tmp/bg.err
}
sigterm() {
    background /dev/video0 "" TERM
    # Also the periodic summary (every second here).
    [ $rc -eq 0 ] && grep -q "stopped (SIGTERM)" /tmp/bg.err && ! grep -q "error" /tmp/bg.json &&
        grep -q "^symline-capture: [0-9.]* fps, latency mean [0-9.-]* ms max" /tmp/bg.err
}
check sigterm-exit-0 sigterm
sigint() {
    background /dev/video0 "" INT
    [ $rc -eq 0 ] && grep -q "stopped (SIGINT)" /tmp/bg.err
}
check sigint-exit-0 sigint
buf_error() {
    background /dev/video0 "Inject V4L2_BUF_FLAG_ERROR" TERM
    [ $rc -eq 0 ] && grep -q "error_buffers=1 " /tmp/bg.err || return 1
    n=$(wc -l </tmp/bg.json)
    capture-check json /tmp/bg.json "$n"
}
check buffer-error-skipped buf_error
qbuf_error() {
    background /dev/video0 "Inject VIDIOC_QBUF Error" TERM
    [ $rc -eq 0 ] && grep -q "requeue_errors=1 " /tmp/bg.err
}
check qbuf-error-recovered qbuf_error
streamon_error() {
    capture-check press /dev/video0 "Inject VIDIOC_STREAMON Error" || return 1
    cap --device /dev/video0 --format GREY --frames 3 >/tmp/s.json 2>/tmp/s.err
    rc=$?; cat /tmp/s.err
    [ $rc -eq 1 ] && grep -q "VIDIOC_STREAMON failed: " /tmp/s.err
}
check streamon-error streamon_error
reqbufs_error() {
    capture-check press /dev/video0 "Inject VIDIOC_REQBUFS Error" || return 1
    cap --device /dev/video0 --format GREY --frames 3 >/tmp/s.json 2>/tmp/s.err
    rc=$?; cat /tmp/s.err
    [ $rc -eq 1 ] && grep -q "VIDIOC_REQBUFS (4 mmap buffers) failed: " /tmp/s.err
}
check reqbufs-error reqbufs_error
recovers() {
    cap --device /dev/video0 --format GREY --frames 3 >/tmp/r.json 2>/tmp/r.err
    rc=$?; cat /tmp/r.err; [ $rc -eq 0 ] && capture-check json /tmp/r.json 3
}
check after-errors-ok recovers
fatal_error() {
    background /dev/video1 "Inject Fatal Streaming Error" TERM
    # vb2 fails the next DQBUF or QBUF with EIO, whichever comes first.
    [ $rc -eq 1 ] && grep -q "device lost during VIDIOC_D*Q*BUF (Input/output error); stopping" /tmp/bg.err
}
check fatal-streaming-error fatal_error
disconnect() {
    background /dev/video0 "Disconnect" TERM
    [ $rc -eq 1 ] && grep -q "device lost" /tmp/bg.err && grep -q "stopped (device lost)" /tmp/bg.err
}
check disconnect disconnect

# Motion-JPEG through a real driver: v4l2loopback, its output side fed one JPEG
# frame (YCbCr 4:2:2, made on the build machine from a bundled frame) every 40 ms,
# as a program relaying a webcam stream does; symline-capture reads the capture
# side. The decoded luma matches libjpeg-turbo's own decoding within 2, and every
# frame finds as many segments as the detector finds in that decoding on the
# build machine.
if [ -f /modules/v4l2loopback.ko ]; then
    insmod /modules/v4l2loopback.ko video_nr=9 card_label=symline-loopback || echo "insmod v4l2loopback.ko failed"
    mjpeg_loopback() {
        local feeder rc
        [ -e /dev/video9 ] || { echo "no /dev/video9"; return 1; }
        capture-check feed /dev/video9 /mjpeg/frame.jpg 608 800 2>/tmp/feed.err &
        feeder=$!
        sleep 1
        cap --device /dev/video9 --format MJPG --width 608 --height 800 --frames 5 --all-frames \
            --record 4 /tmp/mjpeg >/tmp/mjpeg.json 2>/tmp/mjpeg.err
        rc=$?
        kill $feeder 2>/dev/null
        wait $feeder
        cat /tmp/feed.err /tmp/mjpeg.err
        [ $rc -eq 0 ] && grep -q " MJPG 608x800 " /tmp/mjpeg.err && capture-check steady /tmp/mjpeg.json 5 "$(cat /mjpeg/segments)" &&
            capture-check same /tmp/mjpeg/frame000004.pgm /mjpeg/ref.pgm
    }
    t0=$(cut -d ' ' -f 1 /proc/uptime)
    check mjpeg-loopback mjpeg_loopback
    echo "SYMLINE-INFO mjpeg-loopback: step took $(awk -v a="$t0" '{ printf "%.1f", $1 - a }' /proc/uptime) s"
    sed -n 's/^symline-capture: stopped/SYMLINE-INFO mjpeg-loopback: stopped/p' /tmp/mjpeg.err
    echo "SYMLINE-INFO mjpeg-loopback: $(capture-check steady /tmp/mjpeg.json 5 "$(cat /mjpeg/segments)" 2>&1);" \
        "$(capture-check same /tmp/mjpeg/frame000004.pgm /mjpeg/ref.pgm 2>&1)"
fi

if [ -x /bin/guest-libcamera.sh ]; then
    . /bin/guest-libcamera.sh
fi

total=$((pass + fail))
if [ $fail -eq 0 ] && [ $total -gt 0 ]; then
    echo "SYMLINE-RESULT PASS $pass/$total"
else
    echo "SYMLINE-RESULT FAIL $pass/$total"
fi
poweroff -f

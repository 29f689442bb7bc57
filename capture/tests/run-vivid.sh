#!/bin/sh
# SPDX-License-Identifier: Apache-2.0
# Integration test of the capture layer against real kernel drivers: boots
# Debian's own kernel under qemu (TCG), loads vivid (and vimc when libcamera is
# built), and runs a statically linked symline-capture inside the guest.
# Pass/fail comes from the markers the guest prints on its serial console.
# Motion-JPEG, which vivid does not offer, goes through v4l2loopback (built
# here for the guest kernel from Debian's v4l2loopback-dkms source).
# The libcamera checks on vimc run unless SYMLINE_WITH_LIBCAMERA=OFF; what they
# need (libcamera-dev, g++) is installed with apt-get. A step that cannot run
# is printed as SKIP, never counted as passed, and the run then exits 77
# (CTest: skipped) instead of 0.
#
# usage: run-vivid.sh [--cache DIR] [--log FILE]
#   --cache DIR  downloads, extracted kernel and guest build (default:
#                $XDG_CACHE_HOME/symline-capture or ~/.cache/symline-capture)
#   --log FILE   keep the serial log there (default: CACHE/vivid-serial.log)
case ${1:-} in -h | --help) sed -n '2,/^[^#]/{/SPDX-License-Identifier/d;s/^# \{0,1\}//p;}' "$0"; exit 0 ;; esac
set -eu

here=$(cd "$(dirname "$0")" && pwd)
src=$(cd "$here/../.." && pwd)
cache=${XDG_CACHE_HOME:-${HOME:-/tmp}/.cache}/symline-capture
log=
while [ $# -gt 0 ]; do
    case $1 in
        --cache) cache=$2; shift 2 ;;
        --log) log=$2; shift 2 ;;
        *) echo "usage: run-vivid.sh [--cache DIR] [--log FILE]" >&2; exit 2 ;;
    esac
done
mkdir -p "$cache"
cache=$(cd "$cache" && pwd)
[ -n "$log" ] || log=$cache/vivid-serial.log

# shellcheck source=pkgs.sh
. "$(dirname "$0")/pkgs.sh"
need_pkgs qemu-system-x86 busybox-static cpio kmod cmake gcc libc6-dev
skipped=""
skip() {
    echo "SYMLINE-SKIP $1"
    skipped="$skipped
  - $1"
}

set -- $(sh "$here/guest-kernel.sh" "$cache")
ktree=$1
kver=$2
kimage=$ktree/boot/vmlinuz-$kver

# A cached build tree of another checkout is started afresh.
fresh_build_dir() {
    if [ -f "$1/CMakeCache.txt" ] && ! grep -q "^CMAKE_HOME_DIRECTORY:INTERNAL=$src\$" "$1/CMakeCache.txt"; then
        rm -rf "$1"
    fi
}

# Guest build: static, PGM only (no libpng in the guest); Motion-JPEG decoded with
# libturbojpeg's archive, installed here when missing (without it the MJPEG step is skipped).
need_pkgs libturbojpeg0-dev pkg-config || true
gbuild=$cache/guest-build
fresh_build_dir "$gbuild"
cmake -S "$src" -B "$gbuild" -DCMAKE_BUILD_TYPE=Release -DSYMLINE_BUILD_TESTS=OFF \
    -DCMAKE_DISABLE_FIND_PACKAGE_PNG=ON -DCMAKE_EXE_LINKER_FLAGS=-static \
    -DSYMLINE_WITH_LIBCAMERA=OFF -DSYMLINE_WERROR=ON >/dev/null
cmake --build "$gbuild" -j2 --target symline_capture_app capture_check >/dev/null

root=$cache/initramfs-vivid
rm -rf "$root"
mkdir -p "$root/bin" "$root/proc" "$root/sys" "$root/dev" "$root/tmp" "$root/modules" "$root/run"
cp /bin/busybox "$root/bin/busybox"
# Applet links; the list includes 'busybox' itself, which must stay the binary.
for a in $("$root/bin/busybox" --list); do
    [ "$a" = busybox ] || ln -sf busybox "$root/bin/$a"
done
cp "$gbuild/bin/symline-capture" "$gbuild/bin/capture-check" "$root/bin/"
cp "$here/guest-vivid.sh" "$root/init"
chmod +x "$root/init"

# vivid's dependency chain, in load order, from the kernel's own modules.dep.
: >"$root/modules/order"
modprobe -d "$ktree" -S "$kver" --show-depends vivid | while read -r cmd path _; do
    [ "$cmd" = insmod ] || continue
    name=$(basename "$path")
    cp "$path" "$root/modules/$name"
    [ "$name" = vivid.ko ] || echo "$name" >>"$root/modules/order"
done
[ -f "$root/modules/vivid.ko" ] || { echo "run-vivid: vivid.ko not found in $kver" >&2; exit 1; }

# Motion-JPEG through a real driver (vivid offers none): v4l2loopback, built for the
# guest kernel from Debian's v4l2loopback-dkms source; capture-check feeds its output
# side a JPEG made here from a bundled frame, symline-capture reads the capture side.
loop_frame=$src/tests/data/msl_20190606_r2_cam0_20190606_204340.pgm
with_loopback=0
if ! loopko=$(sh "$here/guest-loopback.sh" "$cache" "$kver"); then
    skip "mjpeg-loopback: v4l2loopback could not be built for $kver (see above)"
else
    rc=0
    mkdir -p "$root/mjpeg"
    "$gbuild/bin/capture-check" jpeg "$loop_frame" "$root/mjpeg/frame.jpg" "$root/mjpeg/ref.pgm" >&2 || rc=$?
    missing=
    for d in $(modinfo -F depends "$loopko" | tr ',' ' '); do
        grep -q "^$d.ko\$" "$root/modules/order" || missing="$missing $d"
    done
    # What the detector finds in the reference luma (the same program, replaying it here):
    # the guest must find exactly that in every decoded frame.
    if [ $rc -eq 0 ]; then
        rm -rf "$cache/mjpeg-ref"
        mkdir -p "$cache/mjpeg-ref"
        cp "$root/mjpeg/ref.pgm" "$cache/mjpeg-ref/"
        "$gbuild/bin/symline-capture" --replay "$cache/mjpeg-ref" --frames 1 --summary-every 0 \
            >"$cache/mjpeg-ref.json" 2>/dev/null || rc=$?
        "$gbuild/bin/capture-check" steady "$cache/mjpeg-ref.json" 1 |
            sed -n 's/^steady: 1 lines, \([0-9]*\) segments each$/\1/p' >"$root/mjpeg/segments"
        [ -s "$root/mjpeg/segments" ] || rc=1
    fi
    if [ $rc -eq 77 ]; then
        skip "mjpeg-loopback: the guest build has no libturbojpeg (libturbojpeg0-dev's archive)"
    elif [ $rc -ne 0 ]; then
        echo "run-vivid: cannot make the Motion-JPEG frame or its reference" >&2
        exit 1
    elif [ -n "$missing" ]; then
        skip "mjpeg-loopback: v4l2loopback needs modules vivid does not load:$missing"
    else
        cp "$loopko" "$root/modules/v4l2loopback.ko"
        with_loopback=1
    fi
fi

# libcamera on vimc: its build needs libcamera-dev and g++, installed here when
# missing; only SYMLINE_WITH_LIBCAMERA=OFF or a failed installation leaves it out,
# and then it is reported as skipped.
with_libcamera=0
if [ "${SYMLINE_WITH_LIBCAMERA:-AUTO}" = OFF ]; then
    skip "libcamera checks on vimc: SYMLINE_WITH_LIBCAMERA=OFF"
elif ! need_pkgs libcamera-dev g++ pkg-config; then
    skip "libcamera checks on vimc: libcamera-dev or g++ could not be installed"
elif ! pkg-config --exists libcamera 2>/dev/null; then
    skip "libcamera checks on vimc: pkg-config does not find libcamera"
else
    with_libcamera=1
fi
if [ $with_libcamera = 1 ]; then
    vimc=$(sh "$here/guest-vimc.sh" "$cache" "$kver")
    cp "$vimc" "$root/modules/vimc.ko"
    # libcamera's vimc pipeline needs its IPA module: taken from the package, not installed.
    ipa=$cache/libcamera-ipa
    if [ ! -f "$ipa/.done" ]; then
        rm -rf "$ipa"
        mkdir -p "$ipa"
        (cd "$cache" && rm -f libcamera-ipa_*.deb && apt-get download libcamera-ipa >&2)
        dpkg-deb -x "$cache"/libcamera-ipa_*.deb "$ipa"
        rm -f "$cache"/libcamera-ipa_*.deb
        touch "$ipa/.done"
    fi
    lbuild=$cache/guest-build-libcamera
    fresh_build_dir "$lbuild"
    cmake -S "$src" -B "$lbuild" -DCMAKE_BUILD_TYPE=Release -DSYMLINE_BUILD_TESTS=OFF \
        -DCMAKE_DISABLE_FIND_PACKAGE_PNG=ON -DSYMLINE_WITH_LIBCAMERA=ON >/dev/null
    cmake --build "$lbuild" -j2 --target symline_capture_app >/dev/null
    cp "$lbuild/bin/symline-capture" "$root/bin/symline-capture-lc"
    cp "$here/guest-libcamera.sh" "$root/bin/guest-libcamera.sh"
    chmod +x "$root/bin/guest-libcamera.sh"
    ipadir=$(pkg-config --variable=libdir libcamera)/libcamera
    mkdir -p "$root$ipadir" "$root/usr/share/libcamera/ipa"
    cp "$ipa$ipadir"/ipa_vimc.so "$ipa$ipadir"/ipa_vimc.so.sign "$ipa$ipadir"/vimc_ipa_proxy "$root$ipadir/"
    cp -r "$ipa/usr/share/libcamera/ipa/vimc" "$root/usr/share/libcamera/ipa/"
    # The shared libraries of the dynamic programs, at their own paths.
    for bin in "$root/bin/symline-capture-lc" "$root$ipadir/ipa_vimc.so" "$root$ipadir/vimc_ipa_proxy"; do
        ldd "$bin" | sed -n 's/.*=> \(\/[^ ]*\).*/\1/p; s/^[[:space:]]*\(\/[^ ]*\) (.*/\1/p'
    done | sort -u | while read -r lib; do
        mkdir -p "$root$(dirname "$lib")"
        cp -L "$lib" "$root$lib"
    done
fi

initrd=$cache/initramfs-vivid.cpio.gz
(cd "$root" && find . | cpio -o -H newc --quiet | gzip -1) >"$initrd"

echo "run-vivid: booting $kver under qemu (TCG)" >&2
start=$(date +%s)
timeout 300 qemu-system-x86_64 -accel tcg -m 512 -nographic -no-reboot -nic none \
    -kernel "$kimage" -initrd "$initrd" -append "console=ttyS0 quiet panic=-1" >"$log" 2>&1 || true
end=$(date +%s)

grep -a -E '^(SYMLINE-CHECK|SYMLINE-RESULT|SYMLINE-INFO|    \| )' "$log" | tr -d '\r' || true
echo "run-vivid: guest ran $((end - start)) s; serial log: $log" >&2
# The loopback and libcamera checks were built into the guest: they must also have run.
if [ $with_loopback = 1 ] && ! grep -a -q '^SYMLINE-CHECK mjpeg-loopback ' "$log"; then
    echo "run-vivid: the Motion-JPEG check on v4l2loopback was built but did not run" >&2
    exit 1
fi
if [ $with_libcamera = 1 ] && ! grep -a -q '^SYMLINE-CHECK libcamera-list-vimc ' "$log"; then
    echo "run-vivid: the libcamera checks were built but did not run" >&2
    exit 1
fi
if grep -a -q '^SYMLINE-RESULT PASS' "$log" && ! grep -a -q '^SYMLINE-CHECK .* FAIL' "$log"; then
    if [ -n "$skipped" ]; then
        echo "run-vivid: every check that ran passed; SKIPPED (not passed):$skipped" >&2
        exit 77
    fi
    exit 0
fi
grep -a -q '^SYMLINE-RESULT' "$log" || { echo "run-vivid: the guest did not finish; log tail:" >&2; tail -n 30 "$log" >&2; }
exit 1

#!/bin/sh
# Installs the Debian packages a step needs when they are missing (as root,
# with apt-get). Usage: tools/deps.sh build|test
set -eu
need=""
# dpkg-query -W, not dpkg -s: with a second architecture (arm64, tools/aarch64/check.sh)
# a package installed for both has an ambiguous name that dpkg -s rejects.
add() { dpkg-query -W -f='${Status}\n' "$1" 2>/dev/null | grep -q "ok installed" || need="$need $1"; }
for p in cmake make gcc libc6-dev pkg-config libpng-dev; do add "$p"; done
case "${1:-build}" in
test) for p in libcmocka-dev binutils clang-format; do add "$p"; done ;;
build) ;;
*) echo "usage: tools/deps.sh build|test" >&2; exit 2 ;;
esac
[ -z "$need" ] && exit 0
echo "installing:$need"
if [ "$(id -u)" -ne 0 ]; then
    echo "tools/deps.sh: missing packages:$need — run as root or: sudo apt-get install$need" >&2
    exit 1
fi
export DEBIAN_FRONTEND=noninteractive
# shellcheck disable=SC2086
apt-get install -y -q $need >/dev/null 2>&1 || { apt-get update -q >/dev/null && apt-get install -y -q $need >/dev/null; }

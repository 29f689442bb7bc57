#!/bin/sh
# SPDX-License-Identifier: Apache-2.0
# C sources against .clang-format (clang-format 14).
#   tools/format.sh [--check] [DIR|FILE ...]     default: lib include
# Without --check the files are rewritten in place; with it, every file that
# differs is named and the exit status is 1. Exit 77 when clang-format is
# missing (CTest reports the test as skipped).
case ${1:-} in -h | --help) sed -n '2,/^[^#]/{/SPDX-License-Identifier/d;s/^# \{0,1\}//p;}' "$0"; exit 0 ;; esac
set -u
cd "$(dirname "$0")/.." || exit 2
check=0
if [ "${1:-}" = "--check" ]; then
    check=1
    shift
fi
[ $# -eq 0 ] && set -- lib include
cf=${CLANG_FORMAT:-clang-format}
if ! command -v "$cf" >/dev/null 2>&1; then
    echo "format.sh: $cf not found (apt-get install clang-format)"
    exit 77
fi
bad=0
for f in $(find "$@" -type f \( -name '*.c' -o -name '*.h' -o -name '*.cpp' \) | sort); do
    if [ $check -eq 1 ]; then
        if ! "$cf" --style=file "$f" | cmp -s - "$f"; then
            echo "not formatted: $f (tools/format.sh $f)"
            bad=1
        fi
    else
        "$cf" --style=file -i "$f"
    fi
done
exit $bad

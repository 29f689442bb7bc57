#!/bin/sh
# SPDX-License-Identifier: Apache-2.0
# Every script of the project answers --help: exit 0 and a description on
# stdout, without doing anything else. (The two scripts that run inside the
# integration test's emulated machine, as its /init, are left out.)
# Usage: scripts_help.sh SOURCE_DIR
case ${1:-} in -h | --help) sed -n '2,/^[^#]/{/SPDX-License-Identifier/d;s/^# \{0,1\}//p;}' "$0"; exit 0 ;; esac
set -u
cd "$1" || exit 2
pass=0 fail=0
for s in $(find tools tests capture -name '*.sh' | sort); do
    case $s in capture/tests/guest-vivid.sh | capture/tests/guest-libcamera.sh) continue ;; esac
    # Only scripts that handle --help are run with it: a script that does not might
    # take it for a file name and act on it.
    # (Directly, or through the shared preamble tools/args.sh.)
    if ! head -n 40 "$s" | grep -q -e '--help)' -e '^\. .*/args\.sh"$'; then
        echo "FAIL: $s does not handle --help"
        fail=$((fail + 1))
        continue
    fi
    out=$(sh "$s" --help 2>&1)
    rc=$?
    if [ $rc -eq 0 ] && [ "$(printf '%s\n' "$out" | wc -l)" -ge 2 ]; then
        pass=$((pass + 1))
    else
        echo "FAIL: $s --help (exit $rc):"
        printf '%s\n' "$out" | head -n 5
        fail=$((fail + 1))
    fi
done
# The scripts with the shared preamble (tools/args.sh): a usage error is one line
# naming the script, exit 2, before anything is built or run.
empty=$(mktemp -d)
for s in $(grep -l '^\. .*/args\.sh"$' $(find tools -name '*.sh') | sort); do
    if grep -q '^args_data ' "$s"; then
        set -- "--bogus" "$empty --bogus" "$empty --count" "$empty --count=x" "$empty/none" "--count 3"
    else
        set -- "--bogus" "--build" ""
    fi
    for a in "$@"; do
        # shellcheck disable=SC2086 # the words of one command line
        out=$(sh "$s" $a 2>&1 >/dev/null)
        rc=$?
        if [ $rc -eq 2 ] && [ "$(printf '%s\n' "$out" | wc -l)" -eq 1 ] &&
            printf '%s\n' "$out" | grep -q "^$(basename "$s"): .*(try '$s --help')$"; then
            pass=$((pass + 1))
        else
            echo "FAIL: $s $a: exit $rc, not one usage line:"
            printf '%s\n' "$out" | head -n 5
            fail=$((fail + 1))
        fi
    done
done
rmdir "$empty"
# The demo takes --help as help, not as a frame; an unknown option is a usage error.
sh tools/demo.sh --bogus >/dev/null 2>&1
if [ $? -eq 2 ]; then pass=$((pass + 1)); else echo "FAIL: tools/demo.sh --bogus"; fail=$((fail + 1)); fi
echo "$pass passed, $fail failed"
[ $fail -eq 0 ]

# SPDX-License-Identifier: Apache-2.0
# need_pkgs NAME...: installs the Debian packages of the list that are missing
# (apt-get, as root; sudo otherwise); progress and errors on stderr. Sourced
# by the capture integration test and its guest build scripts, and by the
# evaluation and benchmark scripts in tools/, which call it only where dpkg
# exists.
need_pkgs() {
    missing=
    for p in "$@"; do
        # dpkg-query, not dpkg -s: the latter rejects a name installed for two
        # architectures (e.g. once arm64 is added for the AArch64 check).
        dpkg-query -W -f='${Status}\n' "$p" 2>/dev/null | grep -q '^install ok installed$' ||
            missing="$missing $p"
    done
    [ -z "$missing" ] && return 0
    echo "$(basename "$0"): installing$missing" >&2
    SUDO=
    [ "$(id -u)" -eq 0 ] || SUDO=sudo
    # shellcheck disable=SC2086
    $SUDO apt-get install -y $missing >&2 || { $SUDO apt-get update >&2 && $SUDO apt-get install -y $missing >&2; }
}

# Run rather than sourced: --help prints the header above.
if [ "$(basename "$0")" = pkgs.sh ]; then
    case ${1:-} in
    -h | --help) sed -n '2,/^[^#]/{/SPDX-License-Identifier/d;s/^# \{0,1\}//p;}' "$0"; exit 0 ;;
    esac
    echo "capture/tests/pkgs.sh: source it, then call need_pkgs NAME..." >&2
    exit 2
fi

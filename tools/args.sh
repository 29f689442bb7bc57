# SPDX-License-Identifier: Apache-2.0
# The command-line preamble the evaluation and benchmark scripts share
# (tools/eval/*.sh, tools/bench/*.sh), sourced after `set -eu`. Sets REPO (the
# repository) and provides:
#   args_usage          prints the script's help: its header comment, from
#                       line 3 up to `set -eu`
#   args_error MSG      "SCRIPT: MSG (try 'SCRIPT --help')" on stderr, exit 2
#   args_data "$@"      for scripts whose first argument is DATA_DIR: -h or
#                       --help prints the help (exit 0); no argument is a
#                       usage error; else DATA=$1 (the caller shifts it)
#   args_value "$@"     the value of the option in $1, as --opt VALUE or
#                       --opt=VALUE: ARGS_VALUE, and in ARGS_SHIFT how many
#                       arguments it took; a missing value is a usage error
#   args_common "$@"    -h/--help, or one option of the list ARGS_COMMON
#                       (build out count seed repeat jobs opts: BUILD OUT
#                       COUNT SEED REPEAT JOBS OPTS; count, seed, repeat and
#                       jobs are numbers); sets ARGS_SHIFT; anything else is
#                       a usage error. With `columns` in the list, each
#                       --opts VALUE adds a column: OPTS_1 .. OPTS_$NOPTS
#   args_columns        after the options: one empty column when none given
#   args_dirs           DATA (when set) must be a folder; DATA, BUILD and OUT
#                       (when set) become absolute paths
# Run rather than sourced, --help prints this.
# shellcheck disable=SC2034 # the variables set here are the sourcing script's
REPO=$(cd "$(dirname "$0")/../.." && pwd)

args_usage() {
    sed -n '3,/^set -eu/p' "$0" | sed -e '/^set -eu/d' -e 's/^# \{0,1\}//'
}

args_error() {
    echo "$(basename "$0"): $* (try '$0 --help')" >&2
    exit 2
}

args_data() {
    [ $# -ge 1 ] || args_error "no DATA_DIR given"
    case $1 in
    -h | --help) args_usage; exit 0 ;;
    -*) args_error "the first argument is DATA_DIR, not '$1'" ;;
    esac
    DATA=$1
}

args_value() {
    case $1 in
    --*=*) ARGS_VALUE=${1#*=} ARGS_SHIFT=1 ;;
    *) [ $# -ge 2 ] || args_error "$1 needs a value"
       ARGS_VALUE=$2 ARGS_SHIFT=2 ;;
    esac
}

args_common() {
    case $1 in
    -h | --help) args_usage; exit 0 ;;
    -?*) ;;
    *) args_error "unexpected argument '$1'" ;;
    esac
    args_opt=${1%%=*}
    case " ${ARGS_COMMON:-} " in
    *" ${args_opt#--} "*) ;;
    *" columns "*) [ "$args_opt" = --opts ] || args_error "unknown option '$args_opt'" ;;
    *) args_error "unknown option '$args_opt'" ;;
    esac
    args_value "$@"
    case $args_opt in
    --count | --seed | --repeat | --jobs)
        case $ARGS_VALUE in '' | *[!0-9]*) args_error "$args_opt needs a number" ;; esac ;;
    esac
    case $args_opt in
    --build) BUILD=$ARGS_VALUE ;;
    --out) OUT=$ARGS_VALUE ;;
    --count) COUNT=$ARGS_VALUE ;;
    --seed) SEED=$ARGS_VALUE ;;
    --repeat) REPEAT=$ARGS_VALUE ;;
    --jobs) JOBS=$ARGS_VALUE ;;
    --opts)
        case " $ARGS_COMMON " in
        *" columns "*)
            NOPTS=$((${NOPTS:-0} + 1))
            eval "OPTS_$NOPTS=\$ARGS_VALUE" ;;
        *) OPTS=$ARGS_VALUE ;;
        esac ;;
    esac
}

args_columns() {
    if [ "${NOPTS:-0}" -eq 0 ]; then
        NOPTS=1
        OPTS_1=
    fi
}

args_dirs() {
    if [ -n "${DATA:-}" ]; then
        [ -d "$DATA" ] || args_error "no data folder '$DATA'"
        DATA=$(cd "$DATA" && pwd)
    fi
    case ${BUILD:-/} in /*) ;; *) BUILD=$(pwd)/$BUILD ;; esac
    case ${OUT:-/} in /*) ;; *) OUT=$(pwd)/$OUT ;; esac
}

if [ "$(basename "$0")" = args.sh ]; then
    case ${1:-} in
    -h | --help) sed -n '2,/^[^#]/{/SPDX-License-Identifier/d;s/^# \{0,1\}//p;}' "$0"; exit 0 ;;
    esac
    echo "tools/args.sh: source it from a script in tools/*/" >&2
    exit 2
fi

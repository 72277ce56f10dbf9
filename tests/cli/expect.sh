# expect.sh — sourced by the command-line tests.  Provides:
#   $tmp               a scratch directory, removed on exit
#   bad MESSAGE        count a failure
#   expect STATUS DESCRIPTION -- COMMAND...
#                      run COMMAND (stdout -> $tmp/out, stderr -> $tmp/err)
#                      and count a failure unless it exits with STATUS
#   finish NAME        print the tally and exit non-zero on any failure
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
fails=0

bad() {
    echo "FAIL: $*"
    fails=$((fails + 1))
}

expect() {
    want=$1 what=$2
    shift 3
    "$@" >"$tmp/out" 2>"$tmp/err"
    got=$?
    if [ "$got" != "$want" ]; then
        bad "$what: exit $got, expected $want"
        cat "$tmp/err"
    else
        echo "ok:   $what (exit $got)"
    fi
}

finish() {
    echo "$1: $fails failure(s)"
    [ "$fails" = 0 ]
}

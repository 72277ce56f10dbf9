# expect.sh — sourced by the command-line tests.  Provides:
#   $tmp               a scratch directory, removed on exit
#   bad MESSAGE        count a failure
#   expect STATUS DESCRIPTION -- COMMAND...
#                      run COMMAND (stdout -> $tmp/out, stderr -> $tmp/err)
#                      and count a failure unless it exits with STATUS
#   check DESCRIPTION COMMAND...
#                      count a failure unless COMMAND succeeds
#   nothing_written DESCRIPTION
#                      count a failure if $tmp/w (created here) holds a file
#   finish NAME        print the tally and exit non-zero on any failure
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
mkdir -p "$tmp/w"
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

check() {
    what=$1
    shift
    "$@" || bad "$what"
}

nothing_written() {
    [ -z "$(ls -A "$tmp/w")" ] || bad "$1: files were written: $(ls -A "$tmp/w")"
}

finish() {
    echo "$1: $fails failure(s)"
    [ "$fails" = 0 ]
}

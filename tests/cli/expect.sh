# expect.sh — sourced by the command-line tests.  Provides:
#   $tmp               a scratch directory, removed on exit
#   bad MESSAGE        count a failure
#   expect STATUS DESCRIPTION -- COMMAND...
#                      run COMMAND (stdout -> $tmp/out, stderr -> $tmp/err)
#                      and count a failure unless it exits with STATUS
#   check DESCRIPTION COMMAND...
#                      count a failure unless COMMAND succeeds
#   says DESCRIPTION PATTERN
#                      count a failure unless the last stderr holds PATTERN
#                      (grep -e; a run that fails must fail for its reason)
#   prints DESCRIPTION PATTERN
#                      the same for the last stdout
#   nothing_written DESCRIPTION
#                      count a failure if $tmp/w (created here) holds a file
#   finish NAME        print the tally and exit non-zero on any failure; with
#                      none, the tally is the result line "ok: NAME: ..."
#                      that make check requires (tests/check_guard.sh)
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
mkdir -p "$tmp/w"
fails=0
runs=0

bad() {
    echo "FAIL: $*"
    fails=$((fails + 1))
}

expect() {
    want=$1 what=$2
    shift 3
    "$@" >"$tmp/out" 2>"$tmp/err"
    got=$?
    runs=$((runs + 1))
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

says() {
    grep -q -e "$2" "$tmp/err" || bad "$1: stderr lacks '$2': $(head -3 "$tmp/err")"
}

prints() {
    grep -q -e "$2" "$tmp/out" || bad "$1: stdout lacks '$2': $(head -3 "$tmp/out")"
}

nothing_written() {
    [ -z "$(ls -A "$tmp/w")" ] || bad "$1: files were written: $(ls -A "$tmp/w")"
}

finish() {
    if [ "$fails" = 0 ]; then
        echo "ok: $1: $runs runs, each with its exit status and output as expected"
    else
        echo "$1: $fails failure(s) in $runs runs"
        return 1
    fi
}

#!/bin/sh
# cli.sh TISSUEFIT — the command line's contract: help for every command,
# exit status 2 and nothing written on bad usage, -q silences progress.
set -u
tool=$1
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
fails=0

# expect STATUS DESCRIPTION -- COMMAND...
expect() {
    want=$1 what=$2
    shift 3
    "$@" >"$tmp/out" 2>"$tmp/err"
    got=$?
    if [ "$got" != "$want" ]; then
        echo "FAIL: $what: exit $got, expected $want"; cat "$tmp/err"; fails=$((fails + 1))
    else
        echo "ok:   $what (exit $got)"
    fi
}
nothing_written() {
    if [ -n "$(ls -A "$tmp/w" 2>/dev/null)" ]; then
        echo "FAIL: $1: files were written: $(ls -A "$tmp/w")"; fails=$((fails + 1))
    fi
}
mkdir -p "$tmp/w"

expect 0 "global --help" -- "$tool" --help
grep -q "demo-model" "$tmp/out" || { echo "FAIL: --help does not list demo-model"; fails=$((fails + 1)); }
expect 0 "--version" -- "$tool" --version
expect 0 "demo-model --help" -- "$tool" demo-model --help
grep -q -- "--envelope" "$tmp/out" || { echo "FAIL: demo-model --help lacks its options"; fails=$((fails + 1)); }
expect 0 "help demo-model" -- "$tool" help demo-model
expect 2 "unknown command" -- "$tool" frobnicate
expect 2 "unknown global option" -- "$tool" --frob
expect 2 "no command" -- "$tool"
expect 2 "demo-model without -o" -- "$tool" demo-model
expect 2 "demo-model with a stray argument" -- "$tool" demo-model -o "$tmp/w/a.h" extra
expect 2 "demo-model with an unknown option" -- "$tool" demo-model -o "$tmp/w/a.h" --bogus
expect 2 "demo-model, negative envelope" -- "$tool" demo-model --envelope -1 -o "$tmp/w/a.h"
expect 2 "demo-model, envelope not a number" -- "$tool" demo-model --envelope 1N -o "$tmp/w/a.h"
expect 2 "demo-model, header name not an identifier" -- "$tool" demo-model -o "$tmp/w/Bad-Name.h"
nothing_written "bad usage"
expect 2 "demo-model into a missing directory" -- "$tool" demo-model -o "$tmp/missing/a.h"
grep -q "$tmp/missing/a.h" "$tmp/err" || { echo "FAIL: error does not name the file"; fails=$((fails + 1)); }
expect 0 "demo-model, quiet" -- "$tool" -q demo-model -o "$tmp/w/ok.h"
[ -s "$tmp/err" ] && { echo "FAIL: -q still wrote to stderr"; fails=$((fails + 1)); }
[ -f "$tmp/w/ok.h" ] && [ -f "$tmp/w/ok_golden.h" ] || { echo "FAIL: outputs missing"; fails=$((fails + 1)); }
ls "$tmp/w" | grep -q tmp && { echo "FAIL: temporary files left behind"; fails=$((fails + 1)); }

echo "cli: $fails failure(s)"
[ "$fails" = 0 ]

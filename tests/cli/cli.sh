#!/bin/sh
# cli.sh TISSUEFIT — the command line's contract: help for every command,
# exit status 2 and nothing written on bad usage, -q silences progress.
set -u
tool=$1
. "$(dirname "$0")/expect.sh"

expect 0 "global --help" -- "$tool" --help
grep -q "demo-model" "$tmp/out" || bad "--help does not list demo-model"
expect 0 "--version" -- "$tool" --version
expect 0 "demo-model --help" -- "$tool" demo-model --help
grep -q -- "--envelope" "$tmp/out" || bad "demo-model --help lacks its options"
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
grep -q "$tmp/missing/a.h" "$tmp/err" || bad "error does not name the file"
expect 0 "demo-model, quiet" -- "$tool" -q demo-model -o "$tmp/w/ok.h"
[ -s "$tmp/err" ] && bad "-q still wrote to stderr"
[ -f "$tmp/w/ok.h" ] && [ -f "$tmp/w/ok_golden.h" ] || bad "outputs missing"
ls "$tmp/w" | grep -q tmp && bad "temporary files left behind"

finish cli

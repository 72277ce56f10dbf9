#!/bin/sh
# check_guard.sh NAME LOG — the guard `make check` applies to every check's
# output: a "== ... ==" heading, and a last line that is a result line,
# "ok: WHAT WAS SHOWN" (printed once the check's work is done).  A recipe
# that lost its commands prints no heading; one that stopped after its
# heading, or whose last command printed nothing, has no result line.
set -u
name=$1 log=$2
if ! grep -q '^== .* ==' "$log"; then
    echo "$name: printed no '== ... ==' heading: its rule has no recipe"
    exit 1
fi
last=$(grep -v '^[[:space:]]*$' "$log" | tail -n 1)
case $last in
ok:\ *) ;;
*)
    echo "$name: its output does not end with a result line ('ok: ...'): it ran nothing after its"
    echo "heading or stopped early; last line: $last"
    exit 1
    ;;
esac

#!/bin/sh
# selftest.sh "LAYER..." MUTABLE.o CONST.o — the structure checkers are
# shown what they must reject, and must reject it for the right reason:
# check_includes.sh on copies of host/ with an upward include, an include
# cycle, a cycle of modules, a file in host/ itself and a folder outside the layer list;
# check_globals.sh on an object with mutable statics (and must accept one
# with constant tables and an OpenMP critical section); check_errors.sh on
# copies of host/ with a (char *err, size_t errlen) parameter pair, the pair
# split over two lines under other names, and an errlen member.
set -u
layers=$1 mutable=$2 constant=$3
here=$(dirname "$0")
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
fails=0

# rejects WHAT PATTERN COMMAND...: COMMAND exits 1 and says PATTERN.
rejects() {
    what=$1 pattern=$2
    shift 2
    "$@" >"$tmp/out" 2>&1
    rc=$?
    if [ "$rc" != 1 ]; then
        echo "FAIL: self-test: $what: exit $rc, expected 1"; fails=$((fails + 1))
    elif ! grep -q "$pattern" "$tmp/out"; then
        echo "FAIL: self-test: $what: rejected without saying '$pattern':"; cat "$tmp/out"
        fails=$((fails + 1))
    else
        echo "self-test: $what: rejected ($(grep -m1 "$pattern" "$tmp/out"))"
    fi
}

# A fresh copy of host/ with one defect made by COMMAND (run in the copy).
broken() {
    rm -rf "$tmp/host" && cp -r host "$tmp/host" && (cd "$tmp/host" && eval "$1")
}

broken 'echo "#include \"cli/cli.h\"" >>base/log.c'
rejects "base/log.c including cli/cli.h" "upward include of \"cli/cli.h\"" \
    "$here/check_includes.sh" "$tmp/host" "$layers"
broken 'echo "#include \"base/log.h\"" >>base/context.h'
rejects "base/context.h and base/log.h including each other" "include cycle" \
    "$here/check_includes.sh" "$tmp/host" "$layers"
broken 'echo "#include \"base/log.h\"" >>base/context.c'
rejects "base/context.c including base/log.h, whose .c includes base/context.h" \
    "include cycle between modules" "$here/check_includes.sh" "$tmp/host" "$layers"
broken 'echo "int x;" >stray.c'
rejects "a file in host/ itself" "host/stray.c: only host.mk" \
    "$here/check_includes.sh" "$tmp/host" "$layers"
broken 'mkdir extras && echo "int y;" >extras/y.c'
rejects "a folder outside the layer list" "host/extras/: a folder that is not" \
    "$here/check_includes.sh" "$tmp/host" "$layers"
broken 'echo "#include \"base/nothing.h\"" >>base/log.c'
rejects "an include of a file that does not exist" "neither a host/ path" \
    "$here/check_includes.sh" "$tmp/host" "$layers"
broken 'echo "int tf_planted(int a, char *err, size_t errlen);" >>base/rng.h'
rejects "a function taking (char *err, size_t errlen)" \
    "host/base/rng.h:[0-9]*: a message buffer and its size (char \*err, size_t errlen)" \
    "$here/check_errors.sh" "$tmp/host"
broken 'printf "static int planted(char *errbuf,\\n                   size_t n)\\n{\\n    return 0;\\n}\\n" >>base/log.c'
rejects "a message buffer and its size over two lines" \
    "host/base/log.c:[0-9]*: a message buffer and its size (char \*errbuf, size_t n)" \
    "$here/check_errors.sh" "$tmp/host"
broken 'echo "struct planted { char *msg; size_t errlen; };" >>base/rng.h'
rejects "an errlen member" "host/base/rng.h:[0-9]*: errlen: the buffer-and-size" \
    "$here/check_errors.sh" "$tmp/host"
rejects "an object with a static counter" "calls.* in .bss: mutable state" \
    "$here/check_globals.sh" "$mutable"
rejects "an object with a thread-local variable" "tf_fixture_last in .tbss: mutable state" \
    "$here/check_globals.sh" "$mutable"
if ! "$here/check_globals.sh" "$constant" >"$tmp/out" 2>&1; then
    echo "FAIL: self-test: constant tables rejected:"; cat "$tmp/out"; fails=$((fails + 1))
fi
[ "$fails" = 0 ] || exit 1

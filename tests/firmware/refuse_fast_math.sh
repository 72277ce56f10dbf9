#!/bin/sh
# refuse_fast_math.sh GCC OUT.err FLAG... — the target library refuses to be
# compiled with -ffast-math (tfit_internal.h's #error): compiling one of its
# sources with that option and FLAG... must fail, saying why.  Exits 1 when
# the compiler accepted it or failed for another reason.
set -u
gcc=$1 err=$2
shift 2
if "$gcc" -std=c11 -ffast-math "$@" -Itarget/include -fsyntax-only target/src/tfit_nodal.c 2>"$err"; then
    echo "-ffast-math was accepted"
    exit 1
fi
if ! grep -q "tfit: -ffast-math" "$err"; then
    echo "-ffast-math: the build failed, but not with the library's refusal:"
    cat "$err"
    exit 1
fi
echo "-ffast-math: refused at compile time"

#!/bin/sh
# haptic_config.sh HEADER.h — writes (stdout) the haptic_config.h with which
# target/examples/haptic_loop.c is built for one generated header: the
# header, its IMPLEMENTATION macro, and the first forward model (family
# nodal, modal, zhou2017 or modal_q15; else the first prony model, stepped with its
# state: HAPTIC_FORWARD_PRONY; else the first resonant model, the same way:
# HAPTIC_FORWARD_RESONANT; else the first cut model, at the whole incision:
# HAPTIC_FORWARD_CUT) and the first contact model it defines.
# Fails when the header has neither.
set -eu
header=$1
name=$(basename "$header" .h)
upper=$(echo "$name" | tr a-z A-Z)
# "#define TFIT_X_FAMILY_ID n" in model order
models=$(sed -n 's/^#define TFIT_\([A-Z0-9_]*\)_FAMILY_ID \([0-9]*\)$/\1 \2/p' "$header")
forward=$(echo "$models" | awk '($2 >= 1 && $2 <= 3) || $2 == 8 { print $1; exit }')
prony= resonant= cut=
if [ -z "$forward" ]; then
    forward=$(echo "$models" | awk '$2 == 5 { print $1; exit }')
    [ -z "$forward" ] || prony=1
fi
if [ -z "$forward" ]; then
    forward=$(echo "$models" | awk '$2 == 7 { print $1; exit }')
    [ -z "$forward" ] || resonant=1
fi
if [ -z "$forward" ]; then
    forward=$(echo "$models" | awk '$2 == 6 { print $1; exit }')
    [ -z "$forward" ] || cut=1
fi
contact=$(echo "$models" | awk '$2 == 4 { print $1; exit }')
if [ -z "$forward" ] && [ -z "$contact" ]; then
    echo "haptic_config.sh: $header defines no model" >&2
    exit 1
fi
lower() { echo "$1" | tr A-Z a-z; }
echo "/* haptic_config.h for $name.h, written by tests/firmware/haptic_config.sh */"
echo "#define HAPTIC_HEADER \"$name.h\""
echo "#define TFIT_${upper}_IMPLEMENTATION"
if [ -n "$forward" ]; then
    echo "#define HAPTIC_FORWARD tfit_$(lower "$forward")"
    echo "#define HAPTIC_FORWARD_M(x) TFIT_${forward}_##x"
    [ -z "$prony" ] || echo "#define HAPTIC_FORWARD_PRONY"
    [ -z "$resonant" ] || echo "#define HAPTIC_FORWARD_RESONANT"
    [ -z "$cut" ] || echo "#define HAPTIC_FORWARD_CUT"
fi
if [ -n "$contact" ]; then
    echo "#define HAPTIC_CONTACT tfit_$(lower "$contact")"
    echo "#define HAPTIC_CONTACT_M(x) TFIT_${contact}_##x"
fi

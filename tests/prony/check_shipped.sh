#!/bin/sh
# check_shipped.sh NAME HEADER DIR BOUND — one shipped viscoelastic header
# (tests/prony.mk, check-prony-ve): its datasheet lines, a Q31 form whose
# held-out error is within BOUND of the peak displacement, the float
# model's held-out error within BOUND, a total error (fit + discretisation)
# stated; then its golden vectors (DIR/golden-NAME) and one instruction
# count per tick (DIR/probe-NAME, callgrind).
set -eu
name=$1 h=$2 dir=$3 bound=$4
up=$(echo "$name" | tr a-z A-Z)
fail() { echo "$name: $*"; exit 1; }
sed -n "s/^ \*       \(stateful\|held-out cases are\|error against the physics\|Q31 form tfit_${name}_forward\)/  \1/p" "$h"
grep -q "^#define TFIT_${up}_FORWARD_Q31_STATE_WORDS" "$h" || fail "no Q31 form of its prony model"
def() { sed -n "s/^#define TFIT_${up}_$1 \([^ ]*\).*/\1/p" "$h"; }
q=$(def FORWARD_Q31_HELDOUT_MAX_MM) mx=$(def FORWARD_HELDOUT_MAX_MM) rel=$(def FORWARD_HELDOUT_REL_MAX)
tot=$(def FORWARD_TOTAL_MAX_MM)
awk -v q="$q" -v m="$mx" -v r="$rel" -v b="$bound" 'BEGIN {
    if (q == "" || m == "" || r == "") exit 1; peak = m / r
    printf "  Q31 form against the held-out solves: max %g mm, %.3g %% of the peak %.4g mm (bound %g %%)\n", q, 100 * q / peak, peak, 100 * b
    exit !(q / peak <= b) }' || fail "the Q31 form's held-out error is missing or beyond $bound of the peak"
"$dir/golden-$name" "$name/native"
tests/insncount/run.sh "$dir/probe-$name" "$dir/insncount-$name"
awk -v r="$rel" -v b="$bound" 'BEGIN { exit !(r != "" && r + 0 <= b + 0) }' ||
    fail "held-out error $rel of the peak is beyond $bound"
[ -n "$tot" ] || fail "states no total error (fit + discretisation)"
echo "ok: $name: held-out error $rel of the peak displacement <= $bound; total stated $tot mm"

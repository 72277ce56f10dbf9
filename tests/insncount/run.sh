#!/bin/sh
# run.sh PROBE OUTDIR — runs the probe under callgrind, one dump per
# evaluation, and checks that every model executes the same number of
# instructions for every input (in-envelope, beyond it, subnormal, NaN, Inf),
# and a prony or resonant model for every tick of its sequence, whatever
# the state.
# Prints a table per model; exits 1 when a count differs.
set -eu
probe=$1
out=$2
rm -rf "$out"
mkdir -p "$out"
valgrind --tool=callgrind --callgrind-out-file="$out/cg.out" \
    --toggle-collect=tfit_displacements --toggle-collect=tfit_contact_force \
    --toggle-collect=tfit_prony_step --toggle-collect=tfit_resonant_step \
    --toggle-collect=tfit_displacements_q31 --toggle-collect=tfit_contact_force_q31 \
    --toggle-collect=tfit_prony_step_q31 \
    --toggle-collect=control_branchy \
    "$probe" >"$out/probe.log" 2>&1 || { cat "$out/probe.log"; exit 1; }
# Every dump file: "desc: Trigger: Client Request: set=S family=F vec=V status=X" and "totals: N".
for f in "$out"/cg.out.*; do
    awk '/^desc: Trigger: Client Request:/ { sub(/.*Request: /, ""); label = $0 }
         /^(totals|summary):/ { total = $2 }
         END { print label, "ir=" total }' "$f"
done | sort -t= -k2,2n -k4,4n >"$out/counts.txt"
awk '
{
    split($1, s, "="); split($2, f, "="); split($4, st, "="); split($5, ir, "=")
    key = s[2]; fam[key] = f[2]; n[key]++
    if (!(key in lo) || ir[2] < lo[key]) lo[key] = ir[2]
    if (!(key in hi) || ir[2] > hi[key]) hi[key] = ir[2]
    if (st[2] < 0) bad[key] = ir[2]; else if (st[2] == 1) clamp[key] = ir[2]; else ok[key] = ir[2]
}
END {
    # name[id + 1]: the family ids of tfit.h; the id of a Q31 set is shifted by 10 (probe.c)
    split("control nodal modal zhou2017 contact prony cut resonant modal_q15 - - nodal-q31 - - contact-q31 prony-q31", name, " ")
    printf "%-4s %-11s %7s %12s %12s %12s %s\n", "set", "family", "inputs", "in-envelope", "clamped", "NaN/Inf", "verdict"
    fail = 0
    for (k = 0; k < 64; k++) {
        if (!(k in n)) continue
        v = (lo[k] == hi[k]) ? "identical" : "DIFFERENT"
        if (lo[k] != hi[k]) fail = 1
        printf "%-4d %-11s %7d %12s %12s %12s %s\n", k, name[fam[k] + 1], n[k], ok[k], clamp[k], bad[k], v
    }
    # The control costs more for larger inputs: the measurement must see it.
    if (!(99 in n) || lo[99] == hi[99]) { print "control: input-dependent function NOT detected"; fail = 1 }
    else printf "control (input-dependent loop): %s..%s instructions, detected\n", lo[99], hi[99]
    exit fail
}' "$out/counts.txt"

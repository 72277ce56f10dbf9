#!/bin/sh
# insncount.sh PROBE BUNDLE OUTDIR — runs probe_region under callgrind, one
# dump per call of a region entry point, and checks that every set (a
# region's law ticks, surface vectors, two-instrument ticks, surface pairs)
# executes the same number of instructions for every call whatever the
# input and the state; a control whose cost depends on its input must be
# seen to differ.  Prints a table per entry point; exits 1 when a count
# differs.
set -eu
probe=$1 bundle=$2 out=$3
rm -rf "$out"
mkdir -p "$out"
valgrind --tool=callgrind --callgrind-out-file="$out/cg.out" \
    --toggle-collect=tfit_region_force --toggle-collect=tfit_region_surface \
    --toggle-collect=tfit_region_pair --toggle-collect=tfit_region_surface_pair \
    --toggle-collect=control_branchy \
    "$probe" "$bundle" >"$out/probe.log" 2>&1 || { cat "$out/probe.log"; exit 1; }
for f in "$out"/cg.out.*; do
    awk '/^desc: Trigger: Client Request:/ { sub(/.*Request: /, ""); label = $0 }
         /^(totals|summary):/ { total = $2 }
         END { print label, "ir=" total }' "$f"
done >"$out/counts.txt"
awk '
{
    split($1, s, "="); split($2, f, "="); split($4, st, "="); split($5, ir, "=")
    key = s[2]; fam[key] = f[2]; n[key]++
    if (!(key in lo) || ir[2] + 0 < lo[key]) lo[key] = ir[2] + 0
    if (!(key in hi) || ir[2] + 0 > hi[key]) hi[key] = ir[2] + 0
    seen[key, st[2]] = 1
}
END {
    split("law surface pair surface-pair", name, " ")
    fail = 0
    for (k in n) {
        if (k == 9999) continue
        e = fam[k] - 8
        sets[e]++; calls[e] += n[k]
        if (lo[k] != hi[k]) { fail = 1; printf "set %d (%s): %d..%d instructions: DIFFERENT\n", k, name[e], lo[k], hi[k] }
        if (!(e in mn) || lo[k] < mn[e]) mn[e] = lo[k]
        if (!(e in mx) || lo[k] > mx[e]) mx[e] = lo[k]
        for (q = -1; q <= 2; q++) if ((k, q) in seen) kinds[e, q] = 1
    }
    printf "%-13s %5s %7s %24s  %s\n", "entry", "sets", "calls", "instructions per call", "statuses seen (-1 NaN/Inf, 0 ok, 1 clamped, 2 no contact)"
    for (e = 1; e <= 4; e++) {
        sts = ""
        for (q = -1; q <= 2; q++) if ((e, q) in kinds) sts = sts " " q
        printf "%-13s %5d %7d %11d .. %-10d  %s\n", name[e], sets[e], calls[e], mn[e], mx[e], sts
    }
    print "(within a set one count for every call; the range is over models of different sizes)"
    if (!(9999 in n) || lo[9999] == hi[9999]) { print "control: input-dependent function NOT detected"; fail = 1 }
    else printf "control (input-dependent loop): %s..%s instructions, detected\n", lo[9999], hi[9999]
    exit fail
}' "$out/counts.txt"

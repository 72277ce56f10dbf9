#!/bin/sh
# bench_ccx.sh DECK_TOOL WORK REFERENCE TARGET:DIVISIONS:LAYERS ...
#
# CalculiX's time to accuracy on block48 (issue 21, docs/calculix-reference.md
# "Accuracy per second"): for each target (a relative error at node 61, in
# per cent) runs the C3D20R mesh DIVISIONS x DIVISIONS x LAYERS that the
# committed accuracy table names as the cheapest one reaching it, on the
# whole block with the project's deck (load cases fx and fz, one *STEP and
# one factorisation each), and prints the wall time of the run, the time per
# load case, and the error it reached at node 61 against REFERENCE
# (block48_node61_reference.csv: the extrapolated fx and fz values).
# One CalculiX run at a time, CCX_THREADS threads (default 1).
set -eu
[ $# -ge 4 ] || { echo "usage: $0 DECK_TOOL WORK REFERENCE TARGET:DIVISIONS:LAYERS ..." >&2; exit 2; }
deck_tool=$1 work=$2 reference=$3
shift 3
here=$(cd "$(dirname "$0")" && pwd)
threads=${CCX_THREADS:-1}
mkdir -p "$work"
ref() { awk -F, -v c="$1" '$1 == c { print $3 }' "$reference"; }
ref_fx=$(ref fx) ref_fz=$(ref fz)
[ -n "$ref_fx" ] && [ -n "$ref_fz" ] || { echo "bench_ccx: $reference lacks the fx or fz value" >&2; exit 1; }
printf '%-8s %-10s %9s %11s %12s %12s  %s\n' target mesh "run (s)" "per case (s)" "fx error" "fz error" reached
for t in "$@"; do
    target=$(echo "$t" | cut -d: -f1) n=$(echo "$t" | cut -d: -f2) layers=$(echo "$t" | cut -d: -f3)
    run=bench_${n}x$layers
    "$deck_tool" --divisions "$n" --layers "$layers" --cases fx,fz > "$work/$run.inp"
    rm -f "$work/$run.dat"
    (cd "$work" && OMP_NUM_THREADS=$threads /usr/bin/time -f "%e" -o "$run.time" ccx -i "$run" > "$run.log" 2>&1) ||
        { echo "bench_ccx: $run failed, see $work/$run.log" >&2; exit 1; }
    ux=$(awk -v step=1 -f "$here/dat_to_csv.awk" "$work/$run.inp" "$work/$run.dat" | awk -F, '$1 == 61 { print $5 }')
    uz=$(awk -v step=2 -f "$here/dat_to_csv.awk" "$work/$run.inp" "$work/$run.dat" | awk -F, '$1 == 61 { print $7 }')
    awk -v t="$target" -v m="${n}x${n}x$layers" -v s="$(cat "$work/$run.time")" -v ux="$ux" -v uz="$uz" \
        -v rx="$ref_fx" -v rz="$ref_fz" 'BEGIN {
            ex = 100 * (ux - rx) / rx; ez = 100 * (uz - rz) / rz
            worst = (ex < 0 ? -ex : ex) > (ez < 0 ? -ez : ez) ? (ex < 0 ? -ex : ex) : (ez < 0 ? -ez : ez)
            printf "%-8s %-10s %9.1f %11.1f %+11.3f%% %+11.3f%%  %s\n", t "%", m, s, s / 2, ex, ez, worst <= t ? "yes" : "NO"
        }'
done

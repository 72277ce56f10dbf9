#!/bin/sh
# stomach_clamp.sh ORGAN_COMPARE ORGAN_DECK DATA WORK
#
# How far the stomach's answer moves with its bed clamp (coeffs/stomach.yaml:
# fixed.2, the half-space y > 30 mm; docs/validation.md §14.1): the meshless
# solve with the plane at 27 .. 33 mm against the committed s20r1 data, and
# CalculiX s20r0 with the plane at 29 mm against the committed s20r0 (30 mm).
# A markdown table on stdout; decks and CalculiX output stay in WORK.
set -eu
[ $# -eq 4 ] || { echo "usage: $0 ORGAN_COMPARE ORGAN_DECK DATA WORK" >&2; exit 2; }
compare=$1 deck=$2 data=$3 work=$4
here=$(cd "$(dirname "$0")" && pwd)
. "$here/ccx_cached.sh"
mkdir -p "$work"
plane() { echo "fixed.2={side: {point: [0, $1, 0], normal: [0, 1, 0]}}"; }
# the L2 column (outputs) of organ_compare's three rows, as "fx / fy / fz"
l2() { awk '$2 ~ /^f[xyz]$/ { v[$2] = $9 } END { printf "%s / %s / %s %%", v["fx"], v["fy"], v["fz"] }' "$1"; }
echo "| the bed's plane (mm) | meshless (6 mm) against s20r1: L2 fx / fy / fz |"
echo "|---:|---|"
for y in 27 28 29 30 31 33; do
    echo "stomach_clamp: the plane at y = $y mm ..." >&2
    "$compare" "$data/stomach_s20r1.csv" coeffs/stomach.yaml --set "$(plane $y)" \
        > "$work/meshless_y$y.md" 2> "$work/meshless_y$y.err" || { cat "$work/meshless_y$y.err" >&2; exit 1; }
    echo "| $y | $(l2 "$work/meshless_y$y.md") |"
done
shared=$(cd coeffs/../../shared && pwd)
sed "s|side: {point: \[0, 30, 0\]|side: {point: [0, 29, 0]|; s|file: \.\./\.\./shared|file: $shared|" \
    coeffs/stomach.yaml > "$work/stomach_y29.yaml"
grep -q 'side: {point: \[0, 29, 0\]' "$work/stomach_y29.yaml" || { echo "stomach_clamp: the bed's plane is not at y = 30 in coeffs/stomach.yaml" >&2; exit 1; }
"$deck" "$work/stomach_y29.yaml" --spacing 20 --refine 0 > "$work/stomach_y29.inp.new"
ccx_cached "$work" stomach_y29 1 "%e %M" "s20r0, the bed's plane at 29 mm"
awk -f "$here/organ_dat.awk" "$work/stomach_y29.inp" "$work/stomach_y29.dat" > "$work/stomach_y29.csv"
"$compare" "$data/stomach_s20r0.csv" --csv "$work/stomach_y29.csv" > "$work/ccx_y29.md"
echo
echo "CalculiX s20r0 with the plane at 29 mm against s20r0 at 30 mm (the committed data): L2 $(l2 "$work/ccx_y29.md")"

#!/bin/bash
# block48.sh — the collocation solver's static limit on block48 against the
# CalculiX reference (tests/calculix/data/block48_node61.csv, the finest
# level, h = 0.6 mm C3D20R) and the RPIM Galerkin solver on the same grid
# (tests/solver/node61): node 61's displacement per newton for a force
# along +x and along -z on the top patch (make block48-colloc).
# Writes OUTDIR/block48.csv and prints it as a table.
# Usage: block48.sh COLLOC_BLOCK48 NODE61 OUTDIR
set -euo pipefail
colloc=$1
node61=$2
out=$3
mkdir -p "$out"
ref=tests/calculix/data/block48_node61.csv
ccx_x=$(awk -F, '$1 == "h0.6" && $7 == "fx" { print $8 }' "$ref")
ccx_z=$(awk -F, '$1 == "h0.6" && $7 == "fz" { print $10 }' "$ref")
[ -n "$ccx_x" ] && [ -n "$ccx_z" ] || { echo "block48.sh: no h0.6 rows in $ref" >&2; exit 1; }
tmp=$(mktemp)
trap 'rm -f "$tmp"' EXIT
echo "grid,particles,neighbours,support,stab,colloc_ux_fx,colloc_uz_fz,rpim_ux_fx,rpim_uz_fz,ccx_ux_fx,ccx_uz_fz,colloc_vs_ccx_x,colloc_vs_ccx_z,colloc_vs_rpim_x,colloc_vs_rpim_z,seconds" > "$tmp"
declare -A rpim
row() { # grid neighbours support stab
  local grid=$1 k=$2 sup=$3 stab=$4 n ux uz s1 s2 sec m rx ry rz rs
  IFS=, read -r n ux uz s1 s2 sec <<< \
    "$("$colloc" "$grid" --neighbours "$k" --support "$sup" --stab "$stab")"
  [ -n "${rpim[$grid]:-}" ] || rpim[$grid]=$("$node61" "$grid") # once per grid
  IFS=, read -r m rx ry rz rs <<< "${rpim[$grid]}"
  awk -v g="$grid" -v k="$k" -v sup="$sup" -v s="$stab" -v n="$n" -v ux="$ux" -v uz="$uz" \
      -v rx="$rx" -v rz="$rz" -v cx="$ccx_x" -v cz="$ccx_z" -v sec="$sec" 'BEGIN {
    printf "%s,%s,%s,%s,%s,%.5f,%.5f,%.5f,%.5f,%.5f,%.5f,%+.4f,%+.4f,%+.4f,%+.4f,%s\n",
      g, n, k, sup, s, ux, uz, rx, rz, cx, cz, ux / cx - 1, uz / cz - 1, ux / rx - 1, uz / rz - 1, sec }' |
    sed 's/^\([0-9]*\),\([0-9]*\),\([0-9]*\),/\1x\2x\3,/' >> "$tmp"
  tail -1 "$tmp" >&2
}
# The defaults (k = 10, support 1.5, stab 0.2, written out so that a row
# keeps its meaning if they change) at every grid; the former defaults
# (k = 16, support 2, stab 0.3) at the finest for comparison.
for g in 11,11,3 21,21,5 41,41,9; do row "$g" 10 1.5 0.2; done
row 41,41,9 16 2 0.3
chmod 644 "$tmp"
mv "$tmp" "$out/block48.csv"
trap - EXIT
column -t -s, "$out/block48.csv"

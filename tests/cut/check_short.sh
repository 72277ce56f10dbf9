#!/bin/sh
# check_short.sh DECK CUT_TOOL OUTDIR DATADIR — the short real version of
# make cut-validation (docs/cutting.md): CalculiX at the coarsest level
# (n = 4) and the meshless solves at the coarsest grid (16 x 8 x 8:
# rpim-galerkin and efg-galerkin) are run again and must reproduce the
# committed COD profiles (CalculiX to 1e-6 of the mouth COD: its output has
# 7 digits; the meshless solves to 1e-9); each meshless mouth COD must lie
# within COARSE_BOUND of the finest committed CalculiX level (the lips open,
# by about the right amount).
set -eu
deck=$1 tool=$2 out=$3 data=$4
COARSE_BOUND=0.30
mkdir -p "$out"
"$deck" --divisions 4 > "$out/slit_n4.inp"
(cd "$out" && OMP_NUM_THREADS=1 ccx -i slit_n4 > slit_n4.log 2>&1) ||
    { echo "check-cut: ccx failed (see $out/slit_n4.log)" >&2; exit 1; }
awk '/^\*\* LIP/ { z[++m] = $3; lo[m] = $4; hi[m] = $5 }
     /displacements/ { d = 1; next }
     d && NF == 4 { u[$1] = $2 }
     END { print "z,cod"; for (k = m; k >= 1; --k) printf "%.6f,%.10g\n", z[k], u[hi[k]] - u[lo[k]] }' \
    "$out/slit_n4.inp" "$out/slit_n4.dat" > "$out/ccx_n4.csv"
"$tool" cod tests/cut/slit.yaml geometry.grid=16,8,8 solver.cells=16,8,8 | grep -v '^#' > "$out/meshless_16.csv"
"$tool" cod tests/cut/slit.yaml geometry.grid=16,8,8 solver.cells=16,8,8 solver.method=efg-galerkin |
    grep -v '^#' > "$out/efg_16.csv"
# largest |a - b| / |mouth of b| over the rows of two z,cod files
compare() {
    awk -F, 'FNR == 1 { f++; next }
             f == 1 { a[FNR] = $2; n = FNR }
             f == 2 { b[FNR] = $2; if (FNR == 2) mouth = ($2 < 0 ? -$2 : $2) }
             END { w = 0; for (k = 2; k <= n; ++k) { d = a[k] - b[k]; if (d < 0) d = -d; if (d > w) w = d }
                   if (n < 2 || mouth == 0) print "nan"; else printf "%.3e\n", w / mouth }' "$1" "$2"
}
ccx_dev=$(compare "$out/ccx_n4.csv" "$data/ccx_n4.csv")
mls_dev=$(compare "$out/meshless_16.csv" "$data/meshless_16.csv")
efg_dev=$(compare "$out/efg_16.csv" "$data/efg_16.csv")
ref=$(grep '^ccx,' "$data/runs.csv" | tail -1 | cut -d, -f2,3)
# |mouth COD of a z,cod file - the finest CalculiX level's| / the latter
gap_of() {
    echo "$(sed -n 2p "$1" | cut -d, -f2) ${ref#*,}" |
        awk '{ d = ($1 - $2) / $2; printf "%.4f\n", d < 0 ? -d : d }'
}
gap=$(gap_of "$out/meshless_16.csv")
efg_gap=$(gap_of "$out/efg_16.csv")
echo "slit: CalculiX n = 4 vs committed $ccx_dev, 16x8x8 rpim-galerkin vs committed $mls_dev," \
     "efg-galerkin $efg_dev (of the mouth COD); mouth COD vs CalculiX n = ${ref%,*} ${ref#*,} mm:" \
     "rpim $gap, efg $efg_gap (bound $COARSE_BOUND)"
awk -v c="$ccx_dev" -v m="$mls_dev" -v e="$efg_dev" -v g="$gap" -v h="$efg_gap" -v b="$COARSE_BOUND" \
    'BEGIN { exit !(c != "nan" && m != "nan" && e != "nan" && c + 0 <= 1e-6 && m + 0 <= 1e-9 &&
                    e + 0 <= 1e-9 && g + 0 <= b && h + 0 <= b) }' ||
    { echo "check-cut: FAILED" >&2; exit 1; }
echo "ok: the slit's lips open (RPIM and EFG) and every solve reproduces the committed data"

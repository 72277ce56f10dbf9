#!/bin/sh
# run_validation.sh DECK CUT_TOOL OUTDIR DATADIR — the slit block's
# crack-opening displacement (COD) along its depth at mid-width: CalculiX
# (crack by duplicated nodes) at the element levels CCX_LEVELS and the
# meshless solve at the node grids GRIDS, rpim-galerkin (visibility) and
# efg-galerkin (enriched MLS weights) at EFG_GRIDS (docs/cutting.md).
# Writes DATADIR/ccx_nN.csv, DATADIR/meshless_NX.csv and DATADIR/efg_NX.csv
# (z,cod) and DATADIR/runs.csv (kind,level,mouth_cod,seconds).
set -eu
deck=$1 tool=$2 out=$3 data=$4
CCX_LEVELS=${CCX_LEVELS-4 8 16}
GRIDS=${GRIDS-16,8,8 24,12,12 32,16,16}
EFG_GRIDS=${EFG_GRIDS-$GRIDS}
mkdir -p "$out" "$data"
runs="$out/runs.csv"
echo "kind,level,mouth_cod,seconds" > "$runs"
for n in $CCX_LEVELS; do
    "$deck" --divisions "$n" > "$out/slit_n$n.inp"
    t0=$(date +%s.%N)
    (cd "$out" && OMP_NUM_THREADS=1 ccx -i "slit_n$n" > "slit_n$n.log" 2>&1) ||
        { echo "run_validation: ccx failed at n = $n (see $out/slit_n$n.log)" >&2; exit 1; }
    t1=$(date +%s.%N)
    # COD = u_x of the +x copy minus u_x of the -x node, per ** LIP line
    awk '/^\*\* LIP/ { z[++m] = $3; lo[m] = $4; hi[m] = $5 }
         /displacements/ { d = 1; next }
         d && NF == 4 { u[$1] = $2 }
         END { print "z,cod"; for (k = m; k >= 1; --k) printf "%.6f,%.10g\n", z[k], u[hi[k]] - u[lo[k]] }' \
        "$out/slit_n$n.inp" "$out/slit_n$n.dat" > "$data/ccx_n$n.csv"
    echo "ccx,$n,$(sed -n 2p "$data/ccx_n$n.csv" | cut -d, -f2),$(echo "$t1 - $t0" | bc)" >> "$runs"
done
for g in $GRIDS; do
    nx=${g%%,*}
    t0=$(date +%s.%N)
    "$tool" cod tests/cut/slit.yaml "geometry.grid=$g" "solver.cells=$g" > "$out/meshless_$nx.txt"
    t1=$(date +%s.%N)
    grep -v '^#' "$out/meshless_$nx.txt" > "$data/meshless_$nx.csv"
    grep '^#' "$out/meshless_$nx.txt" > "$data/meshless_$nx.info"
    echo "meshless,$g,$(sed -n 2p "$data/meshless_$nx.csv" | cut -d, -f2),$(echo "$t1 - $t0" | bc)" >> "$runs"
done
for g in $EFG_GRIDS; do
    nx=${g%%,*}
    t0=$(date +%s.%N)
    "$tool" cod tests/cut/slit.yaml "geometry.grid=$g" "solver.cells=$g" solver.method=efg-galerkin \
        > "$out/efg_$nx.txt"
    t1=$(date +%s.%N)
    grep -v '^#' "$out/efg_$nx.txt" > "$data/efg_$nx.csv"
    grep '^#' "$out/efg_$nx.txt" > "$data/efg_$nx.info"
    echo "efg,$g,$(sed -n 2p "$data/efg_$nx.csv" | cut -d, -f2),$(echo "$t1 - $t0" | bc)" >> "$runs"
done
cp "$runs" "$data/runs.csv"
cat "$data/runs.csv"

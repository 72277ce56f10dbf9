#!/bin/sh
# validation.sh TISSUEFIT TOOLDIR OUTDIR [plots] — the tables and plots of
# docs/validation.md (make solver-validation).  About ten minutes: it solves
# block48 at 41 x 41 x 9 a dozen times.  With "plots", only redraws the
# plots from the tables already in OUTDIR.
#
# TOOLDIR holds calculix_compare; OUTDIR receives CSV tables and PNG plots.
set -eu
tool=$1 tools=$2 out=$3
mkdir -p "$out"
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
say() { printf '%s\n' "validation: $*" >&2; }

compute() {
# --- cantilever: refinement, three variants of the method -----------------
say "cantilever"
"$tool" -q verify cantilever --levels 5 --csv "$out/cantilever.csv" >/dev/null
"$tool" -q verify cantilever --levels 4 --set solver.centre=point --csv "$out/cantilever_point.csv" >/dev/null
"$tool" -q verify cantilever --levels 4 --set solver.polynomial=none --csv "$out/cantilever_rbf_only.csv" >/dev/null

# --- patch test: Gauss order, with and without the polynomial -------------
say "patch test"
"$tool" -q verify patch --levels 8 --csv "$out/patch_linear.csv" >/dev/null
"$tool" -q verify patch --levels 8 --set solver.polynomial=none --csv "$out/patch_rbf_only.csv" >/dev/null
"$tool" -q verify patch --levels 8 --set solver.centre=point --csv "$out/patch_point.csv" >/dev/null
"$tool" -q verify patch --levels 6 --set geometry.jitter=0 --csv "$out/patch_regular.csv" >/dev/null
"$tool" -q verify patch --vary grid --levels 3 --set solver.rbf.d_c=2 --csv "$out/patch_refined.csv" >/dev/null

# node 61's row of a block48 solve: u61 GRID FORCE [SETS...]
u61() {
    grid=$1 force=$2
    shift 2
    nx=${grid%%,*}
    node=$(( nx / 2 + nx * (nx / 2) + 1 ))
    "$tool" -q solve tests/solver/block48_seed.yaml --set geometry.grid="$grid" --set contact.0.node="$node" \
        --force "$force" "$@" -o "$tmp/u.csv"
    awk -F, -v n="$node" '$1 == n { print $5 "," $6 "," $7 }' "$tmp/u.csv"
}

# --- penalty against elimination ---------------------------------------------
say "penalty"
"$tool" -q solve tests/solver/block48_seed.yaml --force 0.9,-0.7,-0.22 -o "$tmp/elim.csv"
echo "lambda,max_abs_difference_mm,relative" >"$out/penalty.csv"
for lam in 2 10 100 1e3 1e5 1e7 1e9 1e11 1e13 1e16 1e20 1e50 1e100 1e300; do
    "$tool" -q solve tests/solver/block48_seed.yaml --force 0.9,-0.7,-0.22 --set solver.bc=penalty \
        --set solver.penalty=$lam -o "$tmp/pen.csv"
    paste -d, "$tmp/elim.csv" "$tmp/pen.csv" | awk -F, -v l=$lam '
        NR > 1 { for (k = 5; k <= 7; ++k) { d = $k - $(k + 7); if (d < 0) d = -d; if (d > m) m = d
                                            a = $k; if (a < 0) a = -a; if (a > s) s = a } }
        END { printf "%s,%.3e,%.3e\n", l, m, m / s }' >>"$out/penalty.csv"
done

# --- Young's modulus -------------------------------------------------------------
say "Young's modulus"
echo "E_MPa,ux61_mm,uy61_mm,uz61_mm,E_times_uz61" >"$out/young.csv"
for e in 0.001 0.01 0.32 10 1000; do
    r=$(u61 11,11,3 0.9,-0.7,-0.22 --set material.E=$e)
    echo "$e,$r" | awk -F, '{ printf "%s,%.10g,%.10g,%.10g,%.12g\n", $1, $2, $3, $4, $1 * $4 }' >>"$out/young.csv"
done

# --- conditioning: RBF length d_c and support size --------------------------
say "conditioning"
echo "d_c_mm,support,min_rcond,cantilever_error_l2" >"$out/conditioning.csv"
for dc in 0.5 2 8 32 128; do
    for sup in 2 3; do
        "$tool" verify cantilever --levels 3 --set solver.rbf.d_c=$dc --set solver.support=$sup \
            >"$tmp/v.csv" 2>"$tmp/v.err" || true
        rc=$(grep -o "smallest reciprocal condition [0-9.e+-]*" "$tmp/v.err" | tail -1 | awk '{ print $4 }')
        err=$(awk -F, 'NR == 4 { print $4 }' "$tmp/v.csv")
        echo "$dc,$sup,${rc:-singular},${err:-failed}" >>"$out/conditioning.csv"
    done
done
echo "d_c_mm,min_rcond,warning,ux61_fx,uz61_fz" >"$out/conditioning_block48.csv"
for dc in 0.5 2 8 24 48 96 200 400 3000; do
    "$tool" solve tests/solver/block48_seed.yaml --force 1,0,0 --set solver.rbf.d_c=$dc -o "$tmp/x.csv" 2>"$tmp/x.err" || true
    "$tool" -q solve tests/solver/block48_seed.yaml --force 0,0,-1 --set solver.rbf.d_c=$dc -o "$tmp/z.csv" 2>/dev/null || true
    rc=$(grep -o "smallest reciprocal condition [0-9.e+-]*" "$tmp/x.err" | awk '{ print $4 }')
    warn=$(grep -q "warning" "$tmp/x.err" && echo yes || echo no)
    x=$(awk -F, '$1 == 61 { print $5 }' "$tmp/x.csv" 2>/dev/null || true)
    z=$(awk -F, '$1 == 61 { print $7 }' "$tmp/z.csv" 2>/dev/null || true)
    echo "$dc,${rc:-singular},$warn,${x:-failed},${z:-failed}" >>"$out/conditioning_block48.csv"
    if [ "$dc" = 400 ]; then grep "warning" "$tmp/x.err" >"$out/ill_conditioned_warning.txt" || true; fi
    if [ "$dc" = 3000 ]; then grep "error" "$tmp/x.err" >>"$out/ill_conditioned_warning.txt" || true; fi
    rm -f "$tmp/x.csv" "$tmp/z.csv"
done

# --- block48: levels, time, and the CalculiX reference ------------------------
say "block48 levels"
echo "grid,nodes,ux61_fx,uy61_fy,uz61_fz,seconds,volumetric" >"$out/block48_levels.csv"
for v in cell full; do
    for g in 11,11,3 21,21,5 31,31,7 41,41,9; do
        echo "$(echo $g | tr , x),$("$tools/node61" $g solver.volumetric=$v),$v" >>"$out/block48_levels.csv"
    done
done
"$tools/calculix_compare" --no-check --levels "11,11,3;21,21,5;31,31,7;41,41,9" --csv "$out/calculix.csv" >/dev/null

# --- Poisson's ratio: node 61 by level (and against CalculiX when present) ---
say "Poisson's ratio"
echo "nu,grid,nodes,ux61_fx,uy61_fy,uz61_fz,seconds,volumetric" >"$out/nu_sweep.csv"
for nu in 0 0.3 0.45 0.49 0.499; do
    for v in cell full; do
        for g in 11,11,3 21,21,5 41,41,9; do
            echo "$nu,$(echo $g | tr , x),$("$tools/node61" $g material.nu=$nu solver.volumetric=$v),$v" \
                >>"$out/nu_sweep.csv"
        done
    done
    "$tools/calculix_compare" --no-check --nu $nu --levels 41,41,9 | sed "s/^/$nu,/" >>"$tmp/nu_ccx.csv"
done
{ head -1 "$tmp/nu_ccx.csv" | sed 's/^[^,]*,/nu,/'; grep -v ',level,' "$tmp/nu_ccx.csv"; } >"$out/nu_calculix.csv"
}

# --- plots -----------------------------------------------------------------------
plots() {
say "plots"
ccx=""
if [ -f "$out/calculix.csv" ]; then
    ccx=", '< grep ,fx, $out/calculix.csv' using 3:8 with lines lw 2 dt 3 lc rgb 'black' title 'CalculiX reference, ux', '< grep ,fz, $out/calculix.csv' using 3:(-\$10) with lines lw 2 dt 3 lc rgb 'gray40' title 'CalculiX reference, -uz'"
fi
gnuplot <<EOF
set terminal pngcairo size 720,480 font ",11"
set termoption noenhanced
set datafile separator ","
set key autotitle columnhead
set grid

set output "$out/cantilever.png"
set logscale xy
set xlabel "nodes (h^-2: the beam is a plane problem)"
set ylabel "relative error"
set title "Cantilever (plane strain): error against the exact solution"
plot "$out/cantilever.csv" using 2:4 with linespoints lw 2 title "L2, cell supports (default)", \
     "$out/cantilever.csv" using 2:5 with linespoints lw 2 title "energy, cell supports", \
     "$out/cantilever_point.csv" using 2:4 with linespoints title "L2, point supports (seed)", \
     "$out/cantilever_rbf_only.csv" using 2:4 with linespoints title "L2, RBF only (seed eq 12)", \
     "$out/cantilever.csv" using 2:(0.05*(\$2/170)**(-1.0)) with lines dt 2 lc rgb "black" title "O(h^2)", \
     "$out/cantilever.csv" using 2:(0.11*(\$2/170)**(-0.5)) with lines dt 3 lc rgb "black" title "O(h)"

set output "$out/patch.png"
unset logscale x
set logscale y
set xlabel "Gauss points per axis"
set ylabel "relative L2 error"
set title "Patch test (6 x 6 x 6 nodes): error by Gauss order"
plot "$out/patch_linear.csv" using 1:4 with linespoints lw 2 title "jittered, linear polynomial, cell supports", \
     "$out/patch_point.csv" using 1:4 with linespoints title "jittered, linear polynomial, point supports", \
     "$out/patch_rbf_only.csv" using 1:4 with linespoints title "jittered, RBF only", \
     "$out/patch_regular.csv" using 1:4 with linespoints title "regular grid, linear polynomial"

set output "$out/penalty.png"
set logscale xy
set xrange [1:1e21]
set format x "1e%L"
set xlabel "penalty factor lambda (seed eq 28)"
set ylabel "max |u(penalty) - u(elimination)| / max |u|"
set title "block48: the seed's penalty against direct elimination"
plot "$out/penalty.csv" using 1:(\$3 > 0 ? \$3 : 1e-17) with linespoints lw 2 notitle, \
     0.078/x with lines dt 2 lc rgb "black" title "0.078 / lambda"
unset xrange
set format x "%g"

set output "$out/block48.png"
set logscale x
unset logscale y
set xlabel "nodes"
set ylabel "compliance at node 61 (mm/N)"
set key right center
set title "block48: node 61 under refinement (11x11x3, 21x21x5, 41x41x9)"
set key noautotitle
plot "< grep ,cell $out/block48_levels.csv" using 2:3 with linespoints lw 2 lt 1 title "ux, 1 N along x (B-bar, default)", \
     "< grep ,cell $out/block48_levels.csv" using 2:(-\$5) with linespoints lw 2 lt 2 title "-uz, 1 N along -z (B-bar, default)", \
     "< grep ,full $out/block48_levels.csv" using 2:3 with linespoints dt 2 lt 1 title "ux, full integration", \
     "< grep ,full $out/block48_levels.csv" using 2:(-\$5) with linespoints dt 2 lt 2 title "-uz, full integration"$ccx

set output "$out/poisson.png"
set xlabel "nodes"
set ylabel "-uz at node 61, 1 N along -z (mm)"
set title "block48: Poisson's ratio and refinement (locking near 0.5)"
set key noautotitle
nus = "0 0.3 0.45 0.49 0.499"
set key left top
plot for [i=1:5] "< awk -F, -v n=".word(nus, i)." '\$1 == n && \$8 == \"cell\"' $out/nu_sweep.csv" \
         using 3:(-\$6) with linespoints lw 2 lt i title "nu = ".word(nus, i)." (B-bar)", \
     for [i=1:5] "< awk -F, -v n=".word(nus, i)." '\$1 == n && \$8 == \"full\"' $out/nu_sweep.csv" \
         using 3:(-\$6) with linespoints dt 2 lt i title "full integration"
EOF
}
if [ "${4:-}" != plots ]; then
    compute
fi
plots
say "done: $out"

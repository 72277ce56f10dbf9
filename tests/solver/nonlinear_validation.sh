#!/bin/sh
# nonlinear_validation.sh TISSUEFIT TOOLDIR OUTDIR [plots] — the tables and
# plots of docs/validation.md §8-§11 (make nonlinear-validation): the
# homogeneous tests against closed forms, EFG's patch test and cantilever,
# the weak boundary conditions compared, the small-load limit of every law,
# and block48's force-displacement curves.  With "plots", only redraws the
# plots from the tables in OUTDIR.
set -eu
tool=$1 tools=$2 out=$3
mkdir -p "$out"
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
say() { printf '%s\n' "nonlinear-validation: $*" >&2; }

compute() {
# --- homogeneous tests (acceptance 1) -------------------------------------------
say "homogeneous: force against stretch"
"$tools/homogeneous" stretch >"$out/homogeneous_stretch.csv"
say "homogeneous: relaxation"
"$tools/homogeneous" relax >"$out/homogeneous_relax.csv"
say "homogeneous: creep against the time step"
"$tools/homogeneous" creep >"$out/homogeneous_creep.csv"

# --- EFG: patch test and cantilever (acceptance 2) -------------------------------
say "EFG patch test and cantilever"
E="--set solver.method=efg-galerkin"
"$tool" -q verify patch --levels 8 $E --csv "$out/efg_patch_nitsche.csv" >/dev/null
"$tool" -q verify patch --levels 8 $E --set solver.integration=vci --csv "$out/efg_patch_vci.csv" >/dev/null
"$tool" -q verify cantilever --levels 4 $E --csv "$out/efg_cantilever.csv" >/dev/null
"$tool" -q verify cantilever --levels 4 --csv "$out/rpim_cantilever.csv" >/dev/null

# --- weak boundary conditions: accuracy against the factor, conditioning --------
say "penalty and Nitsche factors (cantilever level 2, EFG)"
echo "method,factor,error_l2,error_energy,rcond" >"$out/weak_bc_factor.csv"
for f in 0.3 3 10 30 100 1000 1e4 1e6; do
    for m in penalty nitsche; do
        "$tool" verify cantilever --levels 3 $E --set solver.bc=$m --set solver.$m=$f \
            >"$tmp/v.csv" 2>"$tmp/v.err" || true
        rc=$(grep -o "reciprocal condition about [0-9.e+-]*" "$tmp/v.err" | tail -1 | awk '{ print $4 }')
        row=$(awk -F, 'NR == 4 { print $4 "," $5 }' "$tmp/v.csv")
        echo "$m,$f,${row:-not positive definite,},${rc:-}" >>"$out/weak_bc_factor.csv"
    done
done

# --- the small-load limit of every law (acceptance 4) ------------------------------
say "small-load limit"
echo "method,law,relative_difference" >"$out/small_load_limit.csv"
limit() { # METHOD LAW-SETTING LINEAR-SETTING [EXTRA]
    "$tool" -q solve tests/solver/block48_seed.yaml --set solver.method=$1 --set "$2" ${4:-} \
        --force 0.3e-7,-0.2e-7,-1e-7 -o "$tmp/n.csv"
    "$tool" -q solve tests/solver/block48_seed.yaml --set solver.method=$1 --set "$3" ${5:-} \
        --force 0.3e-7,-0.2e-7,-1e-7 -o "$tmp/l.csv"
    paste -d, "$tmp/n.csv" "$tmp/l.csv" | awk -F, -v m=$1 -v l="$6" '
        NR > 1 { for (k = 5; k <= 7; ++k) { d = $k - $(k + 7); if (d < 0) d = -d; if (d > w) w = d
                                            a = $(k + 7); if (a < 0) a = -a; if (a > s) s = a } }
        END { printf "%s,%s,%.3e\n", m, l, w / s }' >>"$out/small_load_limit.csv"
}
for m in rpim-galerkin efg-galerkin; do
    beta=""
    [ $m = efg-galerkin ] && beta="--set solver.nitsche=160"
    limit $m material.law=svk material.law=linear "" "" svk
    limit $m material.law=neo-hookean material.law=linear "" "" neo-hookean
    limit $m "material={law: kelvin, nu: 0.49, k1: 0.2, k2: 0.12, eta: 0.3, k: 5}" \
        "material={E: 0.2, nu: 0.49}" "" "$beta" "kelvin k=5 (relaxed; E = k1)"
    limit $m "material={law: kelvin-neo-hookean, nu: 0.49, k1: 0.2, k2: 0.12, eta: 0.3}" \
        "material={E: 0.2, nu: 0.49}" "" "$beta" "kelvin-neo-hookean (relaxed)"
done

# --- block48 at large indentation (acceptance 3): node 61's curve, 3 load levels
say "block48 curves"
echo "grid,law,factor,fx,fy,fz,ux,uy,uz,steps,iterations,tangents,factorisations,seconds" \
    >"$tmp/curves.csv"
for g in 11,11,3 21,21,5; do
    for law in neo-hookean svk; do
        for f in 0,0,-3 1,0,0 1,0,-3; do
            # a law past its limit load fails (exit 1) with its row marked "failed"
            "$tools/block48_curves" $g $law $f 3 2>>"$tmp/curves.err" | tail -n +2 >>"$tmp/curves.csv" || true
        done
    done
done
cp "$tmp/curves.csv" "$out/block48_curves.csv"
}

# --- plots -----------------------------------------------------------------------
plots() {
say "plots"
gnuplot <<EOF
set terminal pngcairo size 720,480 font ",11"
set termoption noenhanced
set datafile separator ","
set grid

set output "$out/homogeneous_stretch.png"
set xlabel "stretch (x+ face moved, uniaxial stress)"
set ylabel "force on the x+ face (N)"
set title "Cube in uniaxial stress: force against stretch (E = 1 MPa, 100 mm^2)"
set key left top
plot "< grep 'rpim-galerkin,svk' $out/homogeneous_stretch.csv" using 4:5 with points pt 6 ps 1.2 title "RPIM, SVK (nu = 0.3)", \
     "< grep 'efg-galerkin,svk' $out/homogeneous_stretch.csv" using 4:5 with points pt 2 title "EFG, SVK", \
     "< grep 'rpim-galerkin,neo-hookean,0.3' $out/homogeneous_stretch.csv" using 4:5 with points pt 4 ps 1.2 title "RPIM, neo-Hookean (nu = 0.3)", \
     "< grep 'efg-galerkin,neo-hookean,0.3' $out/homogeneous_stretch.csv" using 4:5 with points pt 1 title "EFG, neo-Hookean", \
     "< grep 'rpim-galerkin,svk' $out/homogeneous_stretch.csv | sort -t, -k4 -g" using 4:6 with lines lc rgb "black" title "closed forms", \
     "< grep 'rpim-galerkin,neo-hookean,0.3' $out/homogeneous_stretch.csv | sort -t, -k4 -g" using 4:6 with lines lc rgb "black" notitle

set output "$out/homogeneous_relax.png"
set xlabel "time after the strain step (s)"
set ylabel "force on the x+ face (N)"
set title "Kelvin relaxation after a 5 % strain step (tau = 2.5 s)"
set key right top
plot "< grep 'rpim-galerkin,kelvin k=0' $out/homogeneous_relax.csv" using 3:4 with points pt 6 title "RPIM, k = 0", \
     "< grep 'efg-galerkin,kelvin k=5' $out/homogeneous_relax.csv" using 3:4 with points pt 2 title "EFG, k = 5", \
     "< grep 'rpim-galerkin,kelvin-neo-hookean' $out/homogeneous_relax.csv" using 3:4 with points pt 4 title "RPIM, neo-Hookean Kelvin", \
     "< grep 'rpim-galerkin,kelvin k=0' $out/homogeneous_relax.csv" using 3:5 with lines lc rgb "black" title "closed forms", \
     "< grep 'rpim-galerkin,kelvin k=5' $out/homogeneous_relax.csv" using 3:5 with lines lc rgb "black" notitle, \
     "< grep 'rpim-galerkin,kelvin-neo-hookean' $out/homogeneous_relax.csv" using 3:5 with lines lc rgb "black" notitle

set output "$out/homogeneous_creep.png"
set logscale xy
set xlabel "time step (s)"
set ylabel "relative error of the strain at t = 5 s"
set title "Kelvin creep under a stress step: error against the time step"
set key left top
plot "< grep 'rpim-galerkin,kelvin k=0' $out/homogeneous_creep.csv" using 3:6 with linespoints title "RPIM, k = 0", \
     "< grep 'rpim-galerkin,kelvin k=5' $out/homogeneous_creep.csv" using 3:6 with linespoints title "RPIM, k = 5", \
     "< grep 'efg-galerkin,kelvin k=5' $out/homogeneous_creep.csv" using 3:6 with linespoints title "EFG, k = 5", \
     x**2 * 2.5e-3 with lines dt 2 lc rgb "black" title "O(dt^2)"

set output "$out/weak_bc_factor.png"
set xlabel "factor (alpha or beta over (lambda + 2 mu) / h)"
set ylabel "cantilever L2 error, level 3 (EFG)"
set title "Weak essential conditions: accuracy against the factor"
plot "< grep '^penalty' $out/weak_bc_factor.csv | grep -v positive" using 2:3 with linespoints title "penalty ([EFG-Kelvin] eqs 19, 23)", \
     "< grep '^nitsche' $out/weak_bc_factor.csv | grep -v positive" using 2:3 with linespoints title "Nitsche"

set output "$out/efg_patch.png"
unset logscale x
set xlabel "Gauss points per axis"
set ylabel "relative L2 error"
set title "Patch test (jittered 6^3 cloud): EFG and RPIM, Gauss points and VCI"
set logscale y
plot "$out/efg_patch_nitsche.csv" using 1:4 with linespoints title "EFG, Nitsche", \
     "$out/efg_patch_vci.csv" using 1:(\$4 > 1e-16 ? \$4 : 1e-16) with linespoints title "EFG, Nitsche + VCI", \
     "docs/validation/patch_linear.csv" using 1:4 with linespoints title "RPIM (§2)"
set output "$out/block48_curves.png"
unset logscale
set xlabel "force along -z (N)"
set ylabel "-u_z at the top centre (mm)"
set title "block48, 3 N along -z from rest: node 61's curve (3 load levels)"
set key left top
sel(g, l) = sprintf("< grep '^%s,%s,[0-9.e-]*,0,0,' $out/block48_curves.csv | grep -v failed", g, l)
plot sel("11x11x3", "neo-hookean") using (-\$6):(-\$9) with linespoints title "neo-Hookean, 11x11x3", \
     sel("21x21x5", "neo-hookean") using (-\$6):(-\$9) with linespoints title "neo-Hookean, 21x21x5", \
     sel("11x11x3", "svk") using (-\$6):(-\$9) with linespoints title "SVK, 11x11x3", \
     sel("21x21x5", "svk") using (-\$6):(-\$9) with linespoints title "SVK, 21x21x5"
EOF
}
if [ "${4:-}" != plots ]; then
    compute
fi
plots
say "done: $out"

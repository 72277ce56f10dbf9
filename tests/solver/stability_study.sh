#!/bin/bash
# stability_study.sh — the least eigenvalue mu_1 of K_t v = mu K_0 v along
# block48's 3 N neo-Hookean contact load path at several node densities
# (issue 13, acceptance 5; docs/validation.md §13), with a plot.
#
#   stability_study.sh TOOL OUTDIR "GRID:STEPS[:KEY=VALUE...] ..."
#
# Each entry runs `TOOL GRID STEPS KEY=VALUE...` (tests/solver/stability_path.c)
# into OUTDIR/stability_GRID.csv (written to a temporary file and renamed);
# then OUTDIR/stability.png plots mu_1 against the force for every CSV there
# (log scale: a mu_1 <= 0 would leave its point out; the CSV holds it).  No
# entries: the plot only.
set -euo pipefail
tool=$1 out=$2 entries=$3
mkdir -p "$out"
for e in $entries; do
    IFS=: read -r -a f <<< "$e"
    grid=${f[0]} steps=${f[1]}
    name="$out/stability_${grid//,/x}.csv"
    echo "-- $grid, $steps steps ${f[*]:2}" >&2
    "$tool" "$grid" "$steps" "${f[@]:2}" > "$name.tmp"
    mv "$name.tmp" "$name"
done
plots=""
for c in "$out"/stability_*.csv; do
    g=$(basename "$c" .csv); g=${g#stability_}
    plots="$plots${plots:+, }\"$c\" using (-\$2):12 with linespoints title \"$g\""
done
gnuplot <<GP
set terminal pngcairo size 720,480 font ",11"
set termoption noenhanced
set datafile separator ","
set grid
set output "$out/stability.png.tmp"
set xlabel "contact force along -z (N)"
set ylabel "least eigenvalue mu_1 of K_t v = mu K_0 v"
set title "block48, neo-Hookean: stability along the load path"
set key left bottom
set logscale y
set yrange [1e-5:1]
set format y "%g"
plot $plots
GP
mv "$out/stability.png.tmp" "$out/stability.png"
echo "stability study: $(ls "$out"/stability_*.csv | wc -l) grids, plot $out/stability.png" >&2

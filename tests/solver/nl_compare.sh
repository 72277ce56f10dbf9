#!/bin/sh
# nl_compare.sh CURVES_TOOL CALCULIX_DATA OUTDIR [plots] — block48 at large
# indentation against the CalculiX NLGEOM reference (docs/validation.md §12,
# issue 13 acceptance 3; make nonlinear-compare).
#
# Node 61's curve of the meshless solver (block48_curves, 10 equal load
# levels, each continuing from the last) on every cloud of NL_CLOUDS, for
# every law and path of NL_CASES, beside the finest graded CalculiX level:
#   OUTDIR/block48_nl_meshless.csv   cloud,grid,law,factor,fx,fy,fz,ux,uy,uz,
#                                    steps,iterations,tangents,factorisations,seconds
#   OUTDIR/block48_nl_compare.csv    path,law,cloud,factor,u_meshless,u_calculix,rel
#   OUTDIR/block48_nl_compare.md     the relative error per cloud and load level
#   OUTDIR/block48_nl_compare.png    the curves
# Settings from the environment (tests/nonlinear.mk sets them):
#   NL_CLOUDS  "name:grid[:grading[:method]] ..." (grading: the scene's
#              geometry.grading, e.g. 3,3,2; method: solver.method, default
#              the scene's, rpim-galerkin); the last is the finest
#   NL_CASES   "path:law:force:calculix-run ..."
#   NL_PLOT_REFS  more CalculiX runs drawn (not compared), e.g. coarser levels
#   NL_CACHE   where each run's rows are kept (default build/nl_compare); a
#              run whose file is there is not repeated (delete it to redo)
# With "plots" only the table and the plot are redone from OUTDIR's CSV.
set -eu
[ $# -ge 3 ] || { echo "usage: $0 CURVES_TOOL CALCULIX_DATA OUTDIR [plots]" >&2; exit 2; }
tool=$1 data=$2 out=$3
here=$(cd "$(dirname "$0")" && pwd)
mkdir -p "$out"
spec=$(for c in $NL_CASES; do echo "$c" | awk -F: '{ printf "%s:%s:%s ", $1, $2, $4 }'; done)

if [ "${4:-}" != plots ]; then
    cache=${NL_CACHE:-build/nl_compare}
    mkdir -p "$cache"
    tmp=$(mktemp -d)
    trap 'rm -rf "$tmp"' EXIT
    echo "cloud,grid,law,factor,fx,fy,fz,ux,uy,uz,steps,iterations,tangents,factorisations,seconds" \
        > "$tmp/meshless.csv"
    for cl in $NL_CLOUDS; do
        name=$(echo "$cl" | cut -d: -f1) grid=$(echo "$cl" | cut -d: -f2)
        grading=$(echo "$cl" | cut -d: -f3) method=$(echo "$cl" | cut -d: -f4) sets=""
        [ -z "$grading" ] || sets="geometry.grading=$grading"
        [ -z "$method" ] || sets="$sets solver.method=$method"
        for c in $NL_CASES; do
            law=$(echo "$c" | cut -d: -f2) force=$(echo "$c" | cut -d: -f3)
            # one run's rows, kept in CACHE (build/nl_compare) under its
            # settings: a study interrupted goes on where it stopped
            key=$(echo "${grid}_${grading}_${method}${method:+_}${law}_$force" | tr ',' '.')
            if [ ! -s "$cache/$key.csv" ]; then
                echo "nl_compare: $name $law $force ..." >&2
                # a law past its limit load stops (exit 1) with a row marked "failed"
                # shellcheck disable=SC2086
                "$tool" "$grid" "$law" "$force" 10 $sets 2>>"$tmp/err" > "$cache/$key.new" || true
                mv "$cache/$key.new" "$cache/$key.csv"
            fi
            tail -n +2 "$cache/$key.csv" | sed "s/^/$name,/" >> "$tmp/meshless.csv"
        done
    done
    mv "$tmp/meshless.csv" "$out/block48_nl_meshless.csv"
fi

awk -F, -v spec="$spec" -f "$here/nl_compare.awk" "$data/block48_nl_curves.csv" \
    "$out/block48_nl_meshless.csv" > "$out/block48_nl_compare.csv"
awk -F, -v spec="$spec" -v md=1 -f "$here/nl_compare.awk" "$data/block48_nl_curves.csv" \
    "$out/block48_nl_meshless.csv" > "$out/block48_nl_compare.md"

# the plot: |u61| against the load factor, CalculiX's reference runs as lines
refs=$(for c in $NL_CASES; do echo "$c" | cut -d: -f4; done | sort -u)
refs="$refs ${NL_PLOT_REFS:-}"
plot=""
for r in $refs; do
    plot="$plot \"< grep '^$r,' $data/block48_nl_curves.csv\" using 2:(sqrt(\$6**2+\$7**2+\$8**2)) with lines lw 2 title \"CalculiX $r\","
done
for c in $NL_CASES; do
    p=$(echo "$c" | cut -d: -f1) law=$(echo "$c" | cut -d: -f2)
    for cl in $NL_CLOUDS; do
        name=$(echo "$cl" | cut -d: -f1)
        force=$(echo "$c" | cut -d: -f3 | awk -F, '{ printf "%s,%s,%s", $1 == 0 ? "0" : "[0-9.e-]*", $2 == 0 ? "0" : "[0-9.e-]*", $3 == 0 ? "0" : "[0-9.e-]*" }')
        plot="$plot \"< grep -E '^$name,[^,]*,$law,[0-9.e-]*,$force,' $out/block48_nl_meshless.csv | grep -v failed\" using 4:(sqrt(\$8**2+\$9**2+\$10**2)) with linespoints title \"$p $law $name\","
    done
done
gnuplot <<EOF
set terminal pngcairo size 900,600 font ",10"
set termoption noenhanced
set datafile separator ","
set grid
set key left top
set xlabel "load factor (a: 3 N along -z, b: 1 N along x, c: both)"
set ylabel "|u| at node 61 (mm)"
set title "block48, NLGEOM: node 61, meshless (points) against CalculiX C3D20 (lines)"
set output "$out/block48_nl_compare.png"
plot ${plot%,}
EOF
echo "nl_compare: $out/block48_nl_compare.{csv,md,png}" >&2

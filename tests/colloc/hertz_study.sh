#!/bin/bash
# hertz_study.sh — the Hertz convergence study of the collocation solver
# (make hertz-study; docs/collocation.md).  Writes, in OUTDIR:
#   hertz.csv              every run, one row per indentation (tests/colloc/hertz.c)
#   hertz_runs.csv         one row per run: label, law, stab, neighbours, support,
#                          particles, L, h0, L2 force error, L2 indentation error,
#                          largest indentation error, seconds
#   hertz_convergence.png  L2 indentation error against particle count
#   hertz_force.png        force against indentation at 4,353 particles and theory
# Usage: hertz_study.sh HERTZ OUTDIR
set -euo pipefail
hertz=$1
out=$2
mkdir -p "$out"
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
csv=$tmp/hertz.csv
echo "label,law,stab,neighbours,support,particles,images,cells,levels,h0,L,R,nu,d,a,F,F_theory,d_theory,d_error,contacts,steps,seconds" > "$csv"
# R = 100 mm, a = 1 .. 2.5 mm: a/R <= 0.025 (small strain), core 5 mm.
common=(--radius 100 --indent 0.0001,0.00025,0.0004,0.000625 --core 5 --csv "$csv")
run() { echo "-- $*" >&2; "$hertz" "${common[@]}" "$@" | tail -2 >&2; }
for law in linear svk; do
  for c in 4 6 8 10 12 16; do
    run --label "conv-$law" --law "$law" --cells "$c" --levels 7
  done
done
for l in 5 6 8; do   # levels 7 is in the convergence runs
  run --label "size" --law linear --cells 8 --levels "$l"
done
# Each option against the defaults (k = 10, support 1.5, stab 0.2: the
# convergence runs at 8 cells), and the former defaults (k = 16, support 2,
# stab 0.3).
for s in 0 0.1 0.3 1; do
  run --label "stab" --law linear --cells 8 --levels 7 --stab "$s"
done
for k in 6 16 26; do
  run --label "neighbours" --law linear --cells 8 --levels 7 --neighbours "$k"
done
for s in 2 3; do
  run --label "support" --law linear --cells 8 --levels 7 --support "$s"
done
run --label "former-defaults" --law linear --cells 8 --levels 7 --neighbours 16 --support 2 \
  --stab 0.3
run --label "seed-volumes" --law linear --cells 8 --levels 7 --volumes seed
run --label "uniform" --law linear --cells 16 --levels 1 --core 20

# One row per run.
awk -F, 'NR > 1 {
  key = $1 "," $2 "," $3 "," $4 "," $5 "," $6 "," $11 "," $10
  if (!(key in n)) { order[++m] = key }
  n[key]++; sF[key] += ($16 - $17)^2; sF0[key] += $17^2
  sd[key] += ($14 - $18)^2; sd0[key] += $18^2
  e = $19 < 0 ? -$19 : $19; if (e > worst[key]) worst[key] = e
  t[key] += $22
} END {
  print "label,law,stab,neighbours,support,particles,L,h0,l2_force,l2_indent,worst_indent,seconds"
  for (i = 1; i <= m; ++i) { k = order[i]
    printf "%s,%.4f,%.4f,%.4f,%.1f\n", k, sqrt(sF[k] / sF0[k]), sqrt(sd[k] / sd0[k]), worst[k], t[k] }
}' "$csv" > "$tmp/hertz_runs.csv"

grep -E '^conv-linear' "$tmp/hertz_runs.csv" | cut -d, -f6,10,11 | tr , ' ' > "$tmp/lin.dat"
grep -E '^conv-svk' "$tmp/hertz_runs.csv" | cut -d, -f6,10,11 | tr , ' ' > "$tmp/svk.dat"
awk -F, '$1 == "conv-linear" && $8 == 8 { print $14, $16, $17 }' "$csv" > "$tmp/fd_lin.dat"
awk -F, '$1 == "conv-svk" && $8 == 8 { print $14, $16 }' "$csv" > "$tmp/fd_svk.dat"
gnuplot <<GP
set terminal pngcairo size 800,560 font ",11"
set output "$tmp/hertz_convergence.png"
set logscale xy
set xlabel "particles (quarter block, mirror planes x = 0, y = 0)"
set ylabel "error against Hertz's theory"
set title "Hertz test: L2 error over 4 indentations (a = 1 .. 2.5 mm, R = 100 mm)"
set key top right
set grid
set arrow from 6000, graph 0 to 6000, graph 1 nohead dt 2 lc rgb "gray"
plot "$tmp/lin.dat" u 1:2 w lp pt 7 t "L2 indentation error, linear law", \
     "$tmp/svk.dat" u 1:2 w lp pt 5 t "L2 indentation error, St. Venant-Kirchhoff", \
     "$tmp/lin.dat" u 1:3 w lp pt 6 dt 3 t "largest indentation error, linear", \
     0.05 w l dt 2 lc rgb "red" t "5 %"
set output "$tmp/hertz_force.png"
unset logscale
unset arrow
set xlabel "indentation d (mm)"
set ylabel "force F (N)"
set title "Force against indentation, 4,353 particles, E = 1 MPa, nu = 0.3"
set key top left
plot [0:0.07] 4.0/3/(1-0.09)*sqrt(100)*x**1.5 w l lw 2 t "Hertz: F = 4/3 E* sqrt(R) d^{3/2}", \
     "$tmp/fd_lin.dat" u 1:2 w p pt 7 ps 1.5 t "collocation, linear law", \
     "$tmp/fd_svk.dat" u 1:2 w p pt 5 ps 1.2 t "collocation, St. Venant-Kirchhoff"
GP
for f in hertz.csv hertz_runs.csv hertz_convergence.png hertz_force.png; do
  mv "$tmp/$f" "$out/$f"
done
column -t -s, "$out/hertz_runs.csv"

# basis_plot.gp — the basis conditioning study as a picture (docs/stability.md).
#   gnuplot -e "data='basis.dat'; out='stability_basis.png'" tests/stability/basis_plot.gp
# Columns of the data file: basis_study --data (order, log10 condition
# numbers raw / raw with unit columns / normalised, then digits lost:
# float32 raw / normalised / Chebyshev, float64 raw / normalised / Chebyshev,
# float32 Chebyshev in the target's nodal form).
set terminal pngcairo size 1200,480 font ",11"
set output out
set multiplot layout 1,2
set grid
set key top left
set xlabel "polynomial order"
set xrange [0.8:8.2]
set xtics 1

set title "Digits lost evaluating the same polynomial (worst of 3 profiles)"
set ylabel "decimal digits lost = log10(max error / max |P| / unit roundoff)"
set yrange [-1:5]
plot data using 1:5 with linespoints lw 2 pt 7 lc rgb "#c0392b" title "float32, raw mm (seed)", \
     data using 1:6 with linespoints lw 2 pt 5 lc rgb "#2471a3" title "float32, normalised X monomials (API 2)", \
     data using 1:7 with linespoints lw 2 pt 9 lc rgb "#229954" title "float32, Chebyshev in X (target, API 3: Clenshaw)", \
     data using 1:11 with linespoints lw 2 pt 11 lc rgb "#7d3c98" title "float32, Chebyshev (target, nodal form)", \
     data using 1:8 with linespoints lw 1 dt 2 pt 6 lc rgb "#c0392b" title "float64, raw mm", \
     data using 1:9 with linespoints lw 1 dt 2 pt 4 lc rgb "#2471a3" title "float64, normalised X", \
     data using 1:10 with linespoints lw 1 dt 2 pt 8 lc rgb "#229954" title "float64, Chebyshev in X", \
     1 with lines lw 1 lc rgb "black" title "1 digit"

set title "Condition number of the 11-node design matrix (2-norm)"
set ylabel "log10 cond"
set yrange [0:15]
plot data using 1:2 with linespoints lw 2 pt 7 lc rgb "#c0392b" title "raw mm", \
     data using 1:3 with linespoints lw 2 pt 6 lc rgb "#e67e22" title "raw mm, unit-norm columns", \
     data using 1:4 with linespoints lw 2 pt 5 lc rgb "#2471a3" title "normalised X"
unset multiplot

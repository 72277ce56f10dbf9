# convergence.gp — docs/calculix-convergence.png: mesh convergence of the
# block48 CalculiX reference.
#   gnuplot -e "table='T'; data='DIR'; levels='h2.4 h1.2 h0.6'; out='PNG'" convergence.gp
# T is the output of convergence.awk (h, node-61 displacements, RMS changes).

set terminal pngcairo size 1200,900 font ",11"
set output out
set datafile separator whitespace
set multiplot layout 2,2 title "block48, CalculiX C3D20R, nu = 0.49: mesh convergence"
finest = word(levels, words(levels))
set grid
set key top left

set title "node 61 displacement along the load, relative to ".finest
set logscale x 2
set xlabel "element size h in plane (mm; layers halve with h)"
set ylabel "u61 / u61(".finest.")"
set xrange [3:0.5]
plot table using 1:4 with linespoints pt 7 title "fx: ux (fy is its mirror)", \
     table using 1:5 with linespoints pt 5 title "fz: -uz"

set title "RMS change over the 121 nodes against ".finest
set logscale y 10
set ylabel "RMS |u - u(".finest.")| / RMS |u(".finest.")|  (%)"
set key top right
plot table using 1:($6 > 0 ? $6 : 1/0) with linespoints pt 7 title "fx", \
     table using 1:($8 > 0 ? $8 : 1/0) with linespoints pt 5 title "fz"

unset logscale
set xrange [0:48]
set xlabel "x (mm), centre line y = 24"
set datafile separator ","
set key bottom left
set title "fz = (0, 0, -1) N: vertical displacement"
set ylabel "uz (mm)"
plot for [l in levels] sprintf("%s/block48_fz_%s.csv", data, l) using ($3 == 24 ? $2 : 1/0):7 \
     with linespoints title l

set key top left
set title "fx = (1, 0, 0) N: displacement along x"
set ylabel "ux (mm)"
plot for [l in levels] sprintf("%s/block48_fx_%s.csv", data, l) using ($3 == 24 ? $2 : 1/0):5 \
     with linespoints title l
unset multiplot

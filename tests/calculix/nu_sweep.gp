# nu_sweep.gp — docs/calculix-nu-sweep.png: node-61 displacement of block48
# against Poisson's ratio, C3D20R (reduced integration) and C3D20 (full).
#   gnuplot -e "node61='DATA/block48_node61.csv'; div=40; layers=4; level='h1.2'; out='PNG'" nu_sweep.gp

set terminal pngcairo size 1200,500 font ",11"
set output out
set multiplot layout 1,2 title sprintf("block48, CalculiX, level %s: node 61 against Poisson's ratio", level)
set grid
set key bottom right
set xlabel "Poisson's ratio"
set xrange [0:0.5]

# rows "nu ux uy uz" of element el, patch load, case c on the sweep's mesh, by nu
rows(el, c) = sprintf("< awk -F, '$2 == \"%s\" && $4 == %d && $5 == %d && $6 == \"patch\" && $7 == \"%s\" { print $3, $8, $9, $10 }' %s | sort -g", el, div, layers, c, node61)

set title "fx = (1, 0, 0) N"
set ylabel "ux at node 61 (mm)"
plot rows("C3D20R", "fx") using 1:2 with linespoints pt 7 title "C3D20R", \
     rows("C3D20", "fx") using 1:2 with points pt 6 ps 2 title "C3D20"

set key bottom left
set title "fz = (0, 0, -1) N"
set ylabel "-uz at node 61 (mm)"
plot rows("C3D20R", "fz") using 1:(-$4) with linespoints pt 7 title "C3D20R", \
     rows("C3D20", "fz") using 1:(-$4) with points pt 6 ps 2 title "C3D20"
unset multiplot

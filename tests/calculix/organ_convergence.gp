# organ_convergence.gp — docs/validation/organ_convergence.png: the organs'
# meshless solves against their finest CalculiX level as the interior
# spacing falls, with the file's skin and with a refined one.
#   gnuplot -e "table='organ_convergence.csv'; out='PNG'" organ_convergence.gp
# table: organ_convergence.sh's CSV (errors in %, the worst of fx, fy, fz).

set terminal pngcairo size 1200,500 font ",11"
set output out
set datafile separator ","
set multiplot layout 1,2 title "Organs against CalculiX C3D10 (s20r1): the worst of the unit forces along x, y, z"
set grid
set logscale xy
set xrange [13:2.5]
set xtics (12, 10, 8, 6, 5, 4, 3)
set xlabel "interior node spacing (mm)"
set key bottom left opaque
max3(a, b, c) = (a > b ? (a > c ? a : c) : (b > c ? b : c))
# the rows of one organ and skin, so that each series is drawn as a line
sel(o, k) = sprintf("< awk -F, '$1 == \"%s\" && $2 == \"%s\"' %s", o, k, table)

set title "outputs: relative L2 error"
set ylabel "L2 error (%)"
set yrange [1:15]
set ytics (1, 1.5, 2, 3, 4, 6, 8, 10, 15)
plot sel("liver", "refined") using 3:(max3($9, $10, $11)) with linespoints pt 7 lc 1 title "liver, refined skin", \
     sel("liver", "file") using 3:(max3($9, $10, $11)) with linespoints pt 6 dt 2 lc 1 title "liver, the file's skin", \
     sel("stomach", "refined") using 3:(max3($9, $10, $11)) with linespoints pt 5 lc 2 title "stomach, refined skin", \
     sel("stomach", "file") using 3:(max3($9, $10, $11)) with linespoints pt 4 dt 2 lc 2 title "stomach, the file's skin", \
     2 with lines lc rgb "gray" dt 3 lw 2 title "2 %"

set title "the contact vertex: relative error"
set key top right opaque
set ylabel "contact error (%)"
plot sel("liver", "refined") using 3:(max3($6, $7, $8)) with linespoints pt 7 lc 1 title "liver, refined skin", \
     sel("liver", "file") using 3:(max3($6, $7, $8)) with linespoints pt 6 dt 2 lc 1 title "liver, the file's skin", \
     sel("stomach", "refined") using 3:(max3($6, $7, $8)) with linespoints pt 5 lc 2 title "stomach, refined skin", \
     sel("stomach", "file") using 3:(max3($6, $7, $8)) with linespoints pt 4 dt 2 lc 2 title "stomach, the file's skin"
unset multiplot

# nlgeom.gp — docs/calculix-nlgeom.png: node 61's force-displacement curves
# of the large-deformation block48 reference, one panel per material and
# load path, one line per mesh level, the linear reference dotted.
#   gnuplot -e "curves='DATA/block48_nl_curves.csv'; levels='h2.4 h1.2 h0.8'; \
#     materials='neohooke svk'; ux61=0.9156; uz61=-2.3449; element='C3D20'; out='PNG'" nlgeom.gp
# ux61, uz61: the linear compliance at node 61 (mm/N) along fx and fz.

set terminal pngcairo size 1500,900 font ",10"
set output out
set datafile separator whitespace
set multiplot layout 2,3 title sprintf("block48, CalculiX NLGEOM (%s), dead patch load: node 61 against the force", element)
set grid
set key top left

# Each curve is "x ux uz" rows of run nl_MAT_PATH_LEVEL from the CSV, after
# the origin (echo 0 0 0).
do for [m in materials] {
    set title sprintf("%s, path a: F = (0, 0, -3) N", m)
    set xlabel "|F| (N)"
    set ylabel "-uz at node 61 (mm)"
    plot for [l in levels] sprintf("< (echo 0 0 0; awk -F, '$1 == \"nl_%s_a_%s\" { print -$5, $6, $8 }' %s)", m, l, curves) \
             using 1:(-$3) with linespoints pt 7 ps 0.6 title l, \
         [0:3] -uz61 * x with lines dt 3 lc rgb "black" title "linear"
    set title sprintf("%s, path b: F = (1, 0, 0) N", m)
    set ylabel "ux at node 61 (mm)"
    plot for [l in levels] sprintf("< (echo 0 0 0; awk -F, '$1 == \"nl_%s_b_%s\" { print $3, $6, $8 }' %s)", m, l, curves) \
             using 1:2 with linespoints pt 7 ps 0.6 title l, \
         [0:1] ux61 * x with lines dt 3 lc rgb "black" title "linear"
    set title sprintf("%s, path c: F = (1, 0, -3) N (solid -uz, dashed ux)", m)
    set xlabel "load factor (F / (1, 0, -3) N)"
    set ylabel "node 61 (mm)"
    plot for [l in levels] sprintf("< (echo 0 0 0; awk -F, '$1 == \"nl_%s_c_%s\" { print $2, $6, $8 }' %s)", m, l, curves) \
             using 1:(-$3) with linespoints pt 7 ps 0.6 title l, \
         for [l in levels] sprintf("< (echo 0 0 0; awk -F, '$1 == \"nl_%s_c_%s\" { print $2, $6, $8 }' %s)", m, l, curves) \
             using 1:2 with linespoints dt 2 pt 6 ps 0.6 notitle, \
         [0:1] -3 * uz61 * x with lines dt 3 lc rgb "black" title "linear", \
         [0:1] ux61 * x with lines dt 3 lc rgb "black" notitle
}
unset multiplot

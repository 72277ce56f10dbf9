# slit_picture.gp — the slit block's mid-width section, undeformed and
# deformed (gnuplot -e "section='..'; plain='..'; out='..'; scale=S").
set terminal pngcairo size 900,520 font ",11"
set output out
set size ratio -1
set xlabel "x + s u_x (mm)"
set ylabel "z + s u_z (mm)"
set title sprintf("slit block, 1 N along +x, section y = 4.29 mm, displacements x %g: the lips open", scale)
set key outside bottom center horizontal
set xrange [-1:25]
set yrange [-1:12]
plot plain with lines lc rgb "#bbbbbb" title "undeformed grid", \
     section with linespoints pt 7 ps 0.5 lc rgb "#1f5fa8" title "deformed (rpim-galerkin with the cut)", \
     '-' with lines lw 3 lc rgb "#c0392b" title "the cut (x = 10, z = 5..10)"
10 5
10 10
e

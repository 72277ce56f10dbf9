# cod.gp — crack-opening displacement along the slit's depth, CalculiX
# levels and meshless grids (gnuplot -e "data='DIR'; ccx='4 8 16'; grids='16 24 32'; out='..'").
set terminal pngcairo size 820,520 font ",11"
set output out
set datafile separator ","
set xlabel "depth below the top, 10 - z (mm)"
set ylabel "crack opening u_x(+) - u_x(-) (mm)"
set title "slit block: crack-opening displacement at mid-width (front at depth 5 mm)"
set key top right
set grid
plot for [n in ccx] sprintf("%s/ccx_n%s.csv", data, n) using (10 - $1):2 with linespoints pt 4 \
         title sprintf("CalculiX C3D20R, h = 10/%s mm", n), \
     for [g in grids] sprintf("%s/meshless_%s.csv", data, g) using (10 - $1):2 with lines lw 2 \
         title sprintf("rpim-galerkin with the cut, %s nodes along x", g), \
     for [g in grids] sprintf("%s/efg_%s.csv", data, g) using (10 - $1):2 with lines lw 2 dt 2 \
         title sprintf("efg-galerkin with the cut, %s nodes along x", g)

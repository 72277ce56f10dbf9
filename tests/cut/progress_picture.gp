# progress_picture.gp — block48_cut's top surface around the incision at
# three cut progress values, deformed under the contact force
# (gnuplot -e "d0='..'; d1='..'; d2='..'; s0=..; s1=..; s2=..; out='..'; scale=S; force='..'").
set terminal pngcairo size 1500,640 font ",11"
set output out
set multiplot layout 1,3 title sprintf("block48\\_cut: top surface near the incision (x = 18 from y = 14, 3 mm deep), force %s N on the green patch, displacements x %g; grey: the full 20 mm path, red: cut so far", force, scale)
set size ratio -1
set xrange [7:33]
set yrange [7:41]
set xlabel "x + k u_x (mm)"
set ylabel "y + k u_y (mm)"
set key off
set object 1 rect from 21.6,21.6 to 26.4,26.4 fs empty border lc rgb "#2e8b57" lw 2 front
do for [i=0:2] {
    d = i == 0 ? d0 : (i == 1 ? d1 : d2)
    s = i == 0 ? s0 : (i == 1 ? s1 : s2)
    unset arrow
    set arrow 1 from 18,14 to 18,34 nohead dt 2 lw 2 lc rgb "#888888" back
    if (s > 0) { set arrow 2 from 18,14 to 18,(14 + 20 * s) nohead lw 1.5 lc rgb "#c0392b" back }
    set title sprintf("cut progress s = %g (cut to y = %g)", s, 14 + 20 * s)
    plot d with lines lc rgb "#1f5fa8"
}
unset multiplot

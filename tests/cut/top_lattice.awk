# top_lattice.awk — a lattice of top-surface points from `tissuefit solve
# --outputs` (output,x,y,z,ux,uy,uz), deformed by `scale`, as gnuplot line
# blocks of x + scale ux, y + scale uy; a line along x is broken where it
# crosses the cut plane x = cx inside the cut's trace y0 <= y <= y1 (the
# lips), lines along y never cross it.
# Usage: awk -F, -v scale=S -v cx=18 -v y0=14 -v y1=24 -f sort.awk -f top_lattice.awk out.csv
NR > 1 {
    X[$2] = 1; Y[$3] = 1
    px[$2, $3] = $2 + scale * $5; py[$2, $3] = $3 + scale * $6
}
END {
    nx = 0; for (x in X) xs[++nx] = x
    ny = 0; for (y in Y) ys[++ny] = y
    sort(xs, nx); sort(ys, ny)
    for (k = 1; k <= ny; k += 2) {       # every other line along x
        for (i = 1; i <= nx; ++i) {
            if (i > 1 && xs[i - 1] + 0 < cx && xs[i] + 0 > cx && ys[k] + 0 >= y0 && ys[k] + 0 <= y1)
                print ""
            print px[xs[i], ys[k]], py[xs[i], ys[k]]
        }
        print ""
    }
    for (i = 1; i <= nx; i += 2) {       # every other line along y
        for (k = 1; k <= ny; ++k) print px[xs[i], ys[k]], py[xs[i], ys[k]]
        print ""
    }
}

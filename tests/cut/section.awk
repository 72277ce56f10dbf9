# section.awk — the grid lines of one y-row of a solve's CSV
# (node,x,y,z,ux,uy,uz), deformed by `scale`, as gnuplot line blocks of
# x + scale ux, z + scale uz; a line along x is broken where it crosses the
# cut plane x = cx above the front z = cz (the cut's two lips).
# Usage: awk -F, -v y=Y -v scale=S -v cx=10 -v cz=5 -f sort.awk -f section.awk solve.csv
NR > 1 && ($3 - y) ^ 2 < 1e-12 {
    X[$2] = 1; Z[$4] = 1    # keys are the CSV's text, values compared as numbers
    px[$2, $4] = $2 + scale * $5; pz[$2, $4] = $4 + scale * $7
}
END {
    nx = 0; for (x in X) xs[++nx] = x
    nz = 0; for (z in Z) zs[++nz] = z
    sort(xs, nx); sort(zs, nz)
    for (k = 1; k <= nz; ++k) {          # lines along x, one per layer
        for (i = 1; i <= nx; ++i) {
            if (i > 1 && xs[i - 1] + 0 < cx && xs[i] + 0 > cx && zs[k] + 0 > cz) print ""
            print px[xs[i], zs[k]], pz[xs[i], zs[k]]
        }
        print ""
    }
    for (i = 1; i <= nx; ++i) {          # lines along z, one per column
        for (k = 1; k <= nz; ++k) print px[xs[i], zs[k]], pz[xs[i], zs[k]]
        print ""
    }
}

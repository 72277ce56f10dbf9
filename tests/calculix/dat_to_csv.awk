# dat_to_csv.awk — the displacements of a box scene's output points in one
# printed block of a CalculiX run, as CSV (node,x,y,z,ux,uy,uz; the scene's
# output order, node = i + nx j + 1).
#
#   awk -v step=K -f dat_to_csv.awk DECK.inp DECK.dat > case.csv
#
# DECK.inp (from box_deck) maps output node N to a CalculiX node number and
# its coordinates in its "** OUT N ccx x y z" comments, and a point beyond a
# symmetry cut to its mirror image inside ("** MIRROR N source sx sy sz x y
# z": u(N) = (sx ux, sy uy, sz uz) of the source).  DECK.dat holds one
# "displacements (vx,vy,vz) for set OUT" block per step (linear) or per
# printed load level (NLGEOM); step K picks the K-th block.  CalculiX prints
# 7 significant digits; %.10g writes them back unchanged.  Exits 1 with a
# message when a node is missing, repeated or not numeric.

FNR == 1 { file++ }

file == 1 && $1 == "**" && $2 == "OUT" {
    n_out++
    point[$4] = $3
    x[$3] = $5; y[$3] = $6; z[$3] = $7
    next
}
file == 1 && $1 == "**" && $2 == "MIRROR" {
    n_out++
    src[$3] = $4; sg[$3, 1] = $5; sg[$3, 2] = $6; sg[$3, 3] = $7
    x[$3] = $8; y[$3] = $9; z[$3] = $10
    next
}
file == 1 { next }

/displacements \(vx,vy,vz\) for set OUT/ { block++; inside = (block == step); next }
/^ *[a-z]/ { inside = 0; next }   # any other heading ends the block

inside && NF == 4 && ($1 in point) {
    n = point[$1]
    if (n in u) { printf "%s:%d: node %s printed twice\n", FILENAME, FNR, $1 > "/dev/stderr"; bad = 1 }
    for (k = 2; k <= 4; k++) {
        if ($k !~ /^-?[0-9]\.[0-9]+E[-+][0-9]+$/) {
            printf "%s:%d: field %d is not a number: %s\n", FILENAME, FNR, k, $k > "/dev/stderr"; bad = 1
        }
        u[n, k - 1] = $k
    }
    u[n] = 1
}

END {
    if (n_out == 0) { print "dat_to_csv: no output points in the deck" > "/dev/stderr"; exit 1 }
    if (block < step) { printf "dat_to_csv: %s has %d displacement blocks, block %d asked\n", FILENAME, block, step > "/dev/stderr"; exit 1 }
    for (n = 1; n <= n_out; n++) {
        m = (n in src) ? src[n] : n
        if (!(m in u)) { printf "dat_to_csv: %s: block %d lacks output point %d\n", FILENAME, step, m > "/dev/stderr"; bad = 1 }
    }
    if (bad) exit 1
    print "node,x,y,z,ux,uy,uz"
    for (n = 1; n <= n_out; n++) {
        m = (n in src) ? src[n] : n
        printf "%d,%.10g,%.10g,%.10g", n, x[n], y[n], z[n]
        # a mirror image changes only signs: the printed digits stay exact
        for (k = 1; k <= 3; k++) printf ",%.10g", (n in src) ? sg[n, k] * u[m, k] : u[m, k]
        printf "\n"
    }
}

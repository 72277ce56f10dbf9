# dat_to_csv.awk — the displacements of the 121 block48 output nodes in one
# step of a CalculiX run, as CSV (node,x,y,z,ux,uy,uz; block48 node order).
#
#   awk -v step=K -f dat_to_csv.awk DECK.inp DECK.dat > case.csv
#
# DECK.inp (from block48_deck) maps block48 node N to CalculiX node numbers
# and coordinates in its "** OUT N ccx x y z" comments; DECK.dat holds one
# "displacements (vx,vy,vz) for set OUT" block per step (*NODE PRINT).
# CalculiX prints 7 significant digits; %.10g writes them back unchanged.
# Exits 1 with a message when a node is missing, repeated or not numeric.

FNR == 1 { file++ }

file == 1 && $1 == "**" && $2 == "OUT" {
    n_out++
    block48[$4] = $3
    x[$3] = $5; y[$3] = $6; z[$3] = $7
    next
}
file == 1 { next }

/displacements \(vx,vy,vz\) for set OUT/ { block++; inside = (block == step); next }
/^ *[a-z]/ { inside = 0; next }   # any other heading ends the block

inside && NF == 4 && ($1 in block48) {
    n = block48[$1]
    if (n in ux) { printf "%s:%d: node %s printed twice\n", FILENAME, FNR, $1 > "/dev/stderr"; bad = 1 }
    for (k = 2; k <= 4; k++) {
        if ($k !~ /^-?[0-9]\.[0-9]+E[-+][0-9]+$/) {
            printf "%s:%d: field %d is not a number: %s\n", FILENAME, FNR, k, $k > "/dev/stderr"; bad = 1
        }
    }
    ux[n] = $2; uy[n] = $3; uz[n] = $4
}

END {
    if (n_out != 121) { printf "dat_to_csv: %d OUT nodes in the deck, expected 121\n", n_out > "/dev/stderr"; exit 1 }
    if (block < step) { printf "dat_to_csv: %s has %d displacement blocks, step %d asked\n", FILENAME, block, step > "/dev/stderr"; exit 1 }
    for (n = 1; n <= 121; n++) {
        if (!(n in ux)) { printf "dat_to_csv: %s: step %d lacks block48 node %d\n", FILENAME, step, n > "/dev/stderr"; bad = 1 }
    }
    if (bad) exit 1
    print "node,x,y,z,ux,uy,uz"
    for (n = 1; n <= 121; n++) {
        printf "%d,%.10g,%.10g,%.10g,%.10g,%.10g,%.10g\n", n, x[n], y[n], z[n], ux[n], uy[n], uz[n]
    }
}

# organ_dat.awk — the displacements of an organ deck's output vertices in
# its three unit-force steps (or, for an --nlgeom deck, at its printed load
# levels l1 .. lK), as CSV (vertex,x,y,z,case,ux,uy,uz,contact; vertex =
# the mesh file's vertex index as tissuefit reads it; contact = 1 on the
# contact vertex's rows).
#
#   awk -f organ_dat.awk DECK.inp DECK.dat > level.csv
#
# DECK.inp (from organ_deck) maps vertices to CalculiX nodes in its
# "** OUT vertex node x y z" comments and names each step's case in
# "** STEP n case fx fy fz"; DECK.dat holds one "displacements (vx,vy,vz)
# for set OUT" block per step (*NODE PRINT).  CalculiX prints 7 significant
# digits; %.10g writes them back unchanged.  Exits 1 with a message when a
# vertex or a step is missing or a value is not a number.

FNR == 1 { file++ }

file == 1 && $1 == "**" && $2 == "OUT" {
    n_out++
    order[n_out] = $4
    vertex[$4] = $3
    x[$4] = $5; y[$4] = $6; z[$4] = $7
    next
}
file == 1 && $1 == "**" && $2 == "STEP" { name[$3] = $4; steps++; next }
file == 1 && $1 == "**" && $2 == "CONTACT" { contact = $3; next }
file == 1 { next }

/displacements \(vx,vy,vz\) for set OUT/ { block++; inside = 1; next }
/^ *[a-z]/ { inside = 0; next }

inside && NF == 4 && ($1 in vertex) {
    key = block SUBSEP $1
    if (key in ux) { printf "%s:%d: node %s printed twice\n", FILENAME, FNR, $1 > "/dev/stderr"; bad = 1 }
    for (k = 2; k <= 4; k++) {
        if ($k !~ /^-?[0-9]\.[0-9]+E[-+][0-9]+$/) {
            printf "%s:%d: field %d is not a number: %s\n", FILENAME, FNR, k, $k > "/dev/stderr"; bad = 1
        }
    }
    ux[key] = $2; uy[key] = $3; uz[key] = $4
}

END {
    if (n_out == 0 || steps < 1 || block != steps) {
        printf "organ_dat: %d OUT vertices, %d steps in the deck, %d displacement blocks\n", n_out, steps, block > "/dev/stderr"
        exit 1
    }
    print "vertex,x,y,z,case,ux,uy,uz,contact"
    for (s = 1; s <= steps; s++) {
        for (j = 1; j <= n_out; j++) {
            node = order[j]; key = s SUBSEP node
            if (!(key in ux)) { printf "organ_dat: step %d lacks node %s\n", s, node > "/dev/stderr"; bad = 1; continue }
            printf "%d,%.10g,%.10g,%.10g,%s,%.10g,%.10g,%.10g,%d\n", vertex[node], x[node], y[node], z[node], name[s], ux[key], uy[key], uz[key], vertex[node] == contact
        }
    }
    if (bad) exit 1
}

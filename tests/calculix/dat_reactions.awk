# dat_reactions.awk — per step, the applied force (from the deck's
# "** STEP n case fx fy fz" comments) and the total reaction force on the
# clamped faces (the "total force (fx,fy,fz) for set CLAMP" block of the
# .dat), as CSV lines: case,fx,fy,fz,rx,ry,rz.  Equilibrium: r = -f.
#
#   awk -f dat_reactions.awk DECK.inp DECK.dat

FNR == 1 { file++ }

file == 1 && $1 == "**" && $2 == "STEP" { name[$3] = $4; f[$3] = $5 "," $6 "," $7; steps = $3; next }
file == 1 { next }

/total force \(fx,fy,fz\) for set CLAMP/ { block++; want = 1; next }
want && NF == 3 { r[block] = sprintf("%.10g,%.10g,%.10g", $1, $2, $3); want = 0 }

END {
    if (block != steps) { printf "dat_reactions: %s: %d reaction totals for %d steps\n", FILENAME, block, steps > "/dev/stderr"; exit 1 }
    for (s = 1; s <= steps; s++) print name[s] "," f[s] "," r[s]
}

# dat_reactions.awk — per step of a linear run, the applied force (from the
# deck's "** STEP n case fx fy fz" comments) and the whole box's total
# reaction on its supports (support_reaction.awk), as CSV lines
# case,fx,fy,fz,rx,ry,rz.  Equilibrium: r = -f.
#
#   awk -f support_reaction.awk -f dat_reactions.awk DECK.inp DECK.dat

FNR == 1 { file++ }

file == 1 && $1 == "**" && $2 == "STEP" { name[$3] = $4; f[$3] = $5 "," $6 "," $7; steps = $3; next }
file == 1 { support_deck_line(); next }

{ support_dat_line() }

END {
    blocks = support_blocks()
    if (blocks != steps) { printf "dat_reactions: %s: %d reaction totals for %d steps\n", FILENAME, blocks, steps > "/dev/stderr"; exit 1 }
    for (s = 1; s <= steps; s++) print name[s] "," f[s] "," support_total(s)
}

# dat_curve.awk — the force-displacement curve of a large-deformation
# (NLGEOM) run at one output point: one CSV line per printed load level (the
# *TIME POINTS of the deck), factor,fx,fy,fz,ux,uy,uz,rx,ry,rz with the
# applied force f = factor times the path's force (the deck's
# "** STEP 1 path FX FY FZ" line), the point's displacement u (mm) and the
# whole box's total reaction r (N, support_reaction.awk).
#
#   awk -v point=61 -f support_reaction.awk -f dat_curve.awk DECK.inp DECK.dat
#
# The load factor is the step time CalculiX prints in each block heading
# ("... for set OUT and time  0.1000000E+00"; a static step's load ramps
# linearly over its time period 1).  The point must be meshed (an OUT line,
# not a mirror image).  Exits 1 with a message when the deck has no single
# path step or no such point, a level lacks the point or a reaction, or a
# value is not a number.  No header line: the caller prefixes the run.

FNR == 1 { file++ }

file == 1 && $1 == "**" && $2 == "STEP" { steps++; f[1] = $5; f[2] = $6; f[3] = $7; next }
file == 1 && $1 == "**" && $2 == "OUT" && $3 == point { ccx = $4; next }
file == 1 { support_deck_line(); next }

/displacements \(vx,vy,vz\) for set OUT and time/ { level++; t[level] = $NF; inside = 1; next }
support_dat_line() { inside = 0; next }
/^ *[a-z]/ { inside = 0; next }
inside && NF == 4 && $1 == ccx { u[level] = number($2) "," number($3) "," number($4); next }

function number(s) {
    if (s !~ /^-?[0-9]\.[0-9]+E[-+][0-9]+$/) { printf "%s:%d: not a number: %s\n", FILENAME, FNR, s > "/dev/stderr"; bad = 1 }
    return sprintf("%.10g", s)
}

END {
    if (steps != 1 || ccx == "") { print "dat_curve: the deck needs one path step and point " point > "/dev/stderr"; exit 1 }
    if (support_blocks() != level) { printf "dat_curve: %s: %d load levels, %d reaction totals\n", FILENAME, level, support_blocks() > "/dev/stderr"; exit 1 }
    for (k = 1; k <= level; k++) {
        if (!(k in u)) { printf "dat_curve: %s: level %d (time %s) lacks point %s\n", FILENAME, k, t[k], point > "/dev/stderr"; bad = 1 }
        if (support_time["CLAMP", k] != t[k]) { printf "dat_curve: %s: level %d: reaction at time %s\n", FILENAME, k, support_time["CLAMP", k] > "/dev/stderr"; bad = 1 }
    }
    if (bad) exit 1
    for (k = 1; k <= level; k++) {
        s = t[k] + 0
        printf "%.10g,%.10g,%.10g,%.10g,%s,%s\n", s, s * f[1], s * f[2], s * f[3], u[k], support_total(k)
    }
}

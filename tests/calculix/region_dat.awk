# region_dat.awk — the patch-averaged displacement of each site of a
# region deck (organ_deck --sites) under its three unit forces, as CSV
# (site,a,b,x,y,z,case,dx,dy,dz: site k's chart coordinates (a, b) and
# surface point, case fx / fy / fz, d = sum_i w_i u_i over the site's
# patch nodes: the work-conjugate of the probe's force, mm per N).
#
#   awk -f region_dat.awk DECK.inp DECK.dat > level.csv
#
# DECK.inp gives "** SITE k a b x y z area", "** PATCH k node weight" and
# "** STEP n s<k>f<x> fx fy fz" comments; DECK.dat one "displacements
# (vx,vy,vz) for set OUT" block per step.  Exits 1 with a message when a
# step or a patch node is missing or a value is not a number.

FNR == 1 { file++ }

file == 1 && $1 == "**" && $2 == "SITE" { sites++; site[$3] = $4 "," $5 "," $6 "," $7 "," $8; next }
file == 1 && $1 == "**" && $2 == "PATCH" {
    np[$3]++
    pnode[$3, np[$3]] = $4
    pw[$3, np[$3]] = $5
    next
}
file == 1 && $1 == "**" && $2 == "STEP" {
    steps++
    if (match($4, /^s[0-9]+f[xyz]$/) == 0) {
        printf "region_dat: step %s: case %s is not s<k>f<x>\n", $3, $4 > "/dev/stderr"; bad = 1
    }
    k = substr($4, 2, length($4) - 3)
    step_site[$3] = k
    step_case[$3] = substr($4, length($4) - 1)
    next
}
file == 1 { next }

/displacements \(vx,vy,vz\) for set OUT/ { block++; inside = 1; next }
/^ *[a-z]/ { inside = 0; next }

inside && NF == 4 {
    for (c = 2; c <= 4; c++) {
        if ($c !~ /^-?[0-9]\.[0-9]+E[-+][0-9]+$/) {
            printf "%s:%d: field %d is not a number: %s\n", FILENAME, FNR, c, $c > "/dev/stderr"; bad = 1
        }
    }
    u[block, $1, 1] = $2; u[block, $1, 2] = $3; u[block, $1, 3] = $4
    seen[block, $1] = 1
}

END {
    if (sites == 0 || steps != 3 * sites || block != steps) {
        printf "region_dat: %d sites, %d steps in the deck, %d displacement blocks\n", sites, steps, block > "/dev/stderr"
        exit 1
    }
    print "site,a,b,x,y,z,case,dx,dy,dz"
    for (s = 1; s <= steps; s++) {
        k = step_site[s]
        d[1] = d[2] = d[3] = 0
        for (j = 1; j <= np[k]; j++) {
            node = pnode[k, j]
            if (!((s, node) in seen)) { printf "region_dat: step %d lacks node %s\n", s, node > "/dev/stderr"; bad = 1; continue }
            for (c = 1; c <= 3; c++) d[c] += pw[k, j] * u[s, node, c]
        }
        split(site[k], g, ",")
        printf "%d,%.17g,%.17g,%.17g,%.17g,%.17g,%s,%.10g,%.10g,%.10g\n", k, g[1], g[2], g[3], g[4], g[5], step_case[s], d[1], d[2], d[3]
    }
    if (bad) exit 1
}

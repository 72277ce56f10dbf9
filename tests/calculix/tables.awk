# tables.awk — Markdown tables for docs/calculix-reference.md from the
# committed run log and node-61 results:
#   1. every C3D20R patch-load run at nu = 0.49, by mesh (in-plane and
#      through-thickness convergence)
#   2. the Poisson-ratio sweep, C3D20R and C3D20, on the sweep's mesh
#   3. u61(nu = 0.499) / u61(nu = 0.49) per element and mesh (locking)
#   4. the point-load runs (force on node 61 alone, as in the seed)
#   5. the largest reaction imbalance |r + f| over all runs and cases
#
#   awk -v div=40 -v layers=4 -f tables.awk DATA/block48_runs.csv \
#       DATA/block48_node61.csv DATA/block48_reactions.csv

BEGIN { FS = "," }
FNR == 1 { file++; next }

file == 1 { cost[$1] = $11 " s, " $12 " MB"; next }

file == 2 {
    k = $1
    if (!(k in seen)) { seen[k] = 1; run[++runs] = k; el[k] = $2; nu[k] = $3; dv[k] = $4; ly[k] = $5; ld[k] = $6 }
    u61[k, $7] = $7 == "fx" ? $8 : $7 == "fy" ? $9 : $10
    next
}

file == 3 {
    rows++
    for (c = 0; c < 3; c++) {
        d = $(3 + c) + $(6 + c)
        if (d < 0) d = -d
        if (d >= worst) { worst = d; where = $1 " " $2 }
    }
}

END {
    print "| mesh (in plane x layers) | h in plane (mm) | layer (mm) | node 61 fx: ux (mm) | node 61 fz: uz (mm) | cost |"
    print "|---|---|---|---|---|---|"
    n = select("patch", "C3D20R", 0, 0)
    for (i = 1; i <= n; i++) {
        k = pick[i]
        printf "| %dx%dx%d | %g | %g | %.6f | %.6f | %s |\n", dv[k], dv[k], ly[k], 48 / dv[k], 6 / ly[k], \
            u61[k, "fx"], u61[k, "fz"], cost[k]
    }
    print ""
    print "| nu | element | node 61 fx: ux (mm) | node 61 fy: uy (mm) | node 61 fz: uz (mm) |"
    print "|---|---|---|---|---|"
    for (pass = 1; pass <= 2; pass++) {
        n = select("patch", pass == 1 ? "C3D20R" : "C3D20", div, layers)
        for (i = 1; i <= n; i++) {
            k = pick[i]
            printf "| %s | %s | %.6f | %.6f | %.6f |\n", nu[k], el[k], u61[k, "fx"], u61[k, "fy"], u61[k, "fz"]
        }
    }
    print ""
    print "| element, mesh | fx: ux(0.499) / ux(0.49) at node 61 | fz: uz(0.499) / uz(0.49) at node 61 |"
    print "|---|---|---|"
    for (pass = 1; pass <= 2; pass++) {
        e = pass == 1 ? "C3D20R" : "C3D20"
        for (r = 1; r <= runs; r++) {
            a = run[r]
            if (ld[a] != "patch" || el[a] != e || nu[a] != 0.49 || !((a, "fx") in u61)) continue
            for (s = 1; s <= runs; s++) {
                b = run[s]
                if (ld[b] == "patch" && el[b] == e && nu[b] == 0.499 && dv[b] == dv[a] && ly[b] == ly[a])
                    printf "| %s, %dx%dx%d | %.4f | %.4f |\n", e, dv[a], dv[a], ly[a], \
                        u61[b, "fx"] / u61[a, "fx"], u61[b, "fz"] / u61[a, "fz"]
            }
        }
    }
    print ""
    print "| point load on node 61, mesh | node 61 fx: ux (mm) | node 61 fz: uz (mm) |"
    print "|---|---|---|"
    n = select("point", "C3D20R", 0, 0)
    for (i = 1; i <= n; i++) {
        k = pick[i]
        printf "| %dx%dx%d | %.6f | %.6f |\n", dv[k], dv[k], ly[k], u61[k, "fx"], u61[k, "fz"]
    }
    print ""
    printf "Largest reaction imbalance |r + f| over %d run/case rows: %.3g N (%s).\n", rows, worst, where
}

# Fills pick[1..n] with the three-case runs of load form lf and element e
# (on mesh d x d x l when d > 0; else nu = 0.49 on every mesh), sorted by
# mesh then nu; returns n.
function select(lf, e, d, l,    r, k, i, n) {
    n = 0
    for (r = 1; r <= runs; r++) {
        k = run[r]
        if (ld[k] != lf || el[k] != e || !((k, "fx") in u61)) continue
        if (d > 0 && (dv[k] != d || ly[k] != l)) continue
        if (d == 0 && nu[k] != 0.49) continue
        for (i = ++n; i > 1 && later(pick[i - 1], k); i--) pick[i] = pick[i - 1]
        pick[i] = k
    }
    return n
}

function later(a, b) {
    if (dv[a] != dv[b]) return dv[a] + 0 > dv[b] + 0
    if (ly[a] != ly[b]) return ly[a] + 0 > ly[b] + 0
    return nu[a] + 0 > nu[b] + 0
}

# nl_tables.awk — Markdown tables of the large-deformation block48 reference
# for docs/calculix-reference.md, from the committed data:
#   1. every NLGEOM run: mesh, cut, size, increments, cutbacks, Newton
#      iterations, the load reached, time and memory;
#   2. per material and path, node 61's displacement (the components the
#      path moves most) at the load factors FACTORS, one row per run;
#   3. the small-load runs against the linear runs of the same mesh.
#
#   awk -F, -v factors="0.1 0.5 0.9 1" -f nl_tables.awk DATA/block48_nl_runs.csv \
#       DATA/block48_nl_curves.csv DATA/block48_nl_linear.csv

FNR == 1 { file++; next }

file == 1 {
    r = $1; order[++runs] = r
    mat[r] = $2; el[r] = $3; path[r] = $4; dv[r] = $5; ly[r] = $6; sym[r] = $7
    dofs[r] = $10; inc[r] = $11; cut[r] = $12; its[r] = $13; reached[r] = $14; sec[r] = $16; mb[r] = $17
    next
}
file == 2 {
    k = ++levels[$1]; fac[$1, k] = $2; f[$1, k] = $3 "," $4 "," $5
    ux[$1, k] = $6; uz[$1, k] = $8
    next
}
file == 3 { lin[$1, $5, "x"] = $6; lin[$1, $5, "z"] = $8 }

function force(p,    s) {
    return p == "a" ? "(0, 0, -3)" : p == "b" ? "(1, 0, 0)" : p == "c" ? "(1, 0, -3)" : p
}

# node 61 of run r at load factor x: "ux / uz" (path c), "-uz" (a), "ux" (b)
function at(r, x,    k) {
    for (k = 1; k <= levels[r]; k++) {
        if (fac[r, k] + 0 == x + 0) {
            if (path[r] == "a") return sprintf("%.4f", -uz[r, k])
            if (path[r] == "b") return sprintf("%.4f", ux[r, k])
            return sprintf("%.4f / %.4f", ux[r, k], -uz[r, k])
        }
    }
    return "—"
}

END {
    print "| run | element | mesh (cut) | DOFs | increments | cutbacks | iterations | load reached | time (s) | memory (MB) |"
    print "|---|---|---|---|---|---|---|---|---|---|"
    for (i = 1; i <= runs; i++) {
        r = order[i]
        if (path[r] ~ /_s/) continue
        printf "| %s | %s | %dx%dx%d (%s) | %d | %d | %d | %d | %.4g | %s | %s |\n", r, el[r], dv[r], dv[r], ly[r], \
            sym[r] == "xy" ? "quarter" : sym[r] == "y" ? "half" : "whole", dofs[r], inc[r], cut[r], its[r], reached[r], sec[r], mb[r]
    }
    nf = split(factors, fx, " ")
    for (m = 1; m <= 2; m++) {
        mm = m == 1 ? "neohooke" : "svk"
        for (pp = 1; pp <= 3; pp++) {
            p = substr("abc", pp, 1)
            print ""
            printf "%s, path %s, F = %s N: node 61, %s (mm) at the load factor\n\n", mm == "svk" ? "St. Venant-Kirchhoff" : "neo-Hooke", \
                p, force(p), p == "a" ? "-uz" : p == "b" ? "ux" : "ux / -uz"
            printf "| run | element | mesh |"
            for (j = 1; j <= nf; j++) printf " %s |", fx[j]
            printf "\n|---|---|---|"
            for (j = 1; j <= nf; j++) printf "---|"
            printf "\n"
            for (i = 1; i <= runs; i++) {
                r = order[i]
                if (mat[r] != mm || path[r] != p) continue
                printf "| %s | %s | %dx%dx%d |", r, el[r], dv[r], dv[r], ly[r]
                for (j = 1; j <= nf; j++) printf " %s |", at(r, fx[j])
                printf "\n"
            }
        }
    }
    print ""
    print "| small-load run | force (N) | node 61 (mm) | linear, same mesh (mm) | relative difference |"
    print "|---|---|---|---|---|"
    for (i = 1; i <= runs; i++) {
        r = order[i]
        if (path[r] !~ /_s/) continue
        split(r, w, "_"); lr = "linear_" w[4] "_" el[r]
        split(f[r, 1], g, ",")
        wx = g[1] * lin[lr, "fx", "x"] - g[3] * lin[lr, "fz", "x"]
        wz = g[1] * lin[lr, "fx", "z"] - g[3] * lin[lr, "fz", "z"]
        d = sqrt((ux[r, 1] - wx) ^ 2 + (uz[r, 1] - wz) ^ 2) / sqrt(wx ^ 2 + wz ^ 2)
        printf "| %s | (%s) | (%.6g, %.6g) | (%.6g, %.6g) | %.2e |\n", r, f[r, 1], ux[r, 1], uz[r, 1], wx, wz, d
    }
}

# convergence.awk — the mesh-convergence table of the block48 reference from
# the committed data: per level, its size and cost (block48_runs.csv), the
# node-61 displacement along each load, and the RMS change over the 121
# nodes against the finest level (|u - u_finest| / |u_finest|, RMS).
#
#   awk [-v md=1] -f convergence.awk DATA/block48_runs.csv \
#       DATA/block48_{fx,fy,fz}_LEVEL.csv ...      (levels coarse to fine)
#
# Without md: a whitespace table for gnuplot (h in mm first); with md=1: a
# Markdown table for docs/calculix-reference.md.

BEGIN { FS = "," }
FNR == 1 { file++; next }

file == 1 { cost[$1] = $7 " " $8 " " $9 " " $11 " " $12; next }

FNR == 2 {
    n = split(FILENAME, p, "/"); name = p[n]; sub(/\.csv$/, "", name)
    split(name, q, "_"); c = q[2]; lv = q[3]
    if (!(lv in seen)) { seen[lv] = 1; order[++levels] = lv }
}
{ for (k = 1; k <= 3; k++) u[lv, c, $1, k] = $(4 + k) }

END {
    fine = order[levels]
    # component along the load: ux for fx, uy for fy, -uz for fz
    comp["fx"] = 1; comp["fy"] = 2; comp["fz"] = 3; sgn["fx"] = 1; sgn["fy"] = 1; sgn["fz"] = -1
    if (md) {
        print "| level | elements | nodes | free DOFs | node 61 fx: ux (mm) | node 61 fz: uz (mm) | RMS change vs " fine ": fx / fy / fz | node 61 change vs " fine ": fx / fz | run time (s) | peak memory (MB) |"
        print "|---|---|---|---|---|---|---|---|---|---|"
    } else {
        print "# h_mm u61_fx u61_fz u61_fx/finest u61_fz/finest rms_fx rms_fy rms_fz (%)"
    }
    for (l = 1; l <= levels; l++) {
        lv = order[l]
        split(cost[lv], s, " ")
        line = ""
        for (ci = 1; ci <= 3; ci++) {
            c = ci == 1 ? "fx" : ci == 2 ? "fy" : "fz"
            rms[c] = 100 * change(lv, fine, c, 0)
            n61[c] = 100 * change(lv, fine, c, 61)
        }
        a = u[lv, "fx", 61, 1]; b = u[lv, "fz", 61, 3]
        if (md) {
            printf "| %s | %s | %s | %s | %.6f | %.6f | %.3f / %.3f / %.3f %% | %.3f / %.3f %% | %s | %s |\n", \
                lv, s[1], s[2], s[3], a, b, rms["fx"], rms["fy"], rms["fz"], n61["fx"], n61["fz"], s[4], s[5]
        } else {
            h = substr(lv, 2)
            printf "%s %.7g %.7g %.7g %.7g %.5g %.5g %.5g\n", h, a, -b, a / u[fine, "fx", 61, 1], \
                b / u[fine, "fz", 61, 3], rms["fx"], rms["fy"], rms["fz"]
        }
    }
}

# relative change of level a against level b for case c: RMS over all nodes
# (node 0) or at one node
function change(a, b, c, node,    n, k, d, num, den) {
    for (n = 1; n <= 121; n++) {
        if (node && n != node) continue
        for (k = 1; k <= 3; k++) {
            d = u[a, c, n, k] - u[b, c, n, k]
            num += d * d
            den += u[b, c, n, k] * u[b, c, n, k]
        }
    }
    return sqrt(num / den)
}

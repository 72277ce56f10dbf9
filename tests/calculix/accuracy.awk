# accuracy.awk — the accuracy-per-cost table of block48's C3D20R meshes
# (docs/calculix-reference.md, "Accuracy per second"): every ν = 0.49 patch
# run's node 61 against the reference values, with its run time and memory.
#
#   awk -F, -f accuracy.awk DATA/block48_node61_reference.csv \
#       DATA/block48_runs.csv DATA/block48_node61.csv

FNR == 1 { file++; next }
file == 1 { ref[$1] = $3; next }
file == 2 {
    if ($2 == "C3D20R" && $3 == 0.49 && $6 == "patch" && !($1 in sec)) {
        order[++n] = $1; mesh[$1] = $4 "x" $4 "x" $5; dofs[$1] = $9; sec[$1] = $11; mb[$1] = $12
    }
    next
}
$2 == "C3D20R" && $3 == 0.49 && $6 == "patch" {
    if ($7 == "fx") ex[$1] = 100 * ($8 - ref["fx"]) / ref["fx"]
    if ($7 == "fz") ez[$1] = 100 * ($10 - ref["fz"]) / ref["fz"]
}
function abs(x) { return x < 0 ? -x : x }
END {
    print "| mesh | DOFs | fx error | fz error | worst | time, 3 cases (s) | memory (MB) |"
    print "|---|---|---|---|---|---|---|"
    for (i = 1; i <= n; i++) {
        r = order[i]
        w = abs(ex[r]) > abs(ez[r]) ? abs(ex[r]) : abs(ez[r])
        printf "| %s | %d | %+.3f %% | %+.3f %% | %.3f %% | %.1f | %d |\n", mesh[r], dofs[r], ex[r], ez[r], w, sec[r], mb[r]
    }
}

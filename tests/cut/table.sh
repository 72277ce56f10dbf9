#!/bin/sh
# table.sh DATADIR — the refinement table of docs/cutting.md (Markdown on
# stdout) from run_validation.sh's data: mouth COD (z = 10) of every
# CalculiX level and meshless grid (rpim-galerkin, efg-galerkin), and each meshless grid against the
# finest CalculiX level: the mouth COD difference and the largest COD
# difference at z = 6.25, 7.5, 8.75, 10 (nodes of every level), both
# relative to that level's mouth COD.
set -eu
data=$1
ref=$(grep '^ccx,' "$data/runs.csv" | tail -1 | cut -d, -f2)
echo "| solve | level | mouth COD (mm) | vs CalculiX n=$ref: mouth | largest along the slit | time (s) |"
echo "|---|---|---|---|---|---|"
grep -v '^kind' "$data/runs.csv" | while IFS=, read -r kind a b c d e; do
    if [ "$kind" = ccx ]; then
        h=$(awk -v n="$a" 'BEGIN { printf "%.4g", 10 / n }')
        printf '| CalculiX C3D20R, crack by duplicated nodes | n = %s (h = %s mm) | %.4f | | | %.1f |\n' "$a" "$h" "$b" "$c"
    else
        lvl="$a,$b,$c" cod=$d t=$e nx=$a
        if [ "$kind" = efg ]; then name=efg-galerkin file=efg; else name=rpim-galerkin file=meshless; fi
        awk -F, -v lvl="$lvl" -v cod="$cod" -v t="$t" -v name="$name" '
            FNR == 1 { f++; next }
            f == 1 { r[$1 + 0] = $2 }
            f == 2 { m[$1 + 0] = $2 }
            END {
                zs[1] = 6.25; zs[2] = 7.5; zs[3] = 8.75; zs[4] = 10
                worst = 0
                for (k = 1; k <= 4; ++k) {
                    d = m[zs[k]] - r[zs[k]]; if (d < 0) d = -d
                    if (d > worst) worst = d
                }
                printf "| meshless %s with the cut | %s nodes | %.4f | %+.1f %% | %.1f %% | %.1f |\n",
                    name, lvl, cod, 100 * (m[10] - r[10]) / r[10], 100 * worst / r[10], t
            }' "$data/ccx_n$ref.csv" "$data/${file}_$nx.csv"
    fi
done

# nl_stop_table.awk — the stop study's table for docs/calculix-reference.md
# ("Why the fine levels stop"), markdown, one row per run:
#   awk -F, -f nl_stop_table.awk block48_nl_stop.csv block48_nl_stop_field.csv
FNR == 1 { file++; next }
file == 1 { run[++n] = $1; row[$1] = $2 " | " $6 " / " 2.4 / $4 " | " $8 " | " $7 " | " $12 " | " $10 " | " int($13 + 0.5); next }
$3 == 1 && $2 + 0 > 0.699 && $2 + 0 < 0.701 { at07[$1] = sprintf("%.4f | %.3f", -$4, $6) }
$3 == 0 { last[$1] = sprintf("%.4g* | %.4f | %.3f", $2, -$4, $6) }
END {
    print "| run | element | under the patch / far field (mm) | DOFs | smallest increment (of a level) | reached | cutbacks | s | −u_z61 at 0.7 | least stretch at 0.7 | last attempt | −u_z61 | least stretch |"
    print "|---|---|---|---|---|---|---|---|---|---|---|---|---|"
    for (k = 1; k <= n; ++k) {
        r = run[k]
        printf "| %s | %s | %s | %s |\n", r, row[r], (r in at07) ? at07[r] : "— | —", (r in last) ? last[r] : "— | — | —"
    }
}

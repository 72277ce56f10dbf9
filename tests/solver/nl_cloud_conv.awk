# nl_cloud_conv.awk — the meshless side's own convergence at large load
# (docs/validation.md §12.1): node 61's displacement length on the two
# finest clouds of block48_nl_meshless.csv, level by level.
#
#   awk -F, -v coarse=NAME -v fine=NAME -v bound=B [-v maxf=F] [-v shift=S]
#       -f nl_cloud_conv.awk block48_nl_meshless.csv
#
# Prints the largest |u_fine - u_coarse| / |u_fine| over the levels up to
# maxf (default 1) and exits 1 when it exceeds bound, or when a level of the
# fine cloud is missing (or failed) on the coarse one, or no level is there.
# shift (the check's self-test) first moves the fine cloud away from the
# coarse one by shift x |u_fine| at every level.
FNR == 1 { next }
$1 == coarse && $8 != "failed" { uc[sprintf("%.6f", $4)] = sqrt($8 ^ 2 + $9 ^ 2 + $10 ^ 2) }
$1 == fine && $8 != "failed" { uf[sprintf("%.6f", $4)] = sqrt($8 ^ 2 + $9 ^ 2 + $10 ^ 2) }
END {
    if (maxf == "") maxf = 1
    worst = -1
    for (f in uf) {
        if (f + 0 > maxf + 1e-9) continue
        if (!(f in uc)) { print "nl_cloud_conv: level " f " of " fine " missing on " coarse > "/dev/stderr"; exit 1 }
        d = uf[f] - uc[f]
        if (shift != "") d += (d < 0 ? -1 : 1) * shift * uf[f]
        r = (d < 0 ? -d : d) / uf[f]
        if (r > worst) { worst = r; at = f }
    }
    if (worst < 0) { print "nl_cloud_conv: no level of " fine > "/dev/stderr"; exit 1 }
    printf "%s against %s: largest change %.2f %% (at load factor %g)\n", fine, coarse, 100 * worst, at
    exit worst > bound
}

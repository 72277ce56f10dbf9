# nl_cloud_conv.awk — the meshless side's own convergence at large load
# (docs/validation.md §12.1): node 61's u_z on two graded clouds of
# block48_nl_sensitivity.csv (make nonlinear-sensitivity; rows
# variant,grid,factor,uz,seconds, variant "base" the default settings),
# level by level.
#
#   awk -F, -v coarse=GRID -v fine=GRID -v bound=B [-v shift=S]
#       -f nl_cloud_conv.awk block48_nl_sensitivity.csv
#
# Prints the largest |u_fine - u_coarse| / |u_fine| over the fine cloud's
# levels and exits 1 when it exceeds bound, or when a level of the fine
# cloud is missing on the coarse one, or the fine cloud is not there.
# shift (the check's self-test) first moves the fine cloud away from the
# coarse one by shift x |u_fine| at every level.
FNR == 1 { next }
$1 == "base" && $2 == coarse { uc[$3] = $4 < 0 ? -$4 : $4 }
$1 == "base" && $2 == fine { uf[$3] = $4 < 0 ? -$4 : $4 }
END {
    worst = -1
    for (f in uf) {
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

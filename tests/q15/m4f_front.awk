# m4f_front.awk — the error/time Pareto front of a sweep CSV (tissuefit
# sweep --csv) in M4F microseconds (upper bound) instead of the sweep's
# native nanoseconds: forward float32 candidates of the scene's outputs that
# no other is at least as fast and as accurate as, and better in one.
# Prints "model | M4F us | held-out max mm | % of PEAK" by time (-v PEAK=mm,
# the scene's largest displacement).  Used by make q15-study for
# docs/tradeoff.md §5.
BEGIN { FS = "," }
NR > 1 && $5 == "float32" && $15 == "mm" && $1 == "scene" && $9 != "nan" {
    n++; model[n] = $3; us[n] = $9 + 0; err[n] = $13 + 0
}
END {
    for (i = 1; i <= n; i++) {
        front = 1
        for (k = 1; k <= n && front; k++)
            if (k != i && us[k] <= us[i] && err[k] <= err[i] && (us[k] < us[i] || err[k] < err[i]))
                front = 0
        if (front) printf "%09.2f| %s | %.2f | %.3g mm | %.2f %%\n", us[i], model[i], us[i], err[i], 100 * err[i] / PEAK
    }
}

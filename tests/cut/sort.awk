# sort.awk — sort(a, n): a[1..n] ascending as numbers, for the awk scripts
# of tests/cut (mawk has no asort).  Load with -f sort.awk before them.
function sort(a, n,    i, j, t) {    # insertion sort
    for (i = 2; i <= n; ++i) {
        t = a[i]
        for (j = i - 1; j >= 1 && a[j] + 0 > t + 0; --j) a[j + 1] = a[j]
        a[j + 1] = t
    }
}

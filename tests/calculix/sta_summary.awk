# sta_summary.awk — CalculiX's increment log (DECK.sta) of a one-step run as
# one CSV fragment: increments,cutbacks,iterations,reached
#   increments  converged increments
#   cutbacks    attempts that did not converge (marked U) and were retried
#               with a smaller increment
#   iterations  Newton iterations over all attempts (one factorisation each)
#   reached     step time (load factor) of the last converged increment
#
#   awk -f sta_summary.awk DECK.sta

NR <= 2 { next }   # title and column heads
NF == 7 && $3 ~ /U$/ { cut++; it += $4; next }
NF == 7 { inc++; it += $4; reached = $6; next }
{ printf "sta_summary: %s:%d: unexpected line: %s\n", FILENAME, FNR, $0 > "/dev/stderr"; bad = 1 }
END {
    if (bad || inc == 0) { if (!bad) print "sta_summary: " FILENAME ": no converged increment" > "/dev/stderr"; exit 1 }
    printf "%d,%d,%d,%.10g\n", inc, cut, it, reached
}

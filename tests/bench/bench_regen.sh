#!/bin/sh
# bench_regen.sh TISSUEFIT RUNS SCENE... — the time to regenerate each shipped
# header, split as `tissuefit fit` reports it (issue 14 acceptance 5): solver
# setup (assembly, factorisation), load-case solves, family fits, and the
# header (selection, golden vectors, writing).  Medians of RUNS runs; printed,
# never asserted.
set -eu
tool=$1 runs=$2
shift 2
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
printf '%-24s %9s %9s %9s %9s %9s  (median of %s runs, s)\n' scene setup solves fits header total "$runs"
for scene in "$@"; do
    : > "$tmp/times"
    i=0
    while [ "$i" -lt "$runs" ]; do
        if ! "$tool" fit "$scene" -o "$tmp/h.h" 2> "$tmp/log" > /dev/null; then
            echo "bench-regen: $scene: tissuefit fit failed:" >&2
            tail -5 "$tmp/log" >&2
            exit 1
        fi
        line=$(grep '^fit: time: ' "$tmp/log") || {
            echo "bench-regen: $scene: no 'fit: time:' line in the tool's output" >&2
            exit 1
        }
        echo "$line" | awk '{print $4, $7, $10, $13}' >> "$tmp/times"
        i=$((i + 1))
    done
    # median per column (each column sorted on its own)
    med() { cut -d' ' -f"$1" "$tmp/times" | sort -g | awk '{v[NR] = $1} END {print v[int((NR + 1) / 2)]}'; }
    s=$(med 1) c=$(med 2) f=$(med 3) h=$(med 4)
    awk -v n="$(basename "$scene" .yaml)" -v s="$s" -v c="$c" -v f="$f" -v h="$h" \
        'BEGIN {printf "%-24s %9.3f %9.3f %9.3f %9.3f %9.3f\n", n, s, c, f, h, s + c + f + h}'
done

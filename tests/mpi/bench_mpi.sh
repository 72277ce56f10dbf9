#!/bin/sh
# bench_mpi.sh SERIAL MPI SCENE [--set ...] — wall time of `fit` on SCENE:
# the serial tool, and tissuefit-mpi on 1 and 2 ranks, each rank with one
# OpenMP thread (OMP_NUM_THREADS=1), plus the serial tool with two threads
# for comparison; REPS runs of each (default 3), interleaved, medians
# printed, and the speed-up of 2 ranks against 1.  The load average before
# and after is printed: on a shared machine it is part of the result.
# Extra arguments go to every fit.  Numbers are printed, never asserted.
set -u
serial=$1 mpi=$2 scene=$3
shift 3
reps=${REPS:-3}
mpirun=${MPIRUN:-mpirun}
if [ "$(id -u)" = 0 ]; then
    mpirun="$mpirun --allow-run-as-root"
fi
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
name=$(basename "$scene" .yaml)

# run LABEL THREADS COMMAND...: appends the wall time to $tmp/LABEL
run() {
    label=$1 threads=$2
    shift 2
    mkdir -p "$tmp/$label.out"
    start=$(date +%s.%N)
    if ! OMP_NUM_THREADS=$threads "$@" -o "$tmp/$label.out/$name.h" 2>"$tmp/$label.err"; then
        echo "bench-mpi: $label failed:"; tail -5 "$tmp/$label.err"; exit 1
    fi
    awk -v a="$(date +%s.%N)" -v b="$start" 'BEGIN {print a - b}' >>"$tmp/$label"
}

median() { sort -g "$1" | awk '{v[NR] = $1} END {print (NR % 2) ? v[(NR + 1) / 2] : (v[NR / 2] + v[NR / 2 + 1]) / 2}'; }

echo "load average before: $(cut -d' ' -f1-3 /proc/loadavg) on $(nproc) cores"
for r in $(seq "$reps"); do
    run serial-1t 1 "$serial" fit "$scene" "$@"
    run ranks-1 1 $mpirun -n 1 "$mpi" fit "$scene" "$@"
    run ranks-2 1 $mpirun -n 2 "$mpi" fit "$scene" "$@"
    run serial-2t 2 "$serial" fit "$scene" "$@"
done
echo "load average after:  $(cut -d' ' -f1-3 /proc/loadavg)"
grep -h "solving all" "$tmp/serial-1t.err" | head -1 | sed 's/^fit: /cases: /'
grep -h "^dist:" "$tmp/ranks-2.err" | tail -1 | sed 's/^/last 2-rank run: /'
same=yes
for l in ranks-1 ranks-2 serial-2t; do
    cmp -s "$tmp/serial-1t.out/$name.h" "$tmp/$l.out/$name.h" || same=no
done
s1=$(median "$tmp/serial-1t") r1=$(median "$tmp/ranks-1") r2=$(median "$tmp/ranks-2")
s2=$(median "$tmp/serial-2t")
printf '%-44s %8.2f s\n' "tissuefit fit, 1 thread (median of $reps)" "$s1" \
    "mpirun -n 1 tissuefit-mpi fit, 1 thread" "$r1" \
    "mpirun -n 2 tissuefit-mpi fit, 1 thread each" "$r2" \
    "tissuefit fit, 2 threads" "$s2"
awk -v s1="$s1" -v r1="$r1" -v r2="$r2" -v s2="$s2" 'BEGIN {
    printf "speed-up, 2 ranks against 1: %.2f (against the serial tool: %.2f; ", r1 / r2, s1 / r2
    printf "the serial tool on 2 threads: %.2f)\n", s1 / s2 }'
echo "headers byte-identical in every run: $same"

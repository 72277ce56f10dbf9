#!/bin/sh
# regenerate.sh TOOL SCENE OUTDIR "THREADS" [FIT OPTION...] — check-coeffs
# for one shipped header: SCENE fitted once per thread count of THREADS
# (all at once, OpenMP threads waiting passively), each into OUTDIR/tN/;
# both files of every run must equal the committed coeffs/NAME.h and
# coeffs/NAME_golden.h byte for byte, and the golden file must pair with
# its header (the CRC it names; CC, with its flags, compiles the pair).
# Prints one result line; exit 1 naming the first difference.
set -eu
tool=$1 scene=$2 out=$3 threads=$4
shift 4
n=$(basename "$scene" .yaml)
pids=""
for t in $threads; do
    mkdir -p "$out/t$t"
    OMP_WAIT_POLICY=passive OMP_NUM_THREADS=$t "$tool" -q fit "$scene" -o "$out/t$t/$n.h" "$@" &
    pids="$pids $!"
done
for p in $pids; do wait "$p"; done
for t in $threads; do
    for f in "$n.h" "${n}_golden.h"; do
        if ! cmp -s "$out/t$t/$f" "coeffs/$f"; then
            echo "coeffs/$f differs from its regeneration with $t thread(s): run make coeffs"
            diff "$out/t$t/$f" "coeffs/$f" | head -5
            exit 1
        fi
    done
done
printf '#include "%s_golden.h"\n' "$n" | ${CC:-gcc} -Itarget/include -Icoeffs \
    -fsyntax-only -x c - || { echo "coeffs/${n}_golden.h does not pair with coeffs/$n.h"; exit 1; }
echo "ok: coeffs/$n.h: identical to its regeneration with $(echo $threads | sed 's/ / and /g') thread(s); ${n}_golden.h has the CRC it names"

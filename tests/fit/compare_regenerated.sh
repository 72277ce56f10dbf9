#!/bin/sh
# compare_regenerated.sh NAME DIR "THREADS" [FROM] — check-coeffs for one
# shipped header: FROM/NAME.h and NAME_golden.h (FROM: coeffs, or the
# folder of a committed test header) as fitted again with each thread
# count of THREADS (DIR/tN/, coeffs/coeffs.mk's rules) must equal the
# committed files byte for byte, and the golden file must pair with its
# header (the CRC it names; CC, with its flags, compiles the pair).
# Prints one result line; exit 1 naming the first difference.
set -eu
n=$1 dir=$2 threads=$3 from=${4:-coeffs}
for t in $threads; do
    for f in "$n.h" "${n}_golden.h"; do
        if ! cmp -s "$dir/t$t/$f" "$from/$f"; then
            echo "$from/$f differs from its regeneration with $t thread(s): run make coeffs"
            diff "$dir/t$t/$f" "$from/$f" | head -5
            exit 1
        fi
    done
done
printf '#include "%s_golden.h"\n' "$n" | ${CC:-gcc} -Itarget/include -I"$from" \
    -fsyntax-only -x c - || { echo "$from/${n}_golden.h does not pair with $from/$n.h"; exit 1; }
echo "ok: $from/$n.h: identical to its regeneration with $(echo $threads | sed 's/ / and /g') thread(s); ${n}_golden.h has the CRC it names"

#!/bin/sh
# compare_selftest.sh TISSUEFIT COMPARE — the CalculiX comparison run on a
# reference made by tissuefit itself (the 21 x 21 x 5 solution written in
# the agreed CalculiX format), so its reading, node matching and checks
# are exercised before and whatever the real data.
set -u
tool=$1 compare=$2
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
fails=0
printf 'case,level,file\n' >"$tmp/block48_reference.csv"
for c in fx:1,0,0 fy:0,1,0 fz:0,0,-1; do
    name=${c%%:*} force=${c#*:}
    "$tool" -q solve tests/solver/block48_seed.yaml --set geometry.grid=21,21,5 --set contact.0.node=221 \
        --force "$force" -o "$tmp/all.csv" || exit 1
    # the 121 nodes of the 11 x 11 grid on top, numbered N = i + 11 j + 1
    awk -F, 'NR == 1 { print; next }
             $4 == 6 { i = $2 / 4.8; j = $3 / 4.8
                       if (i - int(i + 0.5) < 1e-9 && int(i + 0.5) - i < 1e-9 &&
                           j - int(j + 0.5) < 1e-9 && int(j + 0.5) - j < 1e-9)
                           printf "%d,%s,%s,%s,%s,%s,%s\n", int(i + 0.5) + 11 * int(j + 0.5) + 1,
                                  $2, $3, $4, $5, $6, $7 }' "$tmp/all.csv" |
        sort -t, -k1,1n >"$tmp/block48_${name}_self.csv"
    printf '%s,self,block48_%s_self.csv\n' "$name" "$name" >>"$tmp/block48_reference.csv"
done
if ! "$compare" --data "$tmp" --levels "11,11,3;21,21,5" >"$tmp/out"; then
    echo "FAIL: the comparison rejects its own solution"; cat "$tmp/out"; fails=$((fails + 1))
fi
if ! awk -F, 'NR > 1 && $1 == 1 && $11 != 0 { bad = 1 } END { exit bad }' "$tmp/out"; then
    echo "FAIL: the same solution does not compare equal"; fails=$((fails + 1))
fi
if ! awk -F, 'NR > 1 && $1 == 0 && $11 > 0.05 { seen = 1 } END { exit !seen }' "$tmp/out"; then
    echo "FAIL: the coarse grid does not differ from the fine one"; fails=$((fails + 1))
fi
# rejects WHAT PATTERN ARGS...: the comparison fails (exit 1, not a usage
# error) and says PATTERN, so it is rejected for the reason meant.
rejects() {
    what=$1 pattern=$2
    shift 2
    "$compare" "$@" >"$tmp/rej.out" 2>"$tmp/rej.err"
    rc=$?
    if [ "$rc" != 1 ] || ! grep -q -e "$pattern" "$tmp/rej.err"; then
        echo "FAIL: $what: exit $rc (expected 1) and stderr without '$pattern':"
        cat "$tmp/rej.err"; fails=$((fails + 1))
    else
        echo "rejected as it must be: $what ($(head -1 "$tmp/rej.err"))"
    fi
}
# a reference the coarse grid matches better than the fine one must fail
rejects "a growing error" "the RMS error grows from level 0 to 1" \
    --data "$tmp" --levels "21,21,5;11,11,3"
rejects "a missing data directory" "$tmp/none/block48_reference.csv: No such file" --data "$tmp/none"
sed -i '$d' "$tmp/block48_fz_self.csv"
rejects "a file with 120 rows" "block48_fz_self.csv: expected the header node,x,y,z,ux,uy,uz and 121 rows" \
    --data "$tmp" --levels "21,21,5"
echo "comparison self-test: $fails failure(s)"
[ "$fails" = 0 ]

#!/bin/sh
# check_deck.sh DECK_TOOL — the deck writer's contract, without CalculiX:
# node and DOF counts from an independent count of a 20-node-hexahedron
# grid, the 121 output nodes, the nodal loads of each step summing to its
# unit force, and bad arguments refused (exit 2, nothing written).
set -u
tool=$1
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
fails=0
fail() { echo "FAIL: $*"; fails=$((fails + 1)); }

n=20 l=2
"$tool" --divisions $n --layers $l > "$tmp/d.inp" || fail "deck writer exited $?"
# corners, midsides of x and y edges, midsides of vertical edges; the
# clamped ones are those on the four lateral faces
nodes=$(( (n + 1) * (n + 1) * (l + 1) + 2 * n * (n + 1) * (l + 1) + (n + 1) * (n + 1) * l ))
inner=$(( (n - 1) * (n - 1) * (l + 1) + 2 * (n - 1) * n * (l + 1) + (n - 1) * (n - 1) * l ))
want="$((n * n * l)) $nodes $((3 * inner))"
got=$(awk '$1 == "**" && $2 == "SIZE" { print $3, $4, $5 }' "$tmp/d.inp")
[ "$got" = "$want" ] || fail "SIZE is '$got', expected '$want'"
got=$(awk -F, '/^\*NODE,/ { on = 1; next } /^\*/ { on = 0 } on { c++ } END { print c + 0 }' "$tmp/d.inp")
[ "$got" = "$nodes" ] || fail "$got *NODE lines, expected $nodes"
got=$(grep -c '^\*\* OUT ' "$tmp/d.inp")
[ "$got" = 121 ] || fail "$got output nodes, expected 121"

# per step: the force of its "** STEP" line against the sum of its *CLOAD lines
awk -F, '
    $0 ~ /^\*\* STEP / { split($0, w, " "); want[w[3]] = w[5] " " w[6] " " w[7]; next }
    /^\*STEP/ { s++; next }
    /^\*CLOAD/ { on = 1; next }
    /^\*/ { on = 0 }
    on { sum[s, $2] += $3 }
    END {
        for (k = 1; k <= s; k++) {
            split(want[k], f, " ")
            for (d = 1; d <= 3; d++) {
                e = sum[k, d] - f[d]; if (e < 0) e = -e
                if (e > 1e-12) { printf "FAIL: step %d: nodal loads along %d sum to %.15g, not %s\n", k, d, sum[k, d], f[d]; bad = 1 }
            }
        }
        if (s != 3) { print "FAIL: " s " steps, expected 3"; bad = 1 }
        exit bad
    }' "$tmp/d.inp" || fails=$((fails + 1))

for args in "--divisions 30 --layers 2" "--divisions 20 --layers 0" "--divisions 20 --layers 2 --nu 0.5" \
            "--divisions 20 --layers 2 --element C3D20H" "--divisions 20 --layers 2 --pressure" \
            "--divisions 20 --layers 2 --cases fz --pressure --point" "--divisions 20 --layers 2 --cases fw"; do
    # shellcheck disable=SC2086
    "$tool" $args > "$tmp/bad.inp" 2> "$tmp/err"
    st=$?
    [ "$st" = 2 ] || fail "'$args' exited $st, expected 2"
    [ -s "$tmp/bad.inp" ] && fail "'$args' wrote a deck"
done
[ "$fails" = 0 ] && echo "block48_deck: counts, output nodes, load sums and bad arguments ok"
[ "$fails" = 0 ]

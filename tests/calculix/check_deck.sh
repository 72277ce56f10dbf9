#!/bin/sh
# check_deck.sh DECK_TOOL — the deck writer's contract, without CalculiX:
# element, node and free-DOF counts against an independent count of a
# 20-node-hexahedron grid (whole box, half and quarter), the output points,
# each step's nodal loads summing to the meshed part's share of its force,
# the large-deformation cards and the neo-Hookean constants, and bad
# arguments refused (exit 2, nothing written).
set -u
tool=$1
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
fails=0
fail() { echo "FAIL: $*"; fails=$((fails + 1)); }

# nodes of a grid of a x b x c 20-node hexahedra: corners, then midsides of
# the edges along x, y and z
box_nodes() { echo $(( ($1 + 1) * ($2 + 1) * ($3 + 1) + $1 * ($2 + 1) * ($3 + 1) + ($1 + 1) * $2 * ($3 + 1) + ($1 + 1) * ($2 + 1) * $3 )); }
# nodes of one b x c face of such a grid (8-node quadrilaterals)
face_nodes() { echo $(( ($1 + 1) * ($2 + 1) + $1 * ($2 + 1) + ($1 + 1) * $2 )); }

# expect_size DECK ELEMENTS NODES DOFS
expect_size() {
    got=$(awk '$1 == "**" && $2 == "SIZE" { print $3, $4, $5 }' "$1")
    [ "$got" = "$2 $3 $4" ] || fail "$1: SIZE is '$got', expected '$2 $3 $4'"
    got=$(awk -F, '/^\*NODE,/ { on = 1; next } /^\*/ { on = 0 } on { c++ } END { print c + 0 }' "$1")
    [ "$got" = "$3" ] || fail "$1: $got *NODE lines, expected $3"
}

# expect_outputs DECK COUNT: OUT and MIRROR lines number the points 1..COUNT
# once each, and a mirror image lies at its source's position reflected
# about the patch centre (XC, YC) along the flipped axes, the sign of the
# displacement component normal to each flip reversed
expect_outputs() {
    awk -v want="$2" -v xc="$3" -v yc="$4" '
        $1 == "**" && $2 == "OUT" { seen[$3]++; x[$3] = $5; y[$3] = $6; n++ }
        $1 == "**" && $2 == "MIRROR" { seen[$3]++; src[$3] = $4; sx[$3] = $5; sy[$3] = $6; mx[$3] = $8; my[$3] = $9; n++
                                       if ($7 != 1 || $5 * $5 != 1 || $6 * $6 != 1) {
                                           print "FAIL: mirror point " $3 " has signs " $5 ", " $6 ", " $7; bad = 1 } }
        END {
            for (k = 1; k <= want; k++) if (seen[k] != 1) { print "FAIL: output point " k " listed " seen[k] + 0 " times"; bad = 1 }
            if (n != want) { print "FAIL: " n " output lines, expected " want; bad = 1 }
            for (k in src) {
                s = src[k]
                ex = sx[k] < 0 ? 2 * xc - x[s] : x[s]; ey = sy[k] < 0 ? 2 * yc - y[s] : y[s]
                if (!(s in x) || mx[k] != ex || my[k] != ey) { print "FAIL: mirror point " k " is not the image of " s; bad = 1 }
            }
            exit bad
        }' "$1" || fails=$((fails + 1))
}

# expect_loads DECK STEPS: per step, the sum of its *CLOAD lines against
# the force of its "** STEP" line times the "** SHARE" (1 without a cut)
expect_loads() {
    awk -F, -v steps="$2" '
        $0 ~ /^\*\* STEP / { split($0, w, " "); want[w[3]] = w[5] " " w[6] " " w[7]; next }
        $0 ~ /^\*\* SHARE / { split($0, w, " "); share = w[3]; next }
        /^\*STEP/ { s++; next }
        /^\*CLOAD/ { on = 1; next }
        /^\*/ { on = 0 }
        on { sum[s, $2] += $3 }
        END {
            if (share == "") share = 1
            for (k = 1; k <= s; k++) {
                split(want[k], f, " ")
                for (d = 1; d <= 3; d++) {
                    e = sum[k, d] - share * f[d]; if (e < 0) e = -e
                    if (e > 1e-12) { printf "FAIL: step %d: nodal loads along %d sum to %.15g, not %g x %s\n", k, d, sum[k, d], share, f[d]; bad = 1 }
                }
            }
            if (s != steps) { print "FAIL: " s " steps, expected " steps; bad = 1 }
            exit bad
        }' "$1" || fails=$((fails + 1))
}

deck() { out=$tmp/$1.inp; shift; "$tool" "$@" > "$out" || fail "deck writer exited $? for: $*"; }

# block48, whole box: N x N x L, the four lateral faces clamped
n=20 l=2
deck whole --divisions $n --layers $l
nodes=$(box_nodes $n $n $l)
clamped=$(( 4 * $(face_nodes $n $l) - 4 * (2 * l + 1) )) # four faces, four shared vertical edges
expect_size "$tmp/whole.inp" $((n * n * l)) "$nodes" $((3 * (nodes - clamped)))
expect_outputs "$tmp/whole.inp" 121 24 24
expect_loads "$tmp/whole.inp" 3

# block48, quarter (cut at x = 24 and y = 24): clamped x = 0 and y = 0
h=$((n / 2))
deck quarter --divisions $n --layers $l --symmetry xy --cases fz
nodes=$(box_nodes $h $h $l)
clamped=$(( 2 * $(face_nodes $h $l) - (2 * l + 1) ))
mirror=$(( 2 * ($(face_nodes $h $l) - (2 * l + 1)) )) # one DOF each, clamped edge excluded
expect_size "$tmp/quarter.inp" $((h * h * l)) "$nodes" $((3 * (nodes - clamped) - mirror))
expect_outputs "$tmp/quarter.inp" 121 24 24
expect_loads "$tmp/quarter.inp" 1

# block48, half (cut at y = 24), a large-deformation path
deck half --divisions $n --layers $l --symmetry y --force 1,0,-3 --material neohooke --nlgeom --increments 7
nodes=$(box_nodes $n $h $l)
clamped=$(( 2 * $(face_nodes $h $l) + $(face_nodes $n $l) - 2 * (2 * l + 1) ))
mirror=$(( $(face_nodes $n $l) - 2 * (2 * l + 1) ))
expect_size "$tmp/half.inp" $((n * h * l)) "$nodes" $((3 * (nodes - clamped) - mirror))
expect_outputs "$tmp/half.inp" 121 24 24
expect_loads "$tmp/half.inp" 1
# NLGEOM step, 7 printed load levels k/7, Newton tolerance, and the
# neo-Hookean constants C10 = mu/2, D1 = 2/K of E = 0.32, nu = 0.49
awk -F, '
    /^\*STEP, NLGEOM/ { nl = 1 }
    /^\*TIME POINTS, NAME=RAMP/ { on = 1; next }
    /^\*CONTROLS, PARAMETERS=FIELD/ { ctl = 1 }
    /^\*/ { on = 0 }
    on { pts++; d = $1 - pts / 7; if (d < 0) d = -d; if (d > 1e-12) bad_pt = 1 }
    /^\*HYPERELASTIC, NEO HOOKE/ { getline; c10 = $1; d1 = $2 }
    END {
        mu = 0.32 / (2 * 1.49); k = 0.32 / (3 * (1 - 0.98))
        e1 = c10 / (mu / 2) - 1; e2 = d1 / (2 / k) - 1
        if (!nl || !ctl || pts != 7 || bad_pt) { print "FAIL: NLGEOM step, control or the 7 load levels missing"; bad = 1 }
        if (e1 * e1 > 1e-24 || e2 * e2 > 1e-24) { print "FAIL: neo-Hooke C10 = " c10 ", D1 = " d1; bad = 1 }
        exit bad
    }' "$tmp/half.inp" || fails=$((fails + 1))

# the smallest increment, a fraction of a load level (default 1e-2,
# --min-fraction), and every node's displacement at the levels (--field)
deck minf --divisions $n --layers $l --symmetry xy --force 0,0,-3 --nlgeom --min-fraction 1e-4 --field
for f in half:7:0.01:0 minf:10:0.0001:1; do
    IFS=: read -r name k frac field <<EOT
$f
EOT
    awk -F, -v k="$k" -v frac="$frac" -v field="$field" '
        /^\*STATIC/ { getline; d = $3 / ($1 * frac) - 1; ok = $1 == $4 && d * d < 1e-20 && $1 * k > 0.999 && $1 * k < 1.001 }
        /^\*NODE FILE, TIME POINTS=RAMP/ { getline; nf = $1 == "U" }
        END { if (!ok || nf != field) { print "FAIL: " FILENAME ": smallest increment not " frac " of a level, or --field " (nf ? "written" : "missing"); exit 1 } }' \
        "$tmp/$name.inp" || fails=$((fails + 1))
done

# block48 graded, quarter: --grade 4:1 puts 4, 3, 2, 2 and then 1 elements
# in the 2.4 mm quanta from the patch outwards (0.7 times fewer per quantum,
# rounded up), so 17 per half side; layers thinnest at the top, each 1.6
# times the one above; the counts and loads as for any quarter, node 61 at
# the top centre, the element edges at the quanta and the layer ratio
h=17 l=4
deck graded --grade 4:1 --layers $l --layer-ratio 1.6 --symmetry xy --force 0,0,-3 --nlgeom
nodes=$(box_nodes $h $h $l)
clamped=$(( 2 * $(face_nodes $h $l) - (2 * l + 1) ))
mirror=$(( 2 * ($(face_nodes $h $l) - (2 * l + 1)) ))
expect_size "$tmp/graded.inp" $((h * h * l)) "$nodes" $((3 * (nodes - clamped) - mirror))
expect_outputs "$tmp/graded.inp" 121 24 24
expect_loads "$tmp/graded.inp" 1
grep -q '^\*\* OUT 61 [0-9]* 24 24 6$' "$tmp/graded.inp" || fail "graded: output point 61 is not (24, 24, 6)"
awk -F, '/^\*NODE,/ { on = 1; next } /^\*/ { on = 0 }
    on && $4 == 6 && $3 == 0 { x[$2] = 1 }
    on && $2 == 0 && $3 == 0 { z[$4] = 1 }
    END {
        want = "0 2.4 4.8 7.2 9.6 12 14.4 15.6 16.8 18 19.2 20 20.8 21.6 22.2 22.8 23.4 24"   # corners
        n = split(want, w, " "); for (k = 1; k <= n; k++) if (!(w[k] in x)) { print "FAIL: graded: no corner node at x = " w[k]; bad = 1 }
        for (v in x) c++
        if (c != 35) { print "FAIL: graded: " c " node positions along x, expected 35 (17 elements)"; bad = 1 }
        # corner z of 4 layers from the top, each 1.6 times the one below it
        t = 6 * 0.6 / (1.6 ^ 4 - 1); zz = 6
        for (k = 0; k < 4; k++) { zz -= t * 1.6 ^ k; hit = 0
            for (v in z) if ((v - zz) ^ 2 < 1e-20) hit = 1
            if (!hit) { print "FAIL: graded: no layer at z = " zz; bad = 1 } }
        exit bad }' "$tmp/graded.inp" || fails=$((fails + 1))

# beam40: 16k x 8k x L, clamped on x = 0 only; 9 x 5 outputs
n=16 l=8
deck beam --scene beam40 --divisions $n --layers $l --nu 0.45
nodes=$(box_nodes $n $((n / 2)) $l)
clamped=$(face_nodes $((n / 2)) $l)
expect_size "$tmp/beam.inp" $((n * n / 2 * l)) "$nodes" $((3 * (nodes - clamped)))
expect_outputs "$tmp/beam.inp" 45 30 10
expect_loads "$tmp/beam.inp" 3
grep -q '^\*\* OUT 25 [0-9]* 30 10 20$' "$tmp/beam.inp" || fail "beam40: output point 25 is not the patch centre (30, 10, 20)"

for args in "--divisions 30 --layers 2" "--divisions 20 --layers 0" "--divisions 20 --layers 2 --nu 0.5" \
            "--divisions 20 --layers 2 --element C3D20H" "--divisions 20 --layers 2 --pressure" \
            "--divisions 20 --layers 2 --cases fz --pressure --point" "--divisions 20 --layers 2 --cases fw" \
            "--divisions 20 --layers 2 --material neohooke" "--divisions 20 --layers 2 --increments 5" \
            "--divisions 20 --layers 2 --nlgeom --cases fz --pressure" "--divisions 20 --layers 2 --nlgeom --force 0,0,0" \
            "--divisions 20 --layers 2 --force 1,2" "--divisions 20 --layers 2 --cases fz --force 0,0,1" \
            "--divisions 20 --layers 2 --symmetry y" "--divisions 20 --layers 2 --symmetry x --cases fz,fx" \
            "--divisions 20 --layers 2 --symmetry xy --cases fz --point" "--divisions 20 --layers 2 --symmetry z" \
            "--scene beam40 --divisions 20 --layers 2" "--scene beam40 --divisions 16 --layers 2 --symmetry x --cases fz" \
            "--scene liver --divisions 20 --layers 2" "--divisions 20 --layers 2 --nlgeom --tolerance 0.5" \
            "--divisions 20 --grade 4:1 --layers 2" "--grade 2:3 --layers 2" "--grade 4 --layers 2" \
            "--grade 0:1 --layers 2" "--grade 4:1 --layers 2 --layer-ratio 0.5" \
            "--divisions 20 --layers 2 --min-fraction 1e-4" "--divisions 20 --layers 2 --nlgeom --min-fraction 0" \
            "--divisions 20 --layers 2 --nlgeom --min-fraction 2" "--divisions 20 --layers 2 --nlgeom --min-fraction x"; do
    # shellcheck disable=SC2086
    "$tool" $args > "$tmp/bad.inp" 2> "$tmp/err"
    st=$?
    [ "$st" = 2 ] || fail "'$args' exited $st, expected 2"
    [ -s "$tmp/bad.inp" ] && fail "'$args' wrote a deck"
done
[ "$fails" = 0 ] && echo "box_deck: counts (whole, half, quarter, graded, beam40), output points, load sums, NLGEOM cards, bad arguments ok"
[ "$fails" = 0 ]

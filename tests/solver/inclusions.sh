#!/bin/sh
# inclusions.sh TISSUEFIT — material regions (scene key inclusions): the
# two-material bar of tests/solver/inclusion_bar.yaml against its exact end
# displacement (0.22 mm) with both Galerkin solvers, the error falling as
# the grid is refined; a sphere changes the field only near it; the Newton
# solvers with a neo-Hookean sphere and with a Kelvin sphere; what is not
# built yet is refused by name.
set -u
tool=$1
. "$(dirname "$0")/../cli/expect.sh"
bar=tests/solver/inclusion_bar.yaml

# the mean x displacement of the end face, its error against 0.22 mm in %
end_error() { awk -F, 'NR > 1 && $2 == 40 { s += $5; n++ } END { printf "%.4f", 100 * (s / n - 0.22) / 0.22 }' "$1"; }

for method in rpim-galerkin efg-galerkin; do
    prev=
    for g in 9 17 33; do
        expect 0 "$method, $g nodes along the bar" -- "$tool" -q solve "$bar" \
            --set solver.method=$method --set geometry.grid=$g,5,5 --out "$tmp/u.csv"
        e=$(end_error "$tmp/u.csv")
        echo "  $method, $g nodes along x: end displacement off by $e %"
        awk -v e="$e" 'BEGIN { exit !(e < 0 ? -e < 6 : e < 6) }' || bad "$method $g: $e % off"
        if [ -n "$prev" ]; then
            awk -v a="$prev" -v b="$e" 'BEGIN { a = a < 0 ? -a : a; b = b < 0 ? -b : b; exit !(b < a) }' ||
                bad "$method: the error does not fall from $prev % to $e % at $g nodes"
        fi
        prev=$e
    done
    awk -v e="$prev" 'BEGIN { exit !(e < 0 ? -e < 1.5 : e < 1.5) }' || bad "$method at 33 nodes: $prev %"
done
# the mean x displacement of the end face, mm
end_mean() { awk -F, 'NR > 1 && $2 == 40 { s += $5; n++ } END { printf "%.6f", s / n }' "$1"; }
# the bar with an ellipsoid of semi-axes $1 (x,y,z) around its middle instead of its box
ellipsoid_bar() {
    sed '/^inclusions:/,/^fixed:/{/^fixed:/!d}' "$bar"
    printf 'inclusions:\n  - ellipsoid: {centre: [20, 5, 5], radii: [%s]}\n' "$1"
    printf '    material: {E: 10.0, nu: 0.0}\n'
}
within() { awk -v x="$1" -v lo="$2" -v hi="$3" 'BEGIN { exit !(x > lo && x < hi) }'; }

# the inclusion's material is what the bar sees: without it the end moves 0.4 mm
expect 0 "the bar without its inclusion's stiffness" -- "$tool" -q solve "$bar" \
    --set inclusions.0.material.E=1 --out "$tmp/u.csv"
within "$(end_mean "$tmp/u.csv")" 0.39 0.41 || bad "a uniform bar's end is not at 0.4 mm"
# an ellipsoid holding the whole bar: the bar is uniformly the stiff material
# (end at 40 / (10 x 100) = 0.04 mm); its semi-axes enter one by one
ellipsoid_bar "30, 9, 9" >"$tmp/e.yaml"
expect 0 "the bar in an ellipsoid" -- "$tool" -q solve "$tmp/e.yaml" --out "$tmp/u.csv"
within "$(end_mean "$tmp/u.csv")" 0.0396 0.0404 || bad "the bar inside an ellipsoid is not uniformly stiff"
ellipsoid_bar "30, 9, 4" >"$tmp/e2.yaml"
expect 0 "an ellipsoid thinner than the bar" -- "$tool" -q solve "$tmp/e2.yaml" --out "$tmp/u2.csv"
within "$(end_mean "$tmp/u2.csv")" 0.05 1 || bad "an ellipsoid 4 mm thick in z stiffens the whole bar"
# ParaView's view: the VTU file's "material" is 1 exactly at the nodes of
# the stiff half (x >= 20 on the 17-node grid: 9 of 17 columns of 5 x 5)
expect 0 "the bar as VTU" -- "$tool" -q solve "$bar" --out "$tmp/u.csv" --vtk "$tmp/bar.vtu"
m=$(awk '/Name="material"/ { on = 1; next } on && /<\/DataArray>/ { on = 0 }
         on { n[$1]++ } END { printf "%d,%d", n[0], n[1] }' "$tmp/bar.vtu")
[ "$m" = "200,225" ] || bad "the VTU file's material field: $m nodes of the body and the inclusion, not 200,225"
expect 0 "block48 as VTU" -- "$tool" -q solve tests/solver/block48_seed.yaml --force 0,0,-1 --out "$tmp/u.csv" --vtk "$tmp/b.vtu"
! grep -q 'Name="material"' "$tmp/b.vtu" || bad "a body without material regions has a material field"
# the datasheet names it
expect 0 "a header's datasheet lists the inclusion" -- "$tool" -q fit coeffs/block48.yaml -o "$tmp/b.h" \
    --no-discretisation --set 'inclusions.0.sphere.centre=24,24,3' --set inclusions.0.sphere.radius=2 \
    --set inclusions.0.material.E=3.2 --set inclusions.0.material.nu=0.49
grep -q "inclusion 0: sphere centre (24, 24, 3) mm, radius 2 mm, linear: E = 3.2, nu = 0.49" "$tmp/b.h" ||
    bad "the header's banner does not list the inclusion"
# The Newton solvers (neo-Hookean block48 with a stiff sphere under the
# patch, tests/calculix/scenes/block48_sphere.yaml): at 1e-4 N the solve is
# the linear one on the same cloud, to 1e-4 (the per-material volumetric
# averages of the cells the sphere cuts linearise to the linear B-bar's;
# measured 2.4e-6); an inclusion of the body's own material changes no bit;
# at 1 N the sphere still stiffens the contact.
sphere=tests/calculix/scenes/block48_sphere.yaml
nh="--set material.law=neo-hookean --set inclusions.0.material.law=neo-hookean"
# rel_diff A B: the L2 difference of two displacement CSVs over B's L2
rel_diff() { awk -F, 'NR == FNR { if (FNR > 1) { a[FNR, 5] = $5; a[FNR, 6] = $6; a[FNR, 7] = $7 }; next }
    FNR > 1 { for (k = 5; k <= 7; k++) { d = a[FNR, k] - $k; s += d * d; t += $k * $k } }
    END { printf "%.3g", sqrt(s / t) }' "$1" "$2"; }
# close A B BOUND WHAT: A's relative L2 difference from B is below BOUND
close() {
    r=$(rel_diff "$1" "$2")
    echo "  $4: $r"
    awk -v r="$r" -v b="$3" 'BEGIN { exit !(r < b) }' || bad "$4: $r"
}
# step_solve SCENE FX,FY,FZ OUT: the scene pressed by the force within 1e-4 s
# (a history of one step); OUT the field at the step's end, as a solve's CSV
step_solve() {
    { cat "$1"; printf 'history:\n  dt: 0.0001\n  duration: 0.0001\n  force: [%s]\n' "$2"
      printf '  segments:\n    - {kind: step, to: 1}\n'; } >"$tmp/step.yaml"
    expect 0 "$(basename "$1" .yaml), pressed in 1e-4 s" -- "$tool" -q solve "$tmp/step.yaml" -o "$tmp/step.csv"
    awk -F, 'NR == 1 { print "node,x,y,z,ux,uy,uz"; next }
             $1 == 2 { print $3 "," $4 "," $5 "," $6 "," $7 "," $8 "," $9 }' "$tmp/step.csv" >"$3"
}
# the z displacement of the node nearest the top's centre (24, 24, 6)
centre_uz() { awk -F, 'NR > 1 { d = ($2 - 24) ^ 2 + ($3 - 24) ^ 2 + ($4 - 6) ^ 2
    if (n == 0 || d < best) { best = d; u = $7; n = 1 } } END { printf "%.6f", u }' "$1"; }
for m in rpim efg; do
    expect 0 "$m linear, a sphere, 1e-4 N" -- "$tool" -q solve "$sphere" --set solver.method=$m-galerkin \
        --force 0,0,-0.0001 --out "$tmp/lin.csv"
    expect 0 "$m Newton, neo-Hookean, a sphere, 1e-4 N" -- "$tool" -q solve "$sphere" $nh \
        --set solver.method=$m-newton --force 0,0,-0.0001 --out "$tmp/nh.csv"
    r=$(rel_diff "$tmp/nh.csv" "$tmp/lin.csv")
    echo "  $m-newton with a sphere at 1e-4 N: $r from the linear solve (L2, relative)"
    awk -v r="$r" 'BEGIN { exit !(r < 1e-4 && r > 0) }' || bad "$m-newton with a sphere: $r from the linear solve"
done
sed '/^inclusions:/,/^fixed:/{/^fixed:/!d}' "$sphere" >"$tmp/plain.yaml"
expect 0 "Newton, no inclusion" -- "$tool" -q solve "$tmp/plain.yaml" --set material.law=neo-hookean \
    --force 0.2,0.1,-1 --out "$tmp/u0.csv"
expect 0 "Newton, an inclusion of the body's material" -- "$tool" -q solve "$sphere" $nh \
    --set inclusions.0.material.E=0.32 --force 0.2,0.1,-1 --out "$tmp/u1.csv"
cmp -s "$tmp/u0.csv" "$tmp/u1.csv" || bad "an inclusion of the body's own material changed the Newton solve"
expect 0 "Newton, the stiff sphere at 1 N" -- "$tool" -q solve "$sphere" $nh --force 0.2,0.1,-1 \
    --out "$tmp/u2.csv"
a=$(centre_uz "$tmp/u0.csv") b=$(centre_uz "$tmp/u2.csv")
echo "  neo-Hookean at 1 N: the top's centre moves $a mm without the sphere, $b mm with it"
awk -v a="$a" -v b="$b" 'BEGIN { exit !(b < 0 && a < b) }' || bad "the sphere does not stiffen the contact at 1 N ($a, $b mm)"
# A region of another law of the same kinematics and volume measure: a
# neo-Hookean body with a Kelvin neo-Hookean sphere (k1 3.2, k2 0.8 MPa,
# tau 5 s) at 1 N is, relaxed, the neo-Hookean sphere of E = k1 (6.4e-12
# measured) and, pressed within 1e-4 s, that of E = k1 + k2 (1.6e-7); a
# Kelvin body with the linear sphere, relaxed, the linear solve with the
# body's E = k1 (1.3e-12).
sed 's/material: {E: 3.2, nu: 0.49}/material: {law: kelvin-neo-hookean, k1: 3.2, k2: 0.8, eta: 4, nu: 0.49}/
     s/^  E: 0.32$/  law: neo-hookean\n  E: 0.32/' "$sphere" >"$tmp/nh_knh.yaml"
nf=0.2,0.1,-1
expect 0 "neo-Hookean with a Kelvin neo-Hookean sphere, relaxed" -- "$tool" -q solve "$tmp/nh_knh.yaml" \
    --force $nf --out "$tmp/a.csv"
expect 0 "neo-Hookean with a neo-Hookean sphere, E = k1" -- "$tool" -q solve "$sphere" $nh --force $nf --out "$tmp/b.csv"
close "$tmp/a.csv" "$tmp/b.csv" 1e-9 "a Kelvin neo-Hookean sphere in neo-Hookean tissue, relaxed, from the neo-Hookean sphere of E = k1"
step_solve "$tmp/nh_knh.yaml" $nf "$tmp/s2.csv"
expect 0 "neo-Hookean with a neo-Hookean sphere, E = k1 + k2" -- "$tool" -q solve "$sphere" $nh \
    --set inclusions.0.material.E=4 --force $nf --out "$tmp/c.csv"
close "$tmp/s2.csv" "$tmp/c.csv" 1e-5 "the same pressed in 1e-4 s, from the neo-Hookean sphere of E = k1 + k2"
# refused, naming the key and why
expect 2 "a neo-Hookean region in a linear body" -- "$tool" -q solve "$bar" --set inclusions.0.material.law=neo-hookean
says "a neo-Hookean region in a linear body" "inclusions.0.material.law: not yet: a region of the neo-hookean law in a body of the linear law: a linear elastic body takes material regions of its own law"
expect 2 "a linear region in a neo-Hookean body" -- "$tool" -q solve "$sphere" --set material.law=neo-hookean --force 0,0,-1
says "a linear region in a neo-Hookean body" "the body's law is finite-strain and this law small-strain"
expect 2 "an svk region in a neo-Hookean body" -- "$tool" -q solve "$sphere" $nh --set inclusions.0.material.law=svk \
    --force 0,0,-1
says "an svk region in a neo-Hookean body" "volumetric energies take different volume measures"
# The Kelvin law (k = 0: linear viscoelastic) with a Kelvin sphere of its
# own relaxation (body: k1 0.32, k2 0.192, tau 1 s, g_inf 0.625; sphere:
# k1 3.2, k2 0.8, tau 5 s, g_inf 0.8): relaxed (a static solve) it is the
# linear solve with E = k1 in each material (2.2e-13 measured; 6.9e-4 when
# the sphere's volumetric part relaxed with the body's function), and
# pressed within 1e-4 s the linear solve with E = k1 + k2 (3.7e-5).
sed 's/^  E: 0.32$/  law: kelvin\n  k1: 0.32\n  k2: 0.192\n  eta: 0.192/
     s/material: {E: 3.2, nu: 0.49}/material: {law: kelvin, k1: 3.2, k2: 0.8, eta: 4, nu: 0.49}/' \
    "$sphere" >"$tmp/kelvin.yaml"
kf=0.02,0.01,-0.1
expect 0 "Kelvin with a Kelvin sphere, relaxed" -- "$tool" -q solve "$tmp/kelvin.yaml" --force $kf --out "$tmp/k.csv"
expect 0 "linear, E = k1" -- "$tool" -q solve "$sphere" --force $kf --out "$tmp/k1.csv"
close "$tmp/k.csv" "$tmp/k1.csv" 1e-9 "a Kelvin sphere in Kelvin tissue, relaxed, from the linear solve with E = k1"
step_solve "$tmp/kelvin.yaml" $kf "$tmp/k0.csv"
expect 0 "linear, E = k1 + k2" -- "$tool" -q solve "$sphere" --set material.E=0.512 \
    --set inclusions.0.material.E=4 --force $kf --out "$tmp/k12.csv"
close "$tmp/k0.csv" "$tmp/k12.csv" 1e-4 "the same pressed in 1e-4 s, from the linear solve with E = k1 + k2"
sed 's/^  E: 0.32$/  law: kelvin\n  k1: 0.32\n  k2: 0.192\n  eta: 0.192/' "$sphere" >"$tmp/kelvin_lin.yaml"
expect 0 "Kelvin with a linear sphere, relaxed" -- "$tool" -q solve "$tmp/kelvin_lin.yaml" --force $kf --out "$tmp/d.csv"
close "$tmp/d.csv" "$tmp/k1.csv" 1e-9 "a linear sphere in Kelvin tissue, relaxed, from the linear solve with E = k1"
expect 2 "an inclusion with two shapes" -- "$tool" -q solve "$bar" --set 'inclusions.0.sphere.centre=1,2,3' \
    --set inclusions.0.sphere.radius=1
says "an inclusion with two shapes" "inclusions.0: give exactly one of sphere, ellipsoid or box"
expect 2 "a sphere of no radius" -- "$tool" -q solve coeffs/block48.yaml \
    --set 'inclusions.0.sphere.centre=24,24,3' --set inclusions.0.sphere.radius=0 \
    --set inclusions.0.material.E=1 --set inclusions.0.material.nu=0.3
says "a sphere of no radius" "inclusions.0.sphere: the centre must be finite and the radius a positive number of mm"
expect 1 "MLS collocation" -- "$tool" -q solve "$bar" --set solver.method=mls-collocation
says "MLS collocation" "not yet: material regions"
expect 1 "VCI integration" -- "$tool" -q solve "$bar" --set solver.integration=vci
says "VCI integration" "not yet: material regions with VCI integration"
finish inclusions

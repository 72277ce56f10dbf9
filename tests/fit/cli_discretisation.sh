#!/bin/sh
# cli_discretisation.sh TISSUEFIT — without a reference, `tissuefit fit`
# measures the solve's error itself on a coarser and a finer cloud
# (fitting/discretisation_self.h) and the header states fit +
# discretisation = total; on block48 the measurement is within a factor of 2
# of the one against CalculiX; a contact site by node number and a nonlinear
# law are measured too, a cloud that fails at the envelope's radius at a
# smaller one, a coarser cloud that fails gives way to two finer ones;
# --no-discretisation skips it, and a scene it cannot measure says why in
# the header.
set -u
tool=$1
. "$(dirname "$0")/../cli/expect.sh"

# the header's #define NAME (its value)
define() { sed -n "s/^#define TFIT_[A-Z0-9_]*_$2 \([^ ]*\).*/\1/p" "$1"; }
within2() { awk -v a="$1" -v b="$2" 'BEGIN { r = a / b; exit !(r >= 0.5 && r <= 2) }'; }

expect 0 "block48, self-measured" -- "$tool" fit coeffs/block48.yaml -o "$tmp/w/self.h"
says "the clouds' progress" "fit: discretisation: the cloud of spacing 1.219 mm (9248 nodes) solved"
grep -q "(discretisation: self-measured: Richardson extrapolation over clouds of spacing 2.123, 1.642 (this one), 1.219 mm (2000, 4056, 9248 nodes), observed order" "$tmp/w/self.h" ||
    bad "the header does not say how the discretisation was measured"
grep -q "^ \*       error against the physics: fit .* + discretisation .* = total <= .* mm" "$tmp/w/self.h" ||
    bad "the header states no total"
expect 0 "block48 against CalculiX" -- "$tool" -q fit coeffs/block48.yaml \
    --reference tests/calculix/data/block48_physics.csv -o "$tmp/w/ref.h"
for d in FORWARD_DISCRETISATION_MAX_MM CONTACT_DISCRETISATION_MAX_N; do
    own=$(define "$tmp/w/self.h" $d) ref=$(define "$tmp/w/ref.h" $d)
    if [ -z "$own" ] || [ -z "$ref" ]; then
        bad "$d missing ('$own', '$ref')"
    else
        within2 "$own" "$ref" || bad "$d: self-measured $own is not within a factor of 2 of CalculiX's $ref"
        echo "ok:   $d: self-measured $own, against CalculiX $ref"
    fi
done

expect 0 "--no-discretisation" -- "$tool" -q fit coeffs/block48.yaml --no-discretisation -o "$tmp/w/no.h"
grep -q "error of the solve against the physics: not measured (--no-discretisation; tissuefit fit --reference" "$tmp/w/no.h" ||
    bad "--no-discretisation: the header does not say 'not measured'"
[ -z "$(define "$tmp/w/no.h" FORWARD_DISCRETISATION_MAX_MM)" ] || bad "--no-discretisation: a figure stated"

# a contact site by node number: the clouds' grids keep its point a node
expect 0 "a contact site by node number" -- "$tool" fit tests/solver/block48_seed.yaml -o "$tmp/w/node.h"
says "the node's clouds" "fit: discretisation: the cloud of spacing"
grep -q "(discretisation: self-measured: Richardson extrapolation over clouds of spacing .* (243, 363, 900 nodes), .* bound over the envelope (linear)" "$tmp/w/node.h" ||
    bad "a site by node number: the header does not state the self-measurement over 243, 363 and 900 nodes"
# a nonlinear law: the envelope's six extreme forces, Newton on every cloud
TINY="--set geometry.grid=9,9,3 --set contact.0.node=41 --set fit.train=12 --set fit.heldout=3 --set fit.max_degree=1"
expect 0 "a nonlinear law" -- "$tool" -q fit tests/solver/block48_seed.yaml $TINY \
    --set material.law=neo-hookean -o "$tmp/w/nl.h"
grep -q "(discretisation: self-measured: .* largest over the 6 forces of the envelope's radius along +-x, +-y, +-z; the coarser pair gives" "$tmp/w/nl.h" ||
    bad "a nonlinear law: the header does not state the self-measurement at the envelope's six forces"
grep -q "^ \*       error against the physics: fit .* + discretisation .* = total <= .* mm" "$tmp/w/nl.h" ||
    bad "a nonlinear law: the header states no total"
# a cloud that cannot reach the envelope: St Venant-Kirchhoff's limit point
# in compression comes at a smaller force on a finer (softer) cloud; the six
# forces are tried again at 0.75 of the radius, and the header says so
expect 0 "a cloud that fails at the envelope's radius" -- "$tool" -q fit tests/solver/block48_seed.yaml \
    $TINY --set material.law=svk --set envelope.radius=2.5 --set solver.newton.cuts=2 -o "$tmp/w/reach.h"
grep -q "largest over the 6 forces of 75 % of the envelope's radius along +-x, +-y, +-z (a cloud's solve failed at the radius; not measured beyond)" "$tmp/w/reach.h" ||
    bad "a cloud that fails at the envelope's radius: the header does not state the smaller forces"
says "a cloud that fails at the envelope's radius" "warning: fit: the discretisation is measured up to 75 % of the envelope's radius only"
grep -q "^ \*       error against the physics: fit .* + discretisation .* = total <= .* mm" "$tmp/w/reach.h" ||
    bad "a cloud that fails at the envelope's radius: the header states no total"
# a coarser cloud that fails: the scene's cloud and two finer ones instead.
# Node (3, 3) of 11 x 11 x 3 stays a node only on multiples of 10
# intervals in x and y: no coarser grid keeps it, h/r refines the thickness
# only, h/r^2 every axis (20 intervals)
expect 0 "a contact node no coarser grid keeps" -- "$tool" -q fit tests/solver/block48_seed.yaml \
    --set contact.0.node=37 -o "$tmp/w/kept.h"
grep -q "(discretisation: self-measured: Richardson extrapolation over clouds of spacing 4.104 (this one), 3.585, 2.052 mm (363, 484, 2205 nodes; the coarser cloud: no coarser grid keeps the contact node)" "$tmp/w/kept.h" ||
    bad "a contact node no coarser grid keeps: the header does not state the finer clouds it was measured on"
grep -q "^ \*       error against the physics: fit .* + discretisation .* = total <= .* mm" "$tmp/w/kept.h" ||
    bad "a contact node no coarser grid keeps: the header states no total"
# what cannot be measured this way is stated, and the fit goes on: two
# nodes through the thickness scale the thickness with the spacing, so
# that the contact node leaves the top of every other cloud
expect 0 "a contact node no other cloud keeps" -- "$tool" -q fit tests/solver/block48_seed.yaml \
    --set contact.0.node=37 --set geometry.grid=11,11,2 -o "$tmp/w/kept2.h"
grep -q "not measured (the contact site moves with the cloud .* (after the coarser cloud failed: the contact site is not a node of it)" "$tmp/w/kept2.h" ||
    bad "a contact node no other cloud keeps: the header does not say why it was not measured"
# a contact region: measured at the probe's patch at the region's centre;
# the shipped header (check-coeffs regenerates it byte for byte) states it
for m in SURFACE LAW; do
    grep -q "^#define TFIT_BLOCK48_REGION_${m}_TOTAL_MAX_" coeffs/block48_region.h ||
        bad "block48_region.h: the region's $m states no total"
done
[ "$(grep -c "; at one site of the region, its centre, under the probe's patch)" coeffs/block48_region.h)" = 2 ] ||
    bad "block48_region.h does not say where the region's discretisation was measured"
finish discretisation

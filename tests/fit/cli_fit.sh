#!/bin/sh
# cli_fit.sh TISSUEFIT — `tissuefit fit` refuses scenes it cannot fit, each
# with its own message, exit status 2 and nothing written; --direct (every
# training case solved) gives the same models as superposition, to rounding.
set -u
tool=$1
. "$(dirname "$0")/../cli/expect.sh"
scenes=$(dirname "$0")/scenes

expect 0 "fit --help" -- "$tool" fit --help
prints "fit --help" "forward family to emit, one of: nodal, modal, zhou2017"
expect 2 "no -o" -- "$tool" fit tests/solver/block48_seed.yaml
says "no -o" "expected one scene file and -o FILE.h"
expect 2 "no contact site" -- "$tool" -q fit "$scenes/no_contact.yaml" -o "$tmp/w/a.h"
says "no contact site" "no contact site"
expect 2 "zero envelope" -- "$tool" -q fit tests/solver/block48_seed.yaml --set envelope.radius=0 -o "$tmp/w/a.h"
says "zero envelope" "envelope.radius"
expect 2 "outputs that select nothing" -- "$tool" -q fit "$scenes/no_outputs.yaml" -o "$tmp/w/a.h"
says "no outputs" "outputs"
expect 2 "zhou2017 on a non-flat output set" -- "$tool" -q fit "$scenes/all_layers.yaml" \
    --family zhou2017 -o "$tmp/w/a.h"
says "zhou2017 non-flat" "one plane"
expect 2 "an unknown family" -- "$tool" -q fit tests/solver/block48_seed.yaml --family cubic -o "$tmp/w/a.h"
says "unknown family" "forward families"
expect 2 "an unknown contact site" -- "$tool" -q fit tests/solver/block48_seed.yaml --contact nowhere -o "$tmp/w/a.h"
says "unknown contact site" "has no contact site 'nowhere'"
expect 2 "a bad fit setting" -- "$tool" -q fit tests/solver/block48_seed.yaml --set fit.folds=1 -o "$tmp/w/a.h"
says "bad fit setting" "fit.folds"
expect 2 "a discretisation fraction beyond 1" -- "$tool" -q fit coeffs/block48.yaml \
    --discretisation-rel 2,0.07 -o "$tmp/w/a.h"
says "a discretisation fraction beyond 1" "two fractions in (0, 1)"
expect 2 "a solver step longer than half a history" -- "$tool" -q fit coeffs/block48_ve.yaml \
    --set fit.solve_every=2000 -o "$tmp/w/a.h"
says "a solver step longer than half a history" "fit.solve_every"
# A contact region is never fitted as a point, and what its fit does not
# take yet is refused by name, not ignored.
expect 2 "a region with a point family" -- "$tool" -q fit coeffs/block48_region.yaml \
    --family nodal -o "$tmp/w/a.h"
says "a region with a point family" "would emit a point model"
expect 2 "a region with --budget-us" -- "$tool" -q fit coeffs/block48_region.yaml \
    --budget-us 100 -o "$tmp/w/a.h"
says "a region with --budget-us" "not yet: --budget-us"
expect 2 "a region with a servo budget" -- "$tool" -q fit coeffs/block48_region.yaml \
    --set fit.servo_hz=1000 -o "$tmp/w/a.h"
says "a region with a servo budget" "not yet: fit.servo_hz"
expect 2 "a region of a nonlinear law" -- "$tool" -q fit tests/region/block48_nh_region.yaml \
    -o "$tmp/w/a.h"
says "a region of a nonlinear law" "not yet: a region's models are fitted for an affine solve"
expect 2 "a region's envelope off zero" -- "$tool" -q fit coeffs/block48_region.yaml \
    --set envelope.centre=0.1,0,0 -o "$tmp/w/a.h"
says "a region's envelope off zero" "not yet: a region's surface takes forces"
expect 2 "a site with the region family" -- "$tool" -q fit tests/solver/block48_seed.yaml \
    --family region_surface -o "$tmp/w/a.h"
says "a site with the region family" "fits a contact region"
nothing_written "refused fits"

# A region's header: its law and surface, named so, with the datasheet lines.
expect 0 "fit, a contact region" -- "$tool" -q fit coeffs/block48_region.yaml \
    --set contact.0.region.rect=19.2,24,19.2,24 --no-discretisation -o "$tmp/w/rg.h"
for want in "tfit_rg_law: region P=2" "tfit_rg_surface: region_surface p=1" \
    "held out at the 9 cell centres (sites never fitted)" "target met at spacing" \
    "#define TFIT_RG_LAW_HELDOUT_MAX_N" "#define TFIT_RG_SURFACE_HELDOUT_MAX_MM" \
    "error of the solve against the physics: not measured (--no-discretisation)"; do
    grep -qF "$want" "$tmp/w/rg.h" || bad "rg.h lacks '$want'"
done
grep -q "_forward\|_contact" "$tmp/w/rg.h" && bad "rg.h has a point model"
rm -f "$tmp/w/rg.h" "$tmp/w/rg_golden.h"

# The small-strain warning: a linear solve whose displacements exceed a
# tenth of the body's thickness says linear elasticity does not describe it
# (block48 at 1 N: 2 mm on 6 mm); a nonlinear law does describe it, so the
# same scene with the neo-Hookean law does not warn.
WARN="law is small-strain and does not describe tissue there"
TINY="--set geometry.grid=5,5,2 --set contact.0.node=13 --set fit.train=12 --set fit.heldout=3 --set fit.max_degree=1"
expect 0 "fit, linear, large displacements" -- "$tool" fit tests/solver/block48_seed.yaml $TINY -o "$tmp/w/lw.h"
says "the small-strain warning for the linear law" "the linear $WARN"
grep -q "^ \* Warning (the law's range): displacements reach .*the linear $WARN" "$tmp/w/lw.h" ||
    bad "the header does not carry the small-strain warning"
expect 0 "fit, neo-Hookean, large displacements" -- "$tool" fit tests/solver/block48_seed.yaml $TINY \
    --set material.law=neo-hookean -o "$tmp/w/nw.h"
check "no small-strain warning for the neo-Hookean law" sh -c "! grep -q '$WARN' '$tmp/err'"
grep -q "^ \*   solver: rpim-galerkin (the neo-hookean law by Newton's method: rpim-newton), support" "$tmp/w/nw.h" ||
    bad "the banner does not say which solver solved the neo-Hookean law"
rm -f "$tmp/w/lw.h" "$tmp/w/lw_golden.h" "$tmp/w/nw.h" "$tmp/w/nw_golden.h"

# Superposition against direct solves of every training case: the two
# differ by rounding in the training data (about 1e-15 relative), so every
# float coefficient of both models agrees to 1e-12 of the table's largest
# (measured: 1e-16; coefficients that should be 0 differ by ~1e-16 there).
expect 0 "fit, superposed" -- "$tool" -q fit tests/solver/block48_seed.yaml -o "$tmp/w/s.h"
grep -q "training cases superposed from unit solves" "$tmp/w/s.h" || bad "s.h was not superposed"
expect 0 "fit, direct" -- "$tool" -q fit tests/solver/block48_seed.yaml --direct -o "$tmp/w/d.h"
grep -q "every training case solved directly" "$tmp/w/d.h" || bad "d.h was not solved directly"
# coef HEADER MODEL: the float table of tfit_MODEL, one decimal number a line
coef() {
    sed -n "/^static const float tfit_$2_coef\[/,/^};/p" "$1" |
        grep -o -e '-\{0,1\}0x[0-9a-f.]*p[-+][0-9]*' | xargs env printf '%.17g\n'
}
for m in forward contact; do
    coef "$tmp/w/s.h" "s_$m" >"$tmp/s.$m"
    coef "$tmp/w/d.h" "d_$m" >"$tmp/d.$m"
    [ -s "$tmp/s.$m" ] && [ "$(wc -l <"$tmp/s.$m")" = "$(wc -l <"$tmp/d.$m")" ] ||
        bad "the $m tables of the superposed and direct fits differ in size"
    paste "$tmp/s.$m" "$tmp/d.$m" | awk -v m="$m" '
        { d = $1 - $2; d = d < 0 ? -d : d; a = $1 < 0 ? -$1 : $1
          if (d > dmax) dmax = d; if (a > amax) amax = a }
        END { printf "superposed vs direct, %s: %d coefficients, max difference %.3g of the largest\n",
                     m, NR, dmax / amax
              exit !(NR > 0 && dmax <= 1e-12 * amax) }' ||
        bad "superposed and direct $m models differ beyond rounding"
done
# The banner is a datasheet: the physics the models encode, and whether the
# displacements leave the range of the scene's law (here linear elasticity
# at 2.3 mm on a 6 mm plate; at a tenth of the force, 3.9 %, it does not)
rm -f "$tmp"/w/*
expect 0 "the banner's physics" -- "$tool" -q fit tests/solver/block48_seed.yaml -o "$tmp/w/d.h"
for line in "Physics (as solved):" \
    "  body: box \[0, 48\] x \[0, 48\] x \[0, 6\] mm; 11 x 11 x 3 nodes (363), mean spacing 4.8 x 4.8 x 3 mm" \
    "  material: linear (linear elasticity, small strain.*: E = 0.32 (Young's modulus, MPa), nu = 0.49" \
    "  solver: rpim-galerkin, support 2 spacings" "  fixed 3: face y+, 33 nodes, every component held" \
    "  contact 'top-centre': (24, 24, 6) mm, force spread over a 4.8 x 4.8 mm rectangle of face z+; envelope |F - (0, 0, 0)| <= 1 N" \
    "Warning (the law's range): displacements reach 2.[0-9]* mm on a body 6 mm thick"; do
    grep -q " \* $line" "$tmp/w/d.h" || bad "the banner lacks '$line'"
done
expect 0 "a tenth of the force" -- "$tool" -q fit tests/solver/block48_seed.yaml \
    --set envelope.radius=0.1 -o "$tmp/w/d.h"
grep -q "largest displacement of the training cases: 0.2[0-9]* mm" "$tmp/w/d.h" &&
    ! grep -q "the law's range" "$tmp/w/d.h" || bad "a 0.23 mm dent on a 6 mm plate was warned about"
finish fit

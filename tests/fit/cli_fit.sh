#!/bin/sh
# cli_fit.sh TISSUEFIT — `tissuefit fit` refuses scenes it cannot fit, each
# with its own message, exit status 2 and nothing written; --direct (every
# training case solved) agrees with superposition.
set -u
tool=$1
. "$(dirname "$0")/../cli/expect.sh"
says() {
    grep -q "$2" "$tmp/err" || bad "$1: message lacks '$2': $(cat "$tmp/err")"
}
scenes=$(dirname "$0")/scenes

expect 0 "fit --help" -- "$tool" fit --help
expect 2 "no -o" -- "$tool" fit coeffs/block48.yaml
expect 2 "no contact site" -- "$tool" -q fit "$scenes/no_contact.yaml" -o "$tmp/w/a.h"
says "no contact site" "no contact site"
expect 2 "zero envelope" -- "$tool" -q fit coeffs/block48.yaml --set envelope.radius=0 -o "$tmp/w/a.h"
says "zero envelope" "envelope.radius"
expect 2 "outputs that select nothing" -- "$tool" -q fit "$scenes/no_outputs.yaml" -o "$tmp/w/a.h"
says "no outputs" "outputs"
expect 2 "zhou2017 on a non-flat output set" -- "$tool" -q fit "$scenes/all_layers.yaml" \
    --family zhou2017 -o "$tmp/w/a.h"
says "zhou2017 non-flat" "one plane"
expect 2 "an unknown family" -- "$tool" -q fit coeffs/block48.yaml --family cubic -o "$tmp/w/a.h"
says "unknown family" "forward families"
expect 2 "an unknown contact site" -- "$tool" -q fit coeffs/block48.yaml --contact nowhere -o "$tmp/w/a.h"
expect 2 "a bad fit setting" -- "$tool" -q fit coeffs/block48.yaml --set fit.folds=1 -o "$tmp/w/a.h"
says "bad fit setting" "fit.folds"
nothing_written "refused fits"

# Superposition against direct solves of every training case.
expect 0 "fit, superposed" -- "$tool" -q fit coeffs/block48.yaml -o "$tmp/w/s.h"
expect 0 "fit, direct" -- "$tool" -q fit coeffs/block48.yaml --direct -o "$tmp/w/d.h"
for m in FORWARD_HELDOUT_MAX_MM CONTACT_HELDOUT_MAX_N; do
    a=$(sed -n "s/^#define TFIT_S_$m //p" "$tmp/w/s.h")
    b=$(sed -n "s/^#define TFIT_D_$m //p" "$tmp/w/d.h")
    awk -v a="$a" -v b="$b" 'BEGIN { exit !(a > 0 && b > 0 && a < 2 * b && b < 2 * a) }' ||
        bad "superposed and direct fits disagree on $m: $a vs $b"
done
finish fit

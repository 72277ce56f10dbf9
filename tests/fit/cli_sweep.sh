#!/bin/sh
# cli_sweep.sh TISSUEFIT — `tissuefit sweep` measures every candidate, and
# `tissuefit fit --budget-us/--max-error-mm` chooses among them; a budget or
# an error nothing meets is refused with the best achievable stated and
# nothing written.
set -u
tool=$1
. "$(dirname "$0")/../cli/expect.sh"

expect 0 "sweep, scene outputs" -- "$tool" -q sweep tests/solver/block48_seed.yaml --outputs scene \
    --csv "$tmp/s.csv" --md "$tmp/s.md"
head -1 "$tmp/s.csv" | grep -q '^outputs,n_out,model,family,precision' || bad "sweep CSV header"
for m in "nodal p=1,nodal,float32" "nodal p=1,nodal,Q31" "nodal p=1,nodal,float64" \
         "modal p=1 r=3,modal,float32" "zhou2017 lambda=1,1,1,zhou2017,float32" \
         "contact p=1,contact,float32"; do
    grep -q ",$m," "$tmp/s.csv" || bad "sweep lacks '$m'"
done
# every forward float32 candidate has a time and an error; the front is marked
awk -F, 'NR > 1 && $5 == "float32" && ($12 == "nan" || $13 == "nan") { exit 1 }' "$tmp/s.csv" ||
    bad "a float32 candidate without time or error"
awk -F, 'NR > 1 && $16 == 1 { n++ } END { exit !(n >= 2) }' "$tmp/s.csv" || bad "no Pareto front"
# the exact linear model is on the front and within 1 um
awk -F, '$3 == "nodal p=1" && $5 == "float32" && $16 == 1 && $13 < 0.001 { ok = 1 } END { exit !ok }' \
    "$tmp/s.csv" || bad "nodal p=1 float32 not on the front within 1 um"

chosen() { sed -n 's/.*Chosen among every candidate.*: \(.*\) (.*us) and the contact.*/\1/p' "$1"; }
expect 0 "budget 60 us on the M4F" -- "$tool" -q fit tests/solver/block48_seed.yaml -o "$tmp/w/b.h" --budget-us 60
[ "$(chosen "$tmp/w/b.h")" = "nodal p=1" ] || bad "60 us chose '$(chosen "$tmp/w/b.h")', not nodal p=1"
# on the M7 nodal p=1 costs 7.1 us; below it, with the modal rows in
# assembly, modal p=1 r=2 (5.96 us) is the most accurate model: a budget
# between them buys it
expect 0 "budget 7 us on a 480 MHz M7" -- "$tool" -q fit tests/solver/block48_seed.yaml -o "$tmp/w/b.h" \
    --budget-us 7 --mcu cortex-m7@480
[ "$(chosen "$tmp/w/b.h")" = "modal p=1 r=2" ] || bad "M7 7 us chose '$(chosen "$tmp/w/b.h")'"
expect 0 "error 10 um, cheapest" -- "$tool" -q fit tests/solver/block48_seed.yaml -o "$tmp/w/b.h" --max-error-mm 0.01
[ "$(chosen "$tmp/w/b.h")" = "nodal p=1" ] || bad "10 um chose '$(chosen "$tmp/w/b.h")'"
expect 0 "budget 15 us on a 480 MHz M7" -- "$tool" -q fit tests/solver/block48_seed.yaml -o "$tmp/w/b.h" \
    --budget-us 15 --mcu cortex-m7@480
[ "$(chosen "$tmp/w/b.h")" = "nodal p=1" ] || bad "M7 15 us chose '$(chosen "$tmp/w/b.h")'"
rm -f "$tmp"/w/*

# the cheapest M4F model is modal p=1 r=1 at 16.2 us
expect 2 "a budget nothing meets" -- "$tool" -q fit tests/solver/block48_seed.yaml -o "$tmp/w/x.h" --budget-us 15
grep -q "Fastest: modal p=1 r=1" "$tmp/err" && grep -q "Most accurate: nodal p=1" "$tmp/err" ||
    bad "the refusal does not state the best on each axis: $(cat "$tmp/err")"
expect 2 "an error nothing meets" -- "$tool" -q fit tests/solver/block48_seed.yaml -o "$tmp/w/x.h" --max-error-mm 1e-12
says "an error nothing meets" "no model fits a 1e-12 mm error on cortex-m4f@168"
says "an error nothing meets" "Most accurate: nodal p=1, held-out max"
expect 2 "an unknown core" -- "$tool" -q fit tests/solver/block48_seed.yaml -o "$tmp/w/x.h" --budget-us 100 \
    --mcu cortex-m3@72
says "an unknown core" "--mcu 'cortex-m3@72': cycle estimates exist for cortex-m4f and cortex-m7"
expect 2 "a budget that is not a number" -- "$tool" -q fit tests/solver/block48_seed.yaml -o "$tmp/w/x.h" --budget-us fast
says "a budget that is not a number" "--budget-us 'fast' is not a positive number"
[ -z "$(ls -A "$tmp/w")" ] || bad "a refused fit wrote $(ls -A "$tmp/w")"
expect 2 "sweep of a region scene" -- "$tool" -q sweep coeffs/block48_region.yaml --csv "$tmp/w/r.csv"
says "sweep of a region scene" "contact 'top' is a region: not yet"
[ -z "$(ls -A "$tmp/w")" ] || bad "a refused sweep wrote $(ls -A "$tmp/w")"
finish sweep

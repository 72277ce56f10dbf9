#!/bin/sh
# check_nlgeom.sh CHECKER DATA TMP LEVELS MATERIALS PATHS K ELEMENT CONV_BOUND CONV_FACTOR SMALL_SLOPE
#                [GRADED_LEVELS GRADED_RUNS GRADED_BOUND]
#
# Runs the NLGEOM data checker (check_nlgeom.c) on the committed data, which
# must pass, then on copies broken in one way each, which must fail.
set -u
checker=$1 data=$2 tmp=$3
shift 3
finest=${1##*,}
args="$*"
fails=0
# shellcheck source=tests/calculix/expect_rejected.sh
. "$(dirname "$0")/expect_rejected.sh"
run=nl_$(echo "$2" | cut -d, -f1)_a_$finest   # the first material's path a, finest level
curves=block48_nl_curves.csv field=block48_$run.csv

# shellcheck disable=SC2086
check() { "$checker" "$1" $args; }

check "$data" || exit 1

# mutant NAME FUNCTION: copy the data to TMP, let FUNCTION break the copy,
# expect the checker to reject it (exit 1).
mutant() {
    rm -rf "$tmp" && mkdir -p "$tmp" && cp "$data"/block48_nl_*.csv "$tmp"/
    "$2"
    expect_rejected "$1"
}

# edit FILE AWK-PROGRAM: FILE of the copy through awk (fields comma-separated)
edit() { awk -F, -v OFS=, -v r="$run" "$2" "$data/$1" > "$tmp/$1"; }

drop_level() { edit $curves '!($1 == r && ++n == 3)'; }
wrong_reaction() { edit $curves '$1 == r && ++n == 2 { $11 = -$11 } 1'; }
turns_back() { edit $curves '$1 == r && ++n == 2 { $8 = 0.4 * $8 } 1'; }
# the finest run 5 % softer, its curve and its field alike
softer() {
    edit $curves '$1 == r { $6 *= 1.05; $7 *= 1.05; $8 *= 1.05 } 1'
    edit "$field" 'NR > 1 { $5 *= 1.05; $6 *= 1.05; $7 *= 1.05 } 1'
}
stale_field() { edit "$field" 'NR == 62 { $7 *= 1.001 } 1'; }
small_off() { edit $curves '$1 ~ /_s0.001$/ && !done { $8 *= 1.01; done = 1 } 1'; }
# the finest graded level's first run 5 % softer (with GRADED_LEVELS given)
graded=$(echo "$args" | awk '{ print $9 }')
grun=nl_$(echo "$args" | awk '{ print $10 }' | cut -d, -f1 | cut -d: -f1,2 | tr : _)_${graded##*,}
graded_softer() {
    edit $curves '$1 == "'"$grun"'" { $6 *= 1.05; $7 *= 1.05; $8 *= 1.05 } 1'
    edit "block48_$grun.csv" 'NR > 1 { $5 *= 1.05; $6 *= 1.05; $7 *= 1.05 } 1'
}
other_element() { edit block48_nl_runs.csv '$1 == r { $3 = "C3D8" } 1'; }
asymmetric() { edit "$field" 'NR == 50 { $7 *= 1.01 } 1'; }

mutant "a curve without its third load level" drop_level
mutant "a reaction of the wrong sign" wrong_reaction
mutant "a curve that turns back" turns_back
mutant "the finest level 5 % softer (curve and field)" softer
mutant "a field that is not the curve's end" stale_field
mutant "a field 1 % off its symmetry at one point" asymmetric
mutant "a small-load run 1 % off the linear solution" small_off
mutant "a run logged with another element" other_element
n=8
if [ -n "$graded" ]; then
    mutant "the finest graded level 5 % softer ($grun)" graded_softer
    n=9
fi
rm -rf "$tmp"
[ "$fails" = 0 ] || { echo "FAIL: $fails broken copies accepted"; exit 1; }
echo "ok: committed NLGEOM data valid, $n broken copies rejected"

#!/bin/sh
# check_data.sh CHECKER SCENE DATA TMP LEVELS NUS SWEEP_LEVEL RMS_BOUND POINT_BOUND
#
# Runs the data checker (check_data.c) on the committed CalculiX reference
# data of SCENE (block48 or beam40), which must pass, then on copies broken
# in one way each, which must fail: a pass means something only if these
# are caught.
set -u
checker=$1 scene=$2 data=$3 tmp=$4 levels=$5 nus=$6 sweep=$7 rms=$8 bound=$9
finest=${levels##*,} coarsest=${levels%%,*}
fails=0
# shellcheck source=tests/calculix/expect_rejected.sh
. "$(dirname "$0")/expect_rejected.sh"

check() { "$checker" "$scene" "$1" "$levels" "$nus" "$sweep" "$rms" "$bound"; }

check "$data" || exit 1

# mutant NAME FILE FILTER...: copy the data, pass FILE through FILTER,
# expect the checker to reject the copy (exit 1).
mutant() {
    name=$1 file=${scene}_$2
    shift 2
    rm -rf "$tmp" && mkdir -p "$tmp" && cp "$data"/"$scene"_*.csv "$tmp"/
    "$@" < "$data/$file" > "$tmp/$file"
    expect_rejected "$name"
}

mutant "a missing row" "fz_$finest.csv" sed '$d'
mutant "a NaN" "fx_$finest.csv" sed '12s/,[^,]*$/,nan/'
mutant "swapped x and y columns" "fx_$finest.csv" awk -F, -v OFS=, 'NR > 1 { t = $2; $2 = $3; $3 = t } 1'
mutant "a 1 % change at one point of fy" "fy_$finest.csv" awk -F, -v OFS=, 'NR == 15 { $6 *= 1.01 } 1'
mutant "the coarsest fz as the finest" "fz_$finest.csv" cat "$data/${scene}_fz_$coarsest.csv"
mutant "a reaction of the wrong sign" reactions.csv awk -F, -v OFS=, 'NR == 2 { $6 = -$6 } 1'
mutant "a reference naming another level" reference.csv sed "s/_$finest/_$coarsest/"
if [ "$nus" != none ]; then
    nu_ref=0.49 # block48's, the scene with a sweep
    mutant "a stale nu = $nu_ref sweep file" "nu${nu_ref}_fz.csv" awk -F, -v OFS=, 'NR == 62 { $7 *= 1.001 } 1'
fi
rm -rf "$tmp"
[ "$fails" = 0 ]

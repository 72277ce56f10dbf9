#!/bin/sh
# check_data.sh CHECKER DATA TMP LEVELS NUS SWEEP_LEVEL RMS_BOUND NODE61_BOUND
#
# Runs the data checker (check_data.c) on the committed CalculiX reference
# data, which must pass, then on copies broken in one way each, which must
# fail: a pass means something only if these are caught.
set -u
checker=$1 data=$2 tmp=$3 levels=$4 nus=$5 sweep=$6 rms=$7 n61=$8
finest=${levels##*,} coarsest=${levels%%,*}
fails=0

check() { "$checker" "$1" "$levels" "$nus" "$sweep" "$rms" "$n61"; }

check "$data" || exit 1

# mutant NAME FILE FILTER...: copy the data, pass FILE through FILTER,
# expect the checker to reject the copy (exit 1).
mutant() {
    name=$1 file=$2
    shift 2
    rm -rf "$tmp" && mkdir -p "$tmp" && cp "$data"/*.csv "$tmp"/
    "$@" < "$data/$file" > "$tmp/$file"
    check "$tmp" > "$tmp/out" 2>&1
    st=$?
    if [ "$st" = 1 ]; then
        echo "ok:   rejects $name ($(grep -m1 FAIL "$tmp/out"))"
    else
        echo "FAIL: accepted $name (exit $st)"; fails=$((fails + 1))
    fi
}

mutant "a missing row" "block48_fz_$finest.csv" sed '$d'
mutant "a NaN" "block48_fx_$finest.csv" sed '62s/,[^,]*$/,nan/'
mutant "swapped x and y columns" "block48_fx_$finest.csv" \
    awk -F, -v OFS=, 'NR > 1 { t = $2; $2 = $3; $3 = t } 1'
mutant "a 1 % change at one node of fy" "block48_fy_$finest.csv" \
    awk -F, -v OFS=, 'NR == 51 { $6 *= 1.01 } 1'
mutant "the coarsest fz as the finest" "block48_fz_$finest.csv" cat "$data/block48_fz_$coarsest.csv"
mutant "a reaction of the wrong sign" block48_reactions.csv awk -F, -v OFS=, 'NR == 2 { $6 = -$6 } 1'
mutant "a stale nu = 0.49 sweep file" block48_nu0.49_fz.csv awk -F, -v OFS=, 'NR == 62 { $7 *= 1.001 } 1'
mutant "a reference naming another level" block48_reference.csv sed "s/_$finest/_$coarsest/"
rm -rf "$tmp"
[ "$fails" = 0 ]

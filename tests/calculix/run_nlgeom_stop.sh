#!/bin/sh
# run_nlgeom_stop.sh DECK_TOOL WORK DATA — why the fine NLGEOM meshes of
# block48 stop before the full force (docs/calculix-reference.md, "Why the
# fine levels stop"): neo-Hooke path a (3 N along -z, quarter model) on
# graded meshes, one CalculiX run at a time, each writing every node's
# displacement at the printed load levels (box_deck --field), from which
# frd_stretch.awk takes how far the top surface under the load centre is
# compressed.
#
#   NL_STOP_RUNS  "name:fine:least:layers:element:min_fraction ..." (box_deck
#                 --grade fine:least --layers L --layer-ratio 1.6 --element E
#                 --min-fraction M)
# DATA (tests/calculix/data) gets, after each run (the runs so far: a long
# study stopped part way keeps what it measured):
#   block48_nl_stop.csv        run,element,fine,least,layers,patch_mm,min_fraction,
#                              dofs,increments,cutbacks,iterations,reached,seconds
#   block48_nl_stop_field.csv  run,factor,converged,uz,centre,least (node 61's
#                              uz; the top line's in-plane stretch: of the pair
#                              ending at the centre, and the smallest under
#                              the patch), per printed level and for the last
#                              unconverged attempt (converged 0)
# A run whose deck and output are present is not repeated (delete WORK).
set -eu
[ $# -eq 3 ] || { echo "usage: $0 DECK_TOOL WORK DATA (NL_STOP_RUNS in the environment)" >&2; exit 2; }
deck_tool=$1 work=$2 data=$3
here=$(cd "$(dirname "$0")" && pwd)
mkdir -p "$work"
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
echo "run,element,fine,least,layers,patch_mm,min_fraction,dofs,increments,cutbacks,iterations,reached,seconds" > "$tmp/stop.csv"
echo "run,factor,converged,uz,centre,least" > "$tmp/field.csv"
for spec in $NL_STOP_RUNS; do
    IFS=: read -r run fine least layers el minf <<EOT
$spec
EOT
    "$deck_tool" --grade "$fine:$least" --layers "$layers" --layer-ratio 1.6 --element "$el" \
        --material neohooke --nlgeom --increments 10 --force 0,0,-3 --symmetry xy \
        --min-fraction "$minf" --field > "$work/$run.inp.new"
    if cmp -s "$work/$run.inp.new" "$work/$run.inp" && [ -s "$work/$run.time" ]; then
        rm "$work/$run.inp.new"
        echo "calculix: $run: deck unchanged, reusing its results" >&2
    else
        mv "$work/$run.inp.new" "$work/$run.inp"
        rm -f "$work/$run.time"
        echo "calculix: $run ..." >&2
        st=0
        (cd "$work" && OMP_NUM_THREADS=${CCX_THREADS:-1} /usr/bin/time -f "%e" -o "$run.time.new" \
            ccx -i "$run" > "$run.log" 2>&1) || st=$?
        if [ "$st" != 0 ] && ! grep -q "increment size smaller than minimum\|too many cutbacks\|seems to diverge" "$work/$run.log"; then
            echo "calculix: $run failed (exit $st), see $work/$run.log" >&2; exit 1
        fi
        tail -n 1 "$work/$run.time.new" > "$work/$run.time"
        rm "$work/$run.time.new"
    fi
    dofs=$(awk '$1 == "**" && $2 == "SIZE" { print $5 }' "$work/$run.inp")
    sta=$(awk -f "$here/sta_summary.awk" "$work/$run.sta")
    reached=${sta##*,}
    patch=$(awk -v f="$fine" 'BEGIN { printf "%.4g", 2.4 / f }')
    echo "$run,$el,$fine,$least,$layers,$patch,$minf,$dofs,$sta,$(cat "$work/$run.time")" >> "$tmp/stop.csv"
    awk -v xc=24 -v yc=24 -v zt=6 -v r=2.4 -f "$here/frd_stretch.awk" "$work/$run.frd" |
        awk -F, -v OFS=, -v run="$run" -v reached="$reached" \
            '{ print run, $1, ($1 <= reached + 1e-9 ? 1 : 0), $2, $3, $4 }' >> "$tmp/field.csv"
    echo "calculix: $run: reached $reached" >&2
    for f in stop field; do
        name=block48_nl_stop.csv
        [ "$f" = stop ] || name=block48_nl_stop_field.csv
        cp "$tmp/$f.csv" "$data/$name.new" && mv "$data/$name.new" "$data/$name"
    done
done

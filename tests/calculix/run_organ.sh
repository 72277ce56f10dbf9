#!/bin/sh
# run_organ.sh DECK_TOOL SCENE WORK DATA NAME LEVELS...
#
# The CalculiX reference of an organ scene (docs/validation.md, organs):
# one CalculiX run per level, coarse to fine; a level is
# "label:spacing:refine[:grade]" (organ_deck.c; grade 0 or absent: none).  Decks, CalculiX output and
# logs stay in WORK; DATA receives, once every run succeeded,
#   NAME_<label>.csv   the output vertices' displacements under 1 N along
#                      x, y, z (organ_dat.awk)
#   NAME_runs.csv      label,spacing,refine,elements,nodes,dofs,seconds,max_rss_mb
# A run whose deck is unchanged and whose output is present is not repeated
# (delete WORK to force it).  CCX_THREADS (default 1) threads per run;
# DECK_ARGS: more options for every deck (a box's --quantum, an inclusion's
# --inclusion-spacing, a region's --sites); DAT_AWK: the extraction (default
# organ_dat.awk; region_dat.awk for a region's sites).
set -eu
[ $# -ge 6 ] || { echo "usage: $0 DECK_TOOL SCENE WORK DATA NAME LEVEL..." >&2; exit 2; }
deck_tool=$1 scene=$2 work=$3 data=$4 name=$5
shift 5
here=$(cd "$(dirname "$0")" && pwd)
threads=${CCX_THREADS:-1}
. "$here/ccx_cached.sh"
mkdir -p "$work/out"
echo "label,spacing,refine,grade,elements,nodes,dofs,seconds,max_rss_mb" > "$work/out/${name}_runs.csv"
for level in "$@"; do
    label=$(echo "$level" | cut -d: -f1) spacing=$(echo "$level" | cut -d: -f2)
    refine=$(echo "$level" | cut -d: -f3) grade=$(echo "$level:" | cut -d: -f4)
    grade=${grade:-0}
    run=${name}_$label
    if [ "$grade" = 0 ]; then
        "$deck_tool" "$scene" --spacing "$spacing" --refine "$refine" ${DECK_ARGS:-} > "$work/$run.inp.new"
    else
        "$deck_tool" "$scene" --spacing "$spacing" --refine "$refine" --grade "$grade" ${DECK_ARGS:-} \
            > "$work/$run.inp.new"
    fi
    ccx_cached "$work" "$run" "$threads" "%e %M" "spacing $spacing mm, $refine refinement(s)"
    awk -f "$here/${DAT_AWK:-organ_dat.awk}" "$work/$run.inp" "$work/$run.dat" > "$work/out/$run.csv"
    size=$(awk '$1 == "**" && $2 == "SIZE" { print $3 "," $4 "," $5; exit }' "$work/$run.inp")
    read -r seconds kb < "$work/$run.time"
    mb=$(awk -v kb="$kb" 'BEGIN { printf "%.0f", kb / 1024 }')
    echo "$label,$spacing,$refine,$grade,$size,$seconds,$mb" >> "$work/out/${name}_runs.csv"
    echo "calculix: $run: $seconds s, $mb MB" >&2
done
mkdir -p "$data"
cp "$work/out/${name}_runs.csv" "$data/"
for level in "$@"; do
    cp "$work/out/${name}_$(echo "$level" | cut -d: -f1).csv" "$data/"
done
echo "calculix: wrote $data/${name}_*.csv" >&2

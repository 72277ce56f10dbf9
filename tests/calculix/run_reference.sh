#!/bin/sh
# run_reference.sh DECK_TOOL WORK DATA
#
# The linear CalculiX reference study of a box scene (docs/calculix-reference.md):
# one CalculiX run at a time, each with three load steps (fx, fy, fz).
#
# Settings come from the environment (tests/calculix.mk sets them):
#   SCENE        block48 or beam40 (the deck writer's scene; file prefix)
#   NU_REF       Poisson's ratio of the levels (block48 0.49, beam40 0.45)
#   POINT        the output point of the node table (block48 61, beam40 25)
#   LEVELS       "name:divisions:layers ..." coarse to fine, C3D20R
#   NUS          Poisson ratios of the sweep, run at SWEEP_LEVEL ("" = none)
#   LOCK_LEVEL   level of the element comparison: C3D20 (full integration)
#                against C3D20R at NU_REF and 0.499, and fz applied as a
#                *DLOAD pressure against the consistent nodal loads ("" = none)
#   MESH_RUNS    "level:layers:nu ..." extra C3D20R runs on a level's in-plane
#                mesh with another layer count or Poisson ratio
#   GRID_RUNS    "divisions:layers ..." extra C3D20R runs at NU_REF on meshes
#                that are not levels (the accuracy-per-cost table)
#   POINT_LEVELS levels run again with the force on the patch centre alone
#                (as the seed did), to show that a point load does not converge
#   REUSE        1: a run already in DATA/SCENE_runs.csv (same name, element,
#                nu, mesh and load) is taken from DATA instead of run again,
#                so that new runs can be added to the committed study
#
# Decks, CalculiX output and logs stay in WORK.  DATA is written only after
# every run succeeded:
#   SCENE_<case>_<level>.csv, SCENE_nu<nu>_<case>.csv, SCENE_reference.csv,
#   SCENE_runs.csv       run,element,nu,divisions,layers,load,elements,nodes,
#                        dofs,threads,seconds,max_rss_mb  (load: patch,
#                        pressure or point)
#   SCENE_reactions.csv  run,case,fx,fy,fz,rx,ry,rz
#   SCENE_node61.csv     run,element,nu,divisions,layers,load,case,ux,uy,uz
#                        (block48; beam40's is SCENE_node25.csv)
# A run whose deck is unchanged and whose output is present is not repeated
# (delete WORK to force it).  CCX_THREADS (default 1) threads per run.
set -eu
[ $# -eq 3 ] || { echo "usage: $0 DECK_TOOL WORK DATA (settings in the environment)" >&2; exit 2; }
deck_tool=$1 work=$2 data=$3
scene=$SCENE nu_ref=$NU_REF point=$POINT levels=$LEVELS nus=$NUS sweep_level=$SWEEP_LEVEL
lock_level=$LOCK_LEVEL mesh_runs=$MESH_RUNS grid_runs=$GRID_RUNS point_levels=$POINT_LEVELS
reuse=${REUSE:-0}
here=$(cd "$(dirname "$0")" && pwd)
threads=${CCX_THREADS:-1}
. "$here/ccx_cached.sh"
mkdir -p "$work/out"
out=$work/out
table=node$point
echo "run,element,nu,divisions,layers,load,elements,nodes,dofs,threads,seconds,max_rss_mb" > "$out/runs.csv"
echo "run,case,fx,fy,fz,rx,ry,rz" > "$out/reactions.csv"
echo "run,element,nu,divisions,layers,load,case,ux,uy,uz" > "$out/$table.csv"

# level_field NAME FIELD: divisions (2) or layers (3) of a level
level_field() {
    for l in $levels; do
        [ "${l%%:*}" = "$1" ] && { echo "$l" | cut -d: -f"$2"; return; }
    done
    echo "run_reference: level $1 is not in LEVELS" >&2; exit 2
}

# reused RUN ELEMENT NU N LAYERS LOAD: with REUSE=1, copies the committed
# rows of a run with these settings to WORK/out and succeeds
reused() {
    [ "$reuse" = 1 ] && [ -f "$data/${scene}_runs.csv" ] || return 1
    awk -F, -v r="$1" -v e="$2" -v v="$3" -v n="$4" -v l="$5" -v d="$6" \
        '$1 == r && $2 == e && $3 == v && $4 == n && $5 == l && $6 == d { f = 1 } END { exit !f }' \
        "$data/${scene}_runs.csv" || return 1
    grep "^$1," "$data/${scene}_runs.csv" >> "$out/runs.csv"
    grep "^$1," "$data/${scene}_reactions.csv" >> "$out/reactions.csv"
    grep "^$1," "$data/${scene}_$table.csv" >> "$out/$table.csv"
    echo "calculix: $1: taken from $data" >&2
}

# solve RUN DIVISIONS LAYERS NU ELEMENT [DECK OPTIONS...]
solve() {
    run=$1 n=$2 layers=$3 nu=$4 element=$5 load=patch
    shift 5
    case " $* " in *" --pressure "*) load=pressure ;; *" --point "*) load=point ;; esac
    reused "$run" "$element" "$nu" "$n" "$layers" "$load" && return 0
    "$deck_tool" --scene "$scene" --divisions "$n" --layers "$layers" --nu "$nu" --element "$element" "$@" \
        > "$work/$run.inp.new"
    ccx_cached "$work" "$run" "$threads" "%e %M $threads" "$scene ${n} divisions x $layers layers $element, nu = $nu"
    record "$run" "$n" "$layers" "$nu" "$element" "$load"
}

# record RUN N LAYERS NU ELEMENT LOAD: CSV per step, reactions, the point's
# row per case, run line
record() {
    run=$1 n=$2 layers=$3 nu=$4 element=$5 load=$6
    size=$(awk '$1 == "**" && $2 == "SIZE" { print $3 "," $4 "," $5 }' "$work/$run.inp")
    read -r seconds kb used_threads < "$work/$run.time"
    mb=$(awk -v kb="$kb" 'BEGIN { printf "%.0f", kb / 1024 }')
    echo "$run,$element,$nu,$n,$layers,$load,$size,$used_threads,$seconds,$mb" >> "$out/runs.csv"
    echo "calculix: $run: $seconds s, $mb MB" >&2
    # (no pipe: a failed extraction must stop the study under set -e)
    awk -f "$here/support_reaction.awk" -f "$here/dat_reactions.awk" "$work/$run.inp" "$work/$run.dat" \
        > "$out/$run.reactions"
    sed "s/^/$run,/" "$out/$run.reactions" >> "$out/reactions.csv"
    step=0
    for c in $(awk '$1 == "**" && $2 == "STEP" { print $4 }' "$work/$run.inp"); do
        step=$((step + 1))
        awk -v step=$step -f "$here/dat_to_csv.awk" "$work/$run.inp" "$work/$run.dat" > "$out/${run}_$c.csv"
        awk -F, -v p="$run,$element,$nu,$n,$layers,$load,$c" -v k="$point" '$1 == k { print p "," $5 "," $6 "," $7 }' \
            "$out/${run}_$c.csv" >> "$out/$table.csv"
    done
}

# field RUN CASE: a run's output-point file, from this study or (reused) DATA
field() {
    for f in "$out/${1}_$2.csv" "$data/${scene}_$2_$1.csv" "$data/${scene}_nu${1#*_nu}_$2.csv"; do
        [ -f "$f" ] && { echo "$f"; return; }
    done
    echo "run_reference: no $2 field of run $1" >&2; exit 1
}

for l in $levels; do
    name=${l%%:*}
    solve "$name" "$(level_field "$name" 2)" "$(level_field "$name" 3)" "$nu_ref" C3D20R
done
for nu in $nus; do
    [ "$nu" = "$nu_ref" ] && continue
    solve "${sweep_level}_nu$nu" "$(level_field "$sweep_level" 2)" "$(level_field "$sweep_level" 3)" "$nu" C3D20R
done
if [ -n "$lock_level" ]; then
    n=$(level_field "$lock_level" 2) layers=$(level_field "$lock_level" 3)
    [ "$lock_level" = "$sweep_level" ] || solve "${lock_level}_nu0.499" "$n" "$layers" 0.499 C3D20R
    for nu in "$nu_ref" 0.499; do
        solve "${lock_level}_C3D20_nu$nu" "$n" "$layers" "$nu" C3D20
    done
    solve "${lock_level}_pressure" "$n" "$layers" "$nu_ref" C3D20R --cases fz --pressure
    # The pressure run checks the consistent nodal loads: same field expected.
    if [ -f "$out/${lock_level}_pressure_fz.csv" ]; then
        awk -F, 'FNR == 1 { f++; next } f == 1 { for (k = 5; k <= 7; k++) u[$1, k] = $k; next }
                 { for (k = 5; k <= 7; k++) { d = $k - u[$1, k]; if (d < 0) d = -d; if (d > m) m = d } }
                 END { printf "calculix: fz as *DLOAD pressure vs consistent nodal loads: max |du| = %.3g mm\n", m }' \
            "$(field "$lock_level" fz)" "$out/${lock_level}_pressure_fz.csv" >&2
    fi
fi
for r in $mesh_runs; do
    l=$(echo "$r" | cut -d: -f1) layers=$(echo "$r" | cut -d: -f2) nu=$(echo "$r" | cut -d: -f3)
    name=${l}_layers$layers
    [ "$nu" = "$nu_ref" ] || name=${name}_nu$nu
    solve "$name" "$(level_field "$l" 2)" "$layers" "$nu" C3D20R
done
for r in $grid_runs; do
    n=${r%%:*} layers=${r#*:}
    solve "${n}x${layers}" "$n" "$layers" "$nu_ref" C3D20R
done
for l in $point_levels; do
    solve "${l}_point" "$(level_field "$l" 2)" "$(level_field "$l" 3)" "$nu_ref" C3D20R --point
done

# Everything ran: publish.
mkdir -p "$data"
for c in fx fy fz; do
    for l in $levels; do
        f=$(field "${l%%:*}" $c)
        [ "$f" = "$data/${scene}_${c}_${l%%:*}.csv" ] || cp "$f" "$data/${scene}_${c}_${l%%:*}.csv"
    done
    for nu in $nus; do
        run=${sweep_level}_nu$nu
        [ "$nu" = "$nu_ref" ] && run=$sweep_level
        f=$(field "$run" $c)
        [ "$f" = "$data/${scene}_nu${nu}_$c.csv" ] || cp "$f" "$data/${scene}_nu${nu}_$c.csv"
    done
done
finest=$(for l in $levels; do echo "${l%%:*}"; done | tail -n 1)
{ echo "case,level,file"; for c in fx fy fz; do echo "$c,$finest,${scene}_${c}_$finest.csv"; done; } \
    > "$data/${scene}_reference.csv"
for t in runs reactions $table; do cp "$out/$t.csv" "$data/${scene}_$t.csv"; done
echo "calculix: data written to $data" >&2

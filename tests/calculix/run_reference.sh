#!/bin/sh
# run_reference.sh DECK_TOOL WORK DATA
#
# The CalculiX reference study of block48 (docs/calculix-reference.md): one
# CalculiX run at a time, each with three load steps (fx, fy, fz).
#
# Settings come from the environment (tests/calculix.mk sets them):
#   LEVELS       "name:divisions:layers ..." coarse to fine, nu = 0.49, C3D20R
#   NUS          Poisson ratios of the sweep, run at SWEEP_LEVEL
#   LOCK_LEVEL   level of the element comparison: C3D20 (full integration)
#                against C3D20R at nu = 0.49 and 0.499, and fz applied as
#                a *DLOAD pressure against the consistent nodal loads
#   MESH_RUNS    "level:layers:nu ..." extra C3D20R runs on a level's in-plane
#                mesh with another layer count or Poisson ratio: through-
#                thickness convergence, and whether nu = 0.499 depends on h
#   POINT_LEVELS levels run again with the force on node 61 alone (as the
#                seed did), to show that a point load does not converge
#
# Decks, CalculiX output and logs stay in WORK (build/calculix).  DATA
# (tests/calculix/data) is written only after every run succeeded:
#   block48_<case>_<level>.csv, block48_nu<nu>_<case>.csv, block48_reference.csv,
#   block48_runs.csv       run,element,nu,divisions,layers,load,elements,nodes,
#                          dofs,threads,seconds,max_rss_mb  (load: patch,
#                          pressure or point)
#   block48_reactions.csv  run,case,fx,fy,fz,rx,ry,rz
#   block48_node61.csv     run,element,nu,divisions,layers,load,case,ux,uy,uz
# A run whose deck is unchanged and whose output is present is not repeated
# (delete WORK to force it).  CCX_THREADS (default 1) threads per run.
set -eu
[ $# -eq 3 ] || { echo "usage: $0 DECK_TOOL WORK DATA (settings in the environment)" >&2; exit 2; }
deck_tool=$1 work=$2 data=$3
levels=$LEVELS nus=$NUS sweep_level=$SWEEP_LEVEL lock_level=$LOCK_LEVEL mesh_runs=$MESH_RUNS
point_levels=$POINT_LEVELS
here=$(cd "$(dirname "$0")" && pwd)
threads=${CCX_THREADS:-1}
. "$here/ccx_cached.sh"
mkdir -p "$work/out"
out=$work/out
echo "run,element,nu,divisions,layers,load,elements,nodes,dofs,threads,seconds,max_rss_mb" > "$out/runs.csv"
echo "run,case,fx,fy,fz,rx,ry,rz" > "$out/reactions.csv"
echo "run,element,nu,divisions,layers,load,case,ux,uy,uz" > "$out/node61.csv"

# level_field NAME FIELD: divisions (2) or layers (3) of a level
level_field() {
    for l in $levels; do
        [ "${l%%:*}" = "$1" ] && { echo "$l" | cut -d: -f"$2"; return; }
    done
    echo "run_reference: level $1 is not in LEVELS" >&2; exit 2
}

# solve RUN DIVISIONS LAYERS NU ELEMENT [DECK OPTIONS...]
solve() {
    run=$1 n=$2 layers=$3 nu=$4 element=$5 load=patch
    shift 5
    case " $* " in *" --pressure "*) load=pressure ;; *" --point "*) load=point ;; esac
    "$deck_tool" --divisions "$n" --layers "$layers" --nu "$nu" --element "$element" "$@" \
        > "$work/$run.inp.new"
    ccx_cached "$work" "$run" "$threads" "%e %M $threads" "${n}x${n}x$layers $element, nu = $nu"
    record "$run" "$n" "$layers" "$nu" "$element" "$load"
}

# record RUN N LAYERS NU ELEMENT LOAD: CSV per step, reactions, node 61, run line
record() {
    run=$1 n=$2 layers=$3 nu=$4 element=$5 load=$6
    size=$(awk '$1 == "**" && $2 == "SIZE" { print $3 "," $4 "," $5 }' "$work/$run.inp")
    read -r seconds kb used_threads < "$work/$run.time"
    mb=$(awk -v kb="$kb" 'BEGIN { printf "%.0f", kb / 1024 }')
    echo "$run,$element,$nu,$n,$layers,$load,$size,$used_threads,$seconds,$mb" >> "$out/runs.csv"
    echo "calculix: $run: $seconds s, $mb MB" >&2
    # (no pipe: a failed extraction must stop the study under set -e)
    awk -f "$here/dat_reactions.awk" "$work/$run.inp" "$work/$run.dat" > "$out/$run.reactions"
    sed "s/^/$run,/" "$out/$run.reactions" >> "$out/reactions.csv"
    step=0
    for c in $(awk '$1 == "**" && $2 == "STEP" { print $4 }' "$work/$run.inp"); do
        step=$((step + 1))
        awk -v step=$step -f "$here/dat_to_csv.awk" "$work/$run.inp" "$work/$run.dat" > "$out/${run}_$c.csv"
        awk -F, -v p="$run,$element,$nu,$n,$layers,$load,$c" '$1 == 61 { print p "," $5 "," $6 "," $7 }' \
            "$out/${run}_$c.csv" >> "$out/node61.csv"
    done
}

nu_ref=0.49
for l in $levels; do
    name=${l%%:*}
    solve "$name" "$(level_field "$name" 2)" "$(level_field "$name" 3)" $nu_ref C3D20R
done
for nu in $nus; do
    [ "$nu" = $nu_ref ] && continue
    solve "${sweep_level}_nu$nu" "$(level_field "$sweep_level" 2)" "$(level_field "$sweep_level" 3)" "$nu" C3D20R
done
n=$(level_field "$lock_level" 2) layers=$(level_field "$lock_level" 3)
[ "$lock_level" = "$sweep_level" ] || solve "${lock_level}_nu0.499" "$n" "$layers" 0.499 C3D20R
for nu in $nu_ref 0.499; do
    solve "${lock_level}_C3D20_nu$nu" "$n" "$layers" "$nu" C3D20
done
solve "${lock_level}_pressure" "$n" "$layers" $nu_ref C3D20R --cases fz --pressure
# The pressure run checks the consistent nodal loads: same field expected.
awk -F, 'FNR == 1 { f++; next } f == 1 { for (k = 5; k <= 7; k++) u[$1, k] = $k; next }
         { for (k = 5; k <= 7; k++) { d = $k - u[$1, k]; if (d < 0) d = -d; if (d > m) m = d } }
         END { printf "calculix: fz as *DLOAD pressure vs consistent nodal loads: max |du| = %.3g mm over the 121 nodes\n", m }' \
    "$out/${lock_level}_fz.csv" "$out/${lock_level}_pressure_fz.csv" >&2
for r in $mesh_runs; do
    l=$(echo "$r" | cut -d: -f1) layers=$(echo "$r" | cut -d: -f2) nu=$(echo "$r" | cut -d: -f3)
    name=${l}_layers$layers
    [ "$nu" = $nu_ref ] || name=${name}_nu$nu
    solve "$name" "$(level_field "$l" 2)" "$layers" "$nu" C3D20R
done
for l in $point_levels; do
    solve "${l}_point" "$(level_field "$l" 2)" "$(level_field "$l" 3)" $nu_ref C3D20R --point
done

# Everything ran: publish.
mkdir -p "$data"
for c in fx fy fz; do
    for l in $levels; do cp "$out/${l%%:*}_$c.csv" "$data/block48_${c}_${l%%:*}.csv"; done
    for nu in $nus; do
        run=${sweep_level}_nu$nu
        [ "$nu" = $nu_ref ] && run=$sweep_level
        cp "$out/${run}_$c.csv" "$data/block48_nu${nu}_$c.csv"
    done
done
finest=$(for l in $levels; do echo "${l%%:*}"; done | tail -n 1)
{ echo "case,level,file"; for c in fx fy fz; do echo "$c,$finest,block48_${c}_$finest.csv"; done; } \
    > "$data/block48_reference.csv"
for t in runs reactions node61; do cp "$out/$t.csv" "$data/block48_$t.csv"; done
echo "calculix: data written to $data" >&2

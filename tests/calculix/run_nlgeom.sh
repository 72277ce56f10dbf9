#!/bin/sh
# run_nlgeom.sh DECK_TOOL WORK DATA
#
# The large-deformation (NLGEOM) CalculiX reference of block48
# (docs/calculix-reference.md, "Large deformation"): for every material,
# load path and mesh level one run, the force ramped from zero and node 61's
# displacement and the reaction printed at equal load levels.  One CalculiX
# run at a time.
#
# Settings come from the environment (tests/calculix.mk sets them):
#   NL_LEVELS     "name:divisions:layers ..." coarse to fine
#   NL_ELEMENT    element of the study (C3D20 or C3D20R)
#   NL_MATERIALS  "neohooke svk" (svk: *ELASTIC under NLGEOM)
#   NL_PATHS      "name:FX,FY,FZ:symmetry ..." (symmetry: none, y or xy, the
#                 mirror planes the path allows, used to cut the mesh)
#   NL_LOAD_LEVELS printed load levels per path (equal steps of the force)
#   NL_COMPARE    "level:element ..." every material and path again with
#                 another element on that level
#   NL_EXTRA      "divisions:layers:material:path[:element] ..." single runs
#                 on other meshes (through-thickness and in-plane refinement
#                 apart) or with another element, named nl_MAT_PATH_DxDxL
#                 (+ _ELEMENT when it is not the study's)
#   NL_GRADED     "name:fine:least:layers:ratio ..." graded levels, coarse to
#                 fine (box_deck --grade fine:least --layers L --layer-ratio R:
#                 small elements under and around the patch, coarse towards
#                 the clamped faces, thin layers at the top)
#   NL_GRADED_RUNS "material:path ..." the runs on every graded level, named
#                 nl_MAT_PATH_NAME
#   NL_SMALL      levels of the small-load runs: each path at each factor of
#                 NL_SMALL_FACTORS times its force, in one increment, beside
#                 a linear run of the same mesh and element (the small-load
#                 limit: the difference must shrink in proportion to the force)
#
# Decks, CalculiX output and logs stay in WORK (build/calculix/nl).  DATA
# (tests/calculix/data) is written only after every run ended:
#   block48_nl_runs.csv    run,material,element,path,divisions,layers,symmetry,
#                          elements,nodes,dofs,increments,cutbacks,iterations,
#                          reached,threads,seconds,max_rss_mb
#   block48_nl_curves.csv  run,factor,fx,fy,fz,ux,uy,uz,rx,ry,rz (node 61 and
#                          the reaction at each printed load level)
#   block48_nl_<material>_<path>_<level>.csv  the 121 output points at the
#                          last printed load level of the study's element
#   block48_nl_linear.csv  run,element,divisions,layers,case,ux,uy,uz (node 61
#                          of the linear runs beside the small-load runs)
# A run ends normally when it reaches the full force, or when CalculiX cannot
# converge an increment even after cutting it back ("reached" < 1 then: the
# path's last converged load factor); any other CalculiX error stops the
# study.  A run whose deck is unchanged and whose output is present is not
# repeated (delete WORK to force it).  CCX_THREADS (default 1) threads a run.
set -eu
[ $# -eq 3 ] || { echo "usage: $0 DECK_TOOL WORK DATA (settings in the environment)" >&2; exit 2; }
deck_tool=$1 work=$2 data=$3
here=$(cd "$(dirname "$0")" && pwd)
threads=${CCX_THREADS:-1}
mkdir -p "$work/out"
out=$work/out
echo "run,material,element,path,divisions,layers,symmetry,elements,nodes,dofs,increments,cutbacks,iterations,reached,threads,seconds,max_rss_mb" > "$out/runs.csv"
echo "run,factor,fx,fy,fz,ux,uy,uz,rx,ry,rz" > "$out/curves.csv"
echo "run,element,divisions,layers,case,ux,uy,uz" > "$out/linear.csv"

field() { echo "$1" | cut -d: -f"$2"; }

# ccx_run RUN: runs CalculiX on WORK/RUN.inp unless its results are there;
# returns 0 when it finished or stopped for want of convergence.
ccx_run() {
    run=$1
    if cmp -s "$work/$run.inp.new" "$work/$run.inp" && [ -s "$work/$run.time" ]; then
        rm "$work/$run.inp.new"
        echo "calculix: $run: deck unchanged, reusing its results" >&2
        return 0
    fi
    mv "$work/$run.inp.new" "$work/$run.inp"
    rm -f "$work/$run.dat" "$work/$run.sta" "$work/$run.time"
    echo "calculix: $run ..." >&2
    st=0
    (cd "$work" && OMP_NUM_THREADS=$threads /usr/bin/time -f "%e %M $threads" -o "$run.time.new" \
        ccx -i "$run" > "$run.log" 2>&1) || st=$?
    if [ "$st" != 0 ] && ! grep -q "increment size smaller than minimum\|too many cutbacks\|seems to diverge" "$work/$run.log"; then
        echo "calculix: $run failed (exit $st), see $work/$run.log" >&2; exit 1
    fi
    [ "$st" = 0 ] || echo "calculix: $run: no convergence below the full force" >&2
    tail -n 1 "$work/$run.time.new" > "$work/$run.time"
    rm "$work/$run.time.new"
}

# nonlinear RUN MATERIAL ELEMENT PATH FORCE SYMMETRY MESH LEVELS
# (MESH: the deck tool's mesh options, "--divisions N --layers L" or a grading)
nonlinear() {
    run=$1 mat=$2 el=$3 path=$4 force=$5 sym=$6 mesh=$7 levels=$8
    material=$mat
    [ "$mat" = svk ] && material=elastic
    symopt=""
    [ "$sym" = none ] || symopt="--symmetry $sym"
    # shellcheck disable=SC2086
    "$deck_tool" $mesh --element "$el" --material "$material" \
        --nlgeom --increments "$levels" --force "$force" $symopt > "$work/$run.inp.new"
    ccx_run "$run"
    # divisions (elements along x of the whole box) and layers, from the deck
    n=$(awk 'NR == 2 { print $2; exit }' "$work/$run.inp")
    layers=$(awk 'NR == 2 { print $6; exit }' "$work/$run.inp")
    size=$(awk '$1 == "**" && $2 == "SIZE" { print $3 "," $4 "," $5 }' "$work/$run.inp")
    sta=$(awk -f "$here/sta_summary.awk" "$work/$run.sta")
    read -r seconds kb used < "$work/$run.time"
    mb=$(awk -v kb="$kb" 'BEGIN { printf "%.0f", kb / 1024 }')
    echo "$run,$mat,$el,$path,$n,$layers,$sym,$size,$sta,$used,$seconds,$mb" >> "$out/runs.csv"
    awk -v point=61 -f "$here/support_reaction.awk" -f "$here/dat_curve.awk" \
        "$work/$run.inp" "$work/$run.dat" > "$out/$run.curve"
    sed "s/^/$run,/" "$out/$run.curve" >> "$out/curves.csv"
    blocks=$(wc -l < "$out/$run.curve")
    [ "$blocks" -gt 0 ] || { echo "calculix: $run printed no load level" >&2; exit 1; }
    awk -v step="$blocks" -f "$here/dat_to_csv.awk" "$work/$run.inp" "$work/$run.dat" > "$out/$run.csv"
    echo "calculix: $run: $seconds s, $mb MB, increments,cutbacks,iterations,reached = $sta" >&2
}

# linear RUN ELEMENT DIVISIONS LAYERS: fx and fz, node 61
linear() {
    run=$1 el=$2 n=$3 layers=$4
    "$deck_tool" --divisions "$n" --layers "$layers" --element "$el" --cases fx,fz > "$work/$run.inp.new"
    ccx_run "$run"
    step=0
    for c in fx fz; do
        step=$((step + 1))
        awk -v step=$step -f "$here/dat_to_csv.awk" "$work/$run.inp" "$work/$run.dat" |
            awk -F, -v p="$run,$el,$n,$layers,$c" '$1 == 61 { print p "," $5 "," $6 "," $7 }' >> "$out/linear.csv"
    done
}

level_of() {
    for l in $NL_LEVELS; do
        [ "${l%%:*}" = "$1" ] && { echo "$l"; return; }
    done
    echo "run_nlgeom: level $1 is not in NL_LEVELS" >&2; exit 2
}

# every material and path on one level with one element; SUFFIX names runs
sweep() {
    l=$1 el=$2 suffix=$3 scale=$4 levels=$5
    name=${l%%:*} n=$(field "$l" 2) layers=$(field "$l" 3)
    for mat in $NL_MATERIALS; do
        for p in $NL_PATHS; do
            path=$(field "$p" 1) sym=$(field "$p" 3)
            force=$(field "$p" 2 | awk -F, -v s="$scale" '{ printf "%.10g,%.10g,%.10g", s * $1, s * $2, s * $3 }')
            nonlinear "nl_${mat}_${path}_$name$suffix" "$mat" "$el" "$path$( [ "$scale" = 1 ] || echo "_s$scale")" \
                "$force" "$sym" "--divisions $n --layers $layers" "$levels"
        done
    done
}

for l in $NL_LEVELS; do
    sweep "$l" "$NL_ELEMENT" "" 1 "$NL_LOAD_LEVELS"
done
for c in $NL_COMPARE; do
    sweep "$(level_of "${c%%:*}")" "${c#*:}" "_${c#*:}" 1 "$NL_LOAD_LEVELS"
done
for e in $NL_EXTRA; do
    n=$(field "$e" 1) layers=$(field "$e" 2) mat=$(field "$e" 3) path=$(field "$e" 4)
    el=$(field "$e" 5) suffix=""
    [ -n "$el" ] && [ "$el" != "$NL_ELEMENT" ] && suffix=_$el
    p=$(for q in $NL_PATHS; do [ "$(field "$q" 1)" != "$path" ] || echo "$q"; done)
    [ -n "$p" ] || { echo "run_nlgeom: path $path of NL_EXTRA is not in NL_PATHS" >&2; exit 2; }
    nonlinear "nl_${mat}_${path}_${n}x${n}x$layers$suffix" "$mat" "${el:-$NL_ELEMENT}" "$path" \
        "$(field "$p" 2)" "$(field "$p" 3)" "--divisions $n --layers $layers" "$NL_LOAD_LEVELS"
done
# path_of NAME: the NL_PATHS entry of path NAME
path_of() {
    for q in $NL_PATHS; do [ "$(field "$q" 1)" != "$1" ] || { echo "$q"; return; }; done
    echo "run_nlgeom: path $1 is not in NL_PATHS" >&2; exit 2
}
for g in ${NL_GRADED:-}; do
    name=$(field "$g" 1)
    mesh="--grade $(field "$g" 2):$(field "$g" 3) --layers $(field "$g" 4) --layer-ratio $(field "$g" 5)"
    for r in ${NL_GRADED_RUNS:-}; do
        mat=$(field "$r" 1) p=$(path_of "$(field "$r" 2)")
        nonlinear "nl_${mat}_$(field "$p" 1)_$name" "$mat" "$NL_ELEMENT" "$(field "$p" 1)" \
            "$(field "$p" 2)" "$(field "$p" 3)" "$mesh" "$NL_LOAD_LEVELS"
    done
done
for s in $NL_SMALL; do
    l=$(level_of "$s")
    for f in $NL_SMALL_FACTORS; do
        sweep "$l" "$NL_ELEMENT" "_s$f" "$f" 1
    done
    linear "linear_${s}_$NL_ELEMENT" "$NL_ELEMENT" "$(field "$l" 2)" "$(field "$l" 3)"
done

# Everything ran: publish.
mkdir -p "$data"
for l in $NL_LEVELS; do
    for mat in $NL_MATERIALS; do
        for p in $NL_PATHS; do
            cp "$out/nl_${mat}_$(field "$p" 1)_${l%%:*}.csv" "$data/block48_nl_${mat}_$(field "$p" 1)_${l%%:*}.csv"
        done
    done
done
for g in ${NL_GRADED:-}; do
    for r in ${NL_GRADED_RUNS:-}; do
        f=block48_nl_$(field "$r" 1)_$(field "$r" 2)_$(field "$g" 1).csv
        cp "$out/${f#block48_}" "$data/$f"
    done
done
for t in runs curves linear; do cp "$out/$t.csv" "$data/block48_nl_$t.csv"; done
echo "calculix: data written to $data" >&2

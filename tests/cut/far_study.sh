#!/bin/sh
# far_study.sh — acceptance 2 of issue 17 measured (docs/cutting.md, "Far
# from the cut"): cut vs uncut solves of the slit along the load, by
# method, integration, grid, Gauss points and where the cut lies.
#   far_study.sh CUT_TOOL OUT.md
# Writes a markdown table to OUT.md (via a temporary file).
set -euf # no globbing: the cut paths' brackets
tool=$1
out=$2
S=tests/cut/slit_parallel.yaml
W=tests/cut/slit_parallel_weak.yaml
OFF='cuts.0.path=[[5.3,5.3],[15.3,5.3]] cuts.0.depth=4.7'
tmp=$out.tmp
trap 'rm -f "$tmp"' EXIT

row() { # label scene grid extra-settings...
    label=$1 scene=$2 g=$3
    shift 3
    t0=$(date +%s.%N)
    # shellcheck disable=SC2068
    res=$(nice "$tool" far --bound=1 "$scene" geometry.grid="$g" solver.cells="$g" $@ || true)
    t1=$(date +%s.%N)
    echo "$res" | awk -v label="$label" -v g="$g" -v t0="$t0" -v t1="$t1" '
        /outside every affected support/ {
            match($0, /: [0-9]+ nodes, [0-9]+ outside/); split(substr($0, RSTART + 2, RLENGTH), a, " ")
            nodes = a[1]; far = a[3]
            match($0, /displacement: [^ ]+ there/); split(substr($0, RSTART, RLENGTH), b, " ")
            dfar = b[2]
            match($0, /[-0-9.e+]+ over all nodes/); split(substr($0, RSTART, RLENGTH), c, " ")
            dall = c[1]
        }
        /u_reference/ { n = split($0, c, " "); e0 = c[n - 2]; sub(",", "", e0); ec = c[n] }
        END {
            gsub(",", " x ", g)
            printf "| %s | %s | %s of %s | %s | %s | %s | %s | %.1f |\n", label, g, (far > 0 ? far : 0), nodes,
                   (far > 0 ? dfar : "(none)"), dall, e0, ec, t1 - t0
        }'
}

{
    echo "| solve | nodes | outside every affected support | cut vs uncut there | over all nodes | uncut vs exact | cut vs exact | time (s) |"
    echo "|---|---|---|---|---|---|---|---|"
    for g in ${GRIDS:-16,8,8 24,12,12 32,16,16}; do
        row "rpim-galerkin, rollers on nodes, Gauss 3" $S $g
        row "rpim-galerkin, rollers on nodes, VCI" $S $g solver.integration=vci
        row "efg-galerkin, rollers on faces (Nitsche), Gauss 3" $W $g
        row "efg-galerkin, rollers on faces (Nitsche), VCI" $W $g solver.integration=vci
    done
    if [ -z "${GRIDS:-}" ]; then # GRIDS given: a quick look at those grids only
        row "rpim-galerkin, rollers on nodes, Gauss 2" $S 16,8,8 solver.gauss=2
        row "rpim-galerkin, rollers on nodes, Gauss 5" $S 16,8,8 solver.gauss=5
        row "efg-galerkin, rollers on faces, Gauss 5" $W 16,8,8 solver.gauss=5
        row "rpim-galerkin, rollers on faces (Nitsche), Gauss 3" $W 16,8,8 solver.method=rpim-galerkin solver.bc=nitsche
        row "rpim-galerkin, rollers on faces (Nitsche), VCI" $W 16,8,8 solver.method=rpim-galerkin solver.bc=nitsche solver.integration=vci
        row "rpim-galerkin, Gauss 3, cut off the cell faces" $S 16,8,8 $OFF
        row "rpim-galerkin, VCI, cut off the cell faces" $S 16,8,8 solver.integration=vci $OFF
        row "efg-galerkin, Gauss 3, cut off the cell faces" $W 16,8,8 $OFF
        row "efg-galerkin, VCI, cut off the cell faces" $W 16,8,8 solver.integration=vci $OFF
    fi
} > "$tmp"
mv "$tmp" "$out"
trap - EXIT
cat "$out"

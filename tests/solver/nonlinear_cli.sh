#!/bin/sh
# nonlinear_cli.sh TISSUEFIT — `tissuefit solve` with nonlinear laws and
# load histories: outputs (CSV per step, ParaView .pvd + .vtu), exit
# statuses, messages naming the load step, nothing written on failure.
set -u
tool=$1
. "$(dirname "$0")/../cli/expect.sh"
K=tests/solver/kelvin_block48.yaml
SMALL="--set geometry.grid=7,7,3 --set contact.0.node=25"

expect 0 "neo-Hookean block48, 2 N down" -- "$tool" -q solve tests/solver/block48_seed.yaml $SMALL \
    --set material.law=neo-hookean --force 0,0,-2 -o "$tmp/w/nh.csv"
check "every node" test "$(wc -l <"$tmp/w/nh.csv")" = 148
"$tool" -q solve tests/solver/block48_seed.yaml $SMALL --force 0,0,-2 -o "$tmp/w/lin.csv"
check "node 25 moves down, not as far as the linear law says" sh -c "
    nl=\$(awk -F, '\$1 == 25 { print \$7 }' '$tmp/w/nh.csv')
    li=\$(awk -F, '\$1 == 25 { print \$7 }' '$tmp/w/lin.csv')
    awk -v a=\$nl -v b=\$li 'BEGIN { exit !(a < -1 && a != b) }'"
rm -f "$tmp/w"/*

expect 0 "Kelvin history to files" -- "$tool" solve $K -o "$tmp/w/k.csv" --vtk "$tmp/w/k.pvd"
check "CSV per step" sh -c "head -1 '$tmp/w/k.csv' | grep -qx 'step,time,node,x,y,z,ux,uy,uz'"
# steps: the step at 0, 0.5, 1, the release at 1 (two samples), 1.5, 2
check "six steps of 147 nodes" test "$(wc -l <"$tmp/w/k.csv")" = $((6 * 147 + 1))
check "creep: node 25 sinks while the force is held" awk -F, '
    $3 == 25 && $1 == 1 { a = $9 } $3 == 25 && $1 == 3 { b = $9 } END { exit !(b < a && a < 0) }' "$tmp/w/k.csv"
check "recovery after the release" awk -F, '
    $3 == 25 && $1 == 4 { a = $9 } $3 == 25 && $1 == 6 { b = $9 } END { exit !(a < b && b < 0) }' "$tmp/w/k.csv"
check "a .vtu per step" test "$(ls "$tmp/w" | grep -c '^k_00[0-9][0-9].vtu$')" = 6
check "the collection names them" test "$(grep -c 'file="k_00' "$tmp/w/k.pvd")" = 6
check "progress and the Newton summary on stderr" grep -q "Newton:" "$tmp/err"
check "no temporary files" sh -c "! ls '$tmp/w' | grep -q tmp"
rm -f "$tmp/w"/*
expect 2 "--outputs with a history" -- "$tool" -q solve $K -o "$tmp/w/k.csv" --outputs "$tmp/w/o.csv"
says "--outputs with a history" "solve: --outputs writes one solve's outputs, and $K has a history"
nothing_written "--outputs with a history"
sed '/^history:/,$d' $K >"$tmp/nohist.yaml"
expect 0 "Kelvin without history: the relaxed solve" -- "$tool" -q solve "$tmp/nohist.yaml" \
    --force 0,0,-0.5 -o "$tmp/w/r.csv"
check "one row per node" test "$(wc -l <"$tmp/w/r.csv")" = 148
rm -f "$tmp/w"/*

printf 'time,fx,fy,fz\n0,0,0,-0.2\n1,0,0,-0.4\n' >"$tmp/w/table.csv"
sed "s|    - {kind: release}||; s|  segments:|  table: table.csv|; /kind: step/d; /kind: hold/d; /force: \[0, 0, -0.5\]/d" \
    $K >"$tmp/w/t.yaml"
expect 0 "a table of forces next to the scene" -- "$tool" -q solve "$tmp/w/t.yaml" -o "$tmp/w/t.csv"
check "its steps" test "$(wc -l <"$tmp/w/t.csv")" = $((5 * 147 + 1))
rm -f "$tmp/w"/*

expect 2 "a time series into a .vtu" -- "$tool" solve $K -o "$tmp/w/a.csv" --vtk "$tmp/w/a.vtu"
check "asks for .pvd" grep -q "pvd" "$tmp/err"
sed 's/{kind: hold, time: 1}/{kind: hold}/' $K >"$tmp/h.yaml"
expect 2 "a hold without its time" -- "$tool" solve "$tmp/h.yaml" -o "$tmp/w/a.csv"
check "names file, line and field" grep -q "h.yaml:.*history.segments.1.time" "$tmp/err"
sed 's/{kind: step, to: 1}/{kind: step, to: 1, period: 2}/' $K >"$tmp/p.yaml"
expect 2 "a key that does not belong" -- "$tool" solve "$tmp/p.yaml" -o "$tmp/w/a.csv"
check "names it" grep -q "history.segments.0.period" "$tmp/err"
expect 2 "a material key of another law" -- "$tool" solve $K --set material.E=1 -o "$tmp/w/a.csv"
check "names material.E" grep -q "material.E" "$tmp/err"
nothing_written "bad input"

expect 1 "a history whose force crushes the block" -- "$tool" solve $K \
    --set history.force=0,0,-60 --set solver.newton.cuts=3 -o "$tmp/w/a.csv" --vtk "$tmp/w/a.pvd"
check "names the load step and the force" grep -q "load step .*force (0, 0, -" "$tmp/err"
nothing_written "a failed Newton solve"

# St Venant-Kirchhoff softens in compression and has a limit point (near
# 2.67 N down on the seed grid): past it the solve must end, within a
# bounded time, naming the step, the force and the place.  block48_nh on the
# seed's 11 x 11 x 3 grid, uniform (the shipped scene's cloud is finer).
expect 1 "St Venant-Kirchhoff past its limit point" -- timeout 120 "$tool" solve \
    coeffs/block48_nh.yaml --set geometry.grid=11,11,3 --set geometry.grading=1,1,1 \
    --set material.law=svk --force 0,0,-3 -o "$tmp/w/a.csv"
check "names the load step, the force and the place" \
    grep -q "load step [0-9]* (0.8[0-9]* of the way.*force (0, 0, -2\.[0-9]*) N at top-centre).* mm after 10 step cuts" "$tmp/err"
nothing_written "a solve past the limit point"

finish "nonlinear cli"

#!/bin/sh
# cli.sh TISSUEFIT — `tissuefit solve` and `tissuefit verify` on the command
# line: help, outputs, exit statuses, nothing written on bad input.
set -u
tool=$1
. "$(dirname "$0")/../cli/expect.sh"
B=tests/solver/block48_seed.yaml

expect 0 "solve --help" -- "$tool" solve --help
check "solve --help names --set" grep -q -- "--set KEY=VALUE" "$tmp/out"
expect 0 "verify --help" -- "$tool" verify --help
check "verify --help names the table" grep -q "level,nodes,dofs,error_l2,error_energy,rate" "$tmp/out"
check "--help lists solve" sh -c "'$tool' --help | grep -q '^  solve'"

expect 0 "solve block48, CSV on stdout" -- "$tool" -q solve $B --force 0,0,-1
check "CSV header" sh -c "head -1 '$tmp/out' | grep -qx 'node,x,y,z,ux,uy,uz'"
check "363 nodes" test "$(wc -l <"$tmp/out")" = 364
check "node 61 at the top centre, pushed down" \
    awk -F, '$1 == 61 { ok = ($2 == 24 && $3 == 24 && $4 == 6 && $7 < -1) } END { exit !ok }' "$tmp/out"
check "-q is quiet" test ! -s "$tmp/err"
expect 0 "solve to files" -- "$tool" solve $B --force 1,0,0 -o "$tmp/w/u.csv" --vtk "$tmp/w/u.vtu"
check "progress on stderr" grep -q "factorisation" "$tmp/err"
check "VTU holds every node" grep -q 'NumberOfPoints="363" NumberOfCells="200"' "$tmp/w/u.vtu"
check "VTU holds displacements" grep -q 'Name="displacement"' "$tmp/w/u.vtu"
check "no temporary files" sh -c "! ls '$tmp/w' | grep -q tmp"
rm -f "$tmp/w"/*
expect 0 "solve with overrides" -- "$tool" -q solve $B --set geometry.grid=5,5,2 --set contact.0.node=13 --force 0,0,-1 -o "$tmp/w/s.csv"
check "overrides reach the grid" test "$(wc -l <"$tmp/w/s.csv")" = 51
rm -f "$tmp/w"/*
expect 0 "solve the cantilever (scene loads only)" -- "$tool" -q solve coeffs/cantilever.yaml -o "$tmp/w/c.csv"
check "cantilever: 170 nodes, the free end (x = 48) deflected along +y" \
    awk -F, 'NR > 1 { n++ } $2 == 48 && $6 > 0 { tip++ } END { exit !(n == 170 && tip > 0) }' "$tmp/w/c.csv"
rm -f "$tmp/w"/*

# sites by position: outputs at points between nodes, the header names them
A=tests/solver/block48_at.yaml
expect 0 "solve, outputs at points between nodes" -- "$tool" -q solve $A --set geometry.grid=20,20,5 --force 0,0,-1 -o "$tmp/w/a.csv" --outputs "$tmp/w/o.csv"
check "121 output points" test "$(wc -l <"$tmp/w/o.csv")" = 122
check "output 61 at the top centre, pushed down" \
    awk -F, '$1 == 61 { ok = ($2 == 24 && $3 == 24 && $4 == 6 && $7 < -2) } END { exit !ok }' "$tmp/w/o.csv"
rm -f "$tmp/w"/*
expect 0 "fit, outputs and contact by position" -- "$tool" -q fit $A -o "$tmp/w/b48at.h"
check "header: 121 output points" grep -q "define TFIT_B48AT_OUTPUT_POINTS_N 121u" "$tmp/w/b48at.h"
check "header: the contact point" grep -q "define TFIT_B48AT_CONTACT_POINT_MM" "$tmp/w/b48at.h"
check "header: coefficients name points" grep -q "/\* point 61 z \*/" "$tmp/w/b48at.h"
cat >"$tmp/pts.c" <<EOF
#include "b48at.h"
static const float points[TFIT_B48AT_OUTPUT_POINTS_N][3] = TFIT_B48AT_OUTPUT_POINTS_MM;
static const float contact[3] = TFIT_B48AT_CONTACT_POINT_MM;
int main(void) { return !(points[60][0] == 24.0f && points[60][2] == 6.0f && contact[1] == 24.0f); }
EOF
check "the point macros initialise float arrays (strict firmware flags)" sh -c \
    "cc -std=c11 -Wall -Wextra -Werror -Wdouble-promotion -Wconversion -Wpedantic -Itarget/include -I'$tmp/w' '$tmp/pts.c' -o '$tmp/pts' && '$tmp/pts'"
rm -f "$tmp/w"/*
expect 0 "node number with the grid overridden" -- "$tool" solve $B --set geometry.grid=21,21,5 --force 0,0,-1 -o "$tmp/w/a.csv"
check "warns where node 61 went" grep -q "contact.0.node: node 61 was numbered on the file's grid; with the grid overridden it is the node at (43.2, 4.8, 6) mm" "$tmp/err"
rm -f "$tmp/w"/*

expect 2 "solve without a scene" -- "$tool" solve
says "no scene" "expected one scene file"
expect 2 "solve with two scenes" -- "$tool" solve $B $B
says "two scenes" "expected one scene file"
expect 2 "solve, bad force" -- "$tool" solve $B --force 1,2 -o "$tmp/w/a.csv"
says "bad force" "--force '1,2' is not three numbers"
expect 2 "solve, force not a number" -- "$tool" solve $B --force 1,x,0 -o "$tmp/w/a.csv"
says "force not a number" "--force '1,x,0' is not three numbers"
expect 2 "solve, unknown contact" -- "$tool" solve $B --force 0,0,1 --contact nowhere -o "$tmp/w/a.csv"
says "unknown contact" "has no contact site 'nowhere'"
expect 2 "solve, force without a contact site" -- "$tool" solve coeffs/cantilever.yaml --force 0,0,1 -o "$tmp/w/a.csv"
says "force without a contact site" "cantilever.yaml has no contact site for --force"
expect 2 "solve, no load at all" -- "$tool" solve $B -o "$tmp/w/a.csv"
says "no load at all" "nothing loads the body"
expect 0 "solve, an explicit zero force" -- "$tool" -q solve $B --force 0,0,0 -o "$tmp/w/z.csv"
check "zero force, zero field" awk -F, 'NR > 1 && ($5 != 0 || $6 != 0 || $7 != 0) { exit 1 }' "$tmp/w/z.csv"
rm -f "$tmp/w"/*
expect 2 "solve, unknown option" -- "$tool" solve $B --bogus -o "$tmp/w/a.csv"
says "unknown option" "bad option '--bogus'"
expect 2 "solve, missing scene file" -- "$tool" solve "$tmp/none.yaml" -o "$tmp/w/a.csv"
check "names the missing file" grep -q "$tmp/none.yaml" "$tmp/err"
sed 's/  nu: 0.49/  nu: 0.5/' $B >"$tmp/nu.yaml"
expect 2 "solve, nu = 0.5" -- "$tool" solve "$tmp/nu.yaml" --force 0,0,-1 -o "$tmp/w/a.csv" --vtk "$tmp/w/a.vtu"
nu_line=$(grep -n '^  nu: 0.49' $B | cut -d: -f1)
check "names file, line and field" grep -q "nu.yaml:$nu_line: material.nu" "$tmp/err"
expect 2 "solve, bad --set" -- "$tool" solve $B --set solver.gauss=0 -o "$tmp/w/a.csv"
check "names the override" grep -q "\-\-set solver.gauss=0: solver.gauss" "$tmp/err"
nothing_written "bad input"
expect 2 "solve into a missing directory (refused before the solve)" -- "$tool" -q solve $B --force 0,0,-1 -o "$tmp/missing/a.csv"
check "names the output" grep -q "$tmp/missing/a.csv" "$tmp/err"
expect 2 "solve, a body that is not held (refused before the solve)" -- "$tool" -q solve $B --set 'fixed=[{face: x-, components: [x]}]' --force 0,0,-1 -o "$tmp/w/a.csv"
check "says why, at the entry" grep -q "fixed.0: this region holds 33 nodes .*free to slide" "$tmp/err"
expect 1 "solve, a support without nodes" -- "$tool" -q solve $B --set solver.support=0.5 --force 0,0,-1 -o "$tmp/w/a.csv"
check "says where and what to change" grep -q "around (2.4, 2.4, 1.5) mm: raise solver.support" "$tmp/err"
nothing_written "failed solves"

expect 0 "verify cantilever, two levels" -- "$tool" -q verify cantilever --levels 2 --csv "$tmp/w/v.csv"
check "table on stdout" test "$(wc -l <"$tmp/out")" = 3
check "table in the file" cmp -s "$tmp/out" "$tmp/w/v.csv"
check "a rate on the second row" awk -F, 'NR == 3 { exit !($6 > 1) }' "$tmp/out"
rm -f "$tmp/w"/*
expect 2 "verify, unknown study" -- "$tool" verify beam
says "unknown study" "'beam' is not cantilever or patch"
expect 2 "verify, bad --levels" -- "$tool" verify patch --levels 0
says "bad --levels" "--levels '0' is not 1 to 12"
expect 2 "verify, bad --vary" -- "$tool" verify patch --vary time
says "bad --vary" "--vary 'time' is not grid or gauss"
expect 2 "verify, scene without reference" -- "$tool" verify patch --scene $B --csv "$tmp/w/v.csv"
says "scene without reference" "has no reference section"
nothing_written "bad verify"

finish "solver cli"

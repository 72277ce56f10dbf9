#!/bin/sh
# hostile.sh TISSUEFIT — scenes and command lines a careless user or an
# attacker would write (issue 19): each gets a clear message and the right
# exit status, before any work when the fault is in the input.
set -u
tool=$1
. "$(dirname "$0")/expect.sh"
B=tests/solver/block48_seed.yaml

# --- numbers, whole numbers, documents, syntax (details: test_scene_hostile.c)
for v in "material.nu=0,45" "material.E=3,2" "material.E=0.32 MPa" "geometry.grid=011,11,3" \
         "contact.0.node=61.9" "fit.seed=-1" "material.E=1e308" "material.E=5e-324" \
         "envelope.radius=1e308"; do
    expect 2 "--set $v" -- "$tool" -q solve $B --set "$v" --force 0,0,-1 -o "$tmp/w/a.csv"
    says "--set $v" "--set $v: ${v%%=*}"
done
sed 's/^  nu: 0.49/  nu: 0,45/' $B >"$tmp/comma.yaml"
expect 2 "nu: 0,45 in a file" -- "$tool" -q solve "$tmp/comma.yaml" --force 0,0,-1 -o "$tmp/w/a.csv"
nu_line=$(grep -n '^  nu: 0.49' $B | cut -d: -f1) # the scene's own lines
says "nu: 0,45 in a file" "comma.yaml:$nu_line: material.nu: '0,45' is not a number"
{ cat $B; printf -- '---\nname: other\n'; } >"$tmp/two.yaml"
expect 2 "a second document" -- "$tool" -q solve "$tmp/two.yaml" --force 0,0,-1 -o "$tmp/w/a.csv"
says "a second document" "two.yaml:$(($(wc -l <$B) + 1)): a second YAML document"
{ head -c 200 $B; printf '\377\376\n'; } >"$tmp/utf8.yaml"
expect 2 "bad UTF-8" -- "$tool" -q solve "$tmp/utf8.yaml" --force 0,0,-1 -o "$tmp/w/a.csv"
says "bad UTF-8" "utf8.yaml:[1-9][0-9]*: YAML syntax error"
long=$(head -c 2000 /dev/zero | tr '\0' a)
expect 2 "a --set value of 2,000 characters" -- "$tool" -q solve $B --set "name=$long" --force 0,0,-1
says "a --set value of 2,000 characters" "(2005 characters): name: at most 63 characters"

# --- the malformed flow value a fuzzer found (UB in scene_locate.c before)
expect 2 "--set fixed=[nodes: x-}, {face: x+}]" -- "$tool" -q solve $B \
    --set 'fixed=[nodes: x-}, {face: x+}]' --force 0,0,-1 -o "$tmp/w/a.csv"
says "malformed flow value" "YAML syntax error"

# --- a support that holds no node: the neighbour grid used to crash
expect 1 "solver.support=1e-3 (no node in a support)" -- "$tool" -q solve $B \
    --set solver.support=1e-3 --force 0,0,-1 -o "$tmp/w/a.csv"
says "tiny support" "raise solver.support"
expect 2 "solver.support=1e-16" -- "$tool" -q solve $B --set solver.support=1e-16 \
    --force 0,0,-1 -o "$tmp/w/a.csv"
says "solver.support=1e-16" "solver.support: the support radius"

# --- scene paths that are not files: no blocking, no reading forever
mkfifo "$tmp/fifo.yaml"
expect 2 "a FIFO as the scene" -- timeout 20 "$tool" -q solve "$tmp/fifo.yaml" --force 0,0,-1
says "FIFO" "fifo.yaml: not a regular file"
expect 2 "/dev/zero as the scene" -- sh -c 'ulimit -v 4000000; exec timeout 20 "$0" -q solve /dev/zero' "$tool"
says "/dev/zero" "/dev/zero: not a regular file"
expect 2 "a directory as the scene" -- "$tool" -q solve "$tmp" --force 0,0,-1
says "a directory" "not a regular file"
nothing_written "refused input"

# --- outputs checked before the solve (no solver progress on stderr)
expect 2 "fit into a missing directory" -- "$tool" fit $B -o "$tmp/missing/a.h"
says "missing directory" "$tmp/missing/a.h: no directory"
grep -q "solver:" "$tmp/err" && bad "fit solved before refusing a missing directory"
expect 2 "fit -o with a bad name" -- "$tool" fit $B -o "$tmp/w/Bad-Name.h"
says "bad name" "lower-case C identifier"
grep -q "solver:" "$tmp/err" && bad "fit solved before refusing a bad name"
expect 2 "fit --report into a missing directory" -- "$tool" fit $B -o "$tmp/w/a.h" --report "$tmp/nodir"
grep -q "solver:" "$tmp/err" && bad "fit solved before refusing the report directory"
expect 2 "solve -o into a missing directory" -- "$tool" solve $B --force 0,0,-1 -o "$tmp/missing/a.csv"
grep -q "solver:" "$tmp/err" && bad "solve solved before refusing its output"
expect 2 "sweep --md into a missing directory" -- "$tool" sweep $B --md "$tmp/missing/a.md"
expect 2 "verify --csv into a missing directory" -- "$tool" verify cantilever --csv "$tmp/missing/v.csv"
nothing_written "refused outputs"

# --- every command: standard output that cannot be written is a failure
to_full() { "$@" >/dev/full; }
small="--set geometry.grid=5,5,2 --set contact.0.node=13"
expect 1 "sweep >/dev/full" -- to_full "$tool" -q sweep $B --outputs scene $small
says "sweep >/dev/full" "cannot write"
expect 1 "verify >/dev/full" -- to_full "$tool" -q verify cantilever --levels 1
says "verify >/dev/full" "cannot write standard output"
expect 1 "solve >/dev/full" -- to_full "$tool" -q solve $B $small --force 0,0,-1
for c in fit sweep solve verify replay lm-strd demo-model; do
    expect 1 "$c --help >/dev/full" -- to_full "$tool" "$c" --help
done
expect 1 "--version >/dev/full" -- to_full "$tool" --version

# --- a fit on a scene with 3 outputs (the modal rank search wanted 12 modes)
sed 's/^  select: face .*/  select: nodes/; s/^  face: z+$/  nodes: [61, 60, 62]/' $B >"$tmp/three.yaml"
expect 0 "fit, 3 outputs, --family nodal" -- "$tool" -q fit "$tmp/three.yaml" --family nodal -o "$tmp/w/three.h"
expect 0 "fit, 3 outputs, --family modal" -- "$tool" -q fit "$tmp/three.yaml" --family modal -o "$tmp/w/three.h"
grep -q 'TFIT_THREE_FORWARD_ORDERS "p=[0-9]* r=[1-9]"$' "$tmp/w/three.h" ||
    bad "modal on 3 outputs: $(grep TFIT_THREE_FORWARD_ORDERS "$tmp/w/three.h")"

# --- replay: a NaN among the logged outputs fails the run
"$tool" -q solve $B --force 0.1,-0.2,-0.5 -o "$tmp/u.csv" || bad "solve for the replay log"
awk -F, 'NR == 1 { printf "tick,fx,fy,fz,status,cfx,cfy,cfz"; for (i = 0; i < 363; ++i) printf ",u"; printf "\n"; next }
         NR >= 2 && NR <= 122 { u = u "," $5 "," $6 "," $7 }
         END { for (t = 0; t < 3; ++t) printf "%d,0.1,-0.2,-0.5,0,0,0,0%s\n", t, u }' "$tmp/u.csv" >"$tmp/ticks.csv"
expect 0 "replay, the solve's own displacements" -- "$tool" -q replay $B --ticks "$tmp/ticks.csv"
grep -q "deviation.*: [0-9.e-]* mm" "$tmp/out" || bad "replay prints no deviation: $(cat "$tmp/out")"
awk -F, 'NR == 3 { $20 = "nan" } { print }' OFS=, "$tmp/ticks.csv" >"$tmp/nan.csv"
expect 1 "replay, a NaN in the logged outputs" -- "$tool" -q replay $B --ticks "$tmp/nan.csv"
says "replay NaN" "1 logged outputs of accepted ticks are NaN or Inf (the first at tick 1)"
# --every K: one tick in K, named by the log's tick numbers; refused when
# it keeps no tick and for a solve in time (each tick is a time step)
expect 1 "replay --every 2, the NaN tick kept" -- "$tool" -q replay $B --ticks "$tmp/nan.csv" --every 2
says "replay --every NaN" "1 logged outputs of accepted ticks are NaN or Inf (the first at tick 1)"
expect 2 "replay --every beyond the ticks" -- "$tool" -q replay $B --ticks "$tmp/ticks.csv" --every 4
says "replay --every beyond" "--every 4 keeps none of the 3 ticks"
expect 2 "replay --every, a solve in time" -- "$tool" -q replay coeffs/block48_ve.yaml --ticks "$tmp/ticks.csv" --every 2
says "replay --every in time" "is solved in time, tick by tick; it needs every tick"

# --- a report picture cut short: gnuplot exits 0 when cairo cannot write
# (a full disk); a gnuplot on PATH that does just that
mkdir -p "$tmp/fakegp" "$tmp/rep"
cat >"$tmp/fakegp/gnuplot" <<'GP'
#!/bin/sh
out=$(sed -n "s/^set output '\(.*\)'$/\1/p" | head -n 1)
[ -z "$out" ] || printf '\211PNG\r\n\032\n' >"$out"
exit 0
GP
chmod +x "$tmp/fakegp/gnuplot"
expect 1 "fit --report, gnuplot's image cut short" -- env PATH="$tmp/fakegp:$PATH" \
    "$tool" -q fit $B -o "$tmp/rep/cut.h" --report "$tmp/rep"
says "an image cut short" "gnuplot wrote an incomplete image"
ls "$tmp/rep" | grep -q '\.png' && bad "a cut-short image was kept: $(ls "$tmp/rep")"

# --- cuts: two cuts 0.3 mm apart leave points between them seeing too few
# nodes; the solve fails naming the cut's entry (file:line), not the support
sed -n '/^name/,/^  - {patch/p' tests/cut/slit.yaml | sed 's/grid: \[16, 8, 8\]/grid: [8, 4, 4]/' >"$tmp/two.yaml"
printf 'cuts:\n  - {path: [[10, 0], [10, 10]], depth: 5}\n  - {path: [[10.3, 0], [10.3, 10]], depth: 5}\n' >>"$tmp/two.yaml"
printf 'outputs: {select: all}\nsolver: {cells: [8, 4, 4]}\n' >>"$tmp/two.yaml"
cut_line=$(grep -n '10.3, 0' "$tmp/two.yaml" | cut -d: -f1)
expect 1 "two cuts 0.3 mm apart, rpim-galerkin" -- "$tool" -q solve "$tmp/two.yaml" -o "$tmp/c.csv"
says "two cuts, rpim" "two.yaml:$cut_line: cuts.1: the RPIM system at .* is singular: this cut hides"
expect 1 "two cuts 0.3 mm apart, efg-galerkin" -- "$tool" -q solve "$tmp/two.yaml" \
    --set solver.method=efg-galerkin -o "$tmp/c.csv"
says "two cuts, efg" "two.yaml:$cut_line: cuts.1: the MLS moment matrix at .* is singular: this cut hides"

# --- organs from generated cubes (OBJ; the faces wind outward)
cube() { # cube X0 SIZE: the 8 vertices of [X0, X0 + SIZE]^3
    awk -v a="$1" -v s="$2" 'BEGIN { for (v = 0; v < 8; ++v)
        printf "v %g %g %g\n", a + s * (v == 1 || v == 2 || v == 5 || v == 6),
               a + s * (v == 2 || v == 3 || v == 6 || v == 7), a + s * (v >= 4) }'
}
faces() { # faces OFFSET [REVERSE]: the cube's 12 triangles, vertex numbers + OFFSET
    printf '1 3 2\n1 4 3\n5 6 7\n5 7 8\n1 2 6\n1 6 5\n2 3 7\n2 7 6\n3 4 8\n3 8 7\n4 1 5\n4 5 8\n' |
        awk -v o="$1" -v r="${2:-0}" '{ if (r) print "f", $1 + o, $3 + o, $2 + o; else print "f", $1 + o, $2 + o, $3 + o }'
}
organ() { # organ MESH: a scene of that mesh beside it, clamped at its bottom
    printf 'name: org\ngeometry:\n  surface: {file: %s}\n  spacing: 5\nmaterial: {E: 0.01, nu: 0.3}\n' "$1"
    printf 'fixed:\n  - side: {point: [0, 0, 2], normal: [0, 0, -1]}\n'
    printf 'contact:\n  - name: top\n    site: {point: [10, 10, 20], radius: 15}\noutputs: {select: surface}\n'
}
# two cubes joined at one vertex: every edge has two triangles, one vertex two fans
{ cube 0 20; cube 20 20 | tail -n 7; faces 0; faces 8 | awk '{ for (i = 2; i <= 4; ++i) $i = $i == 9 ? 7 : $i - 1; print }'; } >"$tmp/joined.obj"
organ joined.obj >"$tmp/joined.yaml"
expect 2 "two cubes joined at a vertex" -- "$tool" -q solve "$tmp/joined.yaml" --force 0,0,-0.01 -o "$tmp/c.csv"
says "joined at a vertex" "joined.obj: non-manifold vertex .*: 1 vertex; the first, vertex [0-9]* at (20, 20, 20), joins 2 fans"
# a mesh in cm (a 15 cm cube read as 15 mm) clamped where mm put its bottom
{ cube 0 15; faces 0; } >"$tmp/cm.obj"
organ cm.obj | sed 's/side: .*/sphere: {centre: [75, 75, 0], radius: 10}/' >"$tmp/cm.yaml"
expect 2 "a mesh in cm" -- "$tool" -q solve "$tmp/cm.yaml" --force 0,0,-0.01 -o "$tmp/c.csv"
says "a mesh in cm" "cm.yaml:7: fixed.0: this region holds no node; the body's nodes span x \[0, 15\]"
says "a mesh in cm" "other units than mm"
# inward winding: reversed with a note on stderr (none under -q), recorded in the
# header, and the reversed mesh solves and fits
{ cube 0 20; faces 0 1; } >"$tmp/inward.obj"
organ inward.obj >"$tmp/inward.yaml"
expect 0 "an inward mesh" -- "$tool" solve "$tmp/inward.yaml" --force 0,0,-0.01 -o "$tmp/c.csv"
says "an inward mesh" "inward.yaml: geometry.surface: .*inward.obj: the triangles wound inward (enclosed volume -8000): reversed them"
expect 0 "an inward mesh, -q" -- "$tool" -q solve "$tmp/inward.yaml" --force 0,0,-0.01 -o "$tmp/c.csv"
grep -q "wound inward" "$tmp/err" && bad "-q printed the winding note: $(cat "$tmp/err")"
expect 0 "fit on an inward mesh" -- "$tool" -q fit "$tmp/inward.yaml" -o "$tmp/inw.h"
grep -A1 "Warnings (the scene):" "$tmp/inw.h" | grep -q "wound inward (enclosed volume -8000): reversed them" ||
    bad "the header does not record the winding note: $(grep -A2 Warnings "$tmp/inw.h")"

finish hostile

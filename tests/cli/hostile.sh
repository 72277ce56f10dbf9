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

finish hostile

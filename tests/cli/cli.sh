#!/bin/sh
# cli.sh TISSUEFIT — the command line's contract: help for every command,
# exit status 2 and nothing written on bad usage, -q silences progress.
set -u
tool=$1
. "$(dirname "$0")/expect.sh"

expect 0 "global --help" -- "$tool" --help
grep -q "demo-model" "$tmp/out" || bad "--help does not list demo-model"
# every registered solver (host/solvers/registry.c) and material law
# (host/materials/registry.c), and the Newton tangents, each on its own line
for name in rpim-galerkin efg-galerkin rpim-newton efg-newton mls-collocation \
            linear svk neo-hookean kelvin kelvin-neo-hookean; do
  grep -q "^  $name  " "$tmp/out" || bad "--help does not list $name"
done
grep -q "^  full, modified, krylov, bfgs, patch$" "$tmp/out" || bad "--help lacks the Newton tangents"
expect 0 "--version" -- "$tool" --version
prints "--version" "^tissuefit [0-9][0-9.]* (tfit API [0-9]"
expect 0 "demo-model --help" -- "$tool" demo-model --help
grep -q -- "--envelope" "$tmp/out" || bad "demo-model --help lacks its options"
cp "$tmp/out" "$tmp/help"
expect 0 "help demo-model" -- "$tool" help demo-model
cmp -s "$tmp/out" "$tmp/help" || bad "help demo-model differs from demo-model --help"
expect 2 "unknown command" -- "$tool" frobnicate
says "unknown command" "no command 'frobnicate'"
expect 2 "unknown global option" -- "$tool" --frob
says "unknown global option" "unknown option '--frob'"
expect 2 "no command" -- "$tool"
says "no command" "^usage: tissuefit"
expect 2 "demo-model without -o" -- "$tool" demo-model
says "demo-model without -o" "expected -o FILE.h"
expect 2 "demo-model with a stray argument" -- "$tool" demo-model -o "$tmp/w/a.h" extra
says "stray argument" "expected -o FILE.h and no other arguments"
expect 2 "demo-model with an unknown option" -- "$tool" demo-model -o "$tmp/w/a.h" --bogus
says "unknown option" "bad option '--bogus'"
expect 2 "demo-model, negative envelope" -- "$tool" demo-model --envelope -1 -o "$tmp/w/a.h"
says "negative envelope" "--envelope '-1' is not a positive number"
expect 2 "demo-model, envelope not a number" -- "$tool" demo-model --envelope 1N -o "$tmp/w/a.h"
says "envelope not a number" "--envelope '1N' is not a positive number"
expect 2 "demo-model, header name not an identifier" -- "$tool" demo-model -o "$tmp/w/Bad-Name.h"
says "header name" "Bad-Name.h: the header name must be a lower-case C identifier"
nothing_written "bad usage"
expect 2 "demo-model into a missing directory" -- "$tool" demo-model -o "$tmp/missing/a.h"
grep -q "$tmp/missing/a.h" "$tmp/err" || bad "error does not name the file"
expect 0 "demo-model, quiet" -- "$tool" -q demo-model -o "$tmp/w/ok.h"
[ -s "$tmp/err" ] && bad "-q still wrote to stderr"
[ -f "$tmp/w/ok.h" ] && [ -f "$tmp/w/ok_golden.h" ] || bad "outputs missing"
ls "$tmp/w" | grep -q tmp && bad "temporary files left behind"

# gmsh is opened when an organ is meshed (host/geometry/gmsh_api.c): a
# library that cannot be opened is an error naming it, with nothing written
expect 2 "an organ without its gmsh library" -- env TISSUEFIT_GMSH=/nonexistent/libgmsh.so \
    "$tool" -q solve coeffs/stomach.yaml --force 0,0,-0.1 --out "$tmp/w/organ.csv"
says "an organ without its gmsh library" \
    "geometry.surface.file: .*gmsh could not mesh the volume: cannot use gmsh (/nonexistent/libgmsh.so)"
[ -e "$tmp/w/organ.csv" ] && bad "a solve that could not mesh wrote its output"

finish cli

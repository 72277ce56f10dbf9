#!/bin/bash
# solver_path.sh — the collocation solver through `tissuefit solve`
# (scene, solver interface, tributary patch loads: colloc_solver.c) against
# the core driven directly (tests/colloc/block48.c, the patch overlap
# computed by hand) on block48 at the default grid: node 61's displacement
# per newton for +x and -z must agree to 1e-4 (the relaxations' tolerances).
# Usage: solver_path.sh TISSUEFIT BLOCK48
set -euo pipefail
tool=$1
core=$2
IFS=, read -r n cx cz rest <<< "$("$core" 11,11,3 --law linear)"
node61() { # force -> the component of node 61 along it, per newton
  "$tool" -q solve tests/solver/block48_seed.yaml --set solver.method=mls-collocation --force "$1" |
    awk -F, -v c="$2" -v f="$3" '$1 == 61 { printf "%.10g\n", $c / f }'
}
tx=$(node61 0.01,0,0 5 0.01)
tz=$(node61 0,0,-0.01 7 0.01)
awk -v cx="$cx" -v cz="$cz" -v tx="$tx" -v tz="$tz" 'BEGIN {
  ex = (tx - cx) / cx; ez = (tz - cz) / cz; ex = ex < 0 ? -ex : ex; ez = ez < 0 ? -ez : ez
  printf "node 61, mm/N: x %.7f (tissuefit) vs %.7f (core), z %.7f vs %.7f; relative differences %.1e, %.1e\n", tx, cx, tz, cz, ex, ez
  if (!(ex <= 1e-4 && ez <= 1e-4)) { print "FAIL: the solver path differs from the core"; exit 1 }
  print "ok: tissuefit solve --set solver.method=mls-collocation matches the core" }'

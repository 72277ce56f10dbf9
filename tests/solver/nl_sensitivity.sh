#!/bin/sh
# nl_sensitivity.sh CURVES_TOOL OUT.csv — what moves node 61's large-load
# curve on one graded cloud (docs/validation.md §12.1): block48_curves,
# neo-Hookean, path a to 0.7 of 3 N (2.1 N in 7 levels: the load factors
# 0.1 ... 0.7), once per variant of NL_SENS_RUNS "name:grid:override[;override]"
# (override "-": the defaults; ";" separates several KEY=VALUE), all on the
# graded clouds of §7.3 (geometry.grading=3,3,2).  Writes OUT.csv:
#   variant,grid,factor,uz,seconds
# Each run's block48_curves output is kept in NL_CACHE (default
# build/nl_sensitivity) under its grid and overrides; a run whose file is
# there is not repeated (delete it to redo).
set -eu
[ $# -eq 2 ] || { echo "usage: $0 CURVES_TOOL OUT.csv (NL_SENS_RUNS in the environment)" >&2; exit 2; }
tool=$1 out=$2
cache=${NL_CACHE:-build/nl_sensitivity}
mkdir -p "$cache"
tmp=$(mktemp)
trap 'rm -f "$tmp"' EXIT
echo "variant,grid,factor,uz,seconds" > "$tmp"
for spec in $NL_SENS_RUNS; do
    name=$(echo "$spec" | cut -d: -f1) grid=$(echo "$spec" | cut -d: -f2)
    sets=$(echo "$spec" | cut -d: -f3 | tr ';' ' ')
    [ "$sets" != "-" ] || sets=""
    key=$(echo "${grid}_$sets" | tr ' ,=' '_.-')
    if [ ! -s "$cache/$key.csv" ]; then
        echo "nl_sensitivity: $name $grid $sets ..." >&2
        # shellcheck disable=SC2086
        "$tool" "$grid" neo-hookean 0,0,-2.1 7 geometry.grading=3,3,2 $sets > "$cache/$key.new"
        mv "$cache/$key.new" "$cache/$key.csv"
    fi
    awk -F, -v OFS=, -v name="$name" 'NR > 1 { print name, $1, sprintf("%.1f", 0.7 * $3), $9, $15 }' \
        "$cache/$key.csv" >> "$tmp"
done
mv "$tmp" "$out"

#!/bin/sh
# self_table.sh TISSUEFIT OUT.md — the discretisation error `tissuefit fit`
# measures itself (no reference: a coarser and a finer cloud, Richardson)
# against the one it measures with the CalculiX reference, for every shipped
# scene that has one and a linear solve; the markdown table in OUT.md and on
# stdout.  Minutes: the liver's finer cloud is 26,703 nodes.
set -eu
tool=$1 out=$2
w=$(mktemp -d)
trap 'rm -rf "$w"' EXIT
define() { sed -n "s/^#define TFIT_[A-Z0-9_]*_$2 \([^ ]*\).*/\1/p" "$1"; }
ratio() { awk -v a="$1" -v b="$2" 'BEGIN { printf "%.2f", a / b }'; }
{
    echo "| scene | forward, self-measured (mm) | against CalculiX (mm) | ratio | contact, self-measured (N) | against CalculiX (N) | ratio | order observed | extra time (s) |"
    echo "|---|---:|---:|---:|---:|---:|---:|---|---:|"
    for e in block48:tests/calculix/data/block48_physics.csv liver:tests/calculix/data/liver_physics.csv \
             stomach:tests/calculix/data/stomach_physics.csv heart:tests/calculix/data/heart_physics.csv; do
        n=${e%%:*} ref=${e#*:}
        echo "self_table: $n" >&2
        "$tool" fit coeffs/$n.yaml -o "$w/${n}_self.h" 2> "$w/${n}_self.log"
        "$tool" -q fit coeffs/$n.yaml --reference "$ref" -o "$w/${n}_ref.h"
        fs=$(define "$w/${n}_self.h" FORWARD_DISCRETISATION_MAX_MM)
        fr=$(define "$w/${n}_ref.h" FORWARD_DISCRETISATION_MAX_MM)
        cs=$(define "$w/${n}_self.h" CONTACT_DISCRETISATION_MAX_N)
        cr=$(define "$w/${n}_ref.h" CONTACT_DISCRETISATION_MAX_N)
        order=$(sed -n 's/.*self-measured: Richardson.* nodes), \(.*\), at [0-9]* points.*/\1/p' "$w/${n}_self.h" | head -1)
        secs=$(sed -n 's/^fit: discretisation (self-measured.*; \([0-9.]*\) s$/\1/p' "$w/${n}_self.log")
        echo "| $n | $fs | $fr | $(ratio "$fs" "$fr") | $cs | $cr | $(ratio "$cs" "$cr") | $order | $secs |"
    done
} > "$w/table.md"
mkdir -p "$(dirname "$out")"
cp "$w/table.md" "$out"
cat "$out"

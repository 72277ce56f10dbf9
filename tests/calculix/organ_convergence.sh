#!/bin/sh
# organ_convergence.sh ORGAN_COMPARE DATA OUT.csv ORGAN:SPACING,SPACING,... ...
#
# The organs under refinement (docs/validation.md §14): the meshless solve
# of coeffs/ORGAN.yaml at each interior spacing, with the file's skin and
# with a refined one (geometry.refine_skin), against the organ's finest
# CalculiX level DATA/ORGAN_s20r1.csv, for the unit forces along x, y, z.
# OUT.csv gets a row per solve:
#   organ,skin,spacing,nodes,surface,contact_fx,contact_fy,contact_fz,
#   l2_fx,l2_fy,l2_fz,seconds
# (errors in %), and a markdown table goes to stdout.  The organ's own
# d_c (2 mm) is kept at every spacing.  Progress on stderr.
set -eu
[ $# -ge 4 ] || { echo "usage: $0 ORGAN_COMPARE DATA OUT.csv ORGAN:S,S,..." >&2; exit 2; }
compare=$1 data=$2 out=$3
shift 3
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
echo "organ,skin,spacing,nodes,surface,contact_fx,contact_fy,contact_fz,l2_fx,l2_fy,l2_fz,seconds" \
    > "$tmp/out.csv"
for arg in "$@"; do
    organ=${arg%%:*}
    for s in $(echo "${arg#*:}" | tr , ' '); do
        for skin in file refined; do
            set -- --set "geometry.spacing=$s"
            [ $skin = refined ] && set -- "$@" --set geometry.refine_skin=true
            echo "organ_convergence: $organ at $s mm, the $skin skin ..." >&2
            t0=$(date +%s.%N)
            "$compare" "$data/${organ}_s20r1.csv" "coeffs/$organ.yaml" "$@" \
                > "$tmp/table" 2> "$tmp/err" || { cat "$tmp/err" >&2; exit 1; }
            t1=$(date +%s.%N)
            awk -v organ=$organ -v skin=$skin -v s=$s -v t0=$t0 -v t1=$t1 '
                FILENAME ~ /err$/ && / nodes, / { n = $(NF - 8); surf = $(NF - 6) }
                FILENAME ~ /table$/ && $2 ~ /^f[xyz]$/ { c[$2] = $6; l[$2] = $9 }
                END { printf "%s,%s,%s,%s,%s,%s,%s,%s,%s,%s,%s,%.1f\n", organ, skin, s, n, surf,
                             c["fx"], c["fy"], c["fz"], l["fx"], l["fy"], l["fz"], t1 - t0 }' \
                "$tmp/err" "$tmp/table" >> "$tmp/out.csv"
        done
    done
done
mv "$tmp/out.csv" "$out"
awk -F, 'NR == 1 { print "| organ | skin | spacing (mm) | nodes | surface nodes | contact fx / fy / fz (%) | outputs L2 fx / fy / fz (%) | s |";
                   print "|---|---|---:|---:|---:|---|---|---:|"; next }
         { printf "| %s | %s | %s | %s | %s | %s / %s / %s | %s / %s / %s | %s |\n", $1, $2, $3, $4, $5,
                  $6, $7, $8, $9, $10, $11, $12 }' "$out"

#!/bin/sh
# organ_nl_compare.sh TISSUEFIT SCENE FX,FY,FZ K REF.csv CLOUD... — a scene
# of a nonlinear law (a box or an organ, with or without material regions)
# against a CalculiX NLGEOM level (organ_deck --nlgeom FX,FY,FZ --levels K,
# organ_dat.awk: the output points' displacements at the load levels k F / K,
# cases l1 .. lK).  For each meshless cloud (a KEY=VALUE the solve takes as
# --set: geometry.grid=21,21,5 on a box, geometry.spacing=6 on an organ) and
# each level k, the Newton solve of the scene under k F / K at its contact
# site, and:
#   contact  |u - u_ref| / |u_ref| at the reference's contact point;
#   outputs  sqrt(sum |u - u_ref|^2 / sum |u_ref|^2) over its output points;
# points matched by position (to 1e-4 mm; every output point must be a node
# of the cloud).  One markdown row per cloud and level on stdout, and the
# solve's seconds.  BOUND (environment, a fraction): exit 1 when a contact
# or outputs error of the last cloud exceeds it.
#
#   organ_nl_compare.sh --csv LEVEL.csv REF.csv LABEL   another CalculiX level
#                                                 against REF, the same rows
#   organ_nl_compare.sh --signal ...                a stiff region's signal
#                                                 (below)
set -eu
# errors LEVEL_CASE A.csv B.csv: "contact outputs" of A's case against B's
# (A: organ_dat.awk rows, or a solve's node,x,y,z,ux,uy,uz with LEVEL_CASE "")
errors() {
    awk -F, -v lev="$1" '
        function key(x, y, z) { return sprintf("%.4f,%.4f,%.4f", x, y, z) }
        NR == FNR { if (FNR > 1 && (lev == "" || $5 == lev)) {
                        u[key($2, $3, $4)] = lev == "" ? $5 " " $6 " " $7 : $6 " " $7 " " $8 }
                    next }
        FNR > 1 && $5 == (lev == "" ? cur : lev) {
            k = key($2, $3, $4)
            if (!(k in u)) { printf "no point at (%s)\n", k > "/dev/stderr"; bad = 1; next }
            split(u[k], m, " ")
            d = (m[1] - $6) ^ 2 + (m[2] - $7) ^ 2 + (m[3] - $8) ^ 2
            r = $6 ^ 2 + $7 ^ 2 + $8 ^ 2
            if ($9 == 1) { c = sqrt(d / r); seen = 1 }
            sd += d; sr += r
        }
        END { if (bad || !seen || sr == 0) exit 1; printf "%.4f %.4f", c, sqrt(sd / sr) }' \
        cur="$4" "$2" "$3"
}
pct() { awk -v x="$1" 'BEGIN { printf "%.2f %%", 100 * x }'; }
# contact LEVEL_CASE A.csv REF.csv: the contact point's displacement "ux uy uz"
# in A (organ_dat.awk rows at LEVEL_CASE, or a solve's rows with LEVEL_CASE
# "" matched by position to REF's contact point at level CUR)
contact() {
    awk -F, -v lev="$1" -v cur="$4" '
        function key(x, y, z) { return sprintf("%.4f,%.4f,%.4f", x, y, z) }
        NR == FNR { if (FNR > 1 && $9 == 1 && $5 == cur) want = key($2, $3, $4); next }
        FNR > 1 && (lev == "" || ($5 == lev && $9 == 1)) && key($2, $3, $4) == want {
            print (lev == "" ? $5 " " $6 " " $7 : $6 " " $7 " " $8); found = 1; exit }
        END { if (!found) exit 1 }' "$3" "$2"
}
# stiffness FX,FY,FZ "ux uy uz": |F| / (u . F / |F|), N/mm: the secant
# stiffness along the press
stiffness() {
    echo "$1 $2" | awk '{ split($1, f, ","); n = sqrt(f[1]^2 + f[2]^2 + f[3]^2)
                          d = ($2 * f[1] + $3 * f[2] + $4 * f[3]) / n; printf "%.6g", n / d }'
}
scaled() { echo "$1" | awk -F, -v k="$2" -v K="$3" '{ printf "%.17g,%.17g,%.17g", $1 * k / K, $2 * k / K, $3 * k / K }'; }
if [ "${1:-}" = "--signal" ]; then
    # --signal TISSUEFIT OVER BESIDE F_OVER F_BESIDE K CLOUD REF_OVER REF_BESIDE [REF_OVER REF_BESIDE]...
    # What the hand feels of a stiff region under large deformation: at each
    # load level k F / K, the secant stiffness along the press at each site
    # (k = |F| / depth, the depth the contact point's displacement along F)
    # and the difference dk = k_over - k_beside, for each CalculiX level
    # (finest first) and the Newton solves of CLOUD; BOUND (a fraction):
    # exit 1 when the meshless dk is off the finest level's by more.
    # SIGNAL_KEEP=DIR keeps the Newton solves there and reuses them (the same
    # scenes, forces and cloud only).
    [ $# -ge 10 ] || { echo "usage: $0 --signal TISSUEFIT OVER BESIDE F_OVER F_BESIDE K CLOUD REF_OVER REF_BESIDE..." >&2; exit 2; }
    tool=$2 over=$3 beside=$4 fo=$5 fb=$6 levels=$7 cloud=$8
    shift 8
    tmp=$(mktemp -d)
    trap 'rm -rf "$tmp"' EXIT
    echo "| solve | load level | k over (N/mm) | k beside (N/mm) | dk (N/mm) | dk / k beside | dk against the finest |"
    echo "|---|---|---:|---:|---:|---:|---:|"
    row() { # LABEL k KO KB DK0
        awk -v l="$1" -v k="$2" -v a="$3" -v b="$4" -v d0="$5" 'BEGIN { d = a - b
            printf "| %s | l%d | %.5g | %.5g | %.5g | %.1f %% | %s |\n", l, k, a, b, d, 100 * d / b,
                   d0 == "" ? "—" : sprintf("%+.1f %%", 100 * (d - d0) / d0) }'
    }
    k=1 fail=0
    while [ "$k" -le "$levels" ]; do
        Fo=$(scaled "$fo" "$k" "$levels") Fb=$(scaled "$fb" "$k" "$levels")
        dk0= first=1
        i=1
        for ref in "$@"; do
            if [ $((i % 2)) -eq 1 ]; then ro=$ref; i=$((i + 1)); continue; fi
            rb=$ref i=$((i + 1))
            uo=$(contact "l$k" "$ro" "$ro" "l$k") && ub=$(contact "l$k" "$rb" "$rb" "l$k") ||
                { echo "organ_nl_compare: $ro, $rb: no contact row at l$k" >&2; exit 2; }
            ko=$(stiffness "$Fo" "$uo") kb=$(stiffness "$Fb" "$ub")
            row "CalculiX $(basename "$ro" .csv)" "$k" "$ko" "$kb" "$dk0"
            if [ $first = 1 ]; then dk0=$(awk -v a="$ko" -v b="$kb" 'BEGIN { printf "%.9g", a - b }'); first=0; fo_ref=$ro fb_ref=$rb; fi
        done
        # SIGNAL_KEEP=DIR keeps the solves (and reuses those already there)
        keep=${SIGNAL_KEEP:-$tmp}
        mkdir -p "$keep"
        [ -s "$keep/over_l$k.csv" ] ||
            "$tool" -q solve "$over" --set "$cloud" --force "$Fo" --out "$keep/over_l$k.csv"
        [ -s "$keep/beside_l$k.csv" ] ||
            "$tool" -q solve "$beside" --set "$cloud" --force "$Fb" --out "$keep/beside_l$k.csv"
        uo=$(contact "" "$keep/over_l$k.csv" "$fo_ref" "l$k") &&
            ub=$(contact "" "$keep/beside_l$k.csv" "$fb_ref" "l$k") ||
            { echo "organ_nl_compare: the solves hold no contact point at l$k" >&2; exit 2; }
        ko=$(stiffness "$Fo" "$uo") kb=$(stiffness "$Fb" "$ub")
        row "meshless, $cloud" "$k" "$ko" "$kb" "$dk0"
        if [ -n "${BOUND:-}" ]; then
            awk -v a="$ko" -v b="$kb" -v d0="$dk0" -v B="$BOUND" \
                'BEGIN { d = a - b; exit !((d - d0) / d0 <= B && (d0 - d) / d0 <= B) }' || fail=1
        fi
        k=$((k + 1))
    done
    exit $fail
fi
if [ "${1:-}" = "--csv" ]; then
    [ $# -eq 4 ] || { echo "usage: $0 --csv LEVEL.csv REF.csv LABEL" >&2; exit 2; }
    echo "| level | load level | contact | outputs (L2) |"
    echo "|---|---|---|---|"
    for lev in $(awk -F, 'NR > 1 && !seen[$5]++ { print $5 }' "$3"); do
        row=$(errors "$lev" "$2" "$3" "") || { echo "organ_nl_compare: $2: points do not match" >&2; exit 2; }
        c=${row% *} o=${row#* }
        echo "| $4 | $lev | $(pct "$c") | $(pct "$o") |"
    done
    exit 0
fi
[ $# -ge 6 ] || { echo "usage: $0 TISSUEFIT SCENE FX,FY,FZ K REF.csv KEY=VALUE..." >&2; exit 2; }
tool=$1 scene=$2 force=$3 levels=$4 ref=$5
shift 5
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
echo "| cloud | load (N) | contact | outputs (L2) | solve (s) |"
echo "|---|---|---|---|---|"
fail=0 last=
for cloud in "$@"; do last=$cloud; done
for cloud in "$@"; do
    k=1
    while [ "$k" -le "$levels" ]; do
        f=$(echo "$force" | awk -F, -v k="$k" -v K="$levels" '{ printf "%.17g,%.17g,%.17g", $1 * k / K, $2 * k / K, $3 * k / K }')
        shown=$(echo "$f" | awk -F, '{ printf "%.4g,%.4g,%.4g", $1, $2, $3 }')
        t0=$(date +%s.%N)
        "$tool" -q solve "$scene" --set "$cloud" --force "$f" --out "$tmp/u.csv"
        secs=$(awk -v a="$t0" -v b="$(date +%s.%N)" 'BEGIN { printf "%.1f", b - a }')
        row=$(errors "" "$tmp/u.csv" "$ref" "l$k") || { echo "organ_nl_compare: $cloud at level $k: points do not match" >&2; exit 2; }
        c=${row% *} o=${row#* }
        echo "| $cloud | $shown | $(pct "$c") | $(pct "$o") | $secs |"
        if [ -n "${BOUND:-}" ] && [ "$cloud" = "$last" ]; then
            awk -v c="$c" -v o="$o" -v b="$BOUND" 'BEGIN { exit !(c <= b && o <= b) }' || fail=1
        fi
        k=$((k + 1))
    done
done
exit $fail

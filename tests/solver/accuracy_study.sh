#!/bin/sh
# accuracy_study.sh TISSUEFIT COMPARE OUTDIR [PART...] — the study behind the
# default shape parameter and the best cloud (docs/validation.md §7,
# make accuracy-study).  Parts (default: all, in this order):
#
#   shape    d_c = spacings x the local nodal spacing, for q = 1.03 (the seed)
#            and q = 2.5, against the seed's absolute d_c = 2 mm: the
#            cantilever's L2 and energy errors (level 3, 8514 nodes), the
#            jittered patch test's L2 error (6^3 nodes, 3 Gauss points), and
#            block48 against CalculiX at 11x11x3, 21x21x5, 31x31x7, 41x41x9
#            (node 61 per case, RMS over the 121 points)       shape_*.csv
#   support  the support radius (nodal spacings) at the chosen d_c    support.csv
#   grading  graded clouds (geometry.grading) against uniform ones on a
#            family of grids: error and time, the accuracy-per-second
#            table                                                  grading.csv
#   plots    shape.png, grading.png from the tables
#
# COMPARE is tests/solver/calculix_compare; block48 is solved as
# tests/solver/block48_at.yaml (sites by position, so any grid compares at
# the same points).  Each part takes 5 to 30 minutes on this 2-core machine;
# times in grading.csv are wall times of the solver on a shared machine (the
# bench, make bench, times the chosen clouds in one run).
set -eu
tool=$1 compare=$2 out=$3
shift 3
parts=${*:-shape support grading plots}
mkdir -p "$out"
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
say() { printf '%s\n' "accuracy study: $*" >&2; }

AT=tests/solver/block48_at.yaml
SPACINGS_103="0.5 1 2 4 6 8 16"
SPACINGS_25="1 2 4 8"
LEVELS="11,11,3;21,21,5;31,31,7;41,41,9"
# the choice the study supports (docs/validation.md §7), used by the later parts
CHOSEN="solver.rbf.spacings=8"

# sets_of "K=V K=V" -> "--set K=V --set K=V"
sets_of() { for s in $1; do printf -- '--set %s ' "$s"; done; }

# cantilever and patch rows: "l2,energy" of the last level
verify_row() {
    study=$1 levels=$2
    shift 2
    r=$("$tool" -q verify "$study" --levels "$levels" "$@" 2>/dev/null | tail -1 | cut -d, -f4,5)
    echo "${r:-failed,failed}"
}

# block48 against CalculiX, one row per level: grid,nodes,err61_fx,err61_fz,rms_fx,rms_fz,seconds,min_rcond
# (signed relative errors at node 61: u61 / reference - 1)
block48_rows() {
    levels=$1
    shift
    "$compare" --scene "$AT" --levels "$levels" --no-check "$@" 2>/dev/null |
        awk -F, 'NR > 1 && $4 == "fx" { ex[$2] = $5 / $8 - 1; rx[$2] = $13; n[$2] = $3; t[$2] = $14; c[$2] = $15; o[++k] = $2 }
                 NR > 1 && $4 == "fz" { ez[$2] = $7 / $10 - 1; rz[$2] = $13 }
                 END { for (i = 1; i <= k; ++i) { g = o[i]
                       printf "%s,%d,%.5f,%.5f,%.5f,%.5f,%.2f,%s\n", g, n[g], ex[g], ez[g], rx[g], rz[g], t[g], c[g] } }'
}

shape() {
    say "shape parameter (12 settings, 20 minutes to hours on a shared machine)"
    echo "q,spacings,l2,energy" >"$tmp/cant.csv"
    echo "q,spacings,l2,energy" >"$tmp/patch.csv"
    echo "q,spacings,grid,nodes,err61_fx,err61_fz,rms_fx,rms_fz,seconds,min_rcond" >"$tmp/b48.csv"
    rows="seed:2mm"
    for c in $SPACINGS_103; do rows="$rows 1.03:$c"; done
    for c in $SPACINGS_25; do rows="$rows 2.5:$c"; done
    for row in $rows; do
        q=${row%%:*} c=${row#*:}
        if [ "$q" = seed ]; then
            q=1.03 label=0 set="solver.rbf.d_c=2"
        else
            label=$c set="solver.rbf.spacings=$c solver.rbf.q=$q"
        fi
        say "  q = $q, d_c = $c"
        echo "$q,$label,$(verify_row cantilever 4 $(sets_of "$set"))" >>"$tmp/cant.csv"
        echo "$q,$label,$(verify_row patch 3 $(sets_of "$set"))" >>"$tmp/patch.csv"
        block48_rows "$LEVELS" $(sets_of "$set") | sed "s/^/$q,$label,/" >>"$tmp/b48.csv"
    done
    mv "$tmp/cant.csv" "$out/shape_cantilever.csv"
    mv "$tmp/patch.csv" "$out/shape_patch.csv"
    mv "$tmp/b48.csv" "$out/shape_block48.csv"
}

support() {
    say "support size"
    echo "support,cantilever_l2,cantilever_energy,patch_l2,patch_energy,grid,nodes,err61_fx,err61_fz,rms_fx,rms_fz,seconds,min_rcond" >"$tmp/sup.csv"
    for a in 1.8 2 2.5 3; do
        set="$CHOSEN solver.support=$a"
        cl=$(verify_row cantilever 4 $(sets_of "$set"))
        pl=$(verify_row patch 3 $(sets_of "$set"))
        block48_rows "21,21,5;31,31,7" $(sets_of "$set") | sed "s/^/$a,$cl,$pl,/" >>"$tmp/sup.csv"
    done
    mv "$tmp/sup.csv" "$out/support.csv"
}

grading() {
    say "graded clouds"
    echo "grading,grid,nodes,err61_fx,err61_fz,rms_fx,rms_fz,seconds,min_rcond" >"$tmp/grad.csv"
    for g in 1,1,1 2,2,1 2,2,2 3,3,1 3,3,2; do
        block48_rows "16,16,4;21,21,5;26,26,6;31,31,7;36,36,8;41,41,9" \
            $(sets_of "$CHOSEN geometry.grading=$g") | sed "s|^|$(echo $g | tr , /),|" >>"$tmp/grad.csv"
    done
    mv "$tmp/grad.csv" "$out/grading.csv"
}

plots() {
    say "plots"
    ccx=tests/calculix/data
    # CalculiX C3D20R runs at nu = 0.49 with the patch load: time and node 61's errors
    awk -F, 'NR == FNR { if (FNR > 1 && $2 == "C3D20R" && $3 == 0.49 && $6 == "patch") { t[$1] = $11; n[$1] = $9 }; next }
             FNR > 1 && ($1 in t) && $7 == "fx" { ex[$1] = $8 }
             FNR > 1 && ($1 in t) && $7 == "fz" { ez[$1] = $10 }
             END { for (r in ex) { if (r == "h0.6") continue  # the reference itself
                   a = ex[r] / 0.915615 - 1; b = ez[r] / -2.344933 - 1
                   printf "%s,%d,%.5f,%.5f,%.2f\n", r, n[r], a, b, t[r] } }' \
        "$ccx/block48_runs.csv" "$ccx/block48_node61.csv" | sort -t, -k5 -g >"$tmp/ccx.csv"
    gnuplot <<EOF
set terminal pngcairo size 900,600 font ",11"
set termoption noenhanced
set datafile separator ","
set grid
set output "$out/shape.png"
set logscale xy
set xlabel "d_c in local nodal spacings (d_c = spacings x h)"
set ylabel "relative error"
set key outside below horizontal maxrows 4
set xrange [0.3:30]
set title "d_c = spacings x h: errors against exact solutions and CalculiX (solid q = 1.03, dashed q = 2.5)"
plot "< awk -F, '\$1 == 1.03 && \$2 > 0' $out/shape_cantilever.csv" using 2:3 with linespoints lw 2 lt 1 title "cantilever L2 (level 3)", \
     "< awk -F, '\$1 == 2.5' $out/shape_cantilever.csv" using 2:3 with linespoints dt 2 lt 1 title "cantilever, q = 2.5", \
     "< awk -F, '\$1 == 1.03 && \$2 > 0' $out/shape_patch.csv" using 2:3 with linespoints lw 2 lt 2 title "patch test L2 (jittered)", \
     "< awk -F, '\$1 == 2.5' $out/shape_patch.csv" using 2:3 with linespoints dt 2 lt 2 title "patch test, q = 2.5", \
     "< awk -F, '\$1 == 1.03 && \$2 > 0 && \$3 == \"41x41x9\"' $out/shape_block48.csv" using 2:(abs(\$5)) with linespoints lw 2 lt 3 title "block48 41x41x9 node 61 fx", \
     "< awk -F, '\$1 == 1.03 && \$2 > 0 && \$3 == \"41x41x9\"' $out/shape_block48.csv" using 2:(abs(\$6)) with linespoints lw 2 lt 4 title "block48 41x41x9 node 61 fz", \
     "< awk -F, '\$1 == 2.5 && \$3 == \"41x41x9\"' $out/shape_block48.csv" using 2:(abs(\$5)) with linespoints dt 2 lt 3 title "block48 fx, q = 2.5", \
     "< awk -F, '\$1 == 2.5 && \$3 == \"41x41x9\"' $out/shape_block48.csv" using 2:(abs(\$6)) with linespoints dt 2 lt 4 title "block48 fz, q = 2.5", \
     "< awk -F, '\$1 == 1.03 && \$2 == 0 && \$3 == \"41x41x9\"' $out/shape_block48.csv" using (2 / 1.026):(abs(\$5)) with points pt 6 ps 2 lt 3 title "block48 fx, the seed's 2 mm (1.95 h)", \
     "< awk -F, '\$1 == 1.03 && \$2 == 0' $out/shape_cantilever.csv" using (2.0 / 3):3 with points pt 6 ps 2 lt 1 title "cantilever, the seed's 2 mm (0.67 h)"

unset xrange
set output "$out/grading.png"
set xlabel "wall time (s) on this shared machine (make bench-accuracy times the chosen clouds in one run)"
set ylabel "node 61: larger of |error fx|, |error fz|"
set key outside right top
set title "block48: accuracy per second, tissuefit (defaults; grading x/y/z) and CalculiX C3D20R"
plot for [g in "1/1/1 2/2/1 2/2/2 3/3/1 3/3/2"] "< grep ^".g.", $out/grading.csv" using 8:(abs(\$4) > abs(\$5) ? abs(\$4) : abs(\$5)) with linespoints lw 2 title "grading ".g, \
     "$tmp/ccx.csv" using 5:(abs(\$3) > abs(\$4) ? abs(\$3) : abs(\$4)) with points pt 7 ps 1.5 lc rgb "black" title "CalculiX C3D20R (committed runs)", \
     0.01 with lines dt 2 lc rgb "gray40" title "1 %", 0.003 with lines dt 3 lc rgb "gray40" title "0.3 %"
EOF
}

for p in $parts; do
    case $p in
    shape | support | grading | plots) $p ;;
    *) echo "accuracy_study.sh: unknown part '$p'" >&2; exit 2 ;;
    esac
done
say "done: $out"

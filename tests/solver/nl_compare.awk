# nl_compare.awk — block48 at large indentation (docs/validation.md §12):
# node 61's meshless force-displacement curves against the CalculiX NLGEOM
# reference, per load level.
#
#   awk -F, -v spec="PATH:LAW:RUN ..." [-v bound=B -v grid=G -v maxf=F]
#       [-v md=1] -f nl_compare.awk block48_nl_curves.csv MESHLESS.csv...
#
# block48_nl_curves.csv  CalculiX: run,factor,fx,fy,fz,ux,uy,uz,rx,ry,rz
# MESHLESS.csv           block48_curves rows (a "cloud" column first):
#                        cloud,grid,law,factor,fx,fy,fz,ux,uy,uz,...
# spec   which CalculiX run is the reference of each path and law: e.g.
#        "a:neo-hookean:nl_neohooke_a_g0.6"; the path of a meshless row is
#        told by its force at factor 1 (a: (0,0,-3), b: (1,0,0), c: (1,0,-3)).
#
# Prints path,law,cloud,factor,u_meshless,u_calculix,rel (CSV, u the
# displacement's length in mm and rel = |u_meshless - u_ccx| / |u_ccx| as
# vectors) for every meshless level whose factor the reference printed, or
# with md=1 a markdown table per path and law: the relative error per cloud
# at factors 0.2 .. 1 and the largest.  With bound (and grid, the cloud held
# to it) exits 1 when that cloud's error exceeds bound at any factor up to
# maxf (default 1), or when the cloud or its reference is missing.  With
# shift (the check's self-test) that cloud's curve is first moved away from
# the reference by shift x |u_calculix| at every level.
BEGIN {
    n = split(spec, items, " ")
    for (k = 1; k <= n; ++k) {
        split(items[k], f, ":")
        ref_run[f[1] SUBSEP f[2]] = f[3]
        want[f[3]] = f[1] SUBSEP f[2]
    }
    if (maxf == "") maxf = 1
}
FNR == 1 { file++; next }
file == 1 && ($1 in want) {
    key = want[$1] SUBSEP sprintf("%.6f", $2)
    cx[key] = $6; cy[key] = $7; cz[key] = $8
    next
}
file >= 2 {
    if ($8 == "failed") next
    p = path_of($5 / $4, $6 / $4, $7 / $4)
    if (!((p SUBSEP $3) in ref_run)) next
    key = p SUBSEP $3 SUBSEP sprintf("%.6f", $4)
    if (!(key in cx)) next
    dx = $8 - cx[key]; dy = $9 - cy[key]; dz = $10 - cz[key]
    rl = sqrt(cx[key] ^ 2 + cy[key] ^ 2 + cz[key] ^ 2)
    if (shift != "" && $1 == grid) {
        # the self-test: the cloud moved away from the reference by shift
        dl = sqrt(dx * dx + dy * dy + dz * dz)
        if (dl > 0) { g = (dl + shift * rl) / dl; dx *= g; dy *= g; dz *= g }
        else { dx = shift * cx[key]; dy = shift * cy[key]; dz = shift * cz[key] }
        $8 = cx[key] + dx; $9 = cy[key] + dy; $10 = cz[key] + dz
    }
    rel = sqrt(dx * dx + dy * dy + dz * dz) / rl
    row[++rows] = p "," $3 "," $1 "," $4 "," sqrt($8 ^ 2 + $9 ^ 2 + $10 ^ 2) "," rl "," rel
    err[p SUBSEP $3 SUBSEP $1 SUBSEP sprintf("%.6f", $4)] = rel
    um[p SUBSEP $3 SUBSEP $1 SUBSEP sprintf("%.6f", $4)] = sqrt($8 ^ 2 + $9 ^ 2 + $10 ^ 2)
    uc[p SUBSEP $3 SUBSEP sprintf("%.6f", $4)] = rl
    if (!((p SUBSEP $3 SUBSEP $1) in seen)) { seen[p SUBSEP $3 SUBSEP $1] = 1; order[++clouds] = p SUBSEP $3 SUBSEP $1 }
    if ($1 == grid) {
        held[p SUBSEP $3] = 1
        if ($4 <= maxf + 1e-9) {
            compared[p SUBSEP $3]++; top[p SUBSEP $3] = $4
            if (rel > worst[p SUBSEP $3]) worst[p SUBSEP $3] = rel
        }
    }
}
function path_of(x, y, z) {
    if (near(x, 0) && near(y, 0) && near(z, -3)) return "a"
    if (near(x, 1) && near(y, 0) && near(z, 0)) return "b"
    if (near(x, 1) && near(y, 0) && near(z, -3)) return "c"
    return "?"
}
function near(a, b) { return (a - b) ^ 2 < 1e-18 }
END {
    if (md) markdown()
    else {
        print "path,law,cloud,factor,u_meshless,u_calculix,rel"
        for (k = 1; k <= rows; ++k) print row[k]
    }
    if (bound == "") exit 0
    bad = 0
    for (pl in ref_run) {
        split(pl, q, SUBSEP)
        if (!(pl in held)) {
            printf "nl_compare: no %s rows of path %s, %s against %s\n", grid, q[1], q[2], ref_run[pl] > "/dev/stderr"
            bad = 1
            continue
        }
        printf "nl_compare: path %s, %s, %s against %s: node 61 within %.2f %% at %d load levels up to factor %g (bound %g %%)\n", \
            q[1], q[2], grid, ref_run[pl], 100 * worst[pl], compared[pl], top[pl], 100 * bound > "/dev/stderr"
        if (!(worst[pl] <= bound)) bad = 1
    }
    exit bad
}
function markdown(   k, c, f, line, m, e) {
    print "| path | law | cloud | 0.2 | 0.4 | 0.6 | 0.8 | 1.0 | largest |"
    print "|---|---|---|---|---|---|---|---|---|"
    for (k = 1; k <= clouds; ++k) {
        split(order[k], c, SUBSEP)
        line = "| " c[1] " | " c[2] " | " c[3]
        m = 0
        for (f = 1; f <= 10; ++f) {
            e = (order[k] SUBSEP sprintf("%.6f", f / 10))
            if (e in err && err[e] > m) m = err[e]
            if (f % 2 == 0) line = line " | " (e in err ? sprintf("%.2f %%", 100 * err[e]) : "—")
        }
        print line " | " sprintf("%.2f %%", 100 * m) " |"
    }
    # the curves themselves: |u61| (mm) per cloud, and the reference
    print ""
    print "| path | law | cloud | 0.1 | 0.3 | 0.5 | 0.7 | 0.9 | 1.0 |"
    print "|---|---|---|---|---|---|---|---|---|"
    for (k = 1; k <= clouds; ++k) {
        split(order[k], c, SUBSEP)
        line = "| " c[1] " | " c[2] " | " c[3]
        for (f = 1; f <= 10; f += 2) line = line " | " cell(um, order[k] SUBSEP sprintf("%.6f", f / 10))
        print line " | " cell(um, order[k] SUBSEP sprintf("%.6f", 1)) " |"
        if (k == clouds || order[k + 1] !~ "^" c[1] SUBSEP c[2] SUBSEP) {
            line = "| " c[1] " | " c[2] " | CalculiX " ref_run[c[1] SUBSEP c[2]]
            for (f = 1; f <= 10; f += 2) line = line " | " cell(uc, c[1] SUBSEP c[2] SUBSEP sprintf("%.6f", f / 10))
            print line " | " cell(uc, c[1] SUBSEP c[2] SUBSEP sprintf("%.6f", 1)) " |"
        }
    }
}
function cell(a, key) { return key in a ? sprintf("%.4f", a[key]) : "—" }

# richardson.awk — the reference value of a box scene's load point and its
# error estimate, from the committed levels (docs/calculix-reference.md,
# "The reference value at node 61"):
#
#   awk -F, -v levels="h1.2:40:4 h0.8:60:6 h0.6:80:8" \
#       -f richardson.awk DATA/SCENE_node61.csv > DATA/SCENE_node61_reference.csv
#
# LEVELS are three levels coarse to fine of one uniform refinement family
# (element size h = length / divisions in plane, the layers in proportion);
# their runs are the rows of the node table whose run is the level's name.
# For the fx and fz cases, the load-direction component u(h) (ux of fx, uz of
# fz) is taken as u(h) = u0 + C h^p: the observed order p solves
#     (u1 - u2) / (u2 - u3) = (h1^p - h2^p) / (h2^p - h3^p)
# (bisection on 0.5 <= p <= 8; the levels' ratios need not be equal), and
# u0 = u3 - C h3^p.  The estimated error of u0 is the larger of
#   - the change of u0 when p is set to the next whole order (p rounded up
#     to an integer, at least 2), i.e. how much the extrapolation depends on
#     the fitted order, and
#   - a quarter of the correction |u3 - u0| (an extrapolation is trusted to
#     remove three quarters of the error of the finest level, no more);
# both in per cent of |u0|.  Convergence that is not monotone (the two
# changes of opposite sign) has no p: the finest value is kept and its error
# estimated as the last change.
# Output CSV: case,component,value,finest,order,error_pct,method.

BEGIN {
    n = split(levels, lv, " ")
    if (n != 3) { print "richardson: LEVELS must name three levels" > "/dev/stderr"; exit 2 }
    for (k = 1; k <= 3; k++) {
        split(lv[k], f, ":"); name[k] = f[1]; h[k] = 1 / f[2]
    }
}

FNR > 1 && $6 == "patch" {
    for (k = 1; k <= 3; k++) {
        if ($1 == name[k]) { if ($7 == "fx") ux[k] = $8; if ($7 == "fz") uz[k] = $10 }
    }
}

# the right side of the order equation minus the observed ratio
function g(p, ratio) { return (h[1] ^ p - h[2] ^ p) / (h[2] ^ p - h[3] ^ p) - ratio }

function order(u1, u2, u3,    ratio, lo, hi, mid, it) {
    ratio = (u1 - u2) / (u2 - u3)
    lo = 0.5; hi = 8
    if (g(lo, ratio) * g(hi, ratio) > 0) return -1
    for (it = 0; it < 200; it++) {
        mid = (lo + hi) / 2
        if (g(lo, ratio) * g(mid, ratio) <= 0) hi = mid; else lo = mid
    }
    return (lo + hi) / 2
}

function extrapolate(u2, u3, p) { return u3 - (u2 - u3) / (h[2] ^ p - h[3] ^ p) * h[3] ^ p }

function report(c, comp, u1, u2, u3,    p, u0, q, alt, e1, e2) {
    if ((u1 - u2) * (u2 - u3) <= 0 || (p = order(u1, u2, u3)) < 0) {
        printf "%s,%s,%.7g,%.7g,,%.3g,finest level (convergence not monotone)\n", c, comp, u3, u3, \
            100 * abs(u3 - u2) / abs(u3)
        return
    }
    u0 = extrapolate(u2, u3, p)
    q = int(p) + 1; if (q < 2) q = 2
    alt = extrapolate(u2, u3, q)
    e1 = abs(alt - u0); e2 = abs(u3 - u0) / 4
    printf "%s,%s,%.7g,%.7g,%.3f,%.3g,Richardson %s-%s-%s\n", c, comp, u0, u3, p, \
        100 * (e1 > e2 ? e1 : e2) / abs(u0), name[1], name[2], name[3]
}

function abs(x) { return x < 0 ? -x : x }

END {
    for (k = 1; k <= 3; k++) {
        if (!(k in ux) || !(k in uz)) { printf "richardson: no fx/fz row for level %s\n", name[k] > "/dev/stderr"; exit 1 }
    }
    print "case,component,value,finest,order,error_pct,method"
    report("fx", "ux", ux[1], ux[2], ux[3])
    report("fz", "uz", uz[1], uz[2], uz[3])
}

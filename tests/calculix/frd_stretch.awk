# frd_stretch.awk — how far the top surface under the load centre is
# compressed, from a CalculiX .frd with the displacements of every node
# (box_deck --field): for each displacement block (one per printed load
# level, and the last unconverged attempt of a run that stopped) one line
#   time,uz,centre,least
# time the block's load factor, uz the centre node's displacement along z,
# and on the top line y = yc (a mirror plane) the in-plane stretch along x
# (deformed over reference distance between consecutive nodes): centre, of
# the pair ending at the centre node (xc, yc, zt); least, the smallest of
# the pairs within r of the centre (under the patch: r = half its side).
#   awk -v xc=24 -v yc=24 -v zt=6 -v r=2.4 -f frd_stretch.awk RUN.frd
# Exit 1 when the centre or no neighbour is in the file.
BEGIN { tol = 1e-6; mode = ""; m = 0 }
function abs(v) { return v < 0 ? -v : v }
# frd fixed format: " -1", node id in 10 columns, values in 12 each
function val(i) { return substr($0, 14 + 12 * (i - 1), 12) + 0 }
/^    2C/ { mode = "coords"; next }
/^  100CL/ { time = substr($0, 13, 12) + 0; next }
/^ -4  DISP/ { mode = "disp"; next }
/^ -3/ { if (mode == "disp") emit(); mode = ""; next }
mode == "" || !/^ -1/ { next }
{ n = substr($0, 4, 10) + 0 }
mode == "coords" {
    x = val(1)
    if (abs(val(2) - yc) <= tol && abs(val(3) - zt) <= tol && abs(x - xc) <= r + tol) {
        # insertion by x: the line has a few dozen nodes
        for (k = ++m; k > 1 && px[k - 1] > x; --k) { px[k] = px[k - 1]; pn[k] = pn[k - 1] }
        px[k] = x; pn[k] = n; at[n] = k
    }
    next
}
mode == "disp" { if (n in at) { ux[at[n]] = val(1); uz[at[n]] = val(3) } next }
function emit(   k, s, least, centre, c) {
    c = 0
    for (k = 1; k <= m; ++k) if (abs(px[k] - xc) <= tol) c = k
    if (c < 2) { print "frd_stretch: no top node at the centre or beside it" > "/dev/stderr"; exit 1 }
    least = 1e300
    for (k = 2; k <= m; ++k) {
        s = (px[k] + ux[k] - px[k - 1] - ux[k - 1]) / (px[k] - px[k - 1])
        if (s < least) least = s
        if (k == c) centre = s
    }
    printf "%.6g,%.6f,%.6f,%.6f\n", time, uz[c], centre, least
}

# cube_surface.awk -v S=SIZE -v N=DIVISIONS: the closed surface of the cube [0, S]^3
# as an OBJ, each face split into N x N squares of two triangles, wound
# outward (vertices shared between faces written once).
function vid(x, y, z,   k) { k = x "," y "," z; if (!(k in id)) { id[k] = ++nv; printf "v %g %g %g\n", x * S / N, y * S / N, z * S / N }; return id[k] }
function quad(a, b, c, d) { f[++nf] = a " " b " " c; f[++nf] = a " " c " " d }
BEGIN {
    for (i = 0; i < N; ++i) for (j = 0; j < N; ++j) {
        # z = 0 (normal -z) and z = N (+z)
        quad(vid(i, j, 0), vid(i, j + 1, 0), vid(i + 1, j + 1, 0), vid(i + 1, j, 0))
        quad(vid(i, j, N), vid(i + 1, j, N), vid(i + 1, j + 1, N), vid(i, j + 1, N))
        # y = 0 (-y) and y = N (+y)
        quad(vid(i, 0, j), vid(i + 1, 0, j), vid(i + 1, 0, j + 1), vid(i, 0, j + 1))
        quad(vid(i, N, j), vid(i, N, j + 1), vid(i + 1, N, j + 1), vid(i + 1, N, j))
        # x = 0 (-x) and x = N (+x)
        quad(vid(0, i, j), vid(0, i, j + 1), vid(0, i + 1, j + 1), vid(0, i + 1, j))
        quad(vid(N, i, j), vid(N, i + 1, j), vid(N, i + 1, j + 1), vid(N, i, j + 1))
    }
    for (k = 1; k <= nf; ++k) print "f", f[k]
}

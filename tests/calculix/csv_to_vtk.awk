# csv_to_vtk.awk — one block48 displacement CSV (node,x,y,z,ux,uy,uz; 121
# rows, x fastest) as a legacy VTK structured grid of the top surface with
# the displacement as point vectors, for ParaView (Warp By Vector).
#
#   awk -v title=NAME -f csv_to_vtk.awk block48_fz_h0.6.csv > block48_fz_h0.6.vtk

BEGIN { FS = "," }
NR == 1 { next }
{ p[NR - 1] = $2 " " $3 " " $4; u[NR - 1] = $5 " " $6 " " $7; n = NR - 1 }
END {
    if (n != 121) { printf "csv_to_vtk: %s: %d rows, expected 121\n", FILENAME, n > "/dev/stderr"; exit 1 }
    print "# vtk DataFile Version 3.0"
    print "block48 CalculiX reference " title " (mm)"
    print "ASCII"
    print "DATASET STRUCTURED_GRID"
    print "DIMENSIONS 11 11 1"
    print "POINTS 121 double"
    for (i = 1; i <= n; i++) print p[i]
    print "POINT_DATA 121"
    print "VECTORS displacement double"
    for (i = 1; i <= n; i++) print u[i]
}

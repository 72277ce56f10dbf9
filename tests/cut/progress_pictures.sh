#!/bin/sh
# progress_pictures.sh TISSUEFIT SCENE OUTDIR PNG — block48_cut's top
# surface at the cut progress values 0, 0.5 and 1 (docs/cutting.md, "Cut
# progress"): the scene's outputs replaced by a lattice of top-surface
# points around the incision (so that the field is drawn on both lips, not
# only at the nodes), one solve per s under a force along +x that opens
# the cut, OUTDIR/progress_S.vtu for ParaView (cells a cut passes through
# left out: the cut faces show) and the PNG of the three.
set -eu
tf=$1 scene=$2 dir=$3 png=$4
force=1,0,0 scale=3
mkdir -p "$dir"
# the lattice (0.5 mm, no point on the cut plane x = 18) instead of the face
sed -e 's/^  select: face.*/  select: points/' \
    -e 's/^  face: z+.*/  lattice: {min: [8.25, 8.25, 6], max: [31.75, 39.75, 6], count: [48, 64, 1]}/' \
    "$scene" > "$dir/progress_scene.yaml"
for s in 0 0.5 1; do
    "$tf" -q solve "$dir/progress_scene.yaml" --force $force --cut-progress $s \
        --outputs "$dir/progress_$s.csv" --vtk "$dir/progress_$s.vtu" -o "$dir/progress_$s.txt"
    awk -F, -v scale=$scale -v cx=18 -v y0=14 -v y1="$(echo "14 + 20 * $s" | bc -l)" \
        -f tests/cut/sort.awk -f tests/cut/top_lattice.awk "$dir/progress_$s.csv" > "$dir/progress_$s.dat"
done
gnuplot -e "d0='$dir/progress_0.dat'; d1='$dir/progress_0.5.dat'; d2='$dir/progress_1.dat'; \
  s0=0; s1=0.5; s2=1; out='$png'; scale=$scale; force='($force)'" tests/cut/progress_picture.gp
echo "cut progress: $png, $dir/progress_{0,0.5,1}.vtu (ParaView)"

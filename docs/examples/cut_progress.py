#!/usr/bin/python3
"""docs/cutting-progress.png from Python: block48_cut's top surface around
the incision at the cut progress s = 0, 0.5 and 1 under 1 N along +x,
displacements x 3 (docs/cutting.md, "Cut progress").

    PYTHONPATH=PREFIX/lib/python3.11/dist-packages \\
        python3 docs/examples/cut_progress.py coeffs/block48_cut.yaml OUTDIR

(`make python-example` runs it from a staged install.)  Writes
OUTDIR/progress_S.vtu for ParaView (meshio; the cells a cut passes through
left out), OUTDIR/progress_S.dat (the deformed lattice as gnuplot lines) and
OUTDIR/cutting-progress.png, drawn by the same gnuplot script as
`make cut-progress-pictures` (tests/cut/progress_picture.gp)."""

import os
import subprocess
import sys

import tissuefit  # before numpy: it pins OpenBLAS as the tool does

import numpy as np

FORCE = (1.0, 0.0, 0.0)  # N, opens the cut
SCALE = 3  # displacements drawn x 3
CUT_X, CUT_Y0, CUT_LENGTH = 18.0, 14.0, 20.0  # the incision of coeffs/block48_cut.yaml


def lattice(lo, hi, count):
    """A scene's `lattice:` (host/scene/scene_regions.c): count points per
    axis from lo to hi, x fastest, the last exactly at hi."""
    axes = []
    for a in range(3):
        m = count[a]
        axes.append([lo[a] if m == 1 or i == 0 else hi[a] if i + 1 == m
                     else lo[a] + i * (hi[a] - lo[a]) / (m - 1) for i in range(m)])
    return np.array([(x, y, z) for z in axes[2] for y in axes[1] for x in axes[0]])


def lines(points, u, y1):
    """The deformed lattice as gnuplot line blocks (tests/cut/top_lattice.awk):
    every other line along x, broken where it crosses the cut plane inside
    the cut so far (y0 <= y <= y1), and every other line along y."""
    xs, ys = np.unique(points[:, 0]), np.unique(points[:, 1])
    at = {(p[0], p[1]): (p[0] + SCALE * d[0], p[1] + SCALE * d[1]) for p, d in zip(points, u)}
    out = []
    for y in ys[::2]:
        for i, x in enumerate(xs):
            if i > 0 and xs[i - 1] < CUT_X < x and CUT_Y0 <= y <= y1:
                out.append("")
            out.append("%.6g %.6g" % at[x, y])
        out.append("")
    for x in xs[::2]:
        out += ["%.6g %.6g" % at[x, y] for y in ys] + [""]
    return "\n".join(out) + "\n"


def main(scene_path, outdir):
    os.makedirs(outdir, exist_ok=True)
    scene = tissuefit.Scene(scene_path)
    # a 0.5 mm lattice of top-surface points, none on the cut plane x = 18
    points = lattice((8.25, 8.25, 6), (31.75, 39.75, 6), (48, 64, 1))
    dats = []
    for s in (0, 0.5, 1):
        sol = scene.solve(FORCE, cut_progress=s, points=points)
        sol.write_vtu(os.path.join(outdir, f"progress_{s:g}.vtu"))
        dat = os.path.join(outdir, f"progress_{s:g}.dat")
        with open(dat, "w") as f:
            f.write(lines(points, sol.at_points, CUT_Y0 + CUT_LENGTH * s))
        dats.append(dat)
        print(f"s = {s:g}: largest displacement on the lattice "
              f"{np.abs(sol.at_points).max():.4f} mm, {len(scene.cells()[1])} cells")
    png = os.path.join(outdir, "cutting-progress.png")
    script = os.path.join(os.path.dirname(os.path.abspath(__file__)), "../../tests/cut/progress_picture.gp")
    subprocess.run(["gnuplot", "-e",
                    f"d0='{dats[0]}'; d1='{dats[1]}'; d2='{dats[2]}'; s0=0; s1=0.5; s2=1; "
                    f"out='{png}'; scale={SCALE}; force='(1,0,0)'", script], check=True)
    print(f"cut progress: {png}, {outdir}/progress_{{0,0.5,1}}.vtu (ParaView)")


if __name__ == "__main__":
    if len(sys.argv) != 3:
        sys.exit("usage: cut_progress.py coeffs/block48_cut.yaml OUTDIR")
    main(sys.argv[1], sys.argv[2])

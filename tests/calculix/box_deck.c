/*
 * box_deck.c — writes a CalculiX input deck (.inp) for one of the project's
 * box benchmarks on stdout (docs/calculix-reference.md):
 *
 *   block48  GUIDE §5: box [0,48]x[0,48]x[0,6] mm, the four lateral faces
 *            clamped, the force over the top-face square [21.6,26.4]^2,
 *            outputs on the 11 x 11 grid 4.8 mm apart (node 61 the centre).
 *   beam40   box [0,40]x[0,20]x[0,20] mm clamped on its face x = 0 only,
 *            the force over the top-face square [27.5,32.5]x[7.5,12.5],
 *            outputs on the 9 x 5 grid 5 mm apart (node 25 = (30,10,20), the
 *            patch centre).
 *
 * A 1 N force is spread as a uniform traction over the patch (reference
 * area), one *STEP per load case, E = 0.32 MPa.
 *
 * Mesh: a structured grid of 20-node hexahedra, N elements along x, N Ly/Lx
 * along y and L layers through the thickness.  Each scene has a quantum
 * (half the patch side: 2.4 mm for block48, 2.5 mm for beam40) and N must
 * be a multiple of the box's length in quanta (20 for block48, 16 for
 * beam40): then element edges fall on the patch edges and on the output
 * points, the patch is a set of element faces and the output points and the
 * patch centre are mesh nodes at every level.
 *
 * Graded meshes (--grade F:M instead of --divisions): the number of elements
 * per quantum varies instead, F on the patch's quanta and GRADE_FACTOR times
 * fewer per quantum of distance from the patch (rounded up, at least M),
 * so element edges still fall on every quantum boundary (patch edges, output
 * points); --layer-ratio R makes each layer R times thicker than the one
 * above it (thin layers under the load).  Nodes keep their lattice numbers;
 * positions come from per-axis coordinate tables.
 *
 * Node numbers come from a lattice at half the element size, so a node's
 * number is a formula of its position: id = 1 + i + Kx (j + Ky k),
 * Kx = 2 N + 1, Ky = 2 Ny + 1, with i, j, k the half-step indices along x, y,
 * z.  Lattice points at face and cell centres are not nodes of a 20-node
 * hexahedron and are skipped.
 *
 * Load: CalculiX's *DLOAD has no tangential surface traction (only the
 * normal pressure P1..P6, body forces and gravity), so every case is applied
 * as the consistent nodal loads of a uniform traction t on each loaded
 * 8-node face: -A t / 12 at the corners, +A t / 3 at the midsides
 * (A = face area; the shape functions' integrals over a rectangle).  For fz
 * the pressure form (*DLOAD P2 on the top faces) can be asked for instead,
 * as an independent check of those nodal loads.  --point puts the whole force
 * on the patch centre instead, as the seed (Zhou 2017) did: a point load has
 * no converged answer (the displacement under it grows without bound as the
 * mesh refines), which the study shows beside the patch load.
 *
 * Large deformation (--nlgeom): every step carries NLGEOM and the load ramps
 * linearly from zero over the step (CalculiX's default amplitude in a static
 * step); the results are printed at K equal load levels (*TIME POINTS), and
 * CalculiX's automatic incrementation may cut an increment between them when
 * Newton does not converge (down to MIN_FRACTION of a level's interval; the
 * run then stops and the path ends at the last converged load).  *CLOAD
 * forces keep their global direction and magnitude as the body deforms (dead
 * loads: CalculiX adds xforc to fext unchanged, src/rhsnodef.f), whereas a
 * *DLOAD pressure follows the deformed face under NLGEOM (src/e_c3d.f uses
 * co + vold): so the patch load stays the consistent nodal loads of the
 * reference-area traction, and --pressure is refused with --nlgeom.
 * Materials: *ELASTIC, which under NLGEOM is St. Venant-Kirchhoff (CalculiX
 * manual, "Linear elasticity": PK2 stress linear in the Lagrange strain), or
 * *HYPERELASTIC, NEO HOOKE with U = C10 (I1bar - 3) + (1/D1) (J - 1)^2
 * (manual, *HYPERELASTIC), C10 = mu/2 and D1 = 2/K so that its small-strain
 * limit has the same E and nu.  --force replaces the unit cases by one load
 * path ramped from zero to the given force.  Newton is held to --tolerance
 * (largest residual force over the average force, and largest correction
 * over the increment's largest displacement, *CONTROLS PARAMETERS=FIELD;
 * CalculiX's defaults, 0.005 and 0.01, are too loose for a reference).
 *
 * Symmetry (--symmetry x|y|xy): only the part x <= xc and/or y <= yc of the
 * box is meshed (xc, yc the patch centre, a mirror plane of the scene), with
 * the normal displacement zero on the cut.  The model then carries half or
 * a quarter of the force; a case must be symmetric about the plane (no force
 * component normal to it).  Output points beyond the cut are written as
 * mirror images of points inside.
 *
 * Comment lines the extraction reads (CalculiX ignores lines starting **):
 *   ** SIZE elements nodes free_dofs      (of the meshed part)
 *   ** STEP n case fx fy fz               (the force of step n on the whole box, N)
 *   ** SHARE s                            (the meshed part's share of the force)
 *   ** OUT node ccx_node x y z            (output point node = i + nx j + 1)
 *   ** MIRROR node source sx sy sz x y z  (u(node) = (sx, sy, sz) * u(source))
 *
 * Exit 0 ok, 2 bad usage (nothing written).
 */
#include <getopt.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#define YOUNG 0.32  /* MPa = N/mm^2 */
#define MAX_CASES 4 /* fx, fy, fz and a --force path */
#define PATH_CASE 3
/* Smallest increment CalculiX may cut back to, relative to the interval
 * between printed load levels, before it gives up (--min-fraction changes
 * it, to tell an increment-control stop from a loss of stability). */
#define MIN_FRACTION 1e-2
/* Graded meshes (--grade): elements per quantum fall by this factor per
 * quantum of distance from the patch, down to the given minimum. */
#define GRADE_FACTOR 0.7
#define MAX_DIV 400   /* elements along a side */
#define MAX_LAYERS 100
#define MAX_QUANTA 32 /* box side in quanta */

enum { X0 = 1, X1 = 2, Y0 = 4, Y1 = 8 }; /* lateral faces */
enum { SYM_X = 1, SYM_Y = 2 };           /* mirror planes x = xc, y = yc */

typedef struct {
    const char *name, *title;
    double lx, ly, lz; /* mm */
    int qx, qy;        /* box sides in quanta (a quantum is half the patch side) */
    int px, py;        /* patch lower corner in quanta; the patch is 2 x 2 quanta */
    int out_step;      /* output spacing in quanta */
    int clamp;         /* clamped lateral faces */
    int mirrors;       /* mirror planes through the patch centre the box has */
} scene;

static const scene scenes[] = {
    {"block48", "block48 (docs/validation.md)", 48, 48, 6, 20, 20, 9, 9, 2, X0 | X1 | Y0 | Y1, SYM_X | SYM_Y},
    {"beam40", "beam40 (docs/calculix-reference.md)", 40, 20, 20, 16, 8, 11, 3, 2, X0, SYM_Y},
};

typedef struct {
    const scene *sc;
    int n, ny;        /* elements along x and along y */
    int layers;       /* elements through the thickness */
    int m;            /* elements per quantum */
    int symmetry;     /* SYM_X | SYM_Y: mirror planes cut */
    double nu;
    const char *element;
    enum { LOAD_PATCH, LOAD_PRESSURE, LOAD_POINT } load;
    enum { MAT_ELASTIC, MAT_NEOHOOKE } material;
    int nlgeom;       /* 1: geometrically nonlinear steps */
    int increments;   /* printed load levels per step (NLGEOM) */
    double tolerance; /* Newton residual and correction criteria (NLGEOM) */
    double min_fraction; /* smallest increment / level interval (NLGEOM) */
    int min_given;       /* --min-fraction was given */
    int field;        /* 1: displacements of every node at the printed levels */
    int cases[MAX_CASES];
    int ncases;
    int grade_fine, grade_min; /* --grade FINE:MIN (0: uniform, --divisions) */
    double layer_ratio;        /* --layer-ratio: each layer this times the one above */
    int qx0[MAX_QUANTA + 1], qy0[MAX_QUANTA + 1]; /* first element of each quantum */
    double cx[2 * MAX_DIV + 1], cy[2 * MAX_DIV + 1], cz[2 * MAX_LAYERS + 1]; /* lattice */
} deck;

static const char *const case_name[MAX_CASES] = {"fx", "fy", "fz", "path"};
/* Unit force of each case: +x, +y and -z (pressing into the block); the
 * path's force is set by --force. */
static double case_force[MAX_CASES][3] = {{1, 0, 0}, {0, 1, 0}, {0, 0, -1}, {0, 0, 0}};
static const char *const material_name[] = {"elastic", "neohooke"};
static const char *const load_form[] = {"consistent nodal loads", "pressure (fz)",
                                        "point load at the patch centre"};

/* Lattice extents (half steps) of the whole box, and the patch centre. */
static int imax(const deck *d) { return 2 * d->n; }
static int jmax(const deck *d) { return 2 * d->ny; }
static int kmax(const deck *d) { return 2 * d->layers; }
static int icentre(const deck *d) { return 2 * d->qx0[d->sc->px + 1]; }
static int jcentre(const deck *d) { return 2 * d->qy0[d->sc->py + 1]; }

/* The meshed part: lattice i <= ilast, j <= jlast. */
static int ilast(const deck *d) { return d->symmetry & SYM_X ? icentre(d) : imax(d); }
static int jlast(const deck *d) { return d->symmetry & SYM_Y ? jcentre(d) : jmax(d); }

static long node_id(const deck *d, int i, int j, int k)
{
    long sx = imax(d) + 1, sy = jmax(d) + 1;
    return 1 + i + sx * (j + sy * (long)k);
}

/* A lattice point is a node when at most one of its indices is odd
 * (corner: none odd; midside of an edge: exactly one). */
static int is_node(int i, int j, int k) { return (i & 1) + (j & 1) + (k & 1) <= 1; }

static double coord_x(const deck *d, int i) { return d->cx[i]; }
static double coord_y(const deck *d, int j) { return d->cy[j]; }
static double coord_z(const deck *d, int k) { return d->cz[k]; }

static int clamped(const deck *d, int i, int j)
{
    int c = d->sc->clamp;
    return ((c & X0) && i == 0) || ((c & X1) && i == imax(d)) || ((c & Y0) && j == 0) ||
           ((c & Y1) && j == jmax(d));
}

/* Nodes on a cut mirror plane (and not clamped): normal displacement 0. */
static int on_mirror(const deck *d, int i, int j, int plane)
{
    return !clamped(d, i, j) && (d->symmetry & plane) &&
           (plane == SYM_X ? i == icentre(d) : j == jcentre(d));
}

static int out_nx(const deck *d) { return d->sc->qx / d->sc->out_step + 1; }
static int out_ny(const deck *d) { return d->sc->qy / d->sc->out_step + 1; }
/* Lattice index of output column a / row b (on a quantum boundary). */
static int out_i(const deck *d, int a) { return 2 * d->qx0[a * d->sc->out_step]; }
static int out_j(const deck *d, int b) { return 2 * d->qy0[b * d->sc->out_step]; }

static void count_nodes(const deck *d, long *nodes, long *fixed_dofs)
{
    *nodes = *fixed_dofs = 0;
    for (int k = 0; k <= kmax(d); ++k) {
        for (int j = 0; j <= jlast(d); ++j) {
            for (int i = 0; i <= ilast(d); ++i) {
                if (is_node(i, j, k)) {
                    ++*nodes;
                    *fixed_dofs += clamped(d, i, j) ? 3
                                                    : on_mirror(d, i, j, SYM_X) +
                                                          on_mirror(d, i, j, SYM_Y);
                }
            }
        }
    }
}

static double share(const deck *d)
{
    return ((d->symmetry & SYM_X) ? 0.5 : 1.0) * ((d->symmetry & SYM_Y) ? 0.5 : 1.0);
}

/* The output points: inside the meshed part as OUT, beyond a cut as the
 * mirror image of a point inside. */
static void write_outputs(const deck *d)
{
    int step = d->sc->out_step, nx = out_nx(d);
    for (int b = 0; b < out_ny(d); ++b) {
        for (int a = 0; a < nx; ++a) {
            int i = out_i(d, a), j = out_j(d, b), si = 1, sj = 1, as = a, bs = b;
            if (i > ilast(d)) {
                as = (2 * (d->sc->px + 1) - a * step) / step; /* the mirror image's point */
                i = out_i(d, as);
                si = -1;
            }
            if (j > jlast(d)) {
                bs = (2 * (d->sc->py + 1) - b * step) / step;
                j = out_j(d, bs);
                sj = -1;
            }
            if (si == 1 && sj == 1) {
                printf("** OUT %d %ld %.15g %.15g %.15g\n", a + nx * b + 1, node_id(d, i, j, kmax(d)),
                       coord_x(d, i), coord_y(d, j), d->sc->lz);
            } else {
                printf("** MIRROR %d %d %d %d 1 %.15g %.15g %.15g\n", a + nx * b + 1,
                       as + nx * bs + 1, si, sj, coord_x(d, out_i(d, a)),
                       coord_y(d, out_j(d, b)), d->sc->lz);
            }
        }
    }
}

static void write_header(const deck *d)
{
    long nodes, fixed;
    count_nodes(d, &nodes, &fixed);
    long elements = (long)(ilast(d) / 2) * (jlast(d) / 2) * d->layers;
    printf("** %s written by tests/calculix/box_deck\n", d->sc->title);
    printf("** %d x %d x %d %s elements, nu = %.15g, E = %.15g MPa, load as %s\n", d->n, d->ny,
           d->layers, d->element, d->nu, YOUNG, load_form[d->load]);
    if (d->nlgeom) {
        printf("** material %s, NLGEOM, %d load levels\n", material_name[d->material],
               d->increments);
    }
    if (d->grade_fine != 0 || d->layer_ratio != 1) {
        printf("** graded: %d:%d elements per quantum (patch:least, factor %g per quantum), "
               "layer ratio %g\n", d->grade_fine, d->grade_min, GRADE_FACTOR, d->layer_ratio);
    }
    printf("** SIZE %ld %ld %ld\n", elements, nodes, 3 * nodes - fixed);
    for (int s = 0; s < d->ncases; ++s) {
        const double *f = case_force[d->cases[s]];
        printf("** STEP %d %s %.15g %.15g %.15g\n", s + 1, case_name[d->cases[s]], f[0], f[1], f[2]);
    }
    if (d->symmetry) {
        printf("** SHARE %.15g\n", share(d));
    }
    write_outputs(d);
    printf("*HEADING\n%s %s n=%d layers=%d nu=%.15g\n", d->sc->name, d->element, d->n, d->layers,
           d->nu);
}

static void write_nodes(const deck *d)
{
    printf("*NODE, NSET=NALL\n");
    for (int k = 0; k <= kmax(d); ++k) {
        for (int j = 0; j <= jlast(d); ++j) {
            for (int i = 0; i <= ilast(d); ++i) {
                if (is_node(i, j, k)) {
                    printf("%ld,%.15g,%.15g,%.15g\n", node_id(d, i, j, k), coord_x(d, i),
                           coord_y(d, j), coord_z(d, k));
                }
            }
        }
    }
}

/* Corner and midside offsets (half steps) in CalculiX's C3D20 order:
 * corners of the bottom then the top face counter-clockwise seen from +z,
 * midsides of the bottom edges, of the top edges, then the vertical edges. */
static const int hex20[20][3] = {
    {0, 0, 0}, {2, 0, 0}, {2, 2, 0}, {0, 2, 0}, {0, 0, 2}, {2, 0, 2}, {2, 2, 2},
    {0, 2, 2}, {1, 0, 0}, {2, 1, 0}, {1, 2, 0}, {0, 1, 0}, {1, 0, 2}, {2, 1, 2},
    {1, 2, 2}, {0, 1, 2}, {0, 0, 1}, {2, 0, 1}, {2, 2, 1}, {0, 2, 1}};

static long element_id(const deck *d, int ex, int ey, int ez)
{
    return 1 + ex + (long)d->n * (ey + (long)d->ny * ez);
}

static void write_elements(const deck *d)
{
    printf("*ELEMENT, TYPE=%s, ELSET=EALL\n", d->element);
    for (int ez = 0; ez < d->layers; ++ez) {
        for (int ey = 0; ey < jlast(d) / 2; ++ey) {
            for (int ex = 0; ex < ilast(d) / 2; ++ex) {
                printf("%ld", element_id(d, ex, ey, ez));
                for (int c = 0; c < 20; ++c) {
                    /* CalculiX reads 16 entries a line, then continues */
                    printf("%s%ld", c == 15 ? ",\n" : ",",
                           node_id(d, 2 * ex + hex20[c][0], 2 * ey + hex20[c][1],
                                   2 * ez + hex20[c][2]));
                }
                printf("\n");
            }
        }
    }
}

/* Prints ids as set data lines, 10 to a line. */
static void list_item(long id, int *count)
{
    printf("%s%ld", *count == 0 ? "" : (*count % 10 == 0 ? "\n" : ","), id);
    ++*count;
}

/* A node set of the meshed part: the nodes where keep(d, i, j, arg) holds,
 * on every layer (top only when top is set). */
static void write_node_set(const deck *d, const char *name, int (*keep)(const deck *, int, int, int),
                           int arg)
{
    int count = 0;
    printf("*NSET, NSET=%s\n", name);
    for (int k = 0; k <= kmax(d); ++k) {
        for (int j = 0; j <= jlast(d); ++j) {
            for (int i = 0; i <= ilast(d); ++i) {
                if (is_node(i, j, k) && keep(d, i, j, arg)) {
                    list_item(node_id(d, i, j, k), &count);
                }
            }
        }
    }
    printf("\n");
}

static int keep_clamped(const deck *d, int i, int j, int unused)
{
    (void)unused;
    return clamped(d, i, j);
}

/* Patch elements (top layer) of the meshed part. */
static void write_patch_set(const deck *d)
{
    int count = 0, xhi = d->qx0[d->sc->px + 2], yhi = d->qy0[d->sc->py + 2];
    xhi = xhi < ilast(d) / 2 ? xhi : ilast(d) / 2;
    yhi = yhi < jlast(d) / 2 ? yhi : jlast(d) / 2;
    printf("*ELSET, ELSET=PATCH\n");
    for (int ey = d->qy0[d->sc->py]; ey < yhi; ++ey) {
        for (int ex = d->qx0[d->sc->px]; ex < xhi; ++ex) {
            list_item(element_id(d, ex, ey, d->layers - 1), &count);
        }
    }
    printf("\n");
}

static void write_output_set(const deck *d)
{
    int count = 0;
    printf("*NSET, NSET=OUT\n");
    for (int b = 0; b < out_ny(d) && out_j(d, b) <= jlast(d); ++b) {
        for (int a = 0; a < out_nx(d) && out_i(d, a) <= ilast(d); ++a) {
            list_item(node_id(d, out_i(d, a), out_j(d, b), kmax(d)), &count);
        }
    }
    printf("\n");
}

/* *ELASTIC (linear; St. Venant-Kirchhoff under NLGEOM) or the neo-Hookean
 * energy with the same small-strain moduli: mu = E / (2 (1 + nu)),
 * K = E / (3 (1 - 2 nu)), C10 = mu / 2, D1 = 2 / K. */
static void write_material(const deck *d)
{
    printf("*MATERIAL, NAME=TISSUE\n");
    if (d->material == MAT_ELASTIC) {
        printf("*ELASTIC\n%.15g,%.15g\n", YOUNG, d->nu);
        return;
    }
    double mu = YOUNG / (2 * (1 + d->nu)), bulk = YOUNG / (3 * (1 - 2 * d->nu));
    printf("** neo-Hooke: mu = %.15g MPa, K = %.15g MPa\n", mu, bulk);
    printf("*HYPERELASTIC, NEO HOOKE\n%.15g,%.15g\n", mu / 2, 2 / bulk);
}

/* Sets, material, section, printed load levels and boundary conditions. */
static void write_model(const deck *d)
{
    write_node_set(d, "CLAMP", keep_clamped, 0);
    write_output_set(d);
    write_patch_set(d);
    if (d->symmetry & SYM_X) {
        write_node_set(d, "SYMX", on_mirror, SYM_X);
    }
    if (d->symmetry & SYM_Y) {
        write_node_set(d, "SYMY", on_mirror, SYM_Y);
    }
    write_material(d);
    printf("*SOLID SECTION, ELSET=EALL, MATERIAL=TISSUE\n");
    if (d->nlgeom) {
        printf("*TIME POINTS, NAME=RAMP\n");
        for (int k = 1; k <= d->increments; ++k) {
            printf("%.15g\n", (double)k / d->increments);
        }
    }
    printf("*BOUNDARY\nCLAMP,1,3\n");
    if (d->symmetry & SYM_X) {
        printf("SYMX,1,1\n");
    }
    if (d->symmetry & SYM_Y) {
        printf("SYMY,2,2\n");
    }
}

static double patch_area(const deck *d)
{
    return 4 * (d->sc->lx / d->sc->qx) * (d->sc->ly / d->sc->qy);
}

/* Consistent nodal weights (area each node carries) of a uniform traction
 * on the patch faces of the meshed part, on the top layer's lattice:
 * w[i + (2 N + 1) j].  A point load puts the patch's whole area on its
 * centre. */
static double *patch_weights(const deck *d)
{
    int s = imax(d) + 1;
    double *w = calloc((size_t)s * (size_t)(jmax(d) + 1), sizeof *w);
    if (w == NULL) {
        fprintf(stderr, "box_deck: out of memory\n");
        exit(1);
    }
    if (d->load == LOAD_POINT) {
        w[icentre(d) + s * jcentre(d)] = patch_area(d);
        return w;
    }
    for (int ey = d->qy0[d->sc->py]; ey < d->qy0[d->sc->py + 2]; ++ey) {
        for (int ex = d->qx0[d->sc->px]; ex < d->qx0[d->sc->px + 2]; ++ex) {
            if (2 * ex >= ilast(d) || 2 * ey >= jlast(d)) {
                continue; /* beyond a cut */
            }
            double area = (d->cx[2 * ex + 2] - d->cx[2 * ex]) * (d->cy[2 * ey + 2] - d->cy[2 * ey]);
            for (int c = 4; c < 16; ++c) {
                if (hex20[c][2] != 2) {
                    continue; /* only the top face's 8 nodes */
                }
                int corner = hex20[c][0] != 1 && hex20[c][1] != 1;
                w[2 * ex + hex20[c][0] + s * (2 * ey + hex20[c][1])] +=
                    corner ? -area / 12 : area / 3;
            }
        }
    }
    return w;
}

static void write_step(const deck *d, int step, const double *w)
{
    int c = d->cases[step];
    printf("** load case %s\n", case_name[c]);
    if (d->nlgeom) {
        /* automatic increments of at most one load level; INC caps their
         * number (default 100) */
        double dt = 1.0 / d->increments;
        double inc = 100.0 * d->increments * fmax(1.0, MIN_FRACTION / d->min_fraction);
        printf("*STEP, NLGEOM, INC=%d\n*STATIC\n%.15g,1.,%.15g,%.15g\n", (int)fmin(inc, 1e6), dt,
               dt * d->min_fraction, dt);
        printf("*CONTROLS, PARAMETERS=FIELD\n%.3e,%.3e,,,%.3e\n", d->tolerance, d->tolerance,
               d->tolerance);
    } else {
        printf("*STEP\n*STATIC\n");
    }
    if (d->load == LOAD_PRESSURE) {
        printf("*DLOAD, OP=NEW\nPATCH,P2,%.15g\n", 1.0 / patch_area(d));
    } else {
        int s = imax(d) + 1;
        printf("*CLOAD, OP=NEW\n");
        for (int j = 0; j <= jlast(d); ++j) {
            for (int i = 0; i <= ilast(d); ++i) {
                for (int dof = 0; dof < 3; ++dof) {
                    double f = case_force[c][dof] * w[i + s * j] / patch_area(d);
                    /* CalculiX reads a number from the first 20 characters of
                     * its field: %.12e fits with sign, 13 digits. */
                    if (f != 0) {
                        printf("%ld,%d,%.12e\n", node_id(d, i, j, kmax(d)), dof + 1, f);
                    }
                }
            }
        }
    }
    /* RF is each node's external force (reaction, or the applied load at a
     * loaded node): the clamp's total, and the normal reaction of a cut
     * (no load acts normal to it), balance the meshed part's force. */
    const char *points = d->nlgeom ? ", TIME POINTS=RAMP" : "";
    printf("*NODE PRINT, NSET=OUT%s\nU\n*NODE PRINT, NSET=CLAMP, TOTALS=ONLY%s\nRF\n", points, points);
    for (int plane = SYM_X; plane <= SYM_Y; plane <<= 1) {
        if (d->symmetry & plane) {
            printf("*NODE PRINT, NSET=SYM%c, TOTALS=ONLY%s\nRF\n", plane == SYM_X ? 'X' : 'Y', points);
        }
    }
    if (d->field) {
        printf("*NODE FILE%s\nU\n", points);
    }
    printf("*END STEP\n");
}

static void usage(FILE *out)
{
    fprintf(out,
            "usage: box_deck [--scene block48|beam40] (--divisions N | --grade F:M) --layers L\n"
            "                [--layer-ratio R] [--nu V]\n"
            "                [--element C3D20R|C3D20] [--cases fx,fy,fz | --force FX,FY,FZ]\n"
            "                [--pressure | --point] [--symmetry x|y|xy]\n"
            "                [--material elastic|neohooke] [--nlgeom [--increments K]\n"
            "                [--tolerance T] [--min-fraction M]] [--field]   > deck.inp\n"
            "  --scene S      block48 (default) or beam40\n"
            "  --divisions N  elements along x, a multiple of 20 (block48) or 16 (beam40)\n"
            "  --layers L     elements through the thickness\n"
            "  --grade F:M    instead of --divisions: F elements per quantum (half the\n"
            "                 patch side) on the patch, 0.7 times fewer per quantum\n"
            "                 away from it, at least M\n"
            "  --layer-ratio R  each layer R times thicker than the one above (1 to 4;\n"
            "                 default 1, uniform)\n"
            "  --nu V         Poisson's ratio, 0 <= V < 0.5 (default 0.49)\n"
            "  --element T    C3D20R (default, 2x2x2 points) or C3D20 (3x3x3 points)\n"
            "  --cases LIST   load cases in step order (default fx,fy,fz)\n"
            "  --force F      one step (case \"path\") with the force FX,FY,FZ in N\n"
            "  --pressure     apply fz as *DLOAD pressure P2 (cases must be fz only)\n"
            "  --point        the whole force on the patch centre instead of the patch\n"
            "  --symmetry P   mesh only x <= xc (x), y <= yc (y) or both (xy); the force\n"
            "                 must have no component normal to a cut\n"
            "  --material M   elastic (default; St. Venant-Kirchhoff with --nlgeom) or\n"
            "                 neohooke (C10 = mu/2, D1 = 2/K; needs --nlgeom)\n"
            "  --nlgeom       large deformation, the load ramped from zero\n"
            "  --increments K printed load levels per step (default 10; with --nlgeom)\n"
            "  --tolerance T  Newton residual and correction ratios (default 1e-6)\n"
            "  --min-fraction M  smallest increment CalculiX may cut to, as a fraction\n"
            "                 of a load level (default 1e-2; with --nlgeom)\n"
            "  --field        every node's displacement to the .frd (at the printed\n"
            "                 levels with --nlgeom)\n");
}

static int parse_cases(deck *d, const char *list)
{
    char buf[64];
    if (strlen(list) >= sizeof buf) {
        return -1;
    }
    strcpy(buf, list);
    d->ncases = 0;
    for (char *tok = strtok(buf, ","); tok != NULL; tok = strtok(NULL, ",")) {
        int c = 0;
        while (c < PATH_CASE && strcmp(tok, case_name[c]) != 0) {
            ++c;
        }
        if (c == PATH_CASE || d->ncases == PATH_CASE) {
            return -1;
        }
        d->cases[d->ncases++] = c;
    }
    return d->ncases > 0 ? 0 : -1;
}

/* --force FX,FY,FZ: three finite numbers, not all zero. */
static int parse_force(deck *d, const char *list)
{
    double *f = case_force[PATH_CASE];
    const char *p = list;
    char *end;
    for (int k = 0; k < 3; ++k) {
        f[k] = strtod(p, &end);
        if (end == p || !(f[k] > -1e3 && f[k] < 1e3) || *end != (k < 2 ? ',' : '\0')) {
            return -1;
        }
        p = end + 1;
    }
    if (f[0] == 0 && f[1] == 0 && f[2] == 0) {
        return -1;
    }
    d->cases[0] = PATH_CASE;
    d->ncases = 1;
    return 0;
}

static int parse_material(deck *d, const char *name)
{
    for (int k = 0; k <= MAT_NEOHOOKE; ++k) {
        if (strcmp(name, material_name[k]) == 0) {
            d->material = k;
            return 0;
        }
    }
    return -1;
}

static int parse_scene(deck *d, const char *name)
{
    for (size_t k = 0; k < sizeof scenes / sizeof scenes[0]; ++k) {
        if (strcmp(name, scenes[k].name) == 0) {
            d->sc = &scenes[k];
            return 0;
        }
    }
    return -1;
}

static int parse_symmetry(deck *d, const char *s)
{
    d->symmetry = strcmp(s, "x") == 0 ? SYM_X : strcmp(s, "y") == 0 ? SYM_Y
                  : strcmp(s, "xy") == 0 ? SYM_X | SYM_Y : 0;
    return d->symmetry ? 0 : -1;
}

/* The options that only make sense together: NLGEOM settings need
 * --nlgeom, the neo-Hookean law needs it too (a hyperelastic law is a
 * large-deformation law), a follower pressure is not the dead patch load,
 * and a load path excludes the unit cases. */
static int check_nonlinear(deck *d, int cases_and_force)
{
    if (cases_and_force ||
        ((d->increments != 0 || d->tolerance != 0 || d->min_given) && !d->nlgeom) ||
        (d->material == MAT_NEOHOOKE && !d->nlgeom) || (d->nlgeom && d->load == LOAD_PRESSURE)) {
        return -1;
    }
    if (d->nlgeom) {
        d->increments = d->increments == 0 ? 10 : d->increments;
        d->tolerance = d->tolerance == 0 ? 1e-6 : d->tolerance;
        d->min_fraction = d->min_given ? d->min_fraction : MIN_FRACTION;
        if (d->increments < 1 || d->increments > 1000 || !(d->tolerance > 0 && d->tolerance < 0.1) ||
            !(d->min_fraction >= 1e-9 && d->min_fraction <= 1)) {
            return -1;
        }
    }
    return 0;
}

/* A cut needs a scene mirrored about it, no point load on the cut, and
 * cases without a force component normal to it. */
static int check_symmetry(const deck *d)
{
    if ((d->symmetry & ~d->sc->mirrors) != 0 || (d->symmetry && d->load == LOAD_POINT)) {
        return -1;
    }
    for (int s = 0; s < d->ncases; ++s) {
        const double *f = case_force[d->cases[s]];
        if (((d->symmetry & SYM_X) && f[0] != 0) || ((d->symmetry & SYM_Y) && f[1] != 0)) {
            return -1;
        }
    }
    return 0;
}

/* Elements in quantum q of a side whose patch covers quanta p and p + 1:
 * m uniform, or graded: FINE on the patch, GRADE_FACTOR times fewer per
 * quantum of distance from it (rounded up), at least MIN. */
static int quantum_elements(const deck *d, int q, int p)
{
    if (d->grade_fine == 0) {
        return d->m;
    }
    int dq = q < p ? p - q : q > p + 1 ? q - p - 1 : 0;
    int m = (int)ceil(d->grade_fine * pow(GRADE_FACTOR, dq) - 1e-9);
    return m > d->grade_min ? m : d->grade_min;
}

/* One side's quanta -> elements (q0[q], the first element of quantum q)
 * and lattice coordinates; returns the element count, -1 when too many. */
static int side_lattice(const deck *d, double len, int quanta, int p, int *q0, double *c)
{
    double qw = len / quanta;
    q0[0] = 0;
    for (int q = 0; q < quanta; ++q) {
        int m = quantum_elements(d, q, p);
        q0[q + 1] = q0[q] + m;
        if (q0[q + 1] > MAX_DIV) {
            return -1;
        }
        for (int e = 0; e <= m; ++e) {
            c[2 * (q0[q] + e)] = q * qw + e * (qw / m);
        }
    }
    int n = q0[quanta];
    for (int i = 0; i <= 2 * n; ++i) {
        if (d->grade_fine == 0) {
            c[i] = i * (len / (2 * n)); /* as before grading existed, to the last bit */
        } else if (i & 1) {
            c[i] = (c[i - 1] + c[i + 1]) / 2; /* midside nodes halfway */
        }
    }
    return n;
}

/* Layers from the top (z = lz) down, each layer_ratio times thicker than
 * the one above (1: uniform). */
static void layer_lattice(deck *d)
{
    int k = kmax(d);
    double r = d->layer_ratio, lz = d->sc->lz;
    if (r == 1) {
        for (int i = 0; i <= k; ++i) {
            d->cz[i] = i * (lz / k);
        }
        return;
    }
    double t = lz * (r - 1) / (pow(r, d->layers) - 1); /* top layer */
    d->cz[k] = lz;
    for (int e = d->layers - 1; e >= 0; --e, t *= r) {
        d->cz[2 * e] = e == 0 ? 0 : d->cz[2 * e + 2] - t;
        d->cz[2 * e + 1] = (d->cz[2 * e] + d->cz[2 * e + 2]) / 2;
    }
}

/* Divisions and layers: N a multiple of the box length in quanta (or a
 * grading instead), sizes within what CalculiX can solve here. */
static int check_mesh(deck *d)
{
    if (d->sc->qx > MAX_QUANTA || d->sc->qy > MAX_QUANTA || d->layers <= 0 ||
        d->layers > MAX_LAYERS || !(d->layer_ratio >= 1 && d->layer_ratio <= 4)) {
        return -1;
    }
    if (d->grade_fine != 0) {
        if (d->n != 0 || d->grade_min < 1 || d->grade_min > d->grade_fine || d->grade_fine > 40) {
            return -1;
        }
    } else if (d->n <= 0 || d->n % d->sc->qx != 0 || d->n > MAX_DIV) {
        return -1;
    } else {
        d->m = d->n / d->sc->qx;
    }
    d->n = side_lattice(d, d->sc->lx, d->sc->qx, d->sc->px, d->qx0, d->cx);
    d->ny = side_lattice(d, d->sc->ly, d->sc->qy, d->sc->py, d->qy0, d->cy);
    if (d->n < 0 || d->ny < 0) {
        return -1;
    }
    layer_lattice(d);
    return 0;
}

/* --grade FINE:MIN */
static int parse_grade(deck *d, const char *s)
{
    char *end;
    d->grade_fine = (int)strtol(s, &end, 10);
    if (*end != ':') {
        return -1;
    }
    d->grade_min = (int)strtol(end + 1, &end, 10);
    return *end || d->grade_fine < 1 ? -1 : 0;
}

static int parse_args(deck *d, int argc, char **argv)
{
    static const struct option opts[] = {
        {"divisions", required_argument, NULL, 'n'}, {"layers", required_argument, NULL, 'l'},
        {"nu", required_argument, NULL, 'v'},        {"element", required_argument, NULL, 'e'},
        {"cases", required_argument, NULL, 'c'},     {"pressure", no_argument, NULL, 'p'},
        {"point", no_argument, NULL, 'P'},           {"help", no_argument, NULL, 'h'},
        {"force", required_argument, NULL, 'f'},     {"material", required_argument, NULL, 'm'},
        {"nlgeom", no_argument, NULL, 'g'},          {"increments", required_argument, NULL, 'i'},
        {"tolerance", required_argument, NULL, 't'}, {"scene", required_argument, NULL, 's'},
        {"symmetry", required_argument, NULL, 'y'},  {"grade", required_argument, NULL, 'G'},
        {"layer-ratio", required_argument, NULL, 'r'}, {"min-fraction", required_argument, NULL, 'M'},
        {"field", no_argument, NULL, 'F'},           {NULL, 0, NULL, 0}};
    *d = (deck){.sc = &scenes[0], .nu = 0.49, .element = "C3D20R", .layer_ratio = 1};
    parse_cases(d, "fx,fy,fz");
    int cases_given = 0, force_given = 0;
    char *end;
    for (int o; (o = getopt_long(argc, argv, "", opts, NULL)) != -1;) {
        switch (o) {
        case 'n': d->n = (int)strtol(optarg, &end, 10); if (*end) return -1; break;
        case 'l': d->layers = (int)strtol(optarg, &end, 10); if (*end) return -1; break;
        case 'v': d->nu = strtod(optarg, &end); if (*end) return -1; break;
        case 'e': d->element = optarg; break;
        case 'c': if (parse_cases(d, optarg) != 0) return -1; cases_given = 1; break;
        case 'f': if (parse_force(d, optarg) != 0) return -1; force_given = 1; break;
        case 'p': if (d->load != LOAD_PATCH) return -1; d->load = LOAD_PRESSURE; break;
        case 'P': if (d->load != LOAD_PATCH) return -1; d->load = LOAD_POINT; break;
        case 'g': d->nlgeom = 1; break;
        case 'i': d->increments = (int)strtol(optarg, &end, 10); if (*end) return -1; break;
        case 't': d->tolerance = strtod(optarg, &end); if (*end) return -1; break;
        case 'M': d->min_fraction = strtod(optarg, &end); if (*end) return -1; d->min_given = 1; break;
        case 'F': d->field = 1; break;
        case 'y': if (parse_symmetry(d, optarg) != 0) return -1; break;
        case 'G': if (parse_grade(d, optarg) != 0) return -1; break;
        case 'r': d->layer_ratio = strtod(optarg, &end); if (*end) return -1; break;
        case 'm': if (parse_material(d, optarg) != 0) return -1; break;
        case 's': if (parse_scene(d, optarg) != 0) return -1; break;
        case 'h': usage(stdout); exit(0);
        default: return -1;
        }
    }
    if (optind != argc || check_mesh(d) != 0 || !(d->nu >= 0 && d->nu < 0.5) ||
        (strcmp(d->element, "C3D20R") != 0 && strcmp(d->element, "C3D20") != 0) ||
        (d->load == LOAD_PRESSURE && (d->ncases != 1 || d->cases[0] != 2))) {
        return -1;
    }
    return check_nonlinear(d, cases_given && force_given) != 0 || check_symmetry(d) != 0 ? -1 : 0;
}

int main(int argc, char **argv)
{
    deck d;
    if (parse_args(&d, argc, argv) != 0) {
        fprintf(stderr, "box_deck: bad arguments\n");
        usage(stderr);
        return 2;
    }
    double *w = patch_weights(&d);
    write_header(&d);
    write_nodes(&d);
    write_elements(&d);
    write_model(&d);
    for (int s = 0; s < d.ncases; ++s) {
        write_step(&d, s, w);
    }
    free(w);
    if (fflush(stdout) != 0 || ferror(stdout)) {
        fprintf(stderr, "box_deck: write error\n");
        return 1;
    }
    return 0;
}

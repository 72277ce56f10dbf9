/*
 * block48_deck.c — writes a CalculiX input deck (.inp) for the block48
 * benchmark (GUIDE §5) on stdout: box [0,48]x[0,48]x[0,6] mm, E = 0.32 MPa,
 * lateral faces clamped, a 1 N force spread as a uniform traction over the
 * top-face square [21.6,26.4]^2, one *STEP per load case.
 *
 * Mesh: a structured grid of 20-node hexahedra, N x N in plane and L layers
 * through the thickness.  N must be a multiple of 20 so that element edges
 * fall on x, y = 21.6 and 26.4 (the patch) and on every multiple of 4.8 (the
 * 121 output points): then the patch and the output points are mesh nodes.
 *
 * Node numbers come from a lattice at half the element size, so a node's
 * number is a formula of its position: id = 1 + i + K (j + K k), K = 2N + 1,
 * with i, j, k the half-step indices along x, y, z.  Lattice points at face
 * and cell centres are not nodes of a 20-node hexahedron and are skipped.
 *
 * Load: CalculiX's *DLOAD has no tangential surface traction (only the
 * normal pressure P1..P6, body forces and gravity), so every case is applied
 * as the consistent nodal loads of a uniform traction t on each loaded
 * 8-node face: -A t / 12 at the corners, +A t / 3 at the midsides
 * (A = face area; the shape functions' integrals over a rectangle).  For fz
 * the pressure form (*DLOAD P2 on the top faces) can be asked for instead,
 * as an independent check of those nodal loads.  --point puts the whole force
 * on node 61 instead, as the seed (Zhou 2017) did: a point load has no
 * converged answer (the displacement under it grows without bound as the
 * mesh refines), which the study shows beside the patch load.
 *
 * Comment lines the extraction reads (CalculiX ignores lines starting **):
 *   ** SIZE elements nodes free_dofs
 *   ** STEP n case fx fy fz          (the force of step n, N)
 *   ** OUT node ccx_node x y z       (block48 output node N = i + 11 j + 1)
 *
 * Exit 0 ok, 2 bad usage (nothing written).
 */
#include <getopt.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#define SIDE 48.0        /* mm */
#define THICK 6.0        /* mm */
#define YOUNG 0.32       /* MPa = N/mm^2 */
#define PATCH 4.8        /* mm, side of the loaded square */
#define GRID 11          /* output grid: 11 x 11 points, 4.8 mm apart */
#define MAX_CASES 3

typedef struct {
    int n;            /* elements per side in plane */
    int layers;       /* elements through the thickness */
    double nu;
    const char *element;
    enum { LOAD_PATCH, LOAD_PRESSURE, LOAD_POINT } load;
    int cases[MAX_CASES];
    int ncases;
} deck;

static const char *const case_name[MAX_CASES] = {"fx", "fy", "fz"};
/* Unit force of each case: +x, +y and -z (pressing into the block). */
static const double case_force[MAX_CASES][3] = {{1, 0, 0}, {0, 1, 0}, {0, 0, -1}};
static const char *const load_form[] = {"consistent nodal loads", "pressure (fz)",
                                        "point load at node 61"};

static int lattice(const deck *d) { return 2 * d->n + 1; }

static long node_id(const deck *d, int i, int j, int k)
{
    long s = lattice(d);
    return 1 + i + s * (j + s * (long)k);
}

/* A lattice point is a node when at most one of its indices is odd
 * (corner: none odd; midside of an edge: exactly one). */
static int is_node(int i, int j, int k) { return (i & 1) + (j & 1) + (k & 1) <= 1; }

static double coord_xy(const deck *d, int i) { return i * (SIDE / (2.0 * d->n)); }
static double coord_z(const deck *d, int k) { return k * (THICK / (2.0 * d->layers)); }

static int clamped(const deck *d, int i, int j)
{
    return i == 0 || j == 0 || i == 2 * d->n || j == 2 * d->n;
}

static void write_header(const deck *d)
{
    long nodes = 0, fixed = 0;
    for (int k = 0; k <= 2 * d->layers; ++k) {
        for (int j = 0; j <= 2 * d->n; ++j) {
            for (int i = 0; i <= 2 * d->n; ++i) {
                if (is_node(i, j, k)) {
                    ++nodes;
                    fixed += clamped(d, i, j);
                }
            }
        }
    }
    long elements = (long)d->n * d->n * d->layers;
    printf("** block48 (GUIDE 5) written by tests/calculix/block48_deck\n");
    printf("** %d x %d x %d %s elements, nu = %.15g, E = %.15g MPa, load as %s\n", d->n, d->n,
           d->layers, d->element, d->nu, YOUNG,
           load_form[d->load]);
    printf("** SIZE %ld %ld %ld\n", elements, nodes, 3 * (nodes - fixed));
    for (int s = 0; s < d->ncases; ++s) {
        const double *f = case_force[d->cases[s]];
        printf("** STEP %d %s %.15g %.15g %.15g\n", s + 1, case_name[d->cases[s]], f[0], f[1], f[2]);
    }
    int step = 2 * d->n / (GRID - 1);
    for (int j = 0; j < GRID; ++j) {
        for (int i = 0; i < GRID; ++i) {
            printf("** OUT %d %ld %.15g %.15g %.15g\n", i + GRID * j + 1,
                   node_id(d, i * step, j * step, 2 * d->layers), coord_xy(d, i * step),
                   coord_xy(d, j * step), THICK);
        }
    }
    printf("*HEADING\nblock48 %s n=%d layers=%d nu=%.15g\n", d->element, d->n, d->layers, d->nu);
}

static void write_nodes(const deck *d)
{
    printf("*NODE, NSET=NALL\n");
    for (int k = 0; k <= 2 * d->layers; ++k) {
        for (int j = 0; j <= 2 * d->n; ++j) {
            for (int i = 0; i <= 2 * d->n; ++i) {
                if (is_node(i, j, k)) {
                    printf("%ld,%.15g,%.15g,%.15g\n", node_id(d, i, j, k), coord_xy(d, i),
                           coord_xy(d, j), coord_z(d, k));
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
    return 1 + ex + (long)d->n * (ey + (long)d->n * ez);
}

static void write_elements(const deck *d)
{
    printf("*ELEMENT, TYPE=%s, ELSET=EALL\n", d->element);
    for (int ez = 0; ez < d->layers; ++ez) {
        for (int ey = 0; ey < d->n; ++ey) {
            for (int ex = 0; ex < d->n; ++ex) {
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

static void write_sets(const deck *d)
{
    int count = 0;
    printf("*NSET, NSET=CLAMP\n");
    for (int k = 0; k <= 2 * d->layers; ++k) {
        for (int j = 0; j <= 2 * d->n; ++j) {
            for (int i = 0; i <= 2 * d->n; ++i) {
                if (is_node(i, j, k) && clamped(d, i, j)) {
                    list_item(node_id(d, i, j, k), &count);
                }
            }
        }
    }
    printf("\n*NSET, NSET=OUT\n");
    count = 0;
    int step = 2 * d->n / (GRID - 1);
    for (int j = 0; j < GRID; ++j) {
        for (int i = 0; i < GRID; ++i) {
            list_item(node_id(d, i * step, j * step, 2 * d->layers), &count);
        }
    }
    printf("\n*ELSET, ELSET=PATCH\n");
    count = 0;
    int lo = 9 * d->n / 20, hi = 11 * d->n / 20; /* 21.6 / 48 = 9/20 */
    for (int ey = lo; ey < hi; ++ey) {
        for (int ex = lo; ex < hi; ++ex) {
            list_item(element_id(d, ex, ey, d->layers - 1), &count);
        }
    }
    printf("\n*MATERIAL, NAME=TISSUE\n*ELASTIC\n%.15g,%.15g\n", YOUNG, d->nu);
    printf("*SOLID SECTION, ELSET=EALL, MATERIAL=TISSUE\n");
    printf("*BOUNDARY\nCLAMP,1,3\n");
}

/* Consistent nodal weights (area each node carries) of a uniform traction
 * on the patch, on the top layer's lattice: w[i + K j].  A point load puts
 * the patch's whole area on node 61. */
static double *patch_weights(const deck *d)
{
    int s = lattice(d);
    double *w = calloc((size_t)s * (size_t)s, sizeof *w);
    if (w == NULL) {
        fprintf(stderr, "block48_deck: out of memory\n");
        exit(1);
    }
    if (d->load == LOAD_POINT) {
        w[d->n + s * d->n] = PATCH * PATCH;
        return w;
    }
    double h = SIDE / d->n, area = h * h;
    int lo = 9 * d->n / 20, hi = 11 * d->n / 20;
    for (int ey = lo; ey < hi; ++ey) {
        for (int ex = lo; ex < hi; ++ex) {
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
    printf("** load case %s\n*STEP\n*STATIC\n", case_name[c]);
    if (d->load == LOAD_PRESSURE) {
        printf("*DLOAD, OP=NEW\nPATCH,P2,%.15g\n", 1.0 / (PATCH * PATCH));
    } else {
        int s = lattice(d);
        printf("*CLOAD, OP=NEW\n");
        for (int j = 0; j < s; ++j) {
            for (int i = 0; i < s; ++i) {
                for (int dof = 0; dof < 3; ++dof) {
                    double f = case_force[c][dof] * w[i + s * j] / (PATCH * PATCH);
                    /* CalculiX reads a number from the first 20 characters of
                     * its field: %.12e fits with sign, 13 digits. */
                    if (f != 0) {
                        printf("%ld,%d,%.12e\n", node_id(d, i, j, 2 * d->layers), dof + 1, f);
                    }
                }
            }
        }
    }
    printf("*NODE PRINT, NSET=OUT\nU\n*NODE PRINT, NSET=CLAMP, TOTALS=ONLY\nRF\n*END STEP\n");
}

static void usage(FILE *out)
{
    fprintf(out,
            "usage: block48_deck --divisions N --layers L [--nu V] [--element C3D20R|C3D20]\n"
            "                    [--cases fx,fy,fz] [--pressure | --point]   > deck.inp\n"
            "  --divisions N  elements per side in plane, a multiple of 20 (h = 48/N mm)\n"
            "  --layers L     elements through the 6 mm thickness\n"
            "  --nu V         Poisson's ratio, 0 <= V < 0.5 (default 0.49)\n"
            "  --element T    C3D20R (default, 2x2x2 points) or C3D20 (3x3x3 points)\n"
            "  --cases LIST   load cases in step order (default fx,fy,fz)\n"
            "  --pressure     apply fz as *DLOAD pressure P2 (cases must be fz only)\n"
            "  --point        the whole force on node 61 instead of the patch\n");
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
        while (c < MAX_CASES && strcmp(tok, case_name[c]) != 0) {
            ++c;
        }
        if (c == MAX_CASES || d->ncases == MAX_CASES) {
            return -1;
        }
        d->cases[d->ncases++] = c;
    }
    return d->ncases > 0 ? 0 : -1;
}

static int parse_args(deck *d, int argc, char **argv)
{
    static const struct option opts[] = {
        {"divisions", required_argument, NULL, 'n'}, {"layers", required_argument, NULL, 'l'},
        {"nu", required_argument, NULL, 'v'},        {"element", required_argument, NULL, 'e'},
        {"cases", required_argument, NULL, 'c'},     {"pressure", no_argument, NULL, 'p'},
        {"point", no_argument, NULL, 'P'},       {"help", no_argument, NULL, 'h'},
        {NULL, 0, NULL, 0}};
    *d = (deck){.n = 0, .layers = 0, .nu = 0.49, .element = "C3D20R"};
    parse_cases(d, "fx,fy,fz");
    char *end;
    for (int o; (o = getopt_long(argc, argv, "", opts, NULL)) != -1;) {
        switch (o) {
        case 'n': d->n = (int)strtol(optarg, &end, 10); if (*end) return -1; break;
        case 'l': d->layers = (int)strtol(optarg, &end, 10); if (*end) return -1; break;
        case 'v': d->nu = strtod(optarg, &end); if (*end) return -1; break;
        case 'e': d->element = optarg; break;
        case 'c': if (parse_cases(d, optarg) != 0) return -1; break;
        case 'p': if (d->load != LOAD_PATCH) return -1; d->load = LOAD_PRESSURE; break;
        case 'P': if (d->load != LOAD_PATCH) return -1; d->load = LOAD_POINT; break;
        case 'h': usage(stdout); exit(0);
        default: return -1;
        }
    }
    if (optind != argc || d->n <= 0 || d->n % 20 != 0 || d->n > 400 || d->layers <= 0 ||
        d->layers > 100 || !(d->nu >= 0 && d->nu < 0.5) ||
        (strcmp(d->element, "C3D20R") != 0 && strcmp(d->element, "C3D20") != 0) ||
        (d->load == LOAD_PRESSURE && (d->ncases != 1 || d->cases[0] != 2))) {
        return -1;
    }
    return 0;
}

int main(int argc, char **argv)
{
    deck d;
    if (parse_args(&d, argc, argv) != 0) {
        fprintf(stderr, "block48_deck: bad arguments\n");
        usage(stderr);
        return 2;
    }
    double *w = patch_weights(&d);
    write_header(&d);
    write_nodes(&d);
    write_elements(&d);
    write_sets(&d);
    for (int s = 0; s < d.ncases; ++s) {
        write_step(&d, s, w);
    }
    free(w);
    if (fflush(stdout) != 0 || ferror(stdout)) {
        fprintf(stderr, "block48_deck: write error\n");
        return 1;
    }
    return 0;
}

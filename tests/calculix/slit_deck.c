/*
 * slit_deck.c — writes a CalculiX input deck (.inp) of the slit block
 * (tests/cut/slit.yaml, docs/cutting.md) on stdout: box [0,20] x [0,10] x
 * [0,10] mm, E = 1 MPa, nu = 0.3, the x- face clamped, 1 N along +x as a
 * uniform traction on the x+ face, and a crack in the plane x = 10 through
 * the whole width from the top z = 10 down to z = 5.
 *
 * Mesh: 20-node hexahedra on a structured grid, 2N x N x N elements
 * (h = 10/N mm; N even, so x = 10 and z = 5 are element faces).  Nodes come
 * from a lattice at half the element size (indices i, j, k; id = 1 + i +
 * KX (j + KY k)); lattice points at face and cell centres are skipped.
 *
 * The crack by duplicated nodes: every node of the plane x = 10 above the
 * front (z > 5) is doubled (id + OFFSET); the elements on the +x side use
 * the copy, so the two faces are free to separate.  The front z = 5 stays
 * shared.
 *
 * Load: the consistent nodal loads of a uniform traction t on each 8-node
 * face of x+ (-A t / 12 at corners, A t / 3 at midsides).
 *
 * Comment lines the extraction reads (CalculiX ignores lines starting **):
 *   ** SIZE elements nodes
 *   ** LIP z minus_id plus_id     (the two faces at y = 5, mm)
 *
 * Exit 0 ok, 2 bad usage (nothing written).
 */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#define LX 20.0
#define LY 10.0
#define LZ 10.0
#define CRACK_X 10.0
#define FRONT_Z 5.0
#define YOUNG 1.0
#define POISSON 0.3
#define FORCE 1.0 /* N along +x */

typedef struct deck {
    int n;           /* elements per 10 mm */
    const char *element;
    long kx, ky, kz; /* lattice points per axis */
} deck;

static long node_id(const deck *d, int i, int j, int k)
{
    return 1 + i + d->kx * (j + d->ky * (long)k);
}

static long offset(const deck *d) { return d->kx * d->ky * d->kz; }

static int is_node(int i, int j, int k) { return (i & 1) + (j & 1) + (k & 1) <= 1; }

static double coord(const deck *d, int i) { return i * (10.0 / (2.0 * d->n)); }

/* Lattice indices of the crack plane and the front. */
static int crack_i(const deck *d) { return 2 * d->n; }
static int front_k(const deck *d) { return d->n; }

/* A node of the crack plane above the front: it has a copy. */
static int doubled(const deck *d, int i, int k) { return i == crack_i(d) && k > front_k(d); }

static void write_nodes(const deck *d)
{
    long count = 0;
    for (int pass = 0; pass < 2; ++pass) {
        if (pass == 1) {
            printf("*NODE, NSET=NALL\n");
        }
        for (int k = 0; k < d->kz; ++k) {
            for (int j = 0; j < d->ky; ++j) {
                for (int i = 0; i < d->kx; ++i) {
                    if (!is_node(i, j, k)) {
                        continue;
                    }
                    count += pass == 0 ? 1 + doubled(d, i, k) : 0;
                    if (pass == 1) {
                        printf("%ld,%.15g,%.15g,%.15g\n", node_id(d, i, j, k), coord(d, i),
                               coord(d, j), coord(d, k));
                    }
                    if (pass == 1 && doubled(d, i, k)) {
                        printf("%ld,%.15g,%.15g,%.15g\n", node_id(d, i, j, k) + offset(d),
                               coord(d, i), coord(d, j), coord(d, k));
                    }
                }
            }
        }
        if (pass == 0) {
            printf("** slit block (tests/cut/slit.yaml) written by tests/calculix/slit_deck\n");
            printf("** %d x %d x %d %s elements, crack x = 10, z > 5 by duplicated nodes\n",
                   2 * d->n, d->n, d->n, d->element);
            printf("** SIZE %ld %ld\n", 2L * d->n * d->n * d->n, count);
            for (int k = front_k(d); k < d->kz; ++k) {
                printf("** LIP %.15g %ld %ld\n", coord(d, k), node_id(d, crack_i(d), d->n, k),
                       node_id(d, crack_i(d), d->n, k) + (doubled(d, crack_i(d), k) ? offset(d) : 0));
            }
            printf("*HEADING\nslit block %s n=%d\n", d->element, d->n);
        }
    }
}

/* CalculiX's C3D20 order (half-step offsets): corners of the bottom then
 * the top face counter-clockwise from +z, midsides of the bottom edges, the
 * top edges, then the vertical edges. */
static const int hex20[20][3] = {
    {0, 0, 0}, {2, 0, 0}, {2, 2, 0}, {0, 2, 0}, {0, 0, 2}, {2, 0, 2}, {2, 2, 2},
    {0, 2, 2}, {1, 0, 0}, {2, 1, 0}, {1, 2, 0}, {0, 1, 0}, {1, 0, 2}, {2, 1, 2},
    {1, 2, 2}, {0, 1, 2}, {0, 0, 1}, {2, 0, 1}, {2, 2, 1}, {0, 2, 1}};

static void write_elements(const deck *d)
{
    long id = 1;
    printf("*ELEMENT, TYPE=%s, ELSET=EALL\n", d->element);
    for (int ez = 0; ez < d->n; ++ez) {
        for (int ey = 0; ey < d->n; ++ey) {
            for (int ex = 0; ex < 2 * d->n; ++ex) {
                printf("%ld", id++);
                for (int c = 0; c < 20; ++c) {
                    int i = 2 * ex + hex20[c][0], j = 2 * ey + hex20[c][1], k = 2 * ez + hex20[c][2];
                    long n = node_id(d, i, j, k);
                    if (doubled(d, i, k) && 2 * ex >= crack_i(d)) {
                        n += offset(d); /* the +x side's copy */
                    }
                    printf("%s%ld", c == 15 ? ",\n" : ",", n);
                }
                printf("\n");
            }
        }
    }
}

static void list_item(long id, int *count)
{
    printf("%s%ld", *count == 0 ? "" : (*count % 10 == 0 ? "\n" : ","), id);
    ++*count;
}

static void write_sets_and_step(const deck *d)
{
    int count = 0;
    printf("*NSET, NSET=CLAMP\n");
    for (int k = 0; k < d->kz; ++k) {
        for (int j = 0; j < d->ky; ++j) {
            if (is_node(0, j, k)) {
                list_item(node_id(d, 0, j, k), &count);
            }
        }
    }
    printf("\n*NSET, NSET=LIPS\n");
    count = 0;
    for (int k = front_k(d); k < d->kz; ++k) {
        long id = node_id(d, crack_i(d), d->n, k);
        list_item(id, &count);
        if (doubled(d, crack_i(d), k)) {
            list_item(id + offset(d), &count);
        }
    }
    printf("\n*MATERIAL, NAME=TISSUE\n*ELASTIC\n%.15g,%.15g\n", YOUNG, POISSON);
    printf("*SOLID SECTION, ELSET=EALL, MATERIAL=TISSUE\n*BOUNDARY\nCLAMP,1,3\n");
    printf("*STEP\n*STATIC\n*CLOAD\n");
    double h = 10.0 / d->n, t = FORCE / (LY * LZ), w = h * h * t;
    int last = (int)(d->kx - 1);
    double *f = calloc((size_t)(d->ky * d->kz), sizeof *f);
    if (f == NULL) {
        fprintf(stderr, "slit_deck: out of memory\n");
        exit(1);
    }
    for (int ez = 0; ez < d->n; ++ez) { /* faces of x+: j, k half steps */
        for (int ey = 0; ey < d->n; ++ey) {
            for (int a = 0; a <= 2; ++a) {
                for (int b = 0; b <= 2; ++b) {
                    if (a == 1 && b == 1) {
                        continue;
                    }
                    int corner = a != 1 && b != 1;
                    f[(2 * ey + a) + d->ky * (2 * ez + b)] += corner ? -w / 12 : w / 3;
                }
            }
        }
    }
    for (int k = 0; k < d->kz; ++k) {
        for (int j = 0; j < d->ky; ++j) {
            if (f[j + d->ky * k] != 0) {
                printf("%ld,1,%.12e\n", node_id(d, last, j, k), f[j + d->ky * k]);
            }
        }
    }
    free(f);
    printf("*NODE PRINT, NSET=LIPS\nU\n*END STEP\n");
}

int main(int argc, char **argv)
{
    deck d = {.n = 0, .element = "C3D20R"};
    for (int a = 1; a < argc; ++a) {
        char *end;
        if (strcmp(argv[a], "--divisions") == 0 && a + 1 < argc) {
            d.n = (int)strtol(argv[++a], &end, 10);
            if (*end) {
                d.n = 0;
            }
        } else if (strcmp(argv[a], "--element") == 0 && a + 1 < argc) {
            d.element = argv[++a];
        } else {
            d.n = 0;
            break;
        }
    }
    if (d.n < 2 || d.n % 2 != 0 || d.n > 200 ||
        (strcmp(d.element, "C3D20R") != 0 && strcmp(d.element, "C3D20") != 0)) {
        fprintf(stderr, "usage: slit_deck --divisions N [--element C3D20R|C3D20] > deck.inp\n"
                        "  N  elements per 10 mm, even, 2 to 200 (h = 10/N mm)\n");
        return 2;
    }
    d.kx = 4L * d.n + 1;
    d.ky = 2L * d.n + 1;
    d.kz = 2L * d.n + 1;
    write_nodes(&d);
    write_elements(&d);
    write_sets_and_step(&d);
    return 0;
}

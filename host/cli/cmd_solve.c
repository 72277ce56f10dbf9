/*
 * cmd_solve.c — `tissuefit solve`: one load case of a scene, every node's
 * displacement to CSV (and VTU for ParaView).
 */
#include <getopt.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "base/atomic_file.h"
#include "cli/cli.h"
#include "cli/cmd_args.h"
#include "report/displacement_out.h"
#include "report/organ_pictures.h"
#include "base/log.h"
#include "base/plot.h"
#include "scene/scene.h"
#include "solvers/solver.h"

static void help(FILE *out)
{
    fprintf(out,
            "usage: tissuefit solve SCENE [--force FX,FY,FZ] [--contact NAME]\n"
            "                       [--set KEY=VALUE]... [--out FILE.csv] [--vtk FILE.vtu]\n"
            "                       [--png FILE.png] [--png-rest FILE.png] [--exaggerate K]\n"
            "                       [--view AZ,EL]\n\n"
            "Solves the scene with the RPIM Galerkin method (seed 000) and writes every\n"
            "node's displacement as CSV: header node,x,y,z,ux,uy,uz, mm, %%.17g.\n"
            "The scene's loads always act; --force adds a force (N) at a contact site,\n"
            "spread as the site's patch says.\n\n"
            "Options:\n"
            "  --force FX,FY,FZ   force at the contact site, N\n"
            "  --contact NAME     which contact site (default: the first)\n"
            "  --set KEY=VALUE    override a scene value, e.g. geometry.grid=41,41,9\n"
            "                     (repeatable; see docs/scene-format.md)\n"
            "  -o, --out FILE     CSV file (default: standard output)\n"
            "  --vtk FILE.vtu     also write a VTK unstructured grid for ParaView\n"
            "  --png FILE.png     an organ: its surface deformed by the solve (needs gnuplot)\n"
            "  --png-rest FILE.png  an organ at rest with its fixed region and contact sites\n"
            "  --exaggerate K     draw displacements K times their size (default 1: to scale)\n"
            "  --view AZ,EL       camera azimuth about +z from +x and elevation, degrees\n"
            "                     (default: facing the contact site, turned 35 and raised 20)\n\n"
            "Progress and the time split go to stderr (quiet with tissuefit -q).\n"
            "Exit status: 0 ok, 1 the solve failed, 2 bad usage or a bad scene (nothing\n"
            "written then).\n");
}

typedef struct solve_args {
    const char *scene, *out, *vtk, *contact, *png, *png_rest;
    double force[3], exaggerate, view[2];
    int has_force;
    tf_sets sets;
} solve_args;

static int parse(tf_ctx *ctx, int argc, char **argv, solve_args *a)
{
    static const struct option opts[] = {{"force", required_argument, NULL, 'f'},
                                         {"contact", required_argument, NULL, 'c'},
                                         {"set", required_argument, NULL, 's'},
                                         {"out", required_argument, NULL, 'o'},
                                         {"vtk", required_argument, NULL, 'v'},
                                         {"png", required_argument, NULL, 'p'},
                                         {"png-rest", required_argument, NULL, 'r'},
                                         {"exaggerate", required_argument, NULL, 'x'},
                                         {"view", required_argument, NULL, 'w'},
                                         {0}};
    int c;
    optind = 1;
    opterr = 0;
    while ((c = getopt_long(argc, argv, "o:", opts, NULL)) != -1) {
        switch (c) {
        case 'f':
            if (tf_parse_vec3(optarg, a->force) != 0) {
                tf_error(ctx, "solve: --force '%s' is not three numbers FX,FY,FZ (N)", optarg);
                return -1;
            }
            a->has_force = 1;
            break;
        case 'c':
            a->contact = optarg;
            break;
        case 's':
            if (tf_sets_add(&a->sets, optarg) != 0) {
                tf_error(ctx, "solve: out of memory");
                return -1;
            }
            break;
        case 'o':
            a->out = optarg;
            break;
        case 'v':
            a->vtk = optarg;
            break;
        case 'p':
            a->png = optarg;
            break;
        case 'r':
            a->png_rest = optarg;
            break;
        case 'w':
            if (sscanf(optarg, "%lf,%lf", &a->view[0], &a->view[1]) != 2 ||
                !isfinite(a->view[0]) || !isfinite(a->view[1])) {
                tf_error(ctx, "solve: --view '%s' is not AZIMUTH,ELEVATION (degrees)", optarg);
                return -1;
            }
            break;
        case 'x': {
            char *end;
            a->exaggerate = strtod(optarg, &end);
            if (*end != '\0' || !(a->exaggerate > 0) || a->exaggerate > 1e6) {
                tf_error(ctx, "solve: --exaggerate '%s' is not a positive factor", optarg);
                return -1;
            }
            break;
        }
        default:
            tf_error(ctx, "solve: bad option '%s' (see tissuefit solve --help)", argv[optind - 1]);
            return -1;
        }
    }
    if (optind + 1 != argc) {
        tf_error(ctx, "solve: expected one scene file (see tissuefit solve --help)");
        return -1;
    }
    a->scene = argv[optind];
    return 0;
}

/* The contact site the force goes to, or -1 when there is no force. */
static int pick_contact(tf_ctx *ctx, const solve_args *a, const tf_problem *s)
{
    if (!a->has_force) {
        if (a->contact) {
            tf_error(ctx, "solve: --contact without --force");
            return -2;
        }
        return -1;
    }
    if (s->n_contacts == 0) {
        tf_error(ctx, "solve: %s has no contact site for --force", a->scene);
        return -2;
    }
    int k = a->contact ? tf_problem_contact(s, a->contact) : 0;
    if (k < 0) {
        tf_error(ctx, "solve: %s has no contact site '%s'", a->scene, a->contact);
        return -2;
    }
    return k;
}

/* Both files go to temporaries first, so a failure leaves neither. */
static int write_outputs(tf_ctx *ctx, const solve_args *a, const tf_problem *s, const double *u)
{
    char err[512];
    tf_afile csv, vtu;
    if (a->out && tf_afile_open(&csv, a->out, err, sizeof err) != 0) {
        tf_error(ctx, "solve: %s", err);
        return TF_EXIT_FAIL;
    }
    if (a->vtk && tf_afile_open(&vtu, a->vtk, err, sizeof err) != 0) {
        if (a->out) {
            tf_afile_abort(&csv);
        }
        tf_error(ctx, "solve: %s", err);
        return TF_EXIT_FAIL;
    }
    tf_report_csv_displacements(a->out ? csv.fp : stdout, &s->cloud, NULL, 0, u);
    if (a->vtk) {
        const tf_mesh_geometry *m = tf_problem_mesh(s);
        if (m != NULL) {
            tf_report_vtu_displacements_tets(vtu.fp, &s->cloud, m->tm.tet, m->tm.ntet, u);
        } else {
            tf_report_vtu_displacements(vtu.fp, &s->cloud, u);
        }
    }
    int rc = 0;
    if (a->out) {
        rc = tf_afile_commit(&csv, err, sizeof err);
    }
    if (a->vtk) {
        if (rc == 0) {
            rc = tf_afile_commit(&vtu, err, sizeof err);
        } else {
            tf_afile_abort(&vtu);
        }
    }
    if (rc != 0 || (!a->out && fflush(stdout) != 0)) {
        tf_error(ctx, "solve: %s", rc ? err : "cannot write to standard output");
        return TF_EXIT_FAIL;
    }
    return TF_EXIT_OK;
}

/* The organ pictures (--png, --png-rest). */
static int pictures(tf_ctx *ctx, const solve_args *a, const tf_problem *s, int contact,
                    const double *u)
{
    char err[512];
    tf_report_organ_view v = {.contact = contact < 0 ? 0 : contact, .exaggerate = a->exaggerate,
                       .azimuth = a->view[0], .elevation = a->view[1]};
    const double zero[3] = {0, 0, 0};
    if ((a->png_rest && tf_report_organ_rest_png(a->png_rest, s, &v, err, sizeof err) != 0) ||
        (a->png && tf_report_organ_deformed_png(a->png, s, u, contact < 0 ? zero : a->force, &v, err,
                                         sizeof err) != 0)) {
        tf_error(ctx, "solve: %s", err);
        return TF_EXIT_FAIL;
    }
    return TF_EXIT_OK;
}

/* --png and --png-rest draw organs around a contact site, with gnuplot. */
static int check_pictures(tf_ctx *ctx, const solve_args *a, const tf_problem *s)
{
    if (!a->png && !a->png_rest) {
        return 0;
    }
    if (tf_problem_mesh(s) == NULL || s->n_contacts == 0) {
        tf_error(ctx, "solve: --png and --png-rest draw an organ (geometry.surface) with a "
                      "contact site");
        return -1;
    }
    if (!tf_plot_available()) {
        tf_error(ctx, "solve: --png needs gnuplot with the pngcairo terminal (gnuplot-nox)");
        return -1;
    }
    return 0;
}

static int run(tf_ctx *ctx, int argc, char **argv)
{
    solve_args a = {.exaggerate = 1, .view = {NAN, NAN}};
    tf_scene *s = NULL;
    if (parse(ctx, argc, argv, &a) != 0 || (s = tf_cmd_scene(ctx, a.scene, &a.sets)) == NULL) {
        tf_sets_free(&a.sets);
        return TF_EXIT_USAGE;
    }
    tf_sets_free(&a.sets);
    const tf_problem *p = &s->problem;
    int contact = pick_contact(ctx, &a, p);
    if (contact < -1 || check_pictures(ctx, &a, p) != 0) {
        tf_scene_free(s);
        return TF_EXIT_USAGE;
    }
    int rc = TF_EXIT_FAIL;
    tf_solver *sv = tf_solver_create(p, NULL, ctx);
    double *u = malloc(3 * p->cloud.n * sizeof *u);
    if (sv == NULL || u == NULL) {
        tf_error(ctx, "solve: %s: %s", a.scene, sv ? "out of memory" : ctx->err);
    } else if (tf_solver_solve(sv, contact, (const double(*)[3])a.force, 1, NULL, u) != 0) {
        tf_error(ctx, "solve: %s: %s", a.scene, ctx->err);
    } else {
        tf_solver_report(sv);
        rc = write_outputs(ctx, &a, p, u);
        rc = rc == TF_EXIT_OK ? pictures(ctx, &a, p, contact, u) : rc;
    }
    free(u);
    tf_solver_destroy(sv);
    tf_scene_free(s);
    return rc;
}

const tf_command tf_cmd_solve = {
    .name = "solve",
    .summary = "solve a scene for one force and write nodal displacements (CSV, VTU)",
    .run = run,
    .help = help,
};

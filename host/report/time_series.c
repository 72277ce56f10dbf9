/*
 * time_series.c — CSV and ParaView time series (time_series.h).
 */
#include "report/time_series.h"

void tf_report_series_csv(FILE *fp, const tf_cloud *c, size_t n, const double *t,
                          const double *u)
{
    fprintf(fp, "step,time,node,x,y,z,ux,uy,uz\n");
    for (size_t k = 0; k < n; ++k) {
        const double *uk = u + 3 * c->n * k;
        for (size_t i = 0; i < c->n; ++i) {
            const double *x = c->xyz + 3 * i, *ui = uk + 3 * i;
            fprintf(fp, "%zu,%.17g,%zu,%.17g,%.17g,%.17g,%.17g,%.17g,%.17g\n", k + 1, t[k], i + 1,
                    x[0], x[1], x[2], ui[0], ui[1], ui[2]);
        }
    }
}

void tf_report_series_pvd(FILE *fp, size_t n, const double *t, const char *const *files)
{
    fprintf(fp, "<?xml version=\"1.0\"?>\n"
                "<VTKFile type=\"Collection\" version=\"0.1\" byte_order=\"LittleEndian\">\n"
                "<Collection>\n");
    for (size_t k = 0; k < n; ++k) {
        /* two samples at one time (a jump) would hide one another: the
         * later keeps the time, the earlier moves back by a hair */
        double tk = k + 1 < n && t[k + 1] == t[k] ? t[k] - 1e-9 : t[k];
        fprintf(fp, "<DataSet timestep=\"%.17g\" part=\"0\" file=\"%s\"/>\n", tk, files[k]);
    }
    fprintf(fp, "</Collection>\n</VTKFile>\n");
}

/*
 * plot.c — see plot.h.
 */
#include "base/plot.h"

#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

int tf_plot_available(void)
{
    FILE *gp = popen("gnuplot -e \"set terminal pngcairo\" 2>/dev/null", "r");
    return gp != NULL && pclose(gp) == 0;
}

int tf_plot_open(tf_plot *p, const char *path, int width, int height, char *err, size_t errlen)
{
    snprintf(p->path, sizeof p->path, "%s", path);
    snprintf(p->tmp, sizeof p->tmp, "%s.tmp.png", path);
    p->gp = popen("gnuplot", "w");
    if (p->gp == NULL) {
        snprintf(err, errlen, "%s: cannot run gnuplot", path);
        return -1;
    }
    fprintf(p->gp,
            "set terminal pngcairo size %d,%d font 'DejaVu Sans,10' noenhanced\n"
            "set output '%s'\n",
            width, height, p->tmp);
    return 0;
}

int tf_plot_close(tf_plot *p, char *err, size_t errlen)
{
    fprintf(p->gp, "unset output\n");
    int status = pclose(p->gp);
    p->gp = NULL;
    if (status != 0 || rename(p->tmp, p->path) != 0) {
        unlink(p->tmp);
        snprintf(err, errlen, "%s: gnuplot failed (status %d)", p->path, status);
        return -1;
    }
    return 0;
}

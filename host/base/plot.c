/*
 * plot.c — see plot.h.
 */
#include "base/plot.h"

#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

#include "base/atomic_file.h"

int tf_plot_available(void)
{
    FILE *gp = popen("gnuplot -e \"set terminal pngcairo\" 2>/dev/null", "r");
    return gp != NULL && pclose(gp) == 0;
}

/* A path as a gnuplot single-quoted string: a quote is doubled, so a file
 * name cannot end the string and run gnuplot commands. */
static void quoted(FILE *gp, const char *s)
{
    fputc('\'', gp);
    for (; *s != '\0'; ++s) {
        if (*s == '\'') {
            fputc('\'', gp);
        }
        fputc(*s, gp);
    }
    fputc('\'', gp);
}

int tf_plot_open(tf_ctx *ctx, tf_plot *p, const char *path, int width, int height)
{
    /* the image replaces the file a link names, never a device (atomic_file.h) */
    if (tf_afile_target(ctx, path, p->path, sizeof p->path) != 0) {
        return -1;
    }
    snprintf(p->tmp, sizeof p->tmp, "%s.tmp.png", p->path);
    p->gp = popen("gnuplot", "w");
    if (p->gp == NULL) {
        return tf_fail(ctx, "%s: cannot run gnuplot", path);
    }
    fprintf(p->gp, "set terminal pngcairo size %d,%d font 'DejaVu Sans,10' noenhanced\n"
                   "set output ", width, height);
    quoted(p->gp, p->tmp);
    fputc('\n', p->gp);
    return 0;
}

/* Whether path is a whole PNG, synced: it ends with the IEND chunk.
 * gnuplot exits 0 when cairo could not write the image (a full disk), and
 * the truncated file would have been renamed over the destination. */
static int png_complete(const char *path)
{
    static const unsigned char iend[12] = {0, 0, 0, 0, 'I', 'E', 'N', 'D', 0xae, 0x42, 0x60, 0x82};
    unsigned char tail[12];
    FILE *f = fopen(path, "rb+");
    int ok = f != NULL && fseek(f, -12, SEEK_END) == 0 && fread(tail, 1, 12, f) == 12 &&
             memcmp(tail, iend, 12) == 0 && fflush(f) == 0 && fsync(fileno(f)) == 0;
    if (f != NULL) {
        fclose(f);
    }
    return ok;
}

int tf_plot_close(tf_ctx *ctx, tf_plot *p)
{
    fprintf(p->gp, "unset output\n");
    int status = pclose(p->gp);
    p->gp = NULL;
    if (status != 0) {
        unlink(p->tmp);
        return tf_fail(ctx, "%s: gnuplot failed (status %d)", p->path, status);
    }
    if (!png_complete(p->tmp)) {
        unlink(p->tmp);
        return tf_fail(ctx, "%s: gnuplot wrote an incomplete image (a full disk?)", p->path);
    }
    if (rename(p->tmp, p->path) != 0) {
        unlink(p->tmp);
        return tf_fail(ctx, "%s: cannot rename its temporary file", p->path);
    }
    return 0;
}

/*
 * board_native.c — the haptic loop as a host program: the scripted
 * trajectory as the sensor, the time of each tick measured (median and
 * worst reported), a summary on stdout, and every tick as CSV when
 * HAPTIC_CSV names a file: tick, force, status, the contact force, then the
 * displacement of every output point (ux0,uy0,uz0,ux1,...), which
 * `tissuefit replay` compares with true solves.  The same haptic_loop.c runs
 * on the microcontrollers.
 */
#define _POSIX_C_SOURCE 199309L
#include <stdio.h>
#include <stdlib.h>
#include <time.h>

#include "board.h"
#include "haptic_loop.h"
#include "haptic_script.h"

static uint32_t tick_no, ok, clamped, rejected;
static double worst_ns, t_start, tick_ns[HAPTIC_SCRIPT_TICKS];
static float last_force[3], max_press_force[3], max_press_u;
static FILE *csv;

static double now_ns(void)
{
    struct timespec ts;
    clock_gettime(CLOCK_MONOTONIC, &ts);
    return (double)ts.tv_sec * 1e9 + (double)ts.tv_nsec;
}

void board_init(void)
{
    const char *path = getenv("HAPTIC_CSV");
    if (path != NULL && path[0] != '\0') {
        csv = fopen(path, "w");
        if (csv == NULL) {
            perror(path);
            exit(1);
        }
    }
}

static int by_value(const void *a, const void *b)
{
    double x = *(const double *)a, y = *(const double *)b;
    return (x > y) - (x < y);
}

static void csv_row(const float *u, uint32_t n_points, const float contact_force[3], int status)
{
    if (tick_no == 0) {
        fprintf(csv, "tick,fx,fy,fz,status,contact_fx,contact_fy,contact_fz");
        for (uint32_t j = 0; j < n_points; ++j) {
            fprintf(csv, ",ux%u,uy%u,uz%u", j, j, j);
        }
        fputc('\n', csv);
    }
    fprintf(csv, "%u,%.9g,%.9g,%.9g,%d,%.9g,%.9g,%.9g", tick_no, (double)last_force[0],
            (double)last_force[1], (double)last_force[2], status, (double)contact_force[0],
            (double)contact_force[1], (double)contact_force[2]);
    for (uint32_t k = 0; k < 3 * n_points; ++k) {
        fprintf(csv, ",%.9g", (double)u[k]);
    }
    fputc('\n', csv);
}

int board_wait_tick(void)
{
    t_start = now_ns();
    return tick_no < HAPTIC_SCRIPT_TICKS;
}

void board_read_force(float force[3])
{
    haptic_script_force(tick_no, force);
    for (int i = 0; i < 3; ++i) {
        last_force[i] = force[i];
    }
}

void board_read_position(float disp[3])
{
    haptic_script_position(tick_no, disp);
    for (int i = 0; i < 3; ++i) {
        last_force[i] = disp[i];
    }
}

void board_publish(const float *u, uint32_t n_points, const float contact_force[3], int status)
{
    double dt = now_ns() - t_start;
    tick_ns[tick_no] = dt;
    worst_ns = dt > worst_ns ? dt : worst_ns;
    ok += status == 0;
    clamped += status == 1;
    rejected += status < 0;
    /* the point that moves most along z: the contact site for a press */
    for (uint32_t j = 0; j < n_points; ++j) {
        if (-u[3 * j + 2] > max_press_u) {
            max_press_u = -u[3 * j + 2];
            for (int i = 0; i < 3; ++i) {
                max_press_force[i] = contact_force[i];
            }
        }
    }
    if (csv != NULL) {
        csv_row(u, n_points, contact_force, status);
    }
    ++tick_no;
}

int board_finish(void)
{
    qsort(tick_ns, tick_no, sizeof tick_ns[0], by_value);
    printf("haptic loop: %u ticks (%u in the envelope, %u clamped, %u rejected); largest "
           "indentation %.4g mm, contact force there (%.4g, %.4g, %.4g) N; %.0f ns per tick "
           "(median), %.0f ns worst, this machine\n",
           tick_no, ok, clamped, rejected, (double)max_press_u, (double)max_press_force[0],
           (double)max_press_force[1], (double)max_press_force[2], tick_ns[tick_no / 2], worst_ns);
    if (csv != NULL && fclose(csv) != 0) {
        perror("HAPTIC_CSV");
        return 1;
    }
    return rejected == HAPTIC_SCRIPT_REJECTED ? 0 : 1;
}

void board_fail(const char *why)
{
    fprintf(stderr, "%s\n", why);
    exit(1);
}

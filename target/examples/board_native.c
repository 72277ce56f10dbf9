/*
 * board_native.c — the haptic loop as a host program: the scripted
 * trajectory as the sensor, the time of each tick measured, a summary on
 * stdout, and every tick as CSV when HAPTIC_CSV names a file (tick, force,
 * status, contact-site displacement, contact force).  The same haptic_loop.c
 * runs on the microcontrollers.
 */
#define _POSIX_C_SOURCE 199309L
#include <stdio.h>
#include <stdlib.h>
#include <time.h>

#include "board.h"
#include "haptic_loop.h"
#include "haptic_script.h"

static uint32_t tick_no, ok, clamped, rejected;
static double worst_ns, total_ns, t_start;
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
        fprintf(csv, "tick,fx,fy,fz,status,ux,uy,uz,contact_fx,contact_fy,contact_fz\n");
    }
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
    total_ns += dt;
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
        fprintf(csv, "%u,%.9g,%.9g,%.9g,%d,%.9g,%.9g,%.9g,%.9g,%.9g,%.9g\n", tick_no,
                (double)last_force[0], (double)last_force[1], (double)last_force[2], status,
                (double)u[0], (double)u[1], (double)u[2], (double)contact_force[0],
                (double)contact_force[1], (double)contact_force[2]);
    }
    ++tick_no;
}

int board_finish(void)
{
    printf("haptic loop: %u ticks (%u in the envelope, %u clamped, %u rejected); largest "
           "indentation %.4g mm, contact force there (%.4g, %.4g, %.4g) N; %.0f ns per tick "
           "(mean), %.0f ns worst, this machine\n",
           tick_no, ok, clamped, rejected, (double)max_press_u, (double)max_press_force[0],
           (double)max_press_force[1], (double)max_press_force[2], total_ns / tick_no, worst_ns);
    if (csv != NULL && fclose(csv) != 0) {
        perror("HAPTIC_CSV");
        return 1;
    }
    return rejected == 1u ? 0 : 1;
}

void board_fail(const char *why)
{
    fprintf(stderr, "%s\n", why);
    exit(1);
}

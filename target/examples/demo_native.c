/*
 * demo_native.c — the interim `make demo`: evaluates the header that
 * `tissuefit demo-model` generated, through the target library, on the host.
 *
 * Boot-time check, golden vectors (bit-exact against the host reference),
 * a few forces inside and outside the envelope, and the cost per call.
 */
#define _POSIX_C_SOURCE 199309L
#include <stdio.h>
#include <time.h>

#define TFIT_DEMO_IMPLEMENTATION
#include "demo_golden.h"

#define N_OUT TFIT_DEMO_FORWARD_N_OUT
#define CENTRE_NODE 60 /* node 61, the loaded point */

static double now_ns(void)
{
    struct timespec ts;
    clock_gettime(CLOCK_MONOTONIC, &ts);
    return (double)ts.tv_sec * 1e9 + (double)ts.tv_nsec;
}

static const char *status_name(tfit_status s)
{
    switch (s) {
    case TFIT_OK:
        return "ok";
    case TFIT_CLAMPED:
        return "clamped to envelope";
    case TFIT_ERR_INPUT:
        return "input rejected (NaN/Inf)";
    default:
        return "error";
    }
}

int main(void)
{
    static float u[3 * N_OUT];
    const tfit_model *m = &tfit_demo_forward;

    tfit_status st = tfit_model_check(m);
    printf("model: %s %s, %u nodes, %d ops/eval, %d table bytes, crc32 0x%08x: check %s\n",
           TFIT_DEMO_FORWARD_FAMILY, TFIT_DEMO_FORWARD_ORDERS, (unsigned)m->n_out,
           TFIT_DEMO_FORWARD_OPS, TFIT_DEMO_FORWARD_TABLE_BYTES, (unsigned)tfit_model_crc32(m),
           st == TFIT_OK ? "ok" : "FAILED");
    printf("held-out error (header): max %.3g mm, rms %.3g mm over %d forces\n",
           TFIT_DEMO_FORWARD_HELDOUT_MAX_MM, TFIT_DEMO_FORWARD_HELDOUT_RMS_MM,
           TFIT_DEMO_FORWARD_HELDOUT_CASES);
    uint32_t bad = tfit_golden_run(&tfit_demo_forward_golden, u);
    printf("golden vectors: %u inputs, %u mismatching words\n\n",
           (unsigned)tfit_demo_forward_golden.n_vec, (unsigned)bad);

    static const float forces[][3] = {
        {0.0f, 0.0f, -1.0f}, {0.9f, -0.7f, -0.22f}, {0.3f, 0.0f, 0.0f}, {0.0f, 0.0f, -5.0f},
        {1e30f, 0.0f, 0.0f}, {0.0f, 0.0f, 1.0f / 0.0f},
    };
    printf("%-28s %-26s %s\n", "force [N]", "status", "node 61 displacement [mm]");
    for (size_t i = 0; i < sizeof forces / sizeof forces[0]; ++i) {
        st = tfit_displacements(m, forces[i], u);
        printf("(%8.3g, %8.3g, %8.3g)  %-26s (%+.4f, %+.4f, %+.4f)\n", (double)forces[i][0],
               (double)forces[i][1], (double)forces[i][2], status_name(st),
               (double)u[3 * CENTRE_NODE], (double)u[3 * CENTRE_NODE + 1],
               (double)u[3 * CENTRE_NODE + 2]);
    }

    enum { CALLS = 100000 };
    float f[3] = {0.1f, 0.2f, -0.3f};
    double t0 = now_ns();
    for (int i = 0; i < CALLS; ++i) {
        f[0] = (float)(i % 100) * 0.01f - 0.5f;
        tfit_displacements(m, f, u);
    }
    double per_call = (now_ns() - t0) / CALLS;
    printf("\n%d evaluations of all %u nodes: %.0f ns per call (mean, this machine)\n", CALLS,
           (unsigned)m->n_out, per_call);
    return (bad == 0 && tfit_model_check(m) == TFIT_OK) ? 0 : 1;
}

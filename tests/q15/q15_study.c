/*
 * q15_study.c — issue 14 acceptance 1 feasibility study (tests/q15/q15.mk,
 * `make q15-study`): where the shipped block48_nh forward model's M4F
 * cycles go (the cycle model of host/cost/cycles.c), and how much error a
 * Q15 reconstruction of its modes would add (an emulation of the proposed
 * integer arithmetic against the float model that ships, on a dense sample
 * of the 3 N envelope).  Results: docs/reports/block48_nh_q15.md.
 *
 * Proposed Q15 rows (not built into the firmware, see the report):
 *   U[o][k] = q[o][k] u_k, q int16 with max_o |q[o][k]| = 32767 (u_k per mode);
 *   c_k = trunc(clamp(a_k v_k, +-C)), v_k = u_k / S (one float per mode),
 *   out[o] = (float)(sum_k q[o][k] c_k) * S  (SMLAD: two products a cycle).
 * No 32-bit overflow by construction: |sum| <= r 32767 C <= 2^31 - 1 with
 * C = 8191 for r <= 8.  S makes the rigorous amplitude bound
 * B_k = sum_t |A[k][t]| (|phi_t| <= 1 on the unit cube holding the ball)
 * land within C: S = max_k B_k u_k / C ("bound" variant), or the largest
 * |a_k| over the sample ("sampled" variant, clamped beyond it).
 */
#include <math.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "cost/cycles.h"
#include "model/model.h"
#include "tfit_internal.h"
#define TFIT_BLOCK48_NH_IMPLEMENTATION
#include "block48_nh.h"

#define N_SAMPLES 200000u
#define C_MAX 8191.0f

static double cycles(uint32_t p, uint32_t r, uint32_t n_out)
{
    char err[128];
    uint32_t dims[2] = {p, r};
    tf_model *m = tf_model_new("study", TFIT_FAMILY_MODAL, n_out, dims, 2, err, sizeof err);
    if (m == NULL) {
        fprintf(stderr, "q15_study: %s\n", err);
        exit(1);
    }
    double c = tf_cycles_estimate(m, TF_CORE_M4F).cycles;
    tf_model_free(m);
    return c;
}

/* M4F cycles of the shipped shape split by the model's own sums: the rows
 * (the n_out-dependent part), the amplitudes (the r-dependent part at one
 * point, less one point's rows), the rest (input map, basis, call). */
static void profile(uint32_t p, uint32_t r, uint32_t n_out)
{
    double all = cycles(p, r, n_out), one = cycles(p, r, 1);
    double rows = (all - one) * n_out / (double)(n_out - 1u);
    double r1 = cycles(p, 1, 1) - (cycles(p, 1, 2) - cycles(p, 1, 1));
    double amp = (one - (all - one) / (double)(n_out - 1u)) - r1;
    double rest = all - rows - amp;
    printf("| modal p=%u r=%u | %.0f (%.1f us) | %.0f (%.1f us) | %.0f (%.1f us) | %.0f (%.1f us) |\n",
           p, r, all, all / 168.0, rows, rows / 168.0, amp, amp / 168.0, rest, rest / 168.0);
}

/* One mix line of insn_mix's output ("FUNC loop 1 depth 1: ..." or
 * "FUNC outside: ..."), as M4F upper-bound cycles; exits when missing. */
static double mix_cycles(const char *path, const char *func, const char *region)
{
    FILE *f = fopen(path, "r");
    char line[512], head[160];
    if (f == NULL) {
        fprintf(stderr, "q15_study: %s: cannot open\n", path);
        exit(2);
    }
    snprintf(head, sizeof head, "%s %s", func, region);
    while (fgets(line, sizeof line, f) != NULL) {
        const char *colon = strchr(line, ':');
        if (strncmp(line, head, strlen(head)) != 0 || colon == NULL) continue;
        tf_insn_mix mix;
        line[strcspn(line, "\n")] = '\0';
        if (tf_insn_mix_parse(colon + 2, &mix) != 0) break;
        fclose(f);
        return tf_cycles_of_mix(&mix, TF_CORE_M4F).cycles;
    }
    fclose(f);
    fprintf(stderr, "q15_study: %s: no line \"%s\"\n", path, head);
    exit(2);
}

/* Projected M4F cycles of a Q15 modal model of rank 8 at degree p: the
 * float model's input map, basis and call (profile's "rest") plus the
 * prototypes' measured mixes (amplitudes term by term, their conversion,
 * the Q15 rows) at the shape's counts. */
static void projection(const char *mixes, uint32_t p, uint32_t n_out)
{
    if (n_out % 2u != 1u) {
        fprintf(stderr, "q15_study: the projection counts an odd n_out\n");
        exit(2);
    }
    double all = cycles(p, 8, n_out), one = cycles(p, 8, 1);
    double rows = (all - one) * n_out / (double)(n_out - 1u);
    double r1 = cycles(p, 1, 1) - (cycles(p, 1, 2) - cycles(p, 1, 1));
    double amp = (one - (all - one) / (double)(n_out - 1u)) - r1;
    double rest = all - rows - amp;
    /* the fused amplitude step: set-up, conversion and packing outside,
     * one iteration per term after the first */
    double amp_q = mix_cycles(mixes, "q15_amp_asm", "outside") +
                   (TFIT_TERMS(p) - 1u) * mix_cycles(mixes, "q15_amp_asm", "loop 1");
    /* the rows: the odd point is in "outside" (n_out odd), then pairs */
    double rows_q = mix_cycles(mixes, "q15_rows_asm", "outside") +
                    (n_out / 2u) * mix_cycles(mixes, "q15_rows_asm", "loop 1");
    double total = rest + amp_q + rows_q;
    printf("| Q15 modal p=%u r=8 (projected) | %.0f (%.1f us) | %.0f (%.1f us) | %.0f (%.1f us) | "
           "%.0f (%.1f us) |\n",
           p, total, total / 168.0, rows_q, rows_q / 168.0, amp_q, amp_q / 168.0, rest,
           rest / 168.0);
}

static uint64_t rng = 0x9e3779b97f4a7c15ull;
static double uniform(void)
{
    rng ^= rng << 13;
    rng ^= rng >> 7;
    rng ^= rng << 17;
    return (double)(rng >> 11) * 0x1.0p-53;
}

/* A point of the 3 N ball: uniform inside, every 4th on the boundary. */
static void sample(uint32_t i, float f[3])
{
    double x[3], n2;
    do {
        for (int j = 0; j < 3; ++j) x[j] = 2.0 * uniform() - 1.0;
        n2 = x[0] * x[0] + x[1] * x[1] + x[2] * x[2];
    } while (n2 > 1.0 || n2 < 1e-12);
    double s = (i % 4u == 0u) ? 1.0 / sqrt(n2) : 1.0;
    for (int j = 0; j < 3; ++j) f[j] = (float)(3.0 * s * x[j]);
}

int main(int argc, char **argv)
{
    if (argc != 2) {
        fprintf(stderr, "usage: q15_study MIXES (insn_mix output for the q15 prototypes)\n");
        return 2;
    }
    const tfit_model *m = &tfit_block48_nh_forward;
    const uint32_t p = m->dims[0], r = m->dims[1], n = m->n_out, T = TFIT_TERMS(p);
    const float *amp = m->coef + TFIT_INPUT_MAP_FLOATS;
    const float *U = m->coef + (m->n_coef - 3u * r * n);

    printf("## M4F cycles by part (cycle model, upper bound at 168 MHz)\n\n");
    printf("| model | total | rows | amplitudes | input, basis, call |\n|---|---|---|---|---|\n");
    profile(4, 8, 121);
    profile(3, 8, 121);
    profile(3, 3, 121);
    projection(argv[1], 4, 121);
    projection(argv[1], 3, 121);

    /* per-mode scales of U and the rigorous amplitude bounds */
    float u[TFIT_MAX_RANK], bound[TFIT_MAX_RANK], seen[TFIT_MAX_RANK] = {0};
    for (uint32_t k = 0; k < r; ++k) {
        float mx = 0.0f, b = 0.0f;
        for (uint32_t o = 0; o < 3u * n; ++o) mx = fmaxf(mx, fabsf(U[o * r + k]));
        for (uint32_t t = 0; t < T; ++t) b += fabsf(amp[k * T + t]);
        u[k] = mx / 32767.0f;
        bound[k] = b;
    }
    int16_t *q = malloc(sizeof(int16_t) * 3u * n * r);
    for (uint32_t i = 0; i < 3u * n * r; ++i) q[i] = (int16_t)lrintf(U[i] / u[i % r]);

    float *ref = malloc(sizeof(float) * 3u * n);
    float (*a_all)[TFIT_MAX_RANK] = malloc(sizeof *a_all * N_SAMPLES);
    float (*f_all)[3] = malloc(sizeof *f_all * N_SAMPLES);
    for (uint32_t i = 0; i < N_SAMPLES; ++i) {
        float g[3], phi[TFIT_MAX_TERMS];
        uint32_t bad;
        sample(i, f_all[i]);
        (void)tfit_input_map(m->coef, f_all[i], g, &bad);
        tfit_basis(p, g, phi);
        for (uint32_t k = 0; k < r; ++k) {
            a_all[i][k] = tfit_row(amp + k * T, phi, T);
            seen[k] = fmaxf(seen[k], fabsf(a_all[i][k]));
        }
    }
    double peak = 0.0;
    printf("\n## Amplitude bounds\n\n| mode | u_k (mm) | sampled max |a_k| | bound sum |A_kt| |\n|---|---|---|---|\n");
    for (uint32_t k = 0; k < r; ++k)
        printf("| %u | %.3g | %.4g | %.4g |\n", k, (double)u[k], (double)seen[k], (double)bound[k]);

    for (int variant = 0; variant < 2; ++variant) {
        float S = 0.0f, v[TFIT_MAX_RANK];
        for (uint32_t k = 0; k < r; ++k)
            S = fmaxf(S, (variant == 0 ? bound[k] : seen[k]) * u[k] / C_MAX);
        for (uint32_t k = 0; k < r; ++k) v[k] = u[k] / S;
        double worst = 0.0;
        long long acc_max = 0;
        for (uint32_t i = 0; i < N_SAMPLES; ++i) {
            int32_t c[TFIT_MAX_RANK];
            (void)tfit_displacements(m, f_all[i], ref);
            for (uint32_t k = 0; k < r; ++k) {
                float x = a_all[i][k] * v[k];
                x = x > C_MAX ? C_MAX : (x < -C_MAX ? -C_MAX : x);
                c[k] = (int32_t)x;
            }
            for (uint32_t o = 0; o < 3u * n; ++o) {
                int32_t acc = 0;
                for (uint32_t k = 0; k < r; ++k) acc += (int32_t)q[o * r + k] * c[k];
                if (llabs((long long)acc) > acc_max) acc_max = llabs((long long)acc);
                float out = (float)acc * S;
                double e = fabs((double)out - (double)ref[o]);
                if (e > worst) worst = e;
                if (variant == 0 && fabs((double)ref[o]) > peak) peak = fabs((double)ref[o]);
            }
        }
        /* a priori, per row: |U - q u_k| <= u_k / 2 times |a_k| <= B_k, plus
         * the truncation of c_k (< 1 unit, |q| S each, no saturation with
         * the rigorous bound), plus the two roundings of (float)sum * S */
        double apriori = 0.0;
        for (uint32_t o = 0; variant == 0 && o < 3u * n; ++o) {
            double b = 0.0, mag = 0.0;
            for (uint32_t k = 0; k < r; ++k) {
                b += 0.5 * (double)u[k] * (double)bound[k] + fabs((double)q[o * r + k]) * (double)S;
                mag += fabs((double)q[o * r + k]) * (double)C_MAX * (double)S;
            }
            b += 2.0 * 0x1p-24 * mag;
            if (b > apriori) apriori = b;
        }
        if (variant == 0)
            printf("\nA priori bound of the Q15 rows' deviation from the float model (any force in the "
                   "envelope): %.4f mm (%.3f %% of the peak)\n",
                   apriori, 100.0 * apriori / 7.09);
        printf("\n%s scale S = %.4g mm: Q15 against the shipped float model, max |diff| over %u "
               "forces (a quarter on the 3 N sphere) = %.4f mm (%.3f %% of the 7.09 mm peak); "
               "largest |sum| %lld (< 2^31 = 2147483648)\n",
               variant == 0 ? "Rigorous-bound" : "Sampled-max", (double)S, N_SAMPLES, worst,
               100.0 * worst / 7.09, acc_max);
    }
    printf("\nLargest |output| of the float model over the sample: %.3f mm\n", peak);
    free(q), free(ref), free(a_all), free(f_all);
    return 0;
}

/*
 * check_cycle_model.c — compares the cycle model (host/cost/cycles.c) with what
 * the device executed: for every golden set of a header, the instruction
 * mix traced under QEMU (trace_mix output) must equal, class by class, the
 * mix the model predicts from the model's family, orders and n_out, and
 * every input of a set must have executed the same instructions.
 *
 *   check_cycle_model CORE HEADER.h TRACE_SUMMARY
 *                                   CORE: m4f, m7 (float and Q31 sets), or
 *                                   m3, m0 (Q31 sets only)
 *   check_cycle_model loops CORE    the loop mixes the model assumes, in the
 *                                   format of insn_mix.c
 *   check_cycle_model cost CORE TRACE_SUMMARY
 *                                   cycles of each traced mix (to cost code
 *                                   the model does not describe, e.g. an
 *                                   older version of the library)
 *
 * Golden sets run in the order of the header's models (emit_header.c),
 * float sets first, then the Q31 ones (qemu_golden.c).  The cycle model
 * covers the float evaluator; for a Q31 set only the fixed instruction
 * count is checked.  Prints one line per set; exit status 1 on any
 * difference.
 */
#include <ctype.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "cost/cycles.h"
#include "fitting/families/family.h"

#define MAX_MODELS 64
#define MAX_MACROS 4096

static char macro_name[MAX_MACROS][96];
static char macro_value[MAX_MACROS][320];
static int n_macros;
static char model_names[MAX_MODELS][TF_NAME_MAX];
static int n_models;

static int read_header(const char *path)
{
    FILE *f = fopen(path, "r");
    if (f == NULL) {
        perror(path);
        return -1;
    }
    char line[1024];
    while (fgets(line, sizeof line, f) != NULL) {
        char name[96];
        if (sscanf(line, "extern const tfit_model tfit_%63[a-z0-9_];", name) == 1) {
            if (n_models < MAX_MODELS) {
                snprintf(model_names[n_models++], TF_NAME_MAX, "%.63s", name);
            }
        } else if (n_macros < MAX_MACROS &&
                   sscanf(line, "#define %95s %319[^\n]", macro_name[n_macros],
                          macro_value[n_macros]) == 2) {
            ++n_macros;
        }
    }
    fclose(f);
    return 0;
}

static const char *macro(const char *model, const char *suffix)
{
    char want[128];
    size_t k = (size_t)snprintf(want, sizeof want, "TFIT_");
    for (const char *p = model; *p != '\0' && k + 1 < sizeof want; ++p) {
        want[k++] = (char)toupper((unsigned char)*p);
    }
    snprintf(want + k, sizeof want - k, "_%s", suffix);
    for (int i = 0; i < n_macros; ++i) {
        if (strcmp(macro_name[i], want) == 0) {
            return macro_value[i];
        }
    }
    return NULL;
}

/* A model with the right family, dims and n_out (tables left zero): all
 * the cycle model looks at. */
static tf_model *shape_of(const char *name)
{
    const char *fam = macro(name, "FAMILY_ID"), *ord = macro(name, "ORDERS");
    const char *nout = macro(name, "N_OUT");
    if (fam == NULL || ord == NULL || nout == NULL) {
        return NULL;
    }
    tfit_family family = (tfit_family)atoi(fam);
    uint32_t dims[TFIT_ZHOU2017_DIMS] = {0}, n_dims = 1;
    if (family == TFIT_FAMILY_PRONY || family == TFIT_FAMILY_RESONANT) {
        /* "p=1 K=2 tick=1000000ns", " r=3" after p if modal */
        n_dims = TFIT_PRONY_DIMS;
        if (sscanf(ord, "\"p=%u r=%u K=%u tick=%uns\"", &dims[0], &dims[1], &dims[2],
                   &dims[3]) != 4 &&
            sscanf(ord, "\"p=%u K=%u tick=%uns\"", &dims[0], &dims[2], &dims[3]) != 3) {
            return NULL;
        }
    } else if (family == TFIT_FAMILY_CUT) { /* "p=1 K=8" */
        n_dims = TFIT_CUT_DIMS;
        sscanf(ord, "\"p=%u K=%u\"", &dims[0], &dims[1]);
    } else if (family == TFIT_FAMILY_MODAL || family == TFIT_FAMILY_MODAL_Q15) {
        n_dims = 2;
        sscanf(ord, "\"p=%u r=%u\"", &dims[0], &dims[1]);
    } else if (family == TFIT_FAMILY_ZHOU2017) {
        n_dims = TFIT_ZHOU2017_DIMS;
        int used = 0;
        sscanf(ord, "\"lambda=%u,%u,%u%n", &dims[0], &dims[1], &dims[2], &used);
        const char *p = ord + used;
        for (int pair = 0; pair < 9; ++pair) {
            int n = 0;
            sscanf(p, " %*c%*c:%u/%u/%u%n", &dims[3 + 3 * pair], &dims[4 + 3 * pair],
                   &dims[5 + 3 * pair], &n);
            p += n;
        }
    } else if (family == TFIT_FAMILY_REGION) { /* "P=2 sites=7x7" */
        n_dims = TFIT_REGION_DIMS;
        if (sscanf(ord, "\"P=%u sites=%ux%u\"", &dims[2], &dims[0], &dims[1]) != 3) {
            return NULL;
        }
    } else if (family == TFIT_FAMILY_REGION_SURFACE) { /* "p=1 r=25 sites=7x7 site-modes" */
        n_dims = TFIT_REGION_SURFACE_DIMS;
        if (sscanf(ord, "\"p=%u r=%u sites=%ux%u", &dims[3], &dims[2], &dims[0], &dims[1]) != 4) {
            return NULL;
        }
        dims[4] = strstr(ord, " site-modes") != NULL;
        const char *near = strstr(ord, " near=");
        if (near != NULL) {
            sscanf(near, " near=%u", &dims[5]);
        }
    } else {
        sscanf(ord, "\"p=%u\"", &dims[0]);
    }
    tf_ctx ctx;
    tf_ctx_init(&ctx);
    return tf_model_new(&ctx, name, family, (uint32_t)strtoul(nout, NULL, 10), dims, n_dims);
}

static tf_core core_of(const char *s)
{
    return strcmp(s, "m7") == 0 ? TF_CORE_M7 : TF_CORE_M4F;
}

static int cost_traces(tf_core core, const char *path)
{
    FILE *f = fopen(path, "r");
    if (f == NULL) {
        perror(path);
        return 2;
    }
    char line[2048];
    int set = 0;
    while (fgets(line, sizeof line, f) != NULL) {
        const char *mixtext = strstr(line, "mix: ");
        tf_insn_mix mix;
        if (mixtext == NULL || tf_insn_mix_parse(mixtext + 5, &mix) != 0) {
            continue;
        }
        tf_cycles c = tf_cycles_of_mix(&mix, core);
        printf("set %d: %llu instructions, %s %.0f cycles (%.0f..%.0f) = %.2f us at %.0f MHz\n",
               set++, (unsigned long long)c.instructions, tf_core_name(core), c.cycles,
               c.cycles_low, c.cycles, c.cycles / tf_core_mhz(core), tf_core_mhz(core));
    }
    fclose(f);
    return 0;
}

int main(int argc, char **argv)
{
    if (argc == 3 && strcmp(argv[1], "loops") == 0) {
        char buf[8192];
        tf_form_loop_table(core_of(argv[2]), buf, sizeof buf);
        fputs(buf, stdout);
        return 0;
    }
    if (argc == 4 && strcmp(argv[1], "cost") == 0) {
        return cost_traces(core_of(argv[2]), argv[3]);
    }
    if (argc != 4 || (strcmp(argv[1], "m4f") != 0 && strcmp(argv[1], "m7") != 0 &&
                      strcmp(argv[1], "m3") != 0 && strcmp(argv[1], "m0") != 0)) {
        fprintf(stderr, "usage: check_cycle_model m4f|m7|m3|m0 HEADER.h TRACE_SUMMARY\n");
        return 2;
    }
    tf_core core = core_of(argv[1]);
    const int has_fpu = strcmp(argv[1], "m3") != 0 && strcmp(argv[1], "m0") != 0;
    if (read_header(argv[2]) != 0) {
        return 2;
    }
    FILE *f = fopen(argv[3], "r");
    if (f == NULL) {
        perror(argv[3]);
        return 2;
    }
    char line[2048];
    int fail = 0, set = 0, q31_set = 0;
    while (fgets(line, sizeof line, f) != NULL) {
        unsigned calls;
        char verdict[16], entry[64];
        unsigned long long traced_insns;
        const char *mixtext = strstr(line, "mix: ");
        if (sscanf(line, "set %*d (%63[^)]): %u calls, %15[^,], %llu", entry, &calls, verdict,
                   &traced_insns) != 4 ||
            mixtext == NULL) {
            continue;
        }
        if (strcmp(entry, "tfit_region_pair") == 0 ||
            strcmp(entry, "tfit_region_surface_pair") == 0) { /* a region header's pairs */
            int same = strcmp(verdict, "identical") == 0;
            printf("%-22s %s: %3u calls %s, %6llu instructions\n", argv[2], entry, calls,
                   same ? "same instructions" : "DIFFERENT instructions", traced_insns);
            fail |= !same;
            continue;
        }
        if (strstr(entry, "_q31") != NULL) {
            int same = strcmp(verdict, "identical") == 0;
            printf("%-22s q31 set %d: %3u inputs %s, %6llu instructions\n", argv[2], q31_set++,
                   calls, same ? "same instructions" : "DIFFERENT instructions", traced_insns);
            fail |= !same;
            continue;
        }
        if (set >= n_models) {
            printf("%s: more golden sets traced than models in the header\n", argv[2]);
            fail = 1;
            break;
        }
        const char *name = model_names[set++];
        tf_insn_mix traced, predicted;
        char t_text[512], p_text[512];
        tf_model *m = shape_of(name);
        if (m == NULL || tf_insn_mix_parse(mixtext + 5, &traced) != 0) {
            printf("%s: cannot read the model's shape or the traced mix\n", name);
            fail = 1;
            tf_model_free(m);
            continue;
        }
        tf_model_insn_mix(m, core, &predicted);
        tf_cycles c = tf_model_cycles(m, core);
        int same = memcmp(&traced, &predicted, sizeof traced) == 0;
        /* The header's own number (emit_budget.c) must be what ran. */
        const char *insns = macro(name, "INSNS_ARMV7EM");
        if (core == TF_CORE_M4F &&
            (insns == NULL || strtoull(insns, NULL, 10) != tf_insn_mix_count(&traced))) {
            printf("%s: header says %s instructions per call, the M4F executed %llu\n", name,
                   insns ? insns : "nothing", (unsigned long long)tf_insn_mix_count(&traced));
            fail = 1;
        }
        int fixed = strcmp(verdict, "identical") == 0;
        printf("%-22s %-9s %-14.14s n_out %4u: %3u inputs %s, %6llu instructions traced, model "
               "%s; %s %.0f cycles (%.0f..%.0f) = %.2f us at %.0f MHz\n",
               name, tf_family_of(m->family)->name, macro(name, "ORDERS"), m->n_out, calls,
               fixed ? "same instructions" : "DIFFERENT instructions",
               (unsigned long long)tf_insn_mix_count(&traced), same ? "exact" : "DIFFERS",
               tf_core_name(core), c.cycles, c.cycles_low, c.cycles, c.cycles / tf_core_mhz(core),
               tf_core_mhz(core));
        if (!same) {
            tf_insn_mix_format(&traced, t_text, sizeof t_text);
            tf_insn_mix_format(&predicted, p_text, sizeof p_text);
            printf("    traced: %s\n    model:  %s\n    traced - model:", t_text, p_text);
            for (int k = 0; k < TF_INSN_CLASSES; ++k) {
                if (traced.n[k] != predicted.n[k]) {
                    tf_insn_mix one = {{0}};
                    one.n[k] = 1;
                    char cls[32];
                    tf_insn_mix_format(&one, cls, sizeof cls);
                    cls[strcspn(cls, "=")] = '\0';
                    printf(" %s%+d", cls, (int)traced.n[k] - (int)predicted.n[k]);
                }
            }
            printf("\n");
        }
        fail |= !same || !fixed;
        tf_model_free(m);
    }
    fclose(f);
    int n_q31 = 0;
    for (int i = 0; i < n_models; ++i) {
        n_q31 += macro(model_names[i], "Q31_CRC32") != NULL;
    }
    if ((has_fpu && set != n_models) || q31_set != n_q31) {
        printf("%s: %d models (%d with a Q31 form); traced %d float and %d Q31 golden sets\n",
               argv[2], n_models, n_q31, set, q31_set);
        fail = 1;
    }
    return fail;
}

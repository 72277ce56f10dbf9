/*
 * trace_mix.c — the instruction mix each evaluation actually executed on the
 * device, from a QEMU execution trace of a golden-vector image.
 *
 *   trace_mix DISASSEMBLY QEMU_LOG
 *
 * DISASSEMBLY is `arm-none-eabi-objdump -d --no-show-raw-insn IMAGE`;
 * QEMU_LOG comes from qemu-system-arm -d in_asm,exec,nochain -D QEMU_LOG
 * (in_asm lists the instructions of every translated block, exec logs every
 * execution of a block, nochain makes QEMU log each one).  Every instruction
 * of every executed block is classified as in insn_mix.c (host/cost/cycles.h).
 * A conditional branch ends its block; it was taken (class branch) unless
 * the next block executed starts at the instruction after it (nbranch).
 *
 * An evaluation starts when a block at the entry of tfit_displacements,
 * tfit_displacements_cut, tfit_contact_force, tfit_prony_step,
 * tfit_resonant_step (a stateful model's tick; its reset is not counted),
 * the _q31 forms or the region entry points (tfit_region_force,
 * tfit_region_surface, tfit_region_pair, tfit_region_surface_pair) executes
 * and ends when control is back in tfit_golden_run* (or region_golden_run*,
 * tests/region/qemu_region.c's loops); a golden set starts with its
 * tfit_model_check* call (qemu_golden.c) or a call of trace_group_start
 * (qemu_region.c's traced image).  Output, one line per set:
 *   set S: N calls, identical|DIFFERENT, mix: alu=... (of the first call)
 * Exit status 1 when the calls of a set did not all execute the same mix.
 */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "cost/cycles.h"
#include "insn_class.h"

/* Code lives in the first 4 MB (mps2 SSRAM1) or, copied to fast memory, in
 * the first 4 MB at 0x20000000 (SSRAM2/3, mps2-an500.ld). */
#define WINDOW 0x400000ul
#define RAM_BASE 0x20000000ul
#define MAX_TB_INSNS 512
#define MAX_SETS 256

typedef struct site {
    signed char cls; /* -1: unknown */
    unsigned char words;
    unsigned char cond; /* a conditional branch (may fall through) */
    unsigned char size; /* bytes, from the next instruction's address (0: unknown) */
} site;

static site *sites; /* by address / 2 (Thumb), both windows */
static char funcs[4096][64];
static unsigned long func_addr[4096];
static int n_funcs;

/* Translated blocks: start address -> instruction addresses, and what the
 * start address is (classified once, at its first execution: a trace of a
 * golden image executes a few thousand blocks millions of times). */
typedef struct tb {
    unsigned long start;
    int n;
    int classified;
    const char *fn;      /* the function it lies in */
    unsigned char entry; /* an evaluation's entry point */
    unsigned char check; /* a set's start: tfit_model_check*, trace_group_start */
    unsigned long addr[MAX_TB_INSNS];
} tb;
static tb *tbs;
static int n_tbs, cap_tbs;
static int *tb_at; /* by address / 2 as sites: index into tbs + 1, 0 none */

static site *at(unsigned long addr)
{
    if (addr < WINDOW) {
        return &sites[addr / 2];
    }
    if (addr >= RAM_BASE && addr < RAM_BASE + WINDOW) {
        return &sites[(WINDOW + addr - RAM_BASE) / 2];
    }
    return NULL;
}

static void load_disassembly(const char *path)
{
    FILE *f = fopen(path, "r");
    if (f == NULL) {
        perror(path);
        exit(2);
    }
    sites = calloc(WINDOW, sizeof *sites);
    tb_at = calloc(WINDOW, sizeof *tb_at);
    if (sites == NULL || tb_at == NULL) {
        fprintf(stderr, "trace_mix: out of memory\n");
        exit(2);
    }
    for (unsigned long i = 0; i < WINDOW; ++i) {
        sites[i].cls = -1;
    }
    char line[512], name[64];
    unsigned long addr, prev_addr = 0;
    site *prev = NULL;
    int cur = -1;
    while (fgets(line, sizeof line, f) != NULL) {
        if (sscanf(line, "%lx <%63[^>]>:", &addr, name) == 2) {
            if (n_funcs < 4096) {
                cur = n_funcs++;
                snprintf(funcs[cur], sizeof funcs[cur], "%s", name);
                func_addr[cur] = addr;
            }
            prev = NULL;
            continue;
        }
        char mn[32], ops[256];
        if (cur < 0 || tf_parse_objdump_line(line, &addr, mn, sizeof mn, ops, sizeof ops) != 0) {
            continue;
        }
        site *s = at(addr);
        if (prev != NULL && addr > prev_addr && addr - prev_addr <= 4) {
            prev->size = (unsigned char)(addr - prev_addr);
        }
        prev = NULL;
        if (s != NULL && mn[0] != '.') {
            int words;
            s->cls = (signed char)tf_classify_insn(mn, ops, &words);
            s->words = (unsigned char)words;
            s->cond = (unsigned char)tf_is_conditional_branch(mn);
            prev = s;
            prev_addr = addr;
        }
    }
    fclose(f);
}

static int *tb_slot(unsigned long addr)
{
    site *s = at(addr);
    return s == NULL ? NULL : &tb_at[s - sites];
}

/* Blocks outside the code windows (none in our images) by linear search. */
static tb *find_tb(unsigned long start)
{
    const int *slot = tb_slot(start);
    if (slot != NULL) {
        return *slot == 0 ? NULL : &tbs[*slot - 1];
    }
    for (int i = n_tbs - 1; i >= 0; --i) {
        if (tbs[i].start == start) {
            return &tbs[i];
        }
    }
    return NULL;
}

/* A block translated again at the same start replaces the old one. */
static tb *new_tb(unsigned long start)
{
    tb *t = find_tb(start);
    if (t == NULL) {
        if (n_tbs == cap_tbs) {
            cap_tbs = cap_tbs ? 2 * cap_tbs : 1024;
            tbs = realloc(tbs, (size_t)cap_tbs * sizeof *tbs);
            if (tbs == NULL) {
                fprintf(stderr, "trace_mix: out of memory\n");
                exit(2);
            }
        }
        t = &tbs[n_tbs++];
        int *slot = tb_slot(start);
        if (slot != NULL) {
            *slot = n_tbs;
        }
    }
    t->start = start;
    t->n = 0;
    t->classified = 0;
    return t;
}

static const char *func_of(unsigned long addr)
{
    int best = -1;
    for (int i = 0; i < n_funcs; ++i) {
        if (func_addr[i] <= addr && (best < 0 || func_addr[i] > func_addr[best])) {
            best = i;
        }
    }
    return best < 0 ? "?" : funcs[best];
}

static int is_entry(unsigned long pc)
{
    const char *f = func_of(pc);
    for (int i = 0; i < n_funcs; ++i) {
        if (func_addr[i] == pc) {
            return strcmp(f, "tfit_displacements") == 0 || strcmp(f, "tfit_contact_force") == 0 ||
                   strcmp(f, "tfit_prony_step") == 0 || strcmp(f, "tfit_resonant_step") == 0 ||
                   strcmp(f, "tfit_displacements_cut") == 0 ||
                   strcmp(f, "tfit_displacements_q31") == 0 ||
                   strcmp(f, "tfit_contact_force_q31") == 0 ||
                   strcmp(f, "tfit_prony_step_q31") == 0 ||
                   strcmp(f, "tfit_region_force") == 0 || strcmp(f, "tfit_region_surface") == 0 ||
                   strcmp(f, "tfit_region_pair") == 0 ||
                   strcmp(f, "tfit_region_surface_pair") == 0;
        }
    }
    return 0;
}

static int starts_with(const char *s, const char *p)
{
    return strncmp(s, p, strlen(p)) == 0;
}

/* What the block starting at pc is: its function, an evaluation's entry,
 * a set's start. */
static void classify(tb *t, unsigned long pc)
{
    t->fn = func_of(pc);
    t->entry = (unsigned char)is_entry(pc);
    t->check = 0;
    for (int i = 0; i < n_funcs; ++i) {
        if (func_addr[i] == pc && (starts_with(funcs[i], "tfit_model_check") ||
                                   strcmp(funcs[i], "trace_group_start") == 0)) {
            t->check = 1;
        }
    }
    t->classified = 1;
}

typedef struct set_stats {
    unsigned calls;
    int differ;
    tf_insn_mix first;
    const char *entry;
} set_stats;

static set_stats sets[MAX_SETS];
static int n_sets = -1;

static void finish_call(const tf_insn_mix *mix, const char *entry)
{
    if (n_sets < 0 || n_sets >= MAX_SETS) {
        return;
    }
    set_stats *s = &sets[n_sets];
    if (s->calls == 0) {
        s->first = *mix;
        s->entry = entry;
    } else if (memcmp(&s->first, mix, sizeof *mix) != 0) {
        s->differ = 1;
    }
    s->calls++;
}

int main(int argc, char **argv)
{
    if (argc != 3) {
        fprintf(stderr, "usage: trace_mix DISASSEMBLY QEMU_LOG\n");
        return 2;
    }
    load_disassembly(argv[1]);
    FILE *f = fopen(argv[2], "r");
    if (f == NULL) {
        perror(argv[2]);
        return 2;
    }
    char line[512];
    tb *filling = NULL;
    int in_call = 0;
    const char *entry = "?";
    tf_insn_mix mix;
    unsigned long fallthrough = 0; /* of a conditional branch ending the last block, or 0 */
    while (fgets(line, sizeof line, f) != NULL) {
        unsigned long a, pc;
        if (strncmp(line, "IN:", 3) == 0) {
            filling = NULL;
            continue;
        }
        char *end;
        if (strncmp(line, "0x", 2) == 0 && (a = strtoul(line + 2, &end, 16), *end == ':')) {
            if (filling == NULL) {
                filling = new_tb(a);
            }
            if (filling->n < MAX_TB_INSNS) {
                filling->addr[filling->n++] = a;
            }
            continue;
        }
        filling = NULL;
        /* "Trace N: HOST [FLAGS/PC/...": the block at PC executed */
        const char *b = strncmp(line, "Trace ", 6) == 0 ? strchr(line, '[') : NULL;
        b = b != NULL ? strchr(b, '/') : NULL;
        if (b == NULL || (pc = strtoul(b + 1, &end, 16), *end != '/')) {
            continue;
        }
        if (fallthrough != 0) { /* the last block's conditional branch, now resolved */
            tf_insn_mix_add(&mix, pc == fallthrough ? TF_INSN_NBRANCH : TF_INSN_BRANCH, 0);
            fallthrough = 0;
        }
        tb *t = find_tb(pc), unlisted;
        if (t == NULL) {
            unlisted.classified = 0;
            t = &unlisted;
        }
        if (!t->classified) {
            classify(t, pc);
        }
        const char *fn = t->fn;
        if (t->check) {
            if (in_call) {
                finish_call(&mix, entry);
                in_call = 0;
            }
            ++n_sets;
            continue;
        }
        if (t->entry) {
            if (in_call) {
                finish_call(&mix, entry);
            }
            in_call = 1;
            entry = fn;
            memset(&mix, 0, sizeof mix);
        } else if (in_call && (starts_with(fn, "tfit_golden_run") ||
                               starts_with(fn, "region_golden_run"))) {
            finish_call(&mix, entry);
            in_call = 0;
        }
        if (!in_call) {
            continue;
        }
        if (t == &unlisted) {
            fprintf(stderr, "trace_mix: block at 0x%lx executed but never listed\n", pc);
            return 2;
        }
        for (int i = 0; i < t->n; ++i) {
            site *s = at(t->addr[i]);
            if (s == NULL || s->cls < 0) {
                fprintf(stderr, "trace_mix: no instruction at 0x%lx in the disassembly\n",
                        t->addr[i]);
                return 2;
            }
            if (i == t->n - 1 && s->cond) {
                if (s->size == 0) {
                    fprintf(stderr, "trace_mix: size of the branch at 0x%lx unknown\n",
                            t->addr[i]);
                    return 2;
                }
                fallthrough = t->addr[i] + s->size;
                continue;
            }
            tf_insn_mix_add(&mix, s->cls, s->words);
        }
    }
    fclose(f);
    int fail = 0;
    for (int s = 0; s <= n_sets && s < MAX_SETS; ++s) {
        char buf[512];
        tf_insn_mix_format(&sets[s].first, buf, sizeof buf);
        printf("set %d (%s): %u calls, %s, %llu instructions, mix: %s\n", s,
               sets[s].entry ? sets[s].entry : "none", sets[s].calls,
               sets[s].differ ? "DIFFERENT" : "identical",
               (unsigned long long)tf_insn_mix_count(&sets[s].first), buf);
        fail |= sets[s].differ;
    }
    return fail;
}

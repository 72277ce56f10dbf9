/*
 * insn_mix.c — the instruction mix of compiled code, from
 * `arm-none-eabi-objdump -d --no-show-raw-insn` on stdin.
 *
 * Every function is split into its loops (a conditional branch back to an
 * earlier address of the same function closes a loop; GCC rotates loops so
 * that their back edge is conditional, while an unconditional backward
 * branch is a jump to shared code such as an epilogue) and the code outside
 * them.  A backward branch over a return (pop {pc}, bx lr) is a jump to a
 * shared epilogue (or to a tail call, `b.w <other function>`), not a loop.
 * For each region it prints the instructions that belong to it and to no
 * loop nested inside, by cost class of the Cortex-M technical reference
 * manuals (host/cost/cycles.h, docs/firmware.md):
 *
 *   FUNCTION loop K depth D: class=count ...     (one per loop, by address)
 *   FUNCTION outside: class=count ...
 *
 * Multi-register transfers count one instruction plus one word per register
 * (ldm_words / fldm_words ...).  tests/firmware/check_cycle_model.sh
 * compares these lines with the mixes host/cost/cycles.c assumes.
 * usage: insn_mix [FUNCTION...]   (default: every function)
 */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "cost/cycles.h"
#include "insn_class.h"

#define MAX_INSN 4096
#define MAX_LOOPS 64

typedef struct insn {
    unsigned long addr;
    int cls;   /* tf_insn_class, or -1 for data */
    int words; /* registers moved by a multiple transfer */
    long target; /* backward-branch target inside the function, or -1 */
    int returns; /* pop {pc}, ldm {..., pc} or bx lr */
} insn;

static insn code[MAX_INSN];
static int n_code;
static char func[128];

static void print_mix(const char *label, const tf_insn_mix *mix)
{
    char buf[512];
    tf_insn_mix_format(mix, buf, sizeof buf);
    printf("%s %s: %s\n", func, label, buf);
}

static void analyse(void)
{
    int lo[MAX_LOOPS], hi[MAX_LOOPS], n_loops = 0;
    for (int i = 0; i < n_code; ++i) {
        if (code[i].target >= 0 && (unsigned long)code[i].target <= code[i].addr &&
            n_loops < MAX_LOOPS) {
            int start = 0, exits = 0;
            while (code[start].addr < (unsigned long)code[i].target) {
                ++start;
            }
            for (int k = start; k < i; ++k) {
                exits |= code[k].returns;
            }
            if (!exits) {
                lo[n_loops] = start;
                hi[n_loops++] = i;
            }
        }
    }
    /* Sort loops by start address (then outermost first). */
    for (int a = 0; a < n_loops; ++a) {
        for (int b = a + 1; b < n_loops; ++b) {
            if (lo[b] < lo[a] || (lo[b] == lo[a] && hi[b] > hi[a])) {
                int t = lo[a];
                lo[a] = lo[b];
                lo[b] = t;
                t = hi[a];
                hi[a] = hi[b];
                hi[b] = t;
            }
        }
    }
    tf_insn_mix outside = {{0}};
    tf_insn_mix own[MAX_LOOPS];
    memset(own, 0, sizeof own);
    for (int i = 0; i < n_code; ++i) {
        if (code[i].cls < 0) {
            continue;
        }
        int inner = -1; /* innermost loop holding instruction i */
        for (int l = 0; l < n_loops; ++l) {
            if (i >= lo[l] && i <= hi[l] && (inner < 0 || hi[l] - lo[l] < hi[inner] - lo[inner])) {
                inner = l;
            }
        }
        tf_insn_mix_add(inner < 0 ? &outside : &own[inner], code[i].cls, code[i].words);
    }
    for (int l = 0; l < n_loops; ++l) {
        int depth = 0;
        for (int k = 0; k < n_loops; ++k) {
            depth += k != l && lo[k] <= lo[l] && hi[k] >= hi[l];
        }
        char label[48];
        snprintf(label, sizeof label, "loop %d depth %d", l + 1, depth + 1);
        print_mix(label, &own[l]);
    }
    print_mix("outside", &outside);
}

static int wanted(int argc, char **argv)
{
    if (argc < 2) {
        return 1;
    }
    for (int i = 1; i < argc; ++i) {
        if (strcmp(argv[i], func) == 0) {
            return 1;
        }
    }
    return 0;
}

int main(int argc, char **argv)
{
    char line[512];
    int active = 0;
    while (fgets(line, sizeof line, stdin) != NULL) {
        char name[128];
        if (sscanf(line, "%*x <%127[^>]>:", name) == 1) {
            if (active) {
                analyse();
            }
            snprintf(func, sizeof func, "%s", name);
            active = wanted(argc, argv);
            n_code = 0;
            continue;
        }
        insn in = {0, -1, 0, -1, 0};
        char mn[32], ops[256];
        if (!active || n_code == MAX_INSN ||
            tf_parse_objdump_line(line, &in.addr, mn, sizeof mn, ops, sizeof ops) != 0) {
            continue;
        }
        if (mn[0] != '.') {
            in.cls = tf_classify_insn(mn, ops, &in.words);
            in.returns = in.cls == TF_INSN_LDM_PC || (strncmp(mn, "bx", 2) == 0 && strncmp(ops, "lr", 2) == 0);
            const char *lt = strchr(ops, '<');
            /* b.w <other_function>: a tail call leaves the function like a return */
            if ((strcmp(mn, "b") == 0 || strcmp(mn, "b.w") == 0 || strcmp(mn, "b.n") == 0) &&
                lt != NULL && strncmp(lt + 1, func, strlen(func)) != 0) {
                in.returns = 1;
            }
            if (tf_is_conditional_branch(mn) && lt != NULL &&
                strncmp(lt + 1, func, strlen(func)) == 0 &&
                (lt[1 + strlen(func)] == '+' || lt[1 + strlen(func)] == '>')) {
                in.target = strtol(strrchr(ops, ',') ? strrchr(ops, ',') + 1 : ops, NULL, 16);
            }
        }
        code[n_code++] = in;
    }
    if (active) {
        analyse();
    }
    return 0;
}

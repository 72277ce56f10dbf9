/*
 * insn_class.c — see insn_class.h.  Classes follow the rows of the
 * Cortex-M4 TRM instruction timing tables (docs/firmware.md).
 */
#include "insn_class.h"

#include <stdio.h>
#include <stdlib.h>
#include <string.h>

static int is_cond(const char *s)
{
    static const char *const cc[] = {"eq", "ne", "cs", "cc", "hs", "lo", "mi", "pl", "vs",
                                     "vc", "hi", "ls", "ge", "lt", "gt", "le", "al", NULL};
    for (int i = 0; cc[i] != NULL; ++i) {
        if (strcmp(s, cc[i]) == 0) {
            return 1;
        }
    }
    return 0;
}

static int starts(const char *s, const char *prefix)
{
    return strncmp(s, prefix, strlen(prefix)) == 0;
}

/* Registers in a {...} list: r0-r3 counts 4, d registers count 2 words. */
static int reg_words(const char *ops)
{
    const char *open = strchr(ops, '{'), *close = strchr(ops, '}');
    if (open == NULL || close == NULL) {
        return 1;
    }
    int n = 0;
    for (const char *p = open + 1; p < close;) {
        while (p < close && (*p == ' ' || *p == ',')) {
            ++p;
        }
        if (p >= close) {
            break;
        }
        char kind = *p;
        int a = atoi(p + 1), b = a;
        const char *dash = strchr(p, '-');
        const char *comma = strchr(p, ',');
        if (dash != NULL && dash < close && (comma == NULL || dash < comma)) {
            b = atoi(dash + 2);
        }
        n += (b - a + 1) * (kind == 'd' ? 2 : 1);
        p = (comma != NULL && comma < close) ? comma + 1 : close;
    }
    return n;
}

/* Mnemonic without the .w/.n width and the .f32/.f64 type suffixes. */
static void base_mnemonic(const char *m, char *out, size_t n)
{
    snprintf(out, n, "%s", m);
    char *dot = strchr(out, '.');
    if (dot != NULL) {
        *dot = '\0';
    }
}

int tf_classify_insn(const char *mn, const char *ops, int *words)
{
    char b[32];
    base_mnemonic(mn, b, sizeof b);
    *words = 0;
    size_t len = strlen(b);
    if (strcmp(b, "b") == 0 || strcmp(b, "bl") == 0 || strcmp(b, "bx") == 0 ||
        strcmp(b, "blx") == 0 || strcmp(b, "cbz") == 0 || strcmp(b, "cbnz") == 0 ||
        (len == 3 && b[0] == 'b' && is_cond(b + 1))) {
        return TF_INSN_BRANCH;
    }
    if (strcmp(b, "pop") == 0 || starts(b, "ldm")) {
        *words = reg_words(ops);
        return strstr(ops, "pc") != NULL ? TF_INSN_LDM_PC : TF_INSN_LDM;
    }
    if (strcmp(b, "push") == 0 || starts(b, "stm")) {
        *words = reg_words(ops);
        return TF_INSN_STM;
    }
    if (strcmp(b, "ldrd") == 0) {
        *words = 2;
        return TF_INSN_LDM;
    }
    if (strcmp(b, "strd") == 0) {
        *words = 2;
        return TF_INSN_STM;
    }
    if (starts(b, "ldr")) {
        return TF_INSN_LOAD;
    }
    if (starts(b, "str")) {
        return TF_INSN_STORE;
    }
    if (strcmp(b, "vldr") == 0) {
        return TF_INSN_FLOAD;
    }
    if (strcmp(b, "vstr") == 0) {
        return TF_INSN_FSTORE;
    }
    if (starts(b, "vldm") || strcmp(b, "vpop") == 0) {
        *words = reg_words(ops);
        return TF_INSN_FLDM;
    }
    if (starts(b, "vstm") || strcmp(b, "vpush") == 0) {
        *words = reg_words(ops);
        return TF_INSN_FSTM;
    }
    if (strcmp(b, "vadd") == 0 || strcmp(b, "vsub") == 0) {
        return TF_INSN_FADD;
    }
    if (strcmp(b, "vmul") == 0 || strcmp(b, "vnmul") == 0) {
        return TF_INSN_FMUL;
    }
    if (strcmp(b, "vdiv") == 0 || strcmp(b, "vsqrt") == 0) {
        return TF_INSN_FDIV;
    }
    if (strcmp(b, "vmla") == 0 || strcmp(b, "vmls") == 0 || starts(b, "vfm") ||
        starts(b, "vfnm") || starts(b, "vnml")) {
        return TF_INSN_FMAC;
    }
    if (strcmp(b, "vmrs") == 0 || strcmp(b, "vmsr") == 0 ||
        (strcmp(b, "vmov") == 0 && (ops[0] == 'r' || ops[0] == 'i' || ops[0] == 'l' ||
                                    ops[0] == 'f' || strstr(ops, ", r") || strstr(ops, ", i") ||
                                    strstr(ops, ", l") || strstr(ops, ", f")))) {
        return TF_INSN_FMOV; /* between core and FPU registers */
    }
    if (b[0] == 'v') {
        return TF_INSN_FOTHER; /* vcmp, vcvt, vabs, vneg, vmov s, s / #imm */
    }
    if (strcmp(b, "mla") == 0 || strcmp(b, "mls") == 0) {
        return TF_INSN_MLA;
    }
    if (starts(b, "mul") || strcmp(b, "umull") == 0 || strcmp(b, "smull") == 0 ||
        strcmp(b, "umlal") == 0 || strcmp(b, "smlal") == 0) {
        return TF_INSN_MUL;
    }
    if (strcmp(b, "sdiv") == 0 || strcmp(b, "udiv") == 0) {
        return TF_INSN_DIV;
    }
    return TF_INSN_ALU;
}

int tf_is_conditional_branch(const char *mnemonic)
{
    char b[32];
    base_mnemonic(mnemonic, b, sizeof b);
    return (strlen(b) == 3 && b[0] == 'b' && is_cond(b + 1) && strcmp(b, "bal") != 0) ||
           strcmp(b, "cbz") == 0 || strcmp(b, "cbnz") == 0;
}

int tf_parse_objdump_line(const char *line, unsigned long *addr, char *mn, size_t mn_len,
                          char *ops, size_t ops_len)
{
    const char *t1 = strchr(line, '\t');
    const char *colon = strchr(line, ':');
    if (t1 == NULL || colon == NULL || colon > t1) {
        return -1;
    }
    char *end;
    *addr = strtoul(line, &end, 16);
    if (end == line || end != colon) {
        return -1;
    }
    const char *t2 = strchr(t1 + 1, '\t');
    size_t len = t2 ? (size_t)(t2 - t1 - 1) : strcspn(t1 + 1, "\n");
    snprintf(mn, mn_len, "%.*s", (int)len, t1 + 1);
    ops[0] = '\0';
    if (t2 != NULL) {
        snprintf(ops, ops_len, "%s", t2 + 1);
        ops[strcspn(ops, "\n")] = '\0';
    }
    return mn[0] == '\0' || mn[0] == ' ' ? -1 : 0;
}

void tf_insn_mix_add(tf_insn_mix *mix, int cls, int words)
{
    mix->n[cls] += 1;
    if (cls == TF_INSN_LDM || cls == TF_INSN_LDM_PC || cls == TF_INSN_STM) {
        mix->n[TF_INSN_WORDS] += (unsigned)words;
    } else if (cls == TF_INSN_FLDM || cls == TF_INSN_FSTM) {
        mix->n[TF_INSN_FWORDS] += (unsigned)words;
    }
}

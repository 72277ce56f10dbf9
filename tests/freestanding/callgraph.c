/*
 * callgraph.c — reads `arm-none-eabi-objdump -d` of a fully linked image on
 * stdin and proves the code has no recursion and no indirect calls: it
 * collects every direct call or tail branch from one function to the start
 * of another, rejects indirect calls (blx rN, bx rN other than lr, ldr pc
 * / pop {pc} excluded as returns), and searches the call graph for a cycle.
 * Prints the graph's edges and exits 1 on a cycle or an indirect call.
 *
 * An argument FUNC=T1,T2,... declares the targets of FUNC's indirect calls
 * (a const table of functions, e.g. the modal rows by rank): FUNC's
 * indirect calls are then accepted, an edge FUNC -> Ti is added for each
 * target so that the search for a cycle still covers them, and every Ti
 * must be defined in the image.
 */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#define MAX_FUNCS 512
#define MAX_EDGES 4096

static char names[MAX_FUNCS][96];
static int n_funcs;
static int edge_from[MAX_EDGES], edge_to[MAX_EDGES], n_edges;
static int defined[MAX_FUNCS];

/* The declaration of FUNC among argv's FUNC=T1,T2,..., or NULL. */
static const char *declared_targets(int argc, char **argv, const char *func)
{
    size_t n = strlen(func);
    for (int i = 1; i < argc; ++i) {
        if (strncmp(argv[i], func, n) == 0 && argv[i][n] == '=') {
            return argv[i] + n + 1;
        }
    }
    return NULL;
}

/* Edges func -> each declared target. */
static void add_declared(const char *func, const char *targets);

static int func_id(const char *name)
{
    for (int i = 0; i < n_funcs; ++i) {
        if (strcmp(names[i], name) == 0) {
            return i;
        }
    }
    if (n_funcs == MAX_FUNCS) {
        fprintf(stderr, "callgraph: too many functions\n");
        exit(2);
    }
    snprintf(names[n_funcs], sizeof names[0], "%s", name);
    return n_funcs++;
}

static void add_edge(int from, int to)
{
    for (int i = 0; i < n_edges; ++i) {
        if (edge_from[i] == from && edge_to[i] == to) {
            return;
        }
    }
    if (n_edges == MAX_EDGES) {
        fprintf(stderr, "callgraph: too many edges\n");
        exit(2);
    }
    edge_from[n_edges] = from;
    edge_to[n_edges++] = to;
}

/* 0 unvisited, 1 on the DFS stack, 2 done.  Iterative DFS (no recursion
 * here either). */
static int has_cycle(void)
{
    static int state[MAX_FUNCS], stack[MAX_FUNCS], next_edge[MAX_FUNCS];
    for (int root = 0; root < n_funcs; ++root) {
        if (state[root] != 0) {
            continue;
        }
        int top = 0;
        stack[0] = root;
        state[root] = 1;
        next_edge[0] = 0;
        while (top >= 0) {
            int f = stack[top], e = next_edge[top]++;
            while (e < n_edges && edge_from[e] != f) {
                e = next_edge[top]++;
            }
            if (e >= n_edges) {
                state[f] = 2;
                --top;
                continue;
            }
            int g = edge_to[e];
            if (state[g] == 1) {
                printf("cycle through %s -> %s\n", names[f], names[g]);
                return 1;
            }
            if (state[g] == 0) {
                state[g] = 1;
                stack[++top] = g;
                next_edge[top] = 0;
            }
        }
    }
    return 0;
}

static void add_declared(const char *func, const char *targets)
{
    char list[1024], *save = NULL;
    snprintf(list, sizeof list, "%s", targets);
    for (char *t = strtok_r(list, ",", &save); t != NULL; t = strtok_r(NULL, ",", &save)) {
        add_edge(func_id(func), func_id(t));
    }
}

int main(int argc, char **argv)
{
    char line[512], current[96] = "";
    int indirect = 0;
    while (fgets(line, sizeof line, stdin) != NULL) {
        char name[96];
        /* function header: "00000010 <tfit_basis>:" */
        if (sscanf(line, "%*x <%95[^>]>:", name) == 1) {
            snprintf(current, sizeof current, "%s", name);
            defined[func_id(current)] = 1;
            continue;
        }
        if (current[0] == '\0' || strchr(line, '\t') == NULL) {
            continue;
        }
        char *insn = strchr(strchr(line, '\t') + 1, '\t');
        if (insn == NULL) {
            continue;
        }
        ++insn;
        if (strncmp(insn, "blx\tr", 5) == 0 ||
            (strncmp(insn, "bx\tr", 4) == 0) || strncmp(insn, "blx\tip", 6) == 0) {
            const char *targets = declared_targets(argc, argv, current);
            if (targets != NULL) {
                add_declared(current, targets);
            } else {
                printf("indirect call in %s: %s", current, insn);
                indirect = 1;
            }
            continue;
        }
        int is_branch = insn[0] == 'b' && strchr("\t.lneglhcvmp", insn[1]) != NULL;
        const char *lt = strchr(insn, '<');
        if (!is_branch || lt == NULL || sscanf(lt, "<%95[^>]>", name) != 1) {
            continue;
        }
        if (strchr(name, '+') != NULL || strcmp(name, current) == 0) {
            continue; /* a branch inside a function */
        }
        add_edge(func_id(current), func_id(name));
    }
    for (int i = 0; i < n_edges; ++i) {
        printf("  %s -> %s\n", names[edge_from[i]], names[edge_to[i]]);
    }
    for (int i = 0; i < n_funcs; ++i) { /* a declared target must exist */
        if (!defined[i]) {
            for (int e = 0; e < n_edges; ++e) {
                if (edge_to[e] == i && declared_targets(argc, argv, names[edge_from[e]]) != NULL) {
                    printf("declared indirect target %s is not in the image\n", names[i]);
                    indirect = 1;
                    break;
                }
            }
        }
    }
    int cycle = has_cycle();
    printf("%d functions, %d call edges: %s, %s\n", n_funcs, n_edges,
           cycle ? "RECURSION FOUND" : "no recursion",
           indirect ? "INDIRECT CALLS FOUND" : "no indirect calls");
    return (cycle || indirect) ? 1 : 0;
}

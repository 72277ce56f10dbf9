/*
 * rename_fault.c — an LD_PRELOAD library that interrupts the tool at a
 * chosen point of writing its outputs:
 *
 *   TF_RENAME_FAULT=N:SIG   raises signal SIG just before the N-th call of
 *                           rename(2) in the process;
 *   TF_MKSTEMP_FAULT=N:SIG  raises SIG just after the N-th call of
 *                           mkstemp(3), when that temporary exists;
 *   TF_MKSTEMP_KILL=N:SIG   the same, but sent to the process (kill(2), as
 *                           a shell or a terminal sends it), not to the
 *                           calling thread: the kernel hands it to any
 *                           thread that does not block it.
 *
 * (The tool re-executes itself once to pin OpenBLAS; the counts start in
 * each process image.)  With SIGKILL at the second rename of `tissuefit
 * fit`, the golden file has been replaced and the header not: the state a
 * crash between the two renames leaves.
 */
#define _GNU_SOURCE
#include <dlfcn.h>
#include <signal.h>
#include <stdio.h>
#include <stdlib.h>
#include <unistd.h>

/* Raises the signal of the spec in variable var at the at-th call (to the
 * calling thread, or to the process when process is set). */
static void maybe_raise(const char *var, int *calls, int process)
{
    const char *spec = getenv(var);
    int at = 0, sig = 0;
    if (spec != NULL && sscanf(spec, "%d:%d", &at, &sig) == 2 && ++*calls == at) {
        if (process) {
            kill(getpid(), sig);
        } else {
            raise(sig);
        }
    }
}

int rename(const char *from, const char *to)
{
    static int calls;
    maybe_raise("TF_RENAME_FAULT", &calls, 0);
    int (*real)(const char *, const char *) =
        (int (*)(const char *, const char *))dlsym(RTLD_NEXT, "rename");
    return real(from, to);
}

int mkstemp(char *tmpl)
{
    static int calls;
    int (*real)(char *) = (int (*)(char *))dlsym(RTLD_NEXT, "mkstemp");
    static int killed;
    int fd = real(tmpl);
    maybe_raise("TF_MKSTEMP_FAULT", &calls, 0);
    maybe_raise("TF_MKSTEMP_KILL", &killed, 1);
    return fd;
}

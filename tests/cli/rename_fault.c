/*
 * rename_fault.c — an LD_PRELOAD library that interrupts the tool at a
 * chosen rename: TF_RENAME_FAULT=N:SIG raises signal SIG just before the
 * N-th call of rename(2) in the process (the tool re-executes itself once
 * to pin OpenBLAS; the count starts in each process image).  With SIGKILL at
 * the second rename of `tissuefit fit`, the golden file has been replaced
 * and the header not: the state a crash between the two renames leaves.
 */
#define _GNU_SOURCE
#include <dlfcn.h>
#include <signal.h>
#include <stdio.h>
#include <stdlib.h>

int rename(const char *from, const char *to)
{
    static int calls;
    const char *spec = getenv("TF_RENAME_FAULT");
    int at = 0, sig = 0;
    if (spec != NULL && sscanf(spec, "%d:%d", &at, &sig) == 2 && ++calls == at) {
        raise(sig);
    }
    int (*real)(const char *, const char *) =
        (int (*)(const char *, const char *))dlsym(RTLD_NEXT, "rename");
    return real(from, to);
}

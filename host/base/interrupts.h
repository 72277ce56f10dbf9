/*
 * interrupts.h — SIGINT, SIGTERM and SIGHUP held back while the tool writes
 * its outputs, in a process with threads.
 *
 * A signal sent to a process (by a shell, a terminal or kill(1)) goes to
 * any thread that does not block it, and a thread's signal mask covers that
 * thread only: the OpenMP workers of a fit, started with the signals
 * unblocked, took them while the main thread held them back, and the run
 * died with its temporary files beside the outputs.  So a program that
 * writes outputs starts the watch first thing in main, before any other
 * thread exists: the three signals are blocked in the first thread (every
 * thread created after inherits the mask) and one watcher thread takes
 * them with sigwait(2).  With no output open it ends the process as the
 * signal's default action would; while outputs are open (between
 * tf_interrupts_hold and the matching tf_interrupts_release: atomic_file.c)
 * it keeps the signal, and the last release ends the process with it.
 *
 * The state is the caller's (cli/main.c keeps one for the run, reached
 * through tf_ctx.interrupts), as the context is.
 */
#ifndef TF_INTERRUPTS_H
#define TF_INTERRUPTS_H

#include <pthread.h>

typedef struct tf_interrupts {
    pthread_mutex_t lock;
    unsigned held; /* outputs open */
    int pending;   /* a signal taken while held; 0: none */
} tf_interrupts;

/* Blocks SIGINT, SIGTERM and SIGHUP in the calling thread and starts the
 * watcher.  Call before any other thread starts.  Returns 0, or -1 (no
 * watcher: the mask is restored, and outputs fall back to holding the
 * signals in the writing thread only). */
int tf_interrupts_start(tf_interrupts *g);

/* In a child between fork and exec: unblocks the watched signals, which
 * the child inherited blocked and exec would keep blocked, so that the
 * program it runs (a compiler) ends by them as their default action says
 * when the terminal interrupts the tool's process group.  Only
 * async-signal-safe calls (sigprocmask). */
void tf_interrupts_child(void);

/* An output is open / is renamed or removed.  A release that closes the
 * last open output while a signal is pending ends the process by it. */
void tf_interrupts_hold(tf_interrupts *g);
void tf_interrupts_release(tf_interrupts *g);

#endif /* TF_INTERRUPTS_H */

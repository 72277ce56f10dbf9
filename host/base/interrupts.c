/*
 * interrupts.c — a watcher thread for SIGINT, SIGTERM and SIGHUP
 * (interrupts.h).
 */
#include "base/interrupts.h"

#include <signal.h>
#include <string.h>

static void watched(sigset_t *set)
{
    sigemptyset(set);
    sigaddset(set, SIGINT);
    sigaddset(set, SIGTERM);
    sigaddset(set, SIGHUP);
}

/* Ends the process as the signal's default action does (the exit status a
 * shell reports as 128 + sig): the action reset, the signal unblocked in
 * this thread and raised in it. */
static void end_by(int sig)
{
    sigset_t one;
    signal(sig, SIG_DFL);
    sigemptyset(&one);
    sigaddset(&one, sig);
    pthread_sigmask(SIG_UNBLOCK, &one, NULL);
    raise(sig);
}

static void *watch(void *arg)
{
    tf_interrupts *g = arg;
    sigset_t set;
    watched(&set);
    for (;;) {
        int sig;
        if (sigwait(&set, &sig) != 0) {
            continue;
        }
        pthread_mutex_lock(&g->lock);
        if (g->held == 0) {
            end_by(sig); /* under the lock: no output opens meanwhile */
        }
        if (g->pending == 0) {
            g->pending = sig;
        }
        pthread_mutex_unlock(&g->lock);
    }
    return NULL;
}

void tf_interrupts_child(void)
{
    sigset_t set;
    watched(&set);
    sigprocmask(SIG_UNBLOCK, &set, NULL);
}

int tf_interrupts_start(tf_interrupts *g)
{
    sigset_t set, before;
    memset(g, 0, sizeof *g);
    if (pthread_mutex_init(&g->lock, NULL) != 0) {
        return -1;
    }
    watched(&set);
    pthread_sigmask(SIG_BLOCK, &set, &before);
    pthread_t t;
    pthread_attr_t attr;
    int rc = pthread_attr_init(&attr);
    rc = rc == 0 ? pthread_attr_setdetachstate(&attr, PTHREAD_CREATE_DETACHED) : rc;
    rc = rc == 0 ? pthread_create(&t, &attr, watch, g) : rc;
    pthread_attr_destroy(&attr);
    if (rc != 0) {
        pthread_sigmask(SIG_SETMASK, &before, NULL);
        pthread_mutex_destroy(&g->lock);
        return -1;
    }
    return 0;
}

void tf_interrupts_hold(tf_interrupts *g)
{
    pthread_mutex_lock(&g->lock);
    g->held++;
    pthread_mutex_unlock(&g->lock);
}

/* A watched signal pending for the calling thread (sent to it alone, as
 * raise(3) does: the watcher's sigwait never sees it), or 0. */
static int pending_here(void)
{
    static const int sigs[3] = {SIGINT, SIGTERM, SIGHUP};
    sigset_t p;
    if (sigpending(&p) != 0) {
        return 0;
    }
    for (int i = 0; i < 3; ++i) {
        if (sigismember(&p, sigs[i])) {
            return sigs[i];
        }
    }
    return 0;
}

void tf_interrupts_release(tf_interrupts *g)
{
    pthread_mutex_lock(&g->lock);
    if (g->held > 0) {
        g->held--;
    }
    int sig = g->held == 0 ? (g->pending ? g->pending : pending_here()) : 0;
    if (sig != 0) {
        end_by(sig);
    }
    pthread_mutex_unlock(&g->lock);
}

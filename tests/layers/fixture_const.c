/*
 * fixture_const.c — what check_globals.sh must accept: constant tables,
 * one of them of pointers (which the compiler places in .data.rel.ro), and
 * an OpenMP named critical section (its lock belongs to the runtime).
 */
#include <stddef.h>

const char *tf_fixture_name(size_t i);
int tf_fixture_sum(const int *v, int n);

static const char *const names[] = {"nodal", "modal", "contact"};
static const int weights[3] = {1, 2, 3};

const char *tf_fixture_name(size_t i)
{
    return i < 3 ? names[i] : NULL;
}

int tf_fixture_sum(const int *v, int n)
{
    int s = 0;
#pragma omp parallel for
    for (int i = 0; i < n; ++i) {
#pragma omp critical(tf_fixture)
        s += v[i] * weights[i % 3];
    }
    return s;
}

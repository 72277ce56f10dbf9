/*
 * peak_memory.c — peak resident memory (peak_memory.h).
 */
#include "base/peak_memory.h"

#include <sys/resource.h>

double tf_peak_mib(void)
{
    struct rusage ru;
    if (getrusage(RUSAGE_SELF, &ru) != 0) {
        return 0;
    }
    return (double)ru.ru_maxrss / 1024.0; /* Linux: kilobytes */
}

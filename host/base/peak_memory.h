/*
 * peak_memory.h — how much memory this process has used at most.
 */
#ifndef TF_PEAK_MEMORY_H
#define TF_PEAK_MEMORY_H

/* Peak resident memory of this process, MiB (0 when unknown). */
double tf_peak_mib(void);

#endif /* TF_PEAK_MEMORY_H */

/*
 * bench_time.h — the clock and the median for the LM benchmarks
 * (bench_gsl.c, bench_mgh_gsl.c).
 */
#ifndef TF_BENCH_TIME_H
#define TF_BENCH_TIME_H

/* Seconds on the monotonic clock. */
double bench_now(void);

/* Median of v[0..n-1] (sorts v). */
double bench_median(double *v, int n);

#endif /* TF_BENCH_TIME_H */

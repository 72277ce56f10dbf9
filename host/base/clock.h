/*
 * clock.h — monotonic wall time for progress lines and the timing splits
 * reports and benches print (never asserted in tests).
 */
#ifndef TF_CLOCK_H
#define TF_CLOCK_H

/* Seconds on the monotonic clock (an arbitrary origin: take differences). */
double tf_seconds(void);

#endif /* TF_CLOCK_H */

/*
 * assert_close.h — cmocka assertion for doubles (cmocka 1.1 compares only
 * floats): fails, printing both values, unless |a - b| <= tol.
 */
#ifndef TF_ASSERT_CLOSE_H
#define TF_ASSERT_CLOSE_H

#include <math.h>

#define assert_close(a, b, tol)                                                             \
    do {                                                                                    \
        double a_ = (a), b_ = (b), t_ = (tol);                                              \
        if (!(fabs(a_ - b_) <= t_)) {                                                       \
            print_error("%s = %.17g, %s = %.17g: differ by %.3g > %.3g\n", #a, a_, #b, b_,  \
                        fabs(a_ - b_), t_);                                                 \
            fail();                                                                         \
        }                                                                                   \
    } while (0)

#endif /* TF_ASSERT_CLOSE_H */

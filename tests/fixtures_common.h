/* fixtures_common.h -- helpers the element suites share (after
   test_util.h and the header under test, which brings vlbe_real).
   -- part of vlbe                                  SPDX-License-Identifier: MIT */
#ifndef VLBE_TEST_FIXTURES_COMMON_H
#define VLBE_TEST_FIXTURES_COMMON_H

/* u^T M u in double (M n x n, row-major); *absum = sum of |terms| (the
   rounding scale) when absum != NULL */
static inline double quad_form(int n, const vlbe_real *M, const double *u, double *absum)
{
    double s = 0.0, a = 0.0;
    int i, j;
    for (i = 0; i < n; ++i)
        for (j = 0; j < n; ++j) {
            const double t = u[i] * (double)M[i * n + j] * u[j];
            s += t;
            a += fabs(t);
        }
    if (absum) *absum = a;
    return s;
}

#endif /* VLBE_TEST_FIXTURES_COMMON_H */

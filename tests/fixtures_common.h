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

/* a[i] = v, i < n */
static inline void fill(int n, vlbe_real v, vlbe_real *a)
{
    int i;
    for (i = 0; i < n; ++i) a[i] = v;
}

/* every a[i] == v exactly (e.g. an output left untouched) */
static inline void assert_all_equal(int n, const vlbe_real *a, vlbe_real v)
{
    int i;
    for (i = 0; i < n; ++i) ASSERT_CLOSE_CTX(a[i], v, 0, 0, "entry %d", i);
}

#endif /* VLBE_TEST_FIXTURES_COMMON_H */

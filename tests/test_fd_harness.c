/* test_fd_harness.c -- the finite-difference Jacobian harness itself
   (tests/fd_harness.h): each entry is checked at the scale of its own row
   and column, so a wrong small block no longer hides behind the largest
   entry of the matrix.
   -- part of vlbe                                  SPDX-License-Identifier: MIT
   cc -std=c99 -Wall -Wextra -Wpedantic ... -O2 tests/test_fd_harness.c -lcmocka -lm
   (add -DVLBE_USE_FLOAT for the float build; the same source passes in both)

   Tests
     small_block   a map R^4 -> R^4 with a block of O(1) derivatives (rows
                   and columns 0, 1) and one of size a = 4 FD (rows and
                   columns 2, 3; FD = EPS^(2/3), the relative error of a
                   central difference), every output at most quadratic
                   (the differences are exact but for rounding), at a state
                   of size 1e-3 (outputs ~1e-3: the rounding term small).
                   With tolerance 64 FD as the element suites use:
                   - the exact Jacobian passes (fd_compare <= 1);
                   - a small-block entry 50 % off, and the small block
                     wrongly zero, fail at their own scale while the
                     whole-matrix criterion |Jfd - J| <= 64 FD max|J| (the
                     harness before) passes them (errors 1-4 FD, the zero
                     block's up to 8 FD; own-scale ratios from
                     16 (m~:own_min) to 125 (m~:own_max), whole-matrix
                     0.008 (m~:whole_min) to 0.063 (m~:whole_max));
                   - a large entry off by 1e3 FD fails both ways;
                   - no entry's tolerance exceeds the whole-matrix one
                     (fd_compare's ratio >= the whole-matrix ratio). */
#include "test_util.h"
#include "../vlbe.h"
#include "fd_harness.h"

#define EPS ((double)VLBE_EPS)
#define FD_ERR (cbrt(EPS) * cbrt(EPS))

/* the small block's size, in units where the large one is O(1) */
static double small_a(void) { return 4.0 * FD_ERR; }

/* out = f(q): rows 0, 1 of O(1), rows 2, 3 of size a in x2, x3 only */
static double map_eval(const fd_ctx *c, const vlbe_real *q, const vlbe_real *qd, double *out)
{
    const double a = small_a(), x0 = (double)q[0], x1 = (double)q[1], x2 = (double)q[2],
                 x3 = (double)q[3];
    (void)c;
    (void)qd;
    out[0] = 2.0 * x0 - x1 + 3.0 * x0 * x1;
    out[1] = x0 + 1.5 * x1 - x1 * x1;
    out[2] = a * (x2 + 2.0 * x3 + x2 * x3);
    out[3] = a * (-x2 + 0.5 * x3 + x3 * x3);
    return fmax(fmax(fabs(out[0]), fabs(out[1])), fmax(fabs(out[2]), fabs(out[3])));
}

/* the analytic Jacobian at q */
static void map_jac(const vlbe_real *q, vlbe_real *J)
{
    const double a = small_a(), x0 = (double)q[0], x1 = (double)q[1], x2 = (double)q[2],
                 x3 = (double)q[3];
    double Jd[16] = {0.0};
    int i;
    Jd[0] = 2.0 + 3.0 * x1;
    Jd[1] = -1.0 + 3.0 * x0;
    Jd[4] = 1.0;
    Jd[5] = 1.5 - 2.0 * x1;
    Jd[10] = a * (1.0 + x3);
    Jd[11] = a * (2.0 + x2);
    Jd[14] = -a;
    Jd[15] = a * (0.5 + 2.0 * x3);
    for (i = 0; i < 16; ++i) J[i] = (vlbe_real)Jd[i];
}

/* the whole-matrix criterion of the harness before: max |Jfd - J| over
   (rel max(|J|, |Jfd|)) */
static double whole_ratio(const vlbe_real *J, const double *Jfd, double rel)
{
    double e = 0.0, s = 0.0;
    int i;
    for (i = 0; i < 16; ++i) {
        e = fmax(e, fabs(Jfd[i] - (double)J[i]));
        s = fmax(s, fmax(fabs((double)J[i]), fabs(Jfd[i])));
    }
    return e / (rel * s);
}

static void test_small_block(void **state)
{
    const double rel = 64.0 * FD_ERR;
    const vlbe_real q0[4] = {VLBE_R(1e-3), VLBE_R(-2e-3), VLBE_R(1.5e-3), VLBE_R(0.7e-3)};
    fd_ctx c;
    vlbe_real J[16], Jb[16];
    double Jfd[16], r, w, own_min = HUGE_VAL, own_max = 0.0, whole_min = HUGE_VAL, whole_max = 0.0;
    fd_stats st;
    int k, i;
    (void)state;
    fd_init(&c, 4, map_eval, NULL, 0);
    memcpy(c.q, q0, sizeof q0);
    map_jac(q0, J);
    /* exact */
    r = fd_compare(&c, J, NULL, NULL, rel, 0.0, Jfd, &st);
    w = whole_ratio(J, Jfd, rel);
    tu_report("exact Jacobian, own scale", r, 1.0);
    assert_true(r <= 1.0);
    assert_true(r >= w);
    (void)fd_check(&c, J, NULL, NULL, rel, 0.0, "exact", NULL);
    /* one small-block entry at a time 50 % off, then the block zero */
    for (k = 0; k < 5; ++k) {
        static const int ent[4] = {10, 11, 14, 15};
        memcpy(Jb, J, sizeof Jb);
        if (k < 4)
            Jb[ent[k]] = (vlbe_real)(1.5 * (double)J[ent[k]]);
        else
            for (i = 0; i < 4; ++i) Jb[ent[i]] = VLBE_R(0.0);
        r = fd_compare(&c, Jb, NULL, NULL, rel, 0.0, Jfd, &st);
        w = whole_ratio(Jb, Jfd, rel);
        if (tu_report_on())
            print_message("    small block %s: own scale %.3g, whole matrix %.3g (entry %d, %d)\n",
                          k < 4 ? "entry 50 % off" : "zero", r, w, st.i, st.j);
        own_min = fmin(own_min, r), own_max = fmax(own_max, r);
        whole_min = fmin(whole_min, w), whole_max = fmax(whole_max, w);
        assert_true(w <= 1.0); /* the whole-matrix check let it pass */
        assert_true(r > 1.0);  /* at its own scale it fails */
        assert_true(st.i >= 2 && st.j >= 2);
        assert_true(r >= w);
    }
    tu_measured("own_min", own_min);
    tu_measured("own_max", own_max);
    tu_measured("whole_min", whole_min);
    tu_measured("whole_max", whole_max);
    /* a large entry off by 1e3 FD (relative): both fail */
    memcpy(Jb, J, sizeof Jb);
    Jb[1] = (vlbe_real)((double)J[1] * (1.0 + 1e3 * FD_ERR));
    r = fd_compare(&c, Jb, NULL, NULL, rel, 0.0, Jfd, &st);
    w = whole_ratio(Jb, Jfd, rel);
    assert_true(w > 1.0);
    assert_true(r > 1.0);
    assert_true(r >= w);
    assert_int_equal(st.i, 0);
    assert_int_equal(st.j, 1);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_small_block),
    };
    return cmocka_run_group_tests_name("fd_harness", tests, NULL, NULL);
}

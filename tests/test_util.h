/* test_util.h -- helpers shared by the cmocka suites of vlbe
   -- part of vlbe                                 SPDX-License-Identifier: MIT

   Include it first in a suite, then the header under test:
       #include "test_util.h"
       #include "../ancf_ale.h"
   It does not depend on vlbe.h: everything here works in double precision,
   whatever vlbe_real is, so the same assertions serve the double and the
   -DVLBE_USE_FLOAT builds (the tolerances passed in carry the precision).

   ASSERT_CLOSE(a, b, rtol, atol)         |a - b| <= atol + rtol |b|
   ASSERT_VEC_CLOSE(a, b, n, rtol, atol)  the same for a[i], b[i], i < n;
                                          reports the worst index
   ASSERT_CLOSE_CTX(a, b, rtol, atol, fmt, ...)  ASSERT_CLOSE that first prints
                                          a context line (printf-style) if it fails
   tu_err_ratio(a, b, rtol, atol)         |a - b| / (atol + rtol |b|)
   tu_rng, tu_rng_seed, tu_rng_uniform    deterministic LCG, uniform [-1, 1)
   tu_fd_step(eps, scale)                 central-difference step scale*eps^(1/3)
   tu_central_diff(f, ctx, x, h, n, work, d)   d = (f(x+h) - f(x-h)) / step
   tu_max_abs(n, a)                       max |a_i| of a double array
   tu_report_on(), tu_report(name, err, tol)   with VLBE_TEST_REPORT set, print
                                          each measured error beside its tolerance
   tu_measured(key, value)                with VLBE_TEST_REPORT set, print the line
                                          "MEASURED key value" that tests/measured.sh
                                          checks against the comment tag (m:key)
   TU_SKIP(reason)                        mark the running test skipped (cmocka's
                                          skip()), printing why; counted apart
   tu_slow_run()                          1 in slow builds (-O0, sanitizers,
                                          valgrind, VLBE_TEST_QUICK): shorter runs

   NaN never passes a check.  Equal values (infinities included) always
   pass, so rtol = atol = 0 asks for bitwise-equal results (up to the sign
   of zero).  cmocka 1.1.5's assert_float_equal casts to float and is not
   used for doubles anywhere in vlbe's tests. */
#ifndef VLBE_TEST_UTIL_H
#define VLBE_TEST_UTIL_H

/* cmocka.h needs these four first, in this order */
#include <stdarg.h>
#include <stddef.h>
#include <setjmp.h>
#include <stdint.h>
#include <cmocka.h>

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

/* -- closeness ---------------------------------------------------------- */
/* |a - b| / (atol + rtol |b|): <= 1 means close.  Equal values give 0 (also
   for a zero tolerance and for equal infinities); NaN gives NaN, which
   every check below treats as a failure. */
static inline double tu_err_ratio(double a, double b, double rtol, double atol)
{
    double err, tol;
    if (a == b) return 0.0;
    err = fabs(a - b);
    tol = atol + rtol * fabs(b);
    if (tol > 0.0) return err / tol;
    return err == err ? HUGE_VAL : err; /* zero tolerance: any difference fails */
}

/* Scalar check: b is the reference value. */
#define ASSERT_CLOSE(a, b, rtol, atol)                                                   \
    do {                                                                                 \
        const double tu_ca_ = (double)(a), tu_cb_ = (double)(b);                         \
        const double tu_cr_ = tu_err_ratio(tu_ca_, tu_cb_, (double)(rtol), (double)(atol)); \
        if (!(tu_cr_ <= 1.0))                                                            \
            fail_msg("%s = %.17g, %s = %.17g: |a-b|/(atol+rtol|b|) = %.3g > 1 "         \
                     "(rtol %.3g, atol %.3g)",                                           \
                     #a, tu_ca_, #b, tu_cb_, tu_cr_, (double)(rtol), (double)(atol));    \
    } while (0)

/* ASSERT_CLOSE for checks made in loops: when the check fails, the context
   (a printf format and its arguments, e.g. the loop indices) is printed
   before the failure message.  a and b are evaluated twice. */
#define ASSERT_CLOSE_CTX(a, b, rtol, atol, ...)                                          \
    do {                                                                                 \
        if (!(tu_err_ratio((double)(a), (double)(b), (double)(rtol), (double)(atol)) <= 1.0)) { \
            print_message(__VA_ARGS__);                                                  \
            print_message("\n");                                                         \
        }                                                                                \
        ASSERT_CLOSE(a, b, rtol, atol);                                                  \
    } while (0)

/* Vector check over i = 0..n-1 (b is the reference); a and b are anything
   indexable whose elements convert to double.  On failure it reports the
   index with the largest error ratio (the first NaN, if any). */
#define ASSERT_VEC_CLOSE(a, b, n, rtol, atol)                                            \
    do {                                                                                 \
        const int tu_vn_ = (int)(n);                                                     \
        const double tu_vrt_ = (double)(rtol), tu_vat_ = (double)(atol);                 \
        double tu_vw_ = 0.0;                                                             \
        int tu_vi_, tu_vk_ = -1;                                                         \
        for (tu_vi_ = 0; tu_vi_ < tu_vn_; ++tu_vi_) {                                    \
            const double tu_vr_ =                                                        \
                tu_err_ratio((double)(a)[tu_vi_], (double)(b)[tu_vi_], tu_vrt_, tu_vat_); \
            if (!(tu_vr_ <= tu_vw_)) {                                                   \
                tu_vw_ = tu_vr_;                                                         \
                tu_vk_ = tu_vi_;                                                         \
                if (tu_vr_ != tu_vr_) break; /* NaN: report it */                        \
            }                                                                            \
        }                                                                                \
        if (tu_vk_ >= 0 && !(tu_vw_ <= 1.0))                                             \
            fail_msg("%s[%d] = %.17g, %s[%d] = %.17g: |a-b|/(atol+rtol|b|) = %.3g > 1 "  \
                     "(rtol %.3g, atol %.3g, n %d)",                                     \
                     #a, tu_vk_, (double)(a)[tu_vk_], #b, tu_vk_, (double)(b)[tu_vk_],   \
                     tu_vw_, tu_vrt_, tu_vat_, tu_vn_);                                  \
    } while (0)

/* -- deterministic random numbers --------------------------------------- */
/* 64-bit LCG (Knuth's MMIX constants); the top 53 bits make the double.
   Same sequence on every platform, no hidden state. */
typedef struct tu_rng {
    uint64_t s;
} tu_rng;

static inline tu_rng tu_rng_seed(uint64_t seed)
{
    tu_rng g;
    g.s = seed;
    return g;
}

/* Uniform in [-1, 1). */
static inline double tu_rng_uniform(tu_rng *g)
{
    g->s = g->s * UINT64_C(6364136223846793005) + UINT64_C(1442695040888963407);
    return (double)(g->s >> 11) / 4503599627370496.0 - 1.0; /* 2^52 */
}

/* -- central finite differences ----------------------------------------- */
/* A vector-valued function of one scalar: writes its n components for the
   argument x to out and returns the argument it really used, that is x
   rounded to the working precision of the code under test (so that the
   difference quotient divides by the step that was actually taken). */
typedef double (*tu_vec_fn)(void *ctx, double x, double *out);

/* Step of a central difference: its error is about h^2/6 |f'''| (truncation)
   plus eps |f| / h (rounding of f), smallest for h ~ eps^(1/3) times the
   length over which f varies (scale). */
static inline double tu_fd_step(double eps, double scale) { return scale * cbrt(eps); }

/* d[i] = (f_i(x + h) - f_i(x - h)) / (x+ - x-), i < n, where x+ and x- are the
   arguments f really used.  work: n doubles of scratch. */
static inline void tu_central_diff(tu_vec_fn f, void *ctx, double x, double h, int n,
                                   double *work, double *d)
{
    const double xp = f(ctx, x + h, d);
    const double xm = f(ctx, x - h, work);
    const double inv = 1.0 / (xp - xm);
    int i;
    for (i = 0; i < n; ++i) d[i] = (d[i] - work[i]) * inv;
}

/* -- small helpers ------------------------------------------------------ */
static inline double tu_max_abs(int n, const double *a)
{
    double m = 0.0;
    int i;
    for (i = 0; i < n; ++i) m = fmax(m, fabs(a[i]));
    return m;
}

/* 1 in the slow builds: -O0, AddressSanitizer (GCC and clang), a binary run
   under valgrind (its preload library is in LD_PRELOAD), or VLBE_TEST_QUICK
   set (and not "0").  Those run the shorter variants of the dynamic tests. */
static inline int tu_slow_run(void)
{
    const char *q = getenv("VLBE_TEST_QUICK"), *pre = getenv("LD_PRELOAD");
    int slow = 0;
#if !defined(__OPTIMIZE__) || defined(__SANITIZE_ADDRESS__)
    slow = 1;
#elif defined(__has_feature)
#if __has_feature(address_sanitizer)
    slow = 1;
#endif
#endif
    if (q && q[0] && q[0] != '0') slow = 1;
    if (pre && strstr(pre, "vgpreload") != NULL) slow = 1;
    return slow;
}

/* 1 when VLBE_TEST_REPORT is set (and not "0") */
static inline int tu_report_on(void)
{
    const char *env = getenv("VLBE_TEST_REPORT");
    return env && env[0] && env[0] != '0';
}

/* "name: measured error, tolerance, ratio" when VLBE_TEST_REPORT is set */
static inline void tu_report(const char *name, double err, double tol)
{
    if (tu_report_on())
        print_message("    %-52s err %.3e  tol %.3e  (ratio %.3f)\n", name, err, tol,
                      tol > 0.0 ? err / tol : 0.0);
}

/* -- measured numbers in comments --------------------------------------
   A number a comment quotes as measured carries a tag right after it:
       the drift is 1.07e-7 (m:energy_drift) of Tmax
   and the test reports the value it measured under that key with
   tu_measured("energy_drift", drift).  tests/measured.sh (run by make test on
   the logs of the VLBE_TEST_REPORT runs) fails when the quoted number does not
   round to the measurement at the digits it shows, and `make measured-update`
   rewrites the quoted numbers from the logs.  Tag forms:
       (m:key)        double -O2 build, agree to the quoted digits
       (m@flt:key)    another build (dbl, dbl-O0, flt, san: the Makefile's names)
       (m~:key)       order of magnitude only (within a factor 3), for rounding-
                      level values that differ between compilers and CPUs
   Keys are unique within a suite: [A-Za-z0-9_.]+. */
static inline void tu_measured(const char *key, double value)
{
    if (tu_report_on()) print_message("MEASURED %s %.9e\n", key, value);
}

/* A test that does not apply to this build: print why, then cmocka's skip()
   (which returns from the test; the closing line counts it as skipped). */
#define TU_SKIP(reason)                                                                  \
    do {                                                                                 \
        print_message("    skipped: %s\n", (reason));                                   \
        skip();                                                                          \
    } while (0)

#endif /* VLBE_TEST_UTIL_H */

/* test_vlbe.c -- cmocka suite of vlbe.h (the core)
   -- part of vlbe                                 SPDX-License-Identifier: MIT

   Build and run from the repository root (add -DVLBE_USE_FLOAT for the
   float build; the same source passes in both precisions):
       cc -std=c99 -Wall -Wextra -Wpedantic -O2 tests/test_vlbe.c -o test_vlbe -lcmocka -lm
       ./test_vlbe

   Tolerances are multiples of VLBE_EPS (the machine epsilon of vlbe_real,
   twice its unit roundoff); each carries a one-line reason.  Reference values
   are computed in double (long double for LU residuals), so in the float
   build their own rounding is negligible next to the code under test's.
   Set VLBE_TEST_REPORT=1 to print the worst error of the checks with a
   rounding or difference tolerance next to that tolerance; "measured"
   below is the double -O2 build (tag m:; tests/measured.sh checks it
   against the report).

   Groups: status codes and finite checks | small vector ops | Gauss-Legendre
   | ALE Hermite / linear basis | dense LU. */
#include "test_util.h"
#include "../vlbe.h"
#include "fixtures_common.h"

#include <string.h>

#define EPS ((double)VLBE_EPS)
#define ARRAY_LEN(a) ((int)(sizeof(a) / sizeof((a)[0])))

#ifdef VLBE_USE_FLOAT
#define TEST_MAX_EXP FLT_MAX_EXP /* 2^(MAX_EXP-1) is the largest power of two */
#define TEST_MIN_EXP FLT_MIN_EXP /* 2^(MIN_EXP-1) is the smallest normal       */
#else
#define TEST_MAX_EXP DBL_MAX_EXP
#define TEST_MIN_EXP DBL_MIN_EXP
#endif

/* ======================================================================= */
/* status codes and finite checks                                          */
/* ======================================================================= */

static void test_status_str(void **state)
{
    static const vlbe_status codes[] = {VLBE_OK,        VLBE_EARG,       VLBE_EWORK,
                                        VLBE_ESINGULAR, VLBE_ENOCONV,    VLBE_ENONFINITE,
                                        VLBE_ESTEP,     VLBE_ELENGTH,    VLBE_EWEIGHT,
                                        VLBE_EBOUND,    VLBE_ECALLBACK};
    static const int unknown[] = {1, 42, -11, -1000};
    int i, j;
    (void)state;
    for (i = 0; i < ARRAY_LEN(codes); ++i) {
        const char *s = vlbe_status_str(codes[i]);
        assert_non_null(s);
        assert_true(s[0] != '\0');
        assert_string_not_equal(s, "unknown status");
        for (j = 0; j < i; ++j) assert_string_not_equal(s, vlbe_status_str(codes[j]));
    }
    for (i = 0; i < ARRAY_LEN(unknown); ++i)
        assert_string_equal(vlbe_status_str((vlbe_status)unknown[i]), "unknown status");
}

static void test_all_finite(void **state)
{
    const vlbe_real bad[3] = {(vlbe_real)NAN, (vlbe_real)INFINITY, -(vlbe_real)INFINITY};
    /* extreme but finite values must pass */
    const vlbe_real good[5] = {VLBE_REAL_MAX, -VLBE_REAL_MAX, VLBE_R(0.0), -VLBE_R(0.0),
                               (vlbe_real)ldexp(1.0, TEST_MIN_EXP - 2) /* subnormal */};
    vlbe_real x[5];
    int b, pos;
    (void)state;
    assert_int_equal(vlbe_all_finite(good, 5), 1);
    assert_int_equal(vlbe_all_finite(NULL, 0), 1); /* empty vector: nothing is non-finite */
    for (b = 0; b < 3; ++b)
        for (pos = 0; pos < 5; ++pos) {
            vlbe_vec_copy(5, good, x);
            x[pos] = bad[b];
            assert_int_equal(vlbe_all_finite(x, 5), 0);
            assert_int_equal(vlbe_all_finite(x, pos), 1); /* the prefix before it is fine */
        }
}

/* ======================================================================= */
/* small vector ops (small integer data: every result below is exact)     */
/* ======================================================================= */

static void test_vec2(void **state)
{
    const vlbe_real a[2] = {3, -4};
    const vlbe_real b[2] = {2, 5};
    const vlbe_real y_ref[2] = {7, -7};
    vlbe_real y[2] = {1, 1};
    (void)state;
    ASSERT_CLOSE(vlbe_v2_dot(a, b), -14.0, 0, 0);   /* integers: exact */
    ASSERT_CLOSE(vlbe_v2_cross(a, b), 23.0, 0, 0);  /* integers: exact */
    ASSERT_CLOSE(vlbe_v2_cross(b, a), -23.0, 0, 0); /* antisymmetric   */
    ASSERT_CLOSE(vlbe_v2_norm(a), 5.0, EPS, 0);     /* one correctly rounded sqrt */
    vlbe_v2_axpy(2, a, y);
    ASSERT_VEC_CLOSE(y, y_ref, 2, 0, 0); /* integers: exact */
}

static void test_vec3(void **state)
{
    const vlbe_real a[3] = {1, 2, 3};
    const vlbe_real b[3] = {4, -5, 6};
    const vlbe_real c_ref[3] = {27, 6, -13};
    const vlbe_real d[3] = {2, 3, 6};
    const vlbe_real y_ref[3] = {-2, -5, -6};
    vlbe_real c[3], ba[3], y[3] = {1, 1, 3};
    int i;
    (void)state;
    ASSERT_CLOSE(vlbe_v3_dot(a, b), 12.0, 0, 0); /* integers: exact */
    vlbe_v3_cross(a, b, c);
    ASSERT_VEC_CLOSE(c, c_ref, 3, 0, 0);      /* integers: exact */
    ASSERT_CLOSE(vlbe_v3_dot(a, c), 0.0, 0, 0); /* a x b is orthogonal to a and b */
    ASSERT_CLOSE(vlbe_v3_dot(b, c), 0.0, 0, 0);
    vlbe_v3_cross(b, a, ba);
    for (i = 0; i < 3; ++i) ASSERT_CLOSE(ba[i], -c[i], 0, 0); /* antisymmetric */
    ASSERT_CLOSE(vlbe_v3_norm(d), 7.0, EPS, 0); /* one correctly rounded sqrt */
    vlbe_v3_axpy(-3, a, y);
    ASSERT_VEC_CLOSE(y, y_ref, 3, 0, 0); /* integers: exact */
}

static void test_vec_n(void **state)
{
    const vlbe_real a[5] = {1, -2, 3, 0, 5};
    const vlbe_real b[5] = {2, 2, -1, 7, 3};
    const vlbe_real axpy_ref[5] = {4, -2, 5, 7, 13};
    const vlbe_real scale_ref[5] = {-2, 4, -6, 0, -10};
    vlbe_real y[5], z[5] = {9, 9, 9, 9, 9};
    const vlbe_real nine[5] = {9, 9, 9, 9, 9};
    (void)state;
    ASSERT_CLOSE(vlbe_vec_dot(5, a, b), 10.0, 0, 0); /* integers: exact */
    ASSERT_CLOSE(vlbe_vec_dot(0, a, b), 0.0, 0, 0);  /* empty sum */
    vlbe_vec_copy(5, b, y);
    ASSERT_VEC_CLOSE(y, b, 5, 0, 0);
    vlbe_vec_axpy(5, 2, a, y);
    ASSERT_VEC_CLOSE(y, axpy_ref, 5, 0, 0); /* integers: exact */
    vlbe_vec_copy(5, a, y);
    vlbe_vec_scale(5, -2, y);
    ASSERT_VEC_CLOSE(y, scale_ref, 5, 0, 0); /* integers: exact */
    vlbe_vec_zero(5, y);
    assert_true(vlbe_vec_norm_inf(5, y) == VLBE_R(0.0));
    /* n = 0 touches nothing */
    vlbe_vec_copy(0, a, z);
    vlbe_vec_axpy(0, 1, a, z);
    vlbe_vec_scale(0, 0, z);
    vlbe_vec_zero(0, z);
    ASSERT_VEC_CLOSE(z, nine, 5, 0, 0);
}

/* 2-norm: no overflow/underflow of the squares, NaN and Inf propagate;
   inf-norm: NaN propagates wherever it sits. */
static void test_vec_norms(void **state)
{
    /* powers of two at the ends of the exponent range: 3h, 4h and 5h are
       exact while (4h)^2 overflows (big) or underflows to zero (tiny) */
    const vlbe_real big = (vlbe_real)ldexp(1.0, TEST_MAX_EXP - 4);
    const vlbe_real tiny = (vlbe_real)ldexp(1.0, TEST_MIN_EXP - 1);
    const vlbe_real nan = (vlbe_real)NAN, inf = (vlbe_real)INFINITY;
    vlbe_real x[4], r[7];
    double ref = 0.0;
    tu_rng g = tu_rng_seed(7);
    int i, pos;
    (void)state;

    x[0] = 3 * big, x[1] = 0, x[2] = -4 * big;
    ASSERT_CLOSE(vlbe_vec_norm2(3, x), 5.0 * (double)big, EPS, 0); /* one rounded sqrt */
    x[0] = -3 * tiny, x[1] = 4 * tiny, x[2] = 0;
    ASSERT_CLOSE(vlbe_vec_norm2(3, x), 5.0 * (double)tiny, EPS, 0); /* one rounded sqrt */
#ifndef VLBE_USE_FLOAT
    x[0] = 1e200, x[1] = 1e200, x[2] = 1e200;
    ASSERT_CLOSE(vlbe_vec_norm2(3, x), 1e200 * sqrt(3.0), 4 * EPS, 0); /* 3 adds, sqrt, scale */
#endif
    for (i = 0; i < 7; ++i) {
        r[i] = (vlbe_real)tu_rng_uniform(&g);
        ref += (double)r[i] * (double)r[i];
    }
    /* n = 7 divisions, squares and sums, one sqrt and one product: <= 10 roundings */
    ASSERT_CLOSE(vlbe_vec_norm2(7, r), sqrt(ref), 10 * EPS, 0);
    ASSERT_CLOSE(vlbe_vec_norm2(0, r), 0.0, 0, 0);
    ASSERT_CLOSE(vlbe_vec_norm_inf(0, r), 0.0, 0, 0);

    for (pos = 0; pos < 4; ++pos) {
        x[0] = 1, x[1] = -7, x[2] = 3, x[3] = 2;
        ASSERT_CLOSE(vlbe_vec_norm_inf(4, x), 7.0, 0, 0); /* a max is exact */
        x[pos] = nan;
        assert_true(isnan(vlbe_vec_norm_inf(4, x)));
        assert_true(isnan(vlbe_vec_norm2(4, x)));
        x[pos] = -inf;
        assert_true(isinf(vlbe_vec_norm_inf(4, x)) && vlbe_vec_norm_inf(4, x) > 0);
        assert_true(isinf(vlbe_vec_norm2(4, x)) && vlbe_vec_norm2(4, x) > 0);
    }
}

static void test_mat_vec(void **state)
{
    const vlbe_real A[6] = {1, 2, 3, 4, 5, 6}; /* 2 x 3 row-major */
    const vlbe_real x[3] = {1, -1, 2}, z[2] = {1, -2};
    const vlbe_real y_ref[2] = {5, 11}, w_ref[3] = {-7, -8, -9};
    vlbe_real y[2], w[3] = {100, 100, 100}; /* mat_tvec must overwrite, not add */
    (void)state;
    vlbe_mat_vec(2, 3, A, x, y);
    ASSERT_VEC_CLOSE(y, y_ref, 2, 0, 0); /* integers: exact */
    vlbe_mat_tvec(2, 3, A, z, w);
    ASSERT_VEC_CLOSE(w, w_ref, 3, 0, 0); /* integers: exact */
    /* adjoint identity z.(A x) = (A^T z).x */
    ASSERT_CLOSE(vlbe_vec_dot(2, z, y), vlbe_vec_dot(3, w, x), 0, 0);
}

/* ======================================================================= */
/* Gauss-Legendre                                                          */
/* ======================================================================= */

/* sum_i w_i x_i^k in double from the (vlbe_real) table of rule n */
static double gl_sum(int n, int k)
{
    const vlbe_real *x = NULL, *w = NULL;
    double s = 0.0;
    int i;
    assert_int_equal(vlbe_gl_rule(n, &x, &w), VLBE_OK);
    for (i = 0; i < n; ++i) s += (double)w[i] * pow((double)x[i], k);
    return s;
}

/* exact integral of x^k over [-1, 1] */
static double monomial_integral(int k) { return k % 2 ? 0.0 : 2.0 / (k + 1); }

/* Rounding bound of gl_sum(n, k): each table entry is rounded (eps/2
   relative), so w x^k is off by <= (k + 1) eps/2 relative, and sum |w x^k|
   <= sum w = 2; the double arithmetic adds n + k more roundings (far smaller
   in the float build).  A bound, not an estimate: the worst case measured
   (test_gl_exactness) uses 0.06 (m:gl_ratio) of it. */
static double gl_tol(int n, int k) { return 2.0 * (double)(n + k + 1) * EPS; }

/* Error of the n-point rule on x^(2n): 2^(2n+1) (n!)^4 / ((2n+1) ((2n)!)^2)
   (the Gauss remainder with f^(2n) = (2n)!). */
static double gl_remainder_x2n(int n)
{
    double r = 1.0; /* (n!)^2 / (2n)! = prod_j j / (n + j) */
    int j;
    for (j = 1; j <= n; ++j) r *= (double)j / (double)(n + j);
    return ldexp(r * r, 2 * n + 1) / (double)(2 * n + 1);
}

static void test_gl_exactness(void **state)
{
    double worst = 0.0;
    int n, k;
    (void)state;
    for (n = 1; n <= VLBE_GL_MAX; ++n)
        for (k = 0; k <= 2 * n - 1; ++k) {
            ASSERT_CLOSE_CTX(gl_sum(n, k), monomial_integral(k), 0, gl_tol(n, k),
                             "rule n = %d, x^%d", n, k);
            worst = fmax(worst, fabs(gl_sum(n, k) - monomial_integral(k)) / gl_tol(n, k));
        }
    tu_report("Gauss rules on x^k, k < 2n: err / bound", worst, 1.0);
    tu_measured("gl_ratio", worst);
}

/* Degree 2n is not integrated exactly: the error equals the Gauss remainder
   to rounding, and wherever the remainder exceeds the rounding bound by a
   wide margin (every n in double, n <= 7 in float) the rule is visibly not
   exact. */
static void test_gl_not_exact_2n(void **state)
{
    double worst = 0.0;
    int n, visible = 0;
    (void)state;
    for (n = 1; n <= VLBE_GL_MAX; ++n) {
        const double err = monomial_integral(2 * n) - gl_sum(n, 2 * n);
        const double rem = gl_remainder_x2n(n), tol = gl_tol(n, 2 * n);
        ASSERT_CLOSE_CTX(err, rem, 0, tol, "rule n = %d, x^%d", n, 2 * n);
        worst = fmax(worst, fabs(err - rem) / tol);
        if (rem > 20.0 * tol) {
            assert_true(fabs(err) > 10.0 * tol); /* clearly above rounding */
            ++visible;
        }
    }
    assert_true(visible >= (EPS < 1e-12 ? VLBE_GL_MAX : 7)); /* see above */
    tu_report("Gauss rules on x^2n: err - remainder / bound", worst, 1.0);
}

static void test_gl_nodes_weights(void **state)
{
    int n, i;
    (void)state;
    for (n = 1; n <= VLBE_GL_MAX; ++n) {
        const vlbe_real *x = NULL, *w = NULL;
        assert_int_equal(vlbe_gl_rule(n, &x, &w), VLBE_OK);
        for (i = 0; i < n; ++i) {
            assert_true(w[i] > 0);
            assert_true(x[i] > -1 && x[i] < 1);
            if (i > 0) assert_true(x[i] > x[i - 1]); /* strictly ascending */
            /* symmetric: the tables hold +-x and equal w digit for digit */
            assert_true(x[i] == -x[n - 1 - i]);
            assert_true(w[i] == w[n - 1 - i]);
        }
        ASSERT_CLOSE_CTX(gl_sum(n, 0), 2.0, 0, gl_tol(n, 0), "rule n = %d, sum of weights", n);
    }
    /* NULL outputs are allowed */
    assert_int_equal(vlbe_gl_rule(VLBE_GL_MAX, NULL, NULL), VLBE_OK);
}

static void test_gl_bad_n(void **state)
{
    static const vlbe_real sentinel[1] = {0};
    const int bad[] = {0, -1, VLBE_GL_MAX + 1, 1000};
    int i;
    (void)state;
    for (i = 0; i < ARRAY_LEN(bad); ++i) {
        const vlbe_real *x = sentinel, *w = sentinel;
        assert_int_equal(vlbe_gl_rule(bad[i], &x, &w), VLBE_EARG);
        assert_ptr_equal(x, sentinel); /* a failed call writes nothing */
        assert_ptr_equal(w, sentinel);
    }
}

/* ======================================================================= */
/* ALE Hermite / linear basis                                              */
/* ======================================================================= */
/* The basis is viewed as two families: HERM (N1..N4, h[k][a][i], k <= 3) and
   LIN (H1, H2, l[k][a][i], k <= 1).  Tests that visit every entry walk one
   flat index (herm_decode / herm_index) instead of repeating nested loops. */
enum { HERM = 0, LIN = 1 };
#define HERM_NH (4 * VLBE_DA_N * 4)          /* entries of h */
#define HERM_NV (HERM_NH + 2 * VLBE_DA_N * 2) /* entries of h and l: 120 */

static const int fam_nb[2] = {4, 2};   /* functions per family        */
static const int fam_kmax[2] = {3, 1}; /* highest p-derivative stored */
/* (k1, k2): orders in p1 and p2 of each VLBE_DA_* selector */
static const int da_k[VLBE_DA_N][2] = {{0, 0}, {1, 0}, {0, 1}, {2, 0}, {1, 1}, {0, 2}};

typedef struct herm_entry {
    int fam, k, a, i;
} herm_entry;

static herm_entry herm_decode(int idx)
{
    herm_entry e;
    const int j = idx < HERM_NH ? idx : idx - HERM_NH;
    int nb;
    e.fam = idx < HERM_NH ? HERM : LIN;
    nb = fam_nb[e.fam];
    e.i = j % nb;
    e.a = (j / nb) % VLBE_DA_N;
    e.k = j / (nb * VLBE_DA_N);
    return e;
}

static int herm_index(int fam, int k, int a, int i)
{
    return fam == HERM ? (k * VLBE_DA_N + a) * 4 + i : HERM_NH + (k * VLBE_DA_N + a) * 2 + i;
}

static int da_order(int a) { return da_k[a][0] + da_k[a][1]; }

/* selector of (k1, k2), -1 above second order */
static int da_select(int k1, int k2)
{
    int a;
    for (a = 0; a < VLBE_DA_N; ++a)
        if (da_k[a][0] == k1 && da_k[a][1] == k2) return a;
    return -1;
}

static vlbe_real *herm_at(vlbe_herm_ale *b, herm_entry e)
{
    return e.fam == HERM ? &b->h[e.k][e.a][e.i] : &b->l[e.k][e.a][e.i];
}

static double herm_get(const vlbe_herm_ale *b, int fam, int k, int a, int i)
{
    return (double)(fam == HERM ? b->h[k][a][i] : b->l[k][a][i]);
}

static void herm_flatten(const vlbe_herm_ale *b, double *out)
{
    int idx;
    for (idx = 0; idx < HERM_NV; ++idx) {
        const herm_entry e = herm_decode(idx);
        out[idx] = herm_get(b, e.fam, e.k, e.a, e.i);
    }
}

/* Natural size of an entry: N2, N4 carry a length (they multiply slopes),
   and each derivative in p, p1 or p2 divides by one length, so the entry of
   level m = k + (order in p1, p2) is (a polynomial in xi with coefficients
   of a few tens at most) times L^(u - m).  Absolute tolerances scale with it. */
static double herm_unit(int fam, int i, int m, double L)
{
    const int u = (fam == HERM && (i == 1 || i == 3)) ? 1 : 0;
    return pow(L, (double)(u - m));
}

/* Elements (p1, p2) used by the exact tests: O(1), offset, short, long. */
static const double elems[][2] = {{0.5, 2.0}, {-3.0, -2.75}, {1000.0, 1001.5},
                                  {0.0, 0.01}, {-20.0, 30.0}};
/* points inside an element, as xi = (p - p1)/L (nodes included) */
static const double xis[] = {0.0, 0.2, 0.5, 0.77, 1.0};

/* A material point of an element in working precision; returns L. */
static double elem_point(int el, int ix, vlbe_real *p, vlbe_real *p1, vlbe_real *p2)
{
    *p1 = (vlbe_real)elems[el][0];
    *p2 = (vlbe_real)elems[el][1];
    *p = (xis[ix] == 1.0) ? *p2 : (vlbe_real)((double)*p1 + xis[ix] * ((double)*p2 - (double)*p1));
    return (double)*p2 - (double)*p1;
}

/* (a) values against the paper's formulas in s, written out here
   independently of the library's polynomial-in-xi form. */
static void test_herm_s_form(void **state)
{
    double ws = 0.0, wb = 0.0;
    int el, fam, i, t;
    (void)state;
    for (el = 0; el < ARRAY_LEN(elems); ++el)
        for (t = 0; t <= 20; ++t) {
            vlbe_real p, p1, p2;
            vlbe_herm_ale b;
            double L, s, ref[2][4];
            p1 = (vlbe_real)elems[el][0];
            p2 = (vlbe_real)elems[el][1];
            L = (double)p2 - (double)p1;
            p = (vlbe_real)((double)p1 + L * t / 20.0);
            /* s = (2p - p1 - p2)/L, grouped so that each difference is one
               rounding of a number no larger than L (p1 <= p <= p2) */
            s = (((double)p - (double)p1) + ((double)p - (double)p2)) / L;
            ref[HERM][0] = (s - 1) * (s - 1) * (2 + s) / 4;     /* N1 */
            ref[HERM][1] = L * (s - 1) * (s - 1) * (s + 1) / 8; /* N2 */
            ref[HERM][2] = (s + 1) * (s + 1) * (2 - s) / 4;     /* N3 */
            ref[HERM][3] = L * (s + 1) * (s + 1) * (s - 1) / 8; /* N4 */
            ref[LIN][0] = (1 - s) / 2;                          /* H1 */
            ref[LIN][1] = (1 + s) / 2;                          /* H2 */
            vlbe_herm_ale_eval(p, p1, p2, 0, 0, &b);
            /* library: p - p1, 1/L, a product (1.5 eps relative in xi), then
               2 xi - 1: <= 3.5 eps; the reference adds ~1.5 eps of its own */
            ASSERT_CLOSE_CTX(b.s, s, 0, 8 * EPS, "element %d, t %d", el, t);
            ws = fmax(ws, fabs((double)b.s - s) / EPS);
            ASSERT_CLOSE(b.L, L, 0, 0); /* p2 - p1 of the same two numbers */
            for (fam = HERM; fam <= LIN; ++fam)
                for (i = 0; i < fam_nb[fam]; ++i) {
                    /* s error (<= 8 eps, above) times |dN/ds| <= 3/4 L^u, plus
                       the roundings of the terms 1, 3 xi^2, 2 xi^3 (<= 6 eps):
                       16 eps of the natural size */
                    ASSERT_CLOSE_CTX(herm_get(&b, fam, 0, 0, i), ref[fam][i], 0,
                                     16 * EPS * herm_unit(fam, i, 0, L),
                                     "element %d, t %d, %s%d", el, t, fam == HERM ? "N" : "H",
                                     i + 1);
                    wb = fmax(wb, fabs(herm_get(&b, fam, 0, 0, i) - ref[fam][i]) /
                                      (EPS * herm_unit(fam, i, 0, L)));
                }
        }
    tu_report("s = (2p - p1 - p2)/L, in eps", ws, 8.0);
    tu_report("N1..N4, H1, H2 vs the s form, in eps of natural size", wb, 16.0);
}

/* (b) interpolation conditions at the nodes: value and slope (d/dp) of N1..N4
   and value of H1, H2 select the matching nodal coordinate. */
static void test_herm_interpolation(void **state)
{
    int el, node, k, i;
    (void)state;
    for (el = 0; el < ARRAY_LEN(elems); ++el)
        for (node = 0; node < 2; ++node) {
            vlbe_real p, p1, p2;
            vlbe_herm_ale b;
            const double L = elem_point(el, node ? ARRAY_LEN(xis) - 1 : 0, &p, &p1, &p2);
            vlbe_herm_ale_eval(p, p1, p2, 1, 0, &b);
            for (k = 0; k <= 1; ++k)
                for (i = 0; i < 4; ++i) {
                    /* N_{2 node + k + 1}^(k) = 1, the other three 0 */
                    const double want = (i == 2 * node + k) ? 1.0 : 0.0;
                    /* xi = 1 at p2 only to within ~2 eps (L * (1/L)); slopes of
                       the cubics in xi are <= 6: 8 eps of the natural size */
                    ASSERT_CLOSE_CTX(herm_get(&b, HERM, k, VLBE_DA_0, i), want, 0,
                                     8 * EPS * herm_unit(HERM, i, k, L),
                                     "element %d, node %d, N%d^(%d)", el, node, i + 1, k);
                }
            for (i = 0; i < 2; ++i)
                /* same reasoning, linear function of xi: 2 eps */
                ASSERT_CLOSE_CTX(herm_get(&b, LIN, 0, VLBE_DA_0, i), i == node ? 1.0 : 0.0, 0,
                                 2 * EPS, "element %d, node %d, H%d", el, node, i + 1);
        }
}

/* -- exact identities of the interpolant ---------------------------------- */
/* Test field f(x) = sum_{j<=3} c[j] (x - x0)^j. */
typedef struct poly3 {
    double c[4], x0;
} poly3;

/* f^(r)(x) by Horner on the coefficients of the r-th derivative */
static double poly3_deriv(const poly3 *f, int r, double x)
{
    double s = 0.0, t = x - f->x0;
    int j, q;
    for (j = 3; j >= r; --j) {
        double ff = 1.0; /* j (j-1) ... (j-r+1) */
        for (q = 0; q < r; ++q) ff *= (double)(j - q);
        s = s * t + f->c[j] * ff;
    }
    return s;
}

/* D_p1^j1 D_p2^j2 of the nodal coordinate q_i(p1, p2) of f: for HERM
   q = (f(p1), f'(p1), f(p2), f'(p2)), for LIN q = (f(p1), f(p2)). */
static double nodal_deriv(int fam, int i, int j1, int j2, const poly3 *f, double p1, double p2)
{
    const int node = fam == HERM ? i / 2 : i, slope = fam == HERM ? i % 2 : 0;
    if (node == 0) return j2 ? 0.0 : poly3_deriv(f, slope + j1, p1);
    return j1 ? 0.0 : poly3_deriv(f, slope + j2, p2);
}

/* The interpolant r(p; p1, p2) = sum_i B_i(p; p1, p2) q_i(p1, p2) of a field
   f the family reproduces (degree <= 3 for HERM, <= 1 for LIN) is f(p) for
   every p1 < p2.  So, by Leibniz' rule, for every k and (k1, k2):
     sum_{j1<=k1, j2<=k2} C(k1,j1) C(k2,j2) sum_i [D_p^k D_p1^(k1-j1) D_p2^(k2-j2) B_i]
                                                  [D_p1^j1 D_p2^j2 q_i]
       = f^(k)(p) if k1 = k2 = 0, and 0 otherwise.
   For k1 = k2 = 0 this is reproduction (partition of unity for f = 1); the
   others check the p1/p2 partials exactly, mixed and second order included.
   Rounding: each basis entry is off by a few tens of eps of its natural
   size (herm_unit), so the sum is off by that times sum |C C q_i|. */
static double herm_interp_worst; /* worst error / (eps scale) of check_interpolant */

static void check_interpolant(const vlbe_herm_ale *b, int fam, const poly3 *f, double p,
                              double p1, double p2)
{
    const double L = p2 - p1;
    int k, a, j1, j2, i;
    for (k = 0; k <= fam_kmax[fam]; ++k)
        for (a = 0; a < VLBE_DA_N; ++a) {
            const int k1 = da_k[a][0], k2 = da_k[a][1];
            double sum = 0.0, scale = 0.0;
            for (j1 = 0; j1 <= k1; ++j1)
                for (j2 = 0; j2 <= k2; ++j2) {
                    const double cc = (j1 == 1 && k1 == 2 ? 2.0 : 1.0) *
                                      (j2 == 1 && k2 == 2 ? 2.0 : 1.0); /* binomials */
                    const int sel = da_select(k1 - j1, k2 - j2), m = k + k1 - j1 + k2 - j2;
                    for (i = 0; i < fam_nb[fam]; ++i) {
                        const double q = nodal_deriv(fam, i, j1, j2, f, p1, p2);
                        const double B = herm_get(b, fam, k, sel, i);
                        sum += cc * B * q;
                        scale += cc * (fabs(B) + herm_unit(fam, i, m, L)) * fabs(q);
                    }
                }
            /* 32 eps of the natural sizes: the coefficients of the second
               partials at k = 3 reach a few hundred but the rounding spreads
               over many terms (measured worst: 0.8 (m:herm_interp) eps of
               scale) */
            herm_interp_worst =
                fmax(herm_interp_worst,
                     fabs(sum - (a == VLBE_DA_0 ? poly3_deriv(f, k, p) : 0.0)) / (EPS * scale));
            ASSERT_CLOSE_CTX(sum, a == VLBE_DA_0 ? poly3_deriv(f, k, p) : 0.0, 0,
                             32 * EPS * scale,
                             "%s, p = %.9g, p1 = %.9g, p2 = %.9g, k = %d, (k1,k2) = (%d,%d)",
                             fam == HERM ? "Hermite" : "linear", p, p1, p2, k, k1, k2);
        }
}

/* (c) partition of unity (f = 1), reproduction of linear fields (f = p: the
   interpolant of r(p) = p with unit slopes is p) and of a cubic, with all
   their p-derivatives: the k1 = k2 = 0 rows of check_interpolant.
   (e) exact check of every p1/p2 partial, first, second and mixed, at every
   k: the other rows, for the same fields. */
static void test_herm_reproduction_and_partials(void **state)
{
    /* cubic field in the element's own scale: sum_j gam[j] ((x - x0)/L)^j */
    static const double gam[4] = {0.7, -1.3, 0.9, 0.45};
    int el, ix, fi, fam, j;
    (void)state;
    herm_interp_worst = 0.0;
    for (el = 0; el < ARRAY_LEN(elems); ++el)
        for (ix = 0; ix < ARRAY_LEN(xis); ++ix) {
            vlbe_real p, p1, p2;
            vlbe_herm_ale b;
            const double L = elem_point(el, ix, &p, &p1, &p2);
            vlbe_herm_ale_eval(p, p1, p2, 3, 2, &b);
            for (fi = 0; fi < 3; ++fi) {
                poly3 f;
                f.x0 = (double)p1 + 0.37 * L; /* off centre */
                for (j = 0; j < 4; ++j) f.c[j] = 0.0;
                if (fi == 0) {
                    f.c[0] = 1.0; /* f = 1: partition of unity */
                } else if (fi == 1) {
                    f.c[0] = f.x0, f.c[1] = 1.0; /* f(x) = x: unit slopes */
                } else {
                    for (j = 0; j < 4; ++j) f.c[j] = gam[j] / pow(L, j);
                }
                for (fam = HERM; fam <= LIN; ++fam)
                    if (fam == HERM || fi < 2) /* LIN reproduces degree <= 1 only */
                        check_interpolant(&b, fam, &f, (double)p, (double)p1, (double)p2);
            }
        }
    tu_report("reproduction and p1/p2 partials, in eps of scale", herm_interp_worst, 32.0);
    tu_measured("herm_interp", herm_interp_worst);
}

/* -- finite differences ------------------------------------------------- */
typedef struct herm_fd_ctx {
    vlbe_real x[3]; /* p, p1, p2 */
    int dir;        /* which of them varies */
} herm_fd_ctx;

static double herm_fd_eval(void *vctx, double t, double *out)
{
    const herm_fd_ctx *c = (const herm_fd_ctx *)vctx;
    vlbe_real x[3];
    vlbe_herm_ale b;
    x[0] = c->x[0], x[1] = c->x[1], x[2] = c->x[2];
    x[c->dir] = (vlbe_real)t;
    vlbe_herm_ale_eval(x[0], x[1], x[2], 3, 2, &b);
    herm_flatten(&b, out);
    return (double)x[c->dir];
}

/* Where the derivative in direction dir (0: p, 1: p1, 2: p2) of entry (k, a)
   is stored: returns its flat index, HERM_NV when it is identically zero
   (d/dp beyond the degree), -1 when it is not stored (third order). */
static int fd_target(int dir, herm_entry e)
{
    static const int up[3][VLBE_DA_N] = {
        {0, 0, 0, 0, 0, 0},
        {VLBE_DA_1, VLBE_DA_11, VLBE_DA_12, -1, -1, -1},
        {VLBE_DA_2, VLBE_DA_12, VLBE_DA_22, -1, -1, -1}};
    if (dir == 0) return e.k < fam_kmax[e.fam] ? herm_index(e.fam, e.k + 1, e.a, e.i) : HERM_NV;
    return up[dir][e.a] < 0 ? -1 : herm_index(e.fam, e.k, up[dir][e.a], e.i);
}

/* (d) every stored derivative against a central difference of the level
   below it, in p (k = 1..3 at every p1/p2 order, plus d/dp of the top level
   = 0), in p1 and in p2 (first, second and mixed partials at every k). */
static void test_herm_fd(void **state)
{
    static const double fd_elems[][2] = {{0.5, 2.0}, {-3.0, -2.75}};
    static const double fd_xis[] = {0.0, 0.3, 0.5, 0.85, 1.0};
    /* h = eps^(1/3) L / 4.  In units of the natural size of the derivative
       (herm_unit), the rounding error is ~c eps / hrel, c = a few tens (the
       coefficients of the entries), and the truncation error is hrel^2/6
       times the growth of the coefficients over three more derivatives
       (hundreds at the highest orders).  Measured 4 (m:herm_fd) eps/hrel
       at this step in double, 17 (m@flt:herm_fd) in float (relative to
       |exact| + the natural size); the truncation part grows as h^3
       relative to the rounding part (8x at twice the step). */
    const double hrel = tu_fd_step(EPS, 0.25);
    /* 64 eps/hrel (9e-9 in double, 6e-3 in float) covers both with a
       margin (above); relative to |exact| and to the natural size */
    const double tol = 64 * EPS / hrel;
    double full[HERM_NV], d[HERM_NV], work[HERM_NV], worst = 0.0;
    int el, ix, dir, idx;
    (void)state;
    for (el = 0; el < ARRAY_LEN(fd_elems); ++el)
        for (ix = 0; ix < ARRAY_LEN(fd_xis); ++ix) {
            herm_fd_ctx c;
            vlbe_herm_ale b;
            double L;
            c.x[1] = (vlbe_real)fd_elems[el][0];
            c.x[2] = (vlbe_real)fd_elems[el][1];
            L = (double)c.x[2] - (double)c.x[1];
            c.x[0] = (vlbe_real)((double)c.x[1] + fd_xis[ix] * L);
            vlbe_herm_ale_eval(c.x[0], c.x[1], c.x[2], 3, 2, &b);
            herm_flatten(&b, full);
            for (dir = 0; dir < 3; ++dir) {
                c.dir = dir;
                tu_central_diff(herm_fd_eval, &c, (double)c.x[dir], hrel * L, HERM_NV, work, d);
                for (idx = 0; idx < HERM_NV; ++idx) {
                    const herm_entry e = herm_decode(idx);
                    const int tgt = fd_target(dir, e);
                    const int m = e.k + da_order(e.a) + 1; /* level of the derivative */
                    if (tgt < 0) continue;
                    worst = fmax(worst, fabs(d[idx] - (tgt == HERM_NV ? 0.0 : full[tgt])) /
                                            (EPS / hrel *
                                             (fabs(tgt == HERM_NV ? 0.0 : full[tgt]) +
                                              herm_unit(e.fam, e.i, m, L))));
                    ASSERT_CLOSE_CTX(d[idx], tgt == HERM_NV ? 0.0 : full[tgt], tol,
                                     tol * herm_unit(e.fam, e.i, m, L),
                                     "FD in %s of %s%d, k = %d, selector %d at p = %.9g, "
                                     "p1 = %.9g, p2 = %.9g",
                                     dir == 0 ? "p" : dir == 1 ? "p1" : "p2",
                                     e.fam == HERM ? "N" : "H", e.i + 1, e.k, e.a,
                                     (double)c.x[0], (double)c.x[1], (double)c.x[2]);
                }
            }
        }
    tu_report("basis derivatives vs differences, in eps/hrel", worst, 64.0);
    tu_measured("herm_fd", worst);
}

/* (f) kmax/amax subsets: the requested entries equal the full evaluation bit
   for bit (same operations), and nothing else is written. */
static void test_herm_subsets(void **state)
{
    const vlbe_real sentinel = VLBE_R(-777.0);
    int el, ix, kmax, amax, idx;
    (void)state;
    for (el = 0; el < ARRAY_LEN(elems); ++el)
        for (ix = 0; ix < ARRAY_LEN(xis); ++ix) {
            vlbe_real p, p1, p2;
            vlbe_herm_ale full, sub;
            (void)elem_point(el, ix, &p, &p1, &p2);
            vlbe_herm_ale_eval(p, p1, p2, 3, 2, &full);
            for (kmax = 0; kmax <= 3; ++kmax)
                for (amax = 0; amax <= 2; ++amax) {
                    for (idx = 0; idx < HERM_NV; ++idx) *herm_at(&sub, herm_decode(idx)) = sentinel;
                    vlbe_herm_ale_eval(p, p1, p2, kmax, amax, &sub);
                    assert_true(sub.s == full.s && sub.L == full.L);
                    for (idx = 0; idx < HERM_NV; ++idx) {
                        const herm_entry e = herm_decode(idx);
                        const int wanted = e.k <= kmax && da_order(e.a) <= amax;
                        const vlbe_real got = *herm_at(&sub, e);
                        if (wanted) {
                            ASSERT_CLOSE_CTX(got, *herm_at(&full, e), 0, 0,
                                             "kmax %d amax %d entry %d", kmax, amax, idx);
                        } else {
                            ASSERT_CLOSE_CTX(got, sentinel, 0, 0,
                                             "kmax %d amax %d entry %d written", kmax, amax, idx);
                        }
                    }
                }
        }
}

/* ======================================================================= */
/* dense LU                                                                */
/* ======================================================================= */

static vlbe_real *alloc_real(size_t n) { return (vlbe_real *)test_malloc(n * sizeof(vlbe_real)); }

/* A = uniform[-1, 1) entries + shift * I (m x n, row-major) */
static void fill_random(tu_rng *g, int m, int n, double shift, vlbe_real *A)
{
    int i, j;
    for (i = 0; i < m; ++i)
        for (j = 0; j < n; ++j)
            A[i * n + j] = (vlbe_real)(tu_rng_uniform(g) + (i == j ? shift : 0.0));
}

/* B = A X rounded to working precision; A n x n, X and B n x nrhs */
static void mat_mul_ref(int n, int nrhs, const vlbe_real *A, const vlbe_real *X, vlbe_real *B)
{
    int i, j, r;
    for (i = 0; i < n; ++i)
        for (r = 0; r < nrhs; ++r) {
            long double s = 0.0L;
            for (j = 0; j < n; ++j)
                s += (long double)A[i * n + j] * (long double)X[j * nrhs + r];
            B[i * nrhs + r] = (vlbe_real)s;
        }
}

/* Normwise backward-error check of column r of X against B:
   ||A x - b||_inf <= 10 n eps ||A||_inf ||x||_inf.  Partial pivoting is
   backward stable (|dA| <= ~3n eps |L||U|, small growth here); the residual
   is summed in long double so that, in the double build, its own rounding
   stays well below the bound. */
static double lu_res_worst; /* worst residual / (n eps ||A|| ||x||) of check_residual */

static void check_residual(int n, int nrhs, int r, const vlbe_real *A, const vlbe_real *X,
                           const vlbe_real *B)
{
    double scale, res = lu_residual(n, nrhs, r, A, X, B, &scale);
    ASSERT_CLOSE_CTX(res, 0.0, 0, 10.0 * n * EPS * scale, "n = %d, right-hand side %d", n, r);
    if (scale > 0.0) lu_res_worst = fmax(lu_res_worst, res / (n * EPS * scale));
}

/* Factors A out of place (A must not change), solves for nrhs right-hand
   sides of known solutions, checks residuals; returns nothing, asserts. */
static void lu_solve_check(int n, int nrhs, const vlbe_real *A, tu_rng *g)
{
    const size_t nn = (size_t)n * (size_t)n, nb = (size_t)n * (size_t)nrhs;
    vlbe_real *copy = alloc_real(nn), *LU = alloc_real(nn);
    vlbe_real *X = alloc_real(nb), *B = alloc_real(nb), *x1 = alloc_real((size_t)n);
    int *piv = (int *)test_malloc((size_t)n * sizeof(int));
    int info = -1, i, r;
    memcpy(copy, A, nn * sizeof(vlbe_real));
    fill_random(g, n, nrhs, 0.0, X);
    mat_mul_ref(n, nrhs, A, X, B);
    memcpy(X, B, nb * sizeof(vlbe_real));
    assert_int_equal(vlbe_lu_factor(n, A, LU, piv, &info), VLBE_OK);
    assert_int_equal(info, 0);
    assert_memory_equal(A, copy, nn * sizeof(vlbe_real)); /* out of place: A untouched */
    for (i = 0; i < n; ++i) assert_true(piv[i] >= i && piv[i] < n);
    vlbe_lu_solve(n, LU, piv, nrhs, X);
    for (r = 0; r < nrhs; ++r) {
        check_residual(n, nrhs, r, A, X, B);
        /* one column at a time gives the same numbers: the solve runs the
           same operations on every column */
        for (i = 0; i < n; ++i) x1[i] = B[i * nrhs + r];
        vlbe_lu_solve(n, LU, piv, 1, x1);
        for (i = 0; i < n; ++i) ASSERT_CLOSE(x1[i], X[i * nrhs + r], 0, 0);
    }
    test_free(piv);
    test_free(x1);
    test_free(B);
    test_free(X);
    test_free(LU);
    test_free(copy);
}

static const int lu_sizes[] = {1, 2, 3, 5, 10, 50, 200};

/* random + n I: diagonally dominant, well conditioned, one and three
   right-hand sides */
static void test_lu_random_dominant(void **state)
{
    tu_rng g = tu_rng_seed(12345);
    int s;
    (void)state;
    lu_res_worst = 0.0;
    for (s = 0; s < ARRAY_LEN(lu_sizes); ++s) {
        const int n = lu_sizes[s];
        vlbe_real *A = alloc_real((size_t)n * (size_t)n);
        fill_random(&g, n, n, (double)n, A);
        lu_solve_check(n, 1, A, &g);
        lu_solve_check(n, 3, A, &g);
        test_free(A);
    }
    tu_report("LU, dominant: residual in n eps ||A|| ||x||", lu_res_worst, 10.0);
}

/* plain random matrices: pivoting happens at almost every step */
static void test_lu_random_general(void **state)
{
    tu_rng g = tu_rng_seed(777);
    int s;
    (void)state;
    lu_res_worst = 0.0;
    for (s = 0; s < ARRAY_LEN(lu_sizes); ++s) {
        const int n = lu_sizes[s];
        vlbe_real *A = alloc_real((size_t)n * (size_t)n);
        fill_random(&g, n, n, n == 1 ? 2.0 : 0.0, A); /* keep the 1 x 1 away from 0 */
        lu_solve_check(n, 3, A, &g);
        test_free(A);
    }
    tu_report("LU, general: residual in n eps ||A|| ||x||", lu_res_worst, 10.0);
}

/* Matrices with zeros on the diagonal, which only pivoting can factor, and
   one that pivoting must reorder for accuracy. */
static void test_lu_pivoting(void **state)
{
    enum { N = 6 };
    const vlbe_real swap[4] = {0, 1, 1, 0};
    vlbe_real LU[N * N], P[N * N], b[N], tiny[4];
    int piv[N], info, i;
    (void)state;
    /* [[0,1],[1,0]] x = (2,3)  ->  x = (3,2), exactly */
    b[0] = 2, b[1] = 3;
    assert_int_equal(vlbe_lu_factor(2, swap, LU, piv, &info), VLBE_OK);
    assert_int_equal(piv[0], 1);
    vlbe_lu_solve(2, LU, piv, 1, b);
    ASSERT_CLOSE(b[0], 3.0, 0, 0); /* permutations are exact */
    ASSERT_CLOSE(b[1], 2.0, 0, 0);
    /* P[i][(i + 4) % N] = 1: every diagonal entry 0; P x = b puts b_i in
       x_{(i+4)%N} */
    vlbe_vec_zero(N * N, P);
    for (i = 0; i < N; ++i) P[i * N + (i + 4) % N] = 1, b[i] = (vlbe_real)(10 + i);
    assert_int_equal(vlbe_lu_factor(N, P, LU, piv, &info), VLBE_OK);
    vlbe_lu_solve(N, LU, piv, 1, b);
    for (i = 0; i < N; ++i) ASSERT_CLOSE(b[(i + 4) % N], 10.0 + i, 0, 0); /* exact */
    /* [[t,1],[1,1]] with t << eps: without the row swap the multiplier 1/t
       would wipe out the 1 in the (2,2) entry; x = (1,1)/(1-t) + O(t) */
    tiny[0] = (vlbe_real)(EPS * EPS), tiny[1] = 1, tiny[2] = 1, tiny[3] = 1;
    b[0] = 1, b[1] = 2;
    assert_int_equal(vlbe_lu_factor(2, tiny, LU, piv, &info), VLBE_OK);
    vlbe_lu_solve(2, LU, piv, 1, b);
    ASSERT_CLOSE(b[0], 1.0, 2 * EPS, 0); /* a well-conditioned 2 x 2: a few roundings */
    ASSERT_CLOSE(b[1], 1.0, 2 * EPS, 0);
}

/* A = L U built from small dyadic numbers (|l| <= 1, integer U), so that
   elimination with partial pivoting is exact, keeps the row order and must
   give back L and U; with U[c][c] = 0 the matrix is singular with a
   first zero pivot in column c + 1 (1-based), while no column of A is zero. */
static void build_exact_lu(tu_rng *g, int n, int c, vlbe_real *A, vlbe_real *LUref)
{
    static const double lv[5] = {-1.0, -0.5, 0.0, 0.5, 1.0};
    static const double dv[6] = {-3.0, -2.0, -1.0, 1.0, 2.0, 3.0};
    double L[8 * 8], U[8 * 8];
    int i, j, k;
    assert_true(n <= 8);
    for (i = 0; i < n; ++i)
        for (j = 0; j < n; ++j) {
            const double u = tu_rng_uniform(g); /* [-1, 1) */
            L[i * n + j] = i == j ? 1.0 : (j < i ? lv[(int)((u + 1.0) * 2.5)] : 0.0);
            U[i * n + j] = j < i ? 0.0
                           : j == i ? (i == c ? 0.0 : dv[(int)((u + 1.0) * 3.0)])
                                    : floor(2.5 * u); /* -3..2 */
        }
    for (i = 0; i < n; ++i)
        for (j = 0; j < n; ++j) {
            double s = 0.0;
            for (k = 0; k < n; ++k) s += L[i * n + k] * U[k * n + j];
            A[i * n + j] = (vlbe_real)s;
            LUref[i * n + j] = (vlbe_real)(j < i ? L[i * n + j] : U[i * n + j]);
        }
}

static void test_lu_exact_factor(void **state)
{
    enum { N = 7 };
    vlbe_real A[N * N], ref[N * N], LU[N * N];
    int piv[N], info, t, i;
    tu_rng g = tu_rng_seed(99);
    (void)state;
    for (t = 0; t < 20; ++t) {
        build_exact_lu(&g, N, -1, A, ref);
        assert_int_equal(vlbe_lu_factor(N, A, LU, piv, &info), VLBE_OK);
        for (i = 0; i < N; ++i) assert_int_equal(piv[i], i);
        ASSERT_VEC_CLOSE(LU, ref, N * N, 0, 0); /* dyadic data: exact */
    }
}

/* Exactly singular matrices: VLBE_ESINGULAR, info = the 1-based column, A
   untouched (out of place); info may be NULL. */
static void check_singular(int n, const vlbe_real *A, int want_info)
{
    vlbe_real copy[8 * 8], LU[8 * 8];
    int piv[8], info = -1;
    assert_true(n <= 8);
    memcpy(copy, A, (size_t)(n * n) * sizeof(vlbe_real));
    assert_int_equal(vlbe_lu_factor(n, A, LU, piv, &info), VLBE_ESINGULAR);
    assert_int_equal(info, want_info);
    assert_memory_equal(A, copy, (size_t)(n * n) * sizeof(vlbe_real));
    assert_int_equal(vlbe_lu_factor(n, A, LU, piv, NULL), VLBE_ESINGULAR);
}

static void test_lu_singular(void **state)
{
    enum { N = 7 };
    /* rows 2 and 3 equal: after the swap and one step the third column of
       the remaining row is exactly zero */
    const vlbe_real equal_rows[9] = {1, 2, 3, 4, 5, 6, 4, 5, 6};
    vlbe_real A[N * N], ref[N * N], Z[N * N];
    tu_rng g = tu_rng_seed(2024);
    int c, t;
    (void)state;
    check_singular(3, equal_rows, 3);
    for (c = 0; c < N; ++c)
        for (t = 0; t < 5; ++t) { /* rank deficient at column c + 1, no zero column */
            build_exact_lu(&g, N, c, A, ref);
            check_singular(N, A, c + 1);
        }
    for (c = 0; c < N; ++c) { /* zero column c: it stays zero through elimination */
        int i;
        fill_random(&g, N, N, 0.0, A);
        for (i = 0; i < N; ++i) A[i * N + c] = 0;
        check_singular(N, A, c + 1);
    }
    vlbe_vec_zero(N * N, Z);
    check_singular(N, Z, 1);
    check_singular(1, Z, 1);
}

/* |pivot| <= n eps max|A| counts as zero (documented): [[1,1],[1,1+d]] has
   the pivot d after one step. */
static void test_lu_relative_zero_pivot(void **state)
{
    vlbe_real A[4] = {1, 1, 1, 1}, LU[4];
    int piv[2], info;
    (void)state;
    A[3] = 1 + VLBE_EPS; /* pivot eps <= 2 eps (1 + eps): rejected */
    check_singular(2, A, 2);
    A[3] = 1 + 4 * VLBE_EPS; /* pivot 4 eps > 2 eps (1 + 4 eps): accepted */
    assert_int_equal(vlbe_lu_factor(2, A, LU, piv, &info), VLBE_OK);
    assert_int_equal(info, 0);
}

static void test_lu_nonfinite(void **state)
{
    enum { N = 4 };
    const vlbe_real bad[3] = {(vlbe_real)NAN, (vlbe_real)INFINITY, -(vlbe_real)INFINITY};
    const int pos[3] = {0, 6, N * N - 1};
    vlbe_real A[N * N], copy[N * N], LU[N * N];
    int piv[N], info, b, q;
    tu_rng g = tu_rng_seed(5);
    (void)state;
    for (b = 0; b < 3; ++b)
        for (q = 0; q < 3; ++q) {
            fill_random(&g, N, N, N, A);
            A[pos[q]] = bad[b];
            memcpy(copy, A, sizeof A);
            assert_int_equal(vlbe_lu_factor(N, A, LU, piv, &info), VLBE_ENONFINITE);
            assert_memory_equal(A, copy, sizeof A);
        }
}

/* LU == A: the factor overwrites A and equals the out-of-place factor bit
   for bit; the solve works from it. */
static void test_lu_in_place(void **state)
{
    enum { N = 10 };
    vlbe_real A[N * N], X[N * N], LU[N * N], x[N], b[N];
    int piv[N], piv2[N], info, i;
    tu_rng g = tu_rng_seed(31);
    (void)state;
    fill_random(&g, N, N, 0.0, A);
    memcpy(X, A, sizeof A);
    assert_int_equal(vlbe_lu_factor(N, A, LU, piv, &info), VLBE_OK);
    assert_int_equal(vlbe_lu_factor(N, X, X, piv2, &info), VLBE_OK);
    ASSERT_VEC_CLOSE(X, LU, N * N, 0, 0); /* same operations */
    for (i = 0; i < N; ++i) assert_int_equal(piv[i], piv2[i]);
    fill_random(&g, N, 1, 0.0, x);
    mat_mul_ref(N, 1, A, x, b);
    vlbe_vec_copy(N, b, x);
    vlbe_lu_solve(N, X, piv2, 1, x);
    check_residual(N, 1, 0, A, x, b);
    /* in place and singular: still reported */
    vlbe_vec_zero(N * N, X);
    assert_int_equal(vlbe_lu_factor(N, X, X, piv2, &info), VLBE_ESINGULAR);
    assert_int_equal(info, 1);
}

static void test_lu_flops(void **state)
{
    (void)state;
    ASSERT_CLOSE(vlbe_lu_flops(3), 18.0, 4 * EPS, 0); /* 2/3 rounded, then 3 products */
    ASSERT_CLOSE(vlbe_lu_flops(1), 2.0 / 3.0, 4 * EPS, 0);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_status_str),
        cmocka_unit_test(test_all_finite),
        cmocka_unit_test(test_vec2),
        cmocka_unit_test(test_vec3),
        cmocka_unit_test(test_vec_n),
        cmocka_unit_test(test_vec_norms),
        cmocka_unit_test(test_mat_vec),
        cmocka_unit_test(test_gl_exactness),
        cmocka_unit_test(test_gl_not_exact_2n),
        cmocka_unit_test(test_gl_nodes_weights),
        cmocka_unit_test(test_gl_bad_n),
        cmocka_unit_test(test_herm_s_form),
        cmocka_unit_test(test_herm_interpolation),
        cmocka_unit_test(test_herm_reproduction_and_partials),
        cmocka_unit_test(test_herm_fd),
        cmocka_unit_test(test_herm_subsets),
        cmocka_unit_test(test_lu_random_dominant),
        cmocka_unit_test(test_lu_random_general),
        cmocka_unit_test(test_lu_pivoting),
        cmocka_unit_test(test_lu_exact_factor),
        cmocka_unit_test(test_lu_singular),
        cmocka_unit_test(test_lu_relative_zero_pivot),
        cmocka_unit_test(test_lu_nonfinite),
        cmocka_unit_test(test_lu_in_place),
        cmocka_unit_test(test_lu_flops),
    };
    return cmocka_run_group_tests_name("vlbe", tests, NULL, NULL);
}

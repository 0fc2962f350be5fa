/* test_contract_elem.c -- the failure contract of the element routines:
   planar ALE-ANCF element (ancf_ale.h), its invariant route, the 3D
   beam-shaft element, every rancf.h routine and the co-rotational element
   and transition element of corot2d.h
   -- part of vlbe                                 SPDX-License-Identifier: MIT
   cc -std=c99 -Wall -Wextra -Wpedantic ... -O2 tests/test_contract_elem.c -lcmocka -lm
   (add -DVLBE_USE_FLOAT for the float build; the same source passes in both)

   The contract (every status-returning routine): finite input never gives
   VLBE_OK with a NaN or Inf in an output (VLBE_ENONFINITE instead, or
   VLBE_ELENGTH / VLBE_EWEIGHT when a degenerate length or weight set is
   the cause); a failing call leaves every output bitwise as it was; sizes
   are range-checked (VLBE_EARG).  Every output below is pre-filled with a
   sentinel byte pattern (or, for accumulating outputs, finite values) and
   compared byte for byte with its snapshot after a failing call.

   Reproductions are given in both precisions: the double values (1e-100,
   1e300, ...) are not representable in float, so the float build uses
   values that provoke the same overflow there (L^-4 overflows float for
   L < 4.7e-10, a squared slope of 1e24 times a stiffness overflows, a
   weight ratio of 1e60 is out of float's range); each test says which.
   No tolerance is used: the checks are status codes, finiteness and
   bitwise equality.  VLBE_TEST_REPORT=1 prints how many calls the extreme
   sweep made and how many of them returned VLBE_OK (a sweep whose calls
   were all refused would check no finite output).

   Tests
     ale_force_tiny_length   L = 1e-100 (float 1e-30): L^-4 overflows
     ale_force_huge_slope    slope 1e100 (float 1e12): Q overflows
     ale_subnormal_length    L = 1e-320 (float 1e-44): 1/L is Inf; every
                             planar and rational element call
     ale_mass_huge_slope     mass, mass_jac, energy, strain with slope 1e160
                             (float 1e20)
     ale3_overflow           3D element: tiny L, huge slope, huge rates
     ale3_mat_circle         section constants that overflow
     inv_chain_tiny_length   vlbe_ale_inv_chain_force with L = 1e-320 (float
                             1e-44), huge slopes, bad ne
     inv_sys_overflow        vlbe_ale_inv_sys_init with L = 1e-320, sys_force
                             with huge coordinates
     inv_chain_huge_damping  chain and system forces with EA = 1e-320 (float
                             1e-44) and c_eps = REAL_MAX
     rancf_to_bezier_weights w = {1e300, 1e-300, 1, 1} (float 1e30, 1e-30)
     rancf_split_weights     w = {1e-300, 1, 1, 1e300} (float 1e-30, 1e30)
     rancf_elem_init_weights ratio underflow; float: basis overflow at 1e-20
     rancf_misc              basis_eval with a tiny L, arc and NURBS whose
                             coordinates overflow
     cr2d_elem_init_tiny     X2 - X1 = 1e-120 (float 1e-14): k0 overflows
     cr2d_overflow           force, energy, local, transition force with
                             huge rates or coordinates
     cr2d_position_overflow  X + q overflows: NaN frame; mass, force, energy
     extreme_sweep           every element routine of the planar, rational
                             and 3D elements on a table of extreme inputs:
                             OK implies finite outputs, failure implies
                             untouched outputs */
#include "test_util.h"
#include "../rancf.h"
#include "../corot2d.h"

#include <limits.h>

typedef vlbe_real R;

#ifdef VLBE_USE_FLOAT
#define TINY_L VLBE_R(1e-30)  /* L^-4 = 1e120 overflows float           */
#define SUBN_L VLBE_R(1e-44)  /* subnormal: 1/L = Inf                   */
#define BIG_SLOPE VLBE_R(1e12) /* eps ~ 1e24, EA eps r' ~ 1e38+         */
#define HUGE_SLOPE VLBE_R(1e20) /* |r'|^2 = 1e40 overflows             */
#define W_BIG VLBE_R(1e30)
#define W_SMALL VLBE_R(1e-30)
#define CR_TINY VLBE_R(1e-14) /* |X2 - X1|^-3 = 1e42 overflows float    */
#define HUGE_RATE VLBE_R(1e20) /* q'^2 = 1e40 overflows                 */
#define NEAR_MAX VLBE_R(3e38)
#define HUGE_L VLBE_R(1e25)    /* L^2 = 1e50 overflows                  */
#else
#define TINY_L 1e-100
#define SUBN_L 1e-320
#define BIG_SLOPE 1e100
#define HUGE_SLOPE 1e160
#define W_BIG 1e300
#define W_SMALL 1e-300
#define CR_TINY 1e-120
#define HUGE_RATE 1e160
#define NEAR_MAX 1e308
#define HUGE_L 1e200
#endif

/* -- sentinel snapshots ---------------------------------------------------- */
#define SN_MAX 8
static struct {
    void *p;
    size_t n;
    unsigned char s[24576];
} sn_[SN_MAX];
static int sn_n_;

static void sn_begin(void) { sn_n_ = 0; }

/* fill with the sentinel pattern (0xA5 bytes) and remember */
static void sn_fill(void *p, size_t bytes)
{
    assert_true(sn_n_ < SN_MAX && bytes <= sizeof sn_[0].s);
    memset(p, 0xA5, bytes);
    sn_[sn_n_].p = p;
    sn_[sn_n_].n = bytes;
    memcpy(sn_[sn_n_].s, p, bytes);
    ++sn_n_;
}

/* remember as is (accumulating outputs, structs) */
static void sn_keep(void *p, size_t bytes)
{
    assert_true(sn_n_ < SN_MAX && bytes <= sizeof sn_[0].s);
    sn_[sn_n_].p = p;
    sn_[sn_n_].n = bytes;
    memcpy(sn_[sn_n_].s, p, bytes);
    ++sn_n_;
}

static int sn_same(void)
{
    int i;
    for (i = 0; i < sn_n_; ++i)
        if (memcmp(sn_[i].p, sn_[i].s, sn_[i].n) != 0) return 0;
    return 1;
}

static int all_fin(const R *x, int n)
{
    int i;
    for (i = 0; i < n; ++i)
        if (!isfinite(x[i])) return 0;
    return 1;
}

/* the status is `want` and nothing was written */
#define EXPECT_FAIL(call, want)                                                          \
    do {                                                                                 \
        const vlbe_status st_ = (call);                                                  \
        if (st_ != (want))                                                               \
            fail_msg("%s: status %s, expected %s", #call, vlbe_status_str(st_),          \
                     vlbe_status_str(want));                                             \
        if (!sn_same()) fail_msg("%s: an output was written on failure", #call);       \
    } while (0)

/* -- fixtures -------------------------------------------------------------- */
static vlbe_ale_mat ale_mat(void)
{
    vlbe_ale_mat m;
    memset(&m, 0, sizeof m);
    m.rhoA = 2;
    m.EA = 100;
    m.EI = 3;
    m.c_eps = VLBE_R(0.01);
    m.c_kap = VLBE_R(0.01);
    m.f[1] = -5;
    return m;
}

/* a straight, slightly bent element of length L, slopes of size sl, free p */
static void ale_q(R L, R sl, R *q, R *qd)
{
    const R q0[10] = {0, 0, sl, VLBE_R(0.1) * sl, 0, L, VLBE_R(0.05) * L, sl, 0, L};
    const R qd0[10] = {VLBE_R(0.1), 0, 0, VLBE_R(0.2), VLBE_R(0.3), 0, VLBE_R(0.1), 0, 0,
                       VLBE_R(-0.2)};
    memcpy(q, q0, sizeof q0);
    memcpy(qd, qd0, sizeof qd0);
}

static vlbe_ale_elem el_;
static vlbe_rancf_elem rel_;
static vlbe_ale3_elem el3_;

static int setup(void **state)
{
    vlbe_ale_mat m = ale_mat();
    vlbe_ale3_mat m3;
    const R w[4] = {1, VLBE_R(0.9), VLBE_R(1.2), 1};
    (void)state;
    if (vlbe_ale_elem_init(&el_, &m, 0, 0, 0, 0) != VLBE_OK) return -1;
    if (vlbe_rancf_elem_init(&rel_, &m, w, 0, 0, 0, 0) != VLBE_OK) return -1;
    if (vlbe_ale3_mat_circle(&m3, 7800, VLBE_R(2e11), VLBE_R(8e10), VLBE_R(0.01)) != VLBE_OK)
        return -1;
    m3.c_eps = m3.c_kap = m3.c_phi = VLBE_R(0.001);
    m3.f[2] = -1;
    if (vlbe_ale3_elem_init(&el3_, &m3, 0, 0, 0) != VLBE_OK) return -1;
    return 0;
}

/* -- planar element ------------------------------------------------------ */
/* fails on 77b73ad: VLBE_OK with Q = NaN (L^-4 = Inf in the basis scaling) */
static void test_ale_force_tiny_length(void **state)
{
    R q[10], qd[10], Q[10], K[100], D[100];
    (void)state;
    ale_q(TINY_L, 1, q, qd);
    sn_begin();
    sn_fill(Q, sizeof Q);
    EXPECT_FAIL(vlbe_ale_force(&el_, 0, q, qd, Q, NULL, NULL), VLBE_ELENGTH);
    sn_begin();
    sn_fill(Q, sizeof Q);
    sn_fill(K, sizeof K);
    sn_fill(D, sizeof D);
    EXPECT_FAIL(vlbe_ale_force(&el_, 0, q, qd, Q, K, D), VLBE_ELENGTH);
    EXPECT_FAIL(vlbe_ale_force(&el_, VLBE_ALE_INV_AXIAL, q, qd, Q, K, D), VLBE_ELENGTH);
    EXPECT_FAIL(vlbe_ale_inv_force(&el_, 0, q, qd, Q, K, D), VLBE_ELENGTH);
    EXPECT_FAIL(vlbe_rancf_force(&rel_, 0, q, qd, Q, K, D), VLBE_ELENGTH);
}

/* fails on 77b73ad: VLBE_OK with Q[4] = NaN (eps ~ slope^2 overflows) */
static void test_ale_force_huge_slope(void **state)
{
    R q[10], qd[10], Q[10], K[100], D[100];
    (void)state;
    ale_q(1, BIG_SLOPE, q, qd);
    sn_begin();
    sn_fill(Q, sizeof Q);
    EXPECT_FAIL(vlbe_ale_force(&el_, 0, q, qd, Q, NULL, NULL), VLBE_ENONFINITE);
    sn_begin();
    sn_fill(Q, sizeof Q);
    sn_fill(K, sizeof K);
    sn_fill(D, sizeof D);
    EXPECT_FAIL(vlbe_ale_force(&el_, 0, q, qd, Q, K, D), VLBE_ENONFINITE);
    EXPECT_FAIL(vlbe_ale_force(&el_, VLBE_ALE_INV_AXIAL, q, qd, Q, K, D), VLBE_ENONFINITE);
    EXPECT_FAIL(vlbe_rancf_force(&rel_, 0, q, qd, Q, K, D), VLBE_ENONFINITE);
    /* the same element with a normal slope still works */
    ale_q(1, 1, q, qd);
    assert_int_equal(vlbe_ale_force(&el_, 0, q, qd, Q, K, D), VLBE_OK);
    assert_true(all_fin(Q, 10) && all_fin(K, 100) && all_fin(D, 100));
}

/* fails on 77b73ad: VLBE_OK with NaN from mass, mass_jac, point, split,
   point_force (1/L = Inf) */
static void test_ale_subnormal_length(void **state)
{
    R q[10], qd[10], M[100], E[3], r[2], rp[2], eps, kap, qh[5], qhd[5], Q[10], K[100];
    const R F[2] = {1, 2};
    int i;
    (void)state;
    ale_q(SUBN_L, 1, q, qd);
    assert_true(q[9] > 0);
    sn_begin();
    sn_fill(M, sizeof M);
    sn_fill(E, sizeof E);
    sn_fill(r, sizeof r);
    sn_fill(rp, sizeof rp);
    sn_fill(&eps, sizeof eps);
    sn_fill(&kap, sizeof kap);
    sn_fill(qh, sizeof qh);
    sn_fill(qhd, sizeof qhd);
    EXPECT_FAIL(vlbe_ale_mass(&el_, 0, q, M), VLBE_ELENGTH);
    EXPECT_FAIL(vlbe_ale_mass_jac(&el_, 0, q, qd, M), VLBE_ELENGTH);
    EXPECT_FAIL(vlbe_ale_energy(&el_, 0, q, qd, E), VLBE_ELENGTH);
    EXPECT_FAIL(vlbe_ale_point(q, q[9] / 2, r, rp), VLBE_ELENGTH);
    EXPECT_FAIL(vlbe_ale_strain(q, q[9] / 3, &eps, &kap), VLBE_ELENGTH);
    EXPECT_FAIL(vlbe_ale_split(q, qd, q[9] / 3, qh, qhd), VLBE_ELENGTH);
    EXPECT_FAIL(vlbe_rancf_mass(&rel_, 0, q, M), VLBE_ELENGTH);
    EXPECT_FAIL(vlbe_rancf_mass_jac(&rel_, 0, q, qd, M), VLBE_ELENGTH);
    EXPECT_FAIL(vlbe_rancf_energy(&rel_, 0, q, qd, E), VLBE_ELENGTH);
    EXPECT_FAIL(vlbe_rancf_point(&rel_, q, q[9] / 2, r, rp), VLBE_ELENGTH);
    EXPECT_FAIL(vlbe_rancf_strain(&rel_, q, q[9] / 3, &eps, &kap), VLBE_ELENGTH);
    EXPECT_FAIL(vlbe_rancf_split(&rel_, q, qd, q[9] / 3, qh, qhd, NULL, NULL), VLBE_ELENGTH);
    /* accumulating outputs: finite contents kept */
    for (i = 0; i < 10; ++i) Q[i] = (R)i;
    for (i = 0; i < 100; ++i) K[i] = (R)(i % 7);
    sn_begin();
    sn_keep(Q, sizeof Q);
    sn_keep(K, sizeof K);
    EXPECT_FAIL(vlbe_ale_point_force(q, q[9] / 3, F, Q, K), VLBE_ELENGTH);
    EXPECT_FAIL(vlbe_rancf_point_force(&rel_, q, q[9] / 3, F, Q, K), VLBE_ELENGTH);
}

/* fails on 77b73ad: VLBE_OK with M[44] = Inf, Mq = NaN, E = Inf, eps = Inf,
   and Mq = Inf for a huge acceleration */
static void test_ale_mass_huge_slope(void **state)
{
    R q[10], qd[10], M[100], E[3], eps, kap;
    (void)state;
    ale_q(1, HUGE_SLOPE, q, qd);
    sn_begin();
    sn_fill(M, sizeof M);
    sn_fill(E, sizeof E);
    sn_fill(&eps, sizeof eps);
    sn_fill(&kap, sizeof kap);
    EXPECT_FAIL(vlbe_ale_mass(&el_, 0, q, M), VLBE_ENONFINITE);
    EXPECT_FAIL(vlbe_ale_mass_jac(&el_, 0, q, qd, M), VLBE_ENONFINITE);
    EXPECT_FAIL(vlbe_ale_energy(&el_, 0, q, qd, E), VLBE_ENONFINITE);
    EXPECT_FAIL(vlbe_ale_strain(q, VLBE_R(0.3), &eps, NULL), VLBE_ENONFINITE);
    EXPECT_FAIL(vlbe_rancf_mass(&rel_, 0, q, M), VLBE_ENONFINITE);
    EXPECT_FAIL(vlbe_rancf_energy(&rel_, 0, q, qd, E), VLBE_ENONFINITE);
    /* a short element (L = 0.01) with an acceleration near REAL_MAX:
       d(M a)/dq overflows (its p-columns carry 1/L) */
    ale_q(VLBE_R(0.01), 1, q, qd);
    qd[2] = NEAR_MAX;
    qd[4] = NEAR_MAX;
    EXPECT_FAIL(vlbe_ale_mass_jac(&el_, 0, q, qd, M), VLBE_ENONFINITE);
    EXPECT_FAIL(vlbe_rancf_mass_jac(&rel_, 0, q, qd, M), VLBE_ENONFINITE);
}

/* -- 3D element ------------------------------------------------------------ */
static void ale3_q(R L, R sl, R rate, R *q, R *qd)
{
    int i;
    for (i = 0; i < 16; ++i) q[i] = qd[i] = 0;
    q[3] = sl;
    q[4] = VLBE_R(0.1) * sl;
    q[7] = 0;
    q[8] = L;
    q[9] = VLBE_R(0.05) * L;
    q[11] = sl;
    q[15] = L;
    qd[0] = VLBE_R(0.1) * rate;
    qd[6] = rate;
    qd[7] = VLBE_R(0.3) * rate;
    qd[14] = rate;
    qd[15] = VLBE_R(-0.2) * rate;
}

/* fails on 77b73ad: VLBE_OK with NaN (Q, M, Mq, energy, point, point
   loads) */
static void test_ale3_overflow(void **state)
{
    R q[16], qd[16], Q[16], K[256], D[256], M[256], E[3], r[3], rp[3], th, e, k, ph;
    const R F[3] = {1, 2, 3};
    int i;
    (void)state;
    sn_begin();
    sn_fill(Q, sizeof Q);
    sn_fill(K, sizeof K);
    sn_fill(D, sizeof D);
    sn_fill(M, sizeof M);
    sn_fill(E, sizeof E);
    sn_fill(r, sizeof r);
    sn_fill(rp, sizeof rp);
    sn_fill(&th, sizeof th);
    ale3_q(TINY_L, 1, 1, q, qd);
    EXPECT_FAIL(vlbe_ale3_force(&el3_, 0, q, qd, Q, K, D), VLBE_ELENGTH);
    EXPECT_FAIL(vlbe_ale3_force(&el3_, 0, q, qd, Q, NULL, NULL), VLBE_ELENGTH);
    ale3_q(SUBN_L, 1, 1, q, qd);
    EXPECT_FAIL(vlbe_ale3_mass(&el3_, 0, q, M), VLBE_ELENGTH);
    EXPECT_FAIL(vlbe_ale3_mass_jac(&el3_, 0, q, qd, M), VLBE_ELENGTH);
    EXPECT_FAIL(vlbe_ale3_point(0, q, q[15] / 2, r, rp, &th), VLBE_ELENGTH);
    ale3_q(1, HUGE_SLOPE, 1, q, qd);
    EXPECT_FAIL(vlbe_ale3_force(&el3_, 0, q, qd, Q, K, D), VLBE_ENONFINITE);
    EXPECT_FAIL(vlbe_ale3_mass(&el3_, 0, q, M), VLBE_ENONFINITE);
    EXPECT_FAIL(vlbe_ale3_mass_jac(&el3_, 0, q, qd, M), VLBE_ENONFINITE);
    EXPECT_FAIL(vlbe_ale3_energy(&el3_, 0, q, qd, E), VLBE_ENONFINITE);
    ale3_q(1, 1, HUGE_RATE, q, qd);
    EXPECT_FAIL(vlbe_ale3_force(&el3_, 0, q, qd, Q, NULL, NULL), VLBE_ENONFINITE);
    EXPECT_FAIL(vlbe_ale3_energy(&el3_, 0, q, qd, E), VLBE_ENONFINITE);
    sn_begin();
    sn_fill(&e, sizeof e);
    sn_fill(&k, sizeof k);
    sn_fill(&ph, sizeof ph);
    ale3_q(1, HUGE_SLOPE, 1, q, qd);
    EXPECT_FAIL(vlbe_ale3_strain(0, q, VLBE_R(0.3), &e, &k, &ph), VLBE_ENONFINITE);
    ale3_q(SUBN_L, 1, 1, q, qd);
    for (i = 0; i < 16; ++i) Q[i] = (R)i;
    for (i = 0; i < 256; ++i) K[i] = (R)(i % 5);
    sn_begin();
    sn_keep(Q, sizeof Q);
    sn_keep(K, sizeof K);
    EXPECT_FAIL(vlbe_ale3_point_force(0, q, q[15] / 3, F, Q, K), VLBE_ELENGTH);
    EXPECT_FAIL(vlbe_ale3_point_torque(0, q, q[15] / 3, 2, Q, K), VLBE_ELENGTH);
}

/* fails on 77b73ad: VLBE_OK with rhoA = EA = Inf for a radius of 1e200
   (float 1e20: r^4 overflows) */
static void test_ale3_mat_circle(void **state)
{
#ifdef VLBE_USE_FLOAT
    const R big = VLBE_R(1e20);
#else
    const R big = 1e200;
#endif
    vlbe_ale3_mat m;
    (void)state;
    memset(&m, 0x5A, sizeof m);
    sn_begin();
    sn_keep(&m, sizeof m);
    EXPECT_FAIL(vlbe_ale3_mat_circle(&m, 7800, VLBE_R(2e11), VLBE_R(8e10), big), VLBE_ENONFINITE);
    assert_int_equal(vlbe_ale3_mat_circle(&m, 7800, VLBE_R(2e11), VLBE_R(8e10), VLBE_R(0.01)),
                     VLBE_OK);
    assert_true(all_fin(&m.rhoA, 5) && m.rhoA > 0);
}

/* -- invariant route ------------------------------------------------------ */
#define NE 3
#define NX (4 * (NE + 1))

static void chain_x(R sl, R *x, R *v)
{
    int i;
    for (i = 0; i <= NE; ++i) {
        x[4 * i] = VLBE_R(0.5) * (R)i;
        x[4 * i + 1] = VLBE_R(0.01) * (R)i;
        x[4 * i + 2] = sl;
        x[4 * i + 3] = 0;
        v[4 * i] = v[4 * i + 2] = 0;
        v[4 * i + 1] = VLBE_R(0.1) * (R)i;
        v[4 * i + 3] = VLBE_R(0.01);
    }
}

/* fails on 77b73ad: VLBE_OK with NaN in Q (L = 1e-320, L = 1e200: float
   1e-44, 1e25); ne = 0 and a huge ne hit VLBE_ASSERT (abort) there */
static void test_inv_chain_tiny_length(void **state)
{
    static R K[NX * VLBE_ALE_INV_BW], D[NX * VLBE_ALE_INV_BW];
    R x[NX], v[NX], Q[NX], L[NE] = {VLBE_R(0.5), VLBE_R(0.5), VLBE_R(0.5)};
    (void)state;
    chain_x(1, x, v);
    assert_int_equal(vlbe_ale_inv_chain_force(&el_, VLBE_ALE_INV_AXIAL, NE, L, x, v, Q, K, D),
                     VLBE_OK);
    assert_true(all_fin(Q, NX) && all_fin(K, NX * VLBE_ALE_INV_BW));
    sn_begin();
    sn_fill(Q, sizeof Q);
    sn_fill(K, sizeof K);
    sn_fill(D, sizeof D);
    L[1] = SUBN_L;
    EXPECT_FAIL(vlbe_ale_inv_chain_force(&el_, 0, NE, L, x, v, Q, K, D), VLBE_ELENGTH);
    EXPECT_FAIL(vlbe_ale_inv_chain_force(&el_, VLBE_ALE_INV_AXIAL, NE, L, x, v, Q, NULL, NULL),
                VLBE_ELENGTH);
    L[1] = TINY_L;
    EXPECT_FAIL(vlbe_ale_inv_chain_force(&el_, 0, NE, L, x, v, Q, K, D), VLBE_ELENGTH);
    L[1] = HUGE_L; /* the load rows' w N = L^2 overflows */
    EXPECT_FAIL(vlbe_ale_inv_chain_force(&el_, 0, NE, L, x, v, Q, K, D), VLBE_ENONFINITE);
    L[1] = VLBE_R(0.5);
    chain_x(BIG_SLOPE, x, v);
    EXPECT_FAIL(vlbe_ale_inv_chain_force(&el_, 0, NE, L, x, v, Q, K, D), VLBE_ENONFINITE);
    EXPECT_FAIL(vlbe_ale_inv_chain_force(&el_, VLBE_ALE_INV_AXIAL, NE, L, x, NULL, Q, NULL, NULL),
                VLBE_ENONFINITE);
    chain_x(1, x, v);
    EXPECT_FAIL(vlbe_ale_inv_chain_force(&el_, 0, 0, L, x, v, Q, K, D), VLBE_EARG);
    EXPECT_FAIL(vlbe_ale_inv_chain_force(&el_, 0, INT_MAX, L, x, v, Q, K, D), VLBE_EARG);
    EXPECT_FAIL(vlbe_ale_inv_chain_force(&el_, 0, INT_MAX / 60, L, x, v, Q, K, D), VLBE_EARG);
}

/* fails on 77b73ad: sys_init returned VLBE_OK with Inf tables for L =
   1e-320; sys_force VLBE_OK with NaN forces for huge slopes */
static void test_inv_sys_overflow(void **state)
{
    static R work[88 * NE + 16], K[NX * VLBE_ALE_INV_BW], D[NX * VLBE_ALE_INV_BW];
    R x[NX], v[NX], Q[NX], L[NE] = {VLBE_R(0.5), VLBE_R(0.5), VLBE_R(0.5)};
    vlbe_ale_inv_sys sys;
    (void)state;
    assert_true(vlbe_ale_inv_sys_work_len(NE) <= sizeof work / sizeof work[0]);
    memset(&sys, 0x5A, sizeof sys);
    sn_begin();
    sn_keep(&sys, sizeof sys);
    sn_fill(work, sizeof work);
    L[2] = SUBN_L;
    EXPECT_FAIL(vlbe_ale_inv_sys_init(&sys, &el_, 0, NE, L, work, sizeof work / sizeof work[0]),
                VLBE_ELENGTH);
    L[2] = VLBE_R(0.5);
    assert_int_equal(vlbe_ale_inv_sys_init(&sys, &el_, 0, NE, L, work,
                                           sizeof work / sizeof work[0]),
                     VLBE_OK);
    chain_x(BIG_SLOPE, x, v);
    sn_begin();
    sn_fill(Q, sizeof Q);
    sn_fill(K, sizeof K);
    sn_fill(D, sizeof D);
    EXPECT_FAIL(vlbe_ale_inv_sys_force(&sys, x, v, Q, K, D), VLBE_ENONFINITE);
    EXPECT_FAIL(vlbe_ale_inv_sys_force(&sys, x, NULL, Q, NULL, NULL), VLBE_ENONFINITE);
    chain_x(1, x, v);
    assert_int_equal(vlbe_ale_inv_sys_force(&sys, x, v, Q, K, D), VLBE_OK);
    assert_true(all_fin(Q, NX) && all_fin(K, NX * VLBE_ALE_INV_BW) &&
                all_fin(D, NX * VLBE_ALE_INV_BW));
}

/* fails on bc748ae: VLBE_OK with NaN in Q (and K, D) from the invariant
   route of vlbe_ale_inv_chain_force and from vlbe_ale_inv_sys_force for a
   subnormal EA (1e-320, float 1e-44) and c_eps = REAL_MAX: the force bound
   weighed the damping only through EA (1 + c), but the invariant products
   form c (r' . v') before EA multiplies it, and that overflows alone.  (The
   Gauss route forms EA c first and stayed finite; it shares the bound.) */
static void test_inv_chain_huge_damping(void **state)
{
    static R work[88 * NE + 16], K[NX * VLBE_ALE_INV_BW], D[NX * VLBE_ALE_INV_BW];
    R x[NX], v[NX], Q[NX], L[NE] = {VLBE_R(0.5), VLBE_R(0.5), VLBE_R(0.5)};
    vlbe_ale_mat m = ale_mat();
    vlbe_ale_elem el;
    vlbe_ale_inv_sys sys;
    int i;
    (void)state;
    m.EA = SUBN_L; /* EA c = 1.8e-12 (float 4.8e-6): the product alone is harmless */
    m.c_eps = VLBE_REAL_MAX;
    assert_int_equal(vlbe_ale_elem_init(&el, &m, 0, 0, 0, 0), VLBE_OK);
    chain_x(1, x, v);
    for (i = 0; i <= NE; ++i) { /* slope rates along the slopes: r' . v' = 1 */
        v[4 * i] = (R)i;
        v[4 * i + 2] = 1;
    }
    sn_begin();
    sn_fill(Q, sizeof Q);
    sn_fill(K, sizeof K);
    sn_fill(D, sizeof D);
    EXPECT_FAIL(vlbe_ale_inv_chain_force(&el, VLBE_ALE_INV_AXIAL, NE, L, x, v, Q, NULL, NULL),
                VLBE_ENONFINITE);
    EXPECT_FAIL(vlbe_ale_inv_chain_force(&el, VLBE_ALE_INV_AXIAL, NE, L, x, v, Q, K, D),
                VLBE_ENONFINITE);
    EXPECT_FAIL(vlbe_ale_inv_chain_force(&el, 0, NE, L, x, v, Q, K, D), VLBE_ENONFINITE);
    /* undamped: the same data are fine */
    assert_int_equal(vlbe_ale_inv_chain_force(&el, VLBE_ALE_INV_AXIAL | VLBE_ALE_NO_DAMP, NE, L,
                                              x, v, Q, K, D),
                     VLBE_OK);
    assert_true(all_fin(Q, NX) && all_fin(K, NX * VLBE_ALE_INV_BW) &&
                all_fin(D, NX * VLBE_ALE_INV_BW));
    /* the system route shares the bound */
    assert_true(vlbe_ale_inv_sys_work_len(NE) <= sizeof work / sizeof work[0]);
    assert_int_equal(vlbe_ale_inv_sys_init(&sys, &el, 0, NE, L, work,
                                           sizeof work / sizeof work[0]),
                     VLBE_OK);
    sn_begin();
    sn_fill(Q, sizeof Q);
    sn_fill(K, sizeof K);
    sn_fill(D, sizeof D);
    EXPECT_FAIL(vlbe_ale_inv_sys_force(&sys, x, v, Q, NULL, NULL), VLBE_ENONFINITE);
    EXPECT_FAIL(vlbe_ale_inv_sys_force(&sys, x, v, Q, K, D), VLBE_ENONFINITE);
}

/* -- rancf.h ----------------------------------------------------------- */
/* fails on 77b73ad: VLBE_OK with P[2] = Inf (l w0 / (3 w1) overflows) */
static void test_rancf_to_bezier_weights(void **state)
{
    const R w[4] = {W_BIG, W_SMALL, 1, 1};
    const R x[8] = {0, 0, 1, 0, 1, 0, 1, 0};
    R P[8], y[8];
    (void)state;
    sn_begin();
    sn_fill(P, sizeof P);
    sn_fill(y, sizeof y);
    EXPECT_FAIL(vlbe_rancf_to_bezier(2, w, 1, x, P), VLBE_EWEIGHT);
    EXPECT_FAIL(vlbe_rancf_from_bezier(2, w, 1, x, y), VLBE_EWEIGHT);
    EXPECT_FAIL(vlbe_rancf_to_bezier(0, w, 1, x, P), VLBE_EARG);
    EXPECT_FAIL(vlbe_rancf_to_bezier(4, w, 1, x, P), VLBE_EARG);
}

/* fails on 77b73ad: VLBE_OK with a left weight 0 and a NaN point (the
   homogeneous weight underflowed) */
static void test_rancf_split_weights(void **state)
{
    const R w[4] = {W_SMALL, 1, 1, W_BIG};
    const R P[8] = {0, 0, 1, 1, 2, 1, 3, 0};
    R wl[4], Pl[8], wr[4], Pr[8], r[2];
    (void)state;
    sn_begin();
    sn_fill(wl, sizeof wl);
    sn_fill(Pl, sizeof Pl);
    sn_fill(wr, sizeof wr);
    sn_fill(Pr, sizeof Pr);
    sn_fill(r, sizeof r);
    EXPECT_FAIL(vlbe_rancf_bezier_split(2, w, P, VLBE_R(0.5), wl, Pl, wr, Pr), VLBE_EWEIGHT);
    EXPECT_FAIL(vlbe_rancf_bezier_split(2, w, P, VLBE_R(0.5), wl, NULL, NULL, NULL),
                VLBE_EWEIGHT);
    EXPECT_FAIL(vlbe_rancf_bezier_eval(2, w, P, VLBE_R(0.5), r), VLBE_EWEIGHT);
}

/* fails on 77b73ad: init accepted the weights (k0 = w0 / w3 underflows to
   0); float: w0 = 1e-20 passed there too and gave an Inf/NaN basis table */
static void test_rancf_elem_init_weights(void **state)
{
    static vlbe_rancf_elem el;
    const vlbe_ale_mat m = ale_mat();
    const R w1[4] = {W_SMALL, 1, 1, W_BIG};
#ifdef VLBE_USE_FLOAT
    const R w2[4] = {VLBE_R(1e-20), 1, 1, 1};
#endif
    vlbe_herm_ale b;
    (void)state;
    memset(&el, 0x5A, sizeof el);
    sn_begin();
    sn_keep(&el, sizeof el);
    EXPECT_FAIL(vlbe_rancf_elem_init(&el, &m, w1, 0, 0, 0, 0), VLBE_EWEIGHT);
#ifdef VLBE_USE_FLOAT
    EXPECT_FAIL(vlbe_rancf_elem_init(&el, &m, w2, 0, 0, 0, 0), VLBE_EWEIGHT);
#endif
    sn_begin();
    sn_fill(&b, sizeof b);
    EXPECT_FAIL(vlbe_rancf_basis_eval(w1, VLBE_R(0.5), 0, 1, 2, 2, &b), VLBE_EWEIGHT);
}

/* fails on 77b73ad: basis_eval VLBE_OK with NaN (1/L = Inf), arc VLBE_OK
   with x = Inf, NURBS VLBE_OK with an Inf slope */
static void test_rancf_misc(void **state)
{
    const R w[4] = {1, VLBE_R(0.9), VLBE_R(1.1), 1};
    const R c[2] = {NEAR_MAX, 0};
    const R P[6] = {-NEAR_MAX, 0, NEAR_MAX, 0, 0, 1}, wc[3] = {1, 1, 1};
    const R U[6] = {0, 0, 0, 1, 1, 1};
    R wa[4], xa[8], wn[8], xn[16], pn[4];
    vlbe_herm_ale b;
    int ne = -7;
    (void)state;
    sn_begin();
    sn_fill(&b, sizeof b);
    EXPECT_FAIL(vlbe_rancf_basis_eval(w, 0, 0, SUBN_L, 3, 2, &b), VLBE_ELENGTH);
    EXPECT_FAIL(vlbe_rancf_basis_eval(w, 0, 0, TINY_L, 3, 2, &b), VLBE_ELENGTH);
    sn_begin();
    sn_fill(wa, sizeof wa);
    sn_fill(xa, sizeof xa);
    EXPECT_FAIL(vlbe_rancf_arc(c, NEAR_MAX, 0, 1, wa, xa), VLBE_ENONFINITE);
    sn_begin();
    sn_keep(&ne, sizeof ne);
    sn_fill(wn, sizeof wn);
    sn_fill(xn, sizeof xn);
    sn_fill(pn, sizeof pn);
    EXPECT_FAIL(vlbe_rancf_nurbs(2, 2, 3, P, wc, U, 1, 2, &ne, wn, xn, pn), VLBE_ENONFINITE);
    EXPECT_FAIL(vlbe_rancf_nurbs(2, 2, INT_MAX, P, wc, U, 1, 2, &ne, wn, xn, pn), VLBE_EARG);
}

/* -- corot2d.h ---------------------------------------------------------- */
static vlbe_cr2d_mat cr_mat(void)
{
    vlbe_cr2d_mat m;
    memset(&m, 0, sizeof m);
    m.EA = VLBE_R(1e6);
    m.EI = 10;
    m.rhoA = 1;
    m.rhoI = VLBE_R(0.01);
    m.ray_a = VLBE_R(0.1);
    m.ray_b = VLBE_R(0.001);
    return m;
}

/* fails on 77b73ad: VLBE_OK with k0 = Inf, then the force NaN with OK.
   (float: 1e-120 underflows to L = 0, which 77b73ad already rejected;
   1e-14 gives L^-3 = 1e42, out of float's range) */
static void test_cr2d_elem_init_tiny(void **state)
{
    const vlbe_cr2d_mat m = cr_mat();
    const R X1[2] = {0, 0}, X2[2] = {CR_TINY, 0};
    vlbe_cr2d_elem el;
    (void)state;
    memset(&el, 0x5A, sizeof el);
    sn_begin();
    sn_keep(&el, sizeof el);
    EXPECT_FAIL(vlbe_cr2d_elem_init(&el, &m, X1, X2, 0), VLBE_ELENGTH);
}

/* fails on 77b73ad: VLBE_OK with NaN Q, Inf energy, Inf local strain */
static void test_cr2d_overflow(void **state)
{
    const vlbe_cr2d_mat m = cr_mat();
    const R X1[2] = {0, 0}, X2[2] = {VLBE_R(0.1), 0};
    vlbe_cr2d_elem el;
    vlbe_cr2d_joint jt;
    R q[6] = {0, 0, 0, 0, 0, 0}, qd[6] = {0, HUGE_RATE, HUGE_RATE, 0, -HUGE_RATE, 0};
    R Q[6], K[36], D[36], E[2], loc[6];
    (void)state;
    assert_int_equal(vlbe_cr2d_elem_init(&el, &m, X1, X2, 0), VLBE_OK);
    sn_begin();
    sn_fill(Q, sizeof Q);
    sn_fill(K, sizeof K);
    sn_fill(D, sizeof D);
    sn_fill(E, sizeof E);
    sn_fill(loc, sizeof loc);
    EXPECT_FAIL(vlbe_cr2d_force(&el, 0, q, qd, Q, K, D), VLBE_ENONFINITE);
    EXPECT_FAIL(vlbe_cr2d_force(&el, 0, q, qd, Q, NULL, NULL), VLBE_ENONFINITE);
    EXPECT_FAIL(vlbe_cr2d_energy(&el, 0, q, qd, E), VLBE_ENONFINITE);
    jt.C[0] = VLBE_R(0.05);
    jt.C[1] = 0;
    jt.a[0] = 1;
    jt.a[1] = 0;
    EXPECT_FAIL(vlbe_cr2d_trans_force(&el, &jt, 0, q, qd, Q, K, D), VLBE_ENONFINITE);
    EXPECT_FAIL(vlbe_cr2d_trans_energy(&el, &jt, 0, q, qd, E), VLBE_ENONFINITE);
    q[3] = HUGE_RATE;
    qd[1] = qd[2] = qd[4] = 0;
    EXPECT_FAIL(vlbe_cr2d_local(&el, 0, q, loc), VLBE_ENONFINITE);
    EXPECT_FAIL(vlbe_cr2d_force(&el, 0, q, qd, Q, K, D), VLBE_ENONFINITE);
}

/* Finite X and q whose current positions X + q overflow (both -REAL_MAX):
   the chord and the frame are NaN.  Fails on ecddd90 (found by make fuzz):
   vlbe_cr2d_mass returned VLBE_OK with NaN in M (its commit bound looks at
   the local m only, which is finite); the force, whose outputs are
   scanned, already failed. */
static void test_cr2d_position_overflow(void **state)
{
    const vlbe_cr2d_mat m = cr_mat();
    const R X1[2] = {-VLBE_REAL_MAX, 0}, X2[2] = {-VLBE_REAL_MAX, VLBE_R(30.0)};
    vlbe_cr2d_elem el;
    const R q[6] = {-VLBE_REAL_MAX, 0, 0, -VLBE_REAL_MAX, VLBE_R(19.0), 0};
    const R qd[6] = {0, 0, 0, 0, 0, 0};
    R Q[6], K[36], D[36], M[36], E[2];
    (void)state;
    assert_int_equal(vlbe_cr2d_elem_init(&el, &m, X1, X2, 0), VLBE_OK);
    sn_begin();
    sn_fill(M, sizeof M);
    sn_fill(Q, sizeof Q);
    sn_fill(K, sizeof K);
    sn_fill(D, sizeof D);
    sn_fill(E, sizeof E);
    EXPECT_FAIL(vlbe_cr2d_mass(&el, 0, q, M), VLBE_ENONFINITE);
    EXPECT_FAIL(vlbe_cr2d_force(&el, 0, q, qd, Q, K, D), VLBE_ENONFINITE);
    EXPECT_FAIL(vlbe_cr2d_energy(&el, 0, q, qd, E), VLBE_ENONFINITE);
}

/* -- a sweep over extreme inputs ---------------------------------------- */
static int sweep_viol_;
static int sweep_calls_, sweep_ok_; /* for the report: how many calls, how many VLBE_OK */

static void sweep_check(const char *what, const char *cs, vlbe_status st, R *const *o,
                        const int *n, int no)
{
    int i;
    ++sweep_calls_;
    if (st == VLBE_OK) {
        ++sweep_ok_;
        for (i = 0; i < no; ++i)
            if (!all_fin(o[i], n[i])) {
                print_message("%s (%s): VLBE_OK with a non-finite output %d\n", what, cs, i);
                ++sweep_viol_;
                return;
            }
    } else if (!sn_same()) {
        print_message("%s (%s): %s, an output was written\n", what, cs, vlbe_status_str(st));
        ++sweep_viol_;
    }
}

#define SW(what, call, ...)                                                              \
    do {                                                                                 \
        R *const o_[] = {__VA_ARGS__};                                                   \
        vlbe_status st_;                                                                 \
        int i_;                                                                          \
        sn_begin();                                                                      \
        for (i_ = 0; i_ < (int)(sizeof o_ / sizeof o_[0]); ++i_)                         \
            sn_fill(o_[i_], sizeof(R) * (size_t)sw_n(o_[i_]));                           \
        st_ = (call);                                                                    \
        {                                                                                \
            int n_[8];                                                                   \
            for (i_ = 0; i_ < (int)(sizeof o_ / sizeof o_[0]); ++i_) n_[i_] = sw_n(o_[i_]); \
            sweep_check(what, cs, st_, o_, n_, (int)(sizeof o_ / sizeof o_[0]));         \
        }                                                                                \
    } while (0)

static R sQ[16], sK[256], sD[256], sM[256], sE[3], sA[16], sB[16], sC[16], sW1[4], sW2[4];

static int sw_n(const R *p)
{
    if (p == sQ) return 16;
    if (p == sK || p == sD || p == sM) return 256;
    if (p == sE) return 3;
    if (p == sW1 || p == sW2) return 4;
    return 16;
}

static void sweep_planar(const char *cs, const R *q, const R *qd)
{
    const R F[2] = {1, 2}, p3 = q[4] + (q[9] - q[4]) / 3;
    SW("ale_force Q", vlbe_ale_force(&el_, 0, q, qd, sQ, NULL, NULL), sQ);
    SW("ale_force QKD", vlbe_ale_force(&el_, 0, q, qd, sQ, sK, sD), sQ, sK, sD);
    SW("ale_force K", vlbe_ale_force(&el_, 0, q, qd, sQ, sK, NULL), sQ, sK);
    SW("ale_force INV", vlbe_ale_force(&el_, VLBE_ALE_INV_AXIAL, q, qd, sQ, sK, sD), sQ, sK, sD);
    SW("ale_force CONS", vlbe_ale_force(&el_, VLBE_ALE_CONSERVATIVE, q, qd, sQ, sK, sD), sQ, sK,
       sD);
    SW("ale_inv_force", vlbe_ale_inv_force(&el_, 0, q, qd, sQ, sK, sD), sQ, sK, sD);
    SW("ale_mass", vlbe_ale_mass(&el_, 0, q, sM), sM);
    SW("ale_mass fixed", vlbe_ale_mass(&el_, VLBE_ALE_FIX_P1 | VLBE_ALE_FIX_P2, q, sM), sM);
    SW("ale_mass_jac", vlbe_ale_mass_jac(&el_, 0, q, qd, sM), sM);
    SW("ale_energy", vlbe_ale_energy(&el_, 0, q, qd, sE), sE);
    SW("ale_point", vlbe_ale_point(q, (q[4] + q[9]) / 2, sA, sB), sA, sB);
    SW("ale_strain", vlbe_ale_strain(q, p3, sA, sB), sA, sB);
    SW("ale_split", vlbe_ale_split(q, qd, p3, sA, sB), sA, sB);
    SW("ale_point_force", vlbe_ale_point_force(q, p3, F, sQ, sK), sQ, sK);
    SW("rancf_force", vlbe_rancf_force(&rel_, 0, q, qd, sQ, sK, sD), sQ, sK, sD);
    SW("rancf_force Q", vlbe_rancf_force(&rel_, 0, q, qd, sQ, NULL, NULL), sQ);
    SW("rancf_mass", vlbe_rancf_mass(&rel_, 0, q, sM), sM);
    SW("rancf_mass_jac", vlbe_rancf_mass_jac(&rel_, 0, q, qd, sM), sM);
    SW("rancf_energy", vlbe_rancf_energy(&rel_, 0, q, qd, sE), sE);
    SW("rancf_point", vlbe_rancf_point(&rel_, q, (q[4] + q[9]) / 2, sA, sB), sA, sB);
    SW("rancf_strain", vlbe_rancf_strain(&rel_, q, p3, sA, sB), sA, sB);
    SW("rancf_point_force", vlbe_rancf_point_force(&rel_, q, p3, F, sQ, sK), sQ, sK);
    SW("rancf_split", vlbe_rancf_split(&rel_, q, qd, p3, sA, sB, sW1, sW2), sA, sB, sW1, sW2);
}

static void sweep_3d(const char *cs, const R *q, const R *qd)
{
    const R F[3] = {1, 2, 3}, p3 = q[7] + (q[15] - q[7]) / 3;
    SW("ale3_force QKD", vlbe_ale3_force(&el3_, 0, q, qd, sQ, sK, sD), sQ, sK, sD);
    SW("ale3_force Q", vlbe_ale3_force(&el3_, 0, q, qd, sQ, NULL, NULL), sQ);
    SW("ale3_mass", vlbe_ale3_mass(&el3_, 0, q, sM), sM);
    SW("ale3_mass_jac", vlbe_ale3_mass_jac(&el3_, 0, q, qd, sM), sM);
    SW("ale3_energy", vlbe_ale3_energy(&el3_, 0, q, qd, sE), sE);
    SW("ale3_point", vlbe_ale3_point(0, q, (q[7] + q[15]) / 2, sA, sB, sC), sA, sB, sC);
    SW("ale3_strain", vlbe_ale3_strain(0, q, p3, sA, sB, sC), sA, sB, sC);
    SW("ale3_point_force", vlbe_ale3_point_force(0, q, p3, F, sQ, sK), sQ, sK);
    SW("ale3_point_torque", vlbe_ale3_point_torque(0, q, p3, 2, sQ, sK), sQ, sK);
}

/* fails on 77b73ad: 108 (double) / 126 (float) violations over this table
   (OK with NaN/Inf outputs) */
static void test_extreme_sweep(void **state)
{
    static const struct {
        const char *nm;
        R L, sl, pos, rate, p1;
    } cs_[] = {
        {"base", 1, 1, 0, 1, 0},
        {"tiny L", TINY_L, 1, 0, 1, 0},
        {"subnormal L", SUBN_L, 1, 0, 1, 0},
#ifdef VLBE_USE_FLOAT
        {"L 1e-12", VLBE_R(1e-12), 1, 0, 1, 0},
        {"L 1e37", VLBE_R(1e37), 1, 0, 1, 0},
        {"positions 1e37", 1, 1, VLBE_R(1e37), 1, 0},
        {"rates 1e30", 1, 1, 0, VLBE_R(1e30), 0},
        {"huge p", VLBE_R(3e38), 1, 0, 1, VLBE_R(-3e38)},
#else
        {"L 1e-60", 1e-60, 1, 0, 1, 0},
        {"L 1e300", 1e300, 1, 0, 1, 0},
        {"positions 1e307", 1, 1, 1e307, 1, 0},
        {"rates 1e200", 1, 1, 0, 1e200, 0},
        {"huge p", 1.5e308, 1, 0, 1, -1e308},
#endif
        {"big slope", 1, BIG_SLOPE, 0, 1, 0},
        {"huge slope", 1, HUGE_SLOPE, 0, 1, 0},
    };
    unsigned c;
    int k;
    (void)state;
    sweep_viol_ = sweep_calls_ = sweep_ok_ = 0;
    for (c = 0; c < sizeof cs_ / sizeof cs_[0]; ++c) {
        const char *cs = cs_[c].nm;
        const R L = cs_[c].L, sl = cs_[c].sl, rt = cs_[c].rate;
        R q[10], qd[10], q3[16], qd3[16];
        ale_q(1, sl, q, qd);
        q[4] = cs_[c].p1;
        q[9] = cs_[c].p1 != 0 ? -cs_[c].p1 / 2 : L;
        q[5] = cs_[c].p1 != 0 ? 1 : L;
        q[6] = VLBE_R(0.05) * q[5];
        q[0] += cs_[c].pos;
        q[5] += cs_[c].pos;
        for (k = 0; k < 10; ++k) qd[k] *= rt;
        sweep_planar(cs, q, qd);
        ale3_q(1, 1, 1, q3, qd3);
        for (k = 0; k < 2; ++k) { /* the planar node in the 3D layout */
            q3[8 * k] = q[5 * k];
            q3[8 * k + 1] = q[5 * k + 1];
            q3[8 * k + 3] = q[5 * k + 2];
            q3[8 * k + 4] = q[5 * k + 3];
            q3[8 * k + 7] = q[5 * k + 4];
            qd3[8 * k] = qd[5 * k];
            qd3[8 * k + 1] = qd[5 * k + 1];
            qd3[8 * k + 3] = qd[5 * k + 2];
            qd3[8 * k + 4] = qd[5 * k + 3];
            qd3[8 * k + 6] = rt;
            qd3[8 * k + 7] = qd[5 * k + 4];
        }
        sweep_3d(cs, q3, qd3);
    }
    if (tu_report_on())
        print_message("    extreme sweep: %d calls, %d VLBE_OK (outputs finite), %d refused "
                      "(outputs untouched)\n",
                      sweep_calls_, sweep_ok_, sweep_calls_ - sweep_ok_);
    tu_measured("sweep_calls", (double)sweep_calls_);
    tu_measured("sweep_ok", (double)sweep_ok_);
    assert_int_equal(sweep_viol_, 0);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_ale_force_tiny_length),
        cmocka_unit_test(test_ale_force_huge_slope),
        cmocka_unit_test(test_ale_subnormal_length),
        cmocka_unit_test(test_ale_mass_huge_slope),
        cmocka_unit_test(test_ale3_overflow),
        cmocka_unit_test(test_ale3_mat_circle),
        cmocka_unit_test(test_inv_chain_tiny_length),
        cmocka_unit_test(test_inv_sys_overflow),
        cmocka_unit_test(test_inv_chain_huge_damping),
        cmocka_unit_test(test_rancf_to_bezier_weights),
        cmocka_unit_test(test_rancf_split_weights),
        cmocka_unit_test(test_rancf_elem_init_weights),
        cmocka_unit_test(test_rancf_misc),
        cmocka_unit_test(test_cr2d_elem_init_tiny),
        cmocka_unit_test(test_cr2d_overflow),
        cmocka_unit_test(test_cr2d_position_overflow),
        cmocka_unit_test(test_extreme_sweep),
    };
    return cmocka_run_group_tests_name("contract_elem", tests, setup, NULL);
}

/* test_loads.c -- cmocka suite of the loads between the nodes: point loads
   on chains of ancf_ale.h (vlbe_ale_load: planar, rational through rancf.h,
   3D with spin), the chains' load factor, and the point and distributed
   loads of corot2d.h's beams (vlbe_cr2d_load, dist)
                                                   -- part of vlbe
                                                   SPDX-License-Identifier: MIT
   cc -std=c99 -Wall -Wextra -Wpedantic ... -O2 tests/test_loads.c -lcmocka -lm
   (add -DVLBE_USE_FLOAT for the float build; the same source passes in both)

   The load's part of a callback's output is isolated as the difference of
   the output with and without the load (the element forces cancel to their
   rounding, EPS of max|Q|, well inside every tolerance below).

   Finite differences: central, step h = cbrt(EPS) max(1, |x|), so that
   truncation (h^2 times third derivatives, O(1) for these O(1) states) and
   rounding (EPS/h of the values differenced) are both about EPS^(2/3);
   tolerance FDTOL = 200 EPS^(2/3) (7e-9 double, 5e-3 float) of the
   largest of the entries compared and of |Q| (the load's Q is differenced
   out of the whole Q, whose rounding EPS |Q| / h enters): a margin of two
   decades over that estimate, still far below any missing term (O(1)
   relative).  Kernel cross-checks and
   factor scaling differ only by summation order: RTOL 256 EPS of the
   largest entry.

   Tests
     chain_force_potential   a constant force at a fixed material point on
                             planar, rational and 3D chains with free,
                             prescribed and fixed nodal p: Q = -dV/dq with
                             V = -F . r(p) (vlbe_ale_chain_point), and the
                             chain energy's V changes by that V
     chain_moment_potential  planar moment M: Q = -dV/dq, V = -M atan2(y', x')
                             of vlbe_ale_chain_point's slope
     chain_moment3           the 3D moment vector: in the plane z = 0 the
                             planar moment's Q, along the slope the torque's
     chain_jacobian          K, D of every load kind (constant force and
                             moment, moving callback force and moment
                             depending on r and rd with their derivatives;
                             3D: the torque on the spin angle, the moment
                             vector with and without spin) against central
                             differences of Q in q and v; four chain types
     chain_kernel            a moving constant force's (and 3D torque's) Q, K
                             equal the element kernel (vlbe_ale_point_force,
                             vlbe_rancf_point_force, vlbe_ale3_point_force,
                             vlbe_ale3_point_torque) at the located element
                             and p(t), scattered through the gather map
     chain_factor            Q(lambda) - Q(0) = lambda (Q(1) - Q(0)) and the
                             same for K, D, with mat.f, g on point masses and
                             point loads all present; lambda = 1 bitwise
                             the chain without the field set; lambda = 0 the
                             chain without any applied load
     chain_band              banded K, D with loads equal the dense ones
     chain_bad_input         p outside (EBOUND, -1, Q untouched), outside = 1
                             (no load), NaN in p, f or the factor, unknown
                             kind, 3D moment without spin, a failing callback;
                             the setter refuses and leaves the chain as it was
     chain_static            clamped chain, a force inside an element and a tip
                             moment, two load steps of the factor with
                             vlbe_dae_static: P a^2 (3L - a)/(6 EI), M L^2/(2 EI)
                             and the tip slopes
     cr2d_force_potential    point force and moment at a material point of a
                             deformed beam: Q = -dV/dq, V = -F . r(xi) and
                             -M psi(xi) of the element's interpolation written
                             out here from [H] eqs. 7-9
     cr2d_jacobian           K, D of constant and callback, fixed and moving
                             loads and of the distributed load vs differences
     cr2d_linear             LINEAR elements: the linearised interpolation's
                             constant Q (that of the co-rotational element at
                             the reference state) and no load stiffness
     cr2d_node_load          a force and moment at a node equal P there (Q,
                             and K = 0)
     cr2d_dist_resultant     sum of the translational Q of a distributed load
                             on a deformed beam = w L (times load)
     cr2d_cantilever         static solve, uniform load: tip deflection q L^4
                             / (8 EI) and rotation q L^3 / (6 EI)
     cr2d_simply_supported   static solve: midspan 5 q L^4 / (384 EI)
     cr2d_moving_quasistatic a constant force crossing a simply supported beam
                             slowly (HHT): midspan deflection follows the
                             static influence line
     cr2d_factor_band        load scales Q, K exactly; band = dense
     cr2d_bad_input          s outside, NaN, unknown kind, transition element,
                             failing callback, setter refusals */
#include "../rancf.h"
#include "../corot2d.h"
#include "../integrators.h"
#include "test_util.h"
#include "ale_material.h"

#define EPSD ((double)VLBE_EPS)
#define FDTOL (200.0 * pow(EPSD, 2.0 / 3.0))
#define RTOL (256.0 * EPSD)
#define NMAX 40

/* Central differences of a load's Q(t, q, v) in q and in v at (q0, v0), n
   coordinates: Kf = dQ/dq, Df = dQ/dv (n x n, double), steps EPSD^(1/3)
   max(1, |x_j|). */
typedef void (*qload_fn)(void *ctx, vlbe_real t, const vlbe_real *q, const vlbe_real *v,
                         vlbe_real *Q);
static void fd_qv(qload_fn f, void *ctx, vlbe_real t, const vlbe_real *q0, const vlbe_real *v0,
                  int n, double *Kf, double *Df)
{
    vlbe_real q[64], v[64], Qp[64], Qm[64];
    int i, j;
    assert_true(n <= 64);
    memcpy(q, q0, (size_t)n * sizeof q[0]);
    memcpy(v, v0, (size_t)n * sizeof v[0]);
    for (j = 0; j < n; ++j) {
        const double hq = cbrt(EPSD) * fmax(1.0, fabs((double)q0[j]));
        const double hv = cbrt(EPSD) * fmax(1.0, fabs((double)v0[j]));
        q[j] = (vlbe_real)((double)q0[j] + hq);
        f(ctx, t, q, v0, Qp);
        q[j] = (vlbe_real)((double)q0[j] - hq);
        f(ctx, t, q, v0, Qm);
        q[j] = q0[j];
        for (i = 0; i < n; ++i) Kf[i * n + j] = ((double)Qp[i] - (double)Qm[i]) / (2.0 * hq);
        v[j] = (vlbe_real)((double)v0[j] + hv);
        f(ctx, t, q0, v, Qp);
        v[j] = (vlbe_real)((double)v0[j] - hv);
        f(ctx, t, q0, v, Qm);
        v[j] = v0[j];
        for (i = 0; i < n; ++i) Df[i * n + j] = ((double)Qp[i] - (double)Qm[i]) / (2.0 * hv);
    }
}

static double maxabs(int n, const vlbe_real *a)
{
    double m = 0.0;
    int i;
    for (i = 0; i < n; ++i)
        if (fabs((double)a[i]) > m) m = fabs((double)a[i]);
    return m;
}

/* -- a callback load: f_c = A_c + B_c . r + C_c . rd + E_c r_c^2 (nc rows,
   d columns), with its derivatives ----------------------------------- */
typedef struct cbload {
    int nc, d;
    double A[3], B[3][3], C[3][3], E[3];
    int calls, fail;
} cbload;

static int cb_fun(void *user, vlbe_real t, const vlbe_real *r, const vlbe_real *rd, vlbe_real *f,
                  vlbe_real *dfr, vlbe_real *dfv)
{
    cbload *c = (cbload *)user;
    int i, j;
    (void)t;
    c->calls++;
    if (c->fail) return 1;
    for (i = 0; i < c->nc; ++i) {
        double x = c->A[i] + c->E[i] * (double)r[i] * (double)r[i];
        for (j = 0; j < c->d; ++j) x += c->B[i][j] * (double)r[j] + c->C[i][j] * (double)rd[j];
        f[i] = (vlbe_real)x;
        for (j = 0; j < c->d; ++j) {
            const double dr = i == j ? 2.0 * c->E[i] * (double)r[i] : 0.0;
            if (dfr) dfr[i * c->d + j] = (vlbe_real)(c->B[i][j] + dr);
            if (dfv) dfv[i * c->d + j] = (vlbe_real)c->C[i][j];
        }
    }
    return 0;
}

static void cb_make(cbload *c, int nc, int d, double seed)
{
    int i, j;
    memset(c, 0, sizeof *c);
    c->nc = nc;
    c->d = d;
    for (i = 0; i < nc; ++i) {
        c->A[i] = 0.3 + 0.2 * i - seed;
        c->E[i] = 0.25 * (i + 1) * seed;
        for (j = 0; j < d; ++j) {
            c->B[i][j] = 0.4 * sin(1.0 + i + 2.0 * j + seed);
            c->C[i][j] = 0.3 * cos(2.0 + 3.0 * i + j + seed);
        }
    }
}

/* ===== chains ============================================================ */
typedef struct tch {
    vlbe_ale_mat mat;
    vlbe_ale_elem el;
    vlbe_rancf_elem rel[4];
    vlbe_ale3_mat mat3;
    vlbe_ale3_elem el3;
    vlbe_ale_node node[5];
    vlbe_ale_chain ch;
    vlbe_real q[NMAX], v[NMAX];
    int type; /* 0 planar, 1 rational, 2 3D, 3 3D without spin */
} tch;

static tch g_c; /* large (element tables): static */

/* nodes at p = 0, 0.4, 0.8, 1.2: node 1 free, node 2 prescribed (moving),
   nodes 0, 3 fixed; a deformed state and rates of O(1) */
static void chain_make(tch *c, int type)
{
    int i, k;
    vlbe_real r0[3] = {0.1f, -0.2f, 0.05f}, dir[3] = {0.8f, 0.6f, 0.0f};
    memset(c, 0, sizeof *c);
    c->type = type;
    for (i = 0; i < 4; ++i) {
        c->node[i].pmode = VLBE_ALE_PFIXED;
        c->node[i].p = (vlbe_real)(0.4 * i);
    }
    c->node[1].pmode = VLBE_ALE_PFREE;
    c->node[2].pmode = VLBE_ALE_PPRESCRIBED;
    c->node[2].pd = VLBE_R(0.05);
    c->node[2].pdd = VLBE_R(0.1);
    c->node[3].mass = VLBE_R(0.3);
    if (type >= 2) {
        assert_int_equal(vlbe_ale3_mat_circle(&c->mat3, VLBE_R(1.0), VLBE_R(30.0), VLBE_R(12.0),
                                              VLBE_R(0.1)),
                         VLBE_OK);
        c->mat3.c_eps = VLBE_R(0.01);
        c->mat3.c_kap = VLBE_R(0.02);
        c->mat3.f[0] = VLBE_R(0.2);
        c->mat3.f[2] = VLBE_R(-0.9);
        assert_int_equal(
            vlbe_ale3_elem_init(&c->el3, &c->mat3, type == 3 ? VLBE_ALE3_NO_SPIN : 0u, 0, 0),
            VLBE_OK);
        assert_int_equal(vlbe_ale_chain_init3(&c->ch, &c->el3, c->node, 4, 5, NULL, 0), VLBE_OK);
    } else {
        c->mat = mat_std();
        if (type == 1) {
            for (i = 0; i < 3; ++i) {
                const vlbe_real w[4] = {VLBE_R(1.0), (vlbe_real)(1.0 + 0.15 * (i - 1)),
                                        (vlbe_real)(0.9 + 0.1 * i), VLBE_R(1.1)};
                assert_int_equal(vlbe_rancf_elem_init(&c->rel[i], &c->mat, w, 0, 0, 0, 0), VLBE_OK);
            }
            assert_int_equal(vlbe_rancf_chain_init(&c->ch, c->rel, c->node, 4, 4, NULL, 0),
                             VLBE_OK);
        } else {
            assert_int_equal(vlbe_ale_elem_init(&c->el, &c->mat, 0u, 0, 0, 0), VLBE_OK);
            assert_int_equal(vlbe_ale_chain_init(&c->ch, &c->el, c->node, 4, 5, NULL, 0), VLBE_OK);
        }
    }
    c->ch.g[1] = VLBE_R(-1.5);
    assert_int_equal(vlbe_ale_chain_layout(&c->ch), VLBE_OK);
    vlbe_ale_chain_straight(&c->ch, r0, dir, c->q);
    for (k = 0; k < c->ch.n; ++k) {
        const int isp = k == c->node[1].ofs + 2 * c->ch.d + c->ch.spin; /* node 1's p */
        if (!isp) c->q[k] += (vlbe_real)(0.05 * sin(1.3 * k + 0.4));
        c->v[k] = isp ? VLBE_R(0.04) : (vlbe_real)(0.3 * cos(0.7 * k + 0.2));
    }
}

static int chain_Q(tch *c, vlbe_real t, const vlbe_real *q, const vlbe_real *v, vlbe_real *Q)
{
    return vlbe_ale_chain_force(&c->ch, t, q, v, Q);
}

/* the load part of Q: with minus without the chain's loads */
static void chain_Qload(tch *c, vlbe_real t, const vlbe_real *q, const vlbe_real *v, vlbe_real *Q)
{
    vlbe_real Q0[NMAX];
    const vlbe_ale_load *ld = c->ch.loads;
    const int nl = c->ch.nloads;
    int i;
    assert_int_equal(chain_Q(c, t, q, v, Q), 0);
    c->ch.loads = NULL;
    c->ch.nloads = 0;
    assert_int_equal(chain_Q(c, t, q, v, Q0), 0);
    c->ch.loads = ld;
    c->ch.nloads = nl;
    for (i = 0; i < c->ch.n; ++i) Q[i] -= Q0[i];
}
static void chain_Qload_fn(void *c, vlbe_real t, const vlbe_real *q, const vlbe_real *v,
                           vlbe_real *Q)
{
    chain_Qload((tch *)c, t, q, v, Q);
}

static void chain_Kload(tch *c, vlbe_real t, vlbe_real *K, vlbe_real *D)
{
    static vlbe_real K0[NMAX * NMAX], D0[NMAX * NMAX];
    const vlbe_ale_load *ld = c->ch.loads;
    const int nl = c->ch.nloads, nn = c->ch.n * c->ch.n;
    int i;
    assert_int_equal(vlbe_ale_chain_force_jac(&c->ch, t, c->q, c->v, K, D), 0);
    c->ch.loads = NULL;
    c->ch.nloads = 0;
    assert_int_equal(vlbe_ale_chain_force_jac(&c->ch, t, c->q, c->v, K0, D0), 0);
    c->ch.loads = ld;
    c->ch.nloads = nl;
    for (i = 0; i < nn; ++i) {
        K[i] -= K0[i];
        D[i] -= D0[i];
    }
}

static vlbe_ale_load load_make(int kind, double p0, double p1, double p2, double f0, double f1,
                               double f2)
{
    vlbe_ale_load l;
    memset(&l, 0, sizeof l);
    l.kind = kind;
    l.p[0] = (vlbe_real)p0;
    l.p[1] = (vlbe_real)p1;
    l.p[2] = (vlbe_real)p2;
    l.f[0] = (vlbe_real)f0;
    l.f[1] = (vlbe_real)f1;
    l.f[2] = (vlbe_real)f2;
    return l;
}

static double chain_V(tch *c, vlbe_real t, const vlbe_real *q, const vlbe_real *F, vlbe_real p)
{
    vlbe_real r[3];
    double V = 0.0;
    int k;
    assert_int_equal(vlbe_ale_chain_point(&c->ch, t, q, p, r, NULL), VLBE_OK);
    for (k = 0; k < c->ch.d; ++k) V -= (double)F[k] * (double)r[k];
    return V;
}

static void test_chain_force_potential(void **state)
{
    int type, j;
    (void)state;
    for (type = 0; type < 3; ++type) {
        tch *c = &g_c;
        const vlbe_real t = VLBE_R(0.6);
        vlbe_ale_load ld;
        vlbe_real Q[NMAX], q[NMAX], E1[3], E0[3];
        const vlbe_real p = VLBE_R(0.57); /* in element 1: free p1, prescribed p2 */
        double ref[NMAX], scale;
        chain_make(c, type);
        ld = load_make(VLBE_ALE_LOAD_FORCE, (double)p, 0, 0, 0.7, -1.3, 0.4);
        assert_int_equal(vlbe_ale_chain_loads(&c->ch, &ld, 1), VLBE_OK);
        chain_Qload(c, t, c->q, c->v, Q);
        for (j = 0; j < c->ch.n; ++j) {
            const double h = cbrt(EPSD) * fmax(1.0, fabs((double)c->q[j]));
            double vp, vm;
            memcpy(q, c->q, sizeof q);
            q[j] = (vlbe_real)((double)c->q[j] + h);
            vp = chain_V(c, t, q, ld.f, p);
            q[j] = (vlbe_real)((double)c->q[j] - h);
            vm = chain_V(c, t, q, ld.f, p);
            ref[j] = -(vp - vm) / (2.0 * h);
        }
        scale = maxabs(c->ch.n, Q);
        assert_true(scale > 0.1);
        ASSERT_VEC_CLOSE(Q, ref, c->ch.n, 0.0, FDTOL * scale);
        /* the energy's V: -F . r(p) more, times the factor */
        c->ch.load_factor = VLBE_R(0.75);
        assert_int_equal(vlbe_ale_chain_energy(&c->ch, t, c->q, c->v, E1), VLBE_OK);
        assert_int_equal(vlbe_ale_chain_loads(&c->ch, NULL, 0), VLBE_OK);
        assert_int_equal(vlbe_ale_chain_energy(&c->ch, t, c->q, c->v, E0), VLBE_OK);
        ASSERT_CLOSE(E1[2] - E0[2], 0.75 * chain_V(c, t, c->q, ld.f, p), RTOL,
                     RTOL * fabs((double)E0[2]));
    }
}

static void test_chain_moment_potential(void **state)
{
    int type, j;
    (void)state;
    for (type = 0; type < 2; ++type) {
        tch *c = &g_c;
        const vlbe_real t = VLBE_R(0.6), p = VLBE_R(0.3);
        vlbe_ale_load ld;
        vlbe_real Q[NMAX], q[NMAX], rp[3];
        double ref[NMAX];
        chain_make(c, type);
        ld = load_make(VLBE_ALE_LOAD_MOMENT, (double)p, 0, 0, 0.9, 0, 0);
        assert_int_equal(vlbe_ale_chain_loads(&c->ch, &ld, 1), VLBE_OK);
        chain_Qload(c, t, c->q, c->v, Q);
        for (j = 0; j < c->ch.n; ++j) {
            const double h = cbrt(EPSD) * fmax(1.0, fabs((double)c->q[j]));
            double ap, am;
            memcpy(q, c->q, sizeof q);
            q[j] = (vlbe_real)((double)c->q[j] + h);
            assert_int_equal(vlbe_ale_chain_point(&c->ch, t, q, p, NULL, rp), VLBE_OK);
            ap = atan2((double)rp[1], (double)rp[0]);
            q[j] = (vlbe_real)((double)c->q[j] - h);
            assert_int_equal(vlbe_ale_chain_point(&c->ch, t, q, p, NULL, rp), VLBE_OK);
            am = atan2((double)rp[1], (double)rp[0]);
            ref[j] = 0.9 * (ap - am) / (2.0 * h);
        }
        ASSERT_VEC_CLOSE(Q, ref, c->ch.n, 0.0, FDTOL * maxabs(c->ch.n, Q));
    }
}

/* The 3D moment vector against the planar moment and the 3D torque: a 3D
   chain with spin in the plane z = 0 (theta = 0, state and nodes of the
   planar chain) under M = (0, 0, Mz) has the planar chain's Q under the
   moment Mz on the x, y, x', y', p entries and none on z, z', theta; M =
   m t (t the unit slope at p) has the torque m's Q (VLBE_ALE_LOAD_MOMENT) */
static void test_chain_moment3(void **state)
{
    static tch c2;
    tch *c = &g_c;
    vlbe_real Q2[NMAX], Q3[NMAX], Qt[NMAX], q3[NMAX], v3[NMAX], rp[3];
    vlbe_ale_load ld;
    const vlbe_real t = VLBE_R(0.6), p = VLBE_R(0.57);
    int i, k;
    (void)state;
    chain_make(&c2, 0);
    ld = load_make(VLBE_ALE_LOAD_MOMENT, (double)p, 0, 0, 0.9, 0, 0);
    assert_int_equal(vlbe_ale_chain_loads(&c2.ch, &ld, 1), VLBE_OK);
    chain_Qload(&c2, t, c2.q, c2.v, Q2);
    chain_make(c, 2);
    memset(q3, 0, sizeof q3);
    memset(v3, 0, sizeof v3);
    for (i = 0; i < 4; ++i) {
        const int o2 = c2.node[i].ofs, o3 = c->node[i].ofs;
        for (k = 0; k < 2; ++k) {
            q3[o3 + k] = c2.q[o2 + k];
            q3[o3 + 3 + k] = c2.q[o2 + 2 + k];
            v3[o3 + k] = c2.v[o2 + k];
            v3[o3 + 3 + k] = c2.v[o2 + 2 + k];
        }
        if (i == 1) {
            q3[o3 + 7] = c2.q[o2 + 4];
            v3[o3 + 7] = c2.v[o2 + 4];
        }
    }
    ld = load_make(VLBE_ALE_LOAD_MOMENT3, (double)p, 0, 0, 0, 0, 0.9);
    assert_int_equal(vlbe_ale_chain_loads(&c->ch, &ld, 1), VLBE_OK);
    chain_Qload(c, t, q3, v3, Q3);
    for (i = 0; i < 4; ++i) {
        const int o2 = c2.node[i].ofs, o3 = c->node[i].ofs;
        for (k = 0; k < 2; ++k) {
            ASSERT_CLOSE(Q3[o3 + k], Q2[o2 + k], 0.0, RTOL * maxabs(c2.ch.n, Q2));
            ASSERT_CLOSE(Q3[o3 + 3 + k], Q2[o2 + 2 + k], 0.0, RTOL * maxabs(c2.ch.n, Q2));
        }
        assert_true(Q3[o3 + 2] == VLBE_R(0.0) && Q3[o3 + 5] == VLBE_R(0.0));
        ASSERT_CLOSE(Q3[o3 + 6], 0.0, 0.0, RTOL * maxabs(c2.ch.n, Q2));
        if (i == 1) ASSERT_CLOSE(Q3[o3 + 7], Q2[o2 + 4], 0.0, RTOL * maxabs(c2.ch.n, Q2));
    }
    /* axial: M = 1.3 t against the torque 1.3 */
    assert_int_equal(vlbe_ale_chain_point(&c->ch, t, c->q, p, NULL, rp), VLBE_OK);
    ld = load_make(VLBE_ALE_LOAD_MOMENT, (double)p, 0, 0, 1.3, 0, 0);
    assert_int_equal(vlbe_ale_chain_loads(&c->ch, &ld, 1), VLBE_OK);
    chain_Qload(c, t, c->q, c->v, Qt);
    {
        const double nr = sqrt((double)vlbe_v3_dot(rp, rp));
        ld = load_make(VLBE_ALE_LOAD_MOMENT3, (double)p, 0, 0, 1.3 * (double)rp[0] / nr,
                       1.3 * (double)rp[1] / nr, 1.3 * (double)rp[2] / nr);
    }
    assert_int_equal(vlbe_ale_chain_loads(&c->ch, &ld, 1), VLBE_OK);
    chain_Qload(c, t, c->q, c->v, Q3);
    ASSERT_VEC_CLOSE(Q3, Qt, c->ch.n, 0.0, RTOL * maxabs(c->ch.n, Qt));
    /* a planar chain refuses it */
    assert_int_equal(vlbe_ale_chain_loads(&c2.ch, &ld, 1), VLBE_EARG);
}

/* K, D of the loads vs central differences of their Q */
static void chain_jac_check(tch *c, vlbe_real t)
{
    static vlbe_real K[NMAX * NMAX], D[NMAX * NMAX];
    vlbe_real Qp[NMAX];
    double Kf[NMAX * NMAX], Df[NMAX * NMAX], sc;
    const int n = c->ch.n;
    chain_Kload(c, t, K, D);
    fd_qv(chain_Qload_fn, c, t, c->q, c->v, n, Kf, Df);
    assert_true(maxabs(n * n, K) > 0.01);
    assert_int_equal(chain_Q(c, t, c->q, c->v, Qp), 0);
    sc = fmax(maxabs(n, Qp), fmax(maxabs(n * n, D), maxabs(n * n, K)));
    ASSERT_VEC_CLOSE(K, Kf, n * n, 0.0, FDTOL * sc);
    ASSERT_VEC_CLOSE(D, Df, n * n, 0.0, FDTOL * sc);
}

static void test_chain_jacobian(void **state)
{
    int type, k;
    (void)state;
    for (type = 0; type < 4; ++type)
        for (k = 0; k < 5; ++k) {
            tch *c = &g_c;
            cbload cb;
            vlbe_ale_load ld[2];
            const int d = type >= 2 ? 3 : 2;
            if ((k == 4 && type < 2) || (type == 3 && k != 2 && k != 4)) continue;
            chain_make(c, type);
            cb_make(&cb, k == 3 || (k == 1 && type == 2) ? 1 : d, d, 0.3 + 0.1 * k);
            switch (k) {
            case 0: /* constant force, fixed point, and a moment */
                ld[0] = load_make(VLBE_ALE_LOAD_FORCE, 0.57, 0, 0, 0.7, -1.3, 0.4);
                ld[1] = load_make(VLBE_ALE_LOAD_MOMENT, 0.61, 0, 0, 0.8, 0, 0);
                break;
            case 1: /* moving constant loads */
                ld[0] = load_make(VLBE_ALE_LOAD_FORCE, 0.1, 0.3, 0.2, -0.4, 1.1, 0.6);
                ld[1] = load_make(VLBE_ALE_LOAD_MOMENT, 0.9, 0.2, -0.1, -1.2, 0, 0);
                break;
            case 4: /* 3D moment vector: constant and moving callback */
                ld[0] = load_make(VLBE_ALE_LOAD_MOMENT3, 0.57, 0, 0, 0.7, -1.3, 0.4);
                ld[1] = load_make(VLBE_ALE_LOAD_MOMENT3, 0.2, 0.35, 0.1, 0, 0, 0);
                ld[1].fun = cb_fun;
                ld[1].user = &cb;
                break;
            default: /* callback force (2) or moment (3), moving, with a constant one */
                ld[0] = load_make(k == 2 ? VLBE_ALE_LOAD_FORCE : VLBE_ALE_LOAD_MOMENT, 0.2, 0.35,
                                  0.1, 0, 0, 0);
                ld[0].fun = cb_fun;
                ld[0].user = &cb;
                ld[1] = load_make(VLBE_ALE_LOAD_FORCE, 1.0, 0, 0, 0.5, 0.5, -0.5);
                break;
            }
            assert_int_equal(vlbe_ale_chain_loads(&c->ch, ld, 2), VLBE_OK);
            chain_jac_check(c, VLBE_R(0.7));
        }
}

static void test_chain_kernel(void **state)
{
    int type, k, i, j;
    (void)state;
    for (type = 0; type < 3; ++type)
        for (k = 0; k < (type == 2 ? 2 : 1); ++k) {
            tch *c = &g_c;
            static vlbe_real K[NMAX * NMAX], D[NMAX * NMAX];
            vlbe_real Q[NMAX], Qr[NMAX], Kr[NMAX * NMAX], qe[VLBE_ALE3_NQ], Qe[VLBE_ALE3_NQ];
            vlbe_real Ke[VLBE_ALE3_NQ * VLBE_ALE3_NQ], pt;
            const vlbe_real t = VLBE_R(0.8);
            int e, idx[VLBE_ALE3_NQ], ne, n;
            unsigned md;
            vlbe_ale_load ld;
            chain_make(c, type);
            ld = k ? load_make(VLBE_ALE_LOAD_MOMENT, 0.3, 0.4, 0.25, 1.7, 0, 0)
                   : load_make(VLBE_ALE_LOAD_FORCE, 0.3, 0.4, 0.25, 0.7, -1.3, 0.4);
            assert_int_equal(vlbe_ale_chain_loads(&c->ch, &ld, 1), VLBE_OK);
            chain_Qload(c, t, c->q, c->v, Q);
            chain_Kload(c, t, K, D);
            n = c->ch.n;
            pt = (vlbe_real)(0.3 + 0.4 * 0.8 + 0.125 * 0.64);
            assert_int_equal(vlbe_ale_chain_locate(&c->ch, t, c->q, pt, &e), VLBE_OK);
            assert_int_equal(e, 1);
            assert_int_equal(vlbe_ale_chain_gather(&c->ch, e, t, c->q, NULL, qe, NULL, idx, &md),
                             VLBE_OK);
            ne = type == 2 ? VLBE_ALE3_NQ : 10;
            memset(Qe, 0, sizeof Qe);
            memset(Ke, 0, sizeof Ke);
            if (type == 0) assert_int_equal(vlbe_ale_point_force(qe, pt, ld.f, Qe, Ke), VLBE_OK);
            else if (type == 1)
                assert_int_equal(vlbe_rancf_point_force(&c->rel[e], qe, pt, ld.f, Qe, Ke), VLBE_OK);
            else if (k == 0)
                assert_int_equal(vlbe_ale3_point_force(0u, qe, pt, ld.f, Qe, Ke), VLBE_OK);
            else
                assert_int_equal(vlbe_ale3_point_torque(0u, qe, pt, ld.f[0], Qe, Ke), VLBE_OK);
            memset(Qr, 0, sizeof Qr);
            memset(Kr, 0, sizeof Kr);
            for (i = 0; i < ne; ++i) {
                if (idx[i] < 0) continue;
                Qr[idx[i]] += Qe[i];
                for (j = 0; j < ne; ++j)
                    if (idx[j] >= 0) Kr[idx[i] * n + idx[j]] += Ke[i * ne + j];
            }
            ASSERT_VEC_CLOSE(Q, Qr, n, 0.0, RTOL * maxabs(n, Qr));
            ASSERT_VEC_CLOSE(K, Kr, n * n, 0.0, RTOL * maxabs(n * n, Kr));
            assert_true(maxabs(n * n, D) == 0.0); /* a constant load: no D */
        }
}

static void test_chain_factor(void **state)
{
    int type, i;
    (void)state;
    for (type = 0; type < 3; ++type) {
        tch *c = &g_c;
        static vlbe_real K1[NMAX * NMAX], K0[NMAX * NMAX], Kl[NMAX * NMAX];
        static vlbe_real D1[NMAX * NMAX], D0[NMAX * NMAX], Dl[NMAX * NMAX];
        vlbe_real Q1[NMAX], Q0[NMAX], Ql[NMAX], Qa[NMAX], Qb[NMAX];
        vlbe_real d1[NMAX * NMAX], dl[NMAX * NMAX];
        const vlbe_real t = VLBE_R(0.4), lam = VLBE_R(0.37);
        cbload cb;
        vlbe_ale_load ld[2];
        int n, nn;
        chain_make(c, type);
        cb_make(&cb, type == 2 ? 3 : 2, type == 2 ? 3 : 2, 0.2);
        ld[0] = load_make(VLBE_ALE_LOAD_FORCE, 0.2, 0.1, 0, 0, 0, 0);
        ld[0].fun = cb_fun;
        ld[0].user = &cb;
        ld[1] = load_make(VLBE_ALE_LOAD_MOMENT, 1.0, 0, 0, 0.6, 0, 0);
        /* lambda = 1 is the chain without the field: bitwise */
        assert_int_equal(vlbe_ale_chain_force(&c->ch, t, c->q, c->v, Qa), 0);
        c->ch.load_factor = VLBE_R(1.0);
        assert_int_equal(vlbe_ale_chain_force(&c->ch, t, c->q, c->v, Qb), 0);
        assert_memory_equal(Qa, Qb, sizeof(vlbe_real) * (size_t)c->ch.n);
        assert_int_equal(vlbe_ale_chain_loads(&c->ch, ld, 2), VLBE_OK);
        n = c->ch.n;
        nn = n * n;
        c->ch.load_factor = VLBE_R(1.0);
        assert_int_equal(vlbe_ale_chain_force(&c->ch, t, c->q, c->v, Q1), 0);
        assert_int_equal(vlbe_ale_chain_force_jac(&c->ch, t, c->q, c->v, K1, D1), 0);
        c->ch.load_factor = VLBE_R(0.0);
        assert_int_equal(vlbe_ale_chain_force(&c->ch, t, c->q, c->v, Q0), 0);
        assert_int_equal(vlbe_ale_chain_force_jac(&c->ch, t, c->q, c->v, K0, D0), 0);
        c->ch.load_factor = lam;
        assert_int_equal(vlbe_ale_chain_force(&c->ch, t, c->q, c->v, Ql), 0);
        assert_int_equal(vlbe_ale_chain_force_jac(&c->ch, t, c->q, c->v, Kl, Dl), 0);
        for (i = 0; i < n; ++i) {
            Qa[i] = Ql[i] - Q0[i];
            Qb[i] = lam * (Q1[i] - Q0[i]);
        }
        assert_true(maxabs(n, Qb) > 0.1);
        ASSERT_VEC_CLOSE(Qa, Qb, n, 0.0, RTOL * maxabs(n, Q1));
        for (i = 0; i < nn; ++i) {
            dl[i] = Kl[i] - K0[i];
            d1[i] = lam * (K1[i] - K0[i]);
        }
        ASSERT_VEC_CLOSE(dl, d1, nn, 0.0, RTOL * maxabs(nn, K1));
        for (i = 0; i < nn; ++i) {
            dl[i] = Dl[i] - D0[i];
            d1[i] = lam * (D1[i] - D0[i]);
        }
        assert_true(maxabs(nn, d1) > 0.0);
        ASSERT_VEC_CLOSE(dl, d1, nn, 0.0, RTOL * maxabs(nn, D1));
        /* lambda = 0: no applied load at all (mat.f, g, point loads) */
        assert_int_equal(vlbe_ale_chain_loads(&c->ch, NULL, 0), VLBE_OK);
        c->ch.g[0] = c->ch.g[1] = c->ch.g[2] = VLBE_R(0.0);
        c->ch.load_factor = VLBE_R(1.0);
        for (i = 0; i < 3; ++i) {
            c->el.mat.f[i % 2] = VLBE_R(0.0);
            c->el3.mat.f[i] = VLBE_R(0.0);
            c->rel[i].ale.mat.f[0] = c->rel[i].ale.mat.f[1] = VLBE_R(0.0);
        }
        assert_int_equal(vlbe_ale_chain_force(&c->ch, t, c->q, c->v, Qa), 0);
        ASSERT_VEC_CLOSE(Q0, Qa, n, 0.0, RTOL * maxabs(n, Q1));
    }
}

static void test_chain_band(void **state)
{
    int type, i, j;
    (void)state;
    for (type = 0; type < 3; ++type) {
        tch *c = &g_c;
        static vlbe_real K[NMAX * NMAX], D[NMAX * NMAX], Kb[NMAX * NMAX], Db[NMAX * NMAX];
        int order[NMAX], ld_;
        const vlbe_real t = VLBE_R(0.5);
        cbload cb;
        vlbe_ale_load ld[2];
        chain_make(c, type);
        cb_make(&cb, type == 2 ? 3 : 2, type == 2 ? 3 : 2, 0.5);
        ld[0] = load_make(VLBE_ALE_LOAD_FORCE, 0.2, 0.3, 0, 0, 0, 0);
        ld[0].fun = cb_fun;
        ld[0].user = &cb;
        ld[1] = load_make(VLBE_ALE_LOAD_MOMENT, 0.7, 0, 0, 0.6, 0, 0);
        assert_int_equal(vlbe_ale_chain_loads(&c->ch, ld, 2), VLBE_OK);
        assert_int_equal(vlbe_ale_chain_force_jac(&c->ch, t, c->q, c->v, K, D), 0);
        assert_int_equal(vlbe_ale_chain_band(&c->ch, order, NMAX), VLBE_OK);
        assert_int_equal(vlbe_ale_chain_layout(&c->ch), VLBE_OK);
        assert_int_equal(vlbe_ale_chain_force_jac(&c->ch, t, c->q, c->v, Kb, Db), 0);
        ld_ = c->ch.kl + c->ch.ku + 1;
        for (i = 0; i < c->ch.n; ++i)
            for (j = 0; j < c->ch.n; ++j) {
                const int di = order[i] - order[j];
                if (di > c->ch.kl || -di > c->ch.ku) {
                    assert_true(K[i * c->ch.n + j] == VLBE_R(0.0));
                    continue;
                }
                const size_t at = VLBE_BAND_IDX(ld_, c->ch.kl, order[i], order[j]);
                ASSERT_CLOSE(Kb[at], K[i * c->ch.n + j], 0.0, 0.0);
                ASSERT_CLOSE(Db[at], D[i * c->ch.n + j], 0.0, 0.0);
            }
    }
}

static void test_chain_bad_input(void **state)
{
    tch *c = &g_c;
    vlbe_real Q[NMAX], Qs[NMAX], Q0[NMAX];
    vlbe_ale_load ld[2], ok;
    cbload cb;
    const vlbe_real t = VLBE_R(0.5);
    int i, n;
    (void)state;
    chain_make(c, 0);
    n = c->ch.n;
    assert_int_equal(vlbe_ale_chain_force(&c->ch, t, c->q, c->v, Q0), 0);
    ok = load_make(VLBE_ALE_LOAD_FORCE, 0.5, 0, 0, 1, 1, 0);
    assert_int_equal(vlbe_ale_chain_loads(&c->ch, &ok, 1), VLBE_OK);
    /* the setter refuses bad loads and keeps the previous ones */
    ld[0] = load_make(7, 0.5, 0, 0, 1, 1, 0);
    assert_int_equal(vlbe_ale_chain_loads(&c->ch, ld, 1), VLBE_EARG);
    ld[0] = load_make(VLBE_ALE_LOAD_FORCE, 0.5, 0, 0, 1, 1, 0);
    ld[0].outside = 2;
    assert_int_equal(vlbe_ale_chain_loads(&c->ch, ld, 1), VLBE_EARG);
    ld[0] = load_make(VLBE_ALE_LOAD_FORCE, NAN, 0, 0, 1, 1, 0);
    assert_int_equal(vlbe_ale_chain_loads(&c->ch, ld, 1), VLBE_ENONFINITE);
    ld[0] = load_make(VLBE_ALE_LOAD_FORCE, 0.5, 0, 0, 1, INFINITY, 0);
    assert_int_equal(vlbe_ale_chain_loads(&c->ch, ld, 1), VLBE_ENONFINITE);
    assert_int_equal(vlbe_ale_chain_loads(&c->ch, ld, -1), VLBE_EARG);
    assert_true(c->ch.loads == &ok && c->ch.nloads == 1);
    /* the callbacks check again (the caller may change the array): Q untouched */
    for (i = 0; i < 6; ++i) {
        int want_rc = -1;
        vlbe_status want = VLBE_EARG;
        ld[0] = load_make(VLBE_ALE_LOAD_FORCE, 0.5, 0, 0, 1, 1, 0);
        ld[1] = load_make(VLBE_ALE_LOAD_FORCE, 0.3, 0, 0, 1, 1, 0);
        switch (i) {
        case 0: ld[1].p[0] = VLBE_R(1.3); want = VLBE_EBOUND; break; /* beyond p = 1.2 */
        case 1: ld[1].p[0] = VLBE_R(-0.1); want = VLBE_EBOUND; break;
        case 2: ld[1].p[1] = NAN; want = VLBE_ENONFINITE; want_rc = 1; break;
        case 3: ld[1].f[1] = NAN; want = VLBE_ENONFINITE; want_rc = 1; break;
        case 4: ld[1].kind = 0; break;
        default: c->ch.load_factor = NAN; want = VLBE_ENONFINITE; want_rc = 1; break;
        }
        c->ch.loads = ld;
        c->ch.nloads = 2;
        for (n = 0; n < c->ch.n; ++n) Q[n] = Qs[n] = VLBE_R(42.0);
        assert_int_equal(vlbe_ale_chain_force(&c->ch, t, c->q, c->v, Q), want_rc);
        assert_int_equal(c->ch.err, want);
        assert_int_equal(c->ch.err_load, i == 5 ? -1 : 1);
        assert_memory_equal(Q, Qs, sizeof(vlbe_real) * (size_t)c->ch.n);
        c->ch.load_factor = VLBE_R(1.0);
    }
    /* outside = 1: no load beyond the range */
    ld[0] = load_make(VLBE_ALE_LOAD_FORCE, 1.25, 0, 0, 1, 1, 0);
    ld[0].outside = 1;
    assert_int_equal(vlbe_ale_chain_loads(&c->ch, ld, 1), VLBE_OK);
    assert_int_equal(vlbe_ale_chain_force(&c->ch, t, c->q, c->v, Q), 0);
    assert_memory_equal(Q, Q0, sizeof(vlbe_real) * (size_t)c->ch.n);
    /* a failing callback */
    cb_make(&cb, 2, 2, 0.1);
    cb.fail = 1;
    ld[0] = load_make(VLBE_ALE_LOAD_FORCE, 0.5, 0, 0, 0, 0, 0);
    ld[0].fun = cb_fun;
    ld[0].user = &cb;
    assert_int_equal(vlbe_ale_chain_loads(&c->ch, ld, 1), VLBE_OK);
    assert_int_equal(vlbe_ale_chain_force(&c->ch, t, c->q, c->v, Q), -1);
    assert_int_equal(c->ch.err, VLBE_ECALLBACK);
    assert_int_equal(c->ch.err_load, 0);
    assert_int_equal(c->ch.err_elem, 1);
    /* a 3D chain without spin has no moment */
    chain_make(c, 2);
    {
        vlbe_ale3_elem *e3 = &c->el3;
        assert_int_equal(vlbe_ale3_elem_init(e3, &c->mat3, VLBE_ALE3_NO_SPIN, 0, 0), VLBE_OK);
        assert_int_equal(vlbe_ale_chain_init3(&c->ch, e3, c->node, 4, 5, NULL, 0), VLBE_OK);
        assert_int_equal(vlbe_ale_chain_layout(&c->ch), VLBE_OK);
        ld[0] = load_make(VLBE_ALE_LOAD_MOMENT, 0.5, 0, 0, 1, 0, 0);
        assert_int_equal(vlbe_ale_chain_loads(&c->ch, ld, 1), VLBE_EARG);
        assert_true(c->ch.loads == NULL && c->ch.nloads == 0);
    }
}


/* A clamped Lagrangian cable-beam chain of 6 elements over L = 1.2 (EA =
   100, EI = 1) under a force P at a = 0.7 (inside element 3) or a moment
   M at the tip, reached in two load steps of the factor (0.5, 1) with
   vlbe_dae_static.  Cubic elements with consistent loads are nodally exact
   in linear theory: w(L) = P a^2 (3L - a)/(6 EI), tip slope angle P a^2 /
   (2 EI); moment: M L^2 / (2 EI), M L / EI.  w/L is 2e-5, so the
   geometric nonlinearity (~(w/L)^2) and the axial coupling stay below
   1e-8 relative: tolerance 1e-5 + 1000 EPS (the static solve's own
   increment tolerance and float's conditioning). */
static void test_chain_static(void **state)
{
    static vlbe_real w[8000];
    static int iw[100];
    tch *c = &g_c;
    vlbe_ale_con con[2];
    vlbe_real lam[4] = {0, 0, 0, 0}, q[NMAX], rp[2];
    const double L = 1.2, a = 0.7, P = 1e-4, M = 2e-4, EI = 1.0;
    int k, i;
    (void)state;
    for (k = 0; k < 2; ++k) {
        vlbe_ale_load ld;
        vlbe_static_params sp;
        vlbe_dae sys;
        const vlbe_real r0[2] = {0, 0}, dir[2] = {1, 0};
        double wt, st;
        memset(c, 0, sizeof *c);
        c->mat.EA = VLBE_R(100.0);
        c->mat.EI = VLBE_R(1.0);
        c->mat.rhoA = VLBE_R(1.0);
        assert_int_equal(vlbe_ale_elem_init(&c->el, &c->mat, VLBE_ALE_NO_DAMP, 0, 0, 0), VLBE_OK);
        for (i = 0; i < 5; ++i) c->node[i].p = (vlbe_real)(0.3 * i);
        assert_int_equal(vlbe_ale_chain_init(&c->ch, &c->el, c->node, 5, 5, con, 2), VLBE_OK);
        memset(con, 0, sizeof con);
        con[0].type = VLBE_ALE_CON_POS;
        con[1].type = VLBE_ALE_CON_SLOPE;
        con[1].d[0] = VLBE_R(1.0);
        assert_int_equal(vlbe_ale_chain_add(&c->ch, &con[0]), VLBE_OK);
        assert_int_equal(vlbe_ale_chain_add(&c->ch, &con[1]), VLBE_OK);
        assert_int_equal(vlbe_ale_chain_layout(&c->ch), VLBE_OK);
        vlbe_ale_chain_straight(&c->ch, r0, dir, q);
        ld = k ? load_make(VLBE_ALE_LOAD_MOMENT, L, 0, 0, M, 0, 0)
               : load_make(VLBE_ALE_LOAD_FORCE, a, 0, 0, 0, -P, 0);
        assert_int_equal(vlbe_ale_chain_loads(&c->ch, &ld, 1), VLBE_OK);
        memset(&sys, 0, sizeof sys); /* gcc cannot see that the assert returns only on success */
        assert_int_equal(vlbe_ale_chain_dae(&c->ch, &sys), VLBE_OK);
        vlbe_static_params_default(&sp);
        assert_true(vlbe_static_work_len(sys.n, sys.m) <= 8000);
        for (i = 1; i <= 2; ++i) { /* load stepping */
            c->ch.load_factor = (vlbe_real)(0.5 * i);
            assert_int_equal(vlbe_dae_static(&sys, &sp, 0, q, lam, NULL, w, 8000, iw, 100),
                             VLBE_OK);
        }
        assert_int_equal(vlbe_ale_chain_point(&c->ch, 0, q, (vlbe_real)L, NULL, rp), VLBE_OK);
        wt = k ? M * L * L / (2 * EI) : -P * a * a * (3 * L - a) / (6 * EI);
        st = k ? M * L / EI : -P * a * a / (2 * EI);
        tu_report(k ? "chain, tip moment: tip deflection vs M L^2 / 2EI (rel.)"
                    : "chain, force at a: tip deflection vs P a^2 (3L - a) / 6EI (rel.)",
                  fabs((double)q[c->node[4].ofs + 1] - wt) / fabs(wt), 1e-5 + 1e3 * EPSD);
        tu_report(k ? "chain, tip moment: tip slope vs M L / EI (rel.)"
                    : "chain, force at a: tip slope vs P a^2 / 2EI (rel.)",
                  fabs(atan2((double)rp[1], (double)rp[0]) - st) / fabs(st), 1e-5 + 1e3 * EPSD);
        ASSERT_CLOSE(q[c->node[4].ofs + 1], wt, 1e-5 + 1e3 * EPSD, 0.0);
        ASSERT_CLOSE(atan2((double)rp[1], (double)rp[0]), st, 1e-5 + 1e3 * EPSD, 0.0);
    }
}

/* ===== co-rotational beams =============================================== */
#define CNE 4
typedef struct tbeam {
    vlbe_cr2d_mat mat;
    vlbe_cr2d_elem el[16];
    vlbe_cr2d_beam b;
    vlbe_real q[3 * 17], v[3 * 17];
    int ne;
} tbeam;

static tbeam g_b;

/* ne elements of length 0.5 along a line at 20 deg (along x when
   straight: lengths exactly 0.5), deformed and moving unless straight > 1
   (then q = 0) */
static void beam_make(tbeam *b, int ne, int straight, unsigned flags)
{
    int e, k;
    const double a = straight ? 0.0 : 0.35;
    memset(b, 0, sizeof *b);
    b->ne = ne;
    b->mat.EA = VLBE_R(50.0);
    b->mat.EI = VLBE_R(2.0);
    b->mat.rhoA = VLBE_R(1.2);
    b->mat.rhoI = VLBE_R(0.01);
    for (e = 0; e < ne; ++e) {
        const vlbe_real X1[2] = {(vlbe_real)(0.5 * e * cos(a)), (vlbe_real)(0.5 * e * sin(a))};
        const vlbe_real X2[2] = {(vlbe_real)(0.5 * (e + 1) * cos(a)),
                                 (vlbe_real)(0.5 * (e + 1) * sin(a))};
        assert_int_equal(vlbe_cr2d_elem_init(&b->el[e], &b->mat, X1, X2, flags), VLBE_OK);
    }
    assert_int_equal(vlbe_cr2d_beam_init(&b->b, b->el, ne, NULL, 0), VLBE_OK);
    for (k = 0; k < 3 * (ne + 1); ++k) {
        b->q[k] = straight > 1 ? VLBE_R(0.0) : (vlbe_real)(0.08 * sin(1.1 * k + 0.3));
        b->v[k] = (vlbe_real)(0.4 * cos(0.9 * k + 0.5));
    }
}

static vlbe_cr2d_load cload_make(int kind, double s0, double s1, double s2, double f0, double f1)
{
    vlbe_cr2d_load l;
    memset(&l, 0, sizeof l);
    l.kind = kind;
    l.s[0] = (vlbe_real)s0;
    l.s[1] = (vlbe_real)s1;
    l.s[2] = (vlbe_real)s2;
    l.f[0] = (vlbe_real)f0;
    l.f[1] = (vlbe_real)f1;
    return l;
}

/* position and section rotation at xi of element e, from [H] eqs. 7-9
   written out: r = x1 + xi (x2 - x1) + L (N2 th1 + N4 th2) e2, psi = beta +
   N2' th1 + N4' th2, th_j = a0 + phi_j - beta (near 0 here, no wrap) */
static void beam_point(const tbeam *b, int e, double xi, const vlbe_real *q, double *r,
                       double *psi)
{
    const vlbe_cr2d_elem *el = &b->el[e];
    const vlbe_real *u = q + 3 * e;
    const double x1 = (double)el->X[0] + (double)u[0], y1 = (double)el->X[1] + (double)u[1];
    const double dx = (double)el->X[2] + (double)u[3] - x1;
    const double dy = (double)el->X[3] + (double)u[4] - y1;
    const double beta = atan2(dy, dx), L = (double)el->L;
    const double th1 = (double)el->a0 + (double)u[2] - beta;
    const double th2 = (double)el->a0 + (double)u[5] - beta;
    const double n2 = xi * (1 - xi) * (1 - xi), n4 = xi * xi * (xi - 1);
    const double d2 = (1 - xi) * (1 - 3 * xi), d4 = xi * (3 * xi - 2);
    const double w = L * (n2 * th1 + n4 * th2);
    r[0] = x1 + xi * dx - w * sin(beta);
    r[1] = y1 + xi * dy + w * cos(beta);
    *psi = beta + d2 * th1 + d4 * th2;
}

static void beam_Qload(tbeam *b, vlbe_real t, const vlbe_real *q, const vlbe_real *v, vlbe_real *Q)
{
    vlbe_real Q0[3 * 17];
    vlbe_cr2d_beam b0 = b->b;
    int i;
    assert_int_equal(vlbe_cr2d_beam_force(&b->b, t, q, v, Q), 0);
    b0.loads = NULL;
    b0.nloads = 0;
    b0.dist[0] = b0.dist[1] = VLBE_R(0.0);
    b0.dist_e = NULL;
    assert_int_equal(vlbe_cr2d_beam_force(&b0, t, q, v, Q0), 0);
    for (i = 0; i < b->b.n; ++i) Q[i] -= Q0[i];
}
static void beam_Qload_fn(void *b, vlbe_real t, const vlbe_real *q, const vlbe_real *v,
                          vlbe_real *Q)
{
    beam_Qload((tbeam *)b, t, q, v, Q);
}

static void test_cr2d_force_potential(void **state)
{
    int kind, j;
    (void)state;
    for (kind = 0; kind < 2; ++kind) {
        tbeam *b = &g_b;
        const double s = 0.5 * 1 + 0.5 * 0.37; /* element 1, xi = 0.37 */
        vlbe_cr2d_load ld;
        vlbe_real Q[3 * 17], q[3 * 17];
        double ref[3 * 17], r[2], psi;
        const double F[2] = {0.7, -1.9};
        beam_make(b, CNE, 0, 0u);
        ld = kind ? cload_make(VLBE_CR2D_LOAD_MOMENT, s, 0, 0, 1.3, 0)
                  : cload_make(VLBE_CR2D_LOAD_FORCE, s, 0, 0, F[0], F[1]);
        b->b.load = VLBE_R(0.8);
        assert_int_equal(vlbe_cr2d_beam_loads(&b->b, &ld, 1), VLBE_OK);
        beam_Qload(b, 0, b->q, b->v, Q);
        for (j = 0; j < b->b.n; ++j) {
            const double h = cbrt(EPSD) * fmax(1.0, fabs((double)b->q[j]));
            double Vp, Vm;
            memcpy(q, b->q, sizeof q);
            q[j] = (vlbe_real)((double)b->q[j] + h);
            beam_point(b, 1, 0.37, q, r, &psi);
            Vp = kind ? -1.3 * psi : -(F[0] * r[0] + F[1] * r[1]);
            q[j] = (vlbe_real)((double)b->q[j] - h);
            beam_point(b, 1, 0.37, q, r, &psi);
            Vm = kind ? -1.3 * psi : -(F[0] * r[0] + F[1] * r[1]);
            ref[j] = -0.8 * (Vp - Vm) / (2.0 * h);
        }
        ASSERT_VEC_CLOSE(Q, ref, b->b.n, 0.0, FDTOL * maxabs(b->b.n, Q));
    }
}

static void beam_jac_check(tbeam *b, vlbe_real t)
{
    static vlbe_real K[51 * 51], D[51 * 51], K0[51 * 51], D0[51 * 51];
    static double Kf[51 * 51], Df[51 * 51];
    vlbe_real Qp[3 * 17];
    vlbe_cr2d_beam b0 = b->b;
    const int n = b->b.n;
    double sc;
    int i;
    assert_int_equal(vlbe_cr2d_beam_force_jac(&b->b, t, b->q, b->v, K, D), 0);
    b0.loads = NULL;
    b0.nloads = 0;
    b0.dist[0] = b0.dist[1] = VLBE_R(0.0);
    b0.dist_e = NULL;
    assert_int_equal(vlbe_cr2d_beam_force_jac(&b0, t, b->q, b->v, K0, D0), 0);
    for (i = 0; i < n * n; ++i) {
        K[i] -= K0[i];
        D[i] -= D0[i];
    }
    fd_qv(beam_Qload_fn, b, t, b->q, b->v, n, Kf, Df);
    assert_true(maxabs(n * n, K) > 0.01);
    assert_int_equal(vlbe_cr2d_beam_force(&b->b, t, b->q, b->v, Qp), 0);
    sc = fmax(maxabs(n, Qp), fmax(maxabs(n * n, D), maxabs(n * n, K)));
    ASSERT_VEC_CLOSE(K, Kf, n * n, 0.0, FDTOL * sc);
    ASSERT_VEC_CLOSE(D, Df, n * n, 0.0, FDTOL * sc);
}

static void test_cr2d_jacobian(void **state)
{
    int k;
    (void)state;
    for (k = 0; k < 5; ++k) {
        tbeam *b = &g_b;
        vlbe_cr2d_load ld[3];
        cbload cb;
        vlbe_real de[2 * CNE];
        int i;
        beam_make(b, CNE, 0, 0u);
        cb_make(&cb, k == 3 ? 1 : 2, 2, 0.2 + 0.1 * k);
        ld[0] = cload_make(VLBE_CR2D_LOAD_FORCE, 0.61, 0, 0, 0.9, -1.4);
        ld[1] = cload_make(VLBE_CR2D_LOAD_MOMENT, 1.33, 0, 0, 0.7, 0);
        ld[2] = cload_make(VLBE_CR2D_LOAD_FORCE, 0.2, 0.4, 0.3, -0.6, 0.8);
        if (k >= 2) {
            ld[2].kind = k == 3 ? VLBE_CR2D_LOAD_MOMENT : VLBE_CR2D_LOAD_FORCE;
            ld[2].fun = cb_fun;
            ld[2].user = &cb;
        }
        if (k == 1 || k == 4) { /* distributed, beam-wide and per element */
            b->b.dist[0] = VLBE_R(0.3);
            b->b.dist[1] = VLBE_R(-1.1);
            for (i = 0; i < 2 * CNE; ++i) de[i] = (vlbe_real)(0.2 * sin(i + 0.5));
            b->b.dist_e = de;
        }
        b->b.load = VLBE_R(1.2);
        assert_int_equal(vlbe_cr2d_beam_loads(&b->b, ld, k == 4 ? 0 : 3), VLBE_OK);
        beam_jac_check(b, VLBE_R(0.9));
    }
}

/* LINEAR elements take their loads through the linearised interpolation:
   Q constant (the deformed state's equals the reference state's), K = 0,
   and at the reference state the co-rotational element's Q */
static void test_cr2d_linear(void **state)
{
    tbeam *b = &g_b;
    static vlbe_real K[51 * 51], D[51 * 51], K0[51 * 51], D0[51 * 51];
    vlbe_real Qd[51], Qr[51], Qn[51], z[51];
    vlbe_cr2d_load ld[2];
    vlbe_cr2d_beam b0;
    int i, n;
    (void)state;
    ld[0] = cload_make(VLBE_CR2D_LOAD_FORCE, 0.61, 0, 0, 0.9, -1.4);
    ld[1] = cload_make(VLBE_CR2D_LOAD_MOMENT, 1.33, 0, 0, 0.7, 0);
    beam_make(b, CNE, 0, 0u);
    n = b->b.n;
    memset(z, 0, sizeof z);
    b->b.dist[1] = VLBE_R(-0.9);
    assert_int_equal(vlbe_cr2d_beam_loads(&b->b, ld, 2), VLBE_OK);
    beam_Qload(b, 0, z, b->v, Qn);
    beam_make(b, CNE, 0, VLBE_CR2D_LINEAR);
    b->b.dist[1] = VLBE_R(-0.9);
    assert_int_equal(vlbe_cr2d_beam_loads(&b->b, ld, 2), VLBE_OK);
    beam_Qload(b, 0, b->q, b->v, Qd);
    beam_Qload(b, 0, z, b->v, Qr);
    ASSERT_VEC_CLOSE(Qd, Qr, n, 0.0, RTOL * maxabs(n, Qr));
    ASSERT_VEC_CLOSE(Qr, Qn, n, 0.0, RTOL * maxabs(n, Qn));
    b0 = b->b;
    b0.loads = NULL;
    b0.nloads = 0;
    b0.dist[1] = VLBE_R(0.0);
    assert_int_equal(vlbe_cr2d_beam_force_jac(&b->b, 0, b->q, b->v, K, D), 0);
    assert_int_equal(vlbe_cr2d_beam_force_jac(&b0, 0, b->q, b->v, K0, D0), 0);
    for (i = 0; i < n * n; ++i) assert_true(K[i] == K0[i] && D[i] == D0[i]);
}

static void test_cr2d_node_load(void **state)
{
    tbeam *b = &g_b;
    static vlbe_real K[51 * 51], D[51 * 51], K0[51 * 51], D0[51 * 51];
    vlbe_real Q[3 * 17], P[3 * 17], Qp[3 * 17];
    vlbe_cr2d_load ld[3];
    int n;
    (void)state;
    beam_make(b, CNE, 1, 0u);
    n = b->b.n;
    ld[0] = cload_make(VLBE_CR2D_LOAD_FORCE, 1.0, 0, 0, 0.9, -1.4);  /* node 2 */
    ld[1] = cload_make(VLBE_CR2D_LOAD_MOMENT, 1.0, 0, 0, 0.7, 0);
    ld[2] = cload_make(VLBE_CR2D_LOAD_FORCE, 2.0, 0, 0, 0.3, 0.5);   /* last node */
    assert_int_equal(vlbe_cr2d_beam_loads(&b->b, ld, 3), VLBE_OK);
    assert_int_equal(vlbe_cr2d_beam_force(&b->b, 0, b->q, b->v, Q), 0);
    assert_int_equal(vlbe_cr2d_beam_force_jac(&b->b, 0, b->q, b->v, K, D), 0);
    memset(P, 0, sizeof P);
    P[6] = VLBE_R(0.9);
    P[7] = VLBE_R(-1.4);
    P[8] = VLBE_R(0.7);
    P[12] = VLBE_R(0.3);
    P[13] = VLBE_R(0.5);
    assert_int_equal(vlbe_cr2d_beam_loads(&b->b, NULL, 0), VLBE_OK);
    b->b.P = P;
    assert_int_equal(vlbe_cr2d_beam_force(&b->b, 0, b->q, b->v, Qp), 0);
    assert_int_equal(vlbe_cr2d_beam_force_jac(&b->b, 0, b->q, b->v, K0, D0), 0);
    ASSERT_VEC_CLOSE(Q, Qp, n, 0.0, RTOL * maxabs(n, Qp));
    ASSERT_VEC_CLOSE(K, K0, n * n, 0.0, RTOL * maxabs(n * n, K0));
}

static void test_cr2d_dist_resultant(void **state)
{
    tbeam *b = &g_b;
    vlbe_real Q[3 * 17];
    double R[2] = {0, 0};
    int i;
    (void)state;
    beam_make(b, CNE, 0, 0u);
    b->b.dist[0] = VLBE_R(0.4);
    b->b.dist[1] = VLBE_R(-2.5);
    b->b.load = VLBE_R(0.6);
    beam_Qload(b, 0, b->q, b->v, Q);
    for (i = 0; i <= CNE; ++i) {
        R[0] += (double)Q[3 * i];
        R[1] += (double)Q[3 * i + 1];
    }
    ASSERT_CLOSE(R[0], 0.6 * 0.4 * 0.5 * CNE, 0.0, RTOL * 2.5);
    ASSERT_CLOSE(R[1], 0.6 * -2.5 * 0.5 * CNE, 0.0, RTOL * 2.5);
}

/* static solve of a straight beam along x with the given fixes */
static void beam_static(tbeam *b, vlbe_real *lam)
{
    static vlbe_real w[20000];
    static int iw[200];
    vlbe_static_params sp;
    vlbe_dae sys;
    memset(&sys, 0, sizeof sys); /* gcc cannot see that the assert returns only on success */
    assert_int_equal(vlbe_cr2d_beam_dae(&b->b, &sys), VLBE_OK);
    vlbe_static_params_default(&sp);
    assert_true(vlbe_static_work_len(sys.n, sys.m) <= 20000);
    assert_int_equal(vlbe_dae_static(&sys, &sp, 0, b->q, lam, NULL, w, 20000, iw, 200), VLBE_OK);
}

static vlbe_cr2d_fix fix_make(int dof)
{
    vlbe_cr2d_fix f;
    memset(&f, 0, sizeof f);
    f.dof = dof;
    return f;
}

static void test_cr2d_cantilever(void **state)
{
    tbeam *b = &g_b;
    vlbe_cr2d_fix fx[3];
    vlbe_real lam[3] = {0, 0, 0}; /* the multipliers start at 0 */
    const int ne = 8;
    const double L = 0.5 * ne, qd = -1e-5, EI = 2.0;
    int i;
    (void)state;
    beam_make(b, ne, 2, 0u);
    for (i = 0; i < 3; ++i) fx[i] = fix_make(i);
    assert_int_equal(vlbe_cr2d_beam_init(&b->b, b->el, ne, fx, 3), VLBE_OK);
    b->b.dist[1] = (vlbe_real)(qd / 4);
    b->b.load = VLBE_R(4.0);
    memset(b->q, 0, sizeof b->q);
    beam_static(b, lam);
    /* linear theory, nodally exact for cubic elements with consistent loads;
       w/L = 6e-4: the geometric nonlinearity is ~(w/L)^2, below 1e-6 */
    tu_report("cr2d cantilever, uniform load: tip vs q L^4 / 8EI (rel.)",
              fabs((double)b->q[3 * ne + 1] - qd * pow(L, 4) / (8 * EI)) / fabs(qd * pow(L, 4) / (8 * EI)),
              1e-5 + 1e3 * EPSD);
    ASSERT_CLOSE(b->q[3 * ne + 1], qd * pow(L, 4) / (8 * EI), 1e-5 + 1e3 * EPSD, 0.0);
    ASSERT_CLOSE(b->q[3 * ne + 2], qd * pow(L, 3) / (6 * EI), 1e-5 + 1e3 * EPSD, 0.0);
    ASSERT_CLOSE(-lam[1], -qd * L, 1e-5 + 1e3 * EPSD, 0.0); /* support reaction */
}

static void test_cr2d_simply_supported(void **state)
{
    tbeam *b = &g_b;
    vlbe_cr2d_fix fx[3];
    vlbe_real lam[3] = {0, 0, 0};
    const int ne = 8;
    const double L = 0.5 * ne, qd = -1e-5, EI = 2.0;
    (void)state;
    beam_make(b, ne, 2, 0u);
    fx[0] = fix_make(0);
    fx[1] = fix_make(1);
    fx[2] = fix_make(3 * ne + 1);
    assert_int_equal(vlbe_cr2d_beam_init(&b->b, b->el, ne, fx, 3), VLBE_OK);
    b->b.dist[1] = (vlbe_real)qd;
    memset(b->q, 0, sizeof b->q);
    beam_static(b, lam);
    tu_report("cr2d simply supported, uniform load: midspan vs 5 q L^4 / 384EI (rel.)",
              fabs((double)b->q[3 * (ne / 2) + 1] - 5 * qd * pow(L, 4) / (384 * EI)) /
                  fabs(5 * qd * pow(L, 4) / (384 * EI)),
              1e-5 + 1e3 * EPSD);
    ASSERT_CLOSE(b->q[3 * (ne / 2) + 1], 5 * qd * pow(L, 4) / (384 * EI), 1e-5 + 1e3 * EPSD, 0.0);
    ASSERT_CLOSE(b->q[2], qd * pow(L, 3) / (24 * EI), 1e-5 + 1e3 * EPSD, 0.0);
}

/* A constant force F crossing a simply supported beam (L = 4, 8 elements,
   EI = 2, rhoA = 1.2: first period 2 pi / (pi^2 sqrt(EI / (rhoA L^4))) =
   7.8 s) at constant speed in 120 s, HHT (alpha = -0.05, h = 0.05) with
   light Rayleigh damping (alpha = 0.05 / s).  The dynamic part of the
   response is of the order of the ratio of the crossing frequency to the
   first one, pi c / L / omega_1 = 3 % of the static deflection, and decays
   with the damping: the midspan deflection must follow the static
   influence line F s (3 L^2 - 4 s^2) / (48 EI) (s <= L/2, symmetric)
   within 5 % of its largest value F L^3 / (48 EI). */
static void test_cr2d_moving_quasistatic(void **state)
{
    static vlbe_real w[40000];
    static int iw[200];
    tbeam *b = &g_b;
    vlbe_cr2d_fix fx[3];
    vlbe_cr2d_load ld;
    vlbe_hht_params hp;
    vlbe_hht st;
    vlbe_dae sys;
    const int ne = 8;
    const double L = 4.0, EI = 2.0, F = -1e-3, T = 120.0, h = 0.05;
    const double wmax = fabs(F) * L * L * L / (48 * EI);
    double worst = 0.0;
    int k, e, nstep = (int)(T / h + 0.5);
    (void)state;
    beam_make(b, ne, 2, 0u);
    b->mat.ray_a = VLBE_R(0.05);
    for (e = 0; e < ne; ++e) {
        const vlbe_real X1[2] = {(vlbe_real)(0.5 * e), 0}, X2[2] = {(vlbe_real)(0.5 * (e + 1)), 0};
        assert_int_equal(vlbe_cr2d_elem_init(&b->el[e], &b->mat, X1, X2, 0u), VLBE_OK);
    }
    fx[0] = fix_make(0);
    fx[1] = fix_make(1);
    fx[2] = fix_make(3 * ne + 1);
    assert_int_equal(vlbe_cr2d_beam_init(&b->b, b->el, ne, fx, 3), VLBE_OK);
    ld = cload_make(VLBE_CR2D_LOAD_FORCE, 0, L / T, 0, 0, F);
    assert_int_equal(vlbe_cr2d_beam_loads(&b->b, &ld, 1), VLBE_OK);
    memset(b->q, 0, sizeof b->q);
    memset(b->v, 0, sizeof b->v);
    memset(&sys, 0, sizeof sys);
    sys.n = b->b.n;
    sys.m = 3;
    sys.user = &b->b;
    sys.mass = vlbe_cr2d_beam_mass;
    sys.force = vlbe_cr2d_beam_force;
    sys.force_jac = vlbe_cr2d_beam_force_jac;
    sys.mass_jac = vlbe_cr2d_beam_mass_jac;
    sys.constr = vlbe_cr2d_beam_constr;
    sys.constr_jac = vlbe_cr2d_beam_constr_jac;
    sys.constr_acc = vlbe_cr2d_beam_constr_acc;
    assert_int_equal(vlbe_hht_params_alpha(&hp, VLBE_R(-0.05)), VLBE_OK);
    assert_true(vlbe_hht_work_len(sys.n, sys.m) <= 40000);
    assert_int_equal(vlbe_hht_init(&st, &sys, &hp, 0, b->q, b->v, w, 40000, iw, 200), VLBE_OK);
    for (k = 1; k <= nstep; ++k) {
        double s, ws, err;
        assert_int_equal(vlbe_hht_step(&st, (vlbe_real)h), VLBE_OK);
        s = L * (double)st.t / T;
        if (s > L / 2) s = L - s;
        ws = F * s * (3 * L * L - 4 * s * s) / (48 * EI);
        err = fabs((double)st.q[3 * (ne / 2) + 1] - ws);
        if (err > worst) worst = err;
    }
    tu_report("moving force: |w_mid - static| / w_max", worst / wmax, 0.05);
    assert_true(worst <= 0.05 * wmax);
}

static void test_cr2d_factor_band(void **state)
{
    tbeam *b = &g_b;
    static vlbe_real K1[51 * 51], K0[51 * 51], Kl[51 * 51], D[51 * 51], Kb[51 * 51], Db[51 * 51];
    vlbe_real Q1[51], Q0[51], Ql[51], a[51], c[51];
    vlbe_cr2d_load ld[2];
    cbload cb;
    int order[60], i, j, n, ldb;
    const vlbe_real lam = VLBE_R(0.37);
    (void)state;
    beam_make(b, CNE, 0, 0u);
    n = b->b.n;
    cb_make(&cb, 2, 2, 0.4);
    ld[0] = cload_make(VLBE_CR2D_LOAD_FORCE, 0.3, 0.2, 0, 0, 0);
    ld[0].fun = cb_fun;
    ld[0].user = &cb;
    ld[1] = cload_make(VLBE_CR2D_LOAD_MOMENT, 1.7, 0, 0, 0.6, 0);
    b->b.dist[1] = VLBE_R(-0.8);
    assert_int_equal(vlbe_cr2d_beam_loads(&b->b, ld, 2), VLBE_OK);
    b->b.load = VLBE_R(1.0);
    assert_int_equal(vlbe_cr2d_beam_force(&b->b, 0, b->q, b->v, Q1), 0);
    assert_int_equal(vlbe_cr2d_beam_force_jac(&b->b, 0, b->q, b->v, K1, D), 0);
    b->b.load = VLBE_R(0.0);
    assert_int_equal(vlbe_cr2d_beam_force(&b->b, 0, b->q, b->v, Q0), 0);
    assert_int_equal(vlbe_cr2d_beam_force_jac(&b->b, 0, b->q, b->v, K0, D), 0);
    b->b.load = lam;
    assert_int_equal(vlbe_cr2d_beam_force(&b->b, 0, b->q, b->v, Ql), 0);
    assert_int_equal(vlbe_cr2d_beam_force_jac(&b->b, 0, b->q, b->v, Kl, D), 0);
    for (i = 0; i < n; ++i) {
        a[i] = Ql[i] - Q0[i];
        c[i] = lam * (Q1[i] - Q0[i]);
    }
    ASSERT_VEC_CLOSE(a, c, n, 0.0, RTOL * maxabs(n, Q1));
    for (i = 0; i < n * n; ++i)
        ASSERT_CLOSE(Kl[i] - K0[i], lam * (K1[i] - K0[i]), 0.0, RTOL * maxabs(n * n, K1));
    /* band = dense */
    assert_int_equal(vlbe_cr2d_beam_band(&b->b, order, 60), VLBE_OK);
    assert_int_equal(vlbe_cr2d_beam_force_jac(&b->b, 0, b->q, b->v, Kb, Db), 0);
    ldb = b->b.kl + b->b.ku + 1;
    for (i = 0; i < n; ++i)
        for (j = 0; j < n; ++j) {
            const int di = order[i] - order[j];
            if (di > b->b.kl || -di > b->b.ku) continue;
            const size_t at = VLBE_BAND_IDX(ldb, b->b.kl, order[i], order[j]);
            ASSERT_CLOSE(Kb[at], Kl[i * n + j], 0.0, 0.0);
            ASSERT_CLOSE(Db[at], D[i * n + j], 0.0, 0.0);
        }
}

static void test_cr2d_bad_input(void **state)
{
    tbeam *b = &g_b;
    vlbe_real Q[51], Qs[51], Q0[51];
    vlbe_cr2d_load ld[2], ok;
    cbload cb;
    vlbe_cr2d_joint jt;
    int i, n;
    (void)state;
    beam_make(b, CNE, 0, 0u);
    n = b->b.n;
    assert_true(b->b.user == NULL);
    assert_int_equal(vlbe_cr2d_beam_force(&b->b, 0, b->q, b->v, Q0), 0);
    ok = cload_make(VLBE_CR2D_LOAD_FORCE, 0.5, 0, 0, 1, 1);
    assert_int_equal(vlbe_cr2d_beam_loads(&b->b, &ok, 1), VLBE_OK);
    ld[0] = cload_make(9, 0.5, 0, 0, 1, 1);
    assert_int_equal(vlbe_cr2d_beam_loads(&b->b, ld, 1), VLBE_EARG);
    ld[0] = cload_make(VLBE_CR2D_LOAD_FORCE, NAN, 0, 0, 1, 1);
    assert_int_equal(vlbe_cr2d_beam_loads(&b->b, ld, 1), VLBE_ENONFINITE);
    assert_int_equal(vlbe_cr2d_beam_loads(&b->b, NULL, 2), VLBE_EARG);
    assert_true(b->b.loads == &ok && b->b.nloads == 1);
    for (i = 0; i < 6; ++i) {
        int want_rc = -1;
        vlbe_status want = VLBE_EARG;
        ld[0] = cload_make(VLBE_CR2D_LOAD_FORCE, 0.5, 0, 0, 1, 1);
        ld[1] = cload_make(VLBE_CR2D_LOAD_FORCE, 0.3, 0, 0, 1, 1);
        switch (i) {
        case 0: ld[1].s[0] = VLBE_R(2.01); want = VLBE_EBOUND; break;
        case 1: ld[1].s[0] = VLBE_R(-0.01); want = VLBE_EBOUND; break;
        case 2: ld[1].s[2] = INFINITY; want = VLBE_ENONFINITE; want_rc = 1; break;
        case 3: ld[1].f[0] = NAN; want = VLBE_ENONFINITE; want_rc = 1; break;
        case 4: ld[1].kind = 3; break;
        default: b->b.dist[0] = NAN; want = VLBE_ENONFINITE; want_rc = 1; break;
        }
        b->b.loads = ld;
        b->b.nloads = 2;
        for (n = 0; n < b->b.n; ++n) Q[n] = Qs[n] = VLBE_R(42.0);
        assert_int_equal(vlbe_cr2d_beam_force(&b->b, 0, b->q, b->v, Q), want_rc);
        assert_int_equal(b->b.err, want);
        assert_int_equal(b->b.err_load, i == 5 ? -1 : 1);
        assert_memory_equal(Q, Qs, sizeof(vlbe_real) * (size_t)b->b.n);
        b->b.dist[0] = VLBE_R(0.0);
    }
    /* outside = 1: no load */
    ld[0] = cload_make(VLBE_CR2D_LOAD_FORCE, 2.5, 0, 0, 1, 1);
    ld[0].outside = 1;
    assert_int_equal(vlbe_cr2d_beam_loads(&b->b, ld, 1), VLBE_OK);
    assert_int_equal(vlbe_cr2d_beam_force(&b->b, 0, b->q, b->v, Q), 0);
    assert_memory_equal(Q, Q0, sizeof(vlbe_real) * (size_t)b->b.n);
    /* a failing callback */
    cb_make(&cb, 2, 2, 0.1);
    cb.fail = 1;
    ld[0] = cload_make(VLBE_CR2D_LOAD_FORCE, 0.7, 0, 0, 0, 0);
    ld[0].fun = cb_fun;
    ld[0].user = &cb;
    assert_int_equal(vlbe_cr2d_beam_loads(&b->b, ld, 1), VLBE_OK);
    assert_int_equal(vlbe_cr2d_beam_force(&b->b, 0, b->q, b->v, Q), -1);
    assert_int_equal(b->b.err, VLBE_ECALLBACK);
    assert_int_equal(b->b.err_elem, 1);
    assert_int_equal(b->b.err_load, 0);
    /* no loads between the nodes of the transition element */
    jt.C[0] = VLBE_R(0.4);
    jt.C[1] = VLBE_R(0.0);
    jt.a[0] = VLBE_R(1.0);
    jt.a[1] = VLBE_R(0.0);
    beam_make(b, CNE, 2, 0u);
    b->b.joint = &jt;
    b->b.trans = 0;
    ld[0] = cload_make(VLBE_CR2D_LOAD_FORCE, 0.2, 0, 0, 1, 1);
    assert_int_equal(vlbe_cr2d_beam_loads(&b->b, ld, 1), VLBE_OK);
    for (n = 0; n < b->b.n; ++n) Q[n] = Qs[n] = VLBE_R(42.0);
    assert_int_equal(vlbe_cr2d_beam_force(&b->b, 0, b->q, b->v, Q), -1);
    assert_int_equal(b->b.err, VLBE_EARG);
    assert_memory_equal(Q, Qs, sizeof(vlbe_real) * (size_t)b->b.n);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_chain_force_potential),
        cmocka_unit_test(test_chain_moment_potential),
        cmocka_unit_test(test_chain_moment3),
        cmocka_unit_test(test_chain_jacobian),
        cmocka_unit_test(test_chain_kernel),
        cmocka_unit_test(test_chain_factor),
        cmocka_unit_test(test_chain_band),
        cmocka_unit_test(test_chain_bad_input),
        cmocka_unit_test(test_chain_static),
        cmocka_unit_test(test_cr2d_force_potential),
        cmocka_unit_test(test_cr2d_jacobian),
        cmocka_unit_test(test_cr2d_linear),
        cmocka_unit_test(test_cr2d_node_load),
        cmocka_unit_test(test_cr2d_dist_resultant),
        cmocka_unit_test(test_cr2d_cantilever),
        cmocka_unit_test(test_cr2d_simply_supported),
        cmocka_unit_test(test_cr2d_moving_quasistatic),
        cmocka_unit_test(test_cr2d_factor_band),
        cmocka_unit_test(test_cr2d_bad_input),
    };
    return cmocka_run_group_tests_name("loads", tests, NULL, NULL);
}

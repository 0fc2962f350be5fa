/* test_scenes_shaft.c -- chains of 3D beam-shaft elements (ancf_ale.h,
   vlbe_ale_chain_init3) and the spinning-shaft scene (VLBSE scene 4.3;
   examples/spinning_shaft.c against the modal series of ex_katz.h).
   -- part of vlbe                                  SPDX-License-Identifier: MIT

   Tests
     chain3_jacobians    a 3D chain with every node kind (fixed, free with
                         equal-length groups, prescribed with p'' != 0),
                         spin, point masses and gravity, at a curved,
                         twisted, moving state: K = dQ/dq, D = dQ/dv,
                         d(M a)/dq, C_q, C_t and gamma = -d2C/ds2 along
                         (1, v) against central differences
     chain3_layout       node layout with and without spin, the rows of
                         POS (mask), SLOPE, SPIN; planar-only constraints,
                         sliding nodes and a SPIN without spin angle are
                         VLBE_EARG; insert/remove/length say VLBE_EARG
     straight_spin       the scene's shaft without load, spinning: stays
                         exactly straight (transverse coordinates 0) and
                         every node spins at Omega
     scene_converges     case a = 0.5, k_omega = 1 (1000 steps, load from
                         0.01 l): the 4-element errors are below 2 % of U_s
                         (measured 0.66-1.6 %) and 8 elements divide each
                         of the four by at least 2.5 (measured 3.1-12)
   Tolerances: differences with the step h = EPS^(1/3) L (L = 0.3 the
   element length, the scale on which the forces vary: with h =
   EPS^(1/3) the truncation error measured 3.6 times the tolerance, with
   L/3 it falls as h^2 -- the Jacobians are right, the step was not) have
   errors ~ EPS^(2/3) times the scale of the entries: 64 EPS^(2/3) of the
   largest entry of the matrix (as in the element suites).  The scene tests run in double only (their margins were
   measured in double); the float build runs the chain checks. */
#include "test_util.h"
#define VLBE_EXAMPLE_NO_MAIN
#include "../examples/spinning_shaft.c"

#define EPS ((double)VLBE_EPS)
#define FD_ERR (cbrt(EPS) * cbrt(EPS))
#define C3_LEN 0.3 /* element length of the test chain: the scale on which its
                      forces vary, so the difference step is EPS^(1/3) L */

/* -- a chain with every node kind ----------------------------------------- */
typedef struct c3 {
    vlbe_ale3_elem el;
    vlbe_ale_chain ch;
    vlbe_ale_node node[5];
    vlbe_ale_con con[8];
} c3;

static void c3_make(c3 *c, unsigned flags)
{
    vlbe_ale3_mat m;
    vlbe_ale_con k;
    int i;
    memset(c, 0, sizeof *c);
    memset(&m, 0, sizeof m); /* gcc -O2 cannot see that mat_circle writes it */
    assert_int_equal(vlbe_ale3_mat_circle(&m, VLBE_R(2.0), VLBE_R(40.0), VLBE_R(15.0),
                                          VLBE_R(0.3)), VLBE_OK);
    m.c_eps = VLBE_R(0.02);
    m.c_kap = VLBE_R(0.03);
    m.c_phi = VLBE_R(0.01);
    m.f[0] = VLBE_R(0.2);
    m.f[1] = VLBE_R(-0.5);
    m.f[2] = VLBE_R(0.1);
    assert_int_equal(vlbe_ale3_elem_init(&c->el, &m, flags, 0, 0), VLBE_OK);
    for (i = 0; i < 5; ++i) c->node[i].p = (vlbe_real)(0.3 * i);
    c->node[0].pmode = VLBE_ALE_PFIXED;
    c->node[1].pmode = VLBE_ALE_PFREE;
    c->node[2].pmode = VLBE_ALE_PPRESCRIBED;
    c->node[2].pd = VLBE_R(0.4);
    c->node[2].pdd = VLBE_R(-0.3);
    c->node[3].pmode = VLBE_ALE_PFREE;
    c->node[4].pmode = VLBE_ALE_PFIXED;
    c->node[3].mass = VLBE_R(0.7);
    assert_int_equal(vlbe_ale_chain_init3(&c->ch, &c->el, c->node, 5, 5, c->con, 8), VLBE_OK);
    c->ch.g[0] = VLBE_R(0.3);
    c->ch.g[1] = VLBE_R(-9.81);
    c->ch.g[2] = VLBE_R(1.0);
    memset(&k, 0, sizeof k);
    k.type = VLBE_ALE_CON_POS;
    k.v[0] = VLBE_R(0.01);
    assert_int_equal(vlbe_ale_chain_add(&c->ch, &k), VLBE_OK);
    k.node = 4;
    k.which = 5; /* x and z */
    k.v[2] = VLBE_R(1.2);
    assert_int_equal(vlbe_ale_chain_add(&c->ch, &k), VLBE_OK);
    memset(&k, 0, sizeof k);
    k.type = VLBE_ALE_CON_EQUAL_LEN;
    k.node = 0;
    k.node2 = 2;
    assert_int_equal(vlbe_ale_chain_add(&c->ch, &k), VLBE_OK);
    k.node = 2;
    k.node2 = 4;
    assert_int_equal(vlbe_ale_chain_add(&c->ch, &k), VLBE_OK);
    memset(&k, 0, sizeof k);
    k.type = VLBE_ALE_CON_SLOPE;
    k.node = 4;
    k.v[2] = VLBE_R(1.0);
    assert_int_equal(vlbe_ale_chain_add(&c->ch, &k), VLBE_OK);
    if (!(flags & VLBE_ALE3_NO_SPIN)) {
        memset(&k, 0, sizeof k);
        k.type = VLBE_ALE_CON_SPIN;
        k.v[0] = VLBE_R(0.1);
        k.v[1] = VLBE_R(2.0);
        k.v[2] = VLBE_R(-0.7);
        assert_int_equal(vlbe_ale_chain_add(&c->ch, &k), VLBE_OK);
    }
    assert_int_equal(vlbe_ale_chain_layout(&c->ch), VLBE_OK);
}

/* a curved, stretched, twisted, moving state near the straight chain along z */
static void c3_state(const c3 *c, vlbe_real *q, vlbe_real *v, vlbe_real *a)
{
    const vlbe_real dir[3] = {0, 0, 1}, r0[3] = {0, 0, 0};
    int i;
    vlbe_ale_chain_straight(&c->ch, r0, dir, q);
    for (i = 0; i < c->ch.n; ++i) {
        q[i] += (vlbe_real)(0.05 * sin(1.7 * i + 0.4));
        v[i] = (vlbe_real)(0.4 * cos(0.9 * i + 0.1));
        a[i] = (vlbe_real)sin(0.6 * i + 0.2);
    }
}

/* max |J - J_fd| / max |J| over the columns, J n x n, from central
   differences of f(x + h e_j), *which* selecting what f evaluates */
enum { FD_K, FD_D, FD_MQ };

static double c3_eval(c3 *c, int which, vlbe_real t, vlbe_real *q, vlbe_real *v, const vlbe_real *a,
                      vlbe_real *out, vlbe_real *M)
{
    const int n = c->ch.n;
    int i, k;
    if (which == FD_MQ) {
        assert_int_equal(vlbe_ale_chain_mass(&c->ch, t, q, v, M), 0);
        for (i = 0; i < n; ++i) {
            double s = 0.0;
            for (k = 0; k < n; ++k) s += (double)M[i * n + k] * (double)a[k];
            out[i] = (vlbe_real)s;
        }
    } else
        assert_int_equal(vlbe_ale_chain_force(&c->ch, t, q, v, out), 0);
    return 0.0;
}

static double c3_check(c3 *c, int which, vlbe_real t, vlbe_real *q, vlbe_real *v,
                       const vlbe_real *a, const vlbe_real *J)
{
    const int n = c->ch.n;
    vlbe_real *fp = (vlbe_real *)malloc((size_t)n * sizeof *fp);
    vlbe_real *fm = (vlbe_real *)malloc((size_t)n * sizeof *fm);
    vlbe_real *M = (vlbe_real *)malloc((size_t)n * (size_t)n * sizeof *M);
    double worst = 0.0, big = 0.0;
    int i, j;
    assert_non_null(fp);
    assert_non_null(fm);
    assert_non_null(M);
    for (i = 0; i < n * n; ++i) big = fmax(big, fabs((double)J[i]));
    for (j = 0; j < n; ++j) {
        vlbe_real *x = which == FD_D ? v : q;
        const vlbe_real s = x[j], h = (vlbe_real)(cbrt(EPS) * C3_LEN);
        x[j] = s + h;
        c3_eval(c, which, t, q, v, a, fp, M);
        x[j] = s - h;
        c3_eval(c, which, t, q, v, a, fm, M);
        x[j] = s;
        for (i = 0; i < n; ++i) {
            const double fd = ((double)fp[i] - (double)fm[i]) / (2.0 * (double)h);
            worst = fmax(worst, fabs(fd - (double)J[i * n + j]));
        }
    }
    free(fp);
    free(fm);
    free(M);
    return worst / big;
}

static void chain3_jacobians(void **state)
{
    static const unsigned flags[2] = {0, VLBE_ALE3_NO_SPIN};
    int f;
    (void)state;
    for (f = 0; f < 2; ++f) {
        c3 c;
        int n, m, i, j;
        vlbe_real *q, *v, *a, *K, *D, *Mq, *C, *Cp, *Cm, *Cq, *Ct, *g;
        const vlbe_real t = VLBE_R(0.35);
        double e, big, tol = 64.0 * FD_ERR;
        c3_make(&c, flags[f]);
        n = c.ch.n;
        m = c.ch.m;
        q = (vlbe_real *)malloc((size_t)n * sizeof *q);
        v = (vlbe_real *)malloc((size_t)n * sizeof *v);
        a = (vlbe_real *)malloc((size_t)n * sizeof *a);
        K = (vlbe_real *)malloc((size_t)n * (size_t)n * sizeof *K);
        D = (vlbe_real *)malloc((size_t)n * (size_t)n * sizeof *D);
        Mq = (vlbe_real *)malloc((size_t)n * (size_t)n * sizeof *Mq);
        C = (vlbe_real *)malloc((size_t)m * sizeof *C);
        Cp = (vlbe_real *)malloc((size_t)m * sizeof *Cp);
        Cm = (vlbe_real *)malloc((size_t)m * sizeof *Cm);
        Cq = (vlbe_real *)malloc((size_t)m * (size_t)n * sizeof *Cq);
        Ct = (vlbe_real *)malloc((size_t)m * sizeof *Ct);
        g = (vlbe_real *)malloc((size_t)m * sizeof *g);
        assert_true(q && v && a && K && D && Mq && C && Cp && Cm && Cq && Ct && g);
        c3_state(&c, q, v, a);
        assert_int_equal(vlbe_ale_chain_force_jac(&c.ch, t, q, v, K, D), 0);
        assert_int_equal(vlbe_ale_chain_mass_jac(&c.ch, t, q, v, a, Mq, NULL), 0);
        e = c3_check(&c, FD_K, t, q, v, a, K);
        tu_report("3D chain K = dQ/dq, err / max|K|", e, tol);
        assert_true(e <= tol);
        e = c3_check(&c, FD_D, t, q, v, a, D);
        tu_report("3D chain D = dQ/dv, err / max|D|", e, tol);
        assert_true(e <= tol);
        e = c3_check(&c, FD_MQ, t, q, v, a, Mq);
        tu_report("3D chain d(M a)/dq, err / max", e, tol);
        assert_true(e <= tol);
        /* constraints: C_q, C_t and gamma by differences along q_j, t and
           the path (t + s, q + s v) */
        assert_int_equal(vlbe_ale_chain_constr_jac(&c.ch, t, q, Cq, Ct), 0);
        assert_int_equal(vlbe_ale_chain_constr_acc(&c.ch, t, q, v, g), 0);
        big = 1.0;
        e = 0.0;
        for (j = 0; j < n; ++j) {
            const vlbe_real s = q[j], h = (vlbe_real)cbrt(EPS) * (VLBE_R(1.0) + vlbe_fabs(s));
            q[j] = s + h;
            assert_int_equal(vlbe_ale_chain_constr(&c.ch, t, q, Cp), 0);
            q[j] = s - h;
            assert_int_equal(vlbe_ale_chain_constr(&c.ch, t, q, Cm), 0);
            q[j] = s;
            for (i = 0; i < m; ++i)
                e = fmax(e, fabs(((double)Cp[i] - (double)Cm[i]) / (2.0 * (double)h) -
                                 (double)Cq[i * n + j]));
        }
        {
            const vlbe_real h = (vlbe_real)cbrt(EPS);
            assert_int_equal(vlbe_ale_chain_constr(&c.ch, t + h, q, Cp), 0);
            assert_int_equal(vlbe_ale_chain_constr(&c.ch, t - h, q, Cm), 0);
            for (i = 0; i < m; ++i)
                e = fmax(e, fabs(((double)Cp[i] - (double)Cm[i]) / (2.0 * (double)h) - (double)Ct[i]));
        }
        tu_report("3D chain C_q, C_t, abs err (entries O(1))", e, tol * big);
        assert_true(e <= tol * big);
        {
            /* second difference along the path: h = EPS^(1/4), error ~ EPS^(1/2) */
            const vlbe_real h = (vlbe_real)sqrt(sqrt(EPS));
            vlbe_real *qs = (vlbe_real *)malloc((size_t)n * sizeof *qs);
            double e2 = 0.0;
            const double tol2 = 64.0 * sqrt(EPS);
            assert_non_null(qs);
            for (i = 0; i < n; ++i) qs[i] = q[i] + h * v[i];
            assert_int_equal(vlbe_ale_chain_constr(&c.ch, t + h, qs, Cp), 0);
            for (i = 0; i < n; ++i) qs[i] = q[i] - h * v[i];
            assert_int_equal(vlbe_ale_chain_constr(&c.ch, t - h, qs, Cm), 0);
            assert_int_equal(vlbe_ale_chain_constr(&c.ch, t, q, C), 0);
            for (i = 0; i < m; ++i) {
                const double d2 = ((double)Cp[i] - 2.0 * (double)C[i] + (double)Cm[i]) /
                                  ((double)h * (double)h);
                e2 = fmax(e2, fabs(d2 + (double)g[i]));
            }
            tu_report("3D chain gamma = -d2C/ds2, abs err", e2, tol2);
            assert_true(e2 <= tol2);
            free(qs);
        }
        free(q), free(v), free(a), free(K), free(D), free(Mq);
        free(C), free(Cp), free(Cm), free(Cq), free(Ct), free(g);
    }
}

static void chain3_layout(void **state)
{
    c3 c;
    vlbe_ale_con k;
    int i;
    (void)state;
    c3_make(&c, 0);
    /* per node 3 + 3 + theta (+ p when free): 7, 8, 7, 8, 7 */
    assert_int_equal(c.ch.n, 37);
    /* POS 3 + POS mask 5 (2 rows) + equal lengths 1 + 1 + SLOPE 3 + SPIN 1 */
    assert_int_equal(c.ch.m, 11);
    for (i = 0; i < 5; ++i) assert_int_equal(c.node[i].ofs, 7 * i + (i > 1) + (i > 3));
    c3_make(&c, VLBE_ALE3_NO_SPIN);
    assert_int_equal(c.ch.n, 32);
    assert_int_equal(c.ch.m, 10);
    /* a SPIN constraint without spin angles */
    memset(&k, 0, sizeof k);
    k.type = VLBE_ALE_CON_SPIN;
    assert_int_equal(vlbe_ale_chain_add(&c.ch, &k), VLBE_OK);
    assert_int_equal(vlbe_ale_chain_layout(&c.ch), VLBE_EARG);
    /* planar-only constraints and a bad mask */
    c3_make(&c, 0);
    k.type = VLBE_ALE_CON_SLOPE_DIR;
    assert_int_equal(vlbe_ale_chain_add(&c.ch, &k), VLBE_EARG);
    k.type = VLBE_ALE_CON_SLIDE_C;
    assert_int_equal(vlbe_ale_chain_add(&c.ch, &k), VLBE_EARG);
    k.type = VLBE_ALE_CON_POS;
    k.which = 8;
    assert_int_equal(vlbe_ale_chain_add(&c.ch, &k), VLBE_EARG);
    /* sliding nodes are planar */
    c.node[2].slide = 1;
    assert_int_equal(vlbe_ale_chain_layout(&c.ch), VLBE_EARG);
    c.node[2].slide = 0;
    assert_int_equal(vlbe_ale_chain_layout(&c.ch), VLBE_OK);
    {
        vlbe_real q[64] = {0}, v[64] = {0}, qn[80], vn[80], len;
        const vlbe_real dir[3] = {0, 0, 1}, r0[3] = {0, 0, 0};
        int sl = 2, chg = 0;
        vlbe_ale_chain_straight(&c.ch, r0, dir, q);
        assert_int_equal(vlbe_ale_chain_insert(&c.ch, 0, VLBE_R(0.1), 0, q, v, qn, vn), VLBE_EARG);
        assert_int_equal(vlbe_ale_chain_remove(&c.ch, 1, 0, q, v, qn, vn), VLBE_EARG);
        assert_int_equal(vlbe_ale_chain_length(&c.ch, 0, q, v, &len, NULL), VLBE_EARG);
        (void)sl, (void)chg;
    }
}

/* -- the scene ------------------------------------------------------------ */
static ss_scene g_s;

static void straight_spin(void **state)
{
    vlbe_real q0[64], v0[64];
    vlbe_hht_params par;
    ex_method m;
    ex_run_out out;
    vlbe_real q[64], v[64];
    int i;
    (void)state;
    if ((double)VLBE_EPS > 1e-10) return; /* double only (see the header) */
    assert_int_equal(ss_setup(&g_s, 0.5, 1.0, 4, 0, SS_Z0, q0, v0), 0);
    g_s.ch.pfun = ss_pfun_shift;
    g_s.ref.P = 0.0; /* no load, and a straight start */
    for (i = 0; i <= 4; ++i) {
        const int o = g_s.node[i].ofs;
        q0[o] = q0[o + 1] = q0[o + 3] = q0[o + 4] = VLBE_R(0.0);
        v0[o] = v0[o + 1] = v0[o + 3] = v0[o + 4] = VLBE_R(0.0);
    }
    assert_int_equal(ex_hht_pick(&par, -0.05, 0.0), VLBE_OK);
    par.atol = (vlbe_real)SS_ATOL;
    memset(&m, 0, sizeof m);
    m.hht = &par;
    m.h = (g_s.t1 - g_s.t0) / 400.0;
    assert_int_equal(ex_run(&g_s.sys, &m, q0, v0, g_s.t1 - g_s.t0, NULL, NULL, q, v, NULL, &out),
                     VLBE_OK);
    for (i = 0; i <= 4; ++i) {
        const int o = g_s.node[i].ofs;
        /* transverse position and slope exactly zero: nothing drives them */
        assert_true(q[o] == VLBE_R(0.0) && q[o + 1] == VLBE_R(0.0) && q[o + 3] == VLBE_R(0.0) &&
                    q[o + 4] == VLBE_R(0.0));
        ASSERT_CLOSE(v[o + 6], SS_OMEGA_SPIN, 1e-9, 0);
    }
}

static void scene_converges(void **state)
{
    double e4[4], e8[4], z4[4];
    ex_run_out out;
    int k;
    (void)state;
    if ((double)VLBE_EPS > 1e-10) return;
    assert_int_equal(ss_run(&g_s, 0.5, 1.0, 4, 0, SS_Z0_CONV, 1000, -0.05, 30, e4, z4, &out), VLBE_OK);
    assert_int_equal(ss_run(&g_s, 0.5, 1.0, 8, 0, SS_Z0_CONV, 1000, -0.05, 30, e8, NULL, &out),
                     VLBE_OK);
    for (k = 0; k < 4; ++k) { /* 8 elements at least 2.5 x better (cubic elements: 8 x) */
        tu_report("scene 3, 4 elements, err / U_s", e4[k], 2e-2);
        assert_true(e4[k] <= 2e-2);
        tu_report("scene 3, err(8) / err(4)", e8[k] / e4[k], 0.4);
        assert_true(e8[k] <= 0.4 * e4[k]);
    }
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(chain3_jacobians),
        cmocka_unit_test(chain3_layout),
        cmocka_unit_test(straight_spin),
        cmocka_unit_test(scene_converges),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}

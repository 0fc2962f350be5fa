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
     straight_spin       the scene's shaft without load, spinning, from
                         rest: stays exactly straight (transverse
                         coordinates 0) and every node spins at Omega
     scene_converges     case a = 0.5, k_omega = 1 (1000 steps, load from
                         0.001 l, the shaft starting at rest): the
                         4-element errors against eq. 59 are below 2 % of
                         U_s (in percent of U_s from
                         0.65 (m:conv_err4_min_pct) to
                         1.61 (m:conv_err4_max_pct)), and 8 elements divide
                         each of the four by at least 2.5 (by
                         5.4 (m:conv_gain_min) to 14 (m:conv_gain_max))
                         against the series without the rhoJ terms, the
                         continuum the element discretizes
                         (against eq. 59 the 8-element errors keep its
                         O(beta^2) difference, which no mesh removes)
     z0_independent      the shaft starting at rest, the result does not
                         depend on where the load starts: case 1 with the
                         paper's 4 elements from z0 = 1e-3 l and 3e-3 l
                         (1000 steps, 500 in slow builds; the same step
                         in both) differ by less than the bound B below,
                         over the common part of the traverse, both in the
                         error histories and in their largest values; the
                         exact series' state at z0 as the start (the
                         contrast) fails the same check
     frozen_frequencies  the paper's mesh frozen with the load node at
                         z = 0.5, 0.8, 0.99 l (4 and 6 elements): M and K
                         at the straight state decouple X1 bending from
                         the other free coordinates exactly, its
                         frequencies equal the textbook Hermite beam's on
                         the same nodes, and on the uniform mesh (z = 0.5)
                         they lie above the exact (n pi / l)^2 sqrt(EJ /
                         rhoA) by no more than the leading term
                         (k_n h)^4 / 1440 of the consistent-mass cubic
                         Hermite error (with 4 elements modes 1, 2, 3 at
                         0.98 (m:uniform4_mode1_lead),
                         0.93 (m:uniform4_mode2_lead) and
                         0.85 (m:uniform4_mode3_lead) of it: the ratio
                         tends to 1 as k_n h falls); with 4 elements at
                         z = 0.99 l modes 1 and 2 are high by (percent)
                         0.38 (m:frozen_099_mode1_pct) and
                         10.4 (m:frozen_099_mode2_pct)
   Tolerances.  Jacobians: differences with the step h = EPS^(1/3) L (L =
   0.3 the element length, the scale on which the forces vary: with h =
   EPS^(1/3) the truncation error was found above the tolerance, with L/3
   it falls as h^2 -- the Jacobians are right, the step was not) have
   errors ~ EPS^(2/3) times the scale of the entries: 64 EPS^(2/3) of the
   largest entry of the matrix (as in the element suites).
   z0 independence: starting at rest at t0 = z0 l / v instead of at t = 0
   leaves out the exact state at t0; in the continuum (without the rhoJ
   terms: undamped modes of frequency w_n) the two solutions then differ
   by the free vibration from that state, mode n with amplitude
   sqrt(w_n(t0)^2 + (w_n'(t0) / w_n)^2), so by at most B(z0), their sum
   over the modes, anywhere at any time (B grows as z0^2: the load next to
   a support hardly loads the modes).  Two starts differ by at most
   B(z0a) + B(z0b), in units of U_s 3.4e-4 (m:z0_bound); the histories
   differed by 1.0e-4 (m:z0_rest_hist), their largest values by
   5.5e-5 (m:z0_rest_max) (the mesh's own representation of the small free
   vibration is inside the margin).  Started in the exact series' state at
   z0 instead, the two runs differ by 2.8e-3 (m:z0_exact_hist): the four
   elements cannot take the series' state (its short-wave content becomes
   a spurious free vibration of the mesh).  B(1e-3) is
   3.8e-5 (m:z0_missed_fine) (the example's start SS_Z0), B(5e-3) is
   7.7e-4 (m:z0_missed_coarse) (the start SS_Z0_COARSE of bench/wp_shaft.c).
   Frozen frequencies: M and K of the chain and of the textbook beam agree
   to rounding, but the chain's axial strain at the straight state is
   rounding, an axial force N ~ EA EPS, whose geometric stiffness moves
   w_n by N / (2 EJ k_n^2) = EPS / (2 (n beta_1)^2) relative (beta_1 = k_1
   r_g = 0.02: 1250 EPS for mode 1); 64 times that.  The largest error
   was 5.6 (m:frozen_vs_textbook) of these units.  The eigenvalue solver
   adds a few EPS (vlbe_eig_gsym, shift-invert with sigma = 0).
   Float: the scene's time runs fail (VLBE_ENOCONV: see SHAFT_DOUBLE_ONLY)
   and are skipped; the chain checks and the frozen frequencies run. */
#include "test_util.h"
#include "../scenes/spinning_shaft.h"

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
    k.r[0] = VLBE_R(0.01);
    assert_int_equal(vlbe_ale_chain_add(&c->ch, &k), VLBE_OK);
    k.node = 4;
    k.which = 5; /* x and z */
    k.r[2] = VLBE_R(1.2);
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
    k.d[2] = VLBE_R(1.0);
    assert_int_equal(vlbe_ale_chain_add(&c->ch, &k), VLBE_OK);
    if (!(flags & VLBE_ALE3_NO_SPIN)) {
        memset(&k, 0, sizeof k);
        k.type = VLBE_ALE_CON_SPIN;
        k.law[0] = VLBE_R(0.1);
        k.law[1] = VLBE_R(2.0);
        k.law[2] = VLBE_R(-0.7);
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
    /* planar-only constraints, a zero slope direction and a bad mask */
    c3_make(&c, 0);
    k.type = VLBE_ALE_CON_SLOPE_ANGLE;
    assert_int_equal(vlbe_ale_chain_add(&c.ch, &k), VLBE_EARG);
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

/* The scene's HHT runs need double.  In float, with the default
   tolerances, they stop: straight_spin with VLBE_ESINGULAR, the loaded
   runs with VLBE_ENOCONV.  The moving mesh starts at z0 = 1e-3 with end
   elements of z0 l / 2; an element's bending stiffness grows as 1 / L_e^3,
   so the iteration matrix of such a mesh has relative pivots below what
   float resolves (measured with examples/spinning_shaft.c in float: at
   z0 = 1e-2 the 6-, 8- and 16-element moving meshes run, at z0 = 1e-3
   only the 4-element ones). */
#define SHAFT_DOUBLE_ONLY()                                                                \
    do {                                                                                 \
        if ((double)VLBE_EPS > 1e-10)                                                    \
            TU_SKIP("float: end elements of z0 l / 2 (z0 = 1e-3) are below float's "     \
                    "resolution of the bending stiffness (header)");                     \
    } while (0)

static void straight_spin(void **state)
{
    vlbe_real q0[SS_NE_MAX * 8 + 8], v0[SS_NE_MAX * 8 + 8], q[SS_NE_MAX * 8 + 8],
        v[SS_NE_MAX * 8 + 8];
    vlbe_hht_params par;
    ex_method m;
    ex_run_out out;
    vlbe_status st;
    int i;
    (void)state;
    SHAFT_DOUBLE_ONLY();
    memset(&out, 0, sizeof out);
    assert_int_equal(ss_setup(&g_s, 0.5, 1.0, 4, 0, SS_Z0, q0, v0), 0);
    g_s.ref.P = 0.0; /* no load: the start state at rest stays straight */
    assert_int_equal(ex_hht_pick(&par, -0.05, 0.0), VLBE_OK);
    par.atol = (vlbe_real)SS_ATOL;
    memset(&m, 0, sizeof m);
    m.hht = &par;
    m.h = (g_s.t1 - g_s.t0) / 400.0;
    st = ex_run(&g_s.sys, &m, q0, v0, g_s.t1 - g_s.t0, NULL, NULL, q, v, NULL, &out);
    assert_int_equal(st, VLBE_OK);
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
    ss_err e4, e8, e40, e80;
    ex_run_out out;
    double lo = HUGE_VAL, hi = 0.0, rlo = HUGE_VAL, rhi = 0.0;
    int k;
    (void)state;
    SHAFT_DOUBLE_ONLY();
    memset(&out, 0, sizeof out);
    assert_int_equal(ss_run(&g_s, 0.5, 1.0, 4, 0, SS_Z0, 1000, -0.05, 30, &e4, &e40, &out),
                     VLBE_OK);
    assert_int_equal(ss_run(&g_s, 0.5, 1.0, 8, 0, SS_Z0, 1000, -0.05, 30, &e8, &e80, &out),
                     VLBE_OK);
    for (k = 0; k < 4; ++k) {
        /* against eq. 59 (the paper's comparison) */
        tu_report("scene 3, 4 elements, err / U_s", fabs(e4.e[k]), 2e-2);
        assert_true(fabs(e4.e[k]) <= 2e-2);
        lo = fmin(lo, fabs(e4.e[k]));
        hi = fmax(hi, fabs(e4.e[k]));
        /* 8 elements at least 2.5 x better (cubic elements: 8 x), against
           the element's continuum */
        tu_report("scene 3, err(8) / err(4), without rhoJ", fabs(e80.e[k] / e40.e[k]), 0.4);
        assert_true(fabs(e80.e[k]) <= 0.4 * fabs(e40.e[k]));
        rlo = fmin(rlo, fabs(e40.e[k] / e80.e[k]));
        rhi = fmax(rhi, fabs(e40.e[k] / e80.e[k]));
    }
    tu_measured("conv_err4_min_pct", 100 * lo);
    tu_measured("conv_err4_max_pct", 100 * hi);
    tu_measured("conv_gain_min", rlo);
    tu_measured("conv_gain_max", rhi);
}

/* -- independence of the start position ----------------------------------- */
/* B(z0): the free vibration of the exact solution's state at t0 = z0 l / v
   (rot = 0: undamped modes of frequency w0_n), summed mode by mode,
   sqrt(w_n^2 + (w_n' / w0_n)^2) / U_s: a bound on it anywhere, any time.
   w_n' by central differences (step 1e-4 / w0_n: relative error 2e-9). */
static double z0_missed(const ex_katz *k, double z0, int nmodes)
{
    const double t0 = z0 * k->l / k->v;
    double sum = 0.0;
    int n, c;
    for (n = 1; n <= nmodes; ++n) {
        const double wn = (double)(n * n) * k->w1, h = 1e-4 / wn;
        double w[2], wp[2], wm[2], a2 = 0.0;
        assert_int_equal(ex_katz_mode(k, n, t0, &w[0], &w[1]), 0);
        assert_int_equal(ex_katz_mode(k, n, t0 + h, &wp[0], &wp[1]), 0);
        assert_int_equal(ex_katz_mode(k, n, t0 - h, &wm[0], &wm[1]), 0);
        for (c = 0; c < 2; ++c) {
            const double wd = (wp[c] - wm[c]) / (2.0 * h);
            a2 += w[c] * w[c] + wd * wd / (wn * wn);
        }
        sum += sqrt(a2);
    }
    return sum / k->Us;
}

/* The exact solution's state (60 modes, without the rhoJ terms) at the
   moving nodes at t0 written into q0, v0: a node at the moving material
   point p of the deflected shaft has r = (U1, U2, p), r' = (U1_z, U2_z, 1)
   and the rates r. = (U_t + U_z p', p'), r'. = (U_zt + U_zz p', 0).  The
   contrast to the start at rest. */
static void z0_exact_start(ss_scene *s, vlbe_real *q0, vlbe_real *v0)
{
    const double PI = 3.14159265358979323846, l = s->ref0.l;
    int i, n, c;
    for (i = 0; i <= s->ne; ++i) {
        const int o = s->node[i].ofs;
        vlbe_real p3[3];
        double u[2][5] = {{0}}, z;
        assert_int_equal(vlbe_ale_chain_pnode(&s->ch, i, VLBE_R(0.0), NULL, NULL, p3), VLBE_OK);
        z = (double)p3[0];
        for (n = 1; n <= 60; ++n) {
            const double kn = (double)n * PI / l, wn = (double)(n * n) * s->ref0.w1;
            const double h = 1e-4 / wn, sn = sin(kn * z), cn = cos(kn * z);
            double w[2], wp[2], wm[2];
            assert_int_equal(ex_katz_mode(&s->ref0, n, s->t0, &w[0], &w[1]), 0);
            assert_int_equal(ex_katz_mode(&s->ref0, n, s->t0 + h, &wp[0], &wp[1]), 0);
            assert_int_equal(ex_katz_mode(&s->ref0, n, s->t0 - h, &wm[0], &wm[1]), 0);
            for (c = 0; c < 2; ++c) {
                const double wd = (wp[c] - wm[c]) / (2.0 * h);
                u[c][0] += w[c] * sn;
                u[c][1] += w[c] * kn * cn;
                u[c][2] += wd * sn;
                u[c][3] += wd * kn * cn;
                u[c][4] -= w[c] * kn * kn * sn;
            }
        }
        for (c = 0; c < 2; ++c) {
            q0[o + c] = (vlbe_real)u[c][0];
            q0[o + 3 + c] = (vlbe_real)u[c][1];
            v0[o + c] = (vlbe_real)(u[c][2] + u[c][1] * (double)p3[1]);
            v0[o + 3 + c] = (vlbe_real)(u[c][3] + u[c][4] * (double)p3[1]);
        }
    }
}

/* One run of case 1 with the paper's 4 elements from z0 (exact: the exact
   state, else at rest), nsteps over the traverse; its samples and error
   history stay in g_s. */
static void z0_run(double z0, long nsteps, int exact, ss_err *err)
{
    vlbe_real q0[SS_NE_MAX * 8 + 8], v0[SS_NE_MAX * 8 + 8];
    ex_run_out out;
    memset(&out, 0, sizeof out);
    assert_int_equal(ss_setup(&g_s, 0.5, 1.0, 4, 0, z0, q0, v0), 0);
    if (exact) z0_exact_start(&g_s, q0, v0);
    assert_int_equal(ss_integrate(&g_s, q0, v0, nsteps, -0.05, 30, err, NULL, &out), VLBE_OK);
}

/* the samples and error history of run a, kept from g_s by z0_keep */
static double z0_ta[SS_NSAMP_MAX], z0_ea[4][SS_NSAMP_MAX];
static int z0_na;

static void z0_keep(void)
{
    z0_na = g_s.ns;
    memcpy(z0_ta, g_s.t, sizeof z0_ta);
    memcpy(z0_ea, g_s.e, sizeof z0_ea);
}

/* Run a (kept) against run b (in g_s) over the load positions [zlo, zhi]:
   dh[k] the largest |e_b(t) - e_a(t)| at b's samples (e_a linear between
   its samples), dm[k] the difference of the largest signed errors there. */
static void z0_compare(double zlo, double zhi, double *dh, double *dm)
{
    int i, j, k;
    for (k = 0; k < 4; ++k) {
        double ma = 0.0, mb = 0.0;
        dh[k] = 0.0;
        for (i = 0; i < z0_na; ++i) {
            const double z = g_s.ref.v * z0_ta[i] / g_s.ref.l;
            if (z >= zlo && z <= zhi && fabs(z0_ea[k][i]) > fabs(ma)) ma = z0_ea[k][i];
        }
        for (i = 0, j = 0; i < g_s.ns; ++i) {
            const double z = g_s.ref.v * g_s.t[i] / g_s.ref.l, t = g_s.t[i];
            double x;
            if (z < zlo || z > zhi) continue;
            if (fabs(g_s.e[k][i]) > fabs(mb)) mb = g_s.e[k][i];
            while (j + 2 < z0_na && z0_ta[j + 1] < t) ++j;
            x = (t - z0_ta[j]) / (z0_ta[j + 1] - z0_ta[j]);
            assert_true(x >= 0.0 && x <= 1.0);
            dh[k] = fmax(dh[k], fabs(g_s.e[k][i] - (z0_ea[k][j] + x * (z0_ea[k][j + 1] -
                                                                        z0_ea[k][j]))));
        }
        dm[k] = fabs(ma - mb);
    }
}

static void z0_independent(void **state)
{
    const double za = 1e-3, zb = 3e-3;
    const long na = tu_slow_run() ? 500 : 1000;
    /* the same step in both runs (to 0.05 %) */
    const long nb = (long)floor((double)na * (1.0 - 2.0 * zb) / (1.0 - 2.0 * za) + 0.5);
    double bound, dh[4], dm[4], dx = 0.0;
    ss_err ea, eb;
    int k;
    (void)state;
    SHAFT_DOUBLE_ONLY();
    memset(&ea, 0, sizeof ea);
    memset(&eb, 0, sizeof eb);
    z0_run(za, na, 0, &ea);
    z0_keep();
    bound = z0_missed(&g_s.ref0, za, 60);
    tu_measured("z0_missed_fine", bound);
    z0_run(zb, nb, 0, &eb);
    bound += z0_missed(&g_s.ref0, zb, 60);
    tu_measured("z0_bound", bound);
    tu_measured("z0_missed_coarse", z0_missed(&g_s.ref0, SS_Z0_COARSE, 60));
    z0_compare(zb, 1.0 - zb, dh, dm);
    for (k = 0; k < 4; ++k) {
        tu_report("start at rest, z0 = 1e-3 vs 3e-3: history diff / U_s", dh[k], bound);
        assert_true(dh[k] <= bound);
        tu_report("start at rest, z0 = 1e-3 vs 3e-3: max err diff / U_s", dm[k], bound);
        assert_true(dm[k] <= bound);
    }
    tu_measured("z0_rest_hist", fmax(fmax(dh[0], dh[1]), fmax(dh[2], dh[3])));
    tu_measured("z0_rest_max", fmax(fmax(dm[0], dm[1]), fmax(dm[2], dm[3])));
    /* the contrast: the exact state at z0 fails the same check */
    z0_run(za, na, 1, &ea);
    z0_keep();
    z0_run(zb, nb, 1, &eb);
    z0_compare(zb, 1.0 - zb, dh, dm);
    for (k = 0; k < 4; ++k) dx = fmax(dx, dh[k]);
    tu_measured("z0_exact_hist", dx);
    tu_report("exact-state start: history diff / U_s (must exceed the bound)", bound, dx);
    assert_true(dx > bound);
}

/* -- bending frequencies of the frozen mesh -------------------------------- */
/* The textbook Euler-Bernoulli beam of cubic Hermite elements (e.g.
   Przemieniecki, Theory of Matrix Structural Analysis, 1968: element
   stiffness EJ/L^3 [12 6L -12 6L; 6L 4L^2 -6L 2L^2; ..], consistent mass
   rhoA L/420 [156 22L 54 -13L; ..]) on the nodes of the frozen paper's
   mesh, simply supported: its nf lowest frequencies (rad/s) into w.  Independent of
   ancf_ale.h. */
static void herm_freq(int ne, double z, double EJ, double rhoA, int nf, double *w)
{
    const int nd = 2 * (ne + 1), nb = nd - 2;
    double K[(2 * SS_NE_MAX + 2) * (2 * SS_NE_MAX + 2)];
    double M[(2 * SS_NE_MAX + 2) * (2 * SS_NE_MAX + 2)];
    vlbe_real Mb[4 * SS_NE_MAX * SS_NE_MAX], Kb[4 * SS_NE_MAX * SS_NE_MAX], lam[2 * SS_NE_MAX];
    vlbe_real *wk = (vlbe_real *)malloc(vlbe_eig_work_len(nb) * sizeof *wk);
    int e, i, j, info = 0, map[2 * SS_NE_MAX + 2] = {0};
    assert_non_null(wk);
    assert_true(ne <= SS_NE_MAX);
    for (i = 0; i < nd * nd; ++i) K[i] = M[i] = 0.0;
    for (e = 0; e < ne; ++e) {
        double pa, pb, pd, L;
        ss_mesh(ne, SS_L, z * SS_L, 0.0, e, &pa, &pd);
        ss_mesh(ne, SS_L, z * SS_L, 0.0, e + 1, &pb, &pd);
        L = pb - pa;
        {
            const double L2 = L * L;
            const double k[16] = {12,    6 * L,  -12,    6 * L,
                                  6 * L, 4 * L2, -6 * L, 2 * L2,
                                  -12,   -6 * L, 12,     -6 * L,
                                  6 * L, 2 * L2, -6 * L, 4 * L2};
            const double m[16] = {156,     22 * L, 54,      -13 * L,
                                  22 * L,  4 * L2, 13 * L,  -3 * L2,
                                  54,      13 * L, 156,     -22 * L,
                                  -13 * L, -3 * L2, -22 * L, 4 * L2};
            for (i = 0; i < 4; ++i)
                for (j = 0; j < 4; ++j) {
                    K[(2 * e + i) * nd + 2 * e + j] += EJ / (L * L * L) * k[4 * i + j];
                    M[(2 * e + i) * nd + 2 * e + j] += rhoA * L / 420.0 * m[4 * i + j];
                }
        }
    }
    for (i = 0, j = 0; i < nd; ++i) /* w = 0 at both supports */
        if (i != 0 && i != nd - 2) map[j++] = i;
    for (i = 0; i < nb; ++i)
        for (j = 0; j < nb; ++j) {
            Mb[i * nb + j] = (vlbe_real)M[map[i] * nd + map[j]];
            Kb[i * nb + j] = (vlbe_real)K[map[i] * nd + map[j]];
        }
    assert_int_equal(
        vlbe_eig_gsym(nb, Kb, Mb, VLBE_R(0.0), lam, NULL, &info, wk, vlbe_eig_work_len(nb)),
        VLBE_OK);
    for (i = 0; i < nf; ++i) w[i] = sqrt((double)lam[i]);
    free(wk);
}

/* the rounding allowance of frequency n of the frozen chain (see the
   header): 64 EPS / (2 (n beta_1)^2) relative */
#define FR_TOL(n) (64.0 * EPS / (2.0 * (double)((n) * (n)) * SS_BETA1 * SS_BETA1))

static void frozen_frequencies(void **state)
{
    static const double zs[3] = {0.5, 0.8, 0.99};
    const double PI = 3.14159265358979323846;
    const size_t nmax = (size_t)(SS_NE_MAX + 1) * 7;
    vlbe_real *M = (vlbe_real *)malloc(nmax * nmax * sizeof *M);
    vlbe_real *K = (vlbe_real *)malloc(nmax * nmax * sizeof *K);
    double w[3], wh[3], w1, worst = 0.0;
    int iz, ne, k;
    (void)state;
    assert_true(M && K);
    for (ne = 4; ne <= 6; ne += 2)
        for (iz = 0; iz < 3; ++iz) {
            /* kind of each coordinate: 1 X1 bending, 2 held by a constraint,
               0 the other free ones (X2 bending, axial, spin) */
            int idx[2 * SS_NE_MAX], kind[SS_NE_MAX * 8 + 8] = {0}, nb, n, i, j;
            vlbe_real q[SS_NE_MAX * 8 + 8], Cq[6 * (SS_NE_MAX * 8 + 8)];
            const vlbe_real r0[3] = {0, 0, 0}, dir[3] = {0, 0, 1};
            double big = 0.0, cpl = 0.0;
            /* the X1 bending block decouples (M and K at the straight state) */
            assert_int_equal(ss_frozen_mk(&g_s, ne, zs[iz], M, K), 0);
            n = g_s.ch.n;
            assert_int_equal(g_s.ch.m, 6);
            nb = ss_bending_dofs(&g_s, idx);
            assert_int_equal(nb, 2 * ne);
            for (i = 0; i < nb; ++i) kind[idx[i]] = 1;
            vlbe_ale_chain_straight(&g_s.ch, r0, dir, q);
            assert_int_equal(vlbe_ale_chain_constr_jac(&g_s.ch, VLBE_R(0.0), q, Cq, NULL), 0);
            for (i = 0; i < g_s.ch.m; ++i) { /* each row holds one coordinate */
                int nz = 0;
                for (j = 0; j < n; ++j)
                    if (Cq[i * n + j] != VLBE_R(0.0)) {
                        assert_int_not_equal(kind[j], 1);
                        kind[j] = 2;
                        ++nz;
                    }
                assert_int_equal(nz, 1);
            }
            for (i = 0; i < n; ++i)
                for (j = 0; j < n; ++j) {
                    const double a = fabs((double)K[i * n + j]) + fabs((double)M[i * n + j]);
                    if (kind[i] == 1 && kind[j] == 1) big = fmax(big, a);
                    else if (kind[i] + kind[j] == 1) cpl = fmax(cpl, a);
                }
            tu_report("frozen mesh: coupling of X1 bending / its largest entry", cpl / big, 0.0);
            assert_true(cpl == 0.0);
            /* the frequencies against the textbook Hermite beam on the same nodes */
            assert_int_equal(ss_frozen_freq(&g_s, ne, zs[iz], 3, w), 0);
            herm_freq(ne, zs[iz], g_s.ref.EJ, g_s.ref.rhoA, 3, wh);
            for (k = 0; k < 3; ++k) {
                const double err = fabs(w[k] / wh[k] - 1.0);
                tu_report("frozen mesh vs textbook Hermite beam, rel", err, FR_TOL(k + 1));
                ASSERT_CLOSE(w[k], wh[k], FR_TOL(k + 1), 0.0);
                worst = fmax(worst, err / (EPS / (2.0 * (double)((k + 1) * (k + 1)) * SS_BETA1 *
                                                  SS_BETA1)));
            }
            w1 = g_s.ref.w1;
            if (zs[iz] == 0.5) {
                /* uniform mesh (h = l / ne): above the exact frequencies (a
                   conforming Ritz discretisation) and by less than the
                   leading term (k_n h)^4 / 1440 of the Hermite error */
                for (k = 0; k < 3; ++k) {
                    const double e = w[k] / ((double)((k + 1) * (k + 1)) * w1) - 1.0;
                    const double kh = (double)(k + 1) * PI / (double)ne;
                    const double lead = pow(kh, 4) / 1440.0;
                    tu_report("uniform mesh: rel freq error", e, lead + FR_TOL(k + 1));
                    assert_true(e > -FR_TOL(k + 1) && e <= lead + FR_TOL(k + 1));
                    if (ne == 4) {
                        static const char *const key[3] = {"uniform4_mode1_lead",
                                                           "uniform4_mode2_lead",
                                                           "uniform4_mode3_lead"};
                        tu_measured(key[k], e / lead);
                    }
                }
            }
            if (ne == 4 && zs[iz] == 0.99) {
                tu_measured("frozen_099_mode1_pct", 100 * (w[0] / w1 - 1));
                tu_measured("frozen_099_mode2_pct", 100 * (w[1] / (4 * w1) - 1));
            }
        }
    tu_measured("frozen_vs_textbook", worst);
    free(M);
    free(K);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(chain3_jacobians),
        cmocka_unit_test(chain3_layout),
        cmocka_unit_test(straight_spin),
        cmocka_unit_test(scene_converges),
        cmocka_unit_test(z0_independent),
        cmocka_unit_test(frozen_frequencies),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}

/* test_lin.c -- linearisation of a vlbe_dae about a state (integrators.h:
   vlbe_dae_linearize, vlbe_dae_lin_work_len_sys, vlbe_dae_lin_iwork_len_sys)
   -- part of vlbe                                 SPDX-License-Identifier: MIT

   Each test checks the reduced matrices against an independent fact:
   smd            unconstrained linear spring-mass-damper system given by
                  M, D, K: Mr = M, Dr = D, Kr = K (bit for bit with
                  force_jac: N = I and products with 0 and 1 are exact; by
                  the library's forward differences otherwise, to their
                  rounding error 2 eps |Q| / h = 2 sqrt(eps) |Q|: 4 sqrt(eps) |Q|)
   pendulum       a pendulum in absolute coordinates (x, y), x^2 + y^2 =
                  L^2: hanging Kr / Mr = g / L, inverted -g / L, nothing
                  without the multiplier (Kr = 0 exactly); with constr_hess
                  (exact) and by differences of C_q^T lambda, also under
                  VLBE_DAE_NO_CHESS (which only concerns iteration matrices)
   spring_pend    a mass on a spring under gravity (no constraint): Kr has
                  the eigenvalues m g / r0 (the pendulum of length r0) and
                  k (along the spring)
   redundant      the pendulum with its constraint twice, and a spherical
                  pendulum whose constraint appears three times (one row
                  scaled), hanging and tilted (at rest, its tangential
                  acceleration): the rank is counted out (nr = 1, 2) also
                  where rounding leaves the copies not exactly dependent,
                  N orthonormal and normal to the rod, Kr / Mr = g cos(th)
                  / L on every direction
   cantilever     a clamped ANCF chain (the bar of examples/first_chain.c),
                  4, 8, 16 elements: the three lowest frequencies of Kr x
                  = w^2 Mr x against Euler-Bernoulli (beta L = 1.8751...),
                  the error falling with the element's order h^4
   pinned         a pinned-pinned chain prestressed to tension T
                  (vlbe_ale_prestretch), multipliers from
                  vlbe_dae_consistent_acc: w^2 = k^2 (lam T + EI k^2) /
                  rhoA, k = n pi / l (lam the stretch), same convergence
   band           dense and banded storage of one chain (damped, bent,
                  moving) give the same N, Mr, Dr, Kr to rounding
   frame          a particle on a spring and damper about the centre of a
                  frame turning at Om: the roots of det(Mr s^2 + Dr s + Kr)
                  are the inertial ones shifted by -+ i Om; a particle
                  whirling on a spring of natural length L0 (3D frame):
                  radial w^2 = k / m + 3 Om^2, out of plane w = Om, a zero
                  root; a frame with Om = 0 gives the inertial matrices
   fd             Kr, Dr against central differences of the residual
                  M(q) a + C_q^T lambda - Q(q, v) along the columns of N:
                  a small nonlinear system (q-dependent mass, a nonlinear
                  constraint), with analytic Jacobians and without, and a
                  damped ALE chain with a free material node in a bent,
                  moving state
   errors         argument, workspace, callback and non-finite failures
                  leave nr, N, Mr, Dr, Kr untouched (sentinel fill) */
#include "test_util.h"
#include "../ancf_ale.h"
#include "../integrators.h"

#include <string.h>

#define EPS ((double)VLBE_EPS)
#define SQ_EPS (sqrt((double)VLBE_EPS))

/* -- workspace from the queries ----------------------------------------- */
typedef struct lin_ws {
    vlbe_real *w;
    int *iw;
    size_t lw, liw;
} lin_ws;

static lin_ws ws_get(const vlbe_dae *s)
{
    lin_ws b;
    b.lw = vlbe_dae_lin_work_len_sys(s);
    b.liw = vlbe_dae_lin_iwork_len_sys(s);
    b.w = (vlbe_real *)malloc(b.lw * sizeof *b.w);
    b.iw = (int *)malloc((b.liw + 1) * sizeof *b.iw);
    assert_non_null(b.w);
    assert_non_null(b.iw);
    return b;
}
static void ws_free(lin_ws *b)
{
    free(b->w);
    free(b->iw);
}

/* the reduced matrices of one call, n x n room each */
typedef struct lin_out {
    int nr;
    vlbe_real *N, *Mr, *Dr, *Kr;
} lin_out;

static lin_out out_get(int n)
{
    lin_out o;
    size_t nn = (size_t)n * (size_t)n;
    o.nr = -1;
    o.N = (vlbe_real *)malloc(nn * sizeof *o.N);
    o.Mr = (vlbe_real *)malloc(nn * sizeof *o.Mr);
    o.Dr = (vlbe_real *)malloc(nn * sizeof *o.Dr);
    o.Kr = (vlbe_real *)malloc(nn * sizeof *o.Kr);
    assert_true(o.N && o.Mr && o.Dr && o.Kr);
    return o;
}
static void out_free(lin_out *o)
{
    free(o->N);
    free(o->Mr);
    free(o->Dr);
    free(o->Kr);
}

static vlbe_status lin(const vlbe_dae *s, const vlbe_real *q, const vlbe_real *v,
                       const vlbe_real *a, const vlbe_real *lam, const vlbe_lin_frame *fr,
                       lin_out *o)
{
    lin_ws b = ws_get(s);
    vlbe_status rc = vlbe_dae_linearize(s, 0, q, v, a, lam, fr, &o->nr, o->N, o->Mr, o->Dr, o->Kr,
                                        NULL, b.w, b.lw, b.iw, b.liw);
    ws_free(&b);
    return rc;
}

/* N^T N = I to 8 n eps (Householder vectors: a few eps per reflector) */
static void check_orthonormal(int n, int nr, const vlbe_real *N)
{
    int i, j, k;
    for (i = 0; i < nr; ++i)
        for (j = 0; j < nr; ++j) {
            double s = 0.0;
            for (k = 0; k < n; ++k) s += (double)N[k * nr + i] * (double)N[k * nr + j];
            ASSERT_CLOSE_CTX(s, i == j ? 1.0 : 0.0, 0.0, 8.0 * n * EPS, "N^T N (%d, %d)", i, j);
        }
}

/* ===== unconstrained linear spring-mass-damper ========================== */
static const double smd_M[9] = {2.0, 0.3, 0.1, 0.3, 1.5, -0.2, 0.1, -0.2, 1.0};
static const double smd_D[9] = {0.4, -0.1, 0.0, 0.2, 0.3, 0.05, 0.0, -0.05, 0.2};
static const double smd_K[9] = {50.0, -20.0, 0.0, -20.0, 40.0, -20.0, 0.0, -20.0, 30.0};

static int smd_mass(void *u, vlbe_real t, const vlbe_real *q, const vlbe_real *v, vlbe_real *M)
{
    int i;
    (void)u, (void)t, (void)q, (void)v;
    for (i = 0; i < 9; ++i) M[i] = (vlbe_real)smd_M[i];
    return 0;
}
static int smd_force(void *u, vlbe_real t, const vlbe_real *q, const vlbe_real *v, vlbe_real *Q)
{
    int i, j;
    (void)u, (void)t;
    for (i = 0; i < 3; ++i) {
        vlbe_real s = 0;
        for (j = 0; j < 3; ++j)
            s -= (vlbe_real)smd_K[i * 3 + j] * q[j] + (vlbe_real)smd_D[i * 3 + j] * v[j];
        Q[i] = s;
    }
    return 0;
}
static int smd_force_jac(void *u, vlbe_real t, const vlbe_real *q, const vlbe_real *v,
                         vlbe_real *K, vlbe_real *D)
{
    int i;
    (void)u, (void)t, (void)q, (void)v;
    for (i = 0; i < 9; ++i) {
        K[i] = -(vlbe_real)smd_K[i];
        D[i] = -(vlbe_real)smd_D[i];
    }
    return 0;
}

static vlbe_dae smd_sys(int jac)
{
    vlbe_dae s;
    memset(&s, 0, sizeof s);
    s.n = 3;
    s.flags = VLBE_DAE_MASS_CONST;
    s.mass = smd_mass;
    s.force = smd_force;
    if (jac) s.force_jac = smd_force_jac;
    return s;
}

static void test_smd(void **state)
{
    const vlbe_real q[3] = {VLBE_R(0.3), VLBE_R(-0.2), VLBE_R(0.5)},
                    v[3] = {VLBE_R(1.0), VLBE_R(0.5), VLBE_R(-0.7)}, a[3] = {0, 0, 0};
    int jac, i;
    (void)state;
    for (jac = 1; jac >= 0; --jac) {
        vlbe_dae s = smd_sys(jac);
        lin_out o = out_get(3);
        /* differences: |Q| <= |K| |q| + |D| |v| ~ 50; each entry of the
           forward difference carries 2 eps |Q| / h of rounding, h = sqrt(eps) */
        const double tolK = jac ? 0.0 : 4.0 * SQ_EPS * 50.0, tolD = jac ? 0.0 : 4.0 * SQ_EPS * 50.0;
        assert_int_equal(lin(&s, q, v, a, NULL, NULL, &o), VLBE_OK);
        assert_int_equal(o.nr, 3);
        for (i = 0; i < 9; ++i) {
            ASSERT_CLOSE_CTX(o.N[i], (i % 4 == 0) ? 1.0 : 0.0, 0.0, 0.0, "N %d", i);
            ASSERT_CLOSE_CTX(o.Mr[i], (vlbe_real)smd_M[i], 0.0, 0.0, "Mr %d", i);
            ASSERT_CLOSE_CTX(o.Kr[i], (vlbe_real)smd_K[i], 0.0, tolK, "Kr %d (jac %d)", i, jac);
            ASSERT_CLOSE_CTX(o.Dr[i], (vlbe_real)smd_D[i], 0.0, tolD, "Dr %d (jac %d)", i, jac);
        }
        out_free(&o);
    }
}

/* ===== pendulums in absolute coordinates ================================ */
typedef struct pend {
    int dim;       /* 2: (x, y), 3: (x, y, z); gravity along the last axis */
    int copies;    /* the constraint repeated this often (m = copies)       */
    double m, L, g;
    double k, L0;  /* spring pendulum (copies = 0): spring to the origin    */
} pend;

static int pd_mass(void *u, vlbe_real t, const vlbe_real *q, const vlbe_real *v, vlbe_real *M)
{
    const pend *p = (const pend *)u;
    int i;
    (void)t, (void)q, (void)v;
    for (i = 0; i < p->dim * p->dim; ++i) M[i] = (i % (p->dim + 1) == 0) ? (vlbe_real)p->m : 0;
    return 0;
}
static int pd_force(void *u, vlbe_real t, const vlbe_real *q, const vlbe_real *v, vlbe_real *Q)
{
    const pend *p = (const pend *)u;
    int i;
    (void)t, (void)v;
    for (i = 0; i < p->dim; ++i) Q[i] = 0;
    Q[p->dim - 1] = (vlbe_real)(-p->m * p->g);
    if (p->k > 0.0) { /* spring to the origin */
        vlbe_real r2 = 0, r, f;
        for (i = 0; i < p->dim; ++i) r2 += q[i] * q[i];
        r = vlbe_sqrt(r2);
        f = (vlbe_real)p->k * (r - (vlbe_real)p->L0) / r;
        for (i = 0; i < p->dim; ++i) Q[i] -= f * q[i];
    }
    return 0;
}
/* row c of the constraint: (|q|^2 - L^2) times 1, 1, 2, ... (the third copy scaled) */
static vlbe_real pd_scale(int c) { return c >= 2 ? VLBE_R(2.0) : VLBE_R(1.0); }
static int pd_constr(void *u, vlbe_real t, const vlbe_real *q, vlbe_real *C)
{
    const pend *p = (const pend *)u;
    vlbe_real r2 = 0;
    int i;
    (void)t;
    for (i = 0; i < p->dim; ++i) r2 += q[i] * q[i];
    for (i = 0; i < p->copies; ++i) C[i] = pd_scale(i) * (r2 - (vlbe_real)(p->L * p->L));
    return 0;
}
static int pd_cjac(void *u, vlbe_real t, const vlbe_real *q, vlbe_real *Cq, vlbe_real *Ct)
{
    const pend *p = (const pend *)u;
    int i, c;
    (void)t;
    for (c = 0; c < p->copies; ++c) {
        for (i = 0; i < p->dim; ++i) Cq[c * p->dim + i] = pd_scale(c) * 2 * q[i];
        if (Ct) Ct[c] = 0;
    }
    return 0;
}
/* H = d(C_q^T lambda)/dq = 2 sum_c s_c lambda_c I */
static int pd_chess(void *u, vlbe_real t, const vlbe_real *q, const vlbe_real *lam, vlbe_real *H)
{
    const pend *p = (const pend *)u;
    vlbe_real s = 0;
    int i, c;
    (void)t, (void)q;
    for (c = 0; c < p->copies; ++c) s += 2 * pd_scale(c) * lam[c];
    for (i = 0; i < p->dim * p->dim; ++i) H[i] = (i % (p->dim + 1) == 0) ? s : 0;
    return 0;
}

static vlbe_dae pd_sys(pend *p, int hess)
{
    vlbe_dae s;
    memset(&s, 0, sizeof s);
    s.n = p->dim;
    s.m = p->copies;
    s.user = p;
    s.flags = VLBE_DAE_MASS_CONST;
    s.mass = pd_mass;
    s.force = pd_force;
    if (p->copies > 0) {
        s.constr = pd_constr;
        s.constr_jac = pd_cjac;
        if (hess) s.constr_hess = pd_chess;
    }
    return s;
}

static void test_pendulum(void **state)
{
    pend p = {2, 1, 2.0, 1.5, 9.81, 0.0, 0.0};
    vlbe_real q[2], v[2] = {0, 0}, a[2] = {0, 0}, lam[1];
    int hess, up;
    (void)state;
    for (hess = 0; hess <= 1; ++hess)
        for (up = 0; up <= 1; ++up) {
            vlbe_dae s = pd_sys(&p, hess);
            lin_out o = out_get(2);
            const double sg = up ? 1.0 : -1.0;
            /* constr_hess: N = (1, 0) exactly (one reflector of (0, -+2L)),
               Kr = 2 lambda rounded once or twice: 4 eps.  Differences of
               the linear C_q^T lambda = 2 lambda q: the rounding 2 eps |m g|
               of each value over h = sqrt(eps) max(L, 1) = L sqrt(eps) */
            const double tol = hess ? 4.0 * EPS : 4.0 * SQ_EPS;
            q[0] = 0;
            q[1] = (vlbe_real)(sg * p.L);
            /* C_q^T lambda = Q at rest: 2 (sg L) lambda = -m g */
            lam[0] = (vlbe_real)(-p.m * p.g / (2.0 * sg * p.L));
            assert_int_equal(lin(&s, q, v, a, lam, NULL, &o), VLBE_OK);
            assert_int_equal(o.nr, 1);
            ASSERT_CLOSE(fabs((double)o.N[0]), 1.0, 0.0, 2.0 * EPS);
            ASSERT_CLOSE(o.N[1], 0.0, 0.0, 2.0 * EPS);
            ASSERT_CLOSE(o.Mr[0], p.m, 2.0 * EPS, 0.0);
            ASSERT_CLOSE((double)o.Kr[0] / (double)o.Mr[0], -sg * p.g / p.L, tol, 0.0);
            ASSERT_CLOSE(o.Dr[0], 0.0, 0.0, 0.0);
            /* VLBE_DAE_NO_CHESS (an iteration-matrix economy) does not drop it */
            s.flags |= VLBE_DAE_NO_CHESS;
            assert_int_equal(lin(&s, q, v, a, lam, NULL, &o), VLBE_OK);
            ASSERT_CLOSE((double)o.Kr[0] / (double)o.Mr[0], -sg * p.g / p.L, tol, 0.0);
            s.flags &= ~VLBE_DAE_NO_CHESS;
            /* the constraint term is all of it: without lambda nothing is
               left (the force is constant: its differences are exactly 0) */
            lam[0] = 0;
            assert_int_equal(lin(&s, q, v, a, lam, NULL, &o), VLBE_OK);
            assert_true((double)o.Kr[0] == 0.0);
            out_free(&o);
        }
}

static void test_spring_pend(void **state)
{
    /* m = 1, k = 20, L0 = 1: hanging at r0 = L0 + m g / k */
    pend p = {2, 0, 1.0, 0.0, 9.81, 20.0, 1.0};
    const double r0 = p.L0 + p.m * p.g / p.k;
    vlbe_real q[2], v[2] = {0, 0}, a[2] = {0, 0};
    vlbe_dae s = pd_sys(&p, 0);
    lin_out o = out_get(2);
    /* forward differences of Q: truncation h |Q''| / 2 ~ sqrt(eps) k / 2
       and rounding 2 eps |Q| / h ~ 2 sqrt(eps) m g / r0, h = sqrt(eps) r0:
       4 sqrt(eps) k bounds both */
    const double tol = 4.0 * SQ_EPS * p.k;
    (void)state;
    q[0] = 0;
    q[1] = (vlbe_real)(-r0);
    assert_int_equal(lin(&s, q, v, a, NULL, NULL, &o), VLBE_OK);
    assert_int_equal(o.nr, 2);
    ASSERT_CLOSE(o.Kr[0], p.m * p.g / r0, 0.0, tol); /* sideways: the pendulum of length r0 */
    ASSERT_CLOSE(o.Kr[3], p.k, 0.0, tol);            /* along the spring */
    ASSERT_CLOSE(o.Kr[1], 0.0, 0.0, tol);
    ASSERT_CLOSE(o.Kr[2], 0.0, 0.0, tol);
    out_free(&o);
}

static void test_redundant(void **state)
{
    int dim, tilt;
    (void)state;
    for (dim = 2; dim <= 3; ++dim)
        for (tilt = 0; tilt <= 1; ++tilt) {
            /* planar: the constraint twice; 3D: three times, the third scaled by 2 */
            pend p = {2, 2, 2.0, 1.5, 9.81, 0.0, 0.0};
            /* the rod's direction e: hanging along -y (-z), or tilted, where
               the copies of C_q are no longer exactly dependent after a
               reflector (rounding leaves their trailing parts of order eps
               |C_q|): then only the rank test counts them out */
            const double th = tilt ? 0.7 : 0.0, ph = 0.4;
            double e[3] = {0.0, 0.0, 0.0}, lsum, cth = cos(th);
            vlbe_real q[3] = {0, 0, 0}, v[3] = {0, 0, 0}, a[3] = {0, 0, 0}, lam[3];
            int hess, i, j, k;
            p.dim = dim;
            p.copies = dim == 2 ? 2 : 3;
            if (dim == 2) {
                e[0] = sin(th);
                e[1] = -cth;
            } else {
                e[0] = sin(th) * cos(ph);
                e[1] = sin(th) * sin(ph);
                e[2] = -cth;
            }
            for (i = 0; i < dim; ++i) q[i] = (vlbe_real)(p.L * e[i]);
            /* at rest: C_q^T lambda = 2 q sum_c s_c lambda_c carries the
               component m g cos(th) of the weight along the rod, the rest
               accelerates the mass, a = (Q - C_q^T lambda) / m; any split
               whose sum s_c lambda_c is m g cos(th) / (2 L) holds it */
            lsum = p.m * p.g * cth / (2.0 * p.L);
            lam[0] = (vlbe_real)(0.3 * lsum);
            lam[1] = (vlbe_real)(0.7 * lsum);
            if (dim == 3) {
                lam[0] = (vlbe_real)(0.5 * lsum);
                lam[1] = (vlbe_real)(-0.1 * lsum);
                lam[2] = (vlbe_real)(0.3 * lsum); /* times 2 */
            }
            for (i = 0; i < dim; ++i)
                a[i] = (vlbe_real)(-2.0 * lsum * p.L * e[i] / p.m + (i == dim - 1 ? -p.g : 0.0));
            for (hess = 0; hess <= 1; ++hess) {
                vlbe_dae s = pd_sys(&p, hess);
                lin_out o = out_get(dim);
                /* K = 2 sum_c s_c lambda_c I (Q and M constant), so Kr
                   is that times N^T N: as in test_pendulum, plus the
                   rounding of the split's sum; N^T N = I to an eps or two
                   (one or two reflectors of 2 or 3 entries) */
                const double kap = p.g * cth / p.L;
                const double tol = hess ? 8.0 * EPS : 4.0 * SQ_EPS;
                assert_int_equal(lin(&s, q, v, a, lam, NULL, &o), VLBE_OK);
                assert_int_equal(o.nr, dim - 1);
                check_orthonormal(dim, o.nr, o.N);
                /* C_q N = 0: N has no component along the rod (a reflector
                   or two, a few eps each: 4 eps) */
                for (j = 0; j < o.nr; ++j) {
                    double c = 0.0;
                    for (k = 0; k < dim; ++k) c += e[k] * (double)o.N[k * o.nr + j];
                    ASSERT_CLOSE_CTX(c, 0.0, 0.0, 4.0 * EPS, "e . N col %d dim %d tilt %d", j, dim,
                                     tilt);
                }
                for (i = 0; i < o.nr; ++i)
                    for (j = 0; j < o.nr; ++j) {
                        /* Mr = m N^T N (N^T N as above) */
                        ASSERT_CLOSE_CTX(o.Mr[i * o.nr + j], i == j ? p.m : 0.0, 0.0,
                                         8.0 * EPS * p.m, "Mr %d %d dim %d tilt %d", i, j,
                                         dim, tilt);
                        ASSERT_CLOSE_CTX(o.Kr[i * o.nr + j], i == j ? p.m * kap : 0.0, 0.0,
                                         tol * p.m * kap, "Kr %d %d dim %d tilt %d hess %d", i, j,
                                         dim, tilt, hess);
                    }
                out_free(&o);
            }
        }
}

/* ===== chains of ancf_ale.h ============================================= */
#define NE_MAX 16
#define NN_MAX (NE_MAX + 1)

typedef struct chn {
    vlbe_ale_mat mat;
    vlbe_ale_node node[NN_MAX];
    vlbe_ale_con con[4];
    vlbe_ale_chain ch;
    vlbe_dae sys;
    int ord[5 * NN_MAX + 8];
    double lam; /* stretch */
} chn;

static vlbe_ale_elem g_el; /* Gauss tables: static */
static chn g_c, g_c2;

/* kind 0: the cantilever of examples/first_chain.c (1 m, clamped at x = 0,
   no load); kind 1: pinned-pinned over l = 1 under tension T = 100 N
   (EA 1e4, EI 1, rhoA 2); band: banded storage.  q: straight state. */
static void chn_build(chn *c, int kind, int ne, int band, vlbe_real *q)
{
    const vlbe_real r0[2] = {0, 0};
    vlbe_real dir[2] = {1, 0}, e = 0, lam = 1;
    vlbe_ale_con k;
    int i;
    memset(c, 0, sizeof *c);
    if (kind == 0) {
        c->mat.rhoA = VLBE_R(7.85);
        c->mat.EA = VLBE_R(2.1e8);
        c->mat.EI = VLBE_R(1.75e3);
    } else {
        c->mat.rhoA = 2;
        c->mat.EA = 10000;
        c->mat.EI = 1;
        assert_int_equal(vlbe_ale_prestretch(c->mat.EA, 100, &e, &lam), VLBE_OK);
    }
    c->lam = (double)lam;
    assert_int_equal(vlbe_ale_elem_init(&g_el, &c->mat, 0u, 0, 0, 0), VLBE_OK);
    for (i = 0; i <= ne; ++i) c->node[i].p = (vlbe_real)i / (vlbe_real)ne / lam;
    assert_int_equal(vlbe_ale_chain_init(&c->ch, &g_el, c->node, ne + 1, NN_MAX, c->con, 4),
                     VLBE_OK);
    memset(&k, 0, sizeof k);
    k.type = VLBE_ALE_CON_POS;
    k.node = 0;
    assert_int_equal(vlbe_ale_chain_add(&c->ch, &k), VLBE_OK);
    if (kind == 0) {
        k.type = VLBE_ALE_CON_SLOPE;
        k.d[0] = 1;
    } else {
        k.node = ne;
        k.r[0] = 1;
    }
    assert_int_equal(vlbe_ale_chain_add(&c->ch, &k), VLBE_OK);
    if (band) assert_int_equal(vlbe_ale_chain_band(&c->ch, c->ord, 5 * NN_MAX + 8), VLBE_OK);
    assert_int_equal(vlbe_ale_chain_layout(&c->ch), VLBE_OK);
    assert_int_equal(vlbe_ale_chain_dae(&c->ch, &c->sys), VLBE_OK);
    dir[0] = lam;
    vlbe_ale_chain_straight(&c->ch, r0, dir, q);
}

/* q'' and lambda of the state from vlbe_dae_consistent_acc */
static void chn_acc(const vlbe_dae *s, const vlbe_real *q, const vlbe_real *v, vlbe_real *a,
                    vlbe_real *lam)
{
    size_t lw = vlbe_dae_work_len_sys(s), liw = vlbe_dae_iwork_len_sys(s);
    vlbe_real *w = (vlbe_real *)malloc(lw * sizeof *w);
    int *iw = (int *)malloc(liw * sizeof *iw);
    assert_true(w && iw);
    assert_int_equal(vlbe_dae_consistent_acc(s, 0, q, v, a, lam, NULL, w, lw, iw, liw), VLBE_OK);
    free(w);
    free(iw);
}

/* The three lowest w^2 of Kr x = w^2 Mr x by vlbe_eig_gsym with sigma = 0
   (shift-invert: the lowest modes are the largest eigenvalues of the
   reduced problem, which the Jacobi solver gets to a few eps of
   themselves) */
static void low_modes(int nr, const vlbe_real *Mr, const vlbe_real *Kr, double *w2)
{
    size_t lw = vlbe_eig_work_len(nr);
    vlbe_real *w = (vlbe_real *)malloc(lw * sizeof *w), *ev = (vlbe_real *)malloc((size_t)nr * sizeof *ev);
    int info = 0, k;
    assert_true(w && ev);
    assert_int_equal(vlbe_eig_gsym(nr, Kr, Mr, 0, ev, NULL, &info, w, lw), VLBE_OK);
    for (k = 0; k < 3; ++k) w2[k] = (double)ev[k];
    free(w);
    free(ev);
}

/* Frequencies of the chains against the continuum.  Cubic Hermite
   elements: eigenvalue errors O(h^4) (Strang & Fix, An Analysis of the
   Finite Element Method, sec. 6.3: 2 (k + 1 - m) with degree k = 3,
   derivative order m = 2), from above (Rayleigh-Ritz).  Checked, for the
   three lowest modes, above the rounding floor: the straight state's
   strain is known to a few ulps only (positions and slopes rounded, the
   strain a difference |r'|^2 - 1), so the axial force carries a tension
   of about EA eps that no mesh removes; against the stiffness of the
   first mode, S1 = T + EI (beta1 L)^2 / L^2 (a tension; pinned: beta1 L =
   pi), it moves w^2 by EA eps / S1 relative: floor_ = 8 EA eps / S1 +
   64 eps (a few ulps of strain; 64 eps for the Cholesky and Jacobi of
   vlbe_eig_gsym).  Double: 6e-11 (cantilever), 2e-13; float: 0.033 for the
   steel cantilever (EA / EI = 1.2e5: its frequencies are not to be had
   in float closer than about 0.5 %), 1e-4 for the pinned chain.
   - the error is positive (beyond -floor_);
   - each doubling of the elements divides it by at least 10 (16 in the
     limit; 10 leaves room for the pre-asymptotic 4-element mesh on the
     third mode), the last one (8 -> 16) by 2^3.5 (order 4 minus the
     higher-order terms);
   - the limit is the closed form: the Richardson extrapolation (16 w16^2 -
     w8^2) / 15 of the order-4 error is at least 4 times closer to it
     than w16^2 (a discretisation converging to another value would not
     come closer). */
static void chain_modes(int kind)
{
    static const double betaL[3] = {1.8751040687119611, 4.6940911329741745, 7.8547574382376126};
    const int nes[3] = {4, 8, 16};
    double floor_ = 0.0, err_prev[3] = {0, 0, 0}, w2_prev[3] = {0, 0, 0};
    int s_ne, k;
    for (s_ne = 0; s_ne < 3; ++s_ne) {
        const int ne = nes[s_ne];
        vlbe_real q[5 * NN_MAX], v[5 * NN_MAX], a[5 * NN_MAX], lam[4];
        lin_out o;
        double w2[3];
        chn_build(&g_c, kind, ne, 0, q);
        memset(v, 0, sizeof v);
        chn_acc(&g_c.sys, q, v, a, lam);
        o = out_get(g_c.sys.n);
        assert_int_equal(lin(&g_c.sys, q, v, a, lam, NULL, &o), VLBE_OK);
        assert_int_equal(o.nr, g_c.sys.n - 4);
        check_orthonormal(g_c.sys.n, o.nr, o.N);
        low_modes(o.nr, o.Mr, o.Kr, w2);
        {
            const double S1 = kind == 0 ? (double)g_c.mat.EI * betaL[0] * betaL[0]
                                        : 100.0 + (double)g_c.mat.EI * 9.8696044010893586;
            floor_ = 8.0 * (double)g_c.mat.EA * EPS / S1 + 64.0 * EPS;
        }
        for (k = 0; k < 3; ++k) {
            double ref, err;
            if (kind == 0) {
                const double bl2 = betaL[k] * betaL[k];
                ref = bl2 * bl2 * (double)g_c.mat.EI / (double)g_c.mat.rhoA;
            } else {
                const double kk = (k + 1) * 3.14159265358979323846;
                ref = kk * kk * (g_c.lam * 100.0 + (double)g_c.mat.EI * kk * kk) /
                      (double)g_c.mat.rhoA;
            }
            err = (w2[k] - ref) / ref;
            if (tu_report_on())
                print_message("    %s ne %2d mode %d: w^2 %.10e, ref %.10e, rel. error %.3e\n",
                              kind ? "pinned" : "cantilever", ne, k + 1, w2[k], ref, err);
            assert_true(err > -floor_);
            if (s_ne > 0 && err_prev[k] > 16.0 * floor_)
                assert_true(fabs(err) <= err_prev[k] / (s_ne == 2 ? pow(2.0, 3.5) : 10.0) + floor_);
            if (s_ne == 2) {
                const double ex = ((16.0 * w2[k] - w2_prev[k]) / 15.0 - ref) / ref;
                if (tu_report_on())
                    print_message("    %s mode %d: extrapolated rel. error %.3e\n",
                                  kind ? "pinned" : "cantilever", k + 1, ex);
                assert_true(fabs(ex) <= fabs(err) / 4.0 + floor_);
            }
            err_prev[k] = fabs(err);
            w2_prev[k] = w2[k];
        }
        out_free(&o);
    }
}

static void test_cantilever(void **state)
{
    (void)state;
    chain_modes(0);
}

static void test_pinned(void **state)
{
    (void)state;
    chain_modes(1);
}

/* a damped pinned chain, bent and moving: q, v and a made up, the
   multipliers of its consistent accelerations */
static void chn_moving(chn *c, int band, vlbe_real *q, vlbe_real *v, vlbe_real *a, vlbe_real *lam)
{
    tu_rng g = tu_rng_seed(42);
    int i;
    chn_build(c, 1, 6, band, q);
    c->mat.c_eps = VLBE_R(0.01);
    c->mat.c_kap = VLBE_R(0.02);
    assert_int_equal(vlbe_ale_elem_init(&g_el, &c->mat, 0u, 0, 0, 0), VLBE_OK);
    for (i = 0; i < c->sys.n; ++i) {
        q[i] += (vlbe_real)(0.02 * tu_rng_uniform(&g));
        v[i] = (vlbe_real)(0.5 * tu_rng_uniform(&g));
    }
    chn_acc(&c->sys, q, v, a, lam);
}

static void test_band(void **state)
{
    vlbe_real q[5 * NN_MAX], v[5 * NN_MAX], a[5 * NN_MAX], lam[4];
    vlbe_real q2[5 * NN_MAX], v2[5 * NN_MAX], a2[5 * NN_MAX], lam2[4];
    lin_out od, ob;
    int n, nr, i;
    double mM = 0, mD = 0, mK = 0;
    (void)state;
    chn_moving(&g_c, 0, q, v, a, lam);
    chn_moving(&g_c2, 1, q2, v2, a2, lam2);
    assert_int_equal(g_c2.sys.storage, VLBE_DAE_BANDED);
    n = g_c.sys.n;
    assert_int_equal(g_c2.sys.n, n);
    od = out_get(n);
    ob = out_get(n);
    /* both from the dense state: the banded chain is the same model */
    assert_int_equal(lin(&g_c.sys, q, v, a, lam, NULL, &od), VLBE_OK);
    assert_int_equal(lin(&g_c2.sys, q, v, a, lam, NULL, &ob), VLBE_OK);
    assert_int_equal(od.nr, ob.nr);
    nr = od.nr;
    assert_int_equal(nr, n - 4);
    for (i = 0; i < nr * nr; ++i) {
        mM = fmax(mM, fabs((double)od.Mr[i]));
        mD = fmax(mD, fabs((double)od.Dr[i]));
        mK = fmax(mK, fabs((double)od.Kr[i]));
    }
    assert_true(mD > 0.0);
    /* the same C_q: the same N bit for bit; the matrices are sums of the
       same element terms in another order: 64 eps of the largest entry
       (sums of up to 2 n terms, each rounded) */
    ASSERT_VEC_CLOSE(ob.N, od.N, n * nr, 0.0, 0.0);
    ASSERT_VEC_CLOSE(ob.Mr, od.Mr, nr * nr, 0.0, 64.0 * EPS * mM);
    ASSERT_VEC_CLOSE(ob.Dr, od.Dr, nr * nr, 0.0, 64.0 * EPS * mD);
    ASSERT_VEC_CLOSE(ob.Kr, od.Kr, nr * nr, 0.0, 64.0 * EPS * mK);
    out_free(&od);
    out_free(&ob);
}

/* ===== rotating frame =================================================== */
typedef struct spr {
    int dim;
    double m, k, c, L0; /* mass, spring to the origin (natural length L0), damper */
} spr;

static int sp_mass(void *u, vlbe_real t, const vlbe_real *q, const vlbe_real *v, vlbe_real *M)
{
    const spr *p = (const spr *)u;
    int i;
    (void)t, (void)q, (void)v;
    for (i = 0; i < p->dim * p->dim; ++i) M[i] = (i % (p->dim + 1) == 0) ? (vlbe_real)p->m : 0;
    return 0;
}
/* Q = -k (|q| - L0) q / |q| - c v (L0 = 0: -k q - c v) */
static int sp_force(void *u, vlbe_real t, const vlbe_real *q, const vlbe_real *v, vlbe_real *Q)
{
    const spr *p = (const spr *)u;
    vlbe_real r2 = 0, f = (vlbe_real)p->k;
    int i;
    (void)t;
    for (i = 0; i < p->dim; ++i) r2 += q[i] * q[i];
    if (p->L0 > 0.0) f = (vlbe_real)p->k * (vlbe_sqrt(r2) - (vlbe_real)p->L0) / vlbe_sqrt(r2);
    for (i = 0; i < p->dim; ++i) Q[i] = -f * q[i] - (vlbe_real)p->c * v[i];
    return 0;
}
static vlbe_dae sp_sys(spr *p)
{
    vlbe_dae s;
    memset(&s, 0, sizeof s);
    s.n = p->dim;
    s.user = p;
    s.flags = VLBE_DAE_MASS_CONST;
    s.mass = sp_mass;
    s.force = sp_force;
    return s;
}

/* |det(Mr s^2 + Dr s + Kr)| / (|Mr| |s|^2 + |Dr| |s| + |Kr|)^n at the
   complex s = (sr, si), n <= 3, in double */
static double det_rel(int n, const vlbe_real *Mr, const vlbe_real *Dr, const vlbe_real *Kr,
                      double sr, double si)
{
    double Ar[9], Ai[9], s2r = sr * sr - si * si, s2i = 2.0 * sr * si, dr, di, scale = 0;
    double as = sqrt(sr * sr + si * si);
    double mm = 0, md = 0, mk = 0;
    int i;
    for (i = 0; i < n * n; ++i) {
        Ar[i] = (double)Mr[i] * s2r + (double)Dr[i] * sr + (double)Kr[i];
        Ai[i] = (double)Mr[i] * s2i + (double)Dr[i] * si;
        mm = fmax(mm, fabs((double)Mr[i]));
        md = fmax(md, fabs((double)Dr[i]));
        mk = fmax(mk, fabs((double)Kr[i]));
    }
    scale = mm * as * as + md * as + mk;
    if (n == 2) {
        dr = Ar[0] * Ar[3] - Ai[0] * Ai[3] - (Ar[1] * Ar[2] - Ai[1] * Ai[2]);
        di = Ar[0] * Ai[3] + Ai[0] * Ar[3] - (Ar[1] * Ai[2] + Ai[1] * Ar[2]);
        return sqrt(dr * dr + di * di) / (scale * scale);
    }
    {
        /* cofactor expansion along the first row */
        double cr = 0, ci = 0;
        int j;
        for (j = 0; j < 3; ++j) {
            const int a = 3 + (j + 1) % 3, b = 3 + (j + 2) % 3, c2 = 6 + (j + 1) % 3,
                      d = 6 + (j + 2) % 3;
            const double mr = Ar[a] * Ar[d] - Ai[a] * Ai[d] - (Ar[b] * Ar[c2] - Ai[b] * Ai[c2]);
            const double mi = Ar[a] * Ai[d] + Ai[a] * Ar[d] - (Ar[b] * Ai[c2] + Ai[b] * Ar[c2]);
            cr += Ar[j] * mr - Ai[j] * mi;
            ci += Ar[j] * mi + Ai[j] * mr;
        }
        return sqrt(cr * cr + ci * ci) / (scale * scale * scale);
    }
}

static void test_frame(void **state)
{
    (void)state;
    /* (a) isotropic spring k and damper c at the centre of a planar frame
       turning at Om.  In the complex coordinate z = x + i y the inertial
       motions are z = e^{s0 t} and conj-type e^{conj(s0) t}, s0 roots of
       m s^2 + c s + k = 0; the frame sees z~ = e^{-i Om t} z: the roots are
       s0 - i Om and (for the conjugate z) conj(s0) + i Om and their
       conjugates.  force_jac absent: Kr, Dr by differences of a linear
       force, each entry to 4 sqrt(eps) of |Q| ~ k |q| + c |v| = 0 at the
       centre (exact), so the determinant vanishes to rounding: 64 eps. */
    {
        spr p = {2, 2.0, 50.0, 0.8, 0.0};
        const int vec[1] = {0};
        vlbe_lin_frame fr;
        vlbe_real q[2] = {0, 0}, v[2] = {0, 0}, a[2] = {0, 0};
        vlbe_dae s = sp_sys(&p);
        lin_out o = out_get(2);
        const double Om = 3.0, s0r = -p.c / (2.0 * p.m),
                     s0i = sqrt(p.k / p.m - s0r * s0r);
        memset(&fr, 0, sizeof fr);
        fr.omega[2] = (vlbe_real)Om;
        fr.dim = 2;
        fr.nvec = 1;
        fr.vec = vec;
        assert_int_equal(lin(&s, q, v, a, NULL, &fr, &o), VLBE_OK);
        assert_int_equal(o.nr, 2);
        assert_true(det_rel(2, o.Mr, o.Dr, o.Kr, s0r, s0i - Om) <= 64.0 * EPS);
        assert_true(det_rel(2, o.Mr, o.Dr, o.Kr, s0r, -s0i - Om) <= 64.0 * EPS);
        assert_true(det_rel(2, o.Mr, o.Dr, o.Kr, s0r, s0i + Om) <= 64.0 * EPS);
        assert_true(det_rel(2, o.Mr, o.Dr, o.Kr, s0r, -s0i + Om) <= 64.0 * EPS);
        /* and not at the inertial roots (the frame changed something) */
        assert_true(det_rel(2, o.Mr, o.Dr, o.Kr, s0r, s0i) > 1e-3);
        out_free(&o);
    }
    /* (b) a particle whirling at Om on a spring of natural length L0 (3D
       frame about z): the steady radius k (r0 - L0) = m Om^2 r0.  In polar
       coordinates with angular momentum h = m r^2 th' conserved, m r'' =
       h^2 / (m r^3) - k (r - L0): radial w^2 = k / m + 3 Om^2.  Out of the
       plane the stiffness is the tension over r0, m Om^2: w = Om.  A
       neighbouring circle (another h) makes a zero root.  Differences of
       the nonlinear spring force: truncation sqrt(eps) k / 2 and rounding
       2 sqrt(eps) |Q|, |Q| = m Om^2 r0 ~ k: the determinant to 16 sqrt(eps). */
    {
        spr p = {3, 1.5, 40.0, 0.0, 1.0};
        const double Om = 2.5, r0 = p.k * p.L0 / (p.k - p.m * Om * Om);
        const int vec[1] = {0};
        vlbe_lin_frame fr;
        vlbe_real q[3] = {0, 0, 0}, v[3] = {0, 0, 0}, a[3] = {0, 0, 0};
        vlbe_dae s = sp_sys(&p);
        lin_out o = out_get(3);
        memset(&fr, 0, sizeof fr);
        fr.omega[2] = (vlbe_real)Om;
        fr.dim = 3;
        fr.nvec = 1;
        fr.vec = vec;
        q[0] = (vlbe_real)r0;   /* the steady state: v = G q, a = G^2 q */
        v[1] = (vlbe_real)(Om * r0);
        a[0] = (vlbe_real)(-Om * Om * r0);
        assert_int_equal(lin(&s, q, v, a, NULL, &fr, &o), VLBE_OK);
        assert_int_equal(o.nr, 3);
        assert_true(det_rel(3, o.Mr, o.Dr, o.Kr, 0.0, sqrt(p.k / p.m + 3.0 * Om * Om)) <=
                    16.0 * SQ_EPS);
        assert_true(det_rel(3, o.Mr, o.Dr, o.Kr, 0.0, Om) <= 16.0 * SQ_EPS);
        assert_true(det_rel(3, o.Mr, o.Dr, o.Kr, 0.0, 0.0) <= 16.0 * SQ_EPS);
        /* and not at the radial root sqrt(k/m) of a spring without the
           frame's terms (they matter) */
        assert_true(det_rel(3, o.Mr, o.Dr, o.Kr, 0.0, sqrt(p.k / p.m)) > 1e-3);
        out_free(&o);
    }
    /* (c) Om = 0: the inertial matrices, value for value (damped moving chain,
       every node's position and slope listed) */
    {
        vlbe_real q[5 * NN_MAX], v[5 * NN_MAX], a[5 * NN_MAX], lam[4];
        int vec[2 * NN_MAX], i, n, nr;
        vlbe_lin_frame fr;
        lin_out o1, o2;
        chn_moving(&g_c, 0, q, v, a, lam);
        n = g_c.sys.n;
        memset(&fr, 0, sizeof fr);
        fr.dim = 2;
        fr.nvec = 2 * g_c.ch.nn;
        for (i = 0; i < g_c.ch.nn; ++i) {
            vec[2 * i] = g_c.node[i].ofs;
            vec[2 * i + 1] = g_c.node[i].ofs + 2;
        }
        fr.vec = vec;
        o1 = out_get(n);
        o2 = out_get(n);
        assert_int_equal(lin(&g_c.sys, q, v, a, lam, NULL, &o1), VLBE_OK);
        assert_int_equal(lin(&g_c.sys, q, v, a, lam, &fr, &o2), VLBE_OK);
        nr = o1.nr;
        assert_int_equal(o2.nr, nr);
        ASSERT_VEC_CLOSE(o2.N, o1.N, n * nr, 0.0, 0.0);
        ASSERT_VEC_CLOSE(o2.Mr, o1.Mr, nr * nr, 0.0, 0.0);
        ASSERT_VEC_CLOSE(o2.Dr, o1.Dr, nr * nr, 0.0, 0.0);
        ASSERT_VEC_CLOSE(o2.Kr, o1.Kr, nr * nr, 0.0, 0.0);
        out_free(&o1);
        out_free(&o2);
    }
}

/* ===== finite differences of the residual =============================== */
/* A small nonlinear system: n = 3, m = 1, q-dependent mass, v-dependent
   force, a nonlinear constraint; analytic Jacobians optional. */
static int ty_mass(void *u, vlbe_real t, const vlbe_real *q, const vlbe_real *v, vlbe_real *M)
{
    (void)u, (void)t, (void)v;
    M[0] = 2 + q[1] * q[1];
    M[1] = M[3] = VLBE_R(0.3) * q[0];
    M[2] = M[6] = 0;
    M[4] = VLBE_R(1.5) + VLBE_R(0.2) * vlbe_sin(q[2]);
    M[5] = M[7] = VLBE_R(0.1);
    M[8] = 1;
    return 0;
}
static int ty_force(void *u, vlbe_real t, const vlbe_real *q, const vlbe_real *v, vlbe_real *Q)
{
    (void)u, (void)t;
    Q[0] = -3 * q[0] - q[0] * q[0] * q[0] + VLBE_R(0.5) * q[1] * q[2] - VLBE_R(0.4) * v[0] -
           VLBE_R(0.1) * v[1] * v[1];
    Q[1] = -2 * q[1] + vlbe_sin(q[0]) - VLBE_R(0.3) * v[1] * v[0];
    Q[2] = -5 * q[2] + q[0] * q[1] - VLBE_R(0.2) * v[2] + VLBE_R(0.05) * v[0] * v[2];
    return 0;
}
static int ty_force_jac(void *u, vlbe_real t, const vlbe_real *q, const vlbe_real *v,
                        vlbe_real *K, vlbe_real *D)
{
    (void)u, (void)t;
    K[0] = -3 - 3 * q[0] * q[0];
    K[1] = VLBE_R(0.5) * q[2];
    K[2] = VLBE_R(0.5) * q[1];
    K[3] = vlbe_cos(q[0]);
    K[4] = -2;
    K[5] = 0;
    K[6] = q[1];
    K[7] = q[0];
    K[8] = -5;
    D[0] = VLBE_R(-0.4);
    D[1] = VLBE_R(-0.2) * v[1];
    D[2] = 0;
    D[3] = VLBE_R(-0.3) * v[1];
    D[4] = VLBE_R(-0.3) * v[0];
    D[5] = 0;
    D[6] = VLBE_R(0.05) * v[2];
    D[7] = 0;
    D[8] = VLBE_R(-0.2) + VLBE_R(0.05) * v[0];
    return 0;
}
/* Mq = d(M(q) a)/dq */
static int ty_mass_jac(void *u, vlbe_real t, const vlbe_real *q, const vlbe_real *v,
                       const vlbe_real *a, vlbe_real *Mq, vlbe_real *Mv)
{
    (void)u, (void)t, (void)v, (void)Mv;
    /* M a = ((2 + q1^2) a0 + 0.3 q0 a1, 0.3 q0 a0 + (1.5 + 0.2 sin q2) a1 + 0.1 a2,
              0.1 a1 + a2) */
    Mq[0] = VLBE_R(0.3) * a[1];
    Mq[1] = 2 * q[1] * a[0];
    Mq[2] = 0;
    Mq[3] = VLBE_R(0.3) * a[0];
    Mq[4] = 0;
    Mq[5] = VLBE_R(0.2) * vlbe_cos(q[2]) * a[1];
    Mq[6] = Mq[7] = Mq[8] = 0;
    return 0;
}
static int ty_constr(void *u, vlbe_real t, const vlbe_real *q, vlbe_real *C)
{
    (void)u, (void)t;
    C[0] = q[0] * q[0] + q[1] * q[2] + VLBE_R(0.5) * q[2] * q[2] * q[2] - 1;
    return 0;
}
static int ty_cjac(void *u, vlbe_real t, const vlbe_real *q, vlbe_real *Cq, vlbe_real *Ct)
{
    (void)u, (void)t;
    Cq[0] = 2 * q[0];
    Cq[1] = q[2];
    Cq[2] = q[1] + VLBE_R(1.5) * q[2] * q[2];
    if (Ct) Ct[0] = 0;
    return 0;
}
static int ty_chess(void *u, vlbe_real t, const vlbe_real *q, const vlbe_real *lam, vlbe_real *H)
{
    (void)u, (void)t;
    memset(H, 0, 9 * sizeof *H);
    H[0] = 2 * lam[0];
    H[5] = H[7] = lam[0];
    H[8] = 3 * q[2] * lam[0];
    return 0;
}
static vlbe_dae ty_sys(int jac)
{
    vlbe_dae s;
    memset(&s, 0, sizeof s);
    s.n = 3;
    s.m = 1;
    s.mass = ty_mass;
    s.force = ty_force;
    s.constr = ty_constr;
    s.constr_jac = ty_cjac;
    if (jac) {
        s.force_jac = ty_force_jac;
        s.mass_jac = ty_mass_jac;
        s.constr_hess = ty_chess;
    }
    return s;
}

/* R = M(q) a + C_q(q)^T lambda - Q(q, v), in double from the callbacks */
static void resid(const vlbe_dae *s, const vlbe_real *q, const vlbe_real *v, const vlbe_real *a,
                  const vlbe_real *lam, double *R)
{
    const int n = s->n, m = s->m;
    size_t nn = (size_t)n * (size_t)n;
    vlbe_real *M = (vlbe_real *)calloc(nn + (size_t)m * (size_t)n + (size_t)n, sizeof *M);
    vlbe_real *Cq = M + nn, *Q = Cq + (size_t)m * (size_t)n;
    int i, j;
    assert_non_null(M);
    assert_int_equal(s->mass(s->user, 0, q, v, M), 0);
    assert_int_equal(s->force(s->user, 0, q, v, Q), 0);
    if (m > 0) assert_int_equal(s->constr_jac(s->user, 0, q, Cq, NULL), 0);
    for (i = 0; i < n; ++i) {
        double r = -(double)Q[i];
        for (j = 0; j < n; ++j) r += (double)M[(size_t)i * n + j] * (double)a[j];
        for (j = 0; j < m; ++j) r += (double)Cq[(size_t)j * n + i] * (double)lam[j];
        R[i] = r;
    }
    free(M);
}

/* Kr, Dr of the dense problem s against central differences of resid */
static void check_fd(const vlbe_dae *s, const vlbe_real *q, const vlbe_real *v, const vlbe_real *a,
                     const vlbe_real *lam, double scale_q, double scale_v, double rel_lib,
                     const char *what)
{
    const int n = s->n;
    lin_out o = out_get(n);
    vlbe_real *x = (vlbe_real *)malloc((size_t)n * sizeof *x);
    double *Rp = (double *)malloc((size_t)n * sizeof *Rp), *Rm = (double *)malloc((size_t)n * sizeof *Rm);
    double mK = 0, mD = 0, errK = 0, errD = 0, tolK, tolD;
    int nr, i, j, pass, k;
    assert_true(x && Rp && Rm);
    assert_int_equal(lin(s, q, v, a, lam, NULL, &o), VLBE_OK);
    nr = o.nr;
    for (i = 0; i < nr * nr; ++i) {
        mK = fmax(mK, fabs((double)o.Kr[i]));
        mD = fmax(mD, fabs((double)o.Dr[i]));
    }
    assert_true(mK > 0.0 && mD > 0.0);
    for (pass = 0; pass < 2; ++pass) {
        const double h = tu_fd_step(EPS, pass == 0 ? scale_q : scale_v);
        const vlbe_real *Xr = pass == 0 ? o.Kr : o.Dr;
        for (j = 0; j < nr; ++j) {
            double dp, dm;
            /* R at x +- h N_j (the step that was taken: rounded x) */
            for (k = 0; k < n; ++k) x[k] = (pass == 0 ? q[k] : v[k]) + (vlbe_real)(h * (double)o.N[k * nr + j]);
            dp = h;
            resid(s, pass == 0 ? x : q, pass == 0 ? v : x, a, lam, Rp);
            for (k = 0; k < n; ++k) x[k] = (pass == 0 ? q[k] : v[k]) - (vlbe_real)(h * (double)o.N[k * nr + j]);
            dm = h;
            resid(s, pass == 0 ? x : q, pass == 0 ? v : x, a, lam, Rm);
            for (i = 0; i < nr; ++i) {
                double d = 0.0;
                for (k = 0; k < n; ++k) d += (double)o.N[k * nr + i] * (Rp[k] - Rm[k]);
                d /= dp + dm;
                if (pass == 0) errK = fmax(errK, fabs(d - (double)Xr[i * nr + j]));
                else errD = fmax(errD, fabs(d - (double)Xr[i * nr + j]));
            }
        }
    }
    /* the test's central differences: truncation h^2 |R'''| / 6 and
       rounding eps |R| / h, both ~ eps^(2/3) of the largest entry (the
       rounded steps x +- h N_j add eps |x| / h of the same size): 64
       eps^(2/3); plus the library's own error rel_lib (its forward
       differences where Jacobians are missing) */
    tolK = (64.0 * cbrt(EPS * EPS) + rel_lib) * mK;
    tolD = (64.0 * cbrt(EPS * EPS) + rel_lib) * mD;
    tu_report(what, errK / mK, tolK / mK);
    assert_true(errK <= tolK);
    assert_true(errD <= tolD);
    free(x);
    free(Rp);
    free(Rm);
    out_free(&o);
}

static void test_fd(void **state)
{
    const vlbe_real q[3] = {VLBE_R(0.7), VLBE_R(-0.4), VLBE_R(0.9)},
                    v[3] = {VLBE_R(0.3), VLBE_R(-1.1), VLBE_R(0.6)},
                    a[3] = {VLBE_R(-0.5), VLBE_R(0.8), VLBE_R(1.3)}, lam[1] = {VLBE_R(1.7)};
    int jac;
    (void)state;
    for (jac = 1; jac >= 0; --jac) {
        vlbe_dae s = ty_sys(jac);
        /* library differences (jac 0): forward, error ~ sqrt(eps) |R''| h
           + eps |R| / h, both ~ sqrt(eps) of the entries here: 16 sqrt(eps) */
        check_fd(&s, q, v, a, lam, 1.0, 1.0, jac ? 0.0 : 16.0 * SQ_EPS,
                 jac ? "toy system, analytic Jacobians: max |dKr| / max |Kr|"
                     : "toy system, differences: max |dKr| / max |Kr|");
    }
    /* a damped chain with a free material node in a bent, moving state:
       the chain's analytic Jacobians (mass_jac: M depends on p) */
    {
        vlbe_real qc[5 * NN_MAX + 2], vc[5 * NN_MAX + 2], ac[5 * NN_MAX + 2], lc[4];
        tu_rng g = tu_rng_seed(7);
        int i;
        chn *c = &g_c;
        const vlbe_real r0[2] = {0, 0};
        vlbe_real dir[2];
        vlbe_ale_con k;
        memset(c, 0, sizeof *c);
        c->mat.rhoA = 2;
        c->mat.EA = 1000;
        c->mat.EI = 1;
        c->mat.c_eps = VLBE_R(0.01);
        c->mat.c_kap = VLBE_R(0.02);
        assert_int_equal(vlbe_ale_elem_init(&g_el, &c->mat, 0u, 0, 0, 0), VLBE_OK);
        for (i = 0; i <= 4; ++i) c->node[i].p = (vlbe_real)i / 4;
        c->node[2].pmode = VLBE_ALE_PFREE;
        assert_int_equal(vlbe_ale_chain_init(&c->ch, &g_el, c->node, 5, NN_MAX, c->con, 4), VLBE_OK);
        memset(&k, 0, sizeof k);
        k.type = VLBE_ALE_CON_POS;
        assert_int_equal(vlbe_ale_chain_add(&c->ch, &k), VLBE_OK);
        k.node = 4;
        k.r[0] = 1;
        assert_int_equal(vlbe_ale_chain_add(&c->ch, &k), VLBE_OK);
        assert_int_equal(vlbe_ale_chain_layout(&c->ch), VLBE_OK);
        assert_int_equal(vlbe_ale_chain_dae(&c->ch, &c->sys), VLBE_OK);
        assert_int_equal(c->sys.n, 4 * 5 + 1);
        assert_true(!(c->sys.flags & VLBE_DAE_MASS_CONST));
        dir[0] = 1;
        dir[1] = 0;
        vlbe_ale_chain_straight(&c->ch, r0, dir, qc);
        for (i = 0; i < c->sys.n; ++i) {
            qc[i] += (vlbe_real)(0.05 * tu_rng_uniform(&g));
            vc[i] = (vlbe_real)(0.5 * tu_rng_uniform(&g));
            ac[i] = (vlbe_real)(3.0 * tu_rng_uniform(&g));
        }
        for (i = 0; i < 4; ++i) lc[i] = (vlbe_real)(20.0 * tu_rng_uniform(&g));
        check_fd(&c->sys, qc, vc, ac, lc, 0.1, 1.0, 0.0,
                 "ALE chain, free node: max |dKr| / max |Kr|");
    }
}

/* ===== failures ========================================================= */
static int bad_rc; /* what the failing callback returns */
static int bad_which; /* 0 mass, 1 force, 2 constr_jac, 3 force NaN */
static int bd_mass(void *u, vlbe_real t, const vlbe_real *q, const vlbe_real *v, vlbe_real *M)
{
    if (bad_which == 0) return bad_rc;
    return pd_mass(u, t, q, v, M);
}
static int bd_force(void *u, vlbe_real t, const vlbe_real *q, const vlbe_real *v, vlbe_real *Q)
{
    int rc;
    if (bad_which == 1) return bad_rc;
    rc = pd_force(u, t, q, v, Q);
    if (bad_which == 3) Q[0] = (vlbe_real)NAN;
    return rc;
}
static int bd_cjac(void *u, vlbe_real t, const vlbe_real *q, vlbe_real *Cq, vlbe_real *Ct)
{
    if (bad_which == 2) return bad_rc;
    return pd_cjac(u, t, q, Cq, Ct);
}

static void test_errors(void **state)
{
    pend p = {2, 1, 2.0, 1.5, 9.81, 0.0, 0.0};
    vlbe_dae s = pd_sys(&p, 0), bad;
    vlbe_real q[2] = {0, VLBE_R(-1.5)}, v[2] = {0, 0}, a[2] = {0, 0}, lam[1] = {VLBE_R(6.54)};
    vlbe_real N[4], Mr[4], Dr[4], Kr[4];
    int nr = 77, vec[2] = {0, 1}, i;
    vlbe_lin_frame fr;
    vlbe_dae_stats st;
    lin_ws b = ws_get(&s);
    (void)state;
    memset(&fr, 0, sizeof fr);
    fr.dim = 2;
    fr.nvec = 1;
    fr.vec = vec;
#define SENTINEL()                                                                        \
    do {                                                                                  \
        nr = 77;                                                                          \
        for (i = 0; i < 4; ++i) N[i] = Mr[i] = Dr[i] = Kr[i] = VLBE_R(7777.0);            \
    } while (0)
#define UNTOUCHED()                                                                       \
    do {                                                                                  \
        assert_int_equal(nr, 77);                                                         \
        for (i = 0; i < 4; ++i)                                                           \
            assert_true((double)N[i] == 7777.0 && (double)Mr[i] == 7777.0 &&              \
                        (double)Dr[i] == 7777.0 && (double)Kr[i] == 7777.0);              \
    } while (0)
#define CALL(sys_, q_, fr_, nrp, lw_, liw_) \
    vlbe_dae_linearize(sys_, 0, q_, v, a, lam, fr_, nrp, N, Mr, Dr, Kr, &st, b.w, lw_, b.iw, liw_)
    memset(&st, 0, sizeof st);
    /* a good call first: the sentinels do go */
    SENTINEL();
    assert_int_equal(CALL(&s, q, &fr, &nr, b.lw, b.liw), VLBE_OK);
    assert_int_equal(nr, 1);
    /* arguments */
    SENTINEL();
    assert_int_equal(CALL(&s, q, NULL, NULL, b.lw, b.liw), VLBE_EARG); /* nr NULL */
    UNTOUCHED();
    bad = s;
    bad.m = 3; /* m > n */
    assert_int_equal(CALL(&bad, q, NULL, &nr, b.lw, b.liw), VLBE_EARG);
    UNTOUCHED();
    assert_int_equal(vlbe_dae_linearize(&s, 0, q, v, a, NULL, NULL, &nr, N, Mr, Dr, Kr, &st, b.w,
                                        b.lw, b.iw, b.liw),
                     VLBE_EARG); /* lambda NULL, m = 1 */
    assert_int_equal(vlbe_dae_linearize(&s, 0, q, v, a, lam, NULL, &nr, N, NULL, Dr, Kr, &st, b.w,
                                        b.lw, b.iw, b.liw),
                     VLBE_EARG); /* Mr NULL */
    assert_int_equal(vlbe_dae_linearize(&s, (vlbe_real)NAN, q, v, a, lam, NULL, &nr, N, Mr, Dr, Kr,
                                        &st, b.w, b.lw, b.iw, b.liw),
                     VLBE_EARG);
    UNTOUCHED();
    fr.dim = 4;
    assert_int_equal(CALL(&s, q, &fr, &nr, b.lw, b.liw), VLBE_EARG);
    fr.dim = 1;
    assert_int_equal(CALL(&s, q, &fr, &nr, b.lw, b.liw), VLBE_EARG);
    fr.dim = 2;
    vec[0] = 1; /* the vector (q1, q2): q2 does not exist */
    assert_int_equal(CALL(&s, q, &fr, &nr, b.lw, b.liw), VLBE_EARG);
    vec[0] = -1;
    assert_int_equal(CALL(&s, q, &fr, &nr, b.lw, b.liw), VLBE_EARG);
    vec[0] = 0;
    fr.nvec = -1;
    assert_int_equal(CALL(&s, q, &fr, &nr, b.lw, b.liw), VLBE_EARG);
    fr.nvec = 2; /* vec = {0, 1}: overlapping vectors */
    assert_int_equal(CALL(&s, q, &fr, &nr, b.lw, b.liw), VLBE_EARG);
    fr.nvec = 1;
    fr.vec = NULL;
    assert_int_equal(CALL(&s, q, &fr, &nr, b.lw, b.liw), VLBE_EARG);
    fr.vec = vec;
    fr.omega[2] = (vlbe_real)INFINITY;
    assert_int_equal(CALL(&s, q, &fr, &nr, b.lw, b.liw), VLBE_EARG);
    fr.omega[2] = 0;
    UNTOUCHED();
    /* workspace */
    assert_int_equal(CALL(&s, q, NULL, &nr, b.lw - 1, b.liw), VLBE_EWORK);
    assert_int_equal(CALL(&s, q, NULL, &nr, b.lw, b.liw - 1), VLBE_EWORK);
    UNTOUCHED();
    /* non-finite state */
    q[0] = (vlbe_real)NAN;
    assert_int_equal(CALL(&s, q, NULL, &nr, b.lw, b.liw), VLBE_ENONFINITE);
    q[0] = 0;
    lam[0] = (vlbe_real)INFINITY;
    assert_int_equal(CALL(&s, q, NULL, &nr, b.lw, b.liw), VLBE_ENONFINITE);
    lam[0] = VLBE_R(6.54);
    UNTOUCHED();
    /* callbacks: any value != 0 fails (no smaller step to retry with) */
    bad = s;
    bad.mass = bd_mass;
    bad.force = bd_force;
    bad.constr_jac = bd_cjac;
    for (bad_which = 0; bad_which < 3; ++bad_which) {
        const int rcs[2] = {-1, 1};
        int r;
        for (r = 0; r < 2; ++r) {
            bad_rc = rcs[r];
            st.callback_rc = 0;
            assert_int_equal(CALL(&bad, q, NULL, &nr, b.lw, b.liw), VLBE_ECALLBACK);
            assert_int_equal(st.callback_rc, bad_rc);
            UNTOUCHED();
        }
    }
    bad_which = 3; /* a NaN in Q */
    assert_int_equal(CALL(&bad, q, NULL, &nr, b.lw, b.liw), VLBE_ENONFINITE);
    UNTOUCHED();
    bad_which = -1;
    assert_int_equal(CALL(&bad, q, NULL, &nr, b.lw, b.liw), VLBE_OK);
    assert_int_equal(nr, 1);
#undef SENTINEL
#undef UNTOUCHED
#undef CALL
    ws_free(&b);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_smd),        cmocka_unit_test(test_pendulum),
        cmocka_unit_test(test_spring_pend), cmocka_unit_test(test_redundant),
        cmocka_unit_test(test_cantilever), cmocka_unit_test(test_pinned),
        cmocka_unit_test(test_band),       cmocka_unit_test(test_frame),
        cmocka_unit_test(test_fd),         cmocka_unit_test(test_errors),
    };
    return cmocka_run_group_tests_name("lin", tests, NULL, NULL);
}

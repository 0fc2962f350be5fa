/* test_chain_con3.c -- cmocka suite of the 3D slope constraints of the
   chains of ancf_ale.h: VLBE_ALE_CON_SLOPE_DIR in a 3D chain (r' along a
   direction, |r'| free) and VLBE_ALE_CON_SLOPE_ROT (the direction turned
   about an axis by a prescribed angle: a hub)
                                                   -- part of vlbe
                                                   SPDX-License-Identifier: MIT
   cc -std=c99 -Wall -Wextra -Wpedantic ... -O2 tests/test_chain_con3.c -lcmocka -lm
   (add -DVLBE_USE_FLOAT for the float build; the same source passes in both)

   Every tolerance says why it has its size.  Central first differences with
   the step EPS^(1/3) x (the length over which f varies) carry an error
   ~EPS^(2/3) = FD_ERR times the size of f and its derivatives; second
   differences with the step EPS^(1/4) x that length carry ~EPS^(1/2) =
   FD2_ERR (truncation h^2 f''''/12 and rounding 4 EPS f / h^2 balanced).
   Set VLBE_TEST_REPORT=1 to print the errors beside their tolerances.

   Tests
     basis                  the rows of SLOPE_DIR in 3D: C_q's two rows on the
                            slope orthonormal and across d, for axes, near-axes,
                            general, tiny (1e-30) and huge (1e30) directions, to
                            8 EPS; C = 0 on r' = s d; SLOPE_ROT at a = 0 gives
                            SLOPE_DIR's rows bit for bit, at a its rows are
                            across R(k, a) e0 (Rodrigues in double) to 8 EPS
     fd_rows                C_q vs central differences of C, C_t vs differences
                            in t, gamma vs second differences of C along
                            (q + s v, t + s), H vs differences of C_q^T lambda,
                            on a 3D chain with spin and a free p carrying POS,
                            SLOPE_ROT (law, and the chain's afun), SLOPE_DIR at
                            an interior node, SPIN
     axial_free             3D cantilever along (1, 2, 2)/3 under an axial tip
                            load F: with POS + SLOPE_DIR every node stretches to
                            the closed form lambda^3 - lambda = 2 F / EA (Green
                            strain; tip displacement ~ F L / EA); with POS +
                            SLOPE the root strain stays 0 and the tip moves less
     hub_reproduction       a radial beam on a hub turning about z: a 3D chain
                            with spin (POS + SLOPE_ROT + SPIN) and the planar
                            chain (POS + SLOPE_ANGLE), same HHT steps: in-plane
                            positions and slopes agree to rounding, z, z',
                            theta stay 0
     bad_inputs             zero direction, zero axis, non-finite values, a
                            planar chain: VLBE_EARG / VLBE_ENONFINITE from
                            vlbe_ale_chain_add and layout, chain unchanged; an
                            axis along e0 is accepted (the direction stays) */
#include "test_util.h"
#include "../ancf_ale.h"
#include "ale_fixtures.h"
#include "../integrators.h"

#include <stdlib.h>
#include <string.h>

#define EPS ((double)VLBE_EPS)
#define FD_ERR (EPS / cbrt(EPS)) /* EPS^(2/3) */
#define FD2_ERR sqrt(EPS)        /* EPS^(1/2) */

#define NN_MAX 8
#define NC_MAX 8
#define N_MAX 64
#define M_MAX 16

typedef struct c3 {
    vlbe_ale3_mat mat;
    vlbe_ale3_elem el;
    vlbe_ale_node node[NN_MAX];
    vlbe_ale_con con[NC_MAX];
    vlbe_ale_chain ch;
    vlbe_dae sys;
} c3;

/* nn nodes with fixed p = Le i; the chain, no constraint yet */
static void c3_init(c3 *c, const vlbe_ale3_mat *m, unsigned flags, int nn, double Le)
{
    int i;
    memset(c, 0, sizeof *c);
    c->mat = *m;
    assert_int_equal(vlbe_ale3_elem_init(&c->el, &c->mat, flags, 0, 0), VLBE_OK);
    for (i = 0; i < nn; ++i) c->node[i] = node_make(VLBE_ALE_PFIXED, Le * i);
    assert_int_equal(vlbe_ale_chain_init3(&c->ch, &c->el, c->node, nn, NN_MAX, c->con, NC_MAX),
                     VLBE_OK);
}

static void c3_add(c3 *c, vlbe_ale_con k) { assert_int_equal(vlbe_ale_chain_add(&c->ch, &k), VLBE_OK); }

static void c3_wire(c3 *c)
{
    assert_int_equal(vlbe_ale_chain_layout(&c->ch), VLBE_OK);
    assert_true(c->ch.n <= N_MAX && c->ch.m <= M_MAX);
    assert_int_equal(vlbe_ale_chain_dae(&c->ch, &c->sys), VLBE_OK);
}

/* Rodrigues in double: y = R(k, a) x, k unit */
static void rot_d(const double *k, double a, const double *x, double *y)
{
    const double ca = cos(a), sa = sin(a), kx = k[0] * x[0] + k[1] * x[1] + k[2] * x[2];
    const double cr[3] = {k[1] * x[2] - k[2] * x[1], k[2] * x[0] - k[0] * x[2],
                          k[0] * x[1] - k[1] * x[0]};
    int i;
    for (i = 0; i < 3; ++i) y[i] = x[i] * ca + cr[i] * sa + k[i] * kx * (1.0 - ca);
}

static void unit_d(const double *x, double *u)
{
    const double n = sqrt(x[0] * x[0] + x[1] * x[1] + x[2] * x[2]);
    int i;
    for (i = 0; i < 3; ++i) u[i] = x[i] / n;
}

/* ======================================================================= */
/* 1. the rows                                                               */
/* ======================================================================= */

static vlbe_real bs_Cq[M_MAX * N_MAX];

/* C_q's rows of the one constraint of c (m = 2) on node 0's slope: B[6] */
static void slope_rows(c3 *c, vlbe_real t, const vlbe_real *q, double *B)
{
    const int n = c->ch.n, s = c->node[0].ofs + 3;
    int j, i;
    assert_int_equal(c->ch.m, 2);
    assert_int_equal(vlbe_ale_chain_constr_jac(&c->ch, t, q, bs_Cq, NULL), 0);
    for (j = 0; j < 2; ++j)
        for (i = 0; i < 3; ++i) B[3 * j + i] = (double)bs_Cq[j * n + s + i];
}

/* orthonormal rows across u (unit): worst deviation */
static double rows_dev(const double *B, const double *u)
{
    double w = 0.0;
    int j, l;
    for (j = 0; j < 2; ++j) {
        const double *b = B + 3 * j;
        w = fmax(w, fabs(b[0] * u[0] + b[1] * u[1] + b[2] * u[2]));
        for (l = 0; l < 2; ++l) {
            const double *b2 = B + 3 * l;
            w = fmax(w, fabs(b[0] * b2[0] + b[1] * b2[1] + b[2] * b2[2] - (j == l ? 1.0 : 0.0)));
        }
    }
    return w;
}

/* Tolerance 8 EPS: a unit vector, its projection and a cross product, each
   a few roundings of O(1) numbers (the pair is built from the least
   aligned axis, |e_c - u_c u|^2 >= 2/3: no cancellation). */
static void test_basis(void **state)
{
    static const double dirs[][3] = {
        {1, 0, 0}, {0, 1, 0}, {0, 0, -1}, {1, 1e-9, 0}, {1e-9, -1, 1e-9}, {1, 2, 2},
        {-0.3, 0.5, 0.81}, {1, 1, 1}, {3e-30, 4e-30, 0}, {3e30, 0, -4e30}, {0.7, -0.7, 0.1}};
    static c3 c;
    const vlbe_ale3_mat m = mat3_std();
    const double tol = 8.0 * EPS, k0[3] = {0.3, -0.8, 0.5};
    double worst = 0.0, wrot = 0.0;
    int k, i;
    (void)state;
    for (k = 0; k < (int)(sizeof dirs / sizeof dirs[0]); ++k) {
        vlbe_real q[N_MAX], C[M_MAX];
        double u[3], B[6], Br[6], kk[3], e[3];
        int s;
        unit_d(dirs[k], u);
        c3_init(&c, &m, 0u, 2, 1.0);
        c3_add(&c, con_make(VLBE_ALE_CON_SLOPE_DIR, 0, 0, 0, dirs[k][0], dirs[k][1], dirs[k][2]));
        c3_wire(&c);
        for (i = 0; i < c.ch.n; ++i) q[i] = VLBE_R(0.0);
        s = c.node[0].ofs + 3;
        for (i = 0; i < 3; ++i) q[s + i] = (vlbe_real)(1.07 * u[i]);
        slope_rows(&c, VLBE_R(0.0), q, B);
        worst = fmax(worst, rows_dev(B, u));
        ASSERT_CLOSE(rows_dev(B, u), 0.0, 0, tol);
        /* r' along d: C = 0 to the rounding of r' (1.07 u rounded) */
        assert_int_equal(vlbe_ale_chain_constr(&c.ch, VLBE_R(0.0), q, C), 0);
        ASSERT_CLOSE((double)C[0], 0.0, 0, tol);
        ASSERT_CLOSE((double)C[1], 0.0, 0, tol);
        /* the rotating form: e0 = d, axis k0, a = 0 (bitwise) and a = 1.1 */
        c3_init(&c, &m, 0u, 2, 1.0);
        c3_add(&c, con_rot(0, dirs[k], k0, 0.0, 0.0, 0.0));
        c3_wire(&c);
        slope_rows(&c, VLBE_R(0.0), q, Br);
        for (i = 0; i < 6; ++i) assert_true(Br[i] == B[i]);
        c.con[0].law[0] = VLBE_R(1.1);
        slope_rows(&c, VLBE_R(0.0), q, Br);
        unit_d(k0, kk);
        rot_d(kk, (double)VLBE_R(1.1), u, e);
        wrot = fmax(wrot, rows_dev(Br, e));
        ASSERT_CLOSE(rows_dev(Br, e), 0.0, 0, tol);
    }
    tu_report("SLOPE_DIR 3D rows: orthonormal, across d", worst, tol);
    tu_report("SLOPE_ROT rows across R(k, a) e0", wrot, tol);
}

/* ======================================================================= */
/* 2. derivatives of the rows                                                */
/* ======================================================================= */

/* a(t) of the afun variant: a hub angle with a wobble */
static int afun_hub(void *user, int con, vlbe_real t, vlbe_real *a3)
{
    const double tt = (double)t;
    (void)user;
    (void)con;
    a3[0] = (vlbe_real)(0.3 + 0.7 * tt + 0.2 * sin(3.0 * tt));
    a3[1] = (vlbe_real)(0.7 + 0.6 * cos(3.0 * tt));
    a3[2] = (vlbe_real)(-1.8 * sin(3.0 * tt));
    return 0;
}

/* 5 nodes, p every 0.3, node 2 free in p: POS + SLOPE_ROT + SPIN at node 0,
   SLOPE_DIR at node 2 and node 4 */
static void fd_chain(c3 *c, int use_afun)
{
    static const double e0[3] = {0.9, 0.3, -0.2}, k[3] = {0.2, 0.5, 0.8};
    const vlbe_ale3_mat m = mat3_std();
    c3_init(c, &m, 0u, 5, 0.3);
    c->node[2].pmode = VLBE_ALE_PFREE;
    if (use_afun) c->ch.afun = afun_hub;
    c3_add(c, con_make(VLBE_ALE_CON_POS, 0, 0, 0, 0.1, -0.2, 0.05));
    c3_add(c, con_rot(0, e0, k, 0.4, -1.3, 2.1));
    c3_add(c, con_make(VLBE_ALE_CON_SPIN, 0, 0, 0, 0.0, 0.5, 0.0));
    c3_add(c, con_make(VLBE_ALE_CON_SLOPE_DIR, 2, 0, 0, 0.8, 0.5, 0.3));
    c3_add(c, con_make(VLBE_ALE_CON_SLOPE_DIR, 4, 0, 0, 0.0, -2.0, 1.0));
    c3_wire(c);
}

typedef struct fd3 {
    c3 *c;
    int which, j;
    vlbe_real t;
    const vlbe_real *q, *v, *lam;
} fd3;

enum { F_C_OF_Q, F_C_OF_T, F_C_OF_S, F_CTL_OF_Q };

static vlbe_real fd_Cq[M_MAX * N_MAX];

static double fd3_fn(void *vc, double x, double *out)
{
    const fd3 *f = (const fd3 *)vc;
    vlbe_ale_chain *ch = &f->c->ch;
    const int n = ch->n, m = ch->m;
    const vlbe_real xr = (vlbe_real)x;
    vlbe_real q[N_MAX], C[M_MAX], t = f->t;
    int i, k;
    memcpy(q, f->q, (size_t)n * sizeof *q);
    if (f->which == F_C_OF_Q || f->which == F_CTL_OF_Q) q[f->j] = xr;
    else if (f->which == F_C_OF_T) t = xr;
    else {
        for (i = 0; i < n; ++i) q[i] = f->q[i] + xr * f->v[i];
        t = f->t + xr;
    }
    if (f->which == F_CTL_OF_Q) {
        assert_int_equal(vlbe_ale_chain_constr_jac(ch, t, q, fd_Cq, NULL), 0);
        for (k = 0; k < n; ++k) {
            out[k] = 0.0;
            for (i = 0; i < m; ++i) out[k] += (double)fd_Cq[i * n + k] * (double)f->lam[i];
        }
    } else {
        assert_int_equal(vlbe_ale_chain_constr(ch, t, q, C), 0);
        for (i = 0; i < m; ++i) out[i] = (double)C[i];
    }
    return (double)xr;
}

/* J (rows x ncol, column j = d f / d x_j) vs central differences; column j
   held to tol (max |column| + max |f|) as in test_chain_ale.c.  Returns the
   worst error over that scale. */
static double fd3_cols(fd3 *f, int which, int rows, int ncol, const vlbe_real *J, double tol,
                       const char *what)
{
    double d[N_MAX], work[N_MAX], f0[N_MAX], worst = 0.0, fs;
    int i, j;
    f->which = which;
    f->j = 0;
    fd3_fn(f, which == F_C_OF_T ? (double)f->t : (double)f->q[0], f0);
    fs = tu_max_abs(rows, f0);
    for (j = 0; j < ncol; ++j) {
        const double x = which == F_C_OF_T ? (double)f->t : (double)f->q[j];
        double cs = 0.0;
        f->j = j;
        tu_central_diff(fd3_fn, f, x, tu_fd_step(EPS, fmax(1.0, fabs(x))), rows, work, d);
        for (i = 0; i < rows; ++i) cs = fmax(cs, fmax(fabs(d[i]), fabs((double)J[i * ncol + j])));
        for (i = 0; i < rows; ++i) {
            const double a = (double)J[i * ncol + j], scale = cs + fs;
            worst = fmax(worst, fabs(a - d[i]) / scale);
            ASSERT_CLOSE_CTX(a, d[i], 0, tol * scale, "%s: entry (%d, %d)", what, i, j);
        }
    }
    return worst;
}

/* Tolerances: first differences 16 FD_ERR of the column scale (the rows
   are trigonometric in t with a' ~ 1.3 + 2.1 t, a'' ~ 2: third derivatives
   a few times the entries); gamma against the central second difference
   (C(s = h) - 2 C(0) + C(-h)) / h^2 at h = EPS^(1/4): 16 FD2_ERR of
   (max |C''| + max |C|) (its rounding 4 EPS |C| / h^2 and truncation h^2
   |C''''| / 12, both ~EPS^(1/2)). */
static void test_fd_rows(void **state)
{
    static c3 c;
    const double tol = 16.0 * FD_ERR, tol2 = 16.0 * FD2_ERR;
    double wc = 0.0, wt = 0.0, wg = 0.0, wh = 0.0;
    int variant;
    (void)state;
    for (variant = 0; variant < 2; ++variant) {
        tu_rng g = tu_rng_seed(503 + (uint64_t)variant);
        vlbe_real q[N_MAX], v[N_MAX], lam[M_MAX], Ct[M_MAX], gam[M_MAX], C0[M_MAX];
        static vlbe_real Cq[M_MAX * N_MAX], H[N_MAX * N_MAX];
        double cp[M_MAX], cm[M_MAX], c0[M_MAX], h, hr, sc = 0.0;
        fd3 f;
        int n, m, i;
        fd_chain(&c, variant);
        n = c.ch.n;
        m = c.ch.m;
        /* nodes 7 7 8 7 7; rows POS 3 + ROT 2 + SPIN 1 + DIR 2 + DIR 2 */
        assert_int_equal(n, 36);
        assert_int_equal(m, 10);
        for (i = 0; i < 5; ++i) {
            const int o = c.node[i].ofs;
            int k;
            for (k = 0; k < 3; ++k) {
                q[o + k] = (vlbe_real)(0.3 * i * (k == 0 ? 0.9 : 0.3) + 0.05 * tu_rng_uniform(&g));
                q[o + 3 + k] = (vlbe_real)((k == 0 ? 1.0 : 0.3) + 0.2 * tu_rng_uniform(&g));
            }
            q[o + 6] = (vlbe_real)(0.5 * tu_rng_uniform(&g));
            if (c.node[i].pmode == VLBE_ALE_PFREE) q[o + 7] = (vlbe_real)(0.6 + 0.02 * tu_rng_uniform(&g));
        }
        for (i = 0; i < n; ++i) v[i] = (vlbe_real)tu_rng_uniform(&g);
        for (i = 0; i < m; ++i) lam[i] = (vlbe_real)tu_rng_uniform(&g);
        f.c = &c;
        f.t = VLBE_R(0.4);
        f.q = q;
        f.v = v;
        f.lam = lam;
        assert_int_equal(vlbe_ale_chain_constr_jac(&c.ch, f.t, q, Cq, Ct), 0);
        assert_int_equal(vlbe_ale_chain_constr_acc(&c.ch, f.t, q, v, gam), 0);
        assert_int_equal(vlbe_ale_chain_constr_hess(&c.ch, f.t, q, lam, H), 0);
        wc = fmax(wc, fd3_cols(&f, F_C_OF_Q, m, n, Cq, tol, "C_q"));
        wt = fmax(wt, fd3_cols(&f, F_C_OF_T, m, 1, Ct, tol, "C_t"));
        wh = fmax(wh, fd3_cols(&f, F_CTL_OF_Q, n, n, H, tol, "d(C_q^T lambda)/dq"));
        /* gamma: -d^2 C / ds^2 along (q + s v, t + s) */
        f.which = F_C_OF_S;
        h = sqrt(sqrt(EPS));
        hr = fd3_fn(&f, h, cp);
        (void)fd3_fn(&f, -hr, cm);
        (void)fd3_fn(&f, 0.0, c0);
        assert_int_equal(vlbe_ale_chain_constr(&c.ch, f.t, q, C0), 0);
        for (i = 0; i < m; ++i) {
            const double d2 = (cp[i] - 2.0 * c0[i] + cm[i]) / (hr * hr);
            sc = fmax(sc, fmax(fabs(d2), fabs(c0[i])));
        }
        for (i = 0; i < m; ++i) {
            const double d2 = (cp[i] - 2.0 * c0[i] + cm[i]) / (hr * hr);
            wg = fmax(wg, fabs(-(double)gam[i] - d2) / sc);
            ASSERT_CLOSE_CTX(-(double)gam[i], d2, 0, tol2 * sc, "gamma row %d", i);
        }
    }
    tu_report("C_q vs differences of C, worst / column scale", wc, tol);
    tu_report("C_t vs differences in t", wt, tol);
    tu_report("H vs differences of C_q^T lambda", wh, tol);
    tu_report("gamma vs second differences along (v, 1)", wg, tol2);
}

/* ======================================================================= */
/* 3. the axial strain at a clamp                                            */
/* ======================================================================= */

/* the tip load: the chain's Q plus F dir at the last node */
typedef struct tipload {
    vlbe_ale_chain *ch;
    vlbe_real F[3];
} tipload;

static int tip_force(void *user, vlbe_real t, const vlbe_real *q, const vlbe_real *v,
                     vlbe_real *Q)
{
    tipload *tl = (tipload *)user;
    const int rc = vlbe_ale_chain_force(tl->ch, t, q, v, Q), o = tl->ch->node[tl->ch->nn - 1].ofs;
    int k;
    for (k = 0; k < 3 && rc == 0; ++k) Q[o + k] += tl->F[k];
    return rc;
}
static int tip_force_jac(void *user, vlbe_real t, const vlbe_real *q, const vlbe_real *v,
                         vlbe_real *K, vlbe_real *D)
{
    return vlbe_ale_chain_force_jac(((tipload *)user)->ch, t, q, v, K, D);
}
static int tip_constr(void *user, vlbe_real t, const vlbe_real *q, vlbe_real *C)
{
    return vlbe_ale_chain_constr(((tipload *)user)->ch, t, q, C);
}
static int tip_constr_jac(void *user, vlbe_real t, const vlbe_real *q, vlbe_real *Cq,
                          vlbe_real *Ct)
{
    return vlbe_ale_chain_constr_jac(((tipload *)user)->ch, t, q, Cq, Ct);
}

/* Static cantilever of ne elements (L = 1) along dir, clamped at node 0
   with POS + (SLOPE_DIR or SLOPE), tip load F dir: q on return. */
static void axial_solve(c3 *c, int dir_only, double F, vlbe_real *q)
{
    static const double dr[3] = {1.0, 2.0, 2.0};
    vlbe_ale3_mat m = mat3_std();
    vlbe_static_params par;
    vlbe_real lam[M_MAX], r0[3] = {0, 0, 0}, u[3];
    vlbe_real *w;
    int *iw;
    size_t lw, liw;
    tipload tl;
    vlbe_dae sys;
    const int ne = 4;
    int k;
    m.f[0] = m.f[1] = m.f[2] = VLBE_R(0.0);
    m.EA = VLBE_R(100.0);
    c3_init(c, &m, VLBE_ALE3_NO_SPIN, ne + 1, 1.0 / ne);
    for (k = 0; k < 3; ++k) u[k] = (vlbe_real)(dr[k] / 3.0);
    c3_add(c, con_make(VLBE_ALE_CON_POS, 0, 0, 0, 0, 0, 0));
    if (dir_only) /* any length: the constraint reads the direction */
        c3_add(c, con_make(VLBE_ALE_CON_SLOPE_DIR, 0, 0, 0, dr[0], dr[1], dr[2]));
    else
        c3_add(c, con_make(VLBE_ALE_CON_SLOPE, 0, 0, 0, (double)u[0], (double)u[1], (double)u[2]));
    c3_wire(c);
    vlbe_ale_chain_straight(&c->ch, r0, u, q);
    tl.ch = &c->ch;
    for (k = 0; k < 3; ++k) tl.F[k] = (vlbe_real)F * u[k];
    sys = c->sys;
    sys.user = &tl;
    sys.force = tip_force;
    sys.force_jac = tip_force_jac;
    sys.constr = tip_constr;
    sys.constr_jac = tip_constr_jac;
    sys.mass = NULL;
    sys.mass_jac = NULL;
    sys.constr_acc = NULL;
    sys.constr_hess = NULL; /* linear constraints: H = 0 */
    vlbe_static_params_default(&par);
    lw = vlbe_static_work_len_sys(&sys);
    liw = vlbe_static_iwork_len_sys(&sys);
    w = (vlbe_real *)malloc(lw * sizeof *w);
    iw = (int *)malloc(liw * sizeof *iw);
    assert_non_null(w);
    assert_non_null(iw);
    for (k = 0; k < c->ch.m; ++k) lam[k] = VLBE_R(0.0);
    assert_int_equal(vlbe_dae_static(&sys, &par, VLBE_R(0.0), q, lam, NULL, w, lw, iw, liw),
                     VLBE_OK);
    free(w);
    free(iw);
}

/* Uniform stretch lambda (r' = lambda u) is exact for the cubic basis and
   every Gauss rule: the Green-strain axial force EA eps lambda, eps =
   (lambda^2 - 1)/2, balances F where lambda^3 - lambda = 2 F / EA (eq. 21
   of [V]; lambda - 1 = F / EA to first order).  Tolerance 32 EPS on r and
   r' (L = 1, |r'| ~ 1): the residual's rounding, EPS EA |r'|^3 per term,
   over the axial stiffness EA, summed over the 4 elements' Gauss points and
   the Newton solve (the increment test passes well inside it: Newton
   converges quadratically).  With POS + SLOPE the root strain is that of
   |d| = 1 (4 EPS) and the tip falls short of the free stretch by more than
   16 tolerances (a sixth of an element's share of the stretch, ~3e-4). */
static void test_axial_free(void **state)
{
    static c3 c;
    vlbe_real q[N_MAX], qs[N_MAX];
    const double F = 1.0, EA = 100.0, tol = 32.0 * EPS, u[3] = {1.0 / 3, 2.0 / 3, 2.0 / 3};
    double lam = 1.0 + F / EA, worst = 0.0, tip, tip_s, eps0_s, n2;
    int it, i, k;
    (void)state;
    for (it = 0; it < 50; ++it) lam -= (lam * lam * lam - lam - 2.0 * F / EA) / (3.0 * lam * lam - 1.0);
    axial_solve(&c, 1, F, q);
    for (i = 0; i < c.ch.nn; ++i) {
        const int o = c.node[i].ofs;
        const double p = (double)c.node[i].p;
        for (k = 0; k < 3; ++k) {
            worst = fmax(worst, fabs((double)q[o + k] - lam * p * u[k]));
            worst = fmax(worst, fabs((double)q[o + 3 + k] - lam * u[k]));
            ASSERT_CLOSE_CTX((double)q[o + k], lam * p * u[k], 0, tol, "r of node %d", i);
            ASSERT_CLOSE_CTX((double)q[o + 3 + k], lam * u[k], 0, tol, "r' of node %d", i);
        }
    }
    tip = 0.0;
    for (k = 0; k < 3; ++k) tip += (double)q[c.node[c.ch.nn - 1].ofs + k] * u[k];
    tu_report("POS + SLOPE_DIR: r, r' vs uniform stretch", worst, tol);
    /* POS + SLOPE: |r'(0)| = 1 held, the root strain 0 */
    axial_solve(&c, 0, F, qs);
    n2 = 0.0;
    for (k = 0; k < 3; ++k) n2 += (double)qs[3 + k] * (double)qs[3 + k];
    eps0_s = 0.5 * (n2 - 1.0);
    ASSERT_CLOSE(eps0_s, 0.0, 0, 4.0 * EPS);
    tip_s = 0.0;
    for (k = 0; k < 3; ++k) tip_s += (double)qs[c.node[c.ch.nn - 1].ofs + k] * u[k];
    if (tu_report_on())
        print_message("    tip stretch: closed form %.9g (F L / EA %.3g), SLOPE_DIR %.9g, "
                      "SLOPE %.9g (root strain %.3g, vs %.6g free)\n",
                      lam - 1.0, F / EA, tip - 1.0, tip_s - 1.0, eps0_s, 0.5 * (lam * lam - 1.0));
    /* the held root shortens the stretch by far more than the tolerance */
    assert_true(tip_s - 1.0 < (lam - 1.0) - 16.0 * tol);
}

/* ======================================================================= */
/* 4. the hub: 3D reduced to the plane                                       */
/* ======================================================================= */

typedef struct c2 {
    vlbe_ale_mat mat;
    vlbe_ale_elem el;
    vlbe_ale_node node[NN_MAX];
    vlbe_ale_con con[NC_MAX];
    vlbe_ale_chain ch;
    vlbe_dae sys;
} c2;

typedef struct hht_run {
    vlbe_hht_params par;
    vlbe_hht hs;
    vlbe_real *w;
    int *iw;
    size_t lw, liw;
} hht_run;

static void hht_begin(hht_run *h, const vlbe_dae *sys, const vlbe_real *q)
{
    vlbe_real v[N_MAX];
    int i;
    for (i = 0; i < sys->n; ++i) v[i] = VLBE_R(0.0);
    assert_int_equal(vlbe_hht_params_alpha(&h->par, VLBE_R(-0.1)), VLBE_OK);
    /* full Newton to the rounding level: both runs stop where their
       increments are rounding, not at a tolerance that their different
       roundings could cross at different iterations */
    h->par.modified = 0;
    h->par.rtol = h->par.atol = (vlbe_real)(64.0 * EPS);
    h->par.newton_max = 20;
    h->lw = vlbe_hht_work_len_sys(sys);
    h->liw = vlbe_hht_iwork_len_sys(sys);
    h->w = (vlbe_real *)malloc(h->lw * sizeof *h->w);
    h->iw = (int *)malloc(h->liw * sizeof *h->iw);
    assert_non_null(h->w);
    assert_non_null(h->iw);
    assert_int_equal(vlbe_hht_init(&h->hs, sys, &h->par, VLBE_R(0.0), q, v, h->w, h->lw, h->iw,
                                   h->liw),
                     VLBE_OK);
}

static void hht_end(hht_run *h)
{
    free(h->w);
    free(h->iw);
}

#define HUB_NE 4
#define HUB_STEPS 150

/* A radial beam (4 elements, L = 1, the O(1) materials, in-plane load f)
   on a hub turning about z by a(t) = 0.2 + 3 t^2 / 2, from rest: the 3D
   chain with spin (POS + SLOPE_ROT with e0 = x, k = z, + SPIN theta = 0:
   k.e0 = 0, the documented spin law) and the planar chain (POS +
   SLOPE_ANGLE with the same law), HHT-alpha -0.1, h = 2e-3, 150 steps,
   full Newton to 64 EPS.  In the plane the 3D element's M, Q, K, D equal
   the planar element's to rounding (test_ale3.c, planar_reproduction), its
   z, z', theta rows decouple (their couplings vanish at z = 0, theta = 0),
   and the 3D rows are the planar row (up to sign) and z' = 0, so every step
   solves the same equations: the runs differ by rounding only, which the
   dissipative scheme does not amplify.  Tolerance 64 EPS on the node
   coordinates (|r|, |r'| ~ 1) over the whole run (the Newton stop, 64 EPS,
   being the largest single difference); z, z', theta stay 0 to 64 EPS. */
static void test_hub_reproduction(void **state)
{
    static c2 p;
    static c3 s;
    const vlbe_ale_mat m2 = mat_std();
    vlbe_ale3_mat m3 = mat3_std();
    const double e0[3] = {1, 0, 0}, kz[3] = {0, 0, 1}, g0 = 0.2, g2 = 3.0, h = 2e-3;
    const double tol = 64.0 * EPS, tolz = 64.0 * EPS;
    vlbe_real q2[N_MAX], q3[N_MAX], r0[3] = {0, 0, 0}, dir[3];
    hht_run a, b;
    double worst = 0.0, wz = 0.0;
    int i, k, st;
    (void)state;
    mat3_planar(&m3, &m2);
    /* planar */
    memset(&p, 0, sizeof p);
    p.mat = m2;
    assert_int_equal(vlbe_ale_elem_init(&p.el, &p.mat, 0u, 0, 0, 0), VLBE_OK);
    for (i = 0; i <= HUB_NE; ++i) p.node[i] = node_make(VLBE_ALE_PFIXED, (double)i / HUB_NE);
    assert_int_equal(vlbe_ale_chain_init(&p.ch, &p.el, p.node, HUB_NE + 1, NN_MAX, p.con, NC_MAX),
                     VLBE_OK);
    {
        const vlbe_ale_con kp = con_make(VLBE_ALE_CON_POS, 0, 0, 0, 0, 0, 0);
        const vlbe_ale_con ka = con_make(VLBE_ALE_CON_SLOPE_ANGLE, 0, 0, 0, g0, 0, g2);
        assert_int_equal(vlbe_ale_chain_add(&p.ch, &kp), VLBE_OK);
        assert_int_equal(vlbe_ale_chain_add(&p.ch, &ka), VLBE_OK);
    }
    assert_int_equal(vlbe_ale_chain_layout(&p.ch), VLBE_OK);
    assert_int_equal(vlbe_ale_chain_dae(&p.ch, &p.sys), VLBE_OK);
    /* 3D with spin */
    c3_init(&s, &m3, 0u, HUB_NE + 1, 1.0 / HUB_NE);
    c3_add(&s, con_make(VLBE_ALE_CON_POS, 0, 0, 0, 0, 0, 0));
    c3_add(&s, con_rot(0, e0, kz, g0, 0.0, g2));
    c3_add(&s, con_make(VLBE_ALE_CON_SPIN, 0, 0, 0, 0, 0, 0));
    c3_wire(&s);
    s.sys.flags |= VLBE_DAE_MASS_CONST; /* fixed p: M constant, as the planar chain's */
    dir[0] = vlbe_cos((vlbe_real)g0);
    dir[1] = vlbe_sin((vlbe_real)g0);
    dir[2] = VLBE_R(0.0);
    vlbe_ale_chain_straight(&p.ch, r0, dir, q2);
    vlbe_ale_chain_straight(&s.ch, r0, dir, q3);
    hht_begin(&a, &p.sys, q2);
    hht_begin(&b, &s.sys, q3);
    for (st = 0; st < HUB_STEPS; ++st) {
        assert_int_equal(vlbe_hht_step(&a.hs, (vlbe_real)h), VLBE_OK);
        assert_int_equal(vlbe_hht_step(&b.hs, (vlbe_real)h), VLBE_OK);
        for (i = 0; i <= HUB_NE; ++i) {
            const vlbe_real *x2 = a.hs.q + p.node[i].ofs, *x3 = b.hs.q + s.node[i].ofs;
            for (k = 0; k < 2; ++k) {
                worst = fmax(worst, fabs((double)x2[k] - (double)x3[k]));
                worst = fmax(worst, fabs((double)x2[2 + k] - (double)x3[3 + k]));
            }
            wz = fmax(wz, fmax(fabs((double)x3[2]), fmax(fabs((double)x3[5]), fabs((double)x3[6]))));
        }
    }
    /* the beam has turned with the hub: node 0's slope along a(T), to the
       Newton tolerance that the constraint rows are solved to (x 10) */
    {
        const double aT = g0 + 0.5 * g2 * (h * HUB_STEPS) * (h * HUB_STEPS);
        const vlbe_real *sl = b.hs.q + s.node[0].ofs + 3;
        ASSERT_CLOSE(atan2((double)sl[1], (double)sl[0]), aT, 0, 10.0 * (double)b.par.rtol);
    }
    tu_report("hub: 3D vs planar, in-plane r, r' over the run", worst, tol);
    tu_report("hub: 3D z, z', theta", wz, tolz);
    ASSERT_CLOSE(worst, 0.0, 0, tol);
    ASSERT_CLOSE(wz, 0.0, 0, tolz);
    hht_end(&a);
    hht_end(&b);
}

/* ======================================================================= */
/* 5. bad inputs                                                             */
/* ======================================================================= */

/* a byte copy of the chain and its constraint array */
typedef struct snap {
    vlbe_ale_chain ch;
    vlbe_ale_con con[NC_MAX];
} snap;

static void snap_take(const c3 *c, snap *s)
{
    memcpy(&s->ch, &c->ch, sizeof s->ch);
    memcpy(s->con, c->con, sizeof s->con);
}

static void snap_check(const c3 *c, const snap *s)
{
    assert_memory_equal(&s->ch, &c->ch, sizeof s->ch);
    assert_memory_equal(s->con, c->con, sizeof s->con);
}

static void test_bad_inputs(void **state)
{
    static c3 c;
    static c2 p;
    snap s0;
    const vlbe_ale3_mat m = mat3_std();
    const double z3[3] = {0, 0, 0}, e0[3] = {0.6, 0.8, 0}, k0[3] = {0, 0, 2};
    vlbe_ale_con k;
    vlbe_real q[N_MAX], Ct[M_MAX];
    int i;
    (void)state;
    c3_init(&c, &m, 0u, 3, 0.5);
    c3_add(&c, con_make(VLBE_ALE_CON_POS, 0, 0, 0, 0, 0, 0));
    snap_take(&c, &s0);
    /* zero direction (SLOPE_DIR, SLOPE_ROT), zero axis: VLBE_EARG */
    k = con_make(VLBE_ALE_CON_SLOPE_DIR, 1, 0, 0, 0, 0, 0);
    assert_int_equal(vlbe_ale_chain_add(&c.ch, &k), VLBE_EARG);
    k = con_rot(0, z3, k0, 0, 1, 0);
    assert_int_equal(vlbe_ale_chain_add(&c.ch, &k), VLBE_EARG);
    k = con_rot(0, e0, z3, 0, 1, 0);
    assert_int_equal(vlbe_ale_chain_add(&c.ch, &k), VLBE_EARG);
    /* non-finite direction, axis, law: VLBE_ENONFINITE */
    k = con_rot(0, e0, k0, 0, 1, 0);
    k.d[1] = (vlbe_real)INFINITY;
    assert_int_equal(vlbe_ale_chain_add(&c.ch, &k), VLBE_ENONFINITE);
    k = con_rot(0, e0, k0, 0, 1, 0);
    k.axis[2] = (vlbe_real)NAN;
    assert_int_equal(vlbe_ale_chain_add(&c.ch, &k), VLBE_ENONFINITE);
    k = con_rot(0, e0, k0, 0, 1, 0);
    k.law[2] = (vlbe_real)NAN;
    assert_int_equal(vlbe_ale_chain_add(&c.ch, &k), VLBE_ENONFINITE);
    /* a node out of range */
    k = con_rot(3, e0, k0, 0, 1, 0);
    assert_int_equal(vlbe_ale_chain_add(&c.ch, &k), VLBE_EARG);
    snap_check(&c, &s0);
    /* made zero in place after add: layout refuses, nothing changes */
    c3_add(&c, con_rot(0, e0, k0, 0, 1, 0));
    assert_int_equal(vlbe_ale_chain_layout(&c.ch), VLBE_OK);
    c.con[1].axis[2] = VLBE_R(0.0);
    snap_take(&c, &s0);
    assert_int_equal(vlbe_ale_chain_layout(&c.ch), VLBE_EARG);
    snap_check(&c, &s0);
    /* an axis along e0: accepted; the slope direction stays e0 (C_t = 0
       on r' = s e0: the rows turn about e0 itself) */
    c3_init(&c, &m, 0u, 3, 0.5);
    k = con_rot(0, e0, e0, 0, 1.5, 0);
    c3_add(&c, k);
    c3_wire(&c);
    for (i = 0; i < c.ch.n; ++i) q[i] = VLBE_R(0.0);
    for (i = 0; i < 3; ++i) q[3 + i] = (vlbe_real)(1.2 * e0[i]);
    assert_int_equal(vlbe_ale_chain_constr_jac(&c.ch, VLBE_R(0.7), q, bs_Cq, Ct), 0);
    ASSERT_CLOSE((double)Ct[0], 0.0, 0, 8.0 * EPS);
    ASSERT_CLOSE((double)Ct[1], 0.0, 0, 8.0 * EPS);
    /* a planar chain: SLOPE_ROT does not exist, SLOPE_DIR needs x or y */
    memset(&p, 0, sizeof p);
    p.mat = mat_std();
    assert_int_equal(vlbe_ale_elem_init(&p.el, &p.mat, 0u, 0, 0, 0), VLBE_OK);
    for (i = 0; i < 3; ++i) p.node[i] = node_make(VLBE_ALE_PFIXED, 0.5 * i);
    assert_int_equal(vlbe_ale_chain_init(&p.ch, &p.el, p.node, 3, NN_MAX, p.con, NC_MAX), VLBE_OK);
    k = con_rot(0, e0, k0, 0, 1, 0);
    assert_int_equal(vlbe_ale_chain_add(&p.ch, &k), VLBE_EARG);
    k = con_make(VLBE_ALE_CON_SLOPE_DIR, 1, 0, 0, 0, 0, 1);
    assert_int_equal(vlbe_ale_chain_add(&p.ch, &k), VLBE_EARG);
    assert_int_equal(p.ch.ncon, 0);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_basis),
        cmocka_unit_test(test_fd_rows),
        cmocka_unit_test(test_axial_free),
        cmocka_unit_test(test_hub_reproduction),
        cmocka_unit_test(test_bad_inputs),
    };
    return cmocka_run_group_tests_name("chain_con3", tests, NULL, NULL);
}

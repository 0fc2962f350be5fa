/* test_chain_ale.c -- cmocka suite of the chain part of ancf_ale.h (chains of
   planar ALE-ANCF elements: node material-coordinate modes, sliding nodes,
   point masses, constraints, the vlbe_dae callbacks) and of scene 1
   (examples/moving_string.c)                   -- part of vlbe
                                                   SPDX-License-Identifier: MIT
   cc -std=c99 -Wall -Wextra -Wpedantic ... -O2 tests/test_chain_ale.c -lcmocka -lm
   (add -DVLBE_USE_FLOAT for the float build; the same source passes in both)

   Every tolerance says why it has its size.  Rounding-only checks use
   multiples of EPS (the machine epsilon of vlbe_real); central differences
   with the step h = EPS^(1/3) x (the length over which f varies) use
   multiples of FD_ERR = EPS^(2/3) (the truncation error h^2 f'''/6 and the
   rounding error EPS f / h, both then ~EPS^(2/3) times the size of f and of
   its derivatives): 3.7e-11 in double, 2.4e-5 in float.  Set
   VLBE_TEST_REPORT=1 to print the errors beside their tolerances and the
   numbers of the dynamic runs.

   Slow builds (-O0, AddressSanitizer, or the binary running under valgrind,
   or VLBE_TEST_QUICK=1 in the environment) run shorter variants of the two
   long tests (energy_conservation, scene1_moving_string), each saying what
   it keeps; the whole suite then takes ~0.45 s at -O2 (~23 s under
   valgrind), the full one ~2 s.

   Tests
     assembly_fd            K, D, d(Ma)/dq, C_q, C_t, gamma, d(C_q^T lambda)/dq
                            of the chain callbacks vs central differences, on a
                            chain with every node mode (fixed, prescribed by
                            formula and by pfun, free), a sliding node with a
                            point mass, every constraint type, gravity, loads,
                            damping; with and without VLBE_ALE_CONSERVATIVE
     mass_matrix            M symmetric, positive definite when curved; total
                            mass = rhoA x material length + point masses; the
                            straight chain's M has the null vector (r' dp, dp)
                            at each free node (why free p's need curvature)
     rigid_state            straight unstretched chain, at rest or translating,
                            any angle and offset: Q = 0 to rounding
     energy_conservation    pinned pendulum chain with a free interior p, BDF:
                            T + U + V constant with VLBE_ALE_CONSERVATIVE (drift
                            shrinks with rtol); the paper form's drift reported
     cantilever_static      Newton on [K C_q^T; C_q 0]: tip deflection vs
                            P L^3 / (3 EI) and the elastica's alpha^2 term
     scene1_moving_string   moving string frequency vs exact (16 or 8 elements),
                            4 elements vs exact and the paper, ex_peak_freq on a
                            synthetic three-line signal
     bad_inputs             init / add / layout argument errors (EARG, EWORK,
                            ENONFINITE); failing callbacks: ELENGTH with
                            err_elem (crossing, Lmin, prescribed node), ENONFINITE,
                            pfun failing / NaN, NaN in a free p (known bug)
     shrinking_element      a free node driven onto its neighbour by a
                            prescribed-p constraint under HHT: stops with a
                            status (ELENGTH / ESINGULAR / ENOCONV), state finite
     split_exact            vlbe_ale_split of a deformed, stretched element:
                            r, r', strain, curvature, material velocity at
                            1000 points equal the original's to rounding;
                            bad ph / element: status, outputs untouched
     chain_insert_exact     vlbe_ale_chain_insert: r, r' at 1000 points and
                            T, U, V unchanged (exact rules; bending: the
                            composite-rule energy unchanged, the Gauss
                            artefact falling with the order)
     merge_exact            removing the node between two pieces of one cubic
                            gives that cubic (1000 points, energies); insert +
                            remove round trip bitwise
     merge_error            merging two elements on a circular arc: midpoint
                            deviation = Hermite error h^4/24R^3 (1 - h^2/15R^2),
                            observed order 4; energy changes reported
     insert_remove_bad_inputs  ends, sliding node, mass, constraints,
                            EQUAL_LEN ends, bad e / ph, no capacity: status,
                            chain and outputs untouched
     length_control_unit    one call of vlbe_ale_chain_length_control: changed
                            2 (either side), 1 (at a chain end), 0; new
                            element of length Lstd; r, r' outside the merged
                            span unchanged
     length_control_run     the shrinking scene on 7 nodes: without control it
                            stops (ELENGTH), with control it runs through
                            (3 events, node count constant, elements within
                            [0.5, 1.5] Lstd up to one step of the node) */
#include "test_util.h"
#include "../ancf_ale.h"
#include "ale_fixtures.h"
#include "../integrators.h"

#include "../scenes/moving_string.h"

#include <float.h>
#include <stdlib.h>
#include <string.h>

#define EPS ((double)VLBE_EPS)
#define FD_ERR (EPS / cbrt(EPS)) /* EPS^(2/3): error unit of a central difference */

/* sizes of the chains here */
#define NN_MAX 12 /* nodes                */
#define NC_MAX 16 /* constraints (entries) */
#define N_MAX 64  /* coordinates          */
#define M_MAX 24  /* constraint equations */

/* ------------------------------------------------------------------------ */
/* helpers                                                                    */
/* ------------------------------------------------------------------------ */


/* A chain with its storage and the vlbe_dae wired to the chain callbacks. */
typedef struct chn {
    vlbe_ale_mat mat;
    vlbe_ale_elem el;
    vlbe_ale_node node[NN_MAX];
    vlbe_ale_con con[NC_MAX];
    vlbe_ale_chain ch;
    vlbe_dae sys;
} chn;

/* Element type and chain on c->node[0..nn-1] (filled by the caller); nt:
   Gauss order of the bending term (0 = default). */
static void chn_init(chn *c, int nn, unsigned flags, int nt)
{
    assert_true(nn <= NN_MAX);
    assert_int_equal(vlbe_ale_elem_init(&c->el, &c->mat, flags, 0, 0, nt), VLBE_OK);
    assert_int_equal(vlbe_ale_chain_init(&c->ch, &c->el, c->node, nn, NN_MAX, c->con, NC_MAX),
                     VLBE_OK);
}

static void chn_add(chn *c, vlbe_ale_con k) { assert_int_equal(vlbe_ale_chain_add(&c->ch, &k), VLBE_OK); }

/* Layout, then the vlbe_dae with every callback of the chain. */
static void chn_wire(chn *c)
{
    assert_int_equal(vlbe_ale_chain_layout(&c->ch), VLBE_OK);
    assert_true(c->ch.n <= N_MAX && c->ch.m <= M_MAX);
    assert_int_equal(vlbe_ale_chain_dae(&c->ch, &c->sys), VLBE_OK);
}

/* index of the free p of node i in q */
static int pidx(const chn *c, int i)
{
    const vlbe_ale_node *nd = &c->node[i];
    assert_int_equal(nd->pmode, VLBE_ALE_PFREE);
    return nd->ofs + 4 + 2 * nd->slide;
}

/* HHT-alpha -0.1 with up to `halvings` step halvings on c->sys from the
   consistent start at (t, q, v); the workspace fits any layout up to N_MAX
   coordinates and M_MAX equations, so that a run can restart in place after
   a change of layout.  hht_free releases it. */
typedef struct hht_run {
    vlbe_hht_params par;
    vlbe_hht hs;
    vlbe_real *w;
    int *iw;
    size_t lw, liw;
} hht_run;

static void hht_alloc(hht_run *h, int halvings)
{
    assert_int_equal(vlbe_hht_params_alpha(&h->par, VLBE_R(-0.1)), VLBE_OK);
    h->par.max_halvings = halvings;
    h->lw = vlbe_hht_work_len(N_MAX, M_MAX);
    h->liw = vlbe_hht_iwork_len(N_MAX, M_MAX);
    h->w = (vlbe_real *)malloc(h->lw * sizeof *h->w);
    h->iw = (int *)malloc(h->liw * sizeof *h->iw);
    assert_non_null(h->w);
    assert_non_null(h->iw);
}

static vlbe_status hht_start(hht_run *h, chn *c, vlbe_real t, const vlbe_real *q,
                             const vlbe_real *v)
{
    return vlbe_hht_init(&h->hs, &c->sys, &h->par, t, q, v, h->w, h->lw, h->iw, h->liw);
}

static void hht_free(hht_run *h)
{
    free(h->w);
    free(h->iw);
}

/* Step cap of a fixed-step loop to t_end: HHT takes the steps h it is given
   (halvings inside a step still end at t + h), so the loop runs t_end / h
   times; 4 t_end / h + 100 turns a step that stops advancing t into a
   failure instead of a hang. */
static long hht_cap(double t_end, double h) { return 4 * (long)(t_end / h) + 100; }

static void hht_cap_check(long n, long cap, double t)
{
    if (n > cap) fail_msg("step cap %ld reached at t = %.9g: the steps do not advance", cap, t);
}

/* p(t) of node 3 of the assembly chain in its pfun variant: a sine */
static int pfun_sine(void *user, int node, vlbe_real t, vlbe_real *p3)
{
    const double A = 0.05, w = 3.0, p0 = *(const double *)user, tt = (double)t;
    (void)node;
    p3[0] = (vlbe_real)(p0 + A * sin(w * tt));
    p3[1] = (vlbe_real)(A * w * cos(w * tt));
    p3[2] = (vlbe_real)(-A * w * w * sin(w * tt));
    return 0;
}

/* a(t) of the turning-slope constraint of the assembly chain in its pfun
   variant: a hub-like angle with a sine wobble */
static int afun_wobble(void *user, int con, vlbe_real t, vlbe_real *a3)
{
    const double tt = (double)t;
    (void)user;
    (void)con;
    a3[0] = (vlbe_real)(0.4 + 1.3 * tt + 0.2 * sin(2.0 * tt));
    a3[1] = (vlbe_real)(1.3 + 0.4 * cos(2.0 * tt));
    a3[2] = (vlbe_real)(-0.8 * sin(2.0 * tt));
    return 0;
}

/* ======================================================================= */
/* 1. assembly by central differences                                        */
/* ======================================================================= */

/* The chain of the assembly checks, 7 nodes, 6 elements:
     0 fixed p (0.1)                  POS, EQUAL_LEN 0..2 start
     1 free                           EQUAL_LEN 0..2 interior
     2 free, sliding, point mass 0.6  SLOPE (right), SLOPE_DIR (left),
                                      SLIDE_C, SLIDE_D, EQUAL_LEN 0..2 end
     3 prescribed: p = 0.8 + 0.3 t - 0.35 t^2 (or pfun: sine)  EQUAL_LEN 3..6 start
     4 free                           P (v = 1.0, 0.2, -0.5), EQUAL_LEN interior
     5 free                           EQUAL_LEN interior, SLOPE_ANGLE
                                      (a = 0.3 + 0.7 t - 0.45 t^2, or afun)
     6 fixed p (1.5), point mass 0.25 SLOPE_DIR, EQUAL_LEN 3..6 end
   Material with damping and a distributed load, gravity g on the masses.
   Every constraint type appears; the state need not satisfy them. */
static void assembly_chain(chn *c, unsigned mode, int use_pfun, double *pfun_p0)
{
    memset(c, 0, sizeof *c);
    c->mat = mat_std();
    nodes_mixed7(c->node);
    chn_init(c, 7, 0u, 0);
    c->ch.mode = mode;
    c->ch.g[0] = VLBE_R(0.3);
    c->ch.g[1] = VLBE_R(-1.1);
    if (use_pfun) {
        *pfun_p0 = 0.82;
        c->ch.pfun = pfun_sine;
        c->ch.afun = afun_wobble;
        c->ch.user = pfun_p0;
    }
    chn_add(c, con_make(VLBE_ALE_CON_POS, 0, 0, 0, 0.1, -0.2, 0));
    chn_add(c, con_make(VLBE_ALE_CON_SLOPE, 2, 0, 1, 1.0, 0.1, 0));
    chn_add(c, con_make(VLBE_ALE_CON_SLOPE_DIR, 6, 0, 0, 0.8, 0.6, 0));
    chn_add(c, con_make(VLBE_ALE_CON_SLOPE_DIR, 2, 0, 0, 0.6, 0.8, 0));
    chn_add(c, con_make(VLBE_ALE_CON_P, 4, 0, 0, 1.0, 0.2, -0.5));
    chn_add(c, con_make(VLBE_ALE_CON_EQUAL_LEN, 3, 6, 0, 0, 0, 0));
    chn_add(c, con_make(VLBE_ALE_CON_EQUAL_LEN, 0, 2, 0, 0, 0, 0));
    chn_add(c, con_make(VLBE_ALE_CON_SLIDE_C, 2, 0, 0, 0, 0, 0));
    chn_add(c, con_make(VLBE_ALE_CON_SLIDE_D, 2, 0, 0, 0, 0, 0));
    chn_add(c, con_make(VLBE_ALE_CON_SLOPE_ANGLE, 5, 0, 0, 0.3, 0.7, -0.9));
    chn_wire(c);
}

/* A random deformed state of a chain: nodes near a line at angle th,
   stretched by 5 %, displaced by up to 0.04; slopes turned by up to 0.35 rad
   with magnitudes within +-8 %; the right slope of a sliding node drawn
   separately; free p's moved by up to 0.03 (element lengths stay > 0.15).
   v: O(1) rates, p' up to 0.4. */
static void random_state(const chn *c, tu_rng *g, double th, vlbe_real *q, vlbe_real *v)
{
    const vlbe_ale_chain *ch = &c->ch;
    int i, k, s;
    for (i = 0; i < ch->nn; ++i) {
        const vlbe_ale_node *nd = &c->node[i];
        const double dp = (double)(nd->p - c->node[0].p);
        const int o = nd->ofs;
        q[o] = (vlbe_real)(0.2 + 1.05 * dp * cos(th) + 0.04 * tu_rng_uniform(g));
        q[o + 1] = (vlbe_real)(-0.1 + 1.05 * dp * sin(th) + 0.04 * tu_rng_uniform(g));
        for (s = 0; s <= nd->slide; ++s) {
            const double a = th + 0.35 * tu_rng_uniform(g), m = 1.05 * (1.0 + 0.08 * tu_rng_uniform(g));
            q[o + 2 + 2 * s] = (vlbe_real)(m * cos(a));
            q[o + 3 + 2 * s] = (vlbe_real)(m * sin(a));
        }
        for (k = 0; k < 4 + 2 * nd->slide; ++k) v[o + k] = (vlbe_real)tu_rng_uniform(g);
        if (nd->pmode == VLBE_ALE_PFREE) {
            q[pidx(c, i)] = (vlbe_real)((double)nd->p + 0.03 * tu_rng_uniform(g));
            v[pidx(c, i)] = (vlbe_real)(0.4 * tu_rng_uniform(g));
        }
    }
}

/* The differenced functions of the assembly check. */
enum { FD_Q_OF_Q, FD_Q_OF_V, FD_MA_OF_Q, FD_C_OF_Q, FD_C_OF_T, FD_G_OF_S, FD_CTL_OF_Q };

typedef struct fd_ctx {
    chn *c;
    int which, j;
    vlbe_real t;
    const vlbe_real *q, *v, *a, *lam;
} fd_ctx;

/* Length over which the chain functions vary, for the difference step
   EPS^(1/3) FD_LEN (see tu_fd_step): the random states below have element
   lengths ~0.25 and curvatures up to ~3, and the stiffness terms carry L^-5.
   The K check's worst error over its tolerance (0.19 (m:fd_K) with 0.125)
   is larger with 0.25 (truncation h^2 f'''/6 dominating, falling as h^2)
   and with 0.0625 (rounding EPS f / h dominating): 0.125 balances the two. */
#define FD_LEN 0.125

static vlbe_real fd_M[N_MAX * N_MAX], fd_Cq[M_MAX * N_MAX];

/* The function `which` of the argument x (q_j, v_j, t or the path parameter
   s of gamma); returns x rounded to vlbe_real (the argument really used). */
static double fd_fn(void *vc, double x, double *out)
{
    const fd_ctx *f = (const fd_ctx *)vc;
    vlbe_ale_chain *ch = &f->c->ch;
    const int n = ch->n, m = ch->m;
    const vlbe_real xr = (vlbe_real)x;
    vlbe_real q[N_MAX], v[N_MAX], buf[N_MAX], Ct[M_MAX], t = f->t;
    int i, k;
    memcpy(q, f->q, (size_t)n * sizeof *q);
    memcpy(v, f->v, (size_t)n * sizeof *v);
    switch (f->which) {
    case FD_Q_OF_V: v[f->j] = xr; break;
    case FD_C_OF_T: t = xr; break;
    case FD_G_OF_S:
        for (i = 0; i < n; ++i) q[i] = f->q[i] + xr * f->v[i];
        t = f->t + xr;
        break;
    default: q[f->j] = xr; break;
    }
    switch (f->which) {
    case FD_Q_OF_Q:
    case FD_Q_OF_V:
        assert_int_equal(vlbe_ale_chain_force(ch, t, q, v, buf), 0);
        for (i = 0; i < n; ++i) out[i] = (double)buf[i];
        break;
    case FD_MA_OF_Q:
        assert_int_equal(vlbe_ale_chain_mass(ch, t, q, v, fd_M), 0);
        for (i = 0; i < n; ++i) {
            out[i] = 0.0;
            for (k = 0; k < n; ++k) out[i] += (double)fd_M[i * n + k] * (double)f->a[k];
        }
        break;
    case FD_C_OF_Q:
    case FD_C_OF_T:
        assert_int_equal(vlbe_ale_chain_constr(ch, t, q, buf), 0);
        for (i = 0; i < m; ++i) out[i] = (double)buf[i];
        break;
    case FD_G_OF_S: /* C_q v + C_t along the motion */
        assert_int_equal(vlbe_ale_chain_constr_jac(ch, t, q, fd_Cq, Ct), 0);
        for (i = 0; i < m; ++i) {
            out[i] = (double)Ct[i];
            for (k = 0; k < n; ++k) out[i] += (double)fd_Cq[i * n + k] * (double)f->v[k];
        }
        break;
    default: /* C_q^T lambda */
        assert_int_equal(vlbe_ale_chain_constr_jac(ch, t, q, fd_Cq, NULL), 0);
        for (k = 0; k < n; ++k) {
            out[k] = 0.0;
            for (i = 0; i < m; ++i) out[k] += (double)fd_Cq[i * n + k] * (double)f->lam[i];
        }
        break;
    }
    return (double)xr;
}

/* Checks the analytic matrix J (rows x ncol, row-major, column j = d f /
   d x_j) against central differences, column by column.  The error of a
   central difference is ~FD_ERR times the size of the derivatives (its
   truncation part) and of the function itself (its rounding part, eps |f| /
   h), so column j is held to tol (max |column j| + max |f|), the column
   maximum over the analytic and the differenced entries (a wrongly zero
   column cannot pass).  ncol = 1 with which FD_C_OF_T / FD_G_OF_S checks a
   vector; sign = -1 compares -J (gamma = -dg/ds).  Returns the worst ratio
   error / (max |column| + max |f|). */
static double check_cols(fd_ctx *f, int which, int rows, int ncol, const vlbe_real *J, double sign,
                         double tol, const char *what)
{
    double d[N_MAX], work[N_MAX], f0[N_MAX], worst = 0.0, fs;
    int i, j;
    f->which = which;
    f->j = 0;
    {
        /* the function at the base point, for its size */
        const double x0 = which == FD_Q_OF_V ? (double)f->v[0]
                        : which == FD_C_OF_T ? (double)f->t
                        : which == FD_G_OF_S ? 0.0
                                             : (double)f->q[0];
        fd_fn(f, x0, f0);
        fs = tu_max_abs(rows, f0);
    }
    for (j = 0; j < ncol; ++j) {
        const double x = which == FD_Q_OF_V ? (double)f->v[j]
                       : which == FD_C_OF_T ? (double)f->t
                       : which == FD_G_OF_S ? 0.0
                                            : (double)f->q[j];
        double cs = 0.0;
        f->j = j;
        tu_central_diff(fd_fn, f, x, tu_fd_step(EPS, FD_LEN * fmax(1.0, fabs(x))), rows, work, d);
        for (i = 0; i < rows; ++i)
            cs = fmax(cs, fmax(fabs(d[i]), fabs((double)J[i * ncol + j])));
        for (i = 0; i < rows; ++i) {
            const double a = sign * (double)J[i * ncol + j], scale = cs + fs;
            worst = fmax(worst, fabs(a - d[i]) / scale);
            ASSERT_CLOSE_CTX(a, d[i], 0, tol * scale, "%s: entry (%d, %d), column max %.3g, |f| %.3g",
                             what, i, j, cs, fs);
        }
    }
    return worst;
}

static vlbe_real as_K[N_MAX * N_MAX], as_D[N_MAX * N_MAX], as_Mq[N_MAX * N_MAX],
    as_H[N_MAX * N_MAX], as_Cq[M_MAX * N_MAX];

/* Tolerance 64 FD_ERR (2.4e-9 in double, 1.5e-3 in float) on the column
   scale of check_cols.  The entries carry L^-5 and |r'|^-5 at curvatures
   ~1 and the inertia terms p'^2 N_pp: the third derivatives that set the
   truncation error are up to tens of times the entries, as in the element
   suite (same tolerance there).  Worst error / tolerance: K 0.19 (m:fd_K)
   (double) and 0.15 (m@flt:fd_K) (float), D, Mq, C_q, C_t, gamma, H at most
   0.10 (m:fd_rest). */
static void test_assembly_fd(void **state)
{
    const double tol = 64.0 * FD_ERR;
    double wk = 0, wd = 0, wm = 0, wc = 0, wt = 0, wg = 0, wh = 0, pf0 = 0.0;
    int variant;
    (void)state;
    for (variant = 0; variant < 4; ++variant) {
        static chn c;
        const unsigned mode = (variant & 1) ? VLBE_ALE_CONSERVATIVE : 0u;
        const int use_pfun = variant >= 2;
        tu_rng g = tu_rng_seed(101 + (uint64_t)variant);
        vlbe_real q[N_MAX], v[N_MAX], a[N_MAX], lam[M_MAX], Ct[M_MAX], gam[M_MAX];
        fd_ctx f;
        int n, m, i;
        assembly_chain(&c, mode, use_pfun, &pf0);
        n = c.ch.n;
        m = c.ch.m;
        /* 34 coordinates, 14 equations: (4 + 5 + 7 + 4 + 5 + 5 + 4), (2+2+1+1+1+2+1+2+1+1) */
        assert_int_equal(n, 34);
        assert_int_equal(m, 14);
        random_state(&c, &g, 0.7 + 0.4 * variant, q, v);
        for (i = 0; i < n; ++i) a[i] = (vlbe_real)(2.0 * tu_rng_uniform(&g));
        for (i = 0; i < m; ++i) lam[i] = (vlbe_real)tu_rng_uniform(&g);
        f.c = &c;
        f.t = VLBE_R(0.4);
        f.q = q;
        f.v = v;
        f.a = a;
        f.lam = lam;
        assert_int_equal(vlbe_ale_chain_force_jac(&c.ch, f.t, q, v, as_K, as_D), 0);
        assert_int_equal(vlbe_ale_chain_mass_jac(&c.ch, f.t, q, v, a, as_Mq, NULL), 0);
        assert_int_equal(vlbe_ale_chain_constr_jac(&c.ch, f.t, q, as_Cq, Ct), 0);
        assert_int_equal(vlbe_ale_chain_constr_acc(&c.ch, f.t, q, v, gam), 0);
        assert_int_equal(vlbe_ale_chain_constr_hess(&c.ch, f.t, q, lam, as_H), 0);
        assert_int_equal(c.ch.err, VLBE_OK);
        wk = fmax(wk, check_cols(&f, FD_Q_OF_Q, n, n, as_K, 1.0, tol, "K = dQ/dq"));
        wd = fmax(wd, check_cols(&f, FD_Q_OF_V, n, n, as_D, 1.0, tol, "D = dQ/dv"));
        wm = fmax(wm, check_cols(&f, FD_MA_OF_Q, n, n, as_Mq, 1.0, tol, "Mq = d(M a)/dq"));
        wc = fmax(wc, check_cols(&f, FD_C_OF_Q, m, n, as_Cq, 1.0, tol, "C_q"));
        wt = fmax(wt, check_cols(&f, FD_C_OF_T, m, 1, Ct, 1.0, tol, "C_t"));
        wg = fmax(wg, check_cols(&f, FD_G_OF_S, m, 1, gam, -1.0, tol, "gamma"));
        wh = fmax(wh, check_cols(&f, FD_CTL_OF_Q, n, n, as_H, 1.0, tol, "d(C_q^T lambda)/dq"));
    }
    tu_report("K = dQ/dq (4 variants), worst / column scale", wk, tol);
    tu_report("D = dQ/dv", wd, tol);
    tu_report("Mq = d(M a)/dq", wm, tol);
    tu_report("C_q", wc, tol);
    tu_report("C_t", wt, tol);
    tu_report("gamma = -d(C_q v + C_t)/ds along (v, 1)", wg, tol);
    tu_report("H = d(C_q^T lambda)/dq", wh, tol);
    tu_measured("fd_K", wk / tol);
    tu_measured("fd_rest", fmax(fmax(fmax(wd, wm), fmax(wc, wt)), fmax(wg, wh)) / tol);
}


/* ======================================================================= */
/* 2. mass matrix                                                            */
/* ======================================================================= */

/* Cholesky in double of the n x n matrix A (row-major); returns the
   smallest pivot d_k = l_kk^2 over max |A_ij| (<= 0: not positive definite). */
static double cholesky_min_pivot(int n, const vlbe_real *A)
{
    static double L[N_MAX * N_MAX];
    double amax = max_abs(n * n, A), dmin = HUGE_VAL;
    int i, j, k;
    for (i = 0; i < n * n; ++i) L[i] = (double)A[i];
    for (k = 0; k < n; ++k) {
        double d = L[k * n + k];
        for (j = 0; j < k; ++j) d -= L[k * n + j] * L[k * n + j];
        dmin = fmin(dmin, d / amax);
        if (!(d > 0.0)) return dmin;
        L[k * n + k] = sqrt(d);
        for (i = k + 1; i < n; ++i) {
            double s = L[i * n + k];
            for (j = 0; j < k; ++j) s -= L[i * n + j] * L[k * n + j];
            L[i * n + k] = s / L[k * n + k];
        }
    }
    return dmin;
}

/* A straight chain of nn nodes: both ends fixed in p, the rest free
   (material coordinates p[i]), on the line r0 + dir (p - p0). */
static void straight_chain(chn *c, int nn, const double *p, unsigned flags)
{
    int i;
    memset(c, 0, sizeof *c);
    c->mat = mat_std();
    for (i = 0; i < nn; ++i)
        c->node[i] = node_make(i == 0 || i == nn - 1 ? VLBE_ALE_PFIXED : VLBE_ALE_PFREE, p[i]);
    chn_init(c, nn, flags, 0);
    chn_wire(c);
}

static vlbe_real mm_M[N_MAX * N_MAX];

static void test_mass_matrix(void **state)
{
    static chn c;
    vlbe_real q[N_MAX], v[N_MAX];
    double u[N_MAX], pf0 = 0.0;
    tu_rng g = tu_rng_seed(202);
    int n, i, j, k;
    (void)state;
    assembly_chain(&c, 0u, 0, &pf0);
    n = c.ch.n;
    random_state(&c, &g, 0.3, q, v);
    assert_int_equal(vlbe_ale_chain_mass(&c.ch, VLBE_R(0.4), q, v, mm_M), 0);
    {
        /* symmetric: the element matrices are mirrored copies and the
           assembly adds them in the same order on both sides; 4 EPS of the
           largest entry allows for a reordered sum */
        const double mx = max_abs(n * n, mm_M);
        for (i = 0; i < n; ++i)
            for (j = 0; j < i; ++j)
                ASSERT_CLOSE_CTX(mm_M[i * n + j], mm_M[j * n + i], 0, 4.0 * EPS * mx, "M(%d, %d)", i, j);
    }
    {
        /* positive definite at a curved state (the free p's have inertia
           there, see below): every Cholesky pivot > 0.  The smallest, over
           max |M|, is a p-mode's; 0 would be the
           straight chain's null vectors.  3.3e-5 (m:chol_min) (double) */
        const double dmin = cholesky_min_pivot(n, mm_M);
        if (tu_report_on()) print_message("    smallest Cholesky pivot / max|M|: %.3e\n", dmin);
        tu_measured("chol_min", dmin);
        assert_true(dmin > 0.0);
    }
    /* total mass: a unit translation (positions 1, slopes 0, p' 0) moves
       every material point with unit speed, so u^T M u = rhoA (p_last -
       p_first) + point masses = 1.3 x 1.4 + 0.6 + 0.25.  The mass
       quadrature (4 points) is exact for the degree-6 integrand: rounding
       only, 64 EPS of the sum of |terms| */
    for (k = 0; k < 2; ++k) {
        const double exact = 1.3 * 1.4 + 0.6 + 0.25;
        double absum, mt;
        for (i = 0; i < n; ++i) u[i] = 0.0;
        for (i = 0; i < c.ch.nn; ++i) u[c.node[i].ofs + k] = 1.0;
        mt = quad_form(n, mm_M, u, &absum);
        ASSERT_CLOSE(mt, (double)(c.mat.rhoA * (c.node[6].p - c.node[0].p) + c.node[2].mass +
                                  c.node[6].mass),
                     0, 64.0 * EPS * absum);
        ASSERT_CLOSE(mt, exact, 0, 64.0 * EPS * absum + 4.0 * EPS * exact);
    }
    /* The straight chain: moving free node i along the line (dr_i = r' dp,
       slope rates 0, p_i' = dp) moves no material point (the cubics of both
       elements reproduce the line, only the mesh slides), so M u = 0: the
       mass matrix of a chain with free p's is singular when it is straight
       (and near-singular when the curvature is nearly continuous at the free
       nodes).  Rounding only: 64 EPS of max |M|. */
    {
        static chn s;
        static const double p[5] = {0.0, 0.3, 0.55, 0.8, 1.1};
        const double th = 0.6;
        vlbe_real r0[2], dir[2], Mu[N_MAX], ur[N_MAX];
        double bent = HUGE_VAL;
        int node;
        straight_chain(&s, 5, p, 0u);
        n = s.ch.n;
        r0[0] = VLBE_R(0.3);
        r0[1] = VLBE_R(-0.4);
        dir[0] = (vlbe_real)cos(th);
        dir[1] = (vlbe_real)sin(th);
        vlbe_ale_chain_straight(&s.ch, r0, dir, q);
        for (i = 0; i < n; ++i) v[i] = VLBE_R(0.0);
        assert_int_equal(vlbe_ale_chain_mass(&s.ch, VLBE_R(0.0), q, v, mm_M), 0);
        for (node = 1; node <= 3; ++node) {
            const double mx = max_abs(n * n, mm_M);
            double absum, tt;
            for (i = 0; i < n; ++i) u[i] = 0.0;
            u[s.node[node].ofs] = (double)dir[0];
            u[s.node[node].ofs + 1] = (double)dir[1];
            u[pidx(&s, node)] = 1.0;
            for (i = 0; i < n; ++i) ur[i] = (vlbe_real)u[i];
            vlbe_mat_vec(n, n, mm_M, ur, Mu);
            for (i = 0; i < n; ++i) ASSERT_CLOSE_CTX(Mu[i], 0.0, 0, 64.0 * EPS * mx, "node %d, row %d", node, i);
            tt = quad_form(n, mm_M, u, &absum);
            ASSERT_CLOSE(tt, 0.0, 0, 64.0 * EPS * absum);
        }
        /* bent: slopes turned by +-0.4 rad alternately (curvature jumps at
           the nodes): the same motion now moves material, u^T M u > 0, more
           than 100 times its rounding bound (at least 5.2e-3 (m:bent_ratio)
           of the sum of |terms| in double, 5.2e-3 (m@flt:bent_ratio) in
           float: 2e13 times EPS in double, ~700 times 64 EPS in float) */
        for (i = 0; i < s.ch.nn; ++i) {
            const double b = th + (i % 2 ? 0.4 : -0.4);
            q[s.node[i].ofs + 2] = (vlbe_real)cos(b);
            q[s.node[i].ofs + 3] = (vlbe_real)sin(b);
        }
        assert_int_equal(vlbe_ale_chain_mass(&s.ch, VLBE_R(0.0), q, v, mm_M), 0);
        for (node = 1; node <= 3; ++node) {
            double absum, tt;
            for (i = 0; i < n; ++i) u[i] = 0.0;
            u[s.node[node].ofs] = (double)q[s.node[node].ofs + 2];
            u[s.node[node].ofs + 1] = (double)q[s.node[node].ofs + 3];
            u[pidx(&s, node)] = 1.0;
            tt = quad_form(n, mm_M, u, &absum);
            if (tu_report_on()) print_message("    bent chain, node %d: u^T M u = %.3e (|terms| %.3e)\n", node, tt, absum);
            bent = fmin(bent, tt / absum);
            assert_true(tt > 100.0 * 64.0 * EPS * absum);
        }
        tu_measured("bent_ratio", bent);
    }
}

/* ======================================================================= */
/* 3. rigid states                                                           */
/* ======================================================================= */

/* A straight unstretched chain (free interior nodes at uneven spacing), at
   rest or translating with a constant velocity (p' = 0), at any angle
   (beyond 2 pi too) and offset, has Q = 0: no strain, no curvature, no
   strain rates, no transport inertia; no load, no gravity.  With and
   without the conservative fluxes (u = 0 at the ends).
   Tolerance: the strains vanish only to rounding: eps to ~EPS (|r'|^2 - 1),
   the curvature to ~EPS R / L^2 (r'' sums positions of size R with weights
   ~L^-2), the rates to ~EPS V / L.  The forces carry EA eps, EI kap / L^2
   (x L for the integral) and c EA eps', c EI kap' / L^2, so
   |Q| <= 16 EPS S with S = EA + EI (1 + R) / L^3 + (c_eps EA + c_kap EI / L^2) V / L,
   L = 0.25 the shortest element; max |Q| = 2.1 (m:rigid_q) EPS S (double). */
static void test_rigid_state(void **state)
{
    static const double p[5] = {0.0, 0.25, 0.55, 0.8, 1.1};
    static const double th[5] = {0.0, 0.7, 2.5, -1.3, 7.9};
    static const double off[5][2] = {{0, 0}, {1.5, -0.5}, {-3.0, 2.0}, {0.25, 3.5}, {-2.0, -2.5}};
    static chn c;
    double worst = 0.0;
    int mode, a, mv, i;
    (void)state;
    for (mode = 0; mode < 2; ++mode) {
        straight_chain(&c, 5, p, 0u); /* damping on */
        c.el.mat.f[0] = c.el.mat.f[1] = VLBE_R(0.0); /* no load */
        c.ch.mode = mode ? VLBE_ALE_CONSERVATIVE : 0u;
        for (a = 0; a < 5; ++a)
            for (mv = 0; mv < 2; ++mv) {
                const vlbe_ale_mat *mt = &c.el.mat;
                const double L = 0.25, V = mv ? 1.66 : 0.0;
                const double R = fabs(off[a][0]) + fabs(off[a][1]) + 1.1;
                const double S = (double)mt->EA + (double)mt->EI * (1.0 + R) / (L * L * L) +
                                 ((double)(mt->c_eps * mt->EA) + (double)(mt->c_kap * mt->EI) / (L * L)) * V / L;
                vlbe_real q[N_MAX], v[N_MAX], Q[N_MAX], r0[2], dir[2];
                r0[0] = (vlbe_real)off[a][0];
                r0[1] = (vlbe_real)off[a][1];
                dir[0] = (vlbe_real)cos(th[a]);
                dir[1] = (vlbe_real)sin(th[a]);
                vlbe_ale_chain_straight(&c.ch, r0, dir, q);
                for (i = 0; i < c.ch.n; ++i) v[i] = VLBE_R(0.0);
                if (mv)
                    for (i = 0; i < c.ch.nn; ++i) {
                        v[c.node[i].ofs] = VLBE_R(1.5);
                        v[c.node[i].ofs + 1] = VLBE_R(-0.7);
                    }
                assert_int_equal(vlbe_ale_chain_force(&c.ch, VLBE_R(0.0), q, v, Q), 0);
                worst = fmax(worst, max_abs(c.ch.n, Q) / (16.0 * EPS * S));
                for (i = 0; i < c.ch.n; ++i)
                    ASSERT_CLOSE_CTX(Q[i], 0.0, 0, 16.0 * EPS * S,
                                     "Q[%d], angle %g, offset %d, moving %d, mode %d", i, th[a], a, mv, mode);
            }
    }
    tu_report("rigid states: max |Q| / tolerance", worst, 1.0);
    tu_measured("rigid_q", 16 * worst);
}

/* ======================================================================= */
/* 4. energy conservation                                                    */
/* ======================================================================= */

/* A pendulum chain: 2 elements of length 0.5, node 0 pinned (POS) with p
   fixed, node 1 free in p, node 2 (free end, p fixed) carrying a point
   mass 0.2; rhoA 1, EA 100, EI 0.5, no damping, gravity 9.81 on the beam
   (distributed load) and on the mass.  Released from rest, horizontal, bent
   (nodal slopes at 0.3 sin(2.7 i + 0.4) rad: curvature jumps at node 1, so
   that M is regular and the free p moves: it travels between 0.17 and
   0.92, at speeds up to ~150, in the first second).  nt: Gauss order of
   the bending term. */
#ifndef VLBE_USE_FLOAT /* see test_energy_conservation */
typedef struct en_result {
    vlbe_status rc;
    double t, drift, Tmax, pmin, pmax;
    long steps, rejected;
} en_result;

static void energy_run(unsigned mode, int nt, double rtol, double t_end, en_result *r)
{
    static chn c;
    vlbe_real q[N_MAX], v[N_MAX], r0[2] = {0, 0}, dir[2] = {1, 0}, E[3];
    vlbe_bdf_params bp;
    vlbe_bdf bs;
    size_t lw, liw;
    vlbe_real *w;
    int *iw, i;
    double E0;
    memset(&c, 0, sizeof c);
    c.mat.rhoA = VLBE_R(1.0);
    c.mat.EA = VLBE_R(100.0);
    c.mat.EI = VLBE_R(0.5);
    c.mat.f[1] = VLBE_R(-9.81);
    c.node[0] = node_make(VLBE_ALE_PFIXED, 0.0);
    c.node[1] = node_make(VLBE_ALE_PFREE, 0.5);
    c.node[2] = node_make(VLBE_ALE_PFIXED, 1.0);
    c.node[2].mass = VLBE_R(0.2);
    chn_init(&c, 3, VLBE_ALE_NO_DAMP, nt);
    c.ch.mode = mode;
    c.ch.g[1] = VLBE_R(-9.81);
    chn_add(&c, con_make(VLBE_ALE_CON_POS, 0, 0, 0, 0, 0, 0));
    chn_wire(&c);
    vlbe_ale_chain_straight(&c.ch, r0, dir, q);
    for (i = 0; i < 3; ++i) {
        const double a = 0.3 * sin(2.7 * i + 0.4);
        q[c.node[i].ofs + 2] = (vlbe_real)cos(a);
        q[c.node[i].ofs + 3] = (vlbe_real)sin(a);
    }
    for (i = 0; i < c.ch.n; ++i) v[i] = VLBE_R(0.0);
    vlbe_bdf_params_default(&bp);
    bp.rtol = bp.atol = (vlbe_real)rtol;
    lw = vlbe_bdf_work_len(c.sys.n, c.sys.m);
    liw = vlbe_bdf_iwork_len(c.sys.n, c.sys.m);
    w = (vlbe_real *)malloc(lw * sizeof *w);
    iw = (int *)malloc(liw * sizeof *iw);
    assert_non_null(w);
    assert_non_null(iw);
    assert_int_equal(vlbe_ale_chain_energy(&c.ch, VLBE_R(0.0), q, v, E), VLBE_OK);
    E0 = (double)E[0] + (double)E[1] + (double)E[2];
    r->drift = r->Tmax = 0.0;
    r->pmin = r->pmax = 0.5;
    r->t = 0.0;
    r->steps = r->rejected = 0;
    if ((r->rc = vlbe_bdf_init(&bs, &c.sys, &bp, VLBE_R(0.0), q, v, w, lw, iw, liw)) != VLBE_OK) {
        free(w);
        free(iw);
        return;
    }
    while ((double)bs.t < t_end) {
        const double pn = (double)bs.q[pidx(&c, 1)];
        /* step cap: 1e5 steps per second of run, 4.8 times the 1e-9 run's
           count (2.1e4 steps in 1 s); more means collapsed steps */
        if ((double)bs.stats.steps >= 1e5 * t_end) {
            r->rc = VLBE_EBOUND;
            break;
        }
        if ((r->rc = vlbe_bdf_step(&bs, (vlbe_real)t_end)) != VLBE_OK) break;
        if (vlbe_ale_chain_energy(&c.ch, bs.t, bs.q, bs.v, E) != VLBE_OK) {
            r->rc = VLBE_ECALLBACK;
            break;
        }
        r->drift = fmax(r->drift, fabs((double)E[0] + (double)E[1] + (double)E[2] - E0));
        r->Tmax = fmax(r->Tmax, (double)E[0]);
        r->pmin = fmin(r->pmin, pn);
        r->pmax = fmax(r->pmax, pn);
    }
    r->t = (double)bs.t;
    r->steps = bs.stats.steps;
    r->rejected = bs.stats.rejected;
    free(w);
    free(iw);
}

static void en_print(const char *what, const en_result *r)
{
    if (tu_report_on())
        print_message("    %-34s %s at t %.3f, %ld steps (%ld rejected): max|E - E0| %.3e = "
                      "%.3e Tmax, p1 in [%.3f, %.3f]\n",
                      what, vlbe_status_str(r->rc), r->t, r->steps, r->rejected, r->drift,
                      r->drift / r->Tmax, r->pmin, r->pmax);
}
#endif

/* With VLBE_ALE_CONSERVATIVE the p-rows are the gradient of the strain
   energy (end fluxes included) and the inertia is d'Alembert's over the
   fixed material domain (the velocity field is continuous at the moving
   node), so T + U + V is conserved by the exact flow; what remains is the
   integrator's error (and rounding).  The run (double, 1 s: the pendulum
   swings from horizontal through the bottom, about half its period, and
   the first bending mode (period ~0.55 s) goes through ~2 cycles; Tmax
   6.7 (m:tmax) is the largest kinetic energy), in this run:
   - rtol = atol = 1e-9: max |E - E0| = 7.1e-7 (m:drift9_abs) =
     1.07e-7 (m:drift9) Tmax, 20975 (m:steps9) steps;
   - rtol 1e-7: 2.6e-5 (m:drift7_abs) = 3.8e-6 (m:drift7) Tmax,
     10162 (m:steps7) steps; ratio 36 (m:ratio79).
   The spread and the singular passages below come from experiments on
   this run that the suite does not repeat (60 and 20 starts, 30 s).
   Each is one draw from a spread: the error depends on the step sequence,
   and the step sequence on rounding, so a change of the library's
   rounding (the order of a sum) moves these numbers as a change of the
   start does.  Over 60 starts with the angles shifted by k 1e-13 rad
   (k = 0..59; the physics unchanged to 1e-13): at 1e-9 4.9e-8 .. 1.87e-7
   Tmax (median 7.5e-8), at 1e-7 1.6e-6 .. 1.2e-5 Tmax (median 4.5e-6),
   their ratio 12 .. 127 (median 59), leaving out two runs that pass near
   the free p's singular point (below).  The drift keeps falling with
   rtol, to 3.9e-9 Tmax at 1e-11 (median of 10 starts): the nt = 8
   quadrature mismatch (first item below) is under that, 1/20 of the
   1e-9 drift.  The bounds, from what each must tell apart:
   - drift(1e-9) <= 400 rtol Tmax = 4e-7 Tmax: 2.1 times the largest of
     the spread, and about 7 times below the drift a p-row that is not
     the energy's gradient leaves.  Such a p-row is the default bending
     Gauss order nt = 5: the flux u(p2) is the derivative of the exact
     integral of the strain energy, the p-rows that of its quadrature, so
     the two agree only as far as the bending quadrature is exact (the
     axial integrand is polynomial and exact).  Its drift levels off at
     2.8e-6 Tmax whatever rtol (2.75e-6 .. 2.98e-6 over 20 starts at 1e-9;
     4.7e-5, 1.9e-5, 2.1e-5 at rtol 1e-7, 1e-9, 1e-10), and the nt = 5
     run (fast builds) is asserted above the bound: the bound is shown to
     catch a mismatch of that size.
   - drift(1e-7) >= 10 drift(1e-9): error-per-step control at order k
     takes ~rtol^(-1/(k+1)) steps for a global error ~rtol^(k/(k+1)); here
     all but 24 steps are at order 5, so 100^(5/6) = 46 is expected (the
     steps: 2.06 times more at 1e-9, 100 / 2.06 = 49).  10 = 100^(1/2) is
     order 1's, the least any integrator error gives, while an error that
     does not depend on rtol gives ~1 (nt = 5: 2.5).
   - Near the free p's singular point: its inertia falls as the square of
     the curvature jump at the node.  In this run its effective inertia
     1 / (M^-1)_pp comes down to 5e-7 of M's largest diagonal entry (|p'|
     up to 430); in two of the 60 starts to ~1e-10 (|p'| 1e4), where the
     step collapses to ~1e-12 s through thousands of Newton failures and
     the drift reaches 1.95e-7 and 5.9e-7 Tmax; at rtol 1e-8 and 1e-10
     such a run can end in VLBE_ENOCONV (1 and 2 of 40 starts).  A
     library change that puts this run on such a passage fails here: the
     rejected steps in the report tell it from a force error.
   The paper form (mode 0) exchanges energy through the curvature jump at
   the moving node: 1.5 (m:paper_abs) = 0.22 (m:paper) Tmax after 1 s
   (0.09 .. 0.42 over 20 starts), growing; asserted only to be 1000 times
   the conservative drift (2e6 (m~:paper_ratio) times here).
   Slow builds run 0.2 s (p already covers 0.17 .. 0.70):
   8.9e-8 (m@san:drift9) Tmax (1e-9), 5.3e-6 (m@san:drift7) Tmax
   (1e-7, ratio 60 (m@san:ratio79)), paper form
   5.1e-2 (m@san:paper) Tmax (over the 60 starts 7.5e-8 .. 1.2e-7 Tmax
   and ratio 47 .. 75: no near-singular passage yet); the same bounds
   apply.  -O0, -O2, the sanitizer build and valgrind give the same
   numbers to the printed digits.
   Float: skipped.  The free p's inertia is tiny (the smallest eigenvalue of
   M over the largest is 1e-6 at the start state and falls as the square
   of the curvature jump): in float the BDF corrector does not converge at
   t = 0 (VLBE_ENOCONV after 4-6 attempts), while the same chain with
   fixed p's runs.  Energy at 1e-9 is meaningless in float anyway. */
static void test_energy_conservation(void **state)
{
#ifdef VLBE_USE_FLOAT
    (void)state;
    TU_SKIP("float: the BDF corrector does not converge at t = 0 on the free p's small "
            "inertia, and an energy drift of 1e-9 is below float resolution");
#else
    const int slow = tu_slow_run();
    const double t_end = slow ? 0.2 : 1.0;
    en_result c9, c7, pa, c5;
    (void)state;
    energy_run(VLBE_ALE_CONSERVATIVE, 8, 1e-9, t_end, &c9);
    en_print("conservative, nt 8, rtol 1e-9:", &c9);
    energy_run(VLBE_ALE_CONSERVATIVE, 8, 1e-7, t_end, &c7);
    en_print("conservative, nt 8, rtol 1e-7:", &c7);
    energy_run(0u, 8, 1e-9, t_end, &pa);
    en_print("paper form, nt 8, rtol 1e-9:", &pa);
    print_message("    energy drift over %.1f s: conservative %.2e (rtol 1e-9), %.2e (1e-7); "
                  "paper form %.2e (x Tmax)\n",
                  t_end, c9.drift / c9.Tmax, c7.drift / c7.Tmax, pa.drift / pa.Tmax);
    tu_measured("tmax", c9.Tmax);
    tu_measured("drift9_abs", c9.drift);
    tu_measured("drift9", c9.drift / c9.Tmax);
    tu_measured("steps9", (double)c9.steps);
    tu_measured("drift7_abs", c7.drift);
    tu_measured("drift7", c7.drift / c7.Tmax);
    tu_measured("steps7", (double)c7.steps);
    tu_measured("ratio79", c7.drift / c9.drift);
    tu_measured("paper_abs", pa.drift);
    tu_measured("paper", pa.drift / pa.Tmax);
    tu_measured("paper_ratio", pa.drift / c9.drift);
    if (!slow) {
        energy_run(VLBE_ALE_CONSERVATIVE, 0, 1e-9, t_end, &c5);
        en_print("conservative, nt 5, rtol 1e-9:", &c5);
        /* the bound below catches a p-row that is not the energy's gradient */
        assert_int_equal(c5.rc, VLBE_OK);
        assert_true(c5.drift > 400.0 * 1e-9 * c5.Tmax);
    }
    assert_int_equal(c9.rc, VLBE_OK);
    assert_int_equal(c7.rc, VLBE_OK);
    /* the free p really moves (the test is about the moving node) */
    assert_true(c9.pmax - c9.pmin > 0.1);
    assert_true(c9.drift <= 400.0 * 1e-9 * c9.Tmax);
    assert_true(c7.drift >= 10.0 * c9.drift);
    assert_true(pa.drift >= 1000.0 * c9.drift);
#endif
}

/* ======================================================================= */
/* 5. static cantilever                                                      */
/* ======================================================================= */

/* Lagrangian ANCF cantilever: ne elements (all p fixed), length 1, EI 1,
   clamped at node 0 (POS + SLOPE), a transverse tip load P applied through
   the point-mass mechanism (tip mass 1, ch.g = (0, -P)).  Static
   equilibrium Q(q, 0) = C_q^T lambda, C(q) = 0 by Newton on
   [K - H, -C_q^T; C_q, 0] (vlbe_lu_factor / vlbe_lu_solve), from the
   straight state, until the position increment stops falling (rounding
   floor).  Returns the tip deflection (downwards) and the iterations. */
static double cantilever_solve(double P, double EA, int ne, int *iters)
{
    static chn c;
    static vlbe_real J[(N_MAX + M_MAX) * (N_MAX + M_MAX)], K[N_MAX * N_MAX], D[N_MAX * N_MAX],
        H[N_MAX * N_MAX], Cq[M_MAX * N_MAX];
    vlbe_real q[N_MAX], v[N_MAX], lam[M_MAX], Q[N_MAX], C[M_MAX], R[N_MAX + M_MAX],
        r0[2] = {0, 0}, dir[2] = {1, 0};
    int piv[N_MAX + M_MAX], i, j, it, n, m, N;
    double prev = HUGE_VAL;
    memset(&c, 0, sizeof c);
    c.mat.rhoA = VLBE_R(1.0);
    c.mat.EA = (vlbe_real)EA;
    c.mat.EI = VLBE_R(1.0);
    for (i = 0; i <= ne; ++i) c.node[i] = node_make(VLBE_ALE_PFIXED, (double)i / ne);
    c.node[ne].mass = VLBE_R(1.0);
    chn_init(&c, ne + 1, VLBE_ALE_NO_DAMP, 0);
    c.ch.g[1] = (vlbe_real)(-P);
    chn_add(&c, con_make(VLBE_ALE_CON_POS, 0, 0, 0, 0, 0, 0));
    chn_add(&c, con_make(VLBE_ALE_CON_SLOPE, 0, 0, 0, 1, 0, 0));
    chn_wire(&c);
    n = c.ch.n;
    m = c.ch.m;
    N = n + m;
    vlbe_ale_chain_straight(&c.ch, r0, dir, q);
    for (i = 0; i < n; ++i) v[i] = VLBE_R(0.0);
    for (i = 0; i < m; ++i) lam[i] = VLBE_R(0.0);
    for (it = 1; it <= 30; ++it) {
        double dq = 0.0;
        assert_int_equal(vlbe_ale_chain_force(&c.ch, 0, q, v, Q), 0);
        assert_int_equal(vlbe_ale_chain_force_jac(&c.ch, 0, q, v, K, D), 0);
        assert_int_equal(vlbe_ale_chain_constr(&c.ch, 0, q, C), 0);
        assert_int_equal(vlbe_ale_chain_constr_jac(&c.ch, 0, q, Cq, NULL), 0);
        assert_int_equal(vlbe_ale_chain_constr_hess(&c.ch, 0, q, lam, H), 0);
        for (i = 0; i < n; ++i) {
            R[i] = -Q[i];
            for (j = 0; j < m; ++j) R[i] += Cq[j * n + i] * lam[j];
            for (j = 0; j < n; ++j) J[i * N + j] = K[i * n + j] - H[i * n + j];
            for (j = 0; j < m; ++j) J[i * N + n + j] = -Cq[j * n + i];
        }
        for (i = 0; i < m; ++i) {
            R[n + i] = C[i];
            for (j = 0; j < n; ++j) J[(n + i) * N + j] = Cq[i * n + j];
            for (j = 0; j < m; ++j) J[(n + i) * N + n + j] = VLBE_R(0.0);
        }
        /* J dx = -F with F = (Q - C_q^T lambda, C) = (-R_q, R_c): solve J dx = (R_q, -R_c) */
        for (i = 0; i < m; ++i) R[n + i] = -R[n + i];
        assert_int_equal(vlbe_lu_factor(N, J, J, piv, NULL), VLBE_OK);
        vlbe_lu_solve(N, J, piv, 1, R);
        for (i = 0; i < n; ++i) {
            q[i] += R[i];
            dq = fmax(dq, fabs((double)R[i]));
        }
        for (i = 0; i < m; ++i) lam[i] += R[n + i];
        if (dq <= 4.0 * EPS || dq >= 0.5 * prev) break; /* converged / rounding floor */
        prev = dq;
    }
    *iters = it;
    return -(double)q[c.node[ne].ofs + 1];
}

/* Cubic Hermite elements reproduce the linear Euler-Bernoulli solution (a
   cubic) exactly, so with a small load the difference from P L^3 / (3 EI)
   is the geometric nonlinearity.  Expanding the inextensible elastica
   (theta'' = -alpha cos theta, theta(0) = 0, theta'(1) = 0, alpha =
   P L^2 / EI) to third order gives
        v / L = alpha / 3 - (4 / 105) alpha^3 + O(alpha^5),
   a relative correction -(12/105) alpha^2.  The axial stretch changes this
   by ~P / EA relative (1e-8 here) and the discretization of the alpha^3
   term by a few per cent of it.
   Double, EA = 1e4, 4 elements: the relative difference from the linear
   value is -1.0400e-8 (m:cant_rel0) at v = 1e-4 L (alpha = 3e-4) and
   -1.0400e-6 (m:cant_rel1) at v = 1e-3 L: exactly alpha^2 scaling,
   1.1 (m:cant_off4) % above the elastica term (-1.0286e-8, -1.0286e-6);
   with 8 elements the coefficient is 0.2 (m:cant_off8) % off, with 2
   elements 66 (m:cant_off2) % (at v = 1e-3 L): the discretization of the
   alpha^3 term, asserted to shrink from 4 to 8 elements.  Asserted: at 1e-4 L within 2e-8
   of zero (twice the elastica term) and within 1e-9 of the elastica value;
   at 1e-3 L within 2 % of the elastica value.  The error is the geometric
   nonlinearity of the formulation, none of it from the linear (exact) part.
   Float: EA = 1e4 makes the LU's pivot test (n EPS max |A|) declare the
   iteration matrix singular (axial entries EA / L_e against bending ones
   ~12 EI / L_e^3), so EA = 100 and a larger load, v = 1e-2 L (alpha =
   0.03, elastica term -1.03e-4).  This slenderness adds its own alpha^2
   term (the stretch from the axial force P theta, against a clamp that
   holds the slope at unit length): 2.61 (m:cant_slender2) alpha^2 EI /
   (EA L^2) at v = 1e-2 L and 2.61 (m:cant_slender3) at 1e-3 L in double.
   Asserted in float:
   - independent: within 30 % of the elastica term
     (23 (m@flt:cant_flt_pct) %, the slenderness term);
   - regression pin CANT_FLT_PIN, the double build's own value of the same
     discrete problem (the double build checks that it still computes it,
     -7.93965e-5 (m:cant_flt_ref), to the pin's 6 digits): the float result
     within 16 EPS of it (relative to v: the tip y is a small coordinate,
     held to its own relative precision; the equilibrium's rounding is a few
     EPS: 6.8e-8 (m@flt:cant_flt_dev), 0.6 (m@flt:cant_flt_eps) EPS).  The
     pin makes the float check sharp; the elastica check above is the one
     that does not rest on this code's own output. */
#define CANT_FLT_PIN (-7.93965e-5) /* regression pin: see test_cantilever_static */

static void test_cantilever_static(void **state)
{
    int it;
    (void)state;
#ifndef VLBE_USE_FLOAT
    {
        const double vl[2] = {1e-4, 1e-3};
        double rel[2], off[3];
        int k;
        for (k = 0; k < 2; ++k) {
            const double P = 3.0 * vl[k], alpha = P, el = -(12.0 / 105.0) * alpha * alpha;
            const double v = cantilever_solve(P, 1e4, 4, &it);
            rel[k] = (v - vl[k]) / vl[k];
            if (tu_report_on())
                print_message("    cantilever v/L %.0e: %d iterations, (v - v_lin)/v_lin = %.4e, "
                              "elastica term %.4e\n", vl[k], it, rel[k], el);
            if (k == 0) {
                ASSERT_CLOSE(rel[k], 0.0, 0, 2e-8);
                ASSERT_CLOSE(rel[k], el, 0, 1e-9);
            } else {
                tu_report("cantilever v = 1e-3 L: |rel / elastica - 1|", fabs(rel[k] / el - 1.0),
                          0.02);
                ASSERT_CLOSE(rel[k], el, 0.02, 0);
            }
        }
        tu_measured("cant_rel0", rel[0]);
        tu_measured("cant_rel1", rel[1]);
        print_message("    cantilever tip deflection vs P L^3/(3 EI): %.3e at v = 1e-4 L, "
                      "%.3e at 1e-3 L (elastica -0.114 alpha^2)\n", rel[0], rel[1]);
        /* 2, 4, 8 elements at v = 1e-3 L: the alpha^3 term's discretization */
        for (k = 0; k < 3; ++k) {
            const int ne = 2 << k;
            const double P = 3e-3, el = -(12.0 / 105.0) * P * P;
            off[k] = 100.0 * fabs((cantilever_solve(P, 1e4, ne, &it) - 1e-3) / 1e-3 / el - 1.0);
        }
        tu_measured("cant_off2", off[0]);
        tu_measured("cant_off4", off[1]);
        tu_measured("cant_off8", off[2]);
        assert_true(off[2] < off[1]);
        /* the float problem (EA = 100) in double: the pin, and the
           slenderness coefficient at v = 1e-2 and 1e-3 L */
        for (k = 0; k < 2; ++k) {
            const double vk = k ? 1e-3 : 1e-2, P = 3.0 * vk, el = -(12.0 / 105.0) * P * P;
            const double r = (cantilever_solve(P, 100.0, 4, &it) - vk) / vk;
            const double c = (r - el) / (P * P / 100.0);
            tu_measured(k ? "cant_slender3" : "cant_slender2", c);
            if (k == 0) {
                tu_measured("cant_flt_ref", r);
                ASSERT_CLOSE(r, CANT_FLT_PIN, 0, 5e-11);
            }
        }
    }
#else
    {
        const double vl = 1e-2, P = 3.0 * vl, el = -(12.0 / 105.0) * P * P;
        const double v = cantilever_solve(P, 100.0, 4, &it), rel = (v - vl) / vl;
        if (tu_report_on())
            print_message("    cantilever (float) v/L 1e-2: %d iterations, rel %.4e, elastica %.4e\n",
                          it, rel, el);
        tu_measured("cant_flt_pct", 100 * fabs(rel / el - 1));
        tu_measured("cant_flt_dev", fabs(rel - CANT_FLT_PIN));
        tu_measured("cant_flt_eps", fabs(rel - CANT_FLT_PIN) / EPS);
        ASSERT_CLOSE(rel, el, 0.3, 0);
        ASSERT_CLOSE(rel, CANT_FLT_PIN, 0, 16.0 * EPS);
    }
#endif
}

/* ======================================================================= */
/* 6. scene 1: the axially moving string (examples/moving_string.c)          */
/* ======================================================================= */

/* ex_peak_freq on a synthetic response: a 22.69 Hz line with 30 % and 10 %
   lines at 45.4 and 68 Hz (harmonic-like, as a string response has), 0.5 s
   at dt 1e-4, the search window of the string (12..33 Hz).  The
   Blackman-Harris window's sidelobes (-92 dB) put the other lines' leakage
   low (-92 dB) at 11 bins distance, and the golden-section search stops
   at 1e-10 relative: 8.8e-8 (m:peak_rel) relative (the leakage of the 30 %
   line), held to 1e-6.
   ex_freq.h works in double whatever vlbe_real is: the same in every build. */
static void peak_freq_synthetic(void)
{
    const double PI = 3.14159265358979323846, dt = 1e-4, f0 = 22.69;
    const size_t n = 5001;
    double *y = (double *)malloc(n * sizeof *y), *w = (double *)malloc(n * sizeof *w), f;
    size_t k;
    assert_non_null(y);
    assert_non_null(w);
    for (k = 0; k < n; ++k) {
        const double t = (double)k * dt;
        y[k] = sin(2 * PI * f0 * t + 0.3) + 0.3 * sin(2 * PI * 45.4 * t + 1.0) +
               0.1 * sin(2 * PI * 68.0 * t + 2.0);
    }
    f = ex_peak_freq(y, n, dt, 12.0, 33.0, w);
    free(y);
    free(w);
    tu_report("ex_peak_freq, synthetic 3-line signal, rel. error", fabs(f - f0) / f0, 1e-6);
    tu_measured("peak_rel", fabs(f - f0) / f0);
    ASSERT_CLOSE(f, f0, 1e-6, 0);
}

/* The string's first frequency (moving string, Eulerian window, prescribed
   p(t) at every node), Richardson-extrapolated over h = 2e-4 and 1e-4
   (ms_freq), against the exact value of the prestretched moving string
   ms_f1_exact() = 22.6899099...:
   - 16 elements: 1.1e-8 (m:ms_err16) relative; held to 1e-7.  The spatial
     error falls as ~N^-5.4 (3.95e-5, 9.2e-7 for 4, 8 elements; ~2e-8
     expected at 16), and at 16 elements it meets the spread of the
     measurement itself, ~1e-8: a full Newton iteration to 1e-12, or the
     steps (1e-4, 5e-5), move it between 5e-9 and 2e-8, as have changes of
     the element code's rounding.  1e-7 is 5 times the largest of these.
   - slow builds run 8 elements instead (0.14 s at -O2 against 0.33 s):
     9.2e-7 (m@san:ms_err8), held to 2e-6.
   - 4 elements: 3.95e-5 (m:ms_err4), held to 1e-4 of exact; the paper's
     VLBE value 22.6786 is 5.4e-4 (m:ms_paper) away (held to 6e-4: our
     reading of the data, see moving_string.c, gives a prestretch 1.8e-4
     the paper leaves out).
   - 4 elements, the measurement itself: the Richardson value from steps
     (2e-4, 1e-4) equals the one from (1e-4, 5e-5) to 1e-7 relative (the
     difference is 1.4e-8 (m:ms_rich): the leftover h^4 term and the
     estimator), so the frequencies above carry no integration error at
     the 1e-5 level of the comparison with the paper.  Fast builds only
     (three more runs).
   Float: the tension comes from the Green strain (|r'|^2 - 1)/2 = 1.8e-4
   computed from slopes ~1 with absolute rounding ~FLT_EPSILON, so the
   tension, and c^2 with it, carries a relative error ~FLT_EPSILON / eps =
   6.6e-4 (the frequency error with 4 elements is 9.3e-4 (m@flt:ms_err4);
   with 16 the run fails).  The float check: 4 elements within
   4 FLT_EPSILON / eps (2.6e-3) of exact. */
static void test_scene1_moving_string(void **state)
{
    const double fx = ms_f1_exact();
    double f4, cpu = 0.0;
    (void)state;
    peak_freq_synthetic();
    f4 = ms_freq(4, 0, 2e-4, 0.5, &cpu, NULL);
    assert_true(f4 > 0.0);
#ifndef VLBE_USE_FLOAT
    {
        const int slow = tu_slow_run();
        const int ne = slow ? 8 : 16;
        const double tol = slow ? 2e-6 : 1e-7;
        const double fn = ms_freq(ne, 0, 2e-4, 0.5, NULL, NULL);
        print_message("    moving string f1: exact %.9f; 4 elements %.9f (%.2e, paper VLBE %.2e); "
                      "%d elements %.9f (%.2e)\n",
                      fx, f4, fabs(f4 - fx) / fx, fabs(f4 - MS_F1_PAPER_VLBE) / MS_F1_PAPER_VLBE, ne,
                      fn, fabs(fn - fx) / fx);
        tu_measured(slow ? "ms_err8" : "ms_err16", fabs(fn - fx) / fx);
        tu_measured("ms_err4", fabs(f4 - fx) / fx);
        tu_measured("ms_paper", fabs(f4 - MS_F1_PAPER_VLBE) / MS_F1_PAPER_VLBE);
        tu_report("moving string f1, finer chain vs exact (relative)", fabs(fn - fx) / fx, tol);
        ASSERT_CLOSE(fn, fx, tol, 0);
        ASSERT_CLOSE(f4, fx, 1e-4, 0);
        ASSERT_CLOSE(f4, MS_F1_PAPER_VLBE, 6e-4, 0);
        if (!slow) {
            const double f4h = ms_freq(4, 0, 1e-4, 0.5, NULL, NULL);
            print_message("    4 elements, Richardson (2e-4, 1e-4) vs (1e-4, 5e-5): %.2e\n",
                          fabs(f4 - f4h) / f4h);
            tu_measured("ms_rich", fabs(f4 - f4h) / f4h);
            ASSERT_CLOSE(f4, f4h, 1e-7, 0);
        }
    }
#else
    {
        double rhoA, EA, EI, eps, lam;
        ms_section(&rhoA, &EA, &EI, &eps, &lam);
        print_message("    moving string f1 (float): exact %.6f, 4 elements %.6f (%.2e)\n", fx, f4,
                      fabs(f4 - fx) / fx);
        tu_measured("ms_err4", fabs(f4 - fx) / fx);
        ASSERT_CLOSE(f4, fx, 4.0 * (double)FLT_EPSILON / eps, 0);
    }
#endif
}

/* ======================================================================= */
/* 7. bad inputs and failure statuses                                        */
/* ======================================================================= */

/* pfun that fails (returns nonzero) or returns NaN, for node 3 */
static int pfun_bad(void *user, int node, vlbe_real t, vlbe_real *p3)
{
    const int kind = *(const int *)user;
    (void)node;
    (void)t;
    p3[0] = VLBE_R(1.0);
    p3[1] = p3[2] = VLBE_R(0.0);
    if (kind == 1) return 1;
    if (kind == 2) p3[0] = (vlbe_real)NAN;
    return 0;
}

/* a(t) of a turning slope that fails (kind 1) or returns NaN (kind 2) */
static int afun_bad(void *user, int con, vlbe_real t, vlbe_real *a3)
{
    const int kind = *(const int *)user;
    (void)con;
    a3[0] = t;
    a3[1] = VLBE_R(1.0);
    a3[2] = VLBE_R(0.0);
    if (kind == 1) return 1;
    if (kind == 2) a3[1] = (vlbe_real)NAN;
    return 0;
}

/* Every callback of the chain at (t, q, v) must fail with status st at
   element (or node) `where`; ch.err is reset before each call. */
static void expect_fail(chn *c, vlbe_real t, const vlbe_real *q, const vlbe_real *v,
                        vlbe_status st, int where)
{
    static vlbe_real A[N_MAX * N_MAX], B[N_MAX * N_MAX];
    vlbe_real Q[N_MAX], a[N_MAX], E[3];
    int i, k;
    for (i = 0; i < c->ch.n; ++i) a[i] = VLBE_R(1.0);
    for (k = 0; k < 4; ++k) {
        int rc;
        c->ch.err = VLBE_OK;
        c->ch.err_elem = -1;
        switch (k) {
        case 0: rc = vlbe_ale_chain_mass(&c->ch, t, q, v, A); break;
        case 1: rc = vlbe_ale_chain_force(&c->ch, t, q, v, Q); break;
        case 2: rc = vlbe_ale_chain_force_jac(&c->ch, t, q, v, A, B); break;
        default: rc = vlbe_ale_chain_mass_jac(&c->ch, t, q, v, a, A, NULL); break;
        }
        if (rc == 0 || c->ch.err != st || c->ch.err_elem != where)
            print_message("callback %d: returned %d, err %s, err_elem %d (expected %s at %d)\n", k,
                          rc, vlbe_status_str(c->ch.err), c->ch.err_elem, vlbe_status_str(st), where);
        assert_int_not_equal(rc, 0);
        assert_int_equal(c->ch.err, st);
        assert_int_equal(c->ch.err_elem, where);
    }
    assert_int_equal(vlbe_ale_chain_energy(&c->ch, t, q, v, E), st);
}

static void test_bad_inputs(void **state)
{
    static chn c;
    vlbe_ale_node nd[4];
    vlbe_ale_con cs[2], k;
    vlbe_real q[N_MAX], v[N_MAX], r0[2] = {0, 0}, dir[2] = {1, 0};
    static const double p4[4] = {0.0, 0.3, 0.6, 1.0};
    int i, kind;
    (void)state;

    /* -- init: fewer than 2 nodes, capacity below nn, constraints without storage */
    memset(nd, 0, sizeof nd);
    memset(&c, 0, sizeof c);
    c.mat = mat_std();
    assert_int_equal(vlbe_ale_elem_init(&c.el, &c.mat, 0u, 0, 0, 0), VLBE_OK);
    assert_int_equal(vlbe_ale_chain_init(&c.ch, &c.el, nd, 1, 4, cs, 2), VLBE_EARG);
    assert_int_equal(vlbe_ale_chain_init(&c.ch, &c.el, nd, 4, 3, cs, 2), VLBE_EARG);
    assert_int_equal(vlbe_ale_chain_init(&c.ch, &c.el, nd, 4, 4, NULL, 2), VLBE_EARG);
    assert_int_equal(vlbe_ale_chain_init(&c.ch, &c.el, nd, 4, 4, cs, -1), VLBE_EARG);

    /* -- add: capacity (EWORK), bad type / node / range (EARG), NaN (ENONFINITE);
       a refused constraint is not stored */
    for (i = 0; i < 4; ++i) nd[i] = node_make(VLBE_ALE_PFREE, p4[i]);
    assert_int_equal(vlbe_ale_chain_init(&c.ch, &c.el, nd, 4, 4, cs, 2), VLBE_OK);
    k = con_make(0, 1, 0, 0, 0, 0, 0);
    assert_int_equal(vlbe_ale_chain_add(&c.ch, &k), VLBE_EARG);
    k = con_make(99, 1, 0, 0, 0, 0, 0);
    assert_int_equal(vlbe_ale_chain_add(&c.ch, &k), VLBE_EARG);
    k = con_make(VLBE_ALE_CON_POS, 4, 0, 0, 0, 0, 0);
    assert_int_equal(vlbe_ale_chain_add(&c.ch, &k), VLBE_EARG);
    k = con_make(VLBE_ALE_CON_POS, -1, 0, 0, 0, 0, 0);
    assert_int_equal(vlbe_ale_chain_add(&c.ch, &k), VLBE_EARG);
    k = con_make(VLBE_ALE_CON_EQUAL_LEN, 0, 4, 0, 0, 0, 0); /* node2 out of range */
    assert_int_equal(vlbe_ale_chain_add(&c.ch, &k), VLBE_EARG);
    k = con_make(VLBE_ALE_CON_EQUAL_LEN, 1, 2, 0, 0, 0, 0); /* no node in between */
    assert_int_equal(vlbe_ale_chain_add(&c.ch, &k), VLBE_EARG);
    k = con_make(VLBE_ALE_CON_POS, 1, 0, 0, (double)NAN, 0, 0);
    assert_int_equal(vlbe_ale_chain_add(&c.ch, &k), VLBE_ENONFINITE);
    assert_int_equal(c.ch.ncon, 0);
    k = con_make(VLBE_ALE_CON_POS, 0, 0, 0, 0, 0, 0);
    assert_int_equal(vlbe_ale_chain_add(&c.ch, &k), VLBE_OK);
    assert_int_equal(vlbe_ale_chain_add(&c.ch, &k), VLBE_OK);
    assert_int_equal(vlbe_ale_chain_add(&c.ch, &k), VLBE_EWORK);
    assert_int_equal(c.ch.ncon, 2);

    /* -- layout: constraints that do not fit the node modes (add does not
       know the modes; layout checks them), bad node data.  A refused layout
       leaves n and m as they were (0 after init). */
    for (kind = 0; kind < 9; ++kind) {
        vlbe_status want = VLBE_EARG;
        for (i = 0; i < 4; ++i) nd[i] = node_make(VLBE_ALE_PFREE, p4[i]);
        assert_int_equal(vlbe_ale_chain_init(&c.ch, &c.el, nd, 4, 4, cs, 2), VLBE_OK);
        switch (kind) {
        case 0: /* EQUAL_LEN over a fixed interior node */
            nd[2].pmode = VLBE_ALE_PFIXED;
            k = con_make(VLBE_ALE_CON_EQUAL_LEN, 0, 3, 0, 0, 0, 0);
            break;
        case 1: /* EQUAL_LEN over a prescribed interior node */
            nd[1].pmode = VLBE_ALE_PPRESCRIBED;
            k = con_make(VLBE_ALE_CON_EQUAL_LEN, 0, 3, 0, 0, 0, 0);
            break;
        case 2: k = con_make(VLBE_ALE_CON_SLIDE_C, 1, 0, 0, 0, 0, 0); break; /* not sliding */
        case 3: k = con_make(VLBE_ALE_CON_SLIDE_D, 2, 0, 0, 0, 0, 0); break; /* not sliding */
        case 4: /* P on a fixed node */
            nd[1].pmode = VLBE_ALE_PFIXED;
            k = con_make(VLBE_ALE_CON_P, 1, 0, 0, 0.3, 0, 0);
            break;
        case 5: /* P on a prescribed node */
            nd[1].pmode = VLBE_ALE_PPRESCRIBED;
            k = con_make(VLBE_ALE_CON_P, 1, 0, 0, 0.3, 0, 0);
            break;
        case 6: nd[1].mass = VLBE_R(-1.0); break;
        case 7: nd[1].pmode = 3; break;
        default:
            nd[2].p = (vlbe_real)NAN;
            want = VLBE_ENONFINITE;
            break;
        }
        if (kind <= 5) assert_int_equal(vlbe_ale_chain_add(&c.ch, &k), VLBE_OK);
        assert_int_equal(vlbe_ale_chain_layout(&c.ch), want);
        assert_int_equal(c.ch.n, 0);
        assert_int_equal(c.ch.m, 0);
    }
    /* and the same constraints on fitting nodes are accepted */
    for (i = 0; i < 4; ++i) nd[i] = node_make(VLBE_ALE_PFREE, p4[i]);
    nd[1].slide = 1;
    assert_int_equal(vlbe_ale_chain_init(&c.ch, &c.el, nd, 4, 4, cs, 2), VLBE_OK);
    k = con_make(VLBE_ALE_CON_SLIDE_C, 1, 0, 0, 0, 0, 0);
    assert_int_equal(vlbe_ale_chain_add(&c.ch, &k), VLBE_OK);
    k = con_make(VLBE_ALE_CON_EQUAL_LEN, 0, 3, 0, 0, 0, 0);
    assert_int_equal(vlbe_ale_chain_add(&c.ch, &k), VLBE_OK);
    assert_int_equal(vlbe_ale_chain_layout(&c.ch), VLBE_OK);
    assert_int_equal(c.ch.n, 4 * 5 + 2);
    assert_int_equal(c.ch.m, 2 + 2);

    /* -- failing callbacks: 0 fixed, 1 and 2 free, 3 fixed (elements 0, 1, 2) */
    memset(&c, 0, sizeof c);
    c.mat = mat_std();
    c.node[0] = node_make(VLBE_ALE_PFIXED, p4[0]);
    c.node[1] = node_make(VLBE_ALE_PFREE, p4[1]);
    c.node[2] = node_make(VLBE_ALE_PFREE, p4[2]);
    c.node[3] = node_make(VLBE_ALE_PFIXED, p4[3]);
    chn_init(&c, 4, 0u, 0);
    chn_wire(&c);
    vlbe_ale_chain_straight(&c.ch, r0, dir, q);
    for (i = 0; i < c.ch.n; ++i) v[i] = VLBE_R(0.1);
    /* node 2 moved before node 1: element 1 has L = -0.05 */
    q[pidx(&c, 2)] = VLBE_R(0.25);
    expect_fail(&c, 0, q, v, VLBE_ELENGTH, 1);
    /* node 2 on node 1: L = 0 */
    q[pidx(&c, 2)] = q[pidx(&c, 1)];
    expect_fail(&c, 0, q, v, VLBE_ELENGTH, 1);
    /* Lmin: L = 0.05 > 0 but <= Lmin = 0.1, in element 1, then in element 2 */
    c.ch.Lmin = VLBE_R(0.1);
    q[pidx(&c, 2)] = VLBE_R(0.35);
    expect_fail(&c, 0, q, v, VLBE_ELENGTH, 1);
    q[pidx(&c, 2)] = VLBE_R(0.95);
    expect_fail(&c, 0, q, v, VLBE_ELENGTH, 2);
    c.ch.Lmin = VLBE_R(0.0);
    q[pidx(&c, 2)] = VLBE_R(0.6);
    /* NaN in a position (node 1: element 0 is the first to see it), in a
       slope of node 3 (element 2), in a velocity */
    q[c.node[1].ofs] = (vlbe_real)NAN;
    expect_fail(&c, 0, q, v, VLBE_ENONFINITE, 0);
    q[c.node[1].ofs] = VLBE_R(0.3);
    q[c.node[3].ofs + 3] = (vlbe_real)INFINITY;
    expect_fail(&c, 0, q, v, VLBE_ENONFINITE, 2);
    q[c.node[3].ofs + 3] = VLBE_R(0.0);
    {
        vlbe_real Q[N_MAX];
        v[c.node[2].ofs + 1] = (vlbe_real)NAN;
        c.ch.err = VLBE_OK;
        assert_int_not_equal(vlbe_ale_chain_force(&c.ch, 0, q, v, Q), 0);
        assert_int_equal(c.ch.err, VLBE_ENONFINITE);
        assert_int_equal(c.ch.err_elem, 1);
        v[c.node[2].ofs + 1] = VLBE_R(0.1);
        /* NaN in a free p: reported as non-finite (gather checks finiteness
           before the length test, which NaN would also fail) */
        q[pidx(&c, 1)] = (vlbe_real)NAN;
        c.ch.err = VLBE_OK;
        assert_int_not_equal(vlbe_ale_chain_force(&c.ch, 0, q, v, Q), 0);
        assert_int_equal(c.ch.err, VLBE_ENONFINITE);
        assert_int_equal(c.ch.err_elem, 0);
        q[pidx(&c, 1)] = VLBE_R(0.3);
        c.ch.err = VLBE_OK;
        assert_int_equal(vlbe_ale_chain_force(&c.ch, 0, q, v, Q), 0);
        assert_int_equal(c.ch.err, VLBE_OK);
    }

    /* -- a prescribed node running into its fixed neighbour, and a failing or
       NaN pfun: 0 fixed, 1 free, 2 fixed (0.6), 3 prescribed 1.0 - 0.5 t */
    memset(&c, 0, sizeof c);
    c.mat = mat_std();
    c.node[0] = node_make(VLBE_ALE_PFIXED, p4[0]);
    c.node[1] = node_make(VLBE_ALE_PFREE, p4[1]);
    c.node[2] = node_make(VLBE_ALE_PFIXED, p4[2]);
    c.node[3] = node_make(VLBE_ALE_PPRESCRIBED, p4[3]);
    c.node[3].pd = VLBE_R(-0.5);
    chn_init(&c, 4, 0u, 0);
    chn_wire(&c);
    vlbe_ale_chain_straight(&c.ch, r0, dir, q);
    for (i = 0; i < c.ch.n; ++i) v[i] = VLBE_R(0.0);
    {
        vlbe_real Q[N_MAX];
        assert_int_equal(vlbe_ale_chain_force(&c.ch, VLBE_R(0.7), q, v, Q), 0); /* L2 = 0.05 */
    }
    expect_fail(&c, VLBE_R(0.9), q, v, VLBE_ELENGTH, 2); /* p3 = 0.55 < 0.6 */
    c.ch.pfun = pfun_bad;
    c.ch.user = &kind;
    kind = 1;
    expect_fail(&c, 0, q, v, VLBE_ECALLBACK, 2);
    kind = 2;
    expect_fail(&c, 0, q, v, VLBE_ENONFINITE, 2);

    /* -- a failing or NaN angle function of a turning slope (node 0): the
       constraint callbacks report it (err_elem -1: not an element) */
    c.ch.pfun = NULL;
    c.ch.afun = afun_bad;
    {
        const vlbe_ale_con ka = con_make(VLBE_ALE_CON_SLOPE_ANGLE, 0, 0, 0, 0, 0, 0);
        vlbe_real C[M_MAX], Ct[M_MAX], gam[M_MAX];
        static vlbe_real Cq[M_MAX * N_MAX];
        assert_int_equal(vlbe_ale_chain_add(&c.ch, &ka), VLBE_OK);
        assert_int_equal(vlbe_ale_chain_layout(&c.ch), VLBE_OK);
        for (kind = 1; kind <= 2; ++kind) {
            const vlbe_status st = kind == 1 ? VLBE_ECALLBACK : VLBE_ENONFINITE;
            c.ch.err = VLBE_OK;
            assert_int_not_equal(vlbe_ale_chain_constr(&c.ch, 0, q, C), 0);
            assert_int_equal(c.ch.err, st);
            c.ch.err = VLBE_OK;
            assert_int_not_equal(vlbe_ale_chain_constr_jac(&c.ch, 0, q, Cq, Ct), 0);
            assert_int_equal(c.ch.err, st);
            c.ch.err = VLBE_OK;
            assert_int_not_equal(vlbe_ale_chain_constr_acc(&c.ch, 0, q, v, gam), 0);
            assert_int_equal(c.ch.err, st);
        }
        kind = 0;
        assert_int_equal(vlbe_ale_chain_constr(&c.ch, 0, q, C), 0);
    }
}

/* ======================================================================= */
/* 8. stability: an element shrunk to nothing (no length control)            */
/* ======================================================================= */

/* Three nodes, two elements of length L0 = 0.5: node 0 (p fixed at 0)
   pinned at the origin, node 2 (p fixed at 1) pinned at x = 1.01 (1 %
   prestretch, tension ~1), node 1 free in p with VLBE_ALE_CON_P driving it
   onto node 0: p1(t) = 0.5 - 2 L0 t / Tc + L0 t^2 / Tc^2, so element 0 has
   L(t) = L0 (1 - t / Tc)^2, zero at Tc = 0.8 (and it would grow again
   after).  Beam (EA 100, EI 0.5, rhoA 1, no damping, no load) starting
   straight with the material at rest (node 1 moving with the mesh: x' =
   1.01 p1') plus a transverse velocity 0.1 at node 1 (a vibration, so that
   the integrator has something to do).  HHT alpha -0.1 with the fixed step
   Tc / 100 (L then falls to L0 / 100^2 one step before Tc), to 1.2 Tc.
   Returns the status, the last accepted element length and whether the
   last accepted state (q, v, q'', a, lambda) is finite. */
typedef struct shrink_result {
    vlbe_status rc;
    vlbe_status err;
    int err_elem, finite;
    double L, t;
} shrink_result;

static void shrink_run(double Lmin, int halvings, shrink_result *r)
{
    static chn c;
    const double L0 = 0.5, Tc = 0.8, h = Tc / 100.0;
    vlbe_real q[N_MAX], v[N_MAX], r0[2] = {0, 0}, dir[2] = {VLBE_R(1.01), 0};
    hht_run hr;
    const vlbe_hht *hs = &hr.hs;
    long n = 0;
    int i;
    memset(&c, 0, sizeof c);
    c.mat.rhoA = VLBE_R(1.0);
    c.mat.EA = VLBE_R(100.0);
    c.mat.EI = VLBE_R(0.5);
    c.node[0] = node_make(VLBE_ALE_PFIXED, 0.0);
    c.node[1] = node_make(VLBE_ALE_PFREE, L0);
    c.node[2] = node_make(VLBE_ALE_PFIXED, 2.0 * L0);
    chn_init(&c, 3, VLBE_ALE_NO_DAMP, 0);
    c.ch.Lmin = (vlbe_real)Lmin;
    chn_add(&c, con_make(VLBE_ALE_CON_POS, 0, 0, 0, 0, 0, 0));
    chn_add(&c, con_make(VLBE_ALE_CON_POS, 2, 0, 0, 1.01, 0, 0));
    chn_add(&c, con_make(VLBE_ALE_CON_P, 1, 0, 0, L0, -2.0 * L0 / Tc, 2.0 * L0 / (Tc * Tc)));
    chn_wire(&c);
    vlbe_ale_chain_straight(&c.ch, r0, dir, q);
    for (i = 0; i < c.ch.n; ++i) v[i] = VLBE_R(0.0);
    v[pidx(&c, 1)] = (vlbe_real)(-2.0 * L0 / Tc);
    v[c.node[1].ofs] = (vlbe_real)(1.01 * -2.0 * L0 / Tc);
    v[c.node[1].ofs + 1] = VLBE_R(0.1);
    hht_alloc(&hr, halvings);
    assert_int_equal(hht_start(&hr, &c, VLBE_R(0.0), q, v), VLBE_OK);
    c.ch.err = VLBE_OK;
    c.ch.err_elem = -1;
    r->rc = VLBE_OK;
    while ((double)hs->t < 1.2 * Tc - 0.5 * h) {
        hht_cap_check(++n, hht_cap(1.2 * Tc, h), (double)hs->t);
        if ((r->rc = vlbe_hht_step(&hr.hs, (vlbe_real)h)) != VLBE_OK) break;
    }
    r->err = c.ch.err;
    r->err_elem = c.ch.err_elem;
    r->finite = vlbe_all_finite(hs->q, 4 * c.sys.n + c.sys.m);
    r->L = (double)hs->q[pidx(&c, 1)] - 0.0;
    r->t = (double)hs->t;
    hht_free(&hr);
    if (tu_report_on())
        print_message("    shrinking element, Lmin %g, halvings %d: %s (ch.err %s, element %d) at t = %.4f, "
                      "L = %.3e L0, state finite %d\n",
                      Lmin, halvings, vlbe_status_str(r->rc), vlbe_status_str(r->err), r->err_elem,
                      r->t, r->L / L0, r->finite);
}

/* Without length control the method must stop, with a status and a finite
   last state, never run on with NaN or through L <= 0:
   (a) Lmin = 1e-4 (2e-4 L0), HHT with up to 8 step halvings: the first step
       whose element would be shorter than Lmin fails in the callback:
       VLBE_ECALLBACK with ch.err = VLBE_ELENGTH in element 0; it stops at
       L = 4e-4 (m:shrink_a) L0 (the next step would give 1e-4 L0);
   (b) Lmin = 0, the same: the iteration matrix's entries grow as L^-3
       while others stay O(1); the integrator equilibrates its rows, so
       the LU's relative pivot test need not trip, and Newton fails to
       converge (its trial iterates put p1 past p0: the callback reports
       ELENGTH and the step is halved until the halvings run out), or the
       LU still finds it singular, or L reaches 0 exactly: VLBE_ENOCONV
       (in double, at L = 1e-4 (m:shrink_b) L0), VLBE_ESINGULAR or
       VLBE_ECALLBACK + VLBE_ELENGTH; any of them with L < 1e-3 L0;
   (c) no halvings: Newton diverges well before (the short element's
       bending makes the residual ever more nonlinear while the predictor's
       error stays O(h^2)); the attempt then finishes as full Newton, which
       carries it further but not through: VLBE_ENOCONV at
       L = 1.2e-2 (m:shrink_c) L0;
       asserted only to stop with ENOCONV, ESINGULAR or ELENGTH, finite.
   The element length L is exact in every accepted state (the constraint
   holds to Newton level), so "short" is read directly on p1 - p0.
   Float: the iteration matrix's condition grows as L^-3, and at L ~ 2e-3
   L0 its solution carries errors of the order of L: a Newton iterate puts
   p1 past p0 and the callback fails with ELENGTH (in (a) and (b) at
   L = 1.6e-3 (m@flt:shrink_a) and 1.6e-3 (m@flt:shrink_b) L0); the
   callback calls that "outside the domain", so HHT
   halves the step and goes on until the LU finds the matrix singular
   (VLBE_ESINGULAR) or the halvings run out (VLBE_ECALLBACK + ELENGTH);
   "short" is then L < 1e-2 L0 and in (a) the stop need not come from Lmin
   itself. */
static void test_shrinking_element(void **state)
{
#ifndef VLBE_USE_FLOAT
    const double short_L = 1e-3 * 0.5, above = 1e-4;
#else
    const double short_L = 1e-2 * 0.5, above = 0.0;
#endif
    shrink_result r;
    (void)state;
    shrink_run(1e-4, 8, &r);
    tu_measured("shrink_a", 2 * r.L); /* L / L0 */
    assert_true(r.finite);
#ifndef VLBE_USE_FLOAT
    assert_int_equal(r.rc, VLBE_ECALLBACK);
    assert_int_equal(r.err, VLBE_ELENGTH);
    assert_int_equal(r.err_elem, 0);
#else
    assert_true(r.rc == VLBE_ESINGULAR || (r.rc == VLBE_ECALLBACK && r.err == VLBE_ELENGTH));
#endif
    assert_true(r.L > above && r.L < short_L);

    shrink_run(0.0, 8, &r);
    tu_measured("shrink_b", 2 * r.L); /* L / L0 */
    assert_true(r.finite);
    assert_true(r.rc == VLBE_ENOCONV || r.rc == VLBE_ESINGULAR ||
                (r.rc == VLBE_ECALLBACK && r.err == VLBE_ELENGTH));
    assert_true(r.L > 0.0 && r.L < short_L);

    shrink_run(0.0, 0, &r);
    tu_measured("shrink_c", 2 * r.L); /* L / L0 */
    assert_true(r.finite);
    assert_true(r.rc == VLBE_ENOCONV || r.rc == VLBE_ESINGULAR ||
                (r.rc == VLBE_ECALLBACK && r.err == VLBE_ELENGTH));
    assert_true(r.L > 0.0);
    print_message("    shrinking element without step halving: %s at L = %.2e L0\n",
                  vlbe_status_str(r.rc), r.L / 0.5);
}

/* ======================================================================= */
/* 9. exact segmentation (vlbe_ale_split, vlbe_ale_chain_insert)             */
/* ======================================================================= */

#define NPTS 1000 /* material points of the segmentation and merging checks */

/* Tolerance of the checks that must hold to rounding (segmentation, merging
   of two pieces of one cubic, length control away from the merged span),
   in units of each quantity's rounding scale S (below):
   SEG_TOL = 450 EPS = 1.0e-13 in double (5.4e-5 in float).
   Why 450: evaluating r(p) = sum_j N_j(xi) e_j rounds xi = (p - p1)/L
   (2 EPS, i.e. the point moves by 2 EPS L |r'|), the cubic basis (~10
   operations, partial sums <= 3 max |N|) and the 8-term contraction
   (8 EPS sum |N_j e_j|): at most ~30 EPS S0, S0 = max nodal |r| + L max
   nodal |r'| (the size of the data, not of the curve: a translated element
   rounds its absolute positions).  A piece's new node carries one such
   error, its own evaluation another, and the reference evaluation a third:
   <= ~100 EPS S0.  The k-th p-derivative divides O(S0) data by the piece
   length l^k: S_k = S0 / l^k; strain scale |r'| S1, curvature scale
   S2 / |r'|^2 + 3 |kap| S1 / |r'|.  450 EPS leaves a factor >= 4 over that
   worst case; the errors found (reported beside SEG_TOL with
   VLBE_TEST_REPORT) are a few EPS. */
#define SEG_TOL (450.0 * EPS)

/* max |a_i - b_i|, i < n */
static double max_diff(int n, const double *a, const double *b)
{
    double m = 0.0;
    int i;
    for (i = 0; i < n; ++i) m = fmax(m, fabs(a[i] - b[i]));
    return m;
}

/* material point k of npts spread over [pa, pb], both ends included */
static vlbe_real pt_at(double pa, double pb, int k, int npts)
{
    return k == npts - 1 ? (vlbe_real)pb : (vlbe_real)(pa + (pb - pa) * k / (npts - 1));
}

/* Material velocity N(p) q' of one element at p in [p1, p2] (eq. 14: the
   ALE matrix N = [S, dS/dp1 e, dS/dp2 e] is what vlbe_ale_point_force
   applies: Q = N^T F).  *absum = max_i sum_j |N_ij qd_j| (its rounding scale). */
static void mat_vel(const vlbe_real *q, const vlbe_real *qd, vlbe_real p, double *vel,
                    double *absum)
{
    int c, i;
    *absum = 0.0;
    for (c = 0; c < 2; ++c) {
        vlbe_real F[2] = {0, 0}, Q[10] = {0};
        double s = 0.0, a = 0.0;
        F[c] = VLBE_R(1.0);
        assert_int_equal(vlbe_ale_point_force(q, p, F, Q, NULL), VLBE_OK);
        for (i = 0; i < 10; ++i) {
            s += (double)Q[i] * (double)qd[i];
            a += fabs((double)Q[i] * (double)qd[i]);
        }
        vel[c] = s;
        *absum = fmax(*absum, a);
    }
}

/* r(p; q + x qd) of seg_q/seg_qd: the material motion through time x, for
   the difference check of the material velocity */
typedef struct mv_ctx {
    const vlbe_real *q, *qd;
    vlbe_real p;
} mv_ctx;

static double mv_fn(void *vc, double x, double *out)
{
    const mv_ctx *m = (const mv_ctx *)vc;
    const vlbe_real xr = (vlbe_real)x;
    vlbe_real qx[10], r[2];
    int i;
    for (i = 0; i < 10; ++i) qx[i] = m->q[i] + xr * m->qd[i];
    assert_int_equal(vlbe_ale_point(qx, m->p, r, NULL), VLBE_OK);
    out[0] = (double)r[0];
    out[1] = (double)r[1];
    return (double)xr;
}

/* S0 of the tolerance note: max nodal |r| + L max nodal |r'| of element q */
static double elem_scale(const vlbe_real *q)
{
    const double L = (double)(q[9] - q[4]);
    return fmax((double)vlbe_v2_norm(q), (double)vlbe_v2_norm(q + 5)) +
           L * fmax((double)vlbe_v2_norm(q + 2), (double)vlbe_v2_norm(q + 7));
}

/* A deformed, stretched element: general nodal values, slopes of lengths
   1.33 and 1.61 (not unit, not parallel; |r'| 1.22 .. 1.61 inside),
   p1 = 0.37 < p2 = 1.19 (L = 0.82), curvature -0.16 .. 1.43 (an inflexion);
   rates with p1' = 0.45, p2' = -0.3. */
static const double seg_q[10] = {0.31, -0.22, 1.2, 0.57, 0.37, 1.05, 0.48, 0.35, 1.57, 1.19};
static const double seg_qd[10] = {0.7, -0.4, 0.9, 1.3, 0.45, -0.6, 0.25, -1.1, 0.8, -0.3};

/* vlbe_ale_split at ph = p1 + 0.3 L: the pieces [p1, ph] and [ph, p2] give,
   at 1000 material points of [p1, p2] (each evaluated on the piece holding
   it), the original's position, slope, strain, curvature and material
   velocity to SEG_TOL x their scales (note above).  The material velocity
   of a piece uses its nodal rates: the original's at the old node, qhd at
   H, whose p' is 0 (H is a material point).  That N q' is the material
   velocity d/dt r(p; q + t q') at fixed p is checked by central differences
   (step EPS^(1/3): error ~FD_ERR times the size of the third time
   derivative, which with the moving p's carries powers of p'/L, a few
   times the velocity scale: held to 30 FD_ERR x the velocity scale;
   1.1 (m:split_fd) FD_ERR in double, 0.9 (m@flt:split_fd) in float).
   Bad ph (= p1, = p2, outside, NaN, +-Inf) and bad elements: the status,
   and qh, qhd untouched. */
static void test_split_exact(void **state)
{
    vlbe_real q[10], qd[10], qh[5], qhd[5], qa[10], qb[10], va[10], vb[10];
    const double tol = SEG_TOL;
    double e_r = 0.0, e_rp = 0.0, e_eps = 0.0, e_kap = 0.0, e_v = 0.0, e_fd = 0.0;
    double S0, l, rpmin = HUGE_VAL, rpmax = 0.0, kmax = 0.0, vsc = 0.0;
    vlbe_real ph;
    int i, k;
    (void)state;
    for (i = 0; i < 10; ++i) {
        q[i] = (vlbe_real)seg_q[i];
        qd[i] = (vlbe_real)seg_qd[i];
    }
    ph = (vlbe_real)(seg_q[4] + 0.3 * (seg_q[9] - seg_q[4]));
    assert_int_equal(vlbe_ale_split(q, qd, ph, qh, qhd), VLBE_OK);
    assert_true(qh[4] == ph);
    assert_true(qhd[4] == VLBE_R(0.0));
    for (i = 0; i < 5; ++i) {
        qa[i] = q[i];
        qa[5 + i] = qh[i];
        qb[i] = qh[i];
        qb[5 + i] = q[5 + i];
        va[i] = qd[i];
        va[5 + i] = qhd[i];
        vb[i] = qhd[i];
        vb[5 + i] = qd[5 + i];
    }
    S0 = fmax(elem_scale(q), fmax(elem_scale(qa), elem_scale(qb)));
    l = fmin((double)(ph - q[4]), (double)(q[9] - ph));
    /* the data: errors at every point, then compared with their scales */
    for (k = 0; k < NPTS; ++k) {
        const vlbe_real p = pt_at((double)q[4], (double)q[9], k, NPTS);
        const vlbe_real *qp = p <= ph ? qa : qb, *vp = p <= ph ? va : vb;
        vlbe_real r0[2] = {0, 0}, rp0[2] = {0, 0}, r1[2] = {0, 0}, rp1[2] = {0, 0};
        vlbe_real eps0 = 0, kap0 = 0, eps1 = 0, kap1 = 0;
        double v0[2], v1[2], s0, s1, d[2], w[2];
        mv_ctx m;
        assert_int_equal(vlbe_ale_point(q, p, r0, rp0), VLBE_OK);
        assert_int_equal(vlbe_ale_point(qp, p, r1, rp1), VLBE_OK);
        assert_int_equal(vlbe_ale_strain(q, p, &eps0, &kap0), VLBE_OK);
        assert_int_equal(vlbe_ale_strain(qp, p, &eps1, &kap1), VLBE_OK);
        mat_vel(q, qd, p, v0, &s0);
        mat_vel(qp, vp, p, v1, &s1);
        m.q = q;
        m.qd = qd;
        m.p = p;
        tu_central_diff(mv_fn, &m, 0.0, tu_fd_step(EPS, 1.0), 2, w, d);
        for (i = 0; i < 2; ++i) {
            e_r = fmax(e_r, fabs((double)r1[i] - (double)r0[i]));
            e_rp = fmax(e_rp, fabs((double)rp1[i] - (double)rp0[i]));
            e_v = fmax(e_v, fabs(v1[i] - v0[i]));
            e_fd = fmax(e_fd, fabs(d[i] - v0[i]));
        }
        e_eps = fmax(e_eps, fabs((double)eps1 - (double)eps0));
        e_kap = fmax(e_kap, fabs((double)kap1 - (double)kap0));
        rpmin = fmin(rpmin, (double)vlbe_v2_norm(rp0));
        rpmax = fmax(rpmax, (double)vlbe_v2_norm(rp0));
        kmax = fmax(kmax, fabs((double)kap0));
        vsc = fmax(vsc, fmax(s0, s1));
    }
    {
        const double S1 = S0 / l, S2 = S0 / (l * l);
        const double ks = S2 / (rpmin * rpmin) + 3.0 * kmax * S1 / rpmin;
        tu_report("split: position, 1000 points (/ S0)", e_r / S0, tol);
        tu_report("split: slope (/ S0 / l)", e_rp / S1, tol);
        tu_report("split: strain (/ |r'| S1)", e_eps / (rpmax * S1), tol);
        tu_report("split: curvature (/ kappa scale)", e_kap / ks, tol);
        tu_report("split: material velocity (/ sum |N q'|)", e_v / vsc, tol);
        tu_report("split: N q' vs d/dt r (central diff., / FD_ERR)", e_fd / vsc / FD_ERR, 30.0);
        tu_measured("split_fd", e_fd / vsc / FD_ERR);
        assert_true(e_r <= tol * S0);
        assert_true(e_rp <= tol * S1);
        assert_true(e_eps <= tol * rpmax * S1);
        assert_true(e_kap <= tol * ks);
        assert_true(e_v <= tol * vsc);
        assert_true(e_fd <= 30.0 * FD_ERR * vsc);
    }
    /* bad inputs: status, outputs untouched */
    {
        const double bad[7] = {seg_q[4],    seg_q[9], seg_q[4] - 0.1, seg_q[9] + 1e-3,
                               (double)NAN, HUGE_VAL, -HUGE_VAL};
        const vlbe_status want[7] = {VLBE_EBOUND, VLBE_EBOUND, VLBE_EBOUND, VLBE_EBOUND,
                                     VLBE_ENONFINITE, VLBE_ENONFINITE, VLBE_ENONFINITE};
        vlbe_real qbad[10];
        for (k = 0; k < 10; ++k) {
            vlbe_status st;
            for (i = 0; i < 5; ++i) qh[i] = qhd[i] = VLBE_R(7.0);
            for (i = 0; i < 10; ++i) qbad[i] = q[i];
            if (k < 7) {
                st = vlbe_ale_split(q, qd, (vlbe_real)bad[k], qh, qhd);
                assert_int_equal(st, want[k]);
            } else if (k == 7) { /* p2 <= p1 */
                qbad[9] = qbad[4];
                assert_int_equal(vlbe_ale_split(qbad, qd, qbad[4], qh, qhd), VLBE_ELENGTH);
            } else if (k == 8) { /* NaN in q */
                qbad[2] = (vlbe_real)NAN;
                assert_int_equal(vlbe_ale_split(qbad, qd, ph, qh, qhd), VLBE_ENONFINITE);
            } else { /* Inf in q' */
                vlbe_real qdb[10];
                for (i = 0; i < 10; ++i) qdb[i] = qd[i];
                qdb[9] = (vlbe_real)HUGE_VAL;
                assert_int_equal(vlbe_ale_split(q, qdb, ph, qh, qhd), VLBE_ENONFINITE);
            }
            for (i = 0; i < 5; ++i) {
                assert_true(qh[i] == VLBE_R(7.0));
                assert_true(qhd[i] == VLBE_R(7.0));
            }
        }
        /* without q' the same qh, and qhd is not written */
        for (i = 0; i < 5; ++i) qhd[i] = VLBE_R(7.0);
        assert_int_equal(vlbe_ale_split(q, NULL, ph, qh, qhd), VLBE_OK);
        for (i = 0; i < 5; ++i) {
            assert_true(qh[i] == qa[5 + i]);
            assert_true(qhd[i] == VLBE_R(7.0));
        }
    }
}

/* r and r' at npts material points spread over the chain's [p_0, p_last]
   (vlbe_ale_chain_point), as doubles: r[2k..2k+1], rp[2k..2k+1] */
static void chain_sample(const vlbe_ale_chain *ch, vlbe_real t, const vlbe_real *q, int npts,
                         double *r, double *rp)
{
    vlbe_real pa[3] = {0, 0, 0}, pb[3] = {0, 0, 0}, x[2] = {0, 0}, xp[2] = {0, 0};
    int k;
    assert_int_equal(vlbe_ale_chain_pnode(ch, 0, t, q, NULL, pa), VLBE_OK);
    assert_int_equal(vlbe_ale_chain_pnode(ch, ch->nn - 1, t, q, NULL, pb), VLBE_OK);
    for (k = 0; k < npts; ++k) {
        const vlbe_real p = pt_at((double)pa[0], (double)pb[0], k, npts);
        assert_int_equal(vlbe_ale_chain_point(ch, t, q, p, x, xp), VLBE_OK);
        r[2 * k] = (double)x[0];
        r[2 * k + 1] = (double)x[1];
        rp[2 * k] = (double)xp[0];
        rp[2 * k + 1] = (double)xp[1];
    }
}

/* Strain energy int (EA eps^2 + EI kap^2) / 2 dp of the chain by a
   composite 12-point Gauss rule, npan panels per element (16 in the
   checks), on the pointwise strain and curvature of vlbe_ale_strain: an
   independent integration of the same (smooth, rational) integrand, exact
   to rounding here (test_chain_insert_exact checks that 32 panels change
   it by less than SEG_TOL / 10). */
static double chain_U_composite(const vlbe_ale_chain *ch, vlbe_real t, const vlbe_real *q,
                                int npan)
{
    const vlbe_real *x, *w;
    const vlbe_ale_mat *mt = &ch->el->mat;
    double U = 0.0;
    int e, j, g, idx[10];
    unsigned md = 0u; /* written by a successful gather */
    assert_int_equal(vlbe_gl_rule(12, &x, &w), VLBE_OK);
    for (e = 0; e + 1 < ch->nn; ++e) {
        vlbe_real qe[10];
        double a, b;
        assert_int_equal(vlbe_ale_chain_gather(ch, e, t, q, NULL, qe, NULL, idx, &md), VLBE_OK);
        for (j = 0; j < npan; ++j) {
            a = (double)qe[4] + ((double)qe[9] - (double)qe[4]) * j / npan;
            b = (double)qe[4] + ((double)qe[9] - (double)qe[4]) * (j + 1) / npan;
            for (g = 0; g < 12; ++g) {
                const double p = 0.5 * (a + b) + 0.5 * (b - a) * (double)x[g];
                vlbe_real eps = 0, kap = 0;
                double u;
                assert_int_equal(vlbe_ale_strain(qe, (vlbe_real)p, &eps, &kap), VLBE_OK);
                u = (double)mt->EA * (double)eps * (double)eps;
                if (!((md | ch->el->flags) & VLBE_ALE_NO_BEND))
                    u += (double)mt->EI * (double)kap * (double)kap;
                U += 0.25 * (b - a) * (double)w[g] * u;
            }
        }
    }
    return U;
}

static double sample_r0[2 * NPTS + 2], sample_rp0[2 * NPTS + 2], sample_r1[2 * NPTS + 2],
    sample_rp1[2 * NPTS + 2]; /* up to NPTS + 1 points */

/* max nodal |r| + l_max max nodal |r'| over the chain (S0 of the SEG_TOL
   note); the shortest and (lmax != NULL) the longest element length */
static double chain_scale(const vlbe_ale_chain *ch, vlbe_real t, const vlbe_real *q, double *lmin,
                          double *lmax_out)
{
    double rmax = 0.0, smax = 0.0, lmax = 0.0;
    int i, s;
    *lmin = HUGE_VAL;
    for (i = 0; i < ch->nn; ++i) {
        const int o = ch->node[i].ofs;
        rmax = fmax(rmax, (double)vlbe_v2_norm(q + o));
        for (s = 0; s <= ch->node[i].slide; ++s)
            smax = fmax(smax, (double)vlbe_v2_norm(q + o + 2 + 2 * s));
        if (i > 0) {
            vlbe_real pa[3], pb[3];
            assert_int_equal(vlbe_ale_chain_pnode(ch, i - 1, t, q, NULL, pa), VLBE_OK);
            assert_int_equal(vlbe_ale_chain_pnode(ch, i, t, q, NULL, pb), VLBE_OK);
            lmax = fmax(lmax, (double)(pb[0] - pa[0]));
            *lmin = fmin(*lmin, (double)(pb[0] - pa[0]));
        }
    }
    if (lmax_out) *lmax_out = lmax;
    return rmax + lmax * smax;
}

/* number of coordinates of node i (from the layout) */
static int node_ncoord(const vlbe_ale_chain *ch, int i)
{
    return (i + 1 < ch->nn ? ch->node[i + 1].ofs : ch->n) - ch->node[i].ofs;
}

typedef struct ins_result {
    double E0[3], E1[3], Uc0, Uc1; /* chain energies before/after, composite U */
    double Uc0_fine;               /* Uc0 with 32 panels per element          */
    double dr, drp, S0, lmin;      /* max position/slope change, scales      */
} ins_result;

/* The chain of the insertion check, 4 nodes: 0 fixed p (0.1, pinned: POS),
   1 free (0.45), 2 prescribed (p = 0.8 + 0.3 t - 0.35 t^2), 3 fixed p (1.3)
   with a point mass 0.3 and a SLOPE_DIR constraint; material mat_std (load
   f), gravity on the mass; random deformed state (random_state, element
   lengths ~0.35-0.45, slopes 1.05 +- 8 % at +-0.35 rad, O(1) rates, free
   p' up to 0.4).  Node H inserted in element 1 (between the free and the
   prescribed node) at ph = 0.62, t = 0.37.  chmode: OR'ed into the chain's
   mode; nt: bending Gauss order. */
static void insert_case(unsigned chmode, int nt, ins_result *r)
{
    static chn c;
    static vlbe_real q[N_MAX], v[N_MAX], qn[N_MAX], vn[N_MAX];
    const vlbe_real t = VLBE_R(0.37), ph = VLBE_R(0.62);
    vlbe_ale_node old[4];
    vlbe_real E[3];
    tu_rng g = tu_rng_seed(271828);
    int i, k, n0;
    memset(&c, 0, sizeof c);
    c.mat = mat_std();
    c.node[0] = node_make(VLBE_ALE_PFIXED, 0.1);
    c.node[1] = node_make(VLBE_ALE_PFREE, 0.45);
    c.node[2] = node_make(VLBE_ALE_PPRESCRIBED, 0.8);
    c.node[2].pd = VLBE_R(0.3);
    c.node[2].pdd = VLBE_R(-0.7);
    c.node[3] = node_make(VLBE_ALE_PFIXED, 1.3);
    c.node[3].mass = VLBE_R(0.3);
    chn_init(&c, 4, 0u, nt);
    c.ch.mode = chmode;
    c.ch.g[1] = VLBE_R(-9.81);
    chn_add(&c, con_make(VLBE_ALE_CON_POS, 0, 0, 0, 0, 0, 0));
    chn_add(&c, con_make(VLBE_ALE_CON_SLOPE_DIR, 3, 0, 0, 1, 0, 0));
    chn_wire(&c);
    random_state(&c, &g, 0.4, q, v);
    n0 = c.ch.n;
    memcpy(old, c.node, sizeof old);
    r->S0 = chain_scale(&c.ch, t, q, &r->lmin, NULL);
    chain_sample(&c.ch, t, q, NPTS, sample_r0, sample_rp0);
    assert_int_equal(vlbe_ale_chain_energy(&c.ch, t, q, v, E), VLBE_OK);
    for (i = 0; i < 3; ++i) r->E0[i] = (double)E[i];
    r->Uc0 = chain_U_composite(&c.ch, t, q, 16);
    r->Uc0_fine = chain_U_composite(&c.ch, t, q, 32);

    assert_int_equal(vlbe_ale_chain_insert(&c.ch, 1, ph, t, q, v, qn, vn), VLBE_OK);
    /* the new node: fixed p = ph, plain; the others keep their data and
       coordinates (bitwise); constraints renumbered */
    assert_int_equal(c.ch.nn, 5);
    assert_int_equal(c.ch.n, n0 + 4);
    assert_int_equal(c.node[2].pmode, VLBE_ALE_PFIXED);
    assert_true(c.node[2].p == ph && c.node[2].slide == 0 && c.node[2].mass == VLBE_R(0.0));
    for (i = 0; i < 5; ++i) {
        const int io = i < 2 ? i : i - 1;
        if (i == 2) continue;
        assert_int_equal(c.node[i].pmode, old[io].pmode);
        assert_true(c.node[i].p == old[io].p && c.node[i].mass == old[io].mass);
        for (k = 0; k < node_ncoord(&c.ch, i); ++k) {
            assert_true(qn[c.node[i].ofs + k] == q[old[io].ofs + k]);
            assert_true(vn[c.node[i].ofs + k] == v[old[io].ofs + k]);
        }
    }
    assert_int_equal(c.con[0].node, 0);
    assert_int_equal(c.con[1].node, 4);
    chain_sample(&c.ch, t, qn, NPTS, sample_r1, sample_rp1);
    assert_int_equal(vlbe_ale_chain_energy(&c.ch, t, qn, vn, E), VLBE_OK);
    for (i = 0; i < 3; ++i) r->E1[i] = (double)E[i];
    r->Uc1 = chain_U_composite(&c.ch, t, qn, 16);
    {
        double l1;
        r->S0 = fmax(r->S0, chain_scale(&c.ch, t, qn, &l1, NULL));
        r->lmin = fmin(r->lmin, l1);
    }
    r->dr = max_diff(2 * NPTS, sample_r1, sample_r0);
    r->drp = max_diff(2 * NPTS, sample_rp1, sample_rp0);
}

/* vlbe_ale_chain_insert on a chain with every kind of neighbour (insert_case):
   positions and slopes at 1000 material points over the whole chain
   (vlbe_ale_chain_point) before and after equal to SEG_TOL x S0 (and
   S0 / l for slopes, l the shortest element; see SEG_TOL).  Energies
   (vlbe_ale_chain_energy):
   - cable (VLBE_ALE_NO_BEND): every integrand is a polynomial the default
     rules integrate exactly (T: |v|^2, v cubic in xi, degree 6, 4 points
     exact to degree 7; V: linear in r, degree 3; axial U: eps^2, eps of
     degree 4, degree 8, 5 points exact to degree 9), on the pieces as on
     the original (the pieces are the same cubics), so T, U, V agree to
     SEG_TOL relative (V: relative to |f| S0 x chain length + m |g| S0, its
     rounding scale, as V is a sum of signed terms);
   - beam: the bending integrand EI kap^2 / 2 is rational, the Gauss rule
     is not exact, and the pieces' rule (other points) has another error:
     the chain's U changes by the difference of two quadrature errors
     (this curved random state: 1.96e-3 (m:ins_dU5) = 1.5e-3 (m:ins_dU5_rel)
     relative at the default nt = 5, 8.1e-6 (m:ins_dU8) =
     6.3e-6 (m:ins_dU8_rel) relative at nt = 8).  Independent checks
     instead: the strain energy integrated to rounding by a composite rule
     on the pointwise strain and curvature (chain_U_composite, converged:
     32 panels per element change it by 5e-16 (m~:ucomp_fine) relative,
     4.8e-8 (m@flt~:ucomp_fine) in float) is the same before and after to
     SEG_TOL relative (1.2e-15 (m~:ucomp_change) in double; float
     2.5e-7 (m@flt~:ucomp_change)): the mechanics is unchanged, only the
     quadrature sees other points; and the change falls as the rule
     converges: at nt = 8 at most 1/10 of that at nt = 5
     (4.2e-3 (m:ins_ratio) of it).  T and V (exact rules) still agree to
     SEG_TOL. */
static void test_chain_insert_exact(void **state)
{
    ins_result nb, b5, b8;
    const ins_result *all[3];
    const double tol = SEG_TOL;
    double Vsc;
    int i, k;
    (void)state;
    insert_case(VLBE_ALE_NO_BEND, 0, &nb);
    insert_case(0u, 0, &b5);
    insert_case(0u, 8, &b8);
    all[0] = &nb;
    all[1] = &b5;
    all[2] = &b8;
    for (k = 0; k < 3; ++k) {
        tu_report("insert: positions, 1000 points (/ S0)", all[k]->dr / all[k]->S0, tol);
        tu_report("insert: slopes (/ S0 / l)", all[k]->drp / (all[k]->S0 / all[k]->lmin), tol);
        assert_true(all[k]->dr <= tol * all[k]->S0);
        assert_true(all[k]->drp <= tol * all[k]->S0 / all[k]->lmin);
    }
    Vsc = (double)vlbe_v2_norm(mat_std().f) * nb.S0 * 1.2 + 0.3 * 9.81 * nb.S0;
    tu_report("insert, cable: T (relative)", fabs(nb.E1[0] - nb.E0[0]) / nb.E0[0], tol);
    tu_report("insert, cable: U (relative)", fabs(nb.E1[1] - nb.E0[1]) / nb.E0[1], tol);
    tu_report("insert, cable: V (/ its rounding scale)", fabs(nb.E1[2] - nb.E0[2]) / Vsc, tol);
    ASSERT_CLOSE(nb.E1[0], nb.E0[0], tol, 0.0);
    ASSERT_CLOSE(nb.E1[1], nb.E0[1], tol, 0.0);
    ASSERT_CLOSE(nb.E1[2], nb.E0[2], 0.0, tol * Vsc);
    for (i = 0; i < 3; i += 2) { /* T, V the same with bending on */
        ASSERT_CLOSE(b5.E1[i], b5.E0[i], 0.0, tol * (i ? Vsc : b5.E0[0]));
        ASSERT_CLOSE(b8.E1[i], b8.E0[i], 0.0, tol * (i ? Vsc : b8.E0[0]));
    }
    for (k = 1; k < 3; ++k) {
        const ins_result *r = all[k];
        const double q0 = fabs(r->E0[1] - r->Uc0), q1 = fabs(r->E1[1] - r->Uc1);
        const double dU = fabs(r->E1[1] - r->E0[1]);
        if (tu_report_on())
            print_message("    insert, beam, nt %d: U %.15g, change %.3e (%.2e relative); "
                          "quadrature error before %.3e, after %.3e; composite U %.15g -> %.15g\n",
                          k == 1 ? 5 : 8, r->E0[1], dU, dU / r->E0[1], q0, q1, r->Uc0, r->Uc1);
        /* the exact energy is unchanged (composite integration) */
        ASSERT_CLOSE(r->Uc1, r->Uc0, tol, 0.0);
        tu_measured(k == 1 ? "ins_dU5" : "ins_dU8", dU);
        tu_measured(k == 1 ? "ins_dU5_rel" : "ins_dU8_rel", dU / r->E0[1]);
    }
    /* the composite rule is converged: twice the panels, the same U */
    tu_report("composite U: 32 vs 16 panels per element (relative)",
              fabs(b5.Uc0_fine - b5.Uc0) / b5.Uc0, 0.1 * tol);
    tu_measured("ucomp_fine", fabs(b5.Uc0_fine - b5.Uc0) / b5.Uc0);
    tu_measured("ucomp_change",
                fmax(fabs(b5.Uc1 - b5.Uc0) / b5.Uc0, fabs(b8.Uc1 - b8.Uc0) / b8.Uc0));
    ASSERT_CLOSE(b5.Uc0_fine, b5.Uc0, 0.1 * tol, 0.0);
    /* the change of the chain's U is a quadrature artefact: it falls as the
       rule converges (1.96e-3 at nt = 5, 8.1e-6 at nt = 8, above) */
    tu_measured("ins_ratio", fabs(b8.E1[1] - b8.E0[1]) / fabs(b5.E1[1] - b5.E0[1]));
    assert_true(fabs(b8.E1[1] - b8.E0[1]) <= 0.1 * fabs(b5.E1[1] - b5.E0[1]));
}

/* ======================================================================= */
/* 10. merging (vlbe_ale_chain_remove)                                       */
/* ======================================================================= */

/* A chain of nn nodes at p[0..nn-1], all p fixed except node `slider`
   (free, p' = 0.2; -1: none), no loads or constraints, material mat_std
   without damping: positions and slopes of the curve f (f(p, r, rp)), rates
   of g (a velocity field and its p-derivative). */
typedef void (*curve_fn)(double p, double *r, double *rp);

static void curve_chain(chn *c, int nn, const double *p, int slider, curve_fn f, curve_fn g,
                        unsigned chmode, vlbe_real *q, vlbe_real *v)
{
    int i, k;
    memset(c, 0, sizeof *c);
    c->mat = mat_std();
    c->mat.f[0] = c->mat.f[1] = VLBE_R(0.0);
    for (i = 0; i < nn; ++i)
        c->node[i] = node_make(i == slider ? VLBE_ALE_PFREE : VLBE_ALE_PFIXED, p[i]);
    chn_init(c, nn, VLBE_ALE_NO_DAMP, 0);
    c->ch.mode = chmode;
    chn_wire(c);
    for (i = 0; i < nn; ++i) {
        double r[2], rp[2], s[2], sp[2];
        const int o = c->node[i].ofs;
        f(p[i], r, rp);
        g(p[i], s, sp);
        for (k = 0; k < 2; ++k) {
            q[o + k] = (vlbe_real)r[k];
            q[o + 2 + k] = (vlbe_real)rp[k];
            v[o + k] = (vlbe_real)s[k];
            v[o + 2 + k] = (vlbe_real)sp[k];
        }
        if (i == slider) {
            q[o + 4] = (vlbe_real)p[i];
            v[o + 4] = VLBE_R(0.2);
        }
    }
}

/* a general planar cubic (stretched and curved: |r'| 1.37 .. 2.76 on
   [0.2, 1.1]) and a cubic velocity field */
static void cubic_f(double p, double *r, double *rp)
{
    r[0] = 0.3 + p * (1.1 + p * (-0.4 + 0.7 * p));
    r[1] = -0.2 + p * (0.5 + p * (1.3 - 0.9 * p));
    rp[0] = 1.1 + p * (-0.8 + 2.1 * p);
    rp[1] = 0.5 + p * (2.6 - 2.7 * p);
}

static void cubic_g(double p, double *r, double *rp)
{
    r[0] = -0.6 + p * (0.9 + p * (0.8 - 1.2 * p));
    r[1] = 0.4 + p * (-1.5 + p * (0.3 + 0.5 * p));
    rp[0] = 0.9 + p * (1.6 - 3.6 * p);
    rp[1] = -1.5 + p * (0.6 + 1.5 * p);
}

/* (a) Reduced = full.  Two elements that are exact pieces of one cubic
   (nodes at p = 0.2, 0.55, 1.1 on cubic_f, rates from cubic_g): before and
   after removing the middle node, the chain's r and r' at 1000 points equal
   the cubic itself (an independent evaluation, Hermite interpolation
   reproduces cubics) to SEG_TOL x S0 (S0 / l for r', l the shorter piece),
   and T, U, V of the cable (polynomial integrands, exact rules: see
   test_chain_insert_exact) are unchanged to SEG_TOL relative.  Also the
   round trip insert + remove restores nodes, layout and coordinates
   bitwise (the outer nodes' coordinates are copied, never recomputed). */
static void test_merge_exact(void **state)
{
    static chn c;
    static vlbe_real q[N_MAX], v[N_MAX], qn[N_MAX], vn[N_MAX], q2[N_MAX], v2[N_MAX];
    const double p[3] = {0.2, 0.55, 1.1}, tol = SEG_TOL;
    vlbe_ale_node saved[3];
    vlbe_real E0[3], E1[3];
    static double ex[2 * NPTS], exp_[2 * NPTS];
    double S0, l;
    int k, n0;
    (void)state;
    curve_chain(&c, 3, p, -1, cubic_f, cubic_g, VLBE_ALE_NO_BEND, q, v);
    S0 = chain_scale(&c.ch, 0, q, &l, NULL);
    for (k = 0; k < NPTS; ++k)
        cubic_f((double)pt_at(p[0], p[2], k, NPTS), ex + 2 * k, exp_ + 2 * k);
    chain_sample(&c.ch, 0, q, NPTS, sample_r0, sample_rp0);
    assert_int_equal(vlbe_ale_chain_energy(&c.ch, 0, q, v, E0), VLBE_OK);
    n0 = c.ch.n;
    assert_int_equal(vlbe_ale_chain_remove(&c.ch, 1, 0, q, v, qn, vn), VLBE_OK);
    assert_int_equal(c.ch.nn, 2);
    assert_int_equal(c.ch.n, n0 - 4);
    chain_sample(&c.ch, 0, qn, NPTS, sample_r1, sample_rp1);
    assert_int_equal(vlbe_ale_chain_energy(&c.ch, 0, qn, vn, E1), VLBE_OK);
    tu_report("merge of one cubic: positions vs the cubic (/ S0)",
              fmax(max_diff(2 * NPTS, sample_r0, ex), max_diff(2 * NPTS, sample_r1, ex)) / S0, tol);
    tu_report("merge of one cubic: slopes vs the cubic (/ S0 / l)",
              fmax(max_diff(2 * NPTS, sample_rp0, exp_), max_diff(2 * NPTS, sample_rp1, exp_)) /
                  (S0 / l),
              tol);
    ASSERT_VEC_CLOSE(sample_r0, ex, 2 * NPTS, 0.0, tol * S0);
    ASSERT_VEC_CLOSE(sample_r1, ex, 2 * NPTS, 0.0, tol * S0);
    ASSERT_VEC_CLOSE(sample_rp0, exp_, 2 * NPTS, 0.0, tol * S0 / l);
    ASSERT_VEC_CLOSE(sample_rp1, exp_, 2 * NPTS, 0.0, tol * S0 / l);
    for (k = 0; k < 2; ++k)
        tu_report(k ? "merge of one cubic: U (relative)" : "merge of one cubic: T (relative)",
                  fabs((double)E1[k] - (double)E0[k]) / (double)E0[k], tol);
    ASSERT_CLOSE(E1[0], E0[0], tol, 0.0);
    ASSERT_CLOSE(E1[1], E0[1], tol, 0.0);
    assert_true(E0[2] == VLBE_R(0.0) && E1[2] == VLBE_R(0.0)); /* no load, no masses */

    /* round trip on the merged chain: insert at 0.55, remove it again */
    memcpy(saved, c.node, 2 * sizeof *saved);
    n0 = c.ch.n;
    assert_int_equal(vlbe_ale_chain_insert(&c.ch, 0, (vlbe_real)p[1], 0, qn, vn, q2, v2), VLBE_OK);
    assert_int_equal(vlbe_ale_chain_remove(&c.ch, 1, 0, q2, v2, q2, v2), VLBE_OK);
    assert_int_equal(c.ch.nn, 2);
    assert_int_equal(c.ch.n, n0);
    assert_memory_equal(saved, c.node, 2 * sizeof *saved);
    assert_memory_equal(q2, qn, (size_t)n0 * sizeof *qn);
    assert_memory_equal(v2, vn, (size_t)n0 * sizeof *vn);
}

/* the circular arc of radius ARC_R through the origin, unit speed
   (unstretched): r = R (sin(p/R), 1 - cos(p/R)); and a rigid rotation
   about the origin at unit rate: v = (-y, x), v' = (-y', x') */
#define ARC_R 1.0
static void arc_f(double p, double *r, double *rp)
{
    r[0] = ARC_R * sin(p / ARC_R);
    r[1] = ARC_R * (1.0 - cos(p / ARC_R));
    rp[0] = cos(p / ARC_R);
    rp[1] = sin(p / ARC_R);
}

static void arc_g(double p, double *r, double *rp)
{
    double x[2], xp[2];
    arc_f(p, x, xp);
    r[0] = -x[1];
    r[1] = x[0];
    rp[0] = -xp[1];
    rp[1] = xp[0];
}

typedef struct merge_err {
    double dmax, dmid, dE[3], E0[3];
} merge_err;

/* Two elements of length h on the arc (nodes by interpolation at 0, h,
   2h), merged: max deviation of r over 1001 points of [0, 2h] (the
   midpoint among them), the deviation at the midpoint, energy changes. */
static void merge_arc(double h, merge_err *m)
{
    static chn c;
    static vlbe_real q[N_MAX], v[N_MAX], qn[N_MAX], vn[N_MAX];
    const double p[3] = {0.0, h, 2.0 * h};
    const int np = NPTS + 1;
    vlbe_real E0[3], E1[3];
    int i;
    curve_chain(&c, 3, p, -1, arc_f, arc_g, 0u, q, v);
    chain_sample(&c.ch, 0, q, np, sample_r0, sample_rp0);
    assert_int_equal(vlbe_ale_chain_energy(&c.ch, 0, q, v, E0), VLBE_OK);
    assert_int_equal(vlbe_ale_chain_remove(&c.ch, 1, 0, q, v, qn, vn), VLBE_OK);
    chain_sample(&c.ch, 0, qn, np, sample_r1, sample_rp1);
    assert_int_equal(vlbe_ale_chain_energy(&c.ch, 0, qn, vn, E1), VLBE_OK);
    m->dmax = 0.0;
    for (i = 0; i < np; ++i)
        m->dmax = fmax(m->dmax, hypot(sample_r1[2 * i] - sample_r0[2 * i],
                                      sample_r1[2 * i + 1] - sample_r0[2 * i + 1]));
    m->dmid = hypot(sample_r1[np - 1] - sample_r0[np - 1], sample_r1[np] - sample_r0[np]);
    for (i = 0; i < 3; ++i) {
        m->E0[i] = (double)E0[i];
        m->dE[i] = (double)E1[i] - (double)E0[i];
    }
}

/* (b) The error merging makes.  Two elements of length h interpolating the
   circular arc (R = 1, unstretched; nodal values and slopes of the arc),
   merged into one of length 2h: the merged cubic is the Hermite
   interpolant of the arc on [0, 2h], the two-element chain interpolates it
   at h too.  Independent facts:
   - at the midpoint the chain before merging is exact (a node) and the
     Hermite error of f on [m - h, m + h] at m is f''''(m) h^4 / 24 +
     f^(6)(m) h^6 / 360 + 3 f^(8)(m) h^8 / 8! + ... (interpolate x^4, x^6,
     x^8 on [-h, h]: errors h^4, 2 h^6, 3 h^8); for the arc |f''''| = 1/R^3,
     f^(6) = -f''''/R^2, f^(8) = f''''/R^4, so the deviation there is
     h^4 / (24 R^3) (1 - h^2 / (15 R^2)) (1 + d), |d| <= 2e-3 (h/R)^4
     (d = 1.79e-3 (m:merge_d) (h/R)^4 at h = 0.2); held to 1e-2 (h/R)^4 plus
     the rounding bound 250 EPS h relative to the deviation (below);
   - the max deviation over [0, 2h] (at the midpoint: the two-element
     chain's own error is 1/16 of the merged one) is O(h^4): the observed
     order log2(d(h) / d(h/2)) is 4 up to the h^2 / (15 R^2) correction
     above, which shifts it by -0.072 h^2 (< 0.012 for h <= 0.4), and
     rounding: held to [3.9, 4.1].
   Sizes: double h = 0.2 .. 0.025 (deviations 6.6e-5 .. 1.6e-8; the
   positions, ~2h in size, round to ~1e-17); float h = 0.4 .. 0.1
   (deviations 1.1e-3 .. 4.2e-6).  The rounding bound of the deviation,
   ~250 EPS h (two evaluations of ~30 EPS S0 each, S0 ~ 4h, see SEG_TOL), is
   added to the midpoint check; it is 1e-6 of the deviation in double, but
   0.7 of it at float h = 0.1, where the rounding found is
   1e-4 (m@flt:merge_rel01) of the deviation (midpoint vs formula): the
   order bound holds there on that finding, not on the a-priori bound.
   Orders (double) 3.9971 (m:merge_order1), 3.9993 (m:merge_order2),
   3.9998 (m:merge_order3) (h^2 correction: 4 - 0.072 h^2); float
   3.9884 (m@flt:merge_order1), 3.9969 (m@flt:merge_order2).  Reported:
   max deviation, order, changes of T (rigid rotation at unit rate), U (the
   merged curvature differs from 1/R by O(h^2)), V (0: no loads) and their
   observed orders. */
static void test_merge_error(void **state)
{
#ifndef VLBE_USE_FLOAT
    static const double hs[4] = {0.2, 0.1, 0.05, 0.025};
    const int nh = 4;
#else
    static const double hs[4] = {0.4, 0.2, 0.1, 0.0};
    const int nh = 3;
#endif
    merge_err m[4];
    int i;
    (void)state;
    for (i = 0; i < nh; ++i) {
        const double h = hs[i] / ARC_R, lead = pow(hs[i], 4) / (24.0 * pow(ARC_R, 3));
        const double asym = lead * (1.0 - h * h / 15.0);
        const double rtol = 1e-2 * pow(h, 4) + 250.0 * EPS * hs[i] / lead;
        merge_arc(hs[i], &m[i]);
        print_message("    merge on the arc, h = %-6g: max deviation %.4e (midpoint %.4e, "
                      "h^4/24R^3 (1 - h^2/15R^2) %.4e); dT %.2e, dU %.2e (%.2e rel.), dV %.1e\n",
                      hs[i], m[i].dmax, m[i].dmid, asym, m[i].dE[0], m[i].dE[1],
                      m[i].dE[1] / m[i].E0[1], m[i].dE[2]);
        tu_report("merge on the arc: midpoint deviation vs asymptotic (rel.)",
                  fabs(m[i].dmid / asym - 1.0), rtol);
        {
            const double dev = fabs(m[i].dmid / asym - 1.0);
            const int at01 = hs[i] == 0.1;
            if (i == 0) tu_measured("merge_d", dev / pow(h, 4));
            if (at01) tu_measured("merge_rel01", dev);
        }
        ASSERT_CLOSE(m[i].dmid, asym, rtol, 0.0);
        if (i > 0) {
            const double order = log2(m[i - 1].dmax / m[i].dmax);
            print_message("    observed order, h %g -> %g: deviation %.4f, dT %.2f, dU %.2f\n",
                          hs[i - 1], hs[i], order, log2(m[i - 1].dE[0] / m[i].dE[0]),
                          log2(m[i - 1].dE[1] / m[i].dE[1]));
            {
                static const char *const key[3] = {"merge_order1", "merge_order2", "merge_order3"};
                tu_measured(key[i - 1], order);
            }
            assert_true(order >= 3.9 && order <= 4.1);
        }
    }
}

/* Nodes that vlbe_ale_chain_remove must refuse (VLBE_EARG, chain, nodes,
   constraints and qn untouched): out of range, the two ends, a sliding
   node, a node carrying a mass, a node with a constraint, the first, an
   interior and the last node of an EQUAL_LEN group; insertions
   vlbe_ale_chain_insert must refuse the same way: element out of range or
   inside an EQUAL_LEN group (EARG), ph on a node or outside the element
   (EBOUND), non-finite (ENONFINITE), no capacity (EWORK).  Then a plain
   node is removed. */
static void test_insert_remove_bad_inputs(void **state)
{
    static chn c;
    static vlbe_ale_node nsave[NN_MAX];
    static vlbe_ale_con csave[NC_MAX];
    vlbe_real q[N_MAX], v[N_MAX], qn[N_MAX], vn[N_MAX], r0[2] = {0, 0}, dir[2] = {1, 0};
    static const int bad[11] = {-1, 0, 8, 9, 1, 2, 3, 4, 5, 6, 100};
    int i, k, n0, m0;
    (void)state;
    memset(&c, 0, sizeof c);
    c.mat = mat_std();
    for (i = 0; i < 9; ++i)
        c.node[i] = node_make(i == 5 ? VLBE_ALE_PFREE : VLBE_ALE_PFIXED, 0.2 * i);
    c.node[1].slide = 1;
    c.node[2].mass = VLBE_R(0.3);
    chn_init(&c, 9, 0u, 0);
    chn_add(&c, con_make(VLBE_ALE_CON_POS, 0, 0, 0, 0, 0, 0));
    chn_add(&c, con_make(VLBE_ALE_CON_SLOPE_DIR, 3, 0, 0, 1, 0, 0));
    chn_add(&c, con_make(VLBE_ALE_CON_EQUAL_LEN, 4, 6, 0, 0, 0, 0));
    chn_wire(&c);
    vlbe_ale_chain_straight(&c.ch, r0, dir, q);
    for (i = 0; i < c.ch.n; ++i) v[i] = VLBE_R(0.5);
    n0 = c.ch.n;
    m0 = c.ch.m;
    memcpy(nsave, c.node, sizeof nsave);
    memcpy(csave, c.con, sizeof csave);
    for (k = 0; k < 11 + 9; ++k) {
        for (i = 0; i < N_MAX; ++i) qn[i] = vn[i] = VLBE_R(7.0);
        if (k < 11) {
            if (vlbe_ale_chain_remove(&c.ch, bad[k], 0, q, v, qn, vn) != VLBE_EARG)
                fail_msg("remove(%d) did not return VLBE_EARG", bad[k]);
        } else {
            static const int e[9] = {-1, 8, 7, 7, 7, 7, 7, 4, 5};
            static const double ph[9] = {1.5, 1.5, 1.4, 1.6, 1.7, 0.0, 1.5, 0.9, 1.1};
            static const vlbe_status want[9] = {VLBE_EARG,   VLBE_EARG,      VLBE_EBOUND,
                                                VLBE_EBOUND, VLBE_EBOUND,    VLBE_ENONFINITE,
                                                VLBE_EWORK,  VLBE_EARG,      VLBE_EARG};
            const int j = k - 11;
            const vlbe_real p = j == 5 ? (vlbe_real)NAN : (vlbe_real)ph[j];
            if (j == 6) c.ch.nn_cap = 9;
            assert_int_equal(vlbe_ale_chain_insert(&c.ch, e[j], p, 0, q, v, qn, vn), want[j]);
            c.ch.nn_cap = NN_MAX;
        }
        assert_int_equal(c.ch.nn, 9);
        assert_int_equal(c.ch.n, n0);
        assert_int_equal(c.ch.m, m0);
        assert_memory_equal(nsave, c.node, sizeof nsave);
        assert_memory_equal(csave, c.con, sizeof csave);
        for (i = 0; i < N_MAX; ++i) assert_true(qn[i] == VLBE_R(7.0) && vn[i] == VLBE_R(7.0));
    }
    /* node 7 is plain: removed; the constraints keep their nodes (all < 7) */
    assert_int_equal(vlbe_ale_chain_remove(&c.ch, 7, 0, q, v, qn, vn), VLBE_OK);
    assert_int_equal(c.ch.nn, 8);
    assert_int_equal(c.ch.n, n0 - 4);
    assert_int_equal(c.con[2].node2, 6);
    assert_true(qn[c.node[7].ofs] == q[nsave[8].ofs]);
}

/* ======================================================================= */
/* 11. length control (vlbe_ale_chain_length_control)                        */
/* ======================================================================= */

/* One case of the unit test: a chain of 5 nodes at p[] with the free node
   `slider`, on the arc (arc_f, rates of arc_g: not a cubic, so that merging
   changes the curve), Lstd = 0.25 (threshold 0.375).  Expected: *changed,
   the new slider index, the new nodes' p, the new element of length Lstd
   and the merged span [ma, mb] (ma = mb: none) outside which positions and
   slopes must not change (SEG_TOL). */
typedef struct lc_case {
    double p[5];
    int slider;
    int changed, slider_new, nn_new;
    double p_new[6];
    int e_new; /* the new element of length Lstd (-1: none) */
    double ma, mb;
} lc_case;

/* key: the name under which the merged span's deviation is reported (NULL: none) */
static void lc_unit(const lc_case *k, const char *key)
{
    static chn c;
    static vlbe_real q[N_MAX], v[N_MAX], qn[N_MAX], vn[N_MAX];
    static vlbe_ale_node nsave[NN_MAX];
    const vlbe_real Lstd = VLBE_R(0.25);
    double S0, l, S0n, ln, dout = 0.0, dpout = 0.0, din = 0.0;
    int i, s = k->slider, changed = -1, n0;
    curve_chain(&c, 5, k->p, k->slider, arc_f, arc_g, VLBE_ALE_NO_BEND, q, v);
    n0 = c.ch.n;
    memcpy(nsave, c.node, sizeof nsave);
    S0 = chain_scale(&c.ch, 0, q, &l, NULL);
    chain_sample(&c.ch, 0, q, NPTS, sample_r0, sample_rp0);
    for (i = 0; i < N_MAX; ++i) qn[i] = vn[i] = VLBE_R(7.0);
    assert_int_equal(vlbe_ale_chain_length_control(&c.ch, Lstd, 0, q, v, &s, qn, vn, &changed),
                     VLBE_OK);
    assert_int_equal(changed, k->changed);
    assert_int_equal(s, k->slider_new);
    assert_int_equal(c.ch.nn, k->nn_new);
    assert_int_equal(c.node[s].pmode, VLBE_ALE_PFREE);
    assert_int_equal(c.ch.n, n0 + 4 * (k->nn_new - 5));
    for (i = 0; i < c.ch.nn; ++i) {
        vlbe_real p3[3];
        assert_int_equal(vlbe_ale_chain_pnode(&c.ch, i, 0, qn, vn, p3), VLBE_OK);
        ASSERT_CLOSE_CTX(p3[0], k->p_new[i], 0.0, 2.0 * EPS, "node %d", i);
    }
    if (changed == 0) { /* nothing done: (q, v) copied, the chain as it was */
        assert_memory_equal(qn, q, (size_t)n0 * sizeof *q);
        assert_memory_equal(vn, v, (size_t)n0 * sizeof *v);
        assert_memory_equal(nsave, c.node, sizeof nsave);
        return;
    }
    /* the new element away from the slider has length Lstd */
    ASSERT_CLOSE(c.node[k->e_new + 1].p - c.node[k->e_new].p, Lstd, 0.0, 2.0 * EPS);
    S0n = chain_scale(&c.ch, 0, qn, &ln, NULL);
    S0 = fmax(S0, S0n);
    l = fmin(l, ln);
    chain_sample(&c.ch, 0, qn, NPTS, sample_r1, sample_rp1);
    for (i = 0; i < NPTS; ++i) {
        const double p = (double)pt_at(k->p[0], k->p[4], i, NPTS);
        const double d = hypot(sample_r1[2 * i] - sample_r0[2 * i],
                               sample_r1[2 * i + 1] - sample_r0[2 * i + 1]);
        if (p > k->ma && p < k->mb) {
            din = fmax(din, d);
            continue;
        }
        dout = fmax(dout, d);
        dpout = fmax(dpout, hypot(sample_rp1[2 * i] - sample_rp0[2 * i],
                                  sample_rp1[2 * i + 1] - sample_rp0[2 * i + 1]));
    }
    if (tu_report_on())
        print_message("    length control (changed %d): merged span [%g, %g] deviates by %.3e\n",
                      changed, k->ma, k->mb, din);
    tu_report("length control: positions outside the merged span (/ S0)", dout / S0, SEG_TOL);
    tu_report("length control: slopes outside the merged span (/ S0 / l)", dpout / (S0 / l),
              SEG_TOL);
    assert_true(dout <= SEG_TOL * S0);
    assert_true(dpout <= SEG_TOL * S0 / l);
    /* the merged span did change (the Hermite error of the arc over the
       merged 0.35 and 0.4, l^4 / 384 = 3.9e-5 and 6.7e-5; found
       3.3e-5 (m:lc_din0) and 6.6e-5 (m:lc_din1)): the points excluded
       above are the ones merging moves */
    if (key) tu_measured(key, din);
    if (changed == 2) assert_true(din > 1e-6);
}

/* vlbe_ale_chain_length_control on one call (Figure 7 of the paper), Lstd =
   0.25, 5 nodes on the arc of radius 1 (arc_f, rotating rigidly), the free
   slider moving (p' = 0.2):
   - right element 0.4 > 1.5 Lstd: node inserted at 1.0 - Lstd, the
     slider's left neighbour removed: changed 2, 5 nodes, slider index -1;
   - left element 0.4: node at 0 + Lstd, right neighbour removed: changed 2,
     slider index +1;
   - right element too long but the left neighbour is the chain's end (not
     removable): changed 1, 6 nodes;
   - both elements within 1.5 Lstd: changed 0, (q, v) copied, chain as it was.
   New node p's to 2 EPS (one subtraction); positions and slopes at 1000
   points outside the merged span unchanged to SEG_TOL (exact segmentation,
   copied coordinates); the merged span's deviation reported. */
static void test_length_control_unit(void **state)
{
    static const lc_case cases[4] = {
        {{0, 0.25, 0.5, 0.6, 1.0}, 3, 2, 2, 5, {0, 0.25, 0.6, 0.75, 1.0}, 3, 0.25, 0.6},
        {{0, 0.4, 0.6, 0.8, 1.0}, 1, 2, 2, 5, {0, 0.25, 0.4, 0.8, 1.0}, 0, 0.4, 0.8},
        {{0, 0.1, 0.5, 0.75, 1.0}, 1, 1, 1, 6, {0, 0.1, 0.25, 0.5, 0.75, 1.0}, 2, 0, 0},
        {{0, 0.25, 0.5, 0.7, 1.0}, 3, 0, 3, 5, {0, 0.25, 0.5, 0.7, 1.0}, -1, 0, 0},
    };
    static const char *const key[4] = {"lc_din0", "lc_din1", NULL, NULL};
    int k;
    (void)state;
    for (k = 0; k < 4; ++k) lc_unit(&cases[k], key[k]);
}

/* The scene of test_shrinking_element on a longer chain, with and without
   length control.  Seven nodes at p = 0, 0.5, .., 3 (Lstd = 0.5), node 0
   pinned at the origin, node 6 at x = 3.03 (1 % prestretch), node 4 free
   in p and driven by VLBE_ALE_CON_P at constant speed: p4 = 2 - 1.2 t,
   so the element behind it ([1.5, p4]) would vanish at t = 5/12; the beam
   (rhoA 1, EA 100, EI 0.5, no damping) starts straight, the material at
   rest (node 4 moving with the mesh) plus a transverse velocity 0.1 at
   node 4.  HHT alpha -0.1, fixed step 0.01, up to 8 halvings, to t = 1.2
   (p4 = 0.56).  With control != 0, vlbe_ale_chain_length_control after
   every accepted step and a restart of HHT from (qn, vn) when it changed
   something. */
#define LC_LSTD 0.5
#define LC_SPEED 1.2
#define LC_H 0.01
#define LC_TEND 1.2

typedef struct lc_result {
    vlbe_status rc, err;
    int events, finite, relayout; /* relayout: events that changed nn or n */
    long steps;
    double t, Lmin, Lmax, Lmax_after; /* element lengths seen (after a step; after control) */
} lc_result;

static void lc_run(int control, lc_result *r)
{
    static chn c;
    static vlbe_real q[N_MAX], v[N_MAX], qn[N_MAX], vn[N_MAX];
    vlbe_real r0[2] = {0, 0}, dir[2] = {VLBE_R(1.01), 0};
    hht_run h;
    int i, n0, slider = 4;
    long n = 0;
    memset(&c, 0, sizeof c);
    memset(r, 0, sizeof *r);
    c.mat.rhoA = VLBE_R(1.0);
    c.mat.EA = VLBE_R(100.0);
    c.mat.EI = VLBE_R(0.5);
    for (i = 0; i < 7; ++i)
        c.node[i] = node_make(i == slider ? VLBE_ALE_PFREE : VLBE_ALE_PFIXED, LC_LSTD * i);
    chn_init(&c, 7, VLBE_ALE_NO_DAMP, 0);
    chn_add(&c, con_make(VLBE_ALE_CON_POS, 0, 0, 0, 0, 0, 0));
    chn_add(&c, con_make(VLBE_ALE_CON_POS, 6, 0, 0, 1.01 * 6 * LC_LSTD, 0, 0));
    chn_add(&c, con_make(VLBE_ALE_CON_P, slider, 0, 0, 4 * LC_LSTD, -LC_SPEED, 0));
    chn_wire(&c);
    vlbe_ale_chain_straight(&c.ch, r0, dir, q);
    for (i = 0; i < c.ch.n; ++i) v[i] = VLBE_R(0.0);
    v[pidx(&c, slider)] = (vlbe_real)-LC_SPEED;
    v[c.node[slider].ofs] = (vlbe_real)(1.01 * -LC_SPEED);
    v[c.node[slider].ofs + 1] = VLBE_R(0.1);
    hht_alloc(&h, 8);
    assert_int_equal(hht_start(&h, &c, VLBE_R(0.0), q, v), VLBE_OK);
    n0 = c.ch.n;
    r->Lmin = HUGE_VAL;
    c.ch.err = VLBE_OK;
    while ((double)h.hs.t < LC_TEND - 0.5 * LC_H) {
        double lmin, lmax;
        hht_cap_check(++n, hht_cap(LC_TEND, LC_H), (double)h.hs.t);
        if ((r->rc = vlbe_hht_step(&h.hs, (vlbe_real)LC_H)) != VLBE_OK) break;
        r->steps++;
        chain_scale(&c.ch, h.hs.t, h.hs.q, &lmin, &lmax);
        r->Lmin = fmin(r->Lmin, lmin);
        r->Lmax = fmax(r->Lmax, lmax);
        if (control) {
            const vlbe_real t = h.hs.t;
            int changed;
            vlbe_vec_copy(c.ch.n, h.hs.q, q);
            vlbe_vec_copy(c.ch.n, h.hs.v, v);
            assert_int_equal(vlbe_ale_chain_length_control(&c.ch, (vlbe_real)LC_LSTD, t, q, v,
                                                           &slider, qn, vn, &changed),
                             VLBE_OK);
            assert_int_equal(c.node[slider].pmode, VLBE_ALE_PFREE);
            if (changed) {
                r->events++;
                chn_wire(&c);
                if (c.ch.nn != 7 || c.ch.n != n0) r->relayout++;
                chain_scale(&c.ch, t, qn, &lmin, &lmax);
                r->Lmin = fmin(r->Lmin, lmin);
                r->Lmax_after = fmax(r->Lmax_after, lmax);
                if (tu_report_on())
                    print_message("    length control at t = %.3f: changed %d, slider now node %d, "
                                  "elements in [%.4f, %.4f]\n",
                                  (double)t, changed, slider, lmin, lmax);
                if ((r->rc = hht_start(&h, &c, t, qn, vn)) != VLBE_OK) break;
            } else {
                r->Lmax_after = fmax(r->Lmax_after, lmax);
            }
        }
    }
    r->err = c.ch.err;
    r->t = (double)h.hs.t;
    r->finite = vlbe_all_finite(h.hs.q, 4 * c.sys.n + c.sys.m);
    hht_free(&h);
    if (tu_report_on())
        print_message("    moving node, length control %s: %s (ch.err %s) at t = %.4f, %ld steps, "
                      "%d events, elements in [%.4f, %.4f] (after control <= %.4f), "
                      "state finite %d\n",
                      control ? "on" : "off", vlbe_status_str(r->rc), vlbe_status_str(r->err), r->t,
                      r->steps, r->events, r->Lmin, r->Lmax, r->Lmax_after, r->finite);
}

/* The second half of the stability statement.  Without length control the
   element behind the moving node shrinks to nothing and the run stops with
   a status before t = 5/12, last state finite (as test_shrinking_element
   shows on three nodes).  With it the run reaches t = 1.2 with a finite
   state; the node count and the number of coordinates never change (every
   event is an insertion plus a removal: the node removed is always an
   interior fixed node); p4 crosses 1.75, 1.25 and 0.75 (the thresholds
   where the element ahead reaches 1.5 Lstd), so exactly 3 events; every
   element length, after each step, lies in [0.5 Lstd - c h, 1.5 Lstd +
   c h] (the scheme keeps [0.5, 1.5] Lstd at each call, and one step of the
   node, c h = 0.012, may cross a threshold before the next call), and
   after each call <= 1.5 Lstd. */
static void test_length_control_run(void **state)
{
    const double ch_ = LC_SPEED * LC_H;
    lc_result off, on;
    (void)state;
    lc_run(0, &off);
    assert_int_not_equal(off.rc, VLBE_OK);
    assert_true(off.finite);
    assert_true(off.t < 5.0 / 12.0);
    lc_run(1, &on);
    print_message("    moving node with length control: %s at t = %.3f, %d events, elements in "
                  "[%.3f, %.3f] Lstd; without: %s at t = %.3f, shortest element %.2e Lstd\n",
                  vlbe_status_str(on.rc), on.t, on.events, on.Lmin / LC_LSTD, on.Lmax / LC_LSTD,
                  vlbe_status_str(off.rc), off.t, off.Lmin / LC_LSTD);
    assert_int_equal(on.rc, VLBE_OK);
    assert_true(on.finite);
    assert_true(fabs(on.t - LC_TEND) < 0.5 * LC_H);
    assert_int_equal(on.events, 3);
    assert_int_equal(on.relayout, 0);
    assert_true(on.Lmin >= 0.5 * LC_LSTD - ch_ && on.Lmax <= 1.5 * LC_LSTD + ch_);
    assert_true(on.Lmax_after <= 1.5 * LC_LSTD);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_assembly_fd),
        cmocka_unit_test(test_mass_matrix),
        cmocka_unit_test(test_rigid_state),
        cmocka_unit_test(test_energy_conservation),
        cmocka_unit_test(test_cantilever_static),
        cmocka_unit_test(test_scene1_moving_string),
        cmocka_unit_test(test_bad_inputs),
        cmocka_unit_test(test_shrinking_element),
        cmocka_unit_test(test_split_exact),
        cmocka_unit_test(test_chain_insert_exact),
        cmocka_unit_test(test_merge_exact),
        cmocka_unit_test(test_merge_error),
        cmocka_unit_test(test_insert_remove_bad_inputs),
        cmocka_unit_test(test_length_control_unit),
        cmocka_unit_test(test_length_control_run),
    };
    return cmocka_run_group_tests_name("chain_ale", tests, NULL, NULL);
}

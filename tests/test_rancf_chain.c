/* test_rancf_chain.c -- cmocka suite of chains of rational elements: the
   per-element types of ancf_ale.h (vlbe_ale_etype, vlbe_ale_chain_types)
   driven by rancf.h's vlbe_rancf_chain_init  -- part of vlbe
                                                   SPDX-License-Identifier: MIT
   cc -std=c99 -Wall -Wextra -Wpedantic ... -O2 tests/test_rancf_chain.c -lcmocka -lm
   (add -DVLBE_USE_FLOAT for the float build; the same source passes in both)

   Every tolerance says why it has its size.  Rounding-only checks use
   multiples of EPS (the machine epsilon of vlbe_real); central differences
   with the step h = EPS^(1/3) x (the length over which f varies) use
   multiples of FD_ERR = EPS^(2/3) (truncation h^2 f'''/6 and rounding
   EPS f / h both ~EPS^(2/3) times the size of f and of its derivatives).
   Set VLBE_TEST_REPORT=1 to print the measured errors ("measured" below:
   the double -O2 build, tag m:, the float build where quoted, m@flt:;
   tests/measured.sh checks them against the report).  The suite takes
   ~0.01 s at -O2 and ~1 s under valgrind.

   Tests
     unit_weights       all weights 1: the rational chain's mass, force, K, D,
                        d(Ma)/dq, energy, length and its rate, r(p), r'(p)
                        equal the ALE-ANCF chain's bit for bit (fixed, free,
                        prescribed, sliding nodes, a point mass, gravity)
     arc_fd             a perturbed chain of arc elements (different weights
                        per element): K, D, d(Ma)/dq vs central differences
     insert             vlbe_ale_chain_insert into a rational element: r, r'
                        at 1000 material points, the parts' weights (those of
                        vlbe_rancf_split), the other elements intact (shifted),
                        T, U, V unchanged
     remove             vlbe_ale_chain_remove: merged weights = vlbe_rancf_merge,
                        the merged curve through the removed node at u_H (eq.
                        32), the other elements intact (shifted); on an exact
                        arc: deviation from the circle, rational vs ALE-ANCF
                        merge (printed)
     length_control     slider next to a long element: insert + remove, nn
                        kept, weights consistent; no capacity: VLBE_EWORK and
                        ch, nodes, cons, els byte-identical
     errors             vlbe_ale_chain_types on a 3D chain: VLBE_EARG; remove
                        of a node with a mass: VLBE_EARG, nothing changed */
#include "test_util.h"
#include "../rancf.h"
#include "ale_fixtures.h"
#include "rancf_fixtures.h"

#include <float.h>
#include <stdlib.h>
#include <string.h>

#define EPS ((double)VLBE_EPS)
#define FD_ERR (EPS / cbrt(EPS)) /* EPS^(2/3): error unit of a central difference */

#define NN_MAX 10          /* nodes                */
#define NE_MAX (NN_MAX - 1) /* elements             */
#define NC_MAX 8           /* constraints          */
#define N_MAX 72           /* coordinates          */
#define NPTS 1000          /* material sample points */
#define PI_D 3.14159265358979323846

/* ------------------------------------------------------------------------ */
/* helpers                                                                    */
/* ------------------------------------------------------------------------ */

/* Element arrays of the chains (a vlbe_rancf_elem is ~22 kB: static). */
static vlbe_rancf_elem els_a[NE_MAX], els_b[NE_MAX];

typedef struct rch {
    vlbe_ale_mat mat;
    vlbe_ale_node node[NN_MAX];
    vlbe_ale_con con[NC_MAX];
    vlbe_ale_chain ch;
} rch;


/* The same element (weights, material, flags, rules, ends), comparing only
   what the library defines (not the unused rule points, not padding). */
static int el_same(const vlbe_rancf_elem *a, const vlbe_rancf_elem *b)
{
    const vlbe_ale_rule *ra[3], *rb[3];
    int r;
    if (memcmp(a->k, b->k, sizeof a->k) || memcmp(&a->ale.mat, &b->ale.mat, sizeof a->ale.mat) ||
        a->ale.flags != b->ale.flags || memcmp(a->ale.ends, b->ale.ends, sizeof a->ale.ends))
        return 0;
    ra[0] = &a->ale.rm;
    ra[1] = &a->ale.rl;
    ra[2] = &a->ale.rt;
    rb[0] = &b->ale.rm;
    rb[1] = &b->ale.rl;
    rb[2] = &b->ale.rt;
    for (r = 0; r < 3; ++r)
        if (ra[r]->n != rb[r]->n || memcmp(ra[r]->g, rb[r]->g, (size_t)ra[r]->n * sizeof ra[r]->g[0]))
            return 0;
    return 1;
}

/* chain on c->node[0..nn-1] (filled by the caller) over els, then layout */
static void rch_init(rch *c, vlbe_rancf_elem *els, int nn, int nn_cap)
{
    assert_int_equal(vlbe_rancf_chain_init(&c->ch, els, c->node, nn, nn_cap, c->con, NC_MAX), VLBE_OK);
    assert_int_equal(vlbe_ale_chain_layout(&c->ch), VLBE_OK);
    assert_true(c->ch.n <= N_MAX - 4);
}

static int pidx(const vlbe_ale_chain *ch, int i)
{
    return ch->node[i].ofs + 4 + 2 * ch->node[i].slide;
}

/* max |a - b| over max |b| (0 when equal) */
static double rel_diff(int n, const vlbe_real *a, const vlbe_real *b)
{
    double d = 0.0, s = 0.0;
    int i;
    for (i = 0; i < n; ++i) {
        d = fmax(d, fabs((double)a[i] - (double)b[i]));
        s = fmax(s, fabs((double)b[i]));
    }
    return d == 0.0 ? 0.0 : d / s;
}

/* Elements on the circle of radius R about the origin from polar angle a0:
   element e spans the central angle th[e] with the weights of
   vlbe_rancf_arc (ng: Gauss orders of the elements); nodes on the circle,
   slopes the arc slopes of the element on the right (last node: on the
   left; a sliding node: left and right each of its own element).  The
   caller sets the node p's to the arc lengths (R th).  Then perturbed:
   positions by up to amp, slopes turned by up to 2 amp rad and scaled by
   1 +- amp, free p's moved by up to amp/2.  v (may be NULL): O(1) rates,
   free p' up to 0.3. */
/* c cleared, the O(1) material, nodes 0..4 with fixed p at the arc lengths
   R th[0..3] of four arcs; returns the last node's p */
static double arc_nodes(rch *c, const double *th, double R)
{
    double p = 0.0;
    int i;
    memset(c, 0, sizeof *c);
    c->mat = mat_std();
    for (i = 0; i < 5; ++i) {
        c->node[i] = node_make(VLBE_ALE_PFIXED, p);
        if (i < 4) p += R * th[i];
    }
    return p;
}

static void arc_setup(rch *c, vlbe_rancf_elem *els, const double *th, double R, double a0,
                      int ng, tu_rng *g, double amp, vlbe_real *q, vlbe_real *v)
{
    const vlbe_ale_chain *ch = &c->ch;
    const int ne = ch->nn - 1;
    const vlbe_real c0[2] = {0, 0};
    vlbe_real x[NE_MAX][8], w[4];
    double a = a0;
    int e, i, s, k;
    for (e = 0; e < ne; ++e) {
        assert_int_equal(vlbe_rancf_arc(c0, (vlbe_real)R, (vlbe_real)a, (vlbe_real)th[e], w, x[e]),
                         VLBE_OK);
        rancf_el_init(&els[e], &c->mat, w, ng);
        a += th[e];
    }
    for (i = 0; i < ch->nn; ++i) {
        const vlbe_ale_node *nd = &ch->node[i];
        const int o = nd->ofs;
        const vlbe_real *pos = i < ne ? x[i] : x[ne - 1] + 4;
        q[o] = (vlbe_real)((double)pos[0] + amp * tu_rng_uniform(g));
        q[o + 1] = (vlbe_real)((double)pos[1] + amp * tu_rng_uniform(g));
        for (s = 0; s <= nd->slide; ++s) {
            /* s = 0: the left slope of a sliding node, else the node's slope */
            const int right = !(nd->slide && s == 0);
            const vlbe_real *sl = (right && i < ne) || i == 0 ? x[i] + 2 : x[i - 1] + 6;
            const double ang = 2.0 * amp * tu_rng_uniform(g), m = 1.0 + amp * tu_rng_uniform(g);
            q[o + 2 + 2 * s] = (vlbe_real)(m * (cos(ang) * (double)sl[0] - sin(ang) * (double)sl[1]));
            q[o + 3 + 2 * s] = (vlbe_real)(m * (sin(ang) * (double)sl[0] + cos(ang) * (double)sl[1]));
        }
        if (v)
            for (k = 0; k < 4 + 2 * nd->slide; ++k) v[o + k] = (vlbe_real)tu_rng_uniform(g);
        if (nd->pmode == VLBE_ALE_PFREE) {
            q[pidx(ch, i)] = (vlbe_real)((double)nd->p + 0.5 * amp * tu_rng_uniform(g));
            if (v) v[pidx(ch, i)] = (vlbe_real)(0.3 * tu_rng_uniform(g));
        }
    }
}

/* r(p), r'(p) of the chain at NPTS material points spread over its
   material span [pa, pb] (interleaved x, y) */
static void sample(const vlbe_ale_chain *ch, vlbe_real t, const vlbe_real *q, double pa, double pb,
                   double *r, double *rp)
{
    int k;
    for (k = 0; k < NPTS; ++k) {
        const vlbe_real p = (vlbe_real)(pa + (pb - pa) * (k + 0.5) / NPTS);
        vlbe_real rr[2], rr1[2];
        assert_int_equal(vlbe_ale_chain_point(ch, t, q, p, rr, rr1), VLBE_OK);
        r[2 * k] = (double)rr[0];
        r[2 * k + 1] = (double)rr[1];
        rp[2 * k] = (double)rr1[0];
        rp[2 * k + 1] = (double)rr1[1];
    }
}

static double dmax_diff(int n, const double *a, const double *b, double *scale)
{
    double d = 0.0, s = 0.0;
    int i;
    for (i = 0; i < n; ++i) {
        d = fmax(d, fabs(a[i] - b[i]));
        s = fmax(s, fabs(b[i]));
    }
    *scale = s;
    return d;
}

/* ======================================================================= */
/* 1. unit weights: the rational chain is the ALE-ANCF chain                */
/* ======================================================================= */

static vlbe_ale_elem u_el;
static vlbe_real u_A[N_MAX * N_MAX], u_B[N_MAX * N_MAX], u_C[N_MAX * N_MAX],
    u_D[N_MAX * N_MAX];

/* nodes 0 fixed, 1 fixed, 2 free + sliding + point mass, 3 prescribed
   (p = 0.9 + 0.2 t - 0.2 t^2), 4 free, 5 fixed */
static void unit_nodes(vlbe_ale_node *nd)
{
    nd[0] = node_make(VLBE_ALE_PFIXED, 0.0);
    nd[1] = node_make(VLBE_ALE_PFIXED, 0.3);
    nd[2] = node_make(VLBE_ALE_PFREE, 0.62);
    nd[2].slide = 1;
    nd[2].mass = VLBE_R(0.5);
    nd[3] = node_make(VLBE_ALE_PPRESCRIBED, 0.9);
    nd[3].pd = VLBE_R(0.2);
    nd[3].pdd = VLBE_R(-0.4);
    nd[4] = node_make(VLBE_ALE_PFREE, 1.2);
    nd[5] = node_make(VLBE_ALE_PFIXED, 1.5);
    nd[5].mass = VLBE_R(0.3);
}

/* Tolerance 0: with w = 1 the rational basis is the Hermite basis in
   floating point, not only in exact arithmetic.  The numerators' monomial
   coefficients (vlbe__rancf_g) are then exactly those of
   vlbe_herm_ale_eval's table ({1,0,-3,2}, {0,1,-2,1}, ...: k_i = 1 and
   integer arithmetic), W = n1 + n3 sums to the coefficients {1,0,0,0}
   exactly, so W = 1, W' = W'' = ... = 0, and the quotient rule
   g = (n - sum C g W^(c-i)) / W subtracts exact zeros and divides by 1;
   both then go through the same vlbe__ale_basis_fill and the same
   kernels.  Only the sign of a zero could differ, which == ignores.
   Measured: every difference 0 (m:uw_rel) in double, 0 (m@flt:uw_rel) in
   float. */
static void test_unit_weights(void **state)
{
    static rch c;
    static vlbe_ale_node an[NN_MAX];
    static vlbe_ale_chain ach;
    const vlbe_real w1[4] = {1, 1, 1, 1};
    double worst = 0.0;
    int variant;
    (void)state;
    for (variant = 0; variant < 2; ++variant) {
        const unsigned mode = variant ? VLBE_ALE_CONSERVATIVE : 0u;
        tu_rng g = tu_rng_seed(11 + (uint64_t)variant);
        vlbe_real q[N_MAX], v[N_MAX], a[N_MAX], Qr[N_MAX], Qa[N_MAX], Er[3], Ea[3];
        vlbe_real lr, la, rr, ra;
        int n, i, e, k;
        memset(&c, 0, sizeof c);
        c.mat = mat_std();
        unit_nodes(c.node);
        memcpy(an, c.node, sizeof an);
        rch_init(&c, els_a, 6, NN_MAX);
        for (e = 0; e < 5; ++e) rancf_el_init(&els_a[e], &c.mat, w1, 0);
        assert_int_equal(vlbe_ale_elem_init(&u_el, &c.mat, 0u, 0, 0, 0), VLBE_OK);
        assert_int_equal(vlbe_ale_chain_init(&ach, &u_el, an, 6, NN_MAX, NULL, 0), VLBE_OK);
        c.ch.mode = ach.mode = mode;
        c.ch.g[0] = ach.g[0] = VLBE_R(0.4);
        c.ch.g[1] = ach.g[1] = VLBE_R(-1.2);
        assert_int_equal(vlbe_ale_chain_layout(&c.ch), VLBE_OK);
        assert_int_equal(vlbe_ale_chain_layout(&ach), VLBE_OK);
        n = c.ch.n;
        assert_int_equal(n, ach.n);
        assert_int_equal(n, 4 + 4 + 7 + 4 + 5 + 4);
        /* a random curved state: chord at angle 0.6, slopes turned +-0.4 rad */
        for (i = 0; i < 6; ++i) {
            const vlbe_ale_node *nd = &c.node[i];
            const int o = nd->ofs;
            const double dp = (double)nd->p;
            q[o] = (vlbe_real)(1.02 * dp * cos(0.6) + 0.03 * tu_rng_uniform(&g));
            q[o + 1] = (vlbe_real)(1.02 * dp * sin(0.6) + 0.03 * tu_rng_uniform(&g));
            for (k = 0; k <= nd->slide; ++k) {
                const double an_ = 0.6 + 0.4 * tu_rng_uniform(&g), m = 1.0 + 0.06 * tu_rng_uniform(&g);
                q[o + 2 + 2 * k] = (vlbe_real)(m * cos(an_));
                q[o + 3 + 2 * k] = (vlbe_real)(m * sin(an_));
            }
            for (k = 0; k < 4 + 2 * nd->slide; ++k) v[o + k] = (vlbe_real)tu_rng_uniform(&g);
            if (nd->pmode == VLBE_ALE_PFREE) {
                q[pidx(&c.ch, i)] = (vlbe_real)(dp + 0.02 * tu_rng_uniform(&g));
                v[pidx(&c.ch, i)] = (vlbe_real)(0.3 * tu_rng_uniform(&g));
            }
        }
        for (i = 0; i < n; ++i) a[i] = (vlbe_real)tu_rng_uniform(&g);
        {
            const vlbe_real t = VLBE_R(0.4);
            double d;
            assert_int_equal(vlbe_ale_chain_mass(&c.ch, t, q, v, u_A), 0);
            assert_int_equal(vlbe_ale_chain_mass(&ach, t, q, v, u_B), 0);
            d = rel_diff(n * n, u_A, u_B);
            worst = fmax(worst, d);
            ASSERT_VEC_CLOSE(u_A, u_B, n * n, 0, 0);
            assert_int_equal(vlbe_ale_chain_force(&c.ch, t, q, v, Qr), 0);
            assert_int_equal(vlbe_ale_chain_force(&ach, t, q, v, Qa), 0);
            worst = fmax(worst, rel_diff(n, Qr, Qa));
            ASSERT_VEC_CLOSE(Qr, Qa, n, 0, 0);
            assert_int_equal(vlbe_ale_chain_force_jac(&c.ch, t, q, v, u_A, u_B), 0);
            assert_int_equal(vlbe_ale_chain_force_jac(&ach, t, q, v, u_C, u_D), 0);
            worst = fmax(worst, fmax(rel_diff(n * n, u_A, u_C), rel_diff(n * n, u_B, u_D)));
            ASSERT_VEC_CLOSE(u_A, u_C, n * n, 0, 0);
            ASSERT_VEC_CLOSE(u_B, u_D, n * n, 0, 0);
            assert_int_equal(vlbe_ale_chain_mass_jac(&c.ch, t, q, v, a, u_A, NULL), 0);
            assert_int_equal(vlbe_ale_chain_mass_jac(&ach, t, q, v, a, u_C, NULL), 0);
            worst = fmax(worst, rel_diff(n * n, u_A, u_C));
            ASSERT_VEC_CLOSE(u_A, u_C, n * n, 0, 0);
            assert_int_equal(vlbe_ale_chain_energy(&c.ch, t, q, v, Er), VLBE_OK);
            assert_int_equal(vlbe_ale_chain_energy(&ach, t, q, v, Ea), VLBE_OK);
            worst = fmax(worst, rel_diff(3, Er, Ea));
            ASSERT_VEC_CLOSE(Er, Ea, 3, 0, 0);
            assert_int_equal(vlbe_ale_chain_length(&c.ch, t, q, v, &lr, &rr), VLBE_OK);
            assert_int_equal(vlbe_ale_chain_length(&ach, t, q, v, &la, &ra), VLBE_OK);
            assert_true(lr == la && rr == ra);
            for (k = 0; k < 101; ++k) { /* points, also exactly at the nodes */
                const vlbe_real p = (vlbe_real)(0.015 * k);
                vlbe_real r1[2], p1[2], r2[2], p2[2];
                assert_int_equal(vlbe_ale_chain_point(&c.ch, t, q, p, r1, p1), VLBE_OK);
                assert_int_equal(vlbe_ale_chain_point(&ach, t, q, p, r2, p2), VLBE_OK);
                ASSERT_VEC_CLOSE(r1, r2, 2, 0, 0);
                ASSERT_VEC_CLOSE(p1, p2, 2, 0, 0);
            }
        }
    }
    tu_report("unit weights: M, Q, K, D, Mq, E vs ALE-ANCF (rel)", worst, 0.0);
    tu_measured("uw_rel", worst);
}

/* ======================================================================= */
/* 2. arc chain: K, D, d(Ma)/dq vs central differences                      */
/* ======================================================================= */

enum { FD_Q_OF_Q, FD_Q_OF_V, FD_MA_OF_Q };

typedef struct fd_ctx {
    vlbe_ale_chain *ch;
    int which, j;
    vlbe_real t;
    const vlbe_real *q, *v, *a;
} fd_ctx;

static vlbe_real fd_M[N_MAX * N_MAX];

static double fd_fn(void *vc, double x, double *out)
{
    const fd_ctx *f = (const fd_ctx *)vc;
    const int n = f->ch->n;
    const vlbe_real xr = (vlbe_real)x;
    vlbe_real q[N_MAX], v[N_MAX], Q[N_MAX];
    int i, k;
    memcpy(q, f->q, (size_t)n * sizeof *q);
    memcpy(v, f->v, (size_t)n * sizeof *v);
    if (f->which == FD_Q_OF_V) v[f->j] = xr;
    else q[f->j] = xr;
    if (f->which == FD_MA_OF_Q) {
        assert_int_equal(vlbe_ale_chain_mass(f->ch, f->t, q, v, fd_M), 0);
        for (i = 0; i < n; ++i) {
            out[i] = 0.0;
            for (k = 0; k < n; ++k) out[i] += (double)fd_M[i * n + k] * (double)f->a[k];
        }
    } else {
        assert_int_equal(vlbe_ale_chain_force(f->ch, f->t, q, v, Q), 0);
        for (i = 0; i < n; ++i) out[i] = (double)Q[i];
    }
    return (double)xr;
}

/* Length over which the chain functions vary (elements 0.6 - 1.1 long,
   curvature ~1, stiffness terms ~L^-5): the step is EPS^(1/3) FD_LEN. */
#define FD_LEN 0.125

/* Column j of J (n x n, J[i][j] = d f_i / d x_j) vs the central
   difference, held to tol (max |column j| + max |f|): the truncation part
   of the difference error scales with the derivatives, the rounding part
   (EPS |f| / h) with f.  Returns the worst error / that scale. */
static double check_cols(fd_ctx *f, int which, const vlbe_real *J, double tol, const char *what)
{
    const int n = f->ch->n;
    double d[N_MAX], work[N_MAX], f0[N_MAX], worst = 0.0, fs;
    int i, j;
    f->which = which;
    f->j = 0;
    fd_fn(f, which == FD_Q_OF_V ? (double)f->v[0] : (double)f->q[0], f0);
    fs = tu_max_abs(n, f0);
    for (j = 0; j < n; ++j) {
        const double x = which == FD_Q_OF_V ? (double)f->v[j] : (double)f->q[j];
        double cs = 0.0;
        f->j = j;
        tu_central_diff(fd_fn, f, x, tu_fd_step(EPS, FD_LEN * fmax(1.0, fabs(x))), n, work, d);
        for (i = 0; i < n; ++i) cs = fmax(cs, fmax(fabs(d[i]), fabs((double)J[i * n + j])));
        for (i = 0; i < n; ++i) {
            const double a = (double)J[i * n + j], scale = cs + fs;
            worst = fmax(worst, fabs(a - d[i]) / scale);
            ASSERT_CLOSE_CTX(a, d[i], 0, tol * scale, "%s: entry (%d, %d), column max %.3g, |f| %.3g",
                             what, i, j, cs, fs);
        }
    }
    return worst;
}

static vlbe_real fd_K[N_MAX * N_MAX], fd_D[N_MAX * N_MAX], fd_Mq[N_MAX * N_MAX];

/* Tolerance 64 FD_ERR (2.4e-9 double, 1.5e-3 float) on the column scale:
   the size test_chain_ale.c's assembly check uses for the same kernels
   (third derivatives tens of times the entries: L^-5, |r'|^-5, p'^2 N_pp
   terms); the rational basis adds W^-1 factors of size ~1 (arc weights
   0.9 - 0.98).  The step EPS^(1/3) FD_LEN balances truncation and
   rounding in float too (FD_ERR = 2.4e-5 there), so no check is skipped.
   Chain: nodes fixed, free, free + sliding + mass, prescribed (p'' != 0:
   the inertia term -M ae in Q and K), fixed; damping, load, gravity. */
static void test_arc_fd(void **state)
{
    static rch c;
    const double tol = 64.0 * FD_ERR, th[4] = {0.6, 0.9, 0.7, 1.1}, R = 1.0;
    double wk = 0.0, wd = 0.0, wm = 0.0;
    int variant;
    (void)state;
    for (variant = 0; variant < 2; ++variant) {
        tu_rng g = tu_rng_seed(202 + (uint64_t)variant);
        vlbe_real q[N_MAX], v[N_MAX], a[N_MAX];
        fd_ctx f;
        int i;
        (void)arc_nodes(&c, th, R);
        c.node[1].pmode = VLBE_ALE_PFREE;
        c.node[2].pmode = VLBE_ALE_PFREE;
        c.node[2].slide = 1;
        c.node[2].mass = VLBE_R(0.4);
        c.node[3].pmode = VLBE_ALE_PPRESCRIBED;
        c.node[3].pd = VLBE_R(0.25);
        c.node[3].pdd = VLBE_R(-0.6);
        rch_init(&c, els_a, 5, NN_MAX);
        c.ch.mode = variant ? VLBE_ALE_CONSERVATIVE : 0u;
        c.ch.g[0] = VLBE_R(0.3);
        c.ch.g[1] = VLBE_R(-1.0);
        arc_setup(&c, els_a, th, R, 0.3, 0, &g, 0.03, q, v);
        /* the weights differ per element: w1 = (1 + 2 cos(th/2))/3 */
        assert_true(els_a[0].k[1] != els_a[1].k[1] && els_a[1].k[1] != els_a[3].k[1]);
        for (i = 0; i < c.ch.n; ++i) a[i] = (vlbe_real)(2.0 * tu_rng_uniform(&g));
        f.ch = &c.ch;
        f.t = VLBE_R(0.4);
        f.q = q;
        f.v = v;
        f.a = a;
        assert_int_equal(vlbe_ale_chain_force_jac(&c.ch, f.t, q, v, fd_K, fd_D), 0);
        assert_int_equal(vlbe_ale_chain_mass_jac(&c.ch, f.t, q, v, a, fd_Mq, NULL), 0);
        wk = fmax(wk, check_cols(&f, FD_Q_OF_Q, fd_K, tol, "K = dQ/dq"));
        wd = fmax(wd, check_cols(&f, FD_Q_OF_V, fd_D, tol, "D = dQ/dv"));
        wm = fmax(wm, check_cols(&f, FD_MA_OF_Q, fd_Mq, tol, "Mq = d(M a)/dq"));
    }
    tu_report("arc chain K = dQ/dq, worst / column scale", wk, tol);
    tu_report("arc chain D = dQ/dv", wd, tol);
    tu_report("arc chain Mq = d(M a)/dq", wm, tol);
}

/* T and U of the chain by a composite rule of our own: every element cut
   into 8 pieces, 8 Gauss points each (the rational integrands are then
   integrated to far below rounding), from the element's own r'(p), strain
   and curvature (vlbe_rancf_point, vlbe_rancf_strain) and its material
   velocity N(p) v (the chain's p's fixed: p' = 0).  TU[0] = 1/2 int rhoA
   |v|^2, TU[1] = 1/2 int (EA eps^2 + EI kap^2). */
static void composite_TU(const vlbe_ale_chain *ch, const vlbe_rancf_elem *els, const vlbe_real *q,
                         const vlbe_real *v, double *TU)
{
    const vlbe_real *xi, *w;
    int e, s, k, idx[10];
    TU[0] = TU[1] = 0.0;
    assert_int_equal(vlbe_gl_rule(8, &xi, &w), VLBE_OK);
    for (e = 0; e + 1 < ch->nn; ++e) {
        const vlbe_rancf_elem *el = &els[e];
        vlbe_real qe[10], ve[10], vq[10];
        unsigned md;
        double h;
        assert_int_equal(vlbe_ale_chain_gather(ch, e, VLBE_R(0.0), q, v, qe, ve, idx, &md), VLBE_OK);
        memcpy(vq, ve, sizeof vq);
        vq[4] = qe[4];
        vq[9] = qe[9];
        h = ((double)qe[9] - (double)qe[4]) / 8.0;
        for (s = 0; s < 8; ++s)
            for (k = 0; k < 8; ++k) {
                const double pd = (double)qe[4] + h * (s + 0.5 * (1.0 + (double)xi[k]));
                const double wk = 0.5 * h * (double)w[k];
                vlbe_real vel[2] = {0, 0}, eps = 0, kap = 0;
                assert_int_equal(vlbe_rancf_point(el, vq, (vlbe_real)pd, vel, NULL), VLBE_OK);
                assert_int_equal(vlbe_rancf_strain(el, qe, (vlbe_real)pd, &eps, &kap), VLBE_OK);
                TU[0] += wk * 0.5 * (double)el->ale.mat.rhoA *
                         ((double)vel[0] * (double)vel[0] + (double)vel[1] * (double)vel[1]);
                TU[1] += wk * 0.5 * ((double)el->ale.mat.EA * (double)eps * (double)eps +
                                     (double)el->ale.mat.EI * (double)kap * (double)kap);
            }
    }
}

/* ======================================================================= */
/* 3. insert into a rational element                                         */
/* ======================================================================= */

static double s_r0[2 * NPTS], s_rp0[2 * NPTS], s_r1[2 * NPTS], s_rp1[2 * NPTS];

/* r, r': tolerance 64 EPS of the chain's size (|r| ~ 1.3, |r'| ~ 1).  The
   split is exact in exact arithmetic (de Casteljau on the homogeneous
   control points); in floating point the new node's r, r' and the parts'
   weights carry a few roundings each, and evaluating a part (basis of the
   part's weights at its own u) rounds differently from the original: a
   few EPS, amplified by the basis' sums (|N| up to ~1.5).
   Energies, composite rule (composite_TU): T and U before and after within
   64 EPS of |T| + |U|: the same functional of the same curve, strain,
   curvature and velocity field, summed over other points (the pieces cut
   at ph), so rounding only -- of the curvature (second derivatives, ~L^-2
   W^-3 of the rounded weights) mostly.  The split element's ends have
   p' = 0 (fixed nodes): the parts' velocity field is the original's
   (rancf.h: with moving ends it is not), so T is unchanged too.
   The library's T, U, V (vlbe_ale_chain_energy, Gauss order 8, the
   largest): tolerance 1e-12 of |T| + |U| + |V| in double.  V is linear
   in r: equal; T and U have rational integrands that no Gauss rule
   integrates exactly, and the parts' rules sample other points: the
   difference is the rule error, not rounding (it falls with the Gauss
   order).  Measured at order 8: T differs by 1.5e-13 (m:ins_T) of T, U
   by 2.5e-12 (m:ins_U) of U = 0.86 (m:ins_Uval), 3.4e-13 (m:ins_de) of
   the sum.  Float: 64 EPS (the rule error is far below rounding
   there). */
static void test_insert(void **state)
{
    static rch c;
    const double th[4] = {0.5, 0.8, 0.6, 0.9}, R = 1.2;
    const double tol_r = 64.0 * EPS;
    const double tol_e = sizeof(vlbe_real) == sizeof(float) ? 64.0 * EPS : 1e-12;
    tu_rng g = tu_rng_seed(303);
    vlbe_real q[N_MAX], v[N_MAX], qn[N_MAX], vn[N_MAX], qe[10], ve[10], qh[5], qhd[5], wl[4],
        wr[4], E0[3], E1[3];
    double p = 0.0, pend, sc, dr, drp, de, es, tu0[2], tu1[2], dc;
    const double tol_c = 64.0 * EPS;
    int idx[10], i, e;
    unsigned md;
    const int es_ = 1;
    (void)state;
    p = arc_nodes(&c, th, R);
    pend = p;
    rch_init(&c, els_a, 5, NN_MAX);
    arc_setup(&c, els_a, th, R, -0.4, 8, &g, 0.03, q, v);
    memcpy(els_b, els_a, sizeof els_b);
    {
        const vlbe_real t = VLBE_R(0.0);
        const vlbe_real ph = (vlbe_real)((double)c.node[es_].p + 0.37 * R * th[es_]);
        assert_int_equal(vlbe_ale_chain_gather(&c.ch, es_, t, q, v, qe, ve, idx, &md), VLBE_OK);
        assert_int_equal(vlbe_rancf_split(&els_b[es_], qe, ve, ph, qh, qhd, wl, wr), VLBE_OK);
        sample(&c.ch, t, q, 0.0, pend, s_r0, s_rp0);
        assert_int_equal(vlbe_ale_chain_energy(&c.ch, t, q, v, E0), VLBE_OK);
        composite_TU(&c.ch, els_a, q, v, tu0);
        assert_int_equal(vlbe_ale_chain_insert(&c.ch, es_, ph, t, q, v, qn, vn), VLBE_OK);
        assert_int_equal(c.ch.nn, 6);
        assert_true(c.node[es_ + 1].p == ph);
        /* the parts' weights are vlbe_rancf_split's (w3 = 1: k = w exactly) */
        ASSERT_VEC_CLOSE(els_a[es_].k, wl, 4, 0, 0);
        ASSERT_VEC_CLOSE(els_a[es_ + 1].k, wr, 4, 0, 0);
        assert_true(els_a[es_].ale.rm.n == 8 && els_a[es_ + 1].ale.rt.n == 8);
        /* the other elements intact, the later ones shifted up by one */
        for (e = 0; e < 4; ++e)
            if (e != es_) assert_true(el_same(&els_a[e < es_ ? e : e + 1], &els_b[e]));
        /* the new node is qh, the rates qhd */
        for (i = 0; i < 4; ++i) {
            assert_true(qn[c.node[es_ + 1].ofs + i] == qh[i]);
            assert_true(vn[c.node[es_ + 1].ofs + i] == qhd[i]);
        }
        sample(&c.ch, t, qn, 0.0, pend, s_r1, s_rp1);
        dr = dmax_diff(2 * NPTS, s_r1, s_r0, &sc) / sc;
        drp = dmax_diff(2 * NPTS, s_rp1, s_rp0, &sc) / sc;
        assert_true(dr <= tol_r);
        assert_true(drp <= tol_r);
        assert_int_equal(vlbe_ale_chain_energy(&c.ch, t, qn, vn, E1), VLBE_OK);
        es = fabs((double)E0[0]) + fabs((double)E0[1]) + fabs((double)E0[2]);
        de = 0.0;
        for (i = 0; i < 3; ++i) {
            de = fmax(de, fabs((double)E1[i] - (double)E0[i]) / es);
            ASSERT_CLOSE(E1[i], E0[i], 0, tol_e * es);
        }
        assert_true(fabs((double)E0[0]) > 0.1 * es && fabs((double)E0[1]) > 1e-3 * es);
        tu_measured("ins_T", fabs((double)E1[0] - (double)E0[0]) / fabs((double)E0[0]));
        tu_measured("ins_U", fabs((double)E1[1] - (double)E0[1]) / fabs((double)E0[1]));
        tu_measured("ins_Uval", (double)E0[1]);
        /* the composite rule: rounding only */
        composite_TU(&c.ch, els_a, qn, vn, tu1);
        dc = fmax(fabs(tu1[0] - tu0[0]), fabs(tu1[1] - tu0[1])) / (fabs(tu0[0]) + fabs(tu0[1]));
        assert_true(dc <= tol_c);
    }
    tu_report("insert: composite T, U (rel to |T|+|U|)", dc, tol_c);
    tu_report("insert: r(p) at 1000 points (rel)", dr, tol_r);
    tu_report("insert: r'(p) at 1000 points (rel)", drp, tol_r);
    tu_report("insert: T, U, V (rel to |T|+|U|+|V|)", de, tol_e);
    tu_measured("ins_de", de);
}

/* ======================================================================= */
/* 4. remove: the merged element's weights                                   */
/* ======================================================================= */

/* Deviation from the circle |r| = R over NPTS points of the chain, over R */
static double circle_dev(const vlbe_ale_chain *ch, const vlbe_real *q, double pa, double pb, double R)
{
    double dev = 0.0;
    int k;
    sample(ch, VLBE_R(0.0), q, pa, pb, s_r0, s_rp0);
    for (k = 0; k < NPTS; ++k) dev = fmax(dev, fabs(hypot(s_r0[2 * k], s_r0[2 * k + 1]) - R) / R);
    return dev;
}

static vlbe_ale_elem rm_el;

/* Merged weights: vlbe_rancf_merge of the gathered nodes, tolerance 0
   (the chain calls the same function on the same numbers; w3 = 1, so
   elem_init's k = w / w3 is exact).  Through the removed node: the merged
   curve at pH (u_H = (pH - pA)/(pB - pA), eq. 32) within 64 EPS of R:
   the least-squares problem has 2 equations and 3 unknowns of full rank,
   so its minimum-norm solution satisfies eq. 34 up to the rounding of the
   Jacobi rotations and of the right-hand side (a few EPS of |r| times the
   basis sums and 1/W ~ 1); the evaluation at pH adds a few more (measured
   1 (m~:rm_h) EPS).  The arc comparison has no tolerance: both deviations are
   printed; the rational merge is asserted to be the better one (it is by
   orders of magnitude, the brief's point of eqs. 29-38). */
static void test_remove(void **state)
{
    static rch c, c2;
    static vlbe_ale_node an[NN_MAX];
    static vlbe_ale_chain ach;
    const double th[4] = {0.5, 0.7, 0.6, 0.9}, R = 1.1, tol_h = 64.0 * EPS;
    tu_rng g = tu_rng_seed(404);
    vlbe_real q[N_MAX], v[N_MAX], qn[N_MAX], vn[N_MAX], qa[10], qb[10], k[4], r[2];
    double dh;
    int idx[10], info = -1, i, j, n0;
    unsigned md;
    const int rmv = 2;
    (void)state;
    (void)arc_nodes(&c, th, R);
    c.node[1].pmode = VLBE_ALE_PFREE;
    rch_init(&c, els_a, 5, NN_MAX);
    arc_setup(&c, els_a, th, R, 0.2, 0, &g, 0.02, q, v);
    memcpy(els_b, els_a, sizeof els_b);
    memcpy(an, c.node, sizeof an); /* the old layout */
    n0 = c.ch.n;
    assert_int_equal(vlbe_ale_chain_gather(&c.ch, rmv - 1, 0, q, NULL, qa, NULL, idx, &md), VLBE_OK);
    assert_int_equal(vlbe_ale_chain_gather(&c.ch, rmv, 0, q, NULL, qb, NULL, idx, &md), VLBE_OK);
    assert_int_equal(vlbe_rancf_merge(2, qa, qa + 5, qb + 5, k, &info), VLBE_OK);
    assert_int_equal(info, 0); /* least squares, no fallback (eq. 38) */
    assert_int_equal(vlbe_ale_chain_remove(&c.ch, rmv, 0, q, v, qn, vn), VLBE_OK);
    assert_int_equal(c.ch.nn, 4);
    assert_int_equal(c.ch.n, n0 - 4);
    ASSERT_VEC_CLOSE(els_a[rmv - 1].k, k, 4, 0, 0);
    assert_true(memcmp(&els_a[rmv - 1].ale.mat, &els_b[rmv - 1].ale.mat, sizeof(vlbe_ale_mat)) == 0);
    assert_int_equal(els_a[rmv - 1].ale.rm.n, els_b[rmv - 1].ale.rm.n);
    /* the element before intact, the one after shifted down by one */
    assert_true(el_same(&els_a[0], &els_b[0]));
    assert_true(el_same(&els_a[rmv], &els_b[rmv + 1]));
    /* the other nodes' coordinates copied */
    for (i = 0, j = 0; i < 5; ++i) {
        int m;
        if (i == rmv) continue;
        for (m = 0; m < 4 + (an[i].pmode == VLBE_ALE_PFREE); ++m) {
            assert_true(qn[c.node[j].ofs + m] == q[an[i].ofs + m]);
            assert_true(vn[c.node[j].ofs + m] == v[an[i].ofs + m]);
        }
        ++j;
    }
    /* eq. 32: through r_H at u_H */
    assert_int_equal(vlbe_ale_chain_point(&c.ch, 0, qn, qa[9], r, NULL), VLBE_OK);
    dh = hypot((double)r[0] - (double)qa[5], (double)r[1] - (double)qa[6]) / R;
    tu_report("remove: merged curve at pH vs r_H (rel R)", dh, tol_h);
    tu_measured("rm_h", dh / EPS);
    assert_true(dh <= tol_h);

    /* an exact arc of two equal elements, merged: rational vs ALE-ANCF */
    {
        static const double tot[3] = {PI_D / 4.0, PI_D / 2.0, PI_D};
        int m;
        for (m = 0; m < 3; ++m) {
            const double th2[2] = {0.5 * tot[m], 0.5 * tot[m]};
            vlbe_real q2[N_MAX], qr[N_MAX], qh[N_MAX];
            double dr, dan, d0;
            memset(&c2, 0, sizeof c2);
            c2.mat = mat_std();
            c2.node[0] = node_make(VLBE_ALE_PFIXED, 0.0);
            c2.node[1] = node_make(VLBE_ALE_PFIXED, th2[0]);
            c2.node[2] = node_make(VLBE_ALE_PFIXED, tot[m]);
            memcpy(an, c2.node, sizeof an);
            rch_init(&c2, els_a, 3, NN_MAX);
            arc_setup(&c2, els_a, th2, 1.0, 0.1, 0, &g, 0.0, q2, NULL);
            assert_int_equal(vlbe_ale_elem_init(&rm_el, &c2.mat, 0u, 0, 0, 0), VLBE_OK);
            assert_int_equal(vlbe_ale_chain_init(&ach, &rm_el, an, 3, NN_MAX, NULL, 0), VLBE_OK);
            assert_int_equal(vlbe_ale_chain_layout(&ach), VLBE_OK);
            d0 = circle_dev(&c2.ch, q2, 0.0, tot[m], 1.0); /* the two arcs: exact */
            assert_int_equal(vlbe_ale_chain_remove(&c2.ch, 1, 0, q2, NULL, qr, NULL), VLBE_OK);
            assert_int_equal(vlbe_ale_chain_remove(&ach, 1, 0, q2, NULL, qh, NULL), VLBE_OK);
            dr = circle_dev(&c2.ch, qr, 0.0, tot[m], 1.0);
            dan = circle_dev(&ach, qh, 0.0, tot[m], 1.0);
            print_message("    remove on an arc of %.4f rad (R = 1, two equal elements): max | |r| - R | "
                          "before %.2e, after: rational %.3e, ALE-ANCF %.3e\n",
                          tot[m], d0, dr, dan);
            assert_true(d0 <= 64.0 * EPS);
            assert_true(dr < dan);
        }
    }
}

/* ======================================================================= */
/* 5. length control on a rational chain                                    */
/* ======================================================================= */

/* Nodes p = 0, 0.5, 1.0 (slider: free, sliding), 2.0, 2.5 on an arc of
   radius 1.5, Lstd = 0.6: the element right of the slider (1.0 > 1.5
   Lstd) gets a node at 2.0 - Lstd = 1.4 (rule (a)) and node 1 goes (the
   merge of elements 0, 1).  Weights compared with tolerance 0: the
   chain's split and merge are vlbe_rancf_split and vlbe_rancf_merge on
   the same numbers.  No capacity (nn_cap = nn): VLBE_EWORK, and the
   chain, nodes, constraints, element array and outputs are byte-identical
   (memcmp) to before. */
static void test_length_control(void **state)
{
    static rch c;
    static vlbe_ale_chain ch0;
    static vlbe_ale_node nd0[NN_MAX];
    static vlbe_ale_con co0[NC_MAX];
    static const double pn[5] = {0.0, 0.5, 1.0, 2.0, 2.5};
    const double R = 1.5, Lstd = 0.6;
    double th[4];
    tu_rng g = tu_rng_seed(505);
    vlbe_real q[N_MAX], v[N_MAX], qn[N_MAX], vn[N_MAX], qe[10], ve[10], qa[10], qb[10], qh[5],
        wl[4], wr[4], km[4];
    vlbe_ale_con k0;
    int i, e, s, chg = -1, idx[10], n0;
    unsigned md;
    (void)state;
    memset(&c, 0, sizeof c);
    memset(els_a, 0, sizeof els_a); /* every byte defined for the memcmp below */
    c.mat = mat_std();
    for (i = 0; i < 5; ++i) c.node[i] = node_make(VLBE_ALE_PFIXED, pn[i]);
    for (i = 0; i < 4; ++i) th[i] = (pn[i + 1] - pn[i]) / R;
    c.node[2].pmode = VLBE_ALE_PFREE;
    c.node[2].slide = 1;
    c.node[2].mass = VLBE_R(0.2);
    rch_init(&c, els_a, 5, 5); /* no room for a sixth node */
    k0 = con_make(VLBE_ALE_CON_POS, 0, 0, 0, 0.0, 0.0, 0.0);
    assert_int_equal(vlbe_ale_chain_add(&c.ch, &k0), VLBE_OK);
    k0 = con_make(VLBE_ALE_CON_SLIDE_C, 2, 0, 0, 0.0, 0.0, 0.0);
    assert_int_equal(vlbe_ale_chain_add(&c.ch, &k0), VLBE_OK);
    assert_int_equal(vlbe_ale_chain_layout(&c.ch), VLBE_OK);
    n0 = c.ch.n;
    arc_setup(&c, els_a, th, R, 0.0, 0, &g, 0.02, q, v);
    for (i = 0; i < N_MAX; ++i) qn[i] = vn[i] = VLBE_R(7.0);
    memcpy(&ch0, &c.ch, sizeof ch0);
    memcpy(nd0, c.node, sizeof nd0);
    memcpy(co0, c.con, sizeof co0);
    memcpy(els_b, els_a, sizeof els_b);
    s = 2;
    assert_int_equal(
        vlbe_ale_chain_length_control(&c.ch, (vlbe_real)Lstd, 0, q, v, &s, qn, vn, &chg),
        VLBE_EWORK);
    assert_int_equal(s, 2);
    assert_memory_equal(&ch0, &c.ch, sizeof ch0);
    assert_memory_equal(nd0, c.node, sizeof nd0);
    assert_memory_equal(co0, c.con, sizeof co0);
    assert_memory_equal(els_b, els_a, sizeof els_b);
    for (i = 0; i < N_MAX; ++i) assert_true(qn[i] == VLBE_R(7.0) && vn[i] == VLBE_R(7.0));

    /* with room: insert at 1.4 (split of element 2), remove node 1 (merge of 0, 1) */
    c.ch.nn_cap = NN_MAX;
    assert_int_equal(vlbe_ale_chain_gather(&c.ch, 2, 0, q, v, qe, ve, idx, &md), VLBE_OK);
    assert_int_equal(vlbe_rancf_split(&els_b[2], qe, ve, VLBE_R(1.4), qh, NULL, wl, wr), VLBE_OK);
    assert_int_equal(vlbe_ale_chain_gather(&c.ch, 0, 0, q, NULL, qa, NULL, idx, &md), VLBE_OK);
    assert_int_equal(vlbe_ale_chain_gather(&c.ch, 1, 0, q, NULL, qb, NULL, idx, &md), VLBE_OK);
    assert_int_equal(vlbe_rancf_merge(2, qa, qa + 5, qb + 5, km, NULL), VLBE_OK);
    assert_int_equal(
        vlbe_ale_chain_length_control(&c.ch, (vlbe_real)Lstd, 0, q, v, &s, qn, vn, &chg), VLBE_OK);
    assert_int_equal(chg, 2);
    assert_int_equal(c.ch.nn, 5);
    assert_int_equal(c.ch.n, n0);
    assert_int_equal(s, 1);
    assert_true(c.node[1].slide == 1 && c.node[2].p == VLBE_R(1.4));
    assert_int_equal(c.con[1].node, 1); /* SLIDE_C followed its node */
    ASSERT_VEC_CLOSE(els_a[0].k, km, 4, 0, 0);
    ASSERT_VEC_CLOSE(els_a[1].k, wl, 4, 0, 0);
    ASSERT_VEC_CLOSE(els_a[2].k, wr, 4, 0, 0);
    assert_true(el_same(&els_a[3], &els_b[3]));
    for (e = 0; e + 1 < c.ch.nn; ++e) {
        vlbe_real p1[3], p2[3];
        int j;
        assert_int_equal(vlbe_ale_chain_pnode(&c.ch, e, 0, qn, vn, p1), VLBE_OK);
        assert_int_equal(vlbe_ale_chain_pnode(&c.ch, e + 1, 0, qn, vn, p2), VLBE_OK);
        assert_true(p1[0] < p2[0]);
        for (j = 0; j < 4; ++j) assert_true(isfinite(els_a[e].k[j]) && els_a[e].k[j] > VLBE_R(0.0));
        assert_true(els_a[e].k[3] == VLBE_R(1.0));
    }
    {
        vlbe_real E[3];
        assert_int_equal(vlbe_ale_chain_energy(&c.ch, 0, qn, vn, E), VLBE_OK);
        assert_true(vlbe_all_finite(E, 3));
    }
}

/* ======================================================================= */
/* 6. errors                                                                 */
/* ======================================================================= */

static vlbe_ale3_elem er_el3;

static void test_errors(void **state)
{
    static rch c;
    static vlbe_ale_chain ch3, ch0;
    static vlbe_ale_node n3[3], nd0[NN_MAX];
    vlbe_ale3_mat m3;
    vlbe_ale_etype et;
    const double th[4] = {0.5, 0.6, 0.7, 0.8};
    tu_rng g = tu_rng_seed(606);
    vlbe_real q[N_MAX], v[N_MAX], qn[N_MAX], vn[N_MAX];
    double p = 0.0;
    int i;
    (void)state;
    /* a 3D chain has no per-element types */
    memset(n3, 0, sizeof n3);
    memset(&m3, 0, sizeof m3); /* gcc -O2 cannot see that mat_circle writes it */
    for (i = 0; i < 3; ++i) n3[i] = node_make(VLBE_ALE_PFIXED, 0.5 * i);
    assert_int_equal(vlbe_ale3_mat_circle(&m3, VLBE_R(7800.0), VLBE_R(2.1e11), VLBE_R(8.1e10),
                                          VLBE_R(0.01)), VLBE_OK);
    assert_int_equal(vlbe_ale3_elem_init(&er_el3, &m3, 0u, 0, 0), VLBE_OK);
    assert_int_equal(vlbe_ale_chain_init3(&ch3, &er_el3, n3, 3, 3, NULL, 0), VLBE_OK);
    memset(&et, 0, sizeof et);
    assert_int_equal(vlbe_ale_chain_types(&ch3, &et, els_a), VLBE_EARG);
    assert_true(ch3.et == NULL && ch3.els == NULL);

    /* remove of a node with a mass: VLBE_EARG, nothing changed */
    memset(&c, 0, sizeof c);
    memset(els_a, 0, sizeof els_a);
    c.mat = mat_std();
    for (i = 0; i < 5; ++i) {
        c.node[i] = node_make(VLBE_ALE_PFIXED, p);
        if (i < 4) p += th[i];
    }
    c.node[2].mass = VLBE_R(0.3);
    rch_init(&c, els_a, 5, NN_MAX);
    arc_setup(&c, els_a, th, 1.0, 0.0, 0, &g, 0.02, q, v);
    memcpy(els_b, els_a, sizeof els_b);
    memcpy(&ch0, &c.ch, sizeof ch0);
    memcpy(nd0, c.node, sizeof nd0);
    for (i = 0; i < N_MAX; ++i) qn[i] = vn[i] = VLBE_R(7.0);
    assert_int_equal(vlbe_ale_chain_remove(&c.ch, 2, 0, q, v, qn, vn), VLBE_EARG);
    assert_memory_equal(els_b, els_a, sizeof els_b);
    assert_memory_equal(&ch0, &c.ch, sizeof ch0);
    assert_memory_equal(nd0, c.node, sizeof nd0);
    for (i = 0; i < N_MAX; ++i) assert_true(qn[i] == VLBE_R(7.0) && vn[i] == VLBE_R(7.0));
    /* its neighbour (plain) can go: the chain was usable */
    assert_int_equal(vlbe_ale_chain_remove(&c.ch, 1, 0, q, v, qn, vn), VLBE_OK);
    assert_int_equal(c.ch.nn, 4);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_unit_weights),
        cmocka_unit_test(test_arc_fd),
        cmocka_unit_test(test_insert),
        cmocka_unit_test(test_remove),
        cmocka_unit_test(test_length_control),
        cmocka_unit_test(test_errors),
    };
    return cmocka_run_group_tests_name("rancf_chain", tests, NULL, NULL);
}

/* test_cr2d_band.c -- cmocka suite of the banded mode of the co-rotational
   beam of corot2d.h (vlbe_cr2d_beam_band: the augmented order and band of
   the beam's callbacks) -- part of vlbe         SPDX-License-Identifier: MIT

   Tests
     band_callbacks   random beams (zigzag geometry, 1..9 elements, modes
                      0, NO_NLI, NO_DAMP, LINEAR with a floating frame, a
                      transition element at a joint) with fixes of four
                      layouts (none, clamped node 0, the sliding beam's,
                      random dofs in random order with repeats), at random
                      states: the order is the one of the definition (node
                      by node: u, v, phi, then the rows of that node's
                      fixes in the order of fix[]), a permutation of
                      0..n+m-1; kl = ku = the largest |order[a] - order[b]|
                      over the pairs an element or a fix couples (from the
                      definition, all pairs), and a nonzero entry of the
                      callbacks' matrices lies at that distance (the band
                      is not wider than the matrices need); every slot of
                      the band arrays of mass, force_jac (K, D, each alone
                      too), mass_jac (Mq, Mv) and constr_jac (Cq) equals
                      the dense callback's entry at the permuted place or
                      is 0 (multiplier rows and columns, the transpose of
                      Cq, slots outside the matrix), bit for bit: both add
                      the same element matrices in the same order onto
                      zeros; every dense entry outside the band is exactly
                      0; the vectors (Q, C, Ct, gamma) are those of the
                      dense mode bit for bit; back in dense mode (order
                      NULL) every output equals the one before, bit for bit
     band_width       the half-bandwidth does not grow with the element
                      count: ne = 1..300 give kl = ku = 5 without fixes and
                      8 clamped at node 0, clamped and pinned at the far
                      end, or with the sliding beam's fixes (u of node 0, v
                      and phi of the first half of the nodes); each the
                      value of the definition
     band_errors      order_cap < n + m: VLBE_EWORK, a fix dof outside [0,
                      n): VLBE_EARG, beam and order untouched; a banded
                      matrix callback after nfix changed (the order no
                      longer the beam's): VLBE_EARG (-1), outputs
                      untouched, the force callback unaffected; constr_jac
                      with a fix moved out of the band: VLBE_EARG, moved
                      within it: the entry at its new place; beam_init
                      restarts in dense mode; no fixes: constr_jac takes
                      Cq NULL, or writes n ld zeros
     band_relayout    the sliding beam (scenes/ex_sbeam.h) keeps its
                      banded mode across the re-layout when nodes cross the
                      exit: the order of the new fixes, kl = 8, copied
                      into its vlbe_dae
     band_wiring      vlbe_cr2d_beam_dae: the beam's callbacks, m = nfix,
                      its storage (dense, or its order, kl, ku); VLBE_EARG
                      and nothing written for an order of another nfix
   All comparisons are exact (tolerance 0): the banded and the dense
   callbacks compute the same sums in the same order, so the float build
   runs the same checks. */
#include "test_util.h"
#include "../scenes/ex_sbeam.h"
#include "cr2d_fixtures.h"

#include <string.h>

#define ARRAY_LEN(a) ((int)(sizeof(a) / sizeof((a)[0])))
#define SENTINEL VLBE_R(12345.0)

#define MAXE 9                  /* elements of the callback tests */
#define MAXN (3 * (MAXE + 1))
#define MAXM 24                 /* fixes */
#define MAXNM (MAXN + MAXM)
#define MAXBAND (MAXNM * MAXNM) /* a band array at most N x N */

static int imax(int x, int y) { return x > y ? x : y; }

/* ------------------------------------------------------------------------ */
/* the definitions, written here                                              */
/* ------------------------------------------------------------------------ */
/* The augmented order by its definition: node by node, the node's u, v,
   phi, then the rows of the fixes on the node (dof / 3) in the order of
   fix[] (a scan of all fixes per node). */
static void ref_order(int n, const vlbe_cr2d_fix *fix, int m, int *ord)
{
    int p, k, pos = 0;
    for (p = 0; p < n / 3; ++p) {
        ord[3 * p] = pos++;
        ord[3 * p + 1] = pos++;
        ord[3 * p + 2] = pos++;
        for (k = 0; k < m; ++k)
            if (fix[k].dof / 3 == p) ord[n + k] = pos++;
    }
}

/* The largest |ord[a] - ord[b]| over every pair a, b an element couples
   (its 6 coordinates, all 36 pairs) and every (row n + k, fix[k].dof). */
static int ref_width(int ne, int n, const vlbe_cr2d_fix *fix, int m, const int *ord)
{
    int e, i, j, k, w = 0;
    for (e = 0; e < ne; ++e)
        for (i = 0; i < 6; ++i)
            for (j = 0; j < 6; ++j) w = imax(w, abs(ord[3 * e + i] - ord[3 * e + j]));
    for (k = 0; k < m; ++k) w = imax(w, abs(ord[n + k] - ord[fix[k].dof]));
    return w;
}

/* order[0..N-1] is a permutation of 0..N-1; inv its inverse */
static void check_perm(int N, const int *order, int *inv)
{
    int i;
    for (i = 0; i < N; ++i) inv[i] = -1;
    for (i = 0; i < N; ++i) {
        assert_true(order[i] >= 0 && order[i] < N);
        assert_int_equal(inv[order[i]], -1);
        inv[order[i]] = i;
    }
}

/* ------------------------------------------------------------------------ */
/* beams                                                                      */
/* ------------------------------------------------------------------------ */
/* A beam of ne elements and its fixes, the joint and the frame. */
typedef struct bcase {
    vlbe_cr2d_elem el[MAXE];
    vlbe_cr2d_fix fix[MAXM];
    vlbe_cr2d_fix frame;
    vlbe_cr2d_joint jt;
    vlbe_cr2d_beam bm;
    int ne, n, m;
} bcase;

enum { LAY_NONE, LAY_CLAMP, LAY_SLIDE, LAY_RANDOM, N_LAY };
enum { KIND_PLAIN, KIND_LINEAR_FRAME, KIND_TRANS, N_KIND };

/* The fixes of a layout: none; u, v, phi of node 0; the sliding beam's (u
   of node 0, v and phi of nodes 0..nin); m random dofs in random order
   (repeats allowed). */
static int make_fixes(int lay, int n, int nin, tu_rng *g, vlbe_cr2d_fix *fix)
{
    int m = 0, i;
    memset(fix, 0, sizeof(vlbe_cr2d_fix) * MAXM);
    if (lay == LAY_CLAMP) {
        for (i = 0; i < 3; ++i) fix[m++].dof = i;
    } else if (lay == LAY_SLIDE) {
        fix[m++].dof = 0;
        for (i = 0; i <= nin; ++i) {
            fix[m++].dof = 3 * i + 1;
            fix[m++].dof = 3 * i + 2;
        }
    } else if (lay == LAY_RANDOM) {
        const int cnt = 1 + (int)(0.5 * (tu_rng_uniform(g) + 1.0) * 10.0); /* 1..10 */
        for (i = 0; i < cnt; ++i) {
            int d = (int)(0.5 * (tu_rng_uniform(g) + 1.0) * n);
            fix[m++].dof = d < n ? d : n - 1;
        }
        fix[m++].dof = n - 1; /* the last coordinate: rows after the last node */
    }
    for (i = 0; i < m; ++i) {
        fix[i].g[0] = (vlbe_real)(0.1 * tu_rng_uniform(g));
        fix[i].g[1] = (vlbe_real)(0.5 * tu_rng_uniform(g));
        fix[i].g[2] = (vlbe_real)tu_rng_uniform(g);
    }
    return m;
}

/* kind PLAIN, LINEAR_FRAME: a zigzag (random element angles in +-0.8 rad,
   lengths 0.5..1), the O(1) material varied per element; TRANS: straight
   along the joint's axis (angle 0.4 rad through C = (0.3, -0.2)), element
   nin across the exit (its node 1 0.2 L inside).  lay: the fixes. */
static void bcase_make(bcase *c, int ne, int kind, int lay, tu_rng *g)
{
    const double ax = 0.4, h = 0.6, Cx = 0.3, Cy = -0.2;
    const int nin = ne / 2;
    double x = 0.2, y = -0.1;
    int e;
    memset(c, 0, sizeof *c);
    c->ne = ne;
    c->n = 3 * (ne + 1);
    for (e = 0; e < ne; ++e) {
        vlbe_cr2d_mat mt = cr_mat_unit();
        const unsigned fl = kind == KIND_LINEAR_FRAME ? VLBE_CR2D_LINEAR : 0u;
        mt.EI = (vlbe_real)((double)mt.EI * (1.0 + 0.3 * e));
        mt.rhoA = (vlbe_real)((double)mt.rhoA * (1.0 + 0.1 * tu_rng_uniform(g)));
        if (kind == KIND_TRANS) {
            const double s1 = h * (e - nin - 0.2), s2 = h * (e + 1 - nin - 0.2);
            cr_elem_make(&c->el[e], &mt, Cx + s1 * cos(ax), Cy + s1 * sin(ax), Cx + s2 * cos(ax),
                         Cy + s2 * sin(ax), fl);
        } else {
            const double L = 0.75 + 0.25 * tu_rng_uniform(g), a0 = 0.8 * tu_rng_uniform(g);
            cr_elem_polar(&c->el[e], &mt, x, y, L, a0, fl);
            x = (double)c->el[e].X[2];
            y = (double)c->el[e].X[3];
        }
    }
    c->m = make_fixes(lay, c->n, nin, g, c->fix);
    assert_int_equal(vlbe_cr2d_beam_init(&c->bm, c->el, ne, c->fix, c->m), VLBE_OK);
    assert_true(c->bm.order == NULL); /* dense by default */
    if (kind == KIND_LINEAR_FRAME) {
        c->frame.g[0] = VLBE_R(0.7);
        c->frame.g[1] = VLBE_R(1.3);
        c->frame.g[2] = VLBE_R(-0.4);
        c->bm.frame = &c->frame;
    } else if (kind == KIND_TRANS) {
        c->jt.C[0] = (vlbe_real)Cx;
        c->jt.C[1] = (vlbe_real)Cy;
        c->jt.a[0] = (vlbe_real)cos(ax);
        c->jt.a[1] = (vlbe_real)sin(ax);
        c->bm.joint = &c->jt;
        c->bm.trans = nin;
    }
}

/* A random state: displacements up to 0.05 (0.02 h along the joint for
   TRANS, so node 1 of the transition element stays inside and node 2
   outside), rotations 0.3 rad plus two turns (0.05 rad for TRANS),
   velocities and accelerations O(1). */
static void rand_state(const bcase *c, int kind, tu_rng *g, vlbe_real *q, vlbe_real *v,
                       vlbe_real *a)
{
    const double du = kind == KIND_TRANS ? 0.012 : 0.05;
    const double turns = kind == KIND_TRANS ? 0.0 : 4.0 * CR_PI;
    const double dphi = kind == KIND_TRANS ? 0.05 : 0.3;
    int i;
    for (i = 0; i < c->n; i += 3) {
        q[i] = (vlbe_real)(du * tu_rng_uniform(g));
        q[i + 1] = (vlbe_real)(du * tu_rng_uniform(g));
        q[i + 2] = (vlbe_real)(turns + dphi * tu_rng_uniform(g));
    }
    for (i = 0; i < c->n; ++i) {
        v[i] = (vlbe_real)tu_rng_uniform(g);
        a[i] = (vlbe_real)tu_rng_uniform(g);
    }
}

/* ------------------------------------------------------------------------ */
/* the outputs of every callback                                              */
/* ------------------------------------------------------------------------ */
typedef struct outs {
    vlbe_real M[MAXBAND], K[MAXBAND], D[MAXBAND], K1[MAXBAND], D1[MAXBAND], Mq[MAXBAND],
        Mv[MAXBAND], Cq[MAXBAND];
    vlbe_real Q[MAXN], C[MAXM], Ct[MAXM], gam[MAXM];
} outs;

/* All callbacks at (t, q, v, a) into o, every array prefilled with the
   sentinel (so that a slot left unwritten shows); each returns 0. */
static void run_all(bcase *c, vlbe_real t, const vlbe_real *q, const vlbe_real *v,
                    const vlbe_real *a, outs *o)
{
    vlbe_cr2d_beam *b = &c->bm;
    cr_fill(MAXBAND, SENTINEL, o->M);
    cr_fill(MAXBAND, SENTINEL, o->K);
    cr_fill(MAXBAND, SENTINEL, o->D);
    cr_fill(MAXBAND, SENTINEL, o->K1);
    cr_fill(MAXBAND, SENTINEL, o->D1);
    cr_fill(MAXBAND, SENTINEL, o->Mq);
    cr_fill(MAXBAND, SENTINEL, o->Mv);
    cr_fill(MAXBAND, SENTINEL, o->Cq);
    assert_int_equal(vlbe_cr2d_beam_mass(b, t, q, v, o->M), 0);
    assert_int_equal(vlbe_cr2d_beam_force(b, t, q, v, o->Q), 0);
    assert_int_equal(vlbe_cr2d_beam_force_jac(b, t, q, v, o->K, o->D), 0);
    assert_int_equal(vlbe_cr2d_beam_force_jac(b, t, q, v, o->K1, NULL), 0);
    assert_int_equal(vlbe_cr2d_beam_force_jac(b, t, q, v, NULL, o->D1), 0);
    assert_int_equal(vlbe_cr2d_beam_mass_jac(b, t, q, v, a, o->Mq, o->Mv), 0);
    assert_int_equal(vlbe_cr2d_beam_constr(b, t, q, o->C), 0);
    assert_int_equal(vlbe_cr2d_beam_constr_jac(b, t, q, o->Cq, o->Ct), 0);
    assert_int_equal(vlbe_cr2d_beam_constr_acc(b, t, q, v, o->gam), 0);
}

/* The band array B of the dense matrix A of the beam b (Cq: m x n, else n
   x n): every slot (r, c) of the N x N band, c inside [0, N) or not,
   holds A(i, j) for r = order[i], c = order[j] (i a coordinate, or a
   multiplier n + k for Cq's row k; j a coordinate), exactly, and 0 in
   every other slot; every dense entry outside the band is exactly 0.
   Returns the largest |order[i] - order[j]| of a nonzero dense entry. */
static int check_band(const vlbe_cr2d_beam *b, const int *inv, int is_cq, const vlbe_real *A,
                      const vlbe_real *B, const char *what)
{
    const int n = b->n, N = n + b->nfix, kl = b->kl, ld = b->kl + b->ku + 1;
    const int rows = is_cq ? b->nfix : n;
    int r, c, i, j, w = 0;
    for (r = 0; r < N; ++r)
        for (c = r - kl; c <= r + b->ku; ++c) {
            const vlbe_real x = B[VLBE_BAND_IDX(ld, kl, r, c)];
            double ref = 0.0;
            if (c >= 0 && c < N) {
                i = inv[r];
                j = inv[c];
                if (is_cq && i >= n && j < n) ref = (double)A[(i - n) * n + j];
                if (!is_cq && i < n && j < n) ref = (double)A[i * n + j];
            }
            ASSERT_CLOSE_CTX(x, ref, 0, 0, "%s: band slot (%d, %d)", what, r, c);
        }
    for (i = 0; i < rows; ++i)
        for (j = 0; j < n; ++j) {
            const int d = abs(b->order[is_cq ? n + i : i] - b->order[j]);
            if (A[i * n + j] == VLBE_R(0.0)) continue;
            w = imax(w, d);
            if (d > kl || d > b->ku)
                fail_msg("%s: dense entry (%d, %d) = %g outside the band (distance %d, kl %d)",
                         what, i, j, (double)A[i * n + j], d, kl);
        }
    return w;
}

/* vectors: bit for bit */
static void check_same(int len, const vlbe_real *x, const vlbe_real *y, const char *what)
{
    int i;
    for (i = 0; i < len; ++i) ASSERT_CLOSE_CTX(x[i], y[i], 0, 0, "%s entry %d", what, i);
}

/* ------------------------------------------------------------------------ */
/* tests                                                                      */
/* ------------------------------------------------------------------------ */
static void test_band_callbacks(void **state)
{
    static bcase c;
    static outs dn, bd, dn2;
    static const unsigned plain_modes[] = {0u, VLBE_CR2D_NO_NLI, VLBE_CR2D_NO_DAMP};
    int order[MAXNM], ref[MAXNM], inv[MAXNM];
    vlbe_real q[MAXN], v[MAXN], a[MAXN];
    tu_rng g = tu_rng_seed(4711);
    int kind, lay, ne, rep, ncase = 0;
    (void)state;
    for (kind = 0; kind < N_KIND; ++kind)
        for (lay = 0; lay < N_LAY; ++lay)
            for (ne = kind == KIND_TRANS ? 2 : 1; ne <= MAXE; ne += 4)
                for (rep = 0; rep < 2; ++rep) {
                    const vlbe_real t = (vlbe_real)(0.37 + rep);
                    int N, w, wmax = 0;
                    bcase_make(&c, ne, kind, lay, &g);
                    if (kind == KIND_PLAIN) c.bm.mode = plain_modes[(ne + rep + lay) % 3];
                    N = c.n + c.m;
                    rand_state(&c, kind, &g, q, v, a);
                    run_all(&c, t, q, v, a, &dn);
                    /* banded */
                    assert_int_equal(vlbe_cr2d_beam_band(&c.bm, order, N), VLBE_OK);
                    assert_true(c.bm.order == order && c.bm.order_cap == N);
                    check_perm(N, order, inv);
                    ref_order(c.n, c.fix, c.m, ref);
                    for (w = 0; w < N; ++w) assert_int_equal(order[w], ref[w]);
                    assert_int_equal(c.bm.kl, c.bm.ku);
                    assert_int_equal(c.bm.kl, ref_width(ne, c.n, c.fix, c.m, ref));
                    run_all(&c, t, q, v, a, &bd);
                    wmax = imax(wmax, check_band(&c.bm, inv, 0, dn.M, bd.M, "M"));
                    wmax = imax(wmax, check_band(&c.bm, inv, 0, dn.K, bd.K, "K"));
                    wmax = imax(wmax, check_band(&c.bm, inv, 0, dn.D, bd.D, "D"));
                    wmax = imax(wmax, check_band(&c.bm, inv, 0, dn.K1, bd.K1, "K alone"));
                    wmax = imax(wmax, check_band(&c.bm, inv, 0, dn.D1, bd.D1, "D alone"));
                    wmax = imax(wmax, check_band(&c.bm, inv, 0, dn.Mq, bd.Mq, "Mq"));
                    wmax = imax(wmax, check_band(&c.bm, inv, 0, dn.Mv, bd.Mv, "Mv"));
                    wmax = imax(wmax, check_band(&c.bm, inv, 1, dn.Cq, bd.Cq, "Cq"));
                    assert_int_equal(wmax, c.bm.kl); /* the band is as narrow as the entries */
                    check_same(c.n, bd.Q, dn.Q, "Q");
                    check_same(c.m, bd.C, dn.C, "C");
                    check_same(c.m, bd.Ct, dn.Ct, "Ct");
                    check_same(c.m, bd.gam, dn.gam, "gamma");
                    /* back to dense: every output as before, every slot */
                    assert_int_equal(vlbe_cr2d_beam_band(&c.bm, NULL, 0), VLBE_OK);
                    assert_true(c.bm.order == NULL);
                    run_all(&c, t, q, v, a, &dn2);
                    check_same(MAXBAND, dn2.M, dn.M, "M dense");
                    check_same(MAXBAND, dn2.K, dn.K, "K dense");
                    check_same(MAXBAND, dn2.D, dn.D, "D dense");
                    check_same(MAXBAND, dn2.Mq, dn.Mq, "Mq dense");
                    check_same(MAXBAND, dn2.Mv, dn.Mv, "Mv dense");
                    check_same(MAXBAND, dn2.Cq, dn.Cq, "Cq dense");
                    check_same(c.n, dn2.Q, dn.Q, "Q dense");
                    ++ncase;
                }
    assert_int_equal(ncase, (N_KIND * N_LAY - N_LAY) * 3 * 2 + N_LAY * 2 * 2);
}

/* The half-bandwidth against the element count, ne = 1..300: the value of
   the definition (ref_width on ref_order) and a constant per layout: 5
   without fixes (an element spans its two nodes: 3 + 3 - 1), 8 with u, v,
   phi of node 0 prescribed (node 0's three rows sit between the nodes of
   element 0), 8 clamped at node 0 and pinned (u, v) at the last node (the
   last node's rows follow all coordinates: 3 + 1 - 0 = 4 at most), 8 with
   the sliding beam's fixes (u of node 0, v and phi of nodes 0..ne/2: node
   0 has three rows, the others two). */
static void test_band_width(void **state)
{
    static vlbe_cr2d_elem el[300];
    static vlbe_cr2d_fix fix[2 * 301 + 1];
    static int order[3 * 301 + 2 * 301 + 1], ref[3 * 301 + 2 * 301 + 1],
        inv[3 * 301 + 2 * 301 + 1];
    static const int nes[] = {1, 2, 3, 10, 57, 300};
    static const int expect[] = {5, 8, 8, 8};
    const vlbe_cr2d_mat mt = cr_mat_unit();
    vlbe_cr2d_beam bm;
    tu_rng g = tu_rng_seed(17);
    int e, ie, lay;
    (void)state;
    for (e = 0; e < 300; ++e) cr_elem_polar(&el[e], &mt, 0.5 * e, 0.0, 0.5, 0.0, 0u);
    for (ie = 0; ie < ARRAY_LEN(nes); ++ie)
        for (lay = 0; lay < 4; ++lay) {
            const int ne = nes[ie], n = 3 * (ne + 1);
            int m = 0, i;
            memset(fix, 0, sizeof fix);
            if (lay == 1 || lay == 2)
                for (i = 0; i < 3; ++i) fix[m++].dof = i;
            if (lay == 2) {
                fix[m++].dof = n - 3;
                fix[m++].dof = n - 2;
            }
            if (lay == 3) m = make_fixes(LAY_SLIDE, n, ne / 2, &g, fix);
            memset(&bm, 0, sizeof bm);
            assert_int_equal(vlbe_cr2d_beam_init(&bm, el, ne, fix, m), VLBE_OK);
            assert_int_equal(vlbe_cr2d_beam_band(&bm, order, n + m), VLBE_OK);
            check_perm(n + m, order, inv);
            ref_order(n, fix, m, ref);
            for (i = 0; i < n + m; ++i) assert_int_equal(order[i], ref[i]);
            assert_int_equal(bm.kl, ref_width(ne, n, fix, m, ref));
            assert_int_equal(bm.kl, expect[lay]);
            assert_int_equal(bm.ku, expect[lay]);
        }
}

/* Failures of vlbe_cr2d_beam_band and of the banded callbacks. */
static void test_band_errors(void **state)
{
    static bcase c;
    static vlbe_real out[MAXBAND];
    vlbe_cr2d_beam copy;
    int order[MAXNM], i;
    vlbe_real q[MAXN], v[MAXN], a[MAXN], Q[MAXN], Ct[MAXM];
    tu_rng g = tu_rng_seed(23);
    (void)state;
    bcase_make(&c, 4, KIND_PLAIN, LAY_CLAMP, &g);
    rand_state(&c, KIND_PLAIN, &g, q, v, a);
    /* order_cap one short: EWORK, beam and order untouched */
    for (i = 0; i < MAXNM; ++i) order[i] = -7;
    memcpy(&copy, &c.bm, sizeof copy);
    assert_int_equal(vlbe_cr2d_beam_band(&c.bm, order, c.n + c.m - 1), VLBE_EWORK);
    assert_int_equal(vlbe_cr2d_beam_band(&c.bm, order, -1), VLBE_EWORK);
    assert_memory_equal(&copy, &c.bm, sizeof copy);
    for (i = 0; i < MAXNM; ++i) assert_int_equal(order[i], -7);
    /* a fix outside [0, n) (moved after init): EARG, untouched */
    c.fix[1].dof = c.n;
    assert_int_equal(vlbe_cr2d_beam_band(&c.bm, order, MAXNM), VLBE_EARG);
    c.fix[1].dof = -1;
    assert_int_equal(vlbe_cr2d_beam_band(&c.bm, order, MAXNM), VLBE_EARG);
    assert_memory_equal(&copy, &c.bm, sizeof copy);
    for (i = 0; i < MAXNM; ++i) assert_int_equal(order[i], -7);
    c.fix[1].dof = 1;
    /* exactly n + m: fine (8 = 5 + the three rows of node 0) */
    assert_int_equal(vlbe_cr2d_beam_band(&c.bm, order, c.n + c.m), VLBE_OK);
    assert_int_equal(c.bm.kl, 8);
    /* nfix changed behind the order's back: the matrix callbacks refuse
       (-1, EARG, outputs untouched); the force alone does not use it */
    c.bm.nfix = 2;
    cr_fill(MAXBAND, SENTINEL, out);
    assert_int_equal(vlbe_cr2d_beam_mass(&c.bm, VLBE_R(0.0), q, v, out), -1);
    assert_int_equal(c.bm.err, VLBE_EARG);
    assert_int_equal(vlbe_cr2d_beam_force_jac(&c.bm, VLBE_R(0.0), q, v, out, NULL), -1);
    assert_int_equal(vlbe_cr2d_beam_force_jac(&c.bm, VLBE_R(0.0), q, v, NULL, out), -1);
    assert_int_equal(vlbe_cr2d_beam_mass_jac(&c.bm, VLBE_R(0.0), q, v, a, out, NULL), -1);
    assert_int_equal(vlbe_cr2d_beam_constr_jac(&c.bm, VLBE_R(0.0), q, out, NULL), -1);
    assert_all_equal(MAXBAND, out, SENTINEL);
    c.bm.err = VLBE_OK;
    assert_int_equal(vlbe_cr2d_beam_force(&c.bm, VLBE_R(0.0), q, v, Q), 0);
    assert_int_equal(c.bm.err, VLBE_OK);
    c.bm.nfix = 3;
    /* fix 0 (row 3, u of node 0 at 0) moved to node 3's u (at 12): out of
       the band (9 > 8): EARG, Cq untouched */
    c.fix[0].dof = 9;
    cr_fill(MAXBAND, SENTINEL, out);
    assert_int_equal(vlbe_cr2d_beam_constr_jac(&c.bm, VLBE_R(0.0), q, out, Ct), -1);
    assert_int_equal(c.bm.err, VLBE_EARG);
    assert_all_equal(MAXBAND, out, SENTINEL);
    /* moved to node 1's v (at 7): inside the band (distance 4), the 1 at
       (row 3, column 7), nothing else */
    c.fix[0].dof = 4;
    assert_int_equal(vlbe_cr2d_beam_constr_jac(&c.bm, VLBE_R(0.0), q, out, Ct), 0);
    {
        const int ld = c.bm.kl + c.bm.ku + 1, N = c.n + c.m;
        int r, col, ones = 0;
        assert_true(out[VLBE_BAND_IDX(ld, c.bm.kl, 3, 7)] == VLBE_R(1.0));
        for (r = 0; r < N; ++r)
            for (col = r - c.bm.kl; col <= r + c.bm.ku; ++col) {
                const vlbe_real x = out[VLBE_BAND_IDX(ld, c.bm.kl, r, col)];
                assert_true(x == VLBE_R(0.0) || x == VLBE_R(1.0));
                ones += x == VLBE_R(1.0);
            }
        assert_int_equal(ones, 3);
    }
    c.fix[0].dof = 0;
    /* no fixes: constr_jac may get Cq NULL in banded mode too (nothing to
       write); with an array, n ld zeros */
    assert_int_equal(vlbe_cr2d_beam_init(&c.bm, c.el, c.ne, c.fix, 0), VLBE_OK);
    assert_int_equal(vlbe_cr2d_beam_band(&c.bm, order, c.n), VLBE_OK);
    assert_int_equal(c.bm.kl, 5);
    assert_int_equal(vlbe_cr2d_beam_constr_jac(&c.bm, VLBE_R(0.0), q, NULL, NULL), 0);
    cr_fill(MAXBAND, SENTINEL, out);
    assert_int_equal(vlbe_cr2d_beam_constr_jac(&c.bm, VLBE_R(0.0), q, out, NULL), 0);
    assert_all_equal(c.n * 11, out, VLBE_R(0.0));
    assert_all_equal(MAXBAND - c.n * 11, out + c.n * 11, SENTINEL);
    /* a new layout through beam_init restarts in dense mode */
    assert_int_equal(vlbe_cr2d_beam_init(&c.bm, c.el, c.ne, c.fix, 2), VLBE_OK);
    assert_true(c.bm.order == NULL && c.bm.order_cap == 0 && c.bm.kl == 0 && c.bm.ku == 0);
}

/* The sliding beam of scenes/ex_sbeam.h (the paper's case (b): 14
   elements inside, 10 outside), made banded after its first layout: when
   nodes leave the joint (the state moved 1.5 inside elements out) the
   re-layout rebuilds the fixes and the beam keeps the caller's order,
   now that of the new fixes, kl = 8. */
static void test_band_relayout(void **state)
{
    static sb_model m;
    static vlbe_real q[3 * (SB_MAXEL + 1)];
    static int order[3 * (SB_MAXEL + 1) + 2 * (SB_MAXEL + 1) + 1], ref[5 * (SB_MAXEL + 1) + 1];
    sb_cfg cfg;
    int cap, nf0, i;
    (void)state;
    sb_cfg_paper(&cfg, 'b');
    assert_int_equal(sb_init(&m, &cfg), VLBE_OK);
    cap = m.n + 1 + 2 * m.nn;
    assert_true(cap <= ARRAY_LEN(order));
    memset(q, 0, sizeof q);
    assert_int_equal(sb_layout(&m, q, 0.0, 1), 1);
    assert_true(m.beam.order == NULL);
    nf0 = m.beam.nfix;
    assert_int_equal(vlbe_cr2d_beam_band(&m.beam, order, cap), VLBE_OK);
    assert_int_equal(m.beam.kl, 8);
    {
        const double hin = (cfg.L - cfg.L0) / cfg.n_in;
        for (i = 0; i < m.nn; ++i) q[3 * i] = (vlbe_real)(1.5 * hin);
    }
    assert_int_equal(sb_layout(&m, q, 0.0, 0), 1);
    assert_true(m.beam.nfix < nf0); /* nodes left: fewer fixes */
    assert_true(m.beam.order == order && m.beam.order_cap == cap);
    ref_order(m.n, m.fix, m.beam.nfix, ref);
    for (i = 0; i < m.n + m.beam.nfix; ++i) assert_int_equal(order[i], ref[i]);
    assert_int_equal(m.beam.kl, 8);
    assert_int_equal(m.beam.ku, 8);
    assert_int_equal(m.beam.kl, ref_width(m.ne, m.n, m.fix, m.beam.nfix, ref));
    /* the system follows the beam (ex_cr2d_storage) */
    assert_int_equal(m.sys.m, m.beam.nfix);
    assert_int_equal(m.sys.storage, VLBE_DAE_BANDED);
    assert_true(m.sys.order == order && m.sys.kl == 8 && m.sys.ku == 8);
}

/* vlbe_cr2d_beam_dae: the beam's callbacks (constr_hess NULL), n and m =
   nfix, flags 0; a dense beam gives a dense system (kl = ku = 0, order
   NULL), a banded one its order and half-bandwidths; a banded order made
   for another nfix: VLBE_EARG and nothing written. */
static void test_band_wiring(void **state)
{
    static bcase c;
    vlbe_dae sys, ref;
    int order[MAXNM];
    tu_rng g = tu_rng_seed(29);
    (void)state;
    bcase_make(&c, 3, KIND_PLAIN, LAY_CLAMP, &g);
    memset(&sys, 0xff, sizeof sys);
    assert_int_equal(vlbe_cr2d_beam_dae(&c.bm, &sys), VLBE_OK);
    assert_int_equal(sys.storage, VLBE_DAE_DENSE);
    assert_true(sys.kl == 0 && sys.ku == 0 && sys.order == NULL);
    assert_true(sys.n == c.n && sys.m == c.m && sys.user == &c.bm && sys.flags == 0u);
    assert_true(sys.mass == vlbe_cr2d_beam_mass && sys.force == vlbe_cr2d_beam_force);
    assert_true(sys.force_jac == vlbe_cr2d_beam_force_jac);
    assert_true(sys.mass_jac == vlbe_cr2d_beam_mass_jac);
    assert_true(sys.constr == vlbe_cr2d_beam_constr);
    assert_true(sys.constr_jac == vlbe_cr2d_beam_constr_jac);
    assert_true(sys.constr_acc == vlbe_cr2d_beam_constr_acc);
    assert_true(sys.constr_hess == NULL && sys.lin_factor == NULL && sys.lin_solve == NULL);
    assert_int_equal(vlbe_dae_check(&sys), VLBE_OK);
    assert_int_equal(vlbe_cr2d_beam_band(&c.bm, order, MAXNM), VLBE_OK);
    assert_int_equal(vlbe_cr2d_beam_dae(&c.bm, &sys), VLBE_OK);
    assert_int_equal(sys.storage, VLBE_DAE_BANDED);
    assert_true(sys.kl == 8 && sys.ku == 8 && sys.order == order);
    assert_true(sys.n == c.n && sys.m == c.m && sys.user == &c.bm);
    assert_int_equal(vlbe_dae_check(&sys), VLBE_OK);
    /* one fix fewer than the order was made for */
    c.bm.nfix--;
    memset(&sys, 0x5a, sizeof sys);
    ref = sys;
    assert_int_equal(vlbe_cr2d_beam_dae(&c.bm, &sys), VLBE_EARG);
    assert_memory_equal(&sys, &ref, sizeof sys);
    c.bm.nfix++;
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_band_callbacks),
        cmocka_unit_test(test_band_width),
        cmocka_unit_test(test_band_errors),
        cmocka_unit_test(test_band_relayout),
        cmocka_unit_test(test_band_wiring),
    };
    return cmocka_run_group_tests_name("cr2d_band", tests, NULL, NULL);
}

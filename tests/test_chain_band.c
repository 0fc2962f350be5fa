/* test_chain_band.c -- cmocka suite of the banded mode of the chains of
   ancf_ale.h (vlbe_ale_chain_band: the matrix callbacks in band storage in
   the augmented order; planar, rational through rancf.h, 3D)
                                                   -- part of vlbe
                                                   SPDX-License-Identifier: MIT
   cc -std=c99 -Wall -Wextra -Wpedantic ... -O2 tests/test_chain_band.c -lcmocka -lm
   (add -DVLBE_USE_FLOAT for the float build; the same source passes in both)

   The reference is the chain's own dense mode, whose numbers the other
   suites check (finite differences, exact properties).  The band matrices
   are assembled by the same scatter, element by element in the same order,
   with only the index map changed, so every entry must equal its dense
   counterpart bit for bit (tolerance 0, double and float); every dense
   entry outside the declared band must be exactly 0, which checks kl, ku
   and the order together; every other slot of the band arrays must be 0.
   The vectors (Q, C, Ct, gamma) must be bitwise those of the dense mode.
   The order is checked against its rule independently of the library's
   bookkeeping: a permutation; each node's coordinates consecutive and in q
   order; each constraint row after the coordinates of the node that holds
   the highest column of its dense C_q row, and before the next node's.
   kl is checked to be attained: the largest |order[a] - order[b]| over the
   nonzero entries of the dense M, K, D, d(Ma)/dq, C_q, H equals it (the
   random states make every structural entry nonzero).

   Tests
     planar_all_constraints  7 nodes: fixed, free, sliding with a point
                            mass, prescribed (p'' != 0), every constraint type
                            (POS, masked POS, SLOPE, SLOPE_DIR, SLOPE_ANGLE, P,
                            SLIDE_C, SLIDE_D, EQUAL_LEN with fixed and with
                            free ends); with and without VLBE_ALE_CONSERVATIVE
     planar_lagrangian      fixed-p nodes with a clamp, and a mixed chain whose
                            equal-length group has free ends on both sides (its
                            rows couple across the group: kl spans it)
     rational_chain         ALE-RANCF elements with non-unit weights (rancf.h),
                            a sliding node, free and prescribed p
     chain3d_spin           3D beam-shaft chain with spin: POS (3 rows and
                            masked), SLOPE, SPIN, P, EQUAL_LEN, a point mass;
                            again with SLOPE_ROT at the clamp and SLOPE_DIR
                            (2 rows) at an interior free node and at node 5
     uniform_bandwidth      kl of uniform chains does not grow with the
                            number of elements (3 .. 129 nodes), and equals
                            the count of the widest element's coordinates
                            and the rows between them
     relayout               insert / remove / length control in banded mode
                            (planar and rational): the band recomputed, still
                            equal to the dense callbacks
     ework                  order_cap too small: layout, insert, remove,
                            length control return VLBE_EWORK with the chain,
                            its arrays and order unchanged; band() with a
                            negative capacity: VLBE_EARG
     chain_dae              vlbe_ale_chain_dae: the chain's callbacks,
                            VLBE_DAE_MASS_CONST exactly for planar chains
                            with every p fixed, dense by default, banded
                            with the chain's kl, ku and order in banded
                            mode; VLBE_EARG and nothing written before the
                            first layout */
#include "test_util.h"
#include "../rancf.h"
#include "../scenes/ex_ale.h"
#include "ale_fixtures.h"
#include "rancf_fixtures.h"

#include <string.h>

#define NN_MAX 136 /* nodes (uniform chains up to 129) */
#define NC_MAX 16  /* constraints (entries)             */
#define NA_MAX 112 /* n + m of the chains compared with the dense mode */

/* ------------------------------------------------------------------------ */
/* fixtures                                                                   */
/* ------------------------------------------------------------------------ */

/* A chain with its storage (planar, rational or 3D) and its order buffer. */
typedef struct bch {
    vlbe_ale_mat mat;
    vlbe_ale_elem el;
    vlbe_ale3_mat mat3;
    vlbe_ale3_elem el3;
    vlbe_ale_node node[NN_MAX];
    vlbe_ale_con con[NC_MAX];
    vlbe_ale_chain ch;
    int ord[NA_MAX + 8];
} bch;

/* Rational elements (~22 kB each: static), for chains of up to 13 nodes. */
static vlbe_rancf_elem r_els[12];

static void bch_add(bch *c, vlbe_ale_con k)
{
    assert_int_equal(vlbe_ale_chain_add(&c->ch, &k), VLBE_OK);
}

/* banded mode with the whole order buffer, then layout */
static void bch_band(bch *c)
{
    assert_int_equal(vlbe_ale_chain_band(&c->ch, c->ord, NA_MAX), VLBE_OK);
    assert_int_equal(vlbe_ale_chain_layout(&c->ch), VLBE_OK);
    assert_true(c->ch.n + c->ch.m <= NA_MAX);
}

/* A state of the laid-out chain: straight along dir from r0, every
   coordinate moved by up to 0.04 (positions, slopes, spin angles), free
   p's by up to 0.005 (elements stay longer than 0.09 in the chains here);
   v, a, lambda O(1). */
typedef struct bstate {
    vlbe_real t;
    vlbe_real q[NA_MAX], v[NA_MAX], a[NA_MAX], lam[NA_MAX];
} bstate;

static void bstate_make(const vlbe_ale_chain *ch, uint64_t seed, bstate *s)
{
    const vlbe_real r0[3] = {VLBE_R(0.1), VLBE_R(-0.2), VLBE_R(0.05)};
    const vlbe_real dir2[3] = {VLBE_R(0.8), VLBE_R(0.6), 0}, dir3[3] = {VLBE_R(0.8), VLBE_R(0.5), VLBE_R(0.2)};
    tu_rng g = tu_rng_seed(seed);
    int i, k;
    memset(s, 0, sizeof *s);
    s->t = VLBE_R(0.3);
    vlbe_ale_chain_straight(ch, r0, ch->d == 3 ? dir3 : dir2, s->q);
    for (i = 0; i < ch->nn; ++i) {
        const int o = ch->node[i].ofs, end = i + 1 < ch->nn ? ch->node[i + 1].ofs : ch->n;
        const int free_p = ch->node[i].pmode == VLBE_ALE_PFREE;
        for (k = o; k < end; ++k)
            s->q[k] += (vlbe_real)((free_p && k == end - 1 ? 0.005 : 0.04) * tu_rng_uniform(&g));
    }
    for (i = 0; i < ch->n; ++i) {
        s->v[i] = (vlbe_real)tu_rng_uniform(&g);
        s->a[i] = (vlbe_real)tu_rng_uniform(&g);
    }
    for (i = 0; i < ch->m; ++i) s->lam[i] = (vlbe_real)tu_rng_uniform(&g);
}

/* The outputs of every callback in one mode: matrices dense (n x n, C_q
   m x n) or band ((n + m) ld), vectors. */
enum { MX_M, MX_K, MX_D, MX_MQ, MX_MV, MX_H, MX_CQ, MX_N };
static const char *const mx_name[MX_N] = {"M", "K", "D", "Mq", "Mv", "H", "Cq"};

typedef struct outs {
    vlbe_real A[MX_N][NA_MAX * NA_MAX];
    vlbe_real Q[NA_MAX], C[NA_MAX], Ct[NA_MAX], g[NA_MAX];
} outs;

static outs o_dense, o_band;

/* every callback at the state s; the matrices pre-filled with a sentinel
   so that a slot the callback does not write shows */
static void outs_eval(vlbe_ale_chain *ch, const bstate *s, outs *o)
{
    int k;
    for (k = 0; k < MX_N; ++k) fill(NA_MAX * NA_MAX, VLBE_R(-77.0), o->A[k]);
    assert_int_equal(vlbe_ale_chain_mass(ch, s->t, s->q, s->v, o->A[MX_M]), 0);
    assert_int_equal(vlbe_ale_chain_force(ch, s->t, s->q, s->v, o->Q), 0);
    assert_int_equal(vlbe_ale_chain_force_jac(ch, s->t, s->q, s->v, o->A[MX_K], o->A[MX_D]), 0);
    assert_int_equal(vlbe_ale_chain_mass_jac(ch, s->t, s->q, s->v, s->a, o->A[MX_MQ], o->A[MX_MV]), 0);
    assert_int_equal(vlbe_ale_chain_constr(ch, s->t, s->q, o->C), 0);
    assert_int_equal(vlbe_ale_chain_constr_jac(ch, s->t, s->q, o->A[MX_CQ], o->Ct), 0);
    assert_int_equal(vlbe_ale_chain_constr_acc(ch, s->t, s->q, s->v, o->g), 0);
    assert_int_equal(vlbe_ale_chain_constr_hess(ch, s->t, s->q, s->lam, o->A[MX_H]), 0);
}

/* bitwise equality of two reals (so that -0 and 0 differ, NaN is caught) */
static int same_bits(vlbe_real a, vlbe_real b) { return memcmp(&a, &b, sizeof a) == 0; }

/* The order against its rule, independently of the library's
   bookkeeping (see the opening comment); Cq: the dense C_q. */
static void order_rule_check(const vlbe_ale_chain *ch, const int *ord, const vlbe_real *Cq)
{
    static int seen[NA_MAX];
    const int n = ch->n, m = ch->m;
    int i, k, j;
    memset(seen, 0, sizeof seen);
    for (i = 0; i < n + m; ++i) {
        assert_true(ord[i] >= 0 && ord[i] < n + m);
        assert_int_equal(seen[ord[i]], 0);
        seen[ord[i]] = 1;
    }
    for (i = 0; i < ch->nn; ++i) { /* node i's coordinates consecutive, in q order */
        const int o = ch->node[i].ofs, end = i + 1 < ch->nn ? ch->node[i + 1].ofs : n;
        for (k = o + 1; k < end; ++k) assert_int_equal(ord[k], ord[k - 1] + 1);
        if (i > 0) assert_true(ord[o] > ord[o - 1]);
    }
    for (k = 0; k < m; ++k) { /* row k between its node's coordinates and the next node's
                                  (rows of node 0 alone: before node 0) */
        int hi = -1, nd = 0;
        for (j = 0; j < n; ++j)
            if (Cq[(size_t)k * (size_t)n + (size_t)j] != VLBE_R(0.0)) hi = j;
        assert_true(hi >= 0);
        while (nd + 1 < ch->nn && ch->node[nd + 1].ofs <= hi) ++nd;
        if (nd == 0) { /* a row of node 0 alone: before its coordinates */
            assert_true(ord[n + k] < ord[0]);
        } else {
            const int end = nd + 1 < ch->nn ? ch->node[nd + 1].ofs : n;
            assert_true(ord[n + k] > ord[end - 1]);
            if (end < n) assert_true(ord[n + k] < ord[end]);
        }
    }
}

/* Dense vs banded callbacks of the chain (in banded mode, laid out) at the
   state seeded by `seed`: see the opening comment.  The chain's order and
   kl, ku as they were (set by whatever ran the layout last: insert,
   remove, length control) must equal those of a fresh layout.  Returns
   kl. */
static int band_check(bch *c, uint64_t seed, const char *what)
{
    static int ord0[NA_MAX];
    static bstate s;
    vlbe_ale_chain *ch = &c->ch;
    const int kl0 = ch->kl, ku0 = ch->ku, cap = ch->order_cap;
    int n, m, ld, x, i, j, k, wmax = 0;
    assert_true(ch->order == c->ord && kl0 >= 0);
    memcpy(ord0, c->ord, sizeof ord0);
    /* dense */
    assert_int_equal(vlbe_ale_chain_band(ch, NULL, 0), VLBE_OK);
    assert_int_equal(vlbe_ale_chain_layout(ch), VLBE_OK);
    n = ch->n;
    m = ch->m;
    assert_true(n + m <= NA_MAX);
    bstate_make(ch, seed, &s);
    outs_eval(ch, &s, &o_dense);
    /* banded: the same order and bandwidth as before */
    assert_int_equal(vlbe_ale_chain_band(ch, c->ord, cap), VLBE_OK);
    assert_int_equal(ch->kl, -1);
    assert_int_equal(vlbe_ale_chain_layout(ch), VLBE_OK);
    assert_int_equal(ch->n, n);
    assert_int_equal(ch->m, m);
    assert_int_equal(ch->kl, kl0);
    assert_int_equal(ch->ku, ku0);
    assert_memory_equal(c->ord, ord0, (size_t)(n + m) * sizeof *ord0);
    assert_int_equal(ch->kl, ch->ku);
    ld = ch->kl + ch->ku + 1;
    outs_eval(ch, &s, &o_band);
    order_rule_check(ch, c->ord, o_dense.A[MX_CQ]);
    /* the vectors */
    assert_memory_equal(o_band.Q, o_dense.Q, (size_t)n * sizeof *o_band.Q);
    assert_memory_equal(o_band.C, o_dense.C, (size_t)m * sizeof *o_band.C);
    assert_memory_equal(o_band.Ct, o_dense.Ct, (size_t)m * sizeof *o_band.Ct);
    assert_memory_equal(o_band.g, o_dense.g, (size_t)m * sizeof *o_band.g);
    /* the matrices: the expected band array from the dense one */
    for (x = 0; x < MX_N; ++x) {
        static vlbe_real E[NA_MAX * NA_MAX];
        const int rows = x == MX_CQ ? m : n;
        const vlbe_real *Ad = o_dense.A[x], *Ab = o_band.A[x];
        fill((n + m) * ld, VLBE_R(0.0), E);
        for (i = 0; i < rows; ++i)
            for (j = 0; j < n; ++j) {
                const vlbe_real a = Ad[(size_t)i * (size_t)n + (size_t)j];
                const int r = c->ord[x == MX_CQ ? n + i : i], cc = c->ord[j];
                if (r - cc > ch->kl || cc - r > ch->ku) {
                    if (a != VLBE_R(0.0))
                        fail_msg("%s %s: dense (%d, %d) = %g outside the band (rows %d, %d; kl %d)",
                                 what, mx_name[x], i, j, (double)a, r, cc, ch->kl);
                    continue;
                }
                E[VLBE_BAND_IDX(ld, ch->kl, r, cc)] = a;
                if (a != VLBE_R(0.0) && abs(r - cc) > wmax) wmax = abs(r - cc);
            }
        for (k = 0; k < (n + m) * ld; ++k)
            if (!same_bits(Ab[k], E[k]))
                fail_msg("%s %s: band slot %d (row %d, column %d) = %.17g, dense %.17g", what,
                         mx_name[x], k, k / ld, k / ld + k % ld - ch->kl, (double)Ab[k],
                         (double)E[k]);
        assert_true(same_bits(Ab[(n + m) * ld], VLBE_R(-77.0))); /* nothing written past it */
    }
    assert_int_equal(wmax, ch->kl); /* attained */
    if (tu_report_on())
        print_message("    %-34s n %3d  m %2d  kl = ku = %2d  band %5d reals, dense %5d\n", what, n,
                      m, ch->kl, (n + m) * ld, n * n);
    return ch->kl;
}

/* ------------------------------------------------------------------------ */
/* chains                                                                     */
/* ------------------------------------------------------------------------ */

/* 7 planar nodes, 6 elements:
     0 fixed p (0.1)                  POS, EQUAL_LEN 0..2 start
     1 free                           EQUAL_LEN 0..2 interior
     2 free, sliding, point mass 0.6  SLOPE (right), SLOPE_DIR (left),
                                      SLIDE_C, SLIDE_D, EQUAL_LEN 0..2 end
     3 prescribed p = 0.8 + 0.3 t - 0.35 t^2   EQUAL_LEN 3..6 start
     4 free                           P, EQUAL_LEN interior
     5 free                           EQUAL_LEN interior, SLOPE_ANGLE
     6 fixed p (1.5), point mass 0.25 SLOPE_DIR, POS of y only, EQUAL_LEN end
   Material with damping and a load, gravity on the masses. */
static void planar_chain(bch *c, unsigned mode)
{
    memset(c, 0, sizeof *c);
    c->mat = mat_std();
    assert_int_equal(vlbe_ale_elem_init(&c->el, &c->mat, 0u, 0, 0, 0), VLBE_OK);
    nodes_mixed7(c->node);
    assert_int_equal(vlbe_ale_chain_init(&c->ch, &c->el, c->node, 7, NN_MAX, c->con, NC_MAX), VLBE_OK);
    c->ch.mode = mode;
    c->ch.g[0] = VLBE_R(0.3);
    c->ch.g[1] = VLBE_R(-1.1);
    bch_add(c, con_make(VLBE_ALE_CON_POS, 0, 0, 0, 0.1, -0.2, 0));
    bch_add(c, con_make(VLBE_ALE_CON_SLOPE, 2, 0, 1, 1.0, 0.1, 0));
    bch_add(c, con_make(VLBE_ALE_CON_SLOPE_DIR, 6, 0, 0, 0.8, 0.6, 0));
    bch_add(c, con_make(VLBE_ALE_CON_SLOPE_DIR, 2, 0, 0, 0.6, 0.8, 0));
    bch_add(c, con_make(VLBE_ALE_CON_P, 4, 0, 0, 1.0, 0.2, -0.5));
    bch_add(c, con_make(VLBE_ALE_CON_EQUAL_LEN, 3, 6, 0, 0, 0, 0));
    bch_add(c, con_make(VLBE_ALE_CON_EQUAL_LEN, 0, 2, 0, 0, 0, 0));
    bch_add(c, con_make(VLBE_ALE_CON_SLIDE_C, 2, 0, 0, 0, 0, 0));
    bch_add(c, con_make(VLBE_ALE_CON_SLIDE_D, 2, 0, 0, 0, 0, 0));
    bch_add(c, con_make(VLBE_ALE_CON_SLOPE_ANGLE, 5, 0, 0, 0.3, 0.7, -0.9));
    bch_add(c, con_make(VLBE_ALE_CON_POS, 6, 0, 2, 0, 0.5, 0));
    assert_int_equal(vlbe_ale_chain_layout(&c->ch), VLBE_OK);
}

/* Lagrangian: nn nodes with fixed p every 0.25, clamped at node 0 (POS +
   SLOPE), node nn-1 pinned (POS). */
static void lagrangian_chain(bch *c, int nn)
{
    int i;
    memset(c, 0, sizeof *c);
    c->mat = mat_std();
    assert_int_equal(vlbe_ale_elem_init(&c->el, &c->mat, 0u, 0, 0, 0), VLBE_OK);
    for (i = 0; i < nn; ++i) c->node[i] = node_make(VLBE_ALE_PFIXED, 0.25 * i);
    assert_int_equal(vlbe_ale_chain_init(&c->ch, &c->el, c->node, nn, NN_MAX, c->con, NC_MAX), VLBE_OK);
    bch_add(c, con_make(VLBE_ALE_CON_POS, 0, 0, 0, 0, 0, 0));
    bch_add(c, con_make(VLBE_ALE_CON_SLOPE, 0, 0, 0, 1, 0, 0));
    bch_add(c, con_make(VLBE_ALE_CON_POS, nn - 1, 0, 0, 0, 0, 0));
    assert_int_equal(vlbe_ale_chain_layout(&c->ch), VLBE_OK);
}

/* Mixed: nodes 0, 1, 6 fixed, 2..5 free, p every 0.25; clamp at 0, pin at
   6, EQUAL_LEN 2..5 (its rows touch p2 and p5: placed after node 5). */
static void mixed_chain(bch *c)
{
    int i;
    memset(c, 0, sizeof *c);
    c->mat = mat_std();
    assert_int_equal(vlbe_ale_elem_init(&c->el, &c->mat, 0u, 0, 0, 0), VLBE_OK);
    for (i = 0; i < 7; ++i)
        c->node[i] = node_make(i >= 2 && i <= 5 ? VLBE_ALE_PFREE : VLBE_ALE_PFIXED, 0.25 * i);
    assert_int_equal(vlbe_ale_chain_init(&c->ch, &c->el, c->node, 7, NN_MAX, c->con, NC_MAX), VLBE_OK);
    bch_add(c, con_make(VLBE_ALE_CON_POS, 0, 0, 0, 0, 0, 0));
    bch_add(c, con_make(VLBE_ALE_CON_SLOPE, 0, 0, 0, 1, 0, 0));
    bch_add(c, con_make(VLBE_ALE_CON_EQUAL_LEN, 2, 5, 0, 0, 0, 0));
    bch_add(c, con_make(VLBE_ALE_CON_POS, 6, 0, 0, 0, 0, 0));
    assert_int_equal(vlbe_ale_chain_layout(&c->ch), VLBE_OK);
}

/* Rational: 6 nodes at p = 0, 0.3, 0.6 (free, sliding), 0.9, 1.2
   (prescribed), 1.5 (free), capacity for more; elements with weights
   1 +- 0.2; clamp at 0, SLIDE_C + SLIDE_D at 2, P at 5, SLOPE_DIR at 3. */
static void rational_chain(bch *c)
{
    const double p[6] = {0, 0.3, 0.6, 0.9, 1.2, 1.5};
    int i;
    memset(c, 0, sizeof *c);
    c->mat = mat_std();
    for (i = 0; i < 12; ++i) {
        const vlbe_real w[4] = {VLBE_R(1.0), (vlbe_real)(1.0 + 0.2 * ((i % 3) - 1)),
                                (vlbe_real)(1.0 - 0.1 * (i % 2)), VLBE_R(1.1)};
        rancf_el_init(&r_els[i], &c->mat, w, 0);
    }
    for (i = 0; i < 6; ++i) c->node[i] = node_make(VLBE_ALE_PFIXED, p[i]);
    c->node[2].pmode = VLBE_ALE_PFREE;
    c->node[2].slide = 1;
    c->node[4].pmode = VLBE_ALE_PPRESCRIBED;
    c->node[4].pd = VLBE_R(0.1);
    c->node[4].pdd = VLBE_R(0.2);
    c->node[5].pmode = VLBE_ALE_PFREE;
    assert_int_equal(vlbe_rancf_chain_init(&c->ch, r_els, c->node, 6, 13, c->con, NC_MAX), VLBE_OK);
    bch_add(c, con_make(VLBE_ALE_CON_POS, 0, 0, 0, 0, 0, 0));
    bch_add(c, con_make(VLBE_ALE_CON_SLOPE, 0, 0, 0, 1, 0, 0));
    bch_add(c, con_make(VLBE_ALE_CON_SLIDE_C, 2, 0, 0, 0, 0, 0));
    bch_add(c, con_make(VLBE_ALE_CON_SLIDE_D, 2, 0, 0, 0, 0, 0));
    bch_add(c, con_make(VLBE_ALE_CON_SLOPE_DIR, 3, 0, 0, 0.8, 0.6, 0));
    bch_add(c, con_make(VLBE_ALE_CON_P, 5, 0, 0, 1.5, 0.1, 0));
    assert_int_equal(vlbe_ale_chain_layout(&c->ch), VLBE_OK);
}

/* 3D with spin: nodes 0 fixed, 1, 2 free, 3 prescribed, 4 free, 5 fixed
   with a point mass, p every 0.4; at 0 POS + SLOPE + SPIN (a clamp driven
   in spin), EQUAL_LEN 0..3, P at 4, at 5 SPIN and POS of y and z; damping,
   gravity.  rot: the clamp's SLOPE turned into SLOPE_ROT (e0, axis, law)
   and SLOPE_DIR rows (2 each) at the interior free node 1 and at node 5
   (node 1: its element to free node 2 couples x1 with p2, so kl is
   attained; towards a fixed node the widest pair, x and the next theta,
   is structurally zero). */
static void chain3d(bch *c, int rot)
{
    int i;
    memset(c, 0, sizeof *c);
    assert_int_equal(vlbe_ale3_mat_circle(&c->mat3, VLBE_R(1.0), VLBE_R(100.0), VLBE_R(40.0),
                                          VLBE_R(0.1)),
                     VLBE_OK);
    c->mat3.c_eps = VLBE_R(0.01);
    c->mat3.c_kap = VLBE_R(0.02);
    c->mat3.c_phi = VLBE_R(0.03);
    assert_int_equal(vlbe_ale3_elem_init(&c->el3, &c->mat3, 0u, 0, 0), VLBE_OK);
    for (i = 0; i < 6; ++i) c->node[i] = node_make(VLBE_ALE_PFIXED, 0.4 * i);
    c->node[1].pmode = c->node[2].pmode = c->node[4].pmode = VLBE_ALE_PFREE;
    c->node[3].pmode = VLBE_ALE_PPRESCRIBED;
    c->node[3].pd = VLBE_R(0.05);
    c->node[3].pdd = VLBE_R(0.3);
    c->node[5].mass = VLBE_R(0.4);
    assert_int_equal(vlbe_ale_chain_init3(&c->ch, &c->el3, c->node, 6, NN_MAX, c->con, NC_MAX),
                     VLBE_OK);
    c->ch.g[2] = VLBE_R(-9.81);
    bch_add(c, con_make(VLBE_ALE_CON_POS, 0, 0, 0, 0, 0, 0));
    if (rot) {
        static const double e0[3] = {1.0, 0.2, -0.1}, k[3] = {0.3, 0.4, 0.9};
        bch_add(c, con_rot(0, e0, k, 0.2, 1.5, -0.4));
        bch_add(c, con_make(VLBE_ALE_CON_SLOPE_DIR, 1, 0, 0, 0.9, 0.3, 0.2));
        bch_add(c, con_make(VLBE_ALE_CON_SLOPE_DIR, 5, 0, 0, 1.0, -0.1, 0.3));
    } else {
        bch_add(c, con_make(VLBE_ALE_CON_SLOPE, 0, 0, 0, 1, 0, 0));
    }
    bch_add(c, con_make(VLBE_ALE_CON_SPIN, 0, 0, 0, 0, 2.0, 0.5));
    bch_add(c, con_make(VLBE_ALE_CON_EQUAL_LEN, 0, 3, 0, 0, 0, 0));
    bch_add(c, con_make(VLBE_ALE_CON_P, 4, 0, 0, 1.6, 0.1, 0));
    bch_add(c, con_make(VLBE_ALE_CON_SPIN, 5, 0, 0, 0.1, 0, 0));
    bch_add(c, con_make(VLBE_ALE_CON_POS, 5, 0, 6, 0, 0.3, 0.1));
    assert_int_equal(vlbe_ale_chain_layout(&c->ch), VLBE_OK);
}

/* ------------------------------------------------------------------------ */
/* tests                                                                      */
/* ------------------------------------------------------------------------ */

static bch cA; /* ~ 40 kB with the node array: static */

/* Every constraint type of a planar chain, the paper form and the
   conservative one, two states each. */
static void test_planar_all_constraints(void **state)
{
    (void)state;
    planar_chain(&cA, 0u);
    bch_band(&cA);
    (void)band_check(&cA, 11, "planar, every constraint");
    (void)band_check(&cA, 12, "planar, every constraint");
    planar_chain(&cA, VLBE_ALE_CONSERVATIVE);
    bch_band(&cA);
    (void)band_check(&cA, 13, "planar, conservative");
}

/* Fixed-p nodes with a clamp (kl: the clamped element's 4 coordinates at
   either end, the clamp rows before node 0: 4 + 4 - 1); an equal-length
   group with free ends on both sides, whose rows sit after its last node
   and reach back to its first p: the band spans the group.  Node 2's p,
   the last of its coordinates, is followed by the 3 x 5 coordinates of
   nodes 3..5 and the group's two rows: kl = 3 * 5 + 2. */
static void test_planar_lagrangian(void **state)
{
    (void)state;
    lagrangian_chain(&cA, 6);
    bch_band(&cA);
    assert_int_equal(band_check(&cA, 21, "Lagrangian, clamp + pin"), 4 + 4 - 1);
    mixed_chain(&cA);
    bch_band(&cA);
    assert_int_equal(band_check(&cA, 22, "mixed, equal-length group"), 3 * 5 + 2);
}

static void test_rational_chain(void **state)
{
    (void)state;
    rational_chain(&cA);
    bch_band(&cA);
    (void)band_check(&cA, 31, "rational");
}

static void test_chain3d_spin(void **state)
{
    (void)state;
    chain3d(&cA, 0);
    bch_band(&cA);
    (void)band_check(&cA, 41, "3D with spin");
    (void)band_check(&cA, 42, "3D with spin");
    chain3d(&cA, 1);
    bch_band(&cA);
    (void)band_check(&cA, 43, "3D, SLOPE_ROT and SLOPE_DIR");
    (void)band_check(&cA, 44, "3D, SLOPE_ROT and SLOPE_DIR");
}

/* Uniform chains of nn nodes, p every 0.25 (no band set):
     0  ALE string: every node free, no constraint
     1  Lagrangian: fixed p's, clamp at 0, pin at the end (lagrangian_chain)
     2  ALE between clamped fixed ends: interior nodes free, equally spaced
        (EQUAL_LEN over the chain, its ends fixed: one row per interior node)
     3  3D ALE shaft with spin: every node free, no constraint */
static void uniform_chain(bch *c, int fam, int nn)
{
    int i;
    if (fam == 1) {
        lagrangian_chain(c, nn);
        return;
    }
    memset(c, 0, sizeof *c);
    if (fam == 3) {
        assert_int_equal(vlbe_ale3_mat_circle(&c->mat3, VLBE_R(1.0), VLBE_R(100.0), VLBE_R(40.0),
                                              VLBE_R(0.1)),
                         VLBE_OK);
        assert_int_equal(vlbe_ale3_elem_init(&c->el3, &c->mat3, 0u, 0, 0), VLBE_OK);
        for (i = 0; i < nn; ++i) c->node[i] = node_make(VLBE_ALE_PFREE, 0.25 * i);
        assert_int_equal(vlbe_ale_chain_init3(&c->ch, &c->el3, c->node, nn, NN_MAX, c->con, NC_MAX),
                         VLBE_OK);
    } else {
        c->mat = mat_std();
        assert_int_equal(vlbe_ale_elem_init(&c->el, &c->mat, 0u, 0, 0, 0), VLBE_OK);
        for (i = 0; i < nn; ++i)
            c->node[i] = node_make(fam == 2 && (i == 0 || i == nn - 1) ? VLBE_ALE_PFIXED : VLBE_ALE_PFREE,
                                   0.25 * i);
        assert_int_equal(vlbe_ale_chain_init(&c->ch, &c->el, c->node, nn, NN_MAX, c->con, NC_MAX),
                         VLBE_OK);
        if (fam == 2) {
            bch_add(c, con_make(VLBE_ALE_CON_POS, 0, 0, 0, 0, 0, 0));
            bch_add(c, con_make(VLBE_ALE_CON_SLOPE, 0, 0, 0, 1, 0, 0));
            bch_add(c, con_make(VLBE_ALE_CON_EQUAL_LEN, 0, nn - 1, 0, 0, 0, 0));
            bch_add(c, con_make(VLBE_ALE_CON_POS, nn - 1, 0, 0, 0, 0, 0));
        }
    }
    assert_int_equal(vlbe_ale_chain_layout(&c->ch), VLBE_OK);
}

/* kl of the uniform chains for 3 .. 129 nodes: the same for every length,
   the span of the widest element, from the first coordinate of its first
   node to the last of its second, with the rows placed between them:
     ALE string     5 + 5 - 1 = 9
     Lagrangian     4 + 4 - 1 = 7 (the clamp rows sit before node 0)
     clamped ALE    the interior elements: 5 + 1 (the node's equal-length
                    row) + 5 - 1 = 10 (the first: 4 + 5 - 1 = 8, its clamp
                    rows before node 0; with 3 nodes there is no element
                    between two free p's: 5 + 1 + 4 - 1 = 9)
     3D with spin   8 + 8 - 1 = 15
   At 9 nodes each is compared with the dense callbacks (band_check).
   Storage per matrix at 129 nodes: (n + m)(2 kl + 1) against n^2. */
static void test_uniform_bandwidth(void **state)
{
    static int big[NN_MAX * 8 + 16];
    static const int nns[7] = {3, 5, 9, 17, 33, 65, 129};
    static const int want[4] = {5 + 5 - 1, 4 + 4 - 1, 5 + 1 + 5 - 1, 8 + 8 - 1};
    static const char *const name[4] = {"uniform ALE string", "uniform Lagrangian",
                                        "uniform clamped ALE", "uniform 3D with spin"};
    int fam, k;
    (void)state;
    for (fam = 0; fam < 4; ++fam)
        for (k = 0; k < 7; ++k) {
            vlbe_ale_chain *ch = &cA.ch;
            uniform_chain(&cA, fam, nns[k]);
            assert_int_equal(vlbe_ale_chain_band(ch, big, NN_MAX * 8 + 16), VLBE_OK);
            assert_int_equal(vlbe_ale_chain_layout(ch), VLBE_OK);
            const int wk = fam == 2 && nns[k] == 3 ? 5 + 1 + 4 - 1 : want[fam];
            if (ch->kl != wk)
                fail_msg("%s, %d nodes: kl = %d, expected %d", name[fam], nns[k], ch->kl, wk);
            assert_int_equal(ch->ku, ch->kl);
            if (nns[k] == 129 && tu_report_on())
                print_message("    %-22s 129 nodes: n %4d m %3d kl %2d: %6d reals a matrix, dense %6d\n",
                              name[fam], ch->n, ch->m, ch->kl, (ch->n + ch->m) * (2 * ch->kl + 1),
                              ch->n * ch->n);
            if (nns[k] == 9) {
                bch_band(&cA);
                assert_int_equal(band_check(&cA, 50 + (uint64_t)fam, name[fam]), want[fam]);
            }
        }
}

/* Planar chain with a slider: 5 nodes at p = 0, 0.25, 0.5, 0.6 (free,
   sliding, driven by P), 1.0; clamp at 0, SLIDE_C at 3, pin at 4. */
static void slider_chain(bch *c)
{
    static const double p[5] = {0, 0.25, 0.5, 0.6, 1.0};
    int i;
    memset(c, 0, sizeof *c);
    c->mat = mat_std();
    assert_int_equal(vlbe_ale_elem_init(&c->el, &c->mat, 0u, 0, 0, 0), VLBE_OK);
    for (i = 0; i < 5; ++i) c->node[i] = node_make(VLBE_ALE_PFIXED, p[i]);
    c->node[3].pmode = VLBE_ALE_PFREE;
    c->node[3].slide = 1;
    assert_int_equal(vlbe_ale_chain_init(&c->ch, &c->el, c->node, 5, NN_MAX, c->con, NC_MAX), VLBE_OK);
    bch_add(c, con_make(VLBE_ALE_CON_POS, 0, 0, 0, 0, 0, 0));
    bch_add(c, con_make(VLBE_ALE_CON_SLOPE, 0, 0, 0, 1, 0, 0));
    bch_add(c, con_make(VLBE_ALE_CON_SLIDE_C, 3, 0, 0, 0, 0, 0));
    bch_add(c, con_make(VLBE_ALE_CON_P, 3, 0, 0, 0.6, 0.1, 0));
    bch_add(c, con_make(VLBE_ALE_CON_POS, 4, 0, 0, 0, 0, 0));
    assert_int_equal(vlbe_ale_chain_layout(&c->ch), VLBE_OK);
}

static bstate s_op;
static vlbe_real qn[NA_MAX], vn[NA_MAX];

/* Insert, remove and length control in banded mode re-run the layout: the
   order and kl they leave equal a fresh layout's, and the callbacks still
   match the dense ones (band_check after each).  Planar: insert in element
   0 at p = 0.1, remove that node, then length control of the slider with
   Lstd = 0.25 (right element 0.4 > 1.5 Lstd: a node inserted at 0.75, the
   left neighbour removed, changed 2).  Rational: insert in element 3, then
   length control of the slider with Lstd = 0.18 (left element 0.3 > 1.5
   Lstd: a node inserted; the right neighbour carries a constraint, so
   nothing is removed, changed 1). */
static void test_relayout(void **state)
{
    vlbe_ale_chain *ch = &cA.ch;
    int s, changed;
    (void)state;
    slider_chain(&cA);
    bch_band(&cA);
    (void)band_check(&cA, 61, "slider chain");
    bstate_make(ch, 62, &s_op);
    assert_int_equal(vlbe_ale_chain_insert(ch, 0, VLBE_R(0.1), s_op.t, s_op.q, s_op.v, qn, vn), VLBE_OK);
    assert_int_equal(ch->nn, 6);
    (void)band_check(&cA, 63, "slider chain, inserted");
    bstate_make(ch, 64, &s_op);
    assert_int_equal(vlbe_ale_chain_remove(ch, 1, s_op.t, s_op.q, s_op.v, qn, vn), VLBE_OK);
    assert_int_equal(ch->nn, 5);
    (void)band_check(&cA, 65, "slider chain, removed");
    bstate_make(ch, 66, &s_op);
    s = 3;
    changed = -1;
    assert_int_equal(vlbe_ale_chain_length_control(ch, VLBE_R(0.25), s_op.t, s_op.q, s_op.v, &s, qn,
                                                   vn, &changed),
                     VLBE_OK);
    assert_int_equal(changed, 2);
    assert_int_equal(s, 2);
    (void)band_check(&cA, 67, "slider chain, length control");

    rational_chain(&cA);
    bch_band(&cA);
    bstate_make(ch, 71, &s_op);
    assert_int_equal(vlbe_ale_chain_insert(ch, 3, VLBE_R(1.05), s_op.t, s_op.q, s_op.v, qn, vn), VLBE_OK);
    (void)band_check(&cA, 72, "rational, inserted");
    bstate_make(ch, 73, &s_op);
    s = 2;
    changed = -1;
    assert_int_equal(vlbe_ale_chain_length_control(ch, VLBE_R(0.18), s_op.t, s_op.q, s_op.v, &s, qn,
                                                   vn, &changed),
                     VLBE_OK);
    assert_int_equal(changed, 1);
    (void)band_check(&cA, 74, "rational, length control");
}

/* what a failed call must leave as it was */
typedef struct snap {
    vlbe_ale_chain ch;
    vlbe_ale_node node[NN_MAX];
    vlbe_ale_con con[NC_MAX];
    int ord[NA_MAX + 8];
} snap;

static snap snap0;

static void snap_take(const bch *c, snap *s)
{
    memcpy(&s->ch, &c->ch, sizeof s->ch);
    memcpy(s->node, c->node, sizeof s->node);
    memcpy(s->con, c->con, sizeof s->con);
    memcpy(s->ord, c->ord, sizeof s->ord);
}

static void snap_check(const bch *c, const snap *s)
{
    assert_memory_equal(&s->ch, &c->ch, sizeof s->ch);
    assert_memory_equal(s->node, c->node, sizeof s->node);
    assert_memory_equal(s->con, c->con, sizeof s->con);
    assert_memory_equal(s->ord, c->ord, sizeof s->ord);
}

/* order_cap too small (one short of n + m for the layout; n + m, not the
   n + m + 4 an insertion needs, for insert and length control; set by
   band() below the n + m - 4 of a removal's layout): VLBE_EWORK and the
   chain, its node and constraint arrays, the order and the outputs
   bitwise as before; the rational chain's element objects too.  A
   negative capacity: VLBE_EARG, nothing changed.  n + m suffices for a
   removal, n + m + 4 for an insertion. */
static void test_ework(void **state)
{
    static vlbe_rancf_elem els0[12];
    vlbe_ale_chain *ch = &cA.ch;
    int n, m, s, changed;
    (void)state;
    slider_chain(&cA); /* dense, laid out */
    n = cA.ch.n;
    m = cA.ch.m;
    fill(NA_MAX, VLBE_R(-5.0), qn);
    fill(NA_MAX, VLBE_R(-5.0), vn);
    assert_int_equal(vlbe_ale_chain_band(ch, cA.ord, n + m - 1), VLBE_OK);
    snap_take(&cA, &snap0);
    assert_int_equal(vlbe_ale_chain_layout(ch), VLBE_EWORK);
    snap_check(&cA, &snap0);
    assert_int_equal(vlbe_ale_chain_band(ch, cA.ord, -1), VLBE_EARG);
    snap_check(&cA, &snap0);
    assert_int_equal(vlbe_ale_chain_band(ch, cA.ord, n + m), VLBE_OK);
    assert_int_equal(vlbe_ale_chain_layout(ch), VLBE_OK);
    bstate_make(ch, 81, &s_op);
    snap_take(&cA, &snap0);
    assert_int_equal(vlbe_ale_chain_insert(ch, 0, VLBE_R(0.1), s_op.t, s_op.q, s_op.v, qn, vn),
                     VLBE_EWORK);
    snap_check(&cA, &snap0);
    s = 3;
    changed = -1;
    assert_int_equal(vlbe_ale_chain_length_control(ch, VLBE_R(0.25), s_op.t, s_op.q, s_op.v, &s, qn,
                                                   vn, &changed),
                     VLBE_EWORK);
    snap_check(&cA, &snap0);
    assert_int_equal(s, 3);
    assert_int_equal(changed, -1);
    assert_all_equal(NA_MAX, qn, VLBE_R(-5.0));
    assert_all_equal(NA_MAX, vn, VLBE_R(-5.0));
    /* a capacity shrunk by band() below what the removal's layout needs
       (n + m - 4): the removal refused before anything changes */
    assert_int_equal(vlbe_ale_chain_band(ch, cA.ord, n + m - 5), VLBE_OK);
    snap_take(&cA, &snap0);
    assert_int_equal(vlbe_ale_chain_remove(ch, 2, s_op.t, s_op.q, s_op.v, qn, vn), VLBE_EWORK);
    snap_check(&cA, &snap0);
    assert_all_equal(NA_MAX, qn, VLBE_R(-5.0));
    assert_int_equal(vlbe_ale_chain_band(ch, cA.ord, n + m), VLBE_OK);
    assert_int_equal(vlbe_ale_chain_layout(ch), VLBE_OK);
    /* a removal needs no more room */
    assert_int_equal(vlbe_ale_chain_remove(ch, 2, s_op.t, s_op.q, s_op.v, qn, vn), VLBE_OK);
    (void)band_check(&cA, 82, "slider chain, removed at n + m");
    /* n + m + 4: the insertion fits */
    n = cA.ch.n;
    m = cA.ch.m;
    assert_int_equal(vlbe_ale_chain_band(ch, cA.ord, n + m + 4), VLBE_OK);
    assert_int_equal(vlbe_ale_chain_layout(ch), VLBE_OK);
    bstate_make(ch, 83, &s_op);
    assert_int_equal(vlbe_ale_chain_insert(ch, 0, VLBE_R(0.1), s_op.t, s_op.q, s_op.v, qn, vn), VLBE_OK);
    assert_int_equal(cA.ch.n + cA.ch.m, n + m + 4);
    (void)band_check(&cA, 84, "slider chain, inserted at n + m + 4");

    /* rational: the element objects unchanged as well */
    rational_chain(&cA);
    n = cA.ch.n;
    m = cA.ch.m;
    assert_int_equal(vlbe_ale_chain_band(ch, cA.ord, n + m), VLBE_OK);
    assert_int_equal(vlbe_ale_chain_layout(ch), VLBE_OK);
    bstate_make(ch, 85, &s_op);
    memcpy(els0, r_els, sizeof els0);
    snap_take(&cA, &snap0);
    assert_int_equal(vlbe_ale_chain_insert(ch, 3, VLBE_R(1.05), s_op.t, s_op.q, s_op.v, qn, vn),
                     VLBE_EWORK);
    snap_check(&cA, &snap0);
    assert_memory_equal(els0, r_els, sizeof els0);
    /* back to dense: kl = ku = 0, the dense callbacks (laid out again) */
    assert_int_equal(vlbe_ale_chain_band(ch, NULL, 0), VLBE_OK);
    assert_true(ch->order == NULL && ch->order_cap == 0 && ch->kl == 0 && ch->ku == 0);
    assert_int_equal(vlbe_ale_chain_layout(ch), VLBE_OK);
}

/* every callback of sys the chain's, user the chain, n and m its own */
static void dae_is_chain(const vlbe_dae *sys, vlbe_ale_chain *ch)
{
    assert_true(sys->user == (void *)ch && sys->n == ch->n && sys->m == ch->m);
    assert_true(sys->mass == vlbe_ale_chain_mass && sys->force == vlbe_ale_chain_force);
    assert_true(sys->force_jac == vlbe_ale_chain_force_jac);
    assert_true(sys->mass_jac == vlbe_ale_chain_mass_jac);
    assert_true(sys->constr == vlbe_ale_chain_constr);
    assert_true(sys->constr_jac == vlbe_ale_chain_constr_jac);
    assert_true(sys->constr_acc == vlbe_ale_chain_constr_acc);
    assert_true(sys->constr_hess == vlbe_ale_chain_constr_hess);
    assert_true(sys->lin_factor == NULL && sys->lin_solve == NULL);
}

/* vlbe_ale_chain_dae: the chain's callbacks; VLBE_DAE_MASS_CONST exactly
   when the chain is planar with every p fixed (the Lagrangian chain), not
   with free or prescribed p's (the mixed planar and the rational chain);
   dense storage by default, banded with the chain's kl, ku and order in
   banded mode; before the first layout VLBE_EARG and sys untouched. */
static void test_chain_dae(void **state)
{
    vlbe_dae sys, ref;
    (void)state;
    planar_chain(&cA, 0u);
    memset(&sys, 0xa5, sizeof sys);
    assert_int_equal(vlbe_ale_chain_dae(&cA.ch, &sys), VLBE_OK);
    dae_is_chain(&sys, &cA.ch);
    assert_int_equal((int)sys.flags, 0);
    assert_int_equal(sys.storage, VLBE_DAE_DENSE);
    assert_true(sys.order == NULL && sys.kl == 0 && sys.ku == 0);
    assert_int_equal(vlbe_dae_check(&sys), VLBE_OK);
    bch_band(&cA);
    assert_int_equal(vlbe_ale_chain_dae(&cA.ch, &sys), VLBE_OK);
    dae_is_chain(&sys, &cA.ch);
    assert_int_equal(sys.storage, VLBE_DAE_BANDED);
    assert_int_equal(sys.kl, cA.ch.kl);
    assert_int_equal(sys.ku, cA.ch.ku);
    assert_true(sys.order == cA.ord);
    assert_int_equal(vlbe_dae_check(&sys), VLBE_OK);

    lagrangian_chain(&cA, 5);
    assert_int_equal(vlbe_ale_chain_dae(&cA.ch, &sys), VLBE_OK);
    dae_is_chain(&sys, &cA.ch);
    assert_int_equal((int)sys.flags, (int)VLBE_DAE_MASS_CONST);
    rational_chain(&cA);
    assert_int_equal(vlbe_ale_chain_dae(&cA.ch, &sys), VLBE_OK);
    dae_is_chain(&sys, &cA.ch);
    assert_int_equal((int)sys.flags, 0);

    /* not laid out: nothing written */
    memset(&cA, 0, sizeof cA);
    cA.mat = mat_std();
    assert_int_equal(vlbe_ale_elem_init(&cA.el, &cA.mat, 0u, 0, 0, 0), VLBE_OK);
    cA.node[0] = node_make(VLBE_ALE_PFIXED, 0.0);
    cA.node[1] = node_make(VLBE_ALE_PFIXED, 1.0);
    assert_int_equal(vlbe_ale_chain_init(&cA.ch, &cA.el, cA.node, 2, NN_MAX, cA.con, NC_MAX),
                     VLBE_OK);
    memset(&sys, 0x5a, sizeof sys);
    ref = sys;
    assert_int_equal(vlbe_ale_chain_dae(&cA.ch, &sys), VLBE_EARG);
    assert_memory_equal(&sys, &ref, sizeof sys);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_planar_all_constraints),
        cmocka_unit_test(test_planar_lagrangian),
        cmocka_unit_test(test_rational_chain),
        cmocka_unit_test(test_chain3d_spin),
        cmocka_unit_test(test_uniform_bandwidth),
        cmocka_unit_test(test_relayout),
        cmocka_unit_test(test_ework),
        cmocka_unit_test(test_chain_dae),
    };
    return cmocka_run_group_tests_name("chain_band", tests, NULL, NULL);
}

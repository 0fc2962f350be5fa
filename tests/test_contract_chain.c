/* test_contract_chain.c -- cmocka suite of the failure-path contract of the
   chains of ancf_ale.h (vlbe_ale_chain_*, planar, rational through rancf.h,
   3D) and of the beams of corot2d.h (vlbe_cr2d_beam_*)  -- part of vlbe
                                                   SPDX-License-Identifier: MIT
   cc -std=c99 -Wall -Wextra -Wpedantic ... -O2 tests/test_contract_chain.c -lcmocka -lm
   (add -DVLBE_USE_FLOAT for the float build; the same source passes in both)

   The contract: every index is range-checked without overflow (VLBE_EARG);
   a pointer the documentation allows to be NULL may be NULL; a failed call
   leaves every output, the chain and its node / constraint / element arrays
   bitwise as they were; no VLBE_OK with NaN/Inf from finite inputs.  Each
   check takes a snapshot (memcpy of the chain struct and its arrays) and
   fills the outputs with a sentinel before the call, then compares with
   memcmp: tolerance 0, bitwise.  The callbacks' output arrays are
   documented as unspecified after a failure on finite inputs (assembled in
   place); for non-finite inputs they must stay untouched, which is checked.
   Results that must equal another route (K with and without D) are compared
   bitwise too: the same arithmetic in the same order.

   Tests (each says what failed on 77b73ad)
     range              pnode / gather / insert / remove / locate with indices
                        -1, nn - 1, nn, INT_MAX, INT_MIN (planar and 3D)
     overflow_args      insert at INT_MAX, an EQUAL_LEN constraint whose
                        node2 - node overflows, vlbe_cr2d_beam_init with ne
                        = INT_MAX and INT_MAX / 3
     null_optional      gather with v NULL and ve given; force_jac with D
                        NULL (and K NULL) on planar, rational and 3D chains
     failed_untouched   length control whose removal fails (rational chain),
                        energy with NaN in q, gather failing (NaN, Lmin,
                        pfun), layout refused (d, spin kept)
     lc_args            length control: Lstd NaN, Inf, 0, < 0, 0.5 Lstd <=
                        Lmin; slider outside the chain; 3D chain
     callbacks_input    every chain callback with NaN in q, v, a, lambda:
                        outputs untouched, status and element recorded
     overflow_outputs   finite inputs whose result overflows: chain length,
                        energy, force (gravity on a point mass); the scatter
                        helper's finiteness flag
     beam               vlbe_cr2d_beam_*: init (overflow, NaN fix), NaN in
                        q, v, a, a NaN fix function, a fix moved out of
                        range, loads that overflow, energy that overflows,
                        force_jac with D NULL */
#include "test_util.h"
#include "../rancf.h"
#include "../corot2d.h"
#include "ale_fixtures.h"
#include "rancf_fixtures.h"

#include <limits.h>
#include <string.h>

#define NN 4        /* nodes of the planar chain                  */
#define NNCAP 8     /* node capacity                              */
#define NCCAP 4     /* constraint capacity                        */
#define NMAX 64     /* coordinates (the planar chain has 4*5 + 2) */
#define SENT ((vlbe_real)-1234.5) /* sentinel of the outputs        */

/* ------------------------------------------------------------------------ */
/* fixtures                                                                   */
/* ------------------------------------------------------------------------ */

/* A planar chain: node 0 fixed at p = 0, node 1 free (0.3, point mass 0.2,
   sliding: two slopes), node 2 fixed at 0.6, node 3 prescribed p = 1 + 0.1 t
   + 0.1 t^2 (so the prescribed-p'' inertia runs in force / force_jac);
   gravity (0, -9.81); a straight state along (1, 0) with a small bend and
   velocities 0.1 .. . */
typedef struct pfx {
    vlbe_ale_mat mat;
    vlbe_ale_elem el;
    vlbe_ale_node node[NNCAP];
    vlbe_ale_con con[NCCAP];
    vlbe_ale_chain ch;
    vlbe_real q[NMAX], v[NMAX], a[NMAX], lam[NMAX];
} pfx;

/* what a failed call must leave as it was */
typedef struct snap {
    vlbe_ale_chain ch;
    vlbe_ale_node node[NNCAP];
    vlbe_ale_con con[NCCAP];
} snap;

static void snap_take(const vlbe_ale_chain *ch, snap *s)
{
    memset(s, 0, sizeof *s);
    memcpy(&s->ch, ch, sizeof s->ch);
    memcpy(s->node, ch->node, sizeof(vlbe_ale_node) * (size_t)ch->nn_cap);
    memcpy(s->con, ch->con, sizeof(vlbe_ale_con) * (size_t)ch->ncon_cap);
}

static void snap_check(const vlbe_ale_chain *ch, const snap *s)
{
    assert_memory_equal(&s->ch, ch, sizeof s->ch);
    assert_memory_equal(s->node, ch->node, sizeof(vlbe_ale_node) * (size_t)ch->nn_cap);
    assert_memory_equal(s->con, ch->con, sizeof(vlbe_ale_con) * (size_t)ch->ncon_cap);
}

static void pfx_init(pfx *c)
{
    int i;
    memset(c, 0, sizeof *c); /* every byte defined: the snapshots are compared with memcmp */
    c->mat = mat_std();
    assert_int_equal(vlbe_ale_elem_init(&c->el, &c->mat, 0u, 0, 0, 0), VLBE_OK);
    c->node[0] = node_make(VLBE_ALE_PFIXED, 0.0);
    c->node[1] = node_make(VLBE_ALE_PFREE, 0.3);
    c->node[1].mass = VLBE_R(0.2);
    c->node[1].slide = 1;
    c->node[2] = node_make(VLBE_ALE_PFIXED, 0.6);
    c->node[3] = node_make(VLBE_ALE_PPRESCRIBED, 1.0);
    c->node[3].pd = VLBE_R(0.1);
    c->node[3].pdd = VLBE_R(0.2);
    assert_int_equal(vlbe_ale_chain_init(&c->ch, &c->el, c->node, NN, NNCAP, c->con, NCCAP), VLBE_OK);
    c->ch.g[1] = VLBE_R(-9.81);
    {
        const vlbe_ale_con k1 = con_make(VLBE_ALE_CON_POS, 0, 0, 0, 0.0, 0.0, 0.0);
        const vlbe_ale_con k2 = con_make(VLBE_ALE_CON_SLIDE_D, 1, 0, 0, 0.0, 0.0, 0.0);
        assert_int_equal(vlbe_ale_chain_add(&c->ch, &k1), VLBE_OK);
        assert_int_equal(vlbe_ale_chain_add(&c->ch, &k2), VLBE_OK);
    }
    assert_int_equal(vlbe_ale_chain_layout(&c->ch), VLBE_OK);
    assert_true(c->ch.n <= NMAX && c->ch.m <= NMAX);
    {
        const vlbe_real r0[2] = {0, 0}, dir[2] = {1, 0};
        vlbe_ale_chain_straight(&c->ch, r0, dir, c->q);
    }
    for (i = 0; i < c->ch.n; ++i) {
        c->q[i] += (vlbe_real)(0.01 * (i % 3)); /* a small bend */
        c->v[i] = (vlbe_real)(0.1 + 0.01 * i);
        c->a[i] = (vlbe_real)(0.2 - 0.01 * i);
    }
    c->q[c->node[1].ofs + 6] = VLBE_R(0.3); /* the free p */
    for (i = 0; i < c->ch.m; ++i) c->lam[i] = (vlbe_real)(1.0 + i);
}

/* A 3D chain of three elements (with spin), nodes fixed at 0, 0.5, 1, 1.5. */
typedef struct tfx {
    vlbe_ale3_mat mat;
    vlbe_ale3_elem el;
    vlbe_ale_node node[NNCAP];
    vlbe_ale_con con[NCCAP];
    vlbe_ale_chain ch;
    vlbe_real q[NMAX], v[NMAX];
} tfx;

static void tfx_init(tfx *c)
{
    const vlbe_real r0[3] = {0, 0, 0}, dir[3] = {1, 0, 0};
    int i;
    memset(c, 0, sizeof *c);
    assert_int_equal(vlbe_ale3_mat_circle(&c->mat, VLBE_R(1.0), VLBE_R(100.0), VLBE_R(40.0), VLBE_R(0.1)),
                     VLBE_OK);
    assert_int_equal(vlbe_ale3_elem_init(&c->el, &c->mat, 0u, 0, 0), VLBE_OK);
    for (i = 0; i < 4; ++i) c->node[i] = node_make(VLBE_ALE_PFIXED, 0.5 * i);
    assert_int_equal(vlbe_ale_chain_init3(&c->ch, &c->el, c->node, 4, NNCAP, c->con, NCCAP), VLBE_OK);
    assert_int_equal(vlbe_ale_chain_layout(&c->ch), VLBE_OK);
    assert_true(c->ch.n <= NMAX);
    vlbe_ale_chain_straight(&c->ch, r0, dir, c->q);
    for (i = 0; i < c->ch.n; ++i) {
        c->q[i] += (vlbe_real)(0.01 * (i % 5));
        c->v[i] = (vlbe_real)(0.05 * (i % 4));
    }
}

/* Rational elements (a vlbe_rancf_elem is ~22 kB: static), written through
   a zeroed object so that every byte is defined for memcmp (the library's
   init leaves unused rule points and padding as in its local). */
static vlbe_rancf_elem r_els[NNCAP - 1], r_els0[NNCAP - 1];

static void rel_init(vlbe_rancf_elem *dst, const vlbe_ale_mat *mat)
{
    static const vlbe_real w[4] = {1, 1, 1, 1};
    rancf_el_init(dst, mat, w, 0);
}

/* A rational chain (unit weights) with nodes at p = 0, 1, 1.3 (sliding,
   free p), 2.25, 3.25, straight along x: the slider's left element (0.3)
   is shorter than 0.5 Lstd for Lstd = 1, its right one (0.95) shorter
   than Lstd in double and float, so length control takes rule (b) only:
   remove node 1. */
typedef struct rfx {
    vlbe_ale_mat mat;
    vlbe_ale_node node[NNCAP];
    vlbe_ale_con con[NCCAP];
    vlbe_ale_chain ch;
    vlbe_real q[NMAX], v[NMAX];
} rfx;

static void rfx_init(rfx *c)
{
    static const double pn[5] = {0.0, 1.0, 1.3, 2.25, 3.25};
    const vlbe_real r0[2] = {0, 0}, dir[2] = {1, 0};
    int i;
    memset(c, 0, sizeof *c);
    memset(r_els, 0, sizeof r_els);
    c->mat = mat_std();
    for (i = 0; i < NNCAP - 1; ++i) rel_init(&r_els[i], &c->mat);
    for (i = 0; i < 5; ++i) c->node[i] = node_make(VLBE_ALE_PFIXED, pn[i]);
    c->node[2].pmode = VLBE_ALE_PFREE;
    c->node[2].slide = 1;
    assert_int_equal(vlbe_rancf_chain_init(&c->ch, r_els, c->node, 5, NNCAP, c->con, NCCAP), VLBE_OK);
    {
        const vlbe_ale_con k = con_make(VLBE_ALE_CON_SLIDE_C, 2, 0, 0, 0.0, 0.0, 0.0);
        assert_int_equal(vlbe_ale_chain_add(&c->ch, &k), VLBE_OK);
    }
    assert_int_equal(vlbe_ale_chain_layout(&c->ch), VLBE_OK);
    vlbe_ale_chain_straight(&c->ch, r0, dir, c->q);
    for (i = 0; i < c->ch.n; ++i) c->v[i] = (vlbe_real)(0.01 * (i % 7));
    c->v[c->node[2].ofs + 6] = VLBE_R(0.0);
}

/* O(1) co-rotational material (every term of comparable size) */
static vlbe_cr2d_mat beam_mat(void)
{
    vlbe_cr2d_mat m;
    m.EA = VLBE_R(40.0);
    m.EI = VLBE_R(1.5);
    m.rhoA = VLBE_R(1.3);
    m.rhoI = VLBE_R(0.15);
    m.ray_a = VLBE_R(0.3);
    m.ray_b = VLBE_R(0.02);
    return m;
}

static void fill_int(int n, int *a)
{
    memset(a, 0x5a, sizeof(int) * (size_t)n);
}

static void assert_int_sent(int n, const int *a)
{
    int ref[NMAX];
    fill_int(n, ref);
    assert_memory_equal(a, ref, sizeof(int) * (size_t)n);
}

/* pfun of test_failed_untouched: kind 1 fails, kind 2 gives NaN */
static int pfun_kind;
static int pfun_bad(void *user, int node, vlbe_real t, vlbe_real *p3)
{
    (void)user;
    (void)node;
    p3[0] = VLBE_R(1.0) + VLBE_R(0.1) * t;
    p3[1] = VLBE_R(0.1);
    p3[2] = pfun_kind == 2 ? (vlbe_real)NAN : VLBE_R(0.0);
    return pfun_kind == 1;
}

/* ------------------------------------------------------------------------ */
/* 1. indices out of range                                                    */
/* ------------------------------------------------------------------------ */

/* pnode and gather with indices outside the chain: VLBE_EARG, p3, qe, ve,
   idx, mode untouched.  Fails on 77b73ad: no range check, pnode(nn),
   pnode(-1) and gather(nn - 1) read past node[] (ASan heap-buffer-overflow,
   garbage or a crash elsewhere).  Also insert, remove and locate, which
   already refused these (passes on 77b73ad too, kept as audit). */
static void test_range(void **state)
{
    static pfx c;
    static tfx d;
    static snap s0;
    const int bad_nodes[] = {-1, NN, INT_MAX, INT_MIN};
    const int bad_elems[] = {-1, NN - 1, NN, INT_MAX, INT_MIN};
    vlbe_real p3[3], qe[VLBE_ALE3_NQ], ve[VLBE_ALE3_NQ], qn[NMAX], vn[NMAX];
    int idx[VLBE_ALE3_NQ], k, e;
    unsigned md;
    (void)state;
    pfx_init(&c);
    tfx_init(&d);
    snap_take(&c.ch, &s0);
    for (k = 0; k < 4; ++k) {
        fill(3, SENT, p3);
        assert_int_equal(vlbe_ale_chain_pnode(&c.ch, bad_nodes[k], 0, c.q, c.v, p3), VLBE_EARG);
        assert_all_equal(3, p3, SENT);
        assert_int_equal(vlbe_ale_chain_pnode(&d.ch, bad_nodes[k], 0, d.q, d.v, p3), VLBE_EARG);
        assert_all_equal(3, p3, SENT);
    }
    for (k = 0; k < 5; ++k) {
        const vlbe_ale_chain *chs[2];
        const vlbe_real *qs[2], *vs[2];
        int w;
        chs[0] = &c.ch;
        chs[1] = &d.ch;
        qs[0] = c.q;
        qs[1] = d.q;
        vs[0] = c.v;
        vs[1] = d.v;
        for (w = 0; w < 2; ++w) {
            const int eb = bad_elems[k];
            fill(VLBE_ALE3_NQ, SENT, qe);
            fill(VLBE_ALE3_NQ, SENT, ve);
            fill_int(VLBE_ALE3_NQ, idx);
            md = 0xa5a5a5a5u;
            assert_int_equal(vlbe_ale_chain_gather(chs[w], eb, 0, qs[w], vs[w], qe, ve, idx, &md),
                             VLBE_EARG);
            assert_all_equal(VLBE_ALE3_NQ, qe, SENT);
            assert_all_equal(VLBE_ALE3_NQ, ve, SENT);
            assert_int_sent(VLBE_ALE3_NQ, idx);
            assert_true(md == 0xa5a5a5a5u);
        }
    }
    /* the last element is fine, one past it is not */
    assert_int_equal(vlbe_ale_chain_gather(&c.ch, NN - 2, 0, c.q, c.v, qe, ve, idx, &md), VLBE_OK);
    /* insert, remove: indices outside the chain (audit: refused on 77b73ad too
       except INT_MAX, test_overflow_args) */
    for (k = 0; k < 5; ++k) {
        if (bad_elems[k] == INT_MAX) continue;
        fill(NMAX, SENT, qn);
        fill(NMAX, SENT, vn);
        assert_int_equal(vlbe_ale_chain_insert(&c.ch, bad_elems[k], VLBE_R(0.45), 0, c.q, c.v, qn, vn),
                         VLBE_EARG);
        assert_int_equal(vlbe_ale_chain_remove(&c.ch, bad_elems[k], 0, c.q, c.v, qn, vn), VLBE_EARG);
        assert_all_equal(NMAX, qn, SENT);
        assert_all_equal(NMAX, vn, SENT);
        snap_check(&c.ch, &s0);
    }
    /* locate: a p outside the chain, EBOUND, *e untouched */
    e = -77;
    assert_int_equal(vlbe_ale_chain_locate(&c.ch, 0, c.q, VLBE_R(5.0), &e), VLBE_EBOUND);
    assert_int_equal(e, -77);
    snap_check(&c.ch, &s0);
}

/* ------------------------------------------------------------------------ */
/* 2. range checks that overflowed                                            */
/* ------------------------------------------------------------------------ */

/* vlbe_ale_chain_insert(ch, INT_MAX, ...): VLBE_EARG, nothing written.
   Fails on 77b73ad: e + 1 >= nn overflows, the check passes, and the call
   reads node[INT_MAX] (segfault at -O2).  An EQUAL_LEN constraint with node
   = INT_MIN, node2 = INT_MAX: VLBE_EARG.  Fails on 77b73ad under UBSan
   (node2 - node - 1: signed overflow; elsewhere it happens to wrap to a
   negative count).  vlbe_cr2d_beam_init with ne = INT_MAX and INT_MAX / 3:
   VLBE_EARG, the beam untouched.  Fails on 77b73ad: 3 (ne + 1) overflows
   and init returns VLBE_OK. */
static void test_overflow_args(void **state)
{
    static pfx c;
    static snap s0;
    vlbe_real qn[NMAX], vn[NMAX];
    vlbe_cr2d_elem el[2];
    vlbe_cr2d_beam b, b0;
    vlbe_cr2d_mat m = beam_mat();
    vlbe_ale_con k;
    const int nes[] = {INT_MAX, INT_MAX / 3, INT_MAX - 1, INT_MAX / 2};
    int i;
    (void)state;
    pfx_init(&c);
    snap_take(&c.ch, &s0);
    fill(NMAX, SENT, qn);
    fill(NMAX, SENT, vn);
    assert_int_equal(vlbe_ale_chain_insert(&c.ch, INT_MAX, VLBE_R(0.45), 0, c.q, c.v, qn, vn), VLBE_EARG);
    assert_int_equal(vlbe_ale_chain_insert(&c.ch, INT_MAX, VLBE_R(0.45), 0, c.q, NULL, qn, NULL),
                     VLBE_EARG);
    assert_all_equal(NMAX, qn, SENT);
    assert_all_equal(NMAX, vn, SENT);
    snap_check(&c.ch, &s0);

    k = con_make(VLBE_ALE_CON_EQUAL_LEN, 0, 0, 0, 0.0, 0.0, 0.0);
    k.node = INT_MIN;
    k.node2 = INT_MAX;
    assert_int_equal(vlbe_ale_chain_add(&c.ch, &k), VLBE_EARG);
    k.node = -5;
    k.node2 = INT_MAX - 2;
    assert_int_equal(vlbe_ale_chain_add(&c.ch, &k), VLBE_EARG);
    k.node = 2;
    k.node2 = INT_MIN;
    assert_int_equal(vlbe_ale_chain_add(&c.ch, &k), VLBE_EARG);
    snap_check(&c.ch, &s0);

    memset(el, 0, sizeof el);
    {
        const vlbe_real X1[2] = {0, 0}, X2[2] = {1, 0}, X3[2] = {2, 0};
        assert_int_equal(vlbe_cr2d_elem_init(&el[0], &m, X1, X2, 0u), VLBE_OK);
        assert_int_equal(vlbe_cr2d_elem_init(&el[1], &m, X2, X3, 0u), VLBE_OK);
    }
    for (i = 0; i < 4; ++i) {
        memset(&b, 0x5a, sizeof b);
        memcpy(&b0, &b, sizeof b);
        assert_int_equal(vlbe_cr2d_beam_init(&b, el, nes[i], NULL, 0), VLBE_EARG);
        assert_memory_equal(&b, &b0, sizeof b);
    }
    /* the largest ne whose n = 3 (ne + 1) fits in an int: accepted where
       n * n fits in a size_t (no element is read by init) */
    if (sizeof(size_t) >= 8) {
        assert_int_equal(vlbe_cr2d_beam_init(&b, el, INT_MAX / 3 - 1, NULL, 0), VLBE_OK);
        assert_int_equal(b.n, 3 * (INT_MAX / 3));
    }
}

/* ------------------------------------------------------------------------ */
/* 3. pointers the documentation allows to be NULL                            */
/* ------------------------------------------------------------------------ */

/* gather with v = NULL and ve given: coordinates as with ve = NULL, ve not
   written.  Fails on 77b73ad: the test of ve reads v[] (SIGSEGV).
   force_jac with D = NULL: returns 0 and K bitwise equal to K of the call
   with D (planar, rational, 3D chains); with K = NULL, D bitwise equal.
   Fails on 77b73ad: K[i] = D[i] = 0 writes through NULL (SIGSEGV). */
static void test_null_optional(void **state)
{
    static pfx c;
    static tfx d;
    static rfx r;
    static vlbe_real K0[NMAX * NMAX], D0[NMAX * NMAX], K1[NMAX * NMAX], D1[NMAX * NMAX];
    vlbe_real qe[VLBE_ALE3_NQ], qe0[VLBE_ALE3_NQ], ve[VLBE_ALE3_NQ];
    int idx[VLBE_ALE3_NQ], idx0[VLBE_ALE3_NQ], w;
    unsigned md, md0;
    (void)state;
    pfx_init(&c);
    tfx_init(&d);
    rfx_init(&r);
    assert_int_equal(vlbe_ale_chain_gather(&c.ch, 1, VLBE_R(0.2), c.q, NULL, qe0, NULL, idx0, &md0),
                     VLBE_OK);
    fill(VLBE_ALE3_NQ, SENT, ve);
    assert_int_equal(vlbe_ale_chain_gather(&c.ch, 1, VLBE_R(0.2), c.q, NULL, qe, ve, idx, &md), VLBE_OK);
    assert_memory_equal(qe, qe0, sizeof(vlbe_real) * 10);
    assert_memory_equal(idx, idx0, sizeof(int) * 10);
    assert_true(md == md0);
    assert_all_equal(VLBE_ALE3_NQ, ve, SENT);

    for (w = 0; w < 3; ++w) {
        vlbe_ale_chain *ch = w == 0 ? &c.ch : w == 1 ? &r.ch : &d.ch;
        const vlbe_real *q = w == 0 ? c.q : w == 1 ? r.q : d.q;
        const vlbe_real *v = w == 0 ? c.v : w == 1 ? r.v : d.v;
        const size_t nn = (size_t)ch->n * (size_t)ch->n;
        assert_int_equal(vlbe_ale_chain_force_jac(ch, VLBE_R(0.2), q, v, K0, D0), 0);
        fill(NMAX * NMAX, SENT, D1);
        assert_int_equal(vlbe_ale_chain_force_jac(ch, VLBE_R(0.2), q, v, K1, NULL), 0);
        assert_memory_equal(K1, K0, sizeof(vlbe_real) * nn);
        assert_all_equal(NMAX * NMAX, D1, SENT);
        fill(NMAX * NMAX, SENT, K1);
        assert_int_equal(vlbe_ale_chain_force_jac(ch, VLBE_R(0.2), q, v, NULL, D1), 0);
        assert_memory_equal(D1, D0, sizeof(vlbe_real) * nn);
        assert_all_equal(NMAX * NMAX, K1, SENT);
        assert_int_equal(ch->err, VLBE_OK);
    }
}

/* ------------------------------------------------------------------------ */
/* 4. failed calls write nothing                                              */
/* ------------------------------------------------------------------------ */

/* (a) Length control of the rational chain of rfx_init with Lstd = 1 and
   Lmin = 0.4: rule (b) removes node 1, whose merge gathers element 1 of
   length 0.3 <= Lmin: VLBE_ELENGTH, and the slider, *changed, qn, vn, the
   chain, nodes, constraints and element objects are as before.  Fails on
   77b73ad: *slider went 2 -> 1 and *changed was written before the removal
   failed.
   (b) vlbe_ale_chain_energy with NaN in q: VLBE_ENONFINITE, E untouched.
   Fails on 77b73ad: E was zeroed (and partly summed) first.
   (c) vlbe_ale_chain_gather failing (NaN in q, in v, Lmin, a failing pfun,
   a NaN pfun): qe, ve, idx, mode untouched.  Fails on 77b73ad: mode, idx
   and qe were written before the checks.
   (d) vlbe_ale_chain_layout refused: the chain bitwise as before.  Fails
   on 77b73ad: d and spin were set before the checks (here spin 1 -> 0). */
static void test_failed_untouched(void **state)
{
    static rfx r;
    static pfx c;
    static tfx d;
    static snap s0;
    vlbe_real qn[NMAX], vn[NMAX], E[3], qe[VLBE_ALE3_NQ], ve[VLBE_ALE3_NQ];
    int idx[VLBE_ALE3_NQ], sl, chg, kind;
    unsigned md;
    (void)state;

    /* (a) */
    rfx_init(&r);
    r.ch.Lmin = VLBE_R(0.4);
    snap_take(&r.ch, &s0);
    memcpy(r_els0, r_els, sizeof r_els0);
    fill(NMAX, SENT, qn);
    fill(NMAX, SENT, vn);
    sl = 2;
    chg = -7;
    assert_int_equal(
        vlbe_ale_chain_length_control(&r.ch, VLBE_R(1.0), 0, r.q, r.v, &sl, qn, vn, &chg),
        VLBE_ELENGTH);
    assert_int_equal(sl, 2);
    assert_int_equal(chg, -7);
    assert_all_equal(NMAX, qn, SENT);
    assert_all_equal(NMAX, vn, SENT);
    snap_check(&r.ch, &s0);
    assert_memory_equal(r_els0, r_els, sizeof r_els);
    /* the same with Lmin = 0: done (node 1 removed, the slider follows) */
    r.ch.Lmin = VLBE_R(0.0);
    assert_int_equal(
        vlbe_ale_chain_length_control(&r.ch, VLBE_R(1.0), 0, r.q, r.v, &sl, qn, vn, &chg), VLBE_OK);
    assert_int_equal(sl, 1);
    assert_int_equal(chg, 3);
    assert_int_equal(r.ch.nn, 4);

    /* (b) */
    pfx_init(&c);
    snap_take(&c.ch, &s0);
    assert_int_equal(vlbe_ale_chain_energy(&c.ch, 0, c.q, c.v, E), VLBE_OK);
    fill(3, SENT, E);
    c.q[c.node[2].ofs + 1] = (vlbe_real)NAN;
    assert_int_equal(vlbe_ale_chain_energy(&c.ch, 0, c.q, c.v, E), VLBE_ENONFINITE);
    assert_all_equal(3, E, SENT);
    c.q[c.node[2].ofs + 1] = VLBE_R(0.0);
    c.v[c.node[3].ofs] = (vlbe_real)INFINITY;
    assert_int_equal(vlbe_ale_chain_energy(&c.ch, 0, c.q, c.v, E), VLBE_ENONFINITE);
    assert_all_equal(3, E, SENT);
    snap_check(&c.ch, &s0);

    /* (c) */
    pfx_init(&c);
    for (kind = 0; kind < 5; ++kind) {
        vlbe_status want = VLBE_ENONFINITE;
        int e = 1;
        pfx_init(&c);
        switch (kind) {
        case 0: c.q[c.node[2].ofs + 2] = (vlbe_real)NAN; break;
        case 1: c.v[c.node[1].ofs + 4] = (vlbe_real)-INFINITY; break;
        case 2:
            c.ch.Lmin = VLBE_R(0.35); /* element 1 has length 0.3 */
            want = VLBE_ELENGTH;
            break;
        case 3:
            c.ch.pfun = pfun_bad;
            pfun_kind = 1;
            want = VLBE_ECALLBACK;
            e = 2;
            break;
        default:
            c.ch.pfun = pfun_bad;
            pfun_kind = 2;
            e = 2;
            break;
        }
        snap_take(&c.ch, &s0);
        fill(VLBE_ALE3_NQ, SENT, qe);
        fill(VLBE_ALE3_NQ, SENT, ve);
        fill_int(VLBE_ALE3_NQ, idx);
        md = 0xa5a5a5a5u;
        assert_int_equal(vlbe_ale_chain_gather(&c.ch, e, VLBE_R(0.1), c.q, c.v, qe, ve, idx, &md), want);
        assert_all_equal(VLBE_ALE3_NQ, qe, SENT);
        assert_all_equal(VLBE_ALE3_NQ, ve, SENT);
        assert_int_sent(VLBE_ALE3_NQ, idx);
        assert_true(md == 0xa5a5a5a5u);
        snap_check(&c.ch, &s0);
    }

    /* (d) a 3D chain told NO_SPIN by its mode, with a spin constraint */
    tfx_init(&d);
    {
        const vlbe_ale_con k = con_make(VLBE_ALE_CON_SPIN, 1, 0, 0, 0.0, 0.0, 0.0);
        assert_int_equal(vlbe_ale_chain_add(&d.ch, &k), VLBE_OK);
    }
    assert_int_equal(vlbe_ale_chain_layout(&d.ch), VLBE_OK);
    assert_int_equal(d.ch.spin, 1);
    d.ch.mode = VLBE_ALE3_NO_SPIN;
    snap_take(&d.ch, &s0);
    assert_int_equal(vlbe_ale_chain_layout(&d.ch), VLBE_EARG);
    snap_check(&d.ch, &s0);
    /* a constraint value made NaN in place (add checked it, layout too) */
    pfx_init(&c);
    c.con[0].r[1] = (vlbe_real)NAN;
    snap_take(&c.ch, &s0);
    assert_int_equal(vlbe_ale_chain_layout(&c.ch), VLBE_ENONFINITE);
    snap_check(&c.ch, &s0);
}

/* ------------------------------------------------------------------------ */
/* 5. length control: its parameters                                          */
/* ------------------------------------------------------------------------ */

/* Lstd NaN, +-Inf, 0, < 0, 0.5 Lstd <= Lmin (Lstd = 1, Lmin = 0.5), a
   subnormal Lstd whose half underflows, a slider outside [0, nn), a 3D
   chain: VLBE_EARG, nothing written.  Fails on 77b73ad: NaN was an OK
   no-op (qn, vn written, *changed = 0), Inf removed a node and returned
   VLBE_OK, Lstd <= 0 returned OK, the slider was not checked. */
static void test_lc_args(void **state)
{
    static rfx r;
    static tfx d;
    static snap s0;
    vlbe_real qn[NMAX], vn[NMAX];
    const vlbe_real bad[] = {(vlbe_real)NAN, (vlbe_real)INFINITY, (vlbe_real)-INFINITY,
                             VLBE_R(0.0), VLBE_R(-1.0), VLBE_R(1.0), VLBE_R(1.0)};
    const int bad_sl[] = {-1, 5, INT_MAX, INT_MIN};
    int k, sl, chg;
    (void)state;
    rfx_init(&r);
    memcpy(r_els0, r_els, sizeof r_els0);
    for (k = 0; k < 8; ++k) {
        /* k = 7: the smallest subnormal, whose half rounds to 0 */
        const vlbe_real Lstd = k < 7 ? bad[k] : (vlbe_real)(sizeof(vlbe_real) == 4 ? 1e-45 : 5e-324);
        r.ch.Lmin = k == 5 ? VLBE_R(0.5) : k == 6 ? (vlbe_real)NAN : VLBE_R(0.0);
        snap_take(&r.ch, &s0);
        fill(NMAX, SENT, qn);
        fill(NMAX, SENT, vn);
        sl = 2;
        chg = -7;
        assert_int_equal(vlbe_ale_chain_length_control(&r.ch, Lstd, 0, r.q, r.v, &sl, qn, vn, &chg),
                         VLBE_EARG);
        assert_int_equal(sl, 2);
        assert_int_equal(chg, -7);
        assert_all_equal(NMAX, qn, SENT);
        assert_all_equal(NMAX, vn, SENT);
        snap_check(&r.ch, &s0);
        assert_memory_equal(r_els0, r_els, sizeof r_els);
    }
    r.ch.Lmin = VLBE_R(0.0);
    for (k = 0; k < 4; ++k) {
        sl = bad_sl[k];
        chg = -7;
        snap_take(&r.ch, &s0);
        fill(NMAX, SENT, qn);
        assert_int_equal(
            vlbe_ale_chain_length_control(&r.ch, VLBE_R(1.0), 0, r.q, r.v, &sl, qn, vn, &chg),
            VLBE_EARG);
        assert_int_equal(sl, bad_sl[k]);
        assert_int_equal(chg, -7);
        assert_all_equal(NMAX, qn, SENT);
        snap_check(&r.ch, &s0);
    }
    /* a slider at a chain end: nothing to do, qn = q, *changed = 0 */
    sl = 0;
    assert_int_equal(
        vlbe_ale_chain_length_control(&r.ch, VLBE_R(1.0), 0, r.q, r.v, &sl, qn, vn, &chg), VLBE_OK);
    assert_int_equal(chg, 0);
    assert_memory_equal(qn, r.q, sizeof(vlbe_real) * (size_t)r.ch.n);
    /* 3D chain */
    tfx_init(&d);
    snap_take(&d.ch, &s0);
    sl = 1;
    chg = -7;
    fill(NMAX, SENT, qn);
    assert_int_equal(
        vlbe_ale_chain_length_control(&d.ch, VLBE_R(0.5), 0, d.q, d.v, &sl, qn, vn, &chg),
        VLBE_EARG);
    assert_int_equal(chg, -7);
    assert_all_equal(NMAX, qn, SENT);
    snap_check(&d.ch, &s0);
}

/* ------------------------------------------------------------------------ */
/* 6. callbacks with non-finite inputs                                        */
/* ------------------------------------------------------------------------ */

/* Every chain callback with NaN in q (node 2: element 1 is the first to
   gather it), in v, in a (mass_jac) and in lambda (constr_hess): the
   documented positive value (retry), err = VLBE_ENONFINITE, err_elem the
   element (or -1 for the constraints), every output untouched, nothing
   else of the chain changed.  Fails on 77b73ad: M, Q, K, D, Mq were
   zeroed and partly assembled first; constr, constr_jac, constr_acc and
   constr_hess returned 0 with NaN in C, gamma, H. */
static void test_callbacks_input(void **state)
{
    static pfx c;
    static tfx d;
    static snap s0;
    static vlbe_real A[NMAX * NMAX], B[NMAX * NMAX], C[NMAX], Ct[NMAX];
    int w, kind;
    (void)state;
    for (w = 0; w < 2; ++w)
        for (kind = 0; kind < 3; ++kind) { /* NaN in q, in v, in a */
            vlbe_ale_chain *ch;
            vlbe_real *q, *v, *a;
            int bad_elem;
            pfx_init(&c);
            tfx_init(&d);
            ch = w ? &d.ch : &c.ch;
            q = w ? d.q : c.q;
            v = w ? d.v : c.v;
            a = c.a; /* long enough for both */
            if (kind == 0) q[ch->node[2].ofs + 1] = (vlbe_real)NAN;
            if (kind == 1) v[ch->node[2].ofs + 3] = (vlbe_real)INFINITY;
            if (kind == 2) a[ch->node[2].ofs] = (vlbe_real)NAN;
            bad_elem = 1; /* elements 1 and 2 hold node 2: 1 gathers it first */
            snap_take(ch, &s0);
#define CB_EXPECT(call_, touched_)                                                          \
    do {                                                                                    \
        fill(NMAX * NMAX, SENT, A);                                                         \
        fill(NMAX * NMAX, SENT, B);                                                         \
        fill(NMAX, SENT, C);                                                                \
        fill(NMAX, SENT, Ct);                                                               \
        ch->err = VLBE_OK;                                                                  \
        ch->err_elem = -9;                                                                  \
        if (touched_) {                                                                     \
            assert_int_equal((call_), 1);                                                   \
            assert_int_equal(ch->err, VLBE_ENONFINITE);                                     \
        } else {                                                                            \
            assert_int_equal((call_), 0);                                                   \
            assert_int_equal(ch->err, VLBE_OK);                                             \
        }                                                                                   \
        if (touched_) {                                                                     \
            assert_all_equal(NMAX * NMAX, A, SENT);                                         \
            assert_all_equal(NMAX * NMAX, B, SENT);                                         \
            assert_all_equal(NMAX, C, SENT);                                                \
            assert_all_equal(NMAX, Ct, SENT);                                               \
        }                                                                                   \
        ch->err = s0.ch.err;                                                                \
        ch->err_elem = s0.ch.err_elem;                                                      \
        snap_check(ch, &s0);                                                                \
    } while (0)
            CB_EXPECT(vlbe_ale_chain_mass(ch, 0, q, v, A), kind == 0);
            CB_EXPECT(vlbe_ale_chain_force(ch, 0, q, v, C), kind <= 1);
            CB_EXPECT(vlbe_ale_chain_force_jac(ch, 0, q, v, A, B), kind <= 1);
            CB_EXPECT(vlbe_ale_chain_force_jac(ch, 0, q, v, A, NULL), kind <= 1);
            CB_EXPECT(vlbe_ale_chain_mass_jac(ch, 0, q, v, a, A, B), kind != 1);
            if (w == 0) { /* the planar chain has constraints */
                CB_EXPECT(vlbe_ale_chain_constr(ch, 0, q, C), kind == 0);
                CB_EXPECT(vlbe_ale_chain_constr_jac(ch, 0, q, A, Ct), kind == 0);
                CB_EXPECT(vlbe_ale_chain_constr_acc(ch, 0, q, v, C), kind <= 1);
                CB_EXPECT(vlbe_ale_chain_constr_hess(ch, 0, q, c.lam, A), kind == 0);
            }
            /* the element recorded (the assembly's first failing element) */
            ch->err_elem = -9;
            if (kind <= 1) {
                assert_int_equal(vlbe_ale_chain_force(ch, 0, q, v, C), 1);
                assert_int_equal(ch->err_elem, bad_elem);
            } else {
                assert_int_equal(vlbe_ale_chain_mass_jac(ch, 0, q, v, a, A, NULL), 1);
                assert_int_equal(ch->err_elem, bad_elem);
            }
            if (kind == 2) a[ch->node[2].ofs] = VLBE_R(0.1);
        }
    /* NaN multiplier of constr_hess */
    pfx_init(&c);
    snap_take(&c.ch, &s0);
    c.lam[0] = (vlbe_real)NAN;
    fill(NMAX * NMAX, SENT, A);
    assert_int_equal(vlbe_ale_chain_constr_hess(&c.ch, 0, c.q, c.lam, A), 1);
    assert_int_equal(c.ch.err, VLBE_ENONFINITE);
    assert_all_equal(NMAX * NMAX, A, SENT);
#undef CB_EXPECT
}

/* ------------------------------------------------------------------------ */
/* 7. finite inputs whose result overflows                                    */
/* ------------------------------------------------------------------------ */

/* Finite inputs, results that overflow: VLBE_ENONFINITE (callbacks: 1 with
   err ENONFINITE), outputs of the status routines untouched.
     length: slopes of 2 sqrt(REAL_MAX): |r'|^2 overflows (fails on
       77b73ad: VLBE_OK with len = Inf);
     energy: a point mass REAL_MAX / 2 moving at 4: T overflows (fails on
       77b73ad: VLBE_OK with E[0] = Inf);
     force: gravity 9.81 on that mass (fails on 77b73ad: 0 with Q = -Inf);
     point: r of a chain whose positions are near REAL_MAX: the Hermite
       sum overflows (fails on 77b73ad: VLBE_OK with r = Inf);
   and the helpers that check the assembled matrices: the band of K (every
   entry an element adds to) and the diagonal (of M: positive semidefinite,
   |M_ij| <= sqrt(M_ii M_jj)) see an entry that overflowed. */
static void test_overflow_outputs(void **state)
{
    static pfx c;
    static snap s0;
    vlbe_real len, rate, E[3], Q[NMAX], r[2], rp[2];
    const vlbe_real big = VLBE_R(2.0) * vlbe_sqrt(VLBE_REAL_MAX);
    int i;
    (void)state;

    pfx_init(&c);
    for (i = 0; i < NN; ++i) { /* every slope (both of the sliding node) */
        const int o = c.node[i].ofs;
        c.q[o + 2] = big;
        if (c.node[i].slide) c.q[o + 4] = big;
    }
    snap_take(&c.ch, &s0);
    len = rate = SENT;
    assert_int_equal(vlbe_ale_chain_length(&c.ch, 0, c.q, c.v, &len, &rate), VLBE_ENONFINITE);
    assert_true(len == SENT && rate == SENT);
    snap_check(&c.ch, &s0);

    pfx_init(&c);
    c.node[1].mass = VLBE_REAL_MAX / VLBE_R(2.0);
    assert_int_equal(vlbe_ale_chain_layout(&c.ch), VLBE_OK);
    c.v[c.node[1].ofs] = VLBE_R(4.0);
    snap_take(&c.ch, &s0);
    fill(3, SENT, E);
    assert_int_equal(vlbe_ale_chain_energy(&c.ch, 0, c.q, c.v, E), VLBE_ENONFINITE);
    assert_all_equal(3, E, SENT);
    snap_check(&c.ch, &s0);
    assert_int_equal(vlbe_ale_chain_force(&c.ch, 0, c.q, c.v, Q), 1);
    assert_int_equal(c.ch.err, VLBE_ENONFINITE);
    c.ch.err = s0.ch.err;
    c.ch.err_elem = s0.ch.err_elem;
    snap_check(&c.ch, &s0);

    pfx_init(&c);
    for (i = 0; i < NN; ++i) {
        const int o = c.node[i].ofs;
        c.q[o] = VLBE_REAL_MAX * VLBE_R(0.9);
        c.q[o + 2] = VLBE_REAL_MAX * VLBE_R(0.9);
        if (c.node[i].slide) c.q[o + 4] = VLBE_REAL_MAX * VLBE_R(0.9);
    }
    r[0] = r[1] = rp[0] = rp[1] = SENT;
    {
        const vlbe_status st = vlbe_ale_chain_point(&c.ch, 0, c.q, VLBE_R(0.45), r, rp);
        if (st == VLBE_OK) { /* allowed only with finite results */
            assert_true(isfinite(r[0]) && isfinite(r[1]) && isfinite(rp[0]) && isfinite(rp[1]));
        } else {
            assert_int_equal(st, VLBE_ENONFINITE);
            assert_true(r[0] == SENT && r[1] == SENT && rp[0] == SENT && rp[1] == SENT);
        }
    }

    { /* the assembled-matrix checks (internal helpers): every entry an
         element touches (the band of nodes i-1 .. i+1), the diagonal */
        static vlbe_real K[NMAX * NMAX], D[NMAX * NMAX];
        const size_t n = (size_t)c.ch.n;
        int e2, j;
        pfx_init(&c);
        assert_int_equal(vlbe_ale_chain_force_jac(&c.ch, 0, c.q, c.v, K, D), 0);
        assert_int_equal(vlbe__ale_band_finite(&c.ch, K), 1);
        assert_int_equal(vlbe__ale_diag_finite(c.ch.n, K), 1);
        for (e2 = 0; e2 + 1 < c.ch.nn; ++e2) { /* each element's corner entries */
            const int r0 = c.node[e2].ofs, r1 = c.node[e2 + 1].ofs + 3;
            const size_t ent[2] = {(size_t)r0 * n + (size_t)r1, (size_t)r1 * n + (size_t)r0};
            for (j = 0; j < 2; ++j) {
                const vlbe_real keep = K[ent[j]];
                K[ent[j]] = keep + VLBE_REAL_MAX + VLBE_REAL_MAX; /* overflowed in a sum */
                assert_int_equal(vlbe__ale_band_finite(&c.ch, K), 0);
                K[ent[j]] = keep;
            }
        }
        K[3 * n + 3] = (vlbe_real)NAN;
        assert_int_equal(vlbe__ale_diag_finite(c.ch.n, K), 0);
    }
}

/* ------------------------------------------------------------------------ */
/* 8. beams of corot2d.h                                                      */
/* ------------------------------------------------------------------------ */

#define BNE 3
#define BN (3 * (BNE + 1))

static vlbe_real fix_nan_fun_val;
static void fix_fun(void *ctx, vlbe_real t, vlbe_real *g3)
{
    (void)ctx;
    g3[0] = fix_nan_fun_val + t;
    g3[1] = VLBE_R(1.0);
    g3[2] = VLBE_R(0.0);
}

/* vlbe_cr2d_beam_*: init with a NaN g of a fix without fun: ENONFINITE,
   beam untouched (fails on 77b73ad: OK).  NaN in q, v, a: callbacks
   return 1 with err ENONFINITE at the first element reading it and every
   output untouched (fails on 77b73ad: M, Q, K, D, Mq zeroed first).  A fix
   function giving NaN: constr, constr_jac (Ct), constr_acc return 1 with
   err ENONFINITE (fails on 77b73ad: 0 with NaN); a fix moved to dof = n
   after init: -1 with err EARG and C, Cq untouched (fails on 77b73ad:
   writes past Cq, reads past q).  Loads that overflow (P = REAL_MAX / 2,
   load 4): force returns 1, err ENONFINITE (fails on 77b73ad: 0 with Q
   Inf).  Velocities of 2 sqrt(REAL_MAX): energy_t VLBE_ENONFINITE and E
   untouched (fails on 77b73ad where the element's T overflowed: OK with
   Inf).  force_jac with D NULL: K bitwise that of the call with D. */
static void test_beam(void **state)
{
    static vlbe_real M[BN * BN], K[BN * BN], D[BN * BN], K0[BN * BN];
    vlbe_cr2d_elem el[BNE];
    vlbe_cr2d_beam b, b0;
    vlbe_cr2d_fix fix[2], fix0[2];
    vlbe_cr2d_mat m = beam_mat();
    vlbe_real q[BN], v[BN], a[BN], Q[BN], C[2], Ct[2], gam[2], Cq[2 * BN], E[2], P[BN];
    int e, i, kind;
    (void)state;
    memset(el, 0, sizeof el);
    for (e = 0; e < BNE; ++e) {
        vlbe_real X1[2], X2[2];
        X1[0] = (vlbe_real)e;
        X1[1] = VLBE_R(0.0);
        X2[0] = (vlbe_real)(e + 1);
        X2[1] = VLBE_R(0.0);
        assert_int_equal(vlbe_cr2d_elem_init(&el[e], &m, X1, X2, 0u), VLBE_OK);
    }
    memset(fix, 0, sizeof fix);
    fix[0].dof = 0;
    fix[1].dof = 4;
    fix[1].fun = fix_fun;
    fix_nan_fun_val = VLBE_R(0.0);
    fix[0].g[1] = (vlbe_real)NAN;
    memset(&b, 0x5a, sizeof b);
    memcpy(&b0, &b, sizeof b);
    assert_int_equal(vlbe_cr2d_beam_init(&b, el, BNE, fix, 2), VLBE_ENONFINITE);
    assert_memory_equal(&b, &b0, sizeof b);
    fix[0].g[1] = VLBE_R(0.5);
    memcpy(fix0, fix, sizeof fix0);
    assert_int_equal(vlbe_cr2d_beam_init(&b, el, BNE, fix, 2), VLBE_OK);
    for (i = 0; i < BN; ++i) {
        q[i] = (vlbe_real)(0.01 * (i % 4));
        v[i] = (vlbe_real)(0.1 - 0.02 * (i % 5));
        a[i] = (vlbe_real)(0.3 * (i % 3));
    }
    memcpy(&b0, &b, sizeof b);

    for (kind = 0; kind < 3; ++kind) {
        vlbe_real *x = kind == 0 ? q : kind == 1 ? v : a;
        const vlbe_real keep = x[3 * 2 + 1];
        x[3 * 2 + 1] = (vlbe_real)NAN; /* node 2: element 1 reads it first */
#define BCB(call_, touched_)                                                                \
    do {                                                                                    \
        fill(BN * BN, SENT, M);                                                             \
        fill(BN * BN, SENT, K);                                                             \
        fill(BN, SENT, Q);                                                                  \
        b.err_elem = -9;                                                                    \
        if (touched_) {                                                                     \
            assert_int_equal((call_), 1);                                                   \
            assert_int_equal(b.err, VLBE_ENONFINITE);                                       \
            assert_int_equal(b.err_elem, 1);                                                \
            assert_all_equal(BN * BN, M, SENT);                                             \
            assert_all_equal(BN * BN, K, SENT);                                             \
            assert_all_equal(BN, Q, SENT);                                                  \
        } else {                                                                            \
            assert_int_equal((call_), 0);                                                   \
        }                                                                                   \
        b.err = b0.err;                                                                     \
        b.err_elem = b0.err_elem;                                                           \
        assert_memory_equal(&b, &b0, sizeof b);                                             \
    } while (0)
        BCB(vlbe_cr2d_beam_mass(&b, 0, q, v, M), kind == 0);
        BCB(vlbe_cr2d_beam_force(&b, 0, q, v, Q), kind <= 1);
        BCB(vlbe_cr2d_beam_force_jac(&b, 0, q, v, K, M), kind <= 1);
        BCB(vlbe_cr2d_beam_mass_jac(&b, 0, q, v, a, K, M), kind != 1);
#undef BCB
        x[3 * 2 + 1] = keep;
    }

    /* constraint callbacks: a fix function giving NaN */
    fix_nan_fun_val = (vlbe_real)NAN;
    assert_int_equal(vlbe_cr2d_beam_constr(&b, 0, q, C), 1);
    assert_int_equal(b.err, VLBE_ENONFINITE);
    fix_nan_fun_val = VLBE_R(0.0);
    fix[1].fun = NULL;
    fix[1].g[1] = (vlbe_real)INFINITY;
    b.err = VLBE_OK;
    assert_int_equal(vlbe_cr2d_beam_constr_jac(&b, 0, q, Cq, Ct), 1);
    assert_int_equal(b.err, VLBE_ENONFINITE);
    assert_int_equal(vlbe_cr2d_beam_constr_jac(&b, 0, q, Cq, NULL), 0); /* Ct not wanted */
    fix[1].g[1] = VLBE_R(0.0);
    fix[1].g[2] = (vlbe_real)NAN;
    b.err = VLBE_OK;
    assert_int_equal(vlbe_cr2d_beam_constr_acc(&b, 0, q, v, gam), 1);
    assert_int_equal(b.err, VLBE_ENONFINITE);
    memcpy(fix, fix0, sizeof fix);
    /* a fix moved out of range after init */
    fix[1].dof = BN;
    fill(2, SENT, C);
    fill(2, SENT, Ct);
    fill(2 * BN, SENT, Cq);
    fill(2, SENT, gam);
    b.err = VLBE_OK;
    assert_int_equal(vlbe_cr2d_beam_constr(&b, 0, q, C), -1);
    assert_int_equal(b.err, VLBE_EARG);
    assert_int_equal(vlbe_cr2d_beam_constr_jac(&b, 0, q, Cq, Ct), -1);
    assert_int_equal(vlbe_cr2d_beam_constr_acc(&b, 0, q, v, gam), -1);
    assert_all_equal(2, C, SENT);
    assert_all_equal(2, Ct, SENT);
    assert_all_equal(2 * BN, Cq, SENT);
    assert_all_equal(2, gam, SENT);
    memcpy(fix, fix0, sizeof fix);
    b.err = b0.err;
    b.err_elem = b0.err_elem;
    assert_int_equal(vlbe_cr2d_beam_constr(&b, 0, q, C), 0);

    /* loads that overflow */
    fill(BN, VLBE_REAL_MAX / VLBE_R(2.0), P);
    b.P = P;
    b.load = VLBE_R(4.0);
    assert_int_equal(vlbe_cr2d_beam_force(&b, 0, q, v, Q), 1);
    assert_int_equal(b.err, VLBE_ENONFINITE);
    b.P = NULL;
    b.load = VLBE_R(1.0);
    b.err = b0.err;
    b.err_elem = b0.err_elem;

    /* energy that overflows */
    {
        vlbe_real vb[BN];
        fill(BN, VLBE_R(2.0) * vlbe_sqrt(VLBE_REAL_MAX), vb);
        fill(2, SENT, E);
        assert_int_equal(vlbe_cr2d_beam_energy_t(&b, 0, q, vb, E), VLBE_ENONFINITE);
        assert_all_equal(2, E, SENT);
        assert_int_equal(vlbe_cr2d_beam_energy(&b, q, v, E), VLBE_OK);
        assert_true(isfinite(E[0]) && isfinite(E[1]));
    }

    /* force_jac with D NULL: K bitwise the same */
    assert_int_equal(vlbe_cr2d_beam_force_jac(&b, 0, q, v, K0, D), 0);
    fill(BN * BN, SENT, K);
    assert_int_equal(vlbe_cr2d_beam_force_jac(&b, 0, q, v, K, NULL), 0);
    assert_memory_equal(K, K0, sizeof K);
    assert_memory_equal(&b, &b0, sizeof b);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_range),
        cmocka_unit_test(test_overflow_args),
        cmocka_unit_test(test_null_optional),
        cmocka_unit_test(test_failed_untouched),
        cmocka_unit_test(test_lc_args),
        cmocka_unit_test(test_callbacks_input),
        cmocka_unit_test(test_overflow_outputs),
        cmocka_unit_test(test_beam),
    };
    return cmocka_run_group_tests_name("test_contract_chain", tests, NULL, NULL);
}

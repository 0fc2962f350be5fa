/* fuzz_chain.c -- libFuzzer harness of the planar chains of ancf_ale.h:
   init, constraints, layout, pnode, gather, insert, remove, length control,
   energy, length, point, and the force Jacobian callback, with fuzzed
   indices (-1, nn - 1, nn, nn + 1, INT_MAX, INT_MIN, ...), capacities and
   parameters                        -- part of vlbe  SPDX-License-Identifier: MIT
   Input: flags byte (bit 0 non-finite reals), nn = 2 + byte % 5, spare
   capacity byte % 3, per node: mode byte (pmode byte % 4: 3 is invalid;
   bit 2 sliding; bit 3 a point mass), p increment (moderate; any real with
   the mode's bit 4), pd, pdd; the constraint count byte % 3, per
   constraint type byte % 11, node and node2 (fz_index), which, 3 reals;
   then an operation byte, a variant byte, the state (moderate
   perturbations of a straight chain), the rates, the operation's index
   (fz_index) and reals.
   The node array is placed at the END of a local buffer, so that a read
   of node[nn_cap] is a stack-buffer-overflow under ASan.
   Asserts
     an index out of range (pnode i, gather e, insert e, remove i) =>
       VLBE_EARG (contract 2: checked before any use);
     chain_init / chain_add with bad sizes or nodes => not OK;
     every status routine: OK => outputs finite, else outputs and the chain
       (struct, nodes, constraints) bitwise unchanged (fz_post); insert,
       remove and length control owe finite qn, vn only for finite q, v
       (fz_post_in): they copy the coordinates of the nodes they do not
       touch without looking at them (contract 1 is about finite inputs);
     the callback vlbe_ale_chain_force_jac with D = NULL (allowed by the
       vlbe_dae contract: "Mv may be NULL", K and D: either may be NULL in
       the element calls) must not crash; 0 => K finite. */
#include "fuzz_util.h"
#include "../ancf_ale.h"
#include "../tests/ale_material.h"

#define CH_NMAX 8 /* node buffer */
#define CH_CMAX 3
#define CH_QMAX (CH_NMAX * 7)

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size);
int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
    static vlbe_ale_elem el;
    static int el_ready;
    vlbe_ale_node nbuf[CH_NMAX], *nodes;
    vlbe_ale_con cons[CH_CMAX], c;
    vlbe_ale_chain ch;
    vlbe_real q[CH_QMAX], v[CH_QMAX], qn[CH_QMAX + 8], vn[CH_QMAX + 8], qe[VLBE_ALE3_NQ],
        ve[VLBE_ALE3_NQ], p3[3], E[3], len, rate, r[2], rp[2], p = VLBE_R(0.0), t, Lstd,
        K[CH_QMAX * CH_QMAX], Dm[CH_QMAX * CH_QMAX];
    int nn, cap, ncon, i, k, idx[VLBE_ALE3_NQ], e, slider, changed, n, infin = 1;
    unsigned op, var, md;
    vlbe_status st;
    fz_rd rd;
    fz_begin("chain", &rd, data, size);
    if (!el_ready) {
        const vlbe_ale_mat m = mat_std();
        if (vlbe_ale_elem_init(&el, &m, 0, 0, 0, 0) != VLBE_OK) abort();
        el_ready = 1;
    }
    nn = fz_int(&rd, 2, 6);
    cap = nn + fz_int(&rd, 0, 2);
    memset(nbuf, 0, sizeof nbuf);
    nodes = nbuf + CH_NMAX - cap;
    for (i = 0; i < nn; ++i) {
        const unsigned b = fz_u8(&rd);
        const vlbe_real dp = (b & 16u) ? fz_real(&rd) : VLBE_R(0.2) + vlbe_fabs(fz_mod(&rd, 1.0));
        nodes[i].pmode = (int)(b % 4u);
        nodes[i].slide = (b & 4u) ? 1 : 0;
        nodes[i].p = i ? nodes[i - 1].p + dp : fz_mod(&rd, 2.0);
        nodes[i].pd = fz_mod(&rd, 1.0);
        nodes[i].pdd = fz_mod(&rd, 1.0);
        nodes[i].mass = (b & 8u) ? fz_mod(&rd, 2.0) : VLBE_R(0.0);
    }
    memset(cons, 0, sizeof cons);
    fz_snap_reset();
    fz_fill(&ch, sizeof ch);
    fz_snap(&ch, sizeof ch, "chain");
    fz_note("vlbe_ale_chain_init(nn=%d, nn_cap=%d)", nn, cap);
    st = vlbe_ale_chain_init(&ch, &el, nodes, nn, cap, cons, CH_CMAX);
    FUZZ_CHECK(st == VLBE_OK, "chain_init refused valid sizes");
    ncon = fz_int(&rd, 0, 2);
    for (k = 0; k < ncon; ++k) {
        memset(&c, 0, sizeof c);
        c.type = fz_int(&rd, 0, 10);
        c.node = fz_index(&rd, nn);
        c.node2 = fz_index(&rd, nn);
        c.which = fz_int(&rd, 0, 3);
        fz_reals(&rd, c.r, 3); /* one triple for the field the type reads */
        memcpy(c.d, c.r, sizeof c.d);
        memcpy(c.axis, c.r, sizeof c.axis);
        memcpy(c.law, c.r, sizeof c.law);
        fz_snap_reset();
        fz_snap(&ch, sizeof ch, "chain");
        fz_snap(cons, sizeof cons, "cons");
        fz_note("vlbe_ale_chain_add(type=%d, node=%d, node2=%d)", c.type, c.node, c.node2);
        st = vlbe_ale_chain_add(&ch, &c);
        if (c.node < 0 || c.node >= nn)
            FUZZ_CHECK(st == VLBE_EARG, "chain_add: node out of range not VLBE_EARG");
        fz_post(st);
    }
    fz_note("vlbe_ale_chain_layout");
    if (vlbe_ale_chain_layout(&ch) != VLBE_OK) return 0;
    n = ch.n;
    if (n > CH_QMAX) return 0;

    /* state: straight along x, perturbed; rates */
    {
        const vlbe_real r0[2] = {VLBE_R(0.0), VLBE_R(0.0)}, dir[2] = {VLBE_R(1.0), VLBE_R(0.0)};
        vlbe_ale_chain_straight(&ch, r0, dir, q);
    }
    for (i = 0; i < n; ++i) q[i] += fz_mod(&rd, 0.1);
    fz_mods(&rd, v, n, 1.0);
    for (i = n; i < CH_QMAX; ++i) q[i] = v[i] = VLBE_R(0.0);
    op = fz_u8(&rd) % 9u;
    var = fz_u8(&rd);
    t = fz_mod(&rd, 2.0);
    fz_dump("q", q, n);

    fz_snap_reset();
    fz_snap(&ch, sizeof ch, "chain");
    fz_snap(nbuf, sizeof nbuf, "nodes");
    fz_snap(cons, sizeof cons, "cons");
    fz_in(q, sizeof q, "q");
    fz_in(v, sizeof v, "v");
    switch (op) {
    case 0:
        i = fz_index(&rd, nn);
        fz_out(p3, 3, "p3");
        fz_note("vlbe_ale_chain_pnode(i=%d, nn=%d)", i, nn);
        st = vlbe_ale_chain_pnode(&ch, i, t, q, (var & 1u) ? NULL : v, p3);
        if (i < 0 || i >= nn) FUZZ_CHECK(st == VLBE_EARG, "pnode: node index out of range not VLBE_EARG");
        break;
    case 1: {
        const int wv = !(var & 1u), wve = !(var & 2u);
        unsigned md0;
        e = fz_index(&rd, nn - 1);
        fz_out(qe, VLBE_ALE3_NQ, "qe");
        fz_out(wve ? ve : NULL, VLBE_ALE3_NQ, "ve");
        fz_fill(idx, sizeof idx);
        fz_fill(&md, sizeof md);
        md0 = md;
        fz_snap(idx, sizeof idx, "idx");
        fz_snap(&md, sizeof md, "mode");
        (void)md0;
        fz_note("vlbe_ale_chain_gather(e=%d, nn=%d, v=%s, ve=%s)", e, nn, wv ? "v" : "NULL",
                wve ? "ve" : "NULL");
        st = vlbe_ale_chain_gather(&ch, e, t, q, wv ? v : NULL, qe, wve ? ve : NULL, idx, &md);
        if (e < 0 || e >= nn - 1)
            FUZZ_CHECK(st == VLBE_EARG, "gather: element index out of range not VLBE_EARG");
        break;
    }
    case 2:
    case 3:
    case 4:
        fz_out(qn, (size_t)(n + 8), "qn");
        fz_out(vn, (size_t)(n + 8), "vn");
        infin = fz_finite(q, (size_t)n) && ((op != 4 && (var & 1u)) || fz_finite(v, (size_t)n));
        if (op == 2) {
            e = fz_index(&rd, nn - 1);
            p = (var & 4u) ? fz_real(&rd) : fz_mod(&rd, 1.0);
            if (e >= 0 && e < nn - 1 && !(var & 4u)) {
                vlbe_real pa[3], pb[3];
                if (vlbe_ale_chain_pnode(&ch, e, t, q, v, pa) == VLBE_OK &&
                    vlbe_ale_chain_pnode(&ch, e + 1, t, q, v, pb) == VLBE_OK)
                    p = pa[0] + (VLBE_R(0.5) + VLBE_R(0.5) * p) * (pb[0] - pa[0]);
            }
            fz_note("vlbe_ale_chain_insert(e=%d, nn=%d, cap=%d, ph=%g)", e, nn, cap, (double)p);
            st = vlbe_ale_chain_insert(&ch, e, p, t, q, (var & 1u) ? NULL : v, qn,
                                       (var & 1u) ? NULL : vn);
            if (e < 0 || e >= nn - 1) FUZZ_CHECK(st == VLBE_EARG, "insert: element index out of range not VLBE_EARG");
        } else if (op == 3) {
            i = fz_index(&rd, nn);
            fz_note("vlbe_ale_chain_remove(i=%d, nn=%d)", i, nn);
            st = vlbe_ale_chain_remove(&ch, i, t, q, (var & 1u) ? NULL : v, qn, (var & 1u) ? NULL : vn);
            if (i < 0 || i >= nn) FUZZ_CHECK(st == VLBE_EARG, "remove: node index out of range not VLBE_EARG");
        } else {
            slider = fz_index(&rd, nn);
            Lstd = (var & 4u) ? fz_real(&rd) : VLBE_R(0.1) + vlbe_fabs(fz_mod(&rd, 1.0));
            fz_fill(&changed, sizeof changed);
            fz_snap(&changed, sizeof changed, "changed");
            fz_snap(&slider, sizeof slider, "slider");
            fz_note("vlbe_ale_chain_length_control(slider=%d, nn=%d, Lstd=%g)", slider, nn, (double)Lstd);
            st = vlbe_ale_chain_length_control(&ch, Lstd, t, q, v, &slider, qn, vn, &changed);
            if (st == VLBE_OK)
                FUZZ_CHECK(changed >= 0 && changed <= 3, "length_control: *changed not 0..3");
        }
        break;
    case 5:
        fz_out(E, 3, "E");
        fz_note("vlbe_ale_chain_energy");
        st = vlbe_ale_chain_energy(&ch, t, q, v, E);
        break;
    case 6:
        fz_out(&len, 1, "len");
        fz_out(&rate, 1, "rate");
        fz_note("vlbe_ale_chain_length");
        st = vlbe_ale_chain_length(&ch, t, q, (var & 1u) ? NULL : v, &len, (var & 2u) ? NULL : &rate);
        break;
    case 7:
        p = (var & 4u) ? fz_real(&rd) : nodes[0].p + fz_mod(&rd, 1.0) * (nodes[nn - 1].p - nodes[0].p);
        fz_out(r, 2, "r");
        fz_out(rp, 2, "rp");
        fz_fill(&e, sizeof e);
        fz_snap(&e, sizeof e, "e");
        fz_note("vlbe_ale_chain_locate/point(p=%g)", (double)p);
        st = vlbe_ale_chain_locate(&ch, t, q, p, &e);
        if (st == VLBE_OK) FUZZ_CHECK(e >= 0 && e < nn - 1, "locate: element out of range");
        fz_post(st);
        /* e belongs to locate alone: back to its snapshot for the check of
           _point below, which does not take it */
        fz_fill(&e, sizeof e);
        st = vlbe_ale_chain_point(&ch, t, q, p, (var & 1u) ? NULL : r, (var & 2u) ? NULL : rp);
        break;
    default: { /* the force Jacobian callback, D or K NULL */
        int rc;
        vlbe_real *Kp = (var & 1u) ? NULL : K, *Dp = (var & 2u) ? NULL : Dm;
        if (!Kp && !Dp) Kp = K;
        fz_note("vlbe_ale_chain_force_jac(K=%s, D=%s)", Kp ? "K" : "NULL", Dp ? "D" : "NULL");
        fz_fill(K, sizeof K);
        fz_fill(Dm, sizeof Dm);
        rc = vlbe_ale_chain_force_jac(&ch, t, q, v, Kp, Dp);
        if (rc == 0) {
            FUZZ_CHECK(!Kp || fz_finite(Kp, (size_t)(n * n)), "force_jac returned 0 with NaN/Inf in K");
            FUZZ_CHECK(!Dp || fz_finite(Dp, (size_t)(n * n)), "force_jac returned 0 with NaN/Inf in D");
        }
        return 0;
    }
    }
    fz_post_in(st, infin);
    return 0;
}

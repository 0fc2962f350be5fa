/* fuzz_step.c -- libFuzzer harness of one step of the integrators of
   integrators.h (vlbe_hht_params_*, vlbe_hht_init, vlbe_hht_step,
   vlbe_bdf_init, vlbe_bdf_step) on a small clamped planar ALE-ANCF chain
   (2-4 fixed-length elements, node 0 clamped: POS + SLOPE)
   -- part of vlbe                                   SPDX-License-Identifier: MIT
   Input: flags byte (bit 0 non-finite reals), ne = 2 + byte % 3, element
   length (moderate), integrator byte (bit 0: BDF; bit 1: raw HHT
   parameters instead of vlbe_hht_params_genalpha), the parameters (rho_inf
   or alpha_m, alpha_f, beta, gamma; newton_max, max_halvings, ftol; BDF:
   rtol, atol, h0, h_min, h_max, max_order, fixed_step), t0, the state
   perturbation and rates, h (HHT) or t_stop (BDF).
   Asserts
     params_genalpha / params_hht: not OK => *p unchanged;
     init: OK => t, q, v, q'', a, lambda finite; not OK => the state struct
       bitwise unchanged (the workspace is the caller's scratch: not
       compared);
     step: OK => t and the state finite, t advanced; not OK => t and q, v,
       q'', a, lambda (BDF: q, v, lambda, mu, t, h_last, order_last)
       bitwise unchanged ("leaves the state at the last accepted step").
       Not compared: stats (integrators.h: "Counters of one run
       (cumulative from init)": a failed attempt is counted), the private
       fields (LU cache, divided differences) and BDF's h, order ("step
       size the next step will try", adapted after a failure). */
#include "fuzz_util.h"
#include "../ancf_ale.h"
#include "../integrators.h"

#define ST_NE 4
#define ST_NMAX (4 * (ST_NE + 1))
#define ST_MMAX 4

static vlbe_real st_work[8192];
static int st_iwork[256];

/* the state of HHT the contract covers, into buf (n reals each + m) */
static size_t st_hht_state(const vlbe_hht *s, vlbe_real *buf)
{
    size_t k = 0;
    int i;
    buf[k++] = s->t;
    for (i = 0; i < s->n; ++i) buf[k++] = s->q[i];
    for (i = 0; i < s->n; ++i) buf[k++] = s->v[i];
    for (i = 0; i < s->n; ++i) buf[k++] = s->qdd[i];
    for (i = 0; i < s->n; ++i) buf[k++] = s->a[i];
    for (i = 0; i < s->m; ++i) buf[k++] = s->lambda[i];
    return k;
}

static size_t st_bdf_state(const vlbe_bdf *s, vlbe_real *buf)
{
    size_t k = 0;
    int i;
    buf[k++] = s->t;
    buf[k++] = s->h_last;
    for (i = 0; i < s->n; ++i) buf[k++] = s->q[i];
    for (i = 0; i < s->n; ++i) buf[k++] = s->v[i];
    for (i = 0; i < s->m; ++i) buf[k++] = s->lambda[i];
    for (i = 0; i < s->m; ++i) buf[k++] = s->mu[i];
    return k;
}

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size);
int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
    static vlbe_ale_elem el;
    static int el_ready;
    vlbe_ale_node nodes[ST_NE + 1];
    vlbe_ale_con cons[2];
    vlbe_ale_chain ch;
    vlbe_dae sys;
    vlbe_hht_params hp, hp0;
    vlbe_bdf_params bp;
    vlbe_hht hs;
    vlbe_bdf bs;
    vlbe_real q0[ST_NMAX], v0[ST_NMAX], before[5 * ST_NMAX + 2 * ST_MMAX + 2],
        after[5 * ST_NMAX + 2 * ST_MMAX + 2], Le, t0, h;
    unsigned integ;
    int ne, i, order_last;
    size_t ns;
    vlbe_status st;
    fz_rd rd;
    fz_begin("step", &rd, data, size);
    if (!el_ready) {
        vlbe_ale_mat m;
        m.rhoA = VLBE_R(1.3);
        m.EA = VLBE_R(50.0);
        m.EI = VLBE_R(0.7);
        m.c_eps = VLBE_R(0.01);
        m.c_kap = VLBE_R(0.02);
        m.f[0] = VLBE_R(0.0);
        m.f[1] = VLBE_R(-2.1);
        if (vlbe_ale_elem_init(&el, &m, 0, 0, 0, 0) != VLBE_OK) abort();
        el_ready = 1;
    }
    ne = fz_int(&rd, 2, ST_NE);
    Le = VLBE_R(0.1) + vlbe_fabs(fz_mod(&rd, 1.0));
    if (!isfinite(Le) || !(Le > VLBE_R(0.0))) return 0;
    memset(nodes, 0, sizeof nodes);
    for (i = 0; i <= ne; ++i) nodes[i].p = Le * (vlbe_real)i;
    if (vlbe_ale_chain_init(&ch, &el, nodes, ne + 1, ne + 1, cons, 2) != VLBE_OK) return 0;
    memset(cons, 0, sizeof cons);
    {
        vlbe_ale_con c;
        memset(&c, 0, sizeof c);
        c.type = VLBE_ALE_CON_POS;
        if (vlbe_ale_chain_add(&ch, &c) != VLBE_OK) return 0;
        c.type = VLBE_ALE_CON_SLOPE;
        c.d[0] = VLBE_R(1.0);
        if (vlbe_ale_chain_add(&ch, &c) != VLBE_OK) return 0;
    }
    if (vlbe_ale_chain_layout(&ch) != VLBE_OK) return 0;
    memset(&sys, 0, sizeof sys);
    sys.n = ch.n;
    sys.m = ch.m;
    sys.user = &ch;
    sys.mass = vlbe_ale_chain_mass;
    sys.force = vlbe_ale_chain_force;
    sys.force_jac = vlbe_ale_chain_force_jac;
    sys.mass_jac = vlbe_ale_chain_mass_jac;
    sys.constr = vlbe_ale_chain_constr;
    sys.constr_jac = vlbe_ale_chain_constr_jac;
    sys.constr_acc = vlbe_ale_chain_constr_acc;
    sys.constr_hess = vlbe_ale_chain_constr_hess;
    {
        const vlbe_real r0[2] = {VLBE_R(0.0), VLBE_R(0.0)}, dir[2] = {VLBE_R(1.0), VLBE_R(0.0)};
        vlbe_ale_chain_straight(&ch, r0, dir, q0);
    }
    integ = fz_u8(&rd);

    if (!(integ & 1u)) { /* ---- HHT */
        fz_snap_reset();
        vlbe_hht_params_genalpha(&hp, VLBE_R(0.8));
        if (integ & 2u) {
            hp.alpha_m = fz_real(&rd);
            hp.alpha_f = fz_real(&rd);
            hp.beta = fz_real(&rd);
            hp.gamma = fz_real(&rd);
        } else {
            const vlbe_real rho = (integ & 4u) ? fz_real(&rd) : fz_mod(&rd, 1.0);
            hp0 = hp;
            fz_snap(&hp, sizeof hp, "params");
            fz_note("vlbe_hht_params_genalpha(rho_inf=%g)", (double)rho);
            st = vlbe_hht_params_genalpha(&hp, rho);
            if (st == VLBE_OK) FUZZ_CHECK(fz_finite(&hp.alpha_m, 6), "genalpha OK with non-finite parameters");
            else FZ_CHECK_UNCHANGED();
            if (st != VLBE_OK) hp = hp0;
        }
        hp.newton_max = fz_int(&rd, 0, 12);
        hp.max_halvings = fz_int(&rd, -1, 3);
        hp.ftol = (integ & 8u) ? fz_real(&rd) : VLBE_R(0.0);
        t0 = fz_mod(&rd, 10.0);
        for (i = 0; i < ch.n; ++i) q0[i] += fz_mod(&rd, 0.05);
        fz_mods(&rd, v0, ch.n, 1.0);
        h = (integ & 16u) ? fz_real(&rd) : VLBE_R(1e-3) * (VLBE_R(1.0) + vlbe_fabs(fz_mod(&rd, 10.0)));
        fz_dump("params", &hp.alpha_m, 4);
        fz_dump("t0", &t0, 1);
        fz_dump("h", &h, 1);

        fz_snap_reset();
        fz_fill(&hs, sizeof hs);
        fz_snap(&hs, sizeof hs, "hht state struct");
        fz_in(q0, sizeof q0, "q0");
        fz_in(v0, sizeof v0, "v0");
        fz_note("vlbe_hht_init(t0=%g, alpha_m=%g, alpha_f=%g, beta=%g, gamma=%g)", (double)t0,
                (double)hp.alpha_m, (double)hp.alpha_f, (double)hp.beta, (double)hp.gamma);
        st = vlbe_hht_init(&hs, &sys, &hp, t0, q0, v0, st_work, sizeof st_work / sizeof *st_work,
                           st_iwork, sizeof st_iwork / sizeof *st_iwork);
        if (st == VLBE_OK) {
            ns = st_hht_state(&hs, after);
            FUZZ_CHECK(fz_finite(after, ns), "hht_init OK with NaN/Inf in t or the state");
            FUZZ_CHECK(fz_finite(&hs.par.alpha_m, 6), "hht_init OK with NaN/Inf parameters");
        }
        fz_post(st);
        if (st != VLBE_OK) return 0;
        ns = st_hht_state(&hs, before);
        fz_note("vlbe_hht_step(h=%g)", (double)h);
        st = vlbe_hht_step(&hs, h);
        FUZZ_CHECK(fz_status_known(st), "unknown status value");
        FUZZ_CHECK(st_hht_state(&hs, after) == ns, "state size changed");
        if (st == VLBE_OK) {
            FUZZ_CHECK(fz_finite(after, ns), "hht_step OK with NaN/Inf in t or the state");
            FUZZ_CHECK(after[0] > before[0], "hht_step OK but t did not advance");
        } else {
            FUZZ_CHECK(memcmp(before, after, ns * sizeof *before) == 0,
                       "hht_step failed but the state changed");
        }
        return 0;
    }

    /* ---- BDF */
    vlbe_bdf_params_default(&bp);
    if (integ & 2u) {
        bp.rtol = fz_real(&rd);
        bp.atol = fz_real(&rd);
        bp.h0 = fz_real(&rd);
        bp.h_min = fz_real(&rd);
        bp.h_max = fz_real(&rd);
        bp.max_order = fz_int(&rd, -1, 6);
        bp.newton_max = fz_int(&rd, -1, 6);
        bp.fixed_step = fz_int(&rd, 0, 1);
    } else {
        bp.rtol = bp.atol = VLBE_R(1e-4);
        bp.max_order = fz_int(&rd, 1, 5);
    }
    t0 = fz_mod(&rd, 10.0);
    for (i = 0; i < ch.n; ++i) q0[i] += fz_mod(&rd, 0.05);
    fz_mods(&rd, v0, ch.n, 1.0);
    h = (integ & 16u) ? fz_real(&rd) : t0 + VLBE_R(1e-3) * (VLBE_R(1.0) + vlbe_fabs(fz_mod(&rd, 10.0)));
    fz_snap_reset();
    fz_fill(&bs, sizeof bs);
    fz_snap(&bs, sizeof bs, "bdf state struct");
    fz_in(q0, sizeof q0, "q0");
    fz_in(v0, sizeof v0, "v0");
    fz_note("vlbe_bdf_init(t0=%g, rtol=%g, atol=%g, h0=%g)", (double)t0, (double)bp.rtol,
            (double)bp.atol, (double)bp.h0);
    st = vlbe_bdf_init(&bs, &sys, &bp, t0, q0, v0, st_work, sizeof st_work / sizeof *st_work,
                       st_iwork, sizeof st_iwork / sizeof *st_iwork);
    if (st == VLBE_OK) {
        ns = st_bdf_state(&bs, after);
        FUZZ_CHECK(fz_finite(after, ns) && isfinite(bs.h), "bdf_init OK with NaN/Inf in t, h or the state");
    }
    fz_post(st);
    if (st != VLBE_OK) return 0;
    ns = st_bdf_state(&bs, before);
    order_last = bs.order_last;
    fz_note("vlbe_bdf_step(t_stop=%g)", (double)h);
    st = vlbe_bdf_step(&bs, h);
    FUZZ_CHECK(fz_status_known(st), "unknown status value");
    FUZZ_CHECK(st_bdf_state(&bs, after) == ns, "state size changed");
    if (st == VLBE_OK) {
        FUZZ_CHECK(fz_finite(after, ns), "bdf_step OK with NaN/Inf in t or the state");
    } else {
        FUZZ_CHECK(memcmp(before, after, ns * sizeof *before) == 0 && bs.order_last == order_last,
                   "bdf_step failed but the state changed");
    }
    return 0;
}

/* fuzz_ale.c -- libFuzzer harness of the planar ALE-ANCF element of
   ancf_ale.h: element init, force with K/D, mass, mass Jacobian, energy,
   point force, point / strain, split, and the invariant route
   (vlbe_ale_inv_force, vlbe_ale_inv_chain_force, vlbe_ale_inv_sys_*)
   -- part of vlbe                                   SPDX-License-Identifier: MIT
   Input: flags byte (bit 0 non-finite reals), the material (7 reals), the
   element flags byte (NO_BEND .. INV_AXIAL), Gauss orders nm, nl, nt
   (byte % 11 - 1: -1..9, VLBE_EARG outside 0..8), an operation byte, a
   mode byte, then the state: p1 and L (any reals: lengths down to 1e-300
   and up to 1e300), positions, slopes (scaled by a real: 1e100 slopes) and
   rates, then operation arguments.
   Asserts (fz_post): status OK => every output finite; otherwise every
   output (pre-filled with a sentinel, accumulated outputs snapshotted) and
   the element object bitwise unchanged; const inputs never change. */
#include "fuzz_util.h"
#include "../ancf_ale.h"

static void ale_mat(fz_rd *rd, vlbe_ale_mat *m)
{
    m->rhoA = fz_mod(rd, 4.0);
    m->EA = fz_mod(rd, 100.0);
    m->EI = fz_mod(rd, 4.0);
    m->c_eps = fz_mod(rd, 1.0);
    m->c_kap = fz_mod(rd, 1.0);
    m->f[0] = fz_mod(rd, 4.0);
    m->f[1] = fz_mod(rd, 4.0);
}

/* q, qd of one element: p1, L any reals, positions moderate around a
   chord, slopes moderate times a scale */
static void ale_state(fz_rd *rd, vlbe_real *q, vlbe_real *qd)
{
    const vlbe_real p1 = fz_mod(rd, 4.0), L = fz_real(rd), sc = fz_real(rd);
    int k;
    q[4] = p1;
    q[9] = p1 + L;
    q[0] = fz_mod(rd, 2.0);
    q[1] = fz_mod(rd, 2.0);
    q[5] = q[0] + L * fz_mod(rd, 2.0);
    q[6] = q[1] + L * fz_mod(rd, 2.0);
    for (k = 0; k < 2; ++k) {
        q[2 + k] = sc * fz_mod(rd, 2.0);
        q[7 + k] = sc * fz_mod(rd, 2.0);
    }
    fz_mods(rd, qd, 10, 4.0);
}

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size);
#define NE 4
#define NX (4 * (NE + 1))
int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
    static vlbe_ale_elem el;
    /* the chain of operations 8, 9 (here: checked after the switch) */
    vlbe_real Lc[NE], x[NX], v[NX], Qc[NX], Kc[NX * VLBE_ALE_INV_BW], Dc[NX * VLBE_ALE_INV_BW],
        work[88 * NE + 16];
    vlbe_ale_inv_sys sys;
    vlbe_ale_mat mat;
    vlbe_real q[10], qd[10], a[10], Q[10], K[100], D[100], M[100], E[3], F[2], r[2], rp[2],
        qh[5], qhd[5], eps, kap;
    unsigned eflags, mode, op, kd;
    int nm, nl, nt;
    vlbe_status st;
    fz_rd rd;
    fz_begin("ale", &rd, data, size);
    ale_mat(&rd, &mat);
    eflags = fz_u8(&rd) & 63u;
    nm = fz_int(&rd, -1, 9);
    nl = fz_int(&rd, -1, 9);
    nt = fz_int(&rd, -1, 9);
    op = fz_u8(&rd) % 10u;
    mode = fz_u8(&rd) & 63u;
    kd = fz_u8(&rd); /* K, D present (bits 0, 1) */
    ale_state(&rd, q, qd);
    fz_dump("mat", &mat.rhoA, 7);
    fz_dump("q", q, 10);
    fz_dump("qd", qd, 10);

    /* element init: on failure el (left as a sentinel) must not change */
    fz_snap_reset();
    fz_fill(&el, sizeof el);
    fz_snap(&el, sizeof el, "el");
    fz_in(&mat, sizeof mat, "mat");
    fz_note("vlbe_ale_elem_init(flags=%u, nm=%d, nl=%d, nt=%d)", eflags, nm, nl, nt);
    st = vlbe_ale_elem_init(&el, &mat, eflags, nm, nl, nt);
    if (st != VLBE_OK) {
        fz_post(st);
        return 0;
    }
    FUZZ_CHECK(fz_finite(&el.mat.rhoA, 7), "init OK but the element's material is not finite");

    fz_snap_reset();
    fz_in(&el, sizeof el, "el");
    fz_in(q, sizeof q, "q");
    fz_in(qd, sizeof qd, "qd");
    switch (op) {
    case 0: /* force, K and D optional */
    case 5: /* the invariant route (fixed-length) */
        fz_out(Q, 10, "Q");
        fz_out((kd & 1u) ? K : NULL, 100, "K");
        fz_out((kd & 2u) ? D : NULL, 100, "D");
        fz_note("%s(mode=%u, K=%d, D=%d)", op ? "vlbe_ale_inv_force" : "vlbe_ale_force", mode,
                (int)(kd & 1u), (int)((kd >> 1) & 1u));
        st = op ? vlbe_ale_inv_force(&el, mode, q, qd, Q, (kd & 1u) ? K : NULL, (kd & 2u) ? D : NULL)
                : vlbe_ale_force(&el, mode, q, qd, Q, (kd & 1u) ? K : NULL, (kd & 2u) ? D : NULL);
        break;
    case 1:
        fz_out(M, 100, "M");
        fz_note("vlbe_ale_mass(mode=%u)", mode);
        st = vlbe_ale_mass(&el, mode, q, M);
        break;
    case 2:
        fz_mods(&rd, a, 10, 4.0);
        fz_in(a, sizeof a, "a");
        fz_out(M, 100, "Mq");
        fz_note("vlbe_ale_mass_jac(mode=%u)", mode);
        st = vlbe_ale_mass_jac(&el, mode, q, a, M);
        break;
    case 3:
        fz_out(E, 3, "E");
        fz_note("vlbe_ale_energy(mode=%u)", mode);
        st = vlbe_ale_energy(&el, mode, q, qd, E);
        break;
    case 4: { /* point force: Q, K accumulate */
        const vlbe_real pf = (kd & 4u) ? fz_real(&rd) : q[4] + fz_mod(&rd, 1.0) * (q[9] - q[4]);
        F[0] = fz_mod(&rd, 10.0);
        F[1] = fz_mod(&rd, 10.0);
        fz_mods(&rd, Q, 10, 1.0);
        fz_mods(&rd, K, 100, 1.0);
        fz_in(F, sizeof F, "F");
        fz_acc(Q, 10, "Q");
        fz_acc((kd & 1u) ? K : NULL, 100, "K");
        fz_note("vlbe_ale_point_force(pf=%g)", (double)pf);
        st = vlbe_ale_point_force(q, pf, F, Q, (kd & 1u) ? K : NULL);
        break;
    }
    case 6: { /* point and strain at p */
        const vlbe_real p = (kd & 4u) ? fz_real(&rd) : q[4] + fz_mod(&rd, 1.0) * (q[9] - q[4]);
        fz_out(r, 2, "r");
        fz_out(rp, 2, "rp");
        fz_note("vlbe_ale_point(p=%g)", (double)p);
        st = vlbe_ale_point(q, p, r, rp);
        fz_post(st);
        fz_snap_reset();
        fz_in(q, sizeof q, "q");
        fz_out(&eps, 1, "eps");
        fz_out(&kap, 1, "kap");
        fz_note("vlbe_ale_strain(p=%g)", (double)p);
        st = vlbe_ale_strain(q, p, &eps, (kd & 8u) ? NULL : &kap);
        break;
    }
    case 7: { /* exact split */
        const vlbe_real ph = (kd & 4u) ? fz_real(&rd) : q[4] + fz_mod(&rd, 1.0) * (q[9] - q[4]);
        fz_out(qh, 5, "qh");
        fz_out((kd & 1u) ? qhd : NULL, 5, "qhd");
        fz_note("vlbe_ale_split(ph=%g, qd=%d)", (double)ph, (int)(kd & 1u));
        st = vlbe_ale_split(q, (kd & 1u) ? qd : NULL, ph, qh, (kd & 1u) ? qhd : NULL);
        break;
    }
    case 8:
    case 9: { /* a fixed-length cable chain of ne elements: element loop
                 (8) or system invariants (9) */
        const int ne = fz_int(&rd, 1, NE);
        int e, k;
        for (e = 0; e < ne; ++e) Lc[e] = (kd & 4u) ? fz_real(&rd) : VLBE_R(0.25) + vlbe_fabs(fz_mod(&rd, 2.0));
        for (k = 0; k <= ne; ++k) {
            x[4 * k] = fz_mod(&rd, 4.0);
            x[4 * k + 1] = fz_mod(&rd, 4.0);
            x[4 * k + 2] = fz_mod(&rd, 2.0);
            x[4 * k + 3] = fz_mod(&rd, 2.0);
        }
        fz_mods(&rd, v, 4 * (ne + 1), 4.0);
        fz_dump("L", Lc, ne);
        fz_in(Lc, sizeof(vlbe_real) * (size_t)ne, "L");
        fz_in(x, sizeof(vlbe_real) * (size_t)(4 * (ne + 1)), "x");
        fz_in(v, sizeof(vlbe_real) * (size_t)(4 * (ne + 1)), "v");
        fz_out(Qc, (size_t)(4 * (ne + 1)), "Q");
        fz_out((kd & 1u) ? Kc : NULL, (size_t)(4 * (ne + 1) * VLBE_ALE_INV_BW), "K");
        fz_out((kd & 2u) ? Dc : NULL, (size_t)(4 * (ne + 1) * VLBE_ALE_INV_BW), "D");
        if (op == 8) {
            fz_note("vlbe_ale_inv_chain_force(mode=%u, ne=%d)", mode, ne);
            st = vlbe_ale_inv_chain_force(&el, mode, ne, Lc, x, (kd & 8u) ? NULL : v, Qc,
                                          (kd & 1u) ? Kc : NULL, (kd & 2u) ? Dc : NULL);
            break;
        }
        {
            /* the system invariants: init (sys, work untouched on failure),
               then force; work_len fuzzed too */
            const size_t need = vlbe_ale_inv_sys_work_len(ne);
            const size_t wl = (kd & 16u) ? need - 1 : need;
            vlbe_status s0;
            fz_snap_reset();
            fz_in(Lc, sizeof(vlbe_real) * (size_t)ne, "L");
            fz_fill(&sys, sizeof sys);
            fz_fill(work, sizeof work);
            fz_snap(&sys, sizeof sys, "sys");
            fz_snap(work, sizeof work, "work");
            fz_note("vlbe_ale_inv_sys_init(mode=%u, ne=%d, work_len=%zu of %zu)", mode, ne, wl, need);
            s0 = vlbe_ale_inv_sys_init(&sys, &el, mode, ne, Lc, work, wl);
            fz_post(s0);
            if (s0 != VLBE_OK) return 0;
            fz_snap_reset();
            fz_in(x, sizeof(vlbe_real) * (size_t)(4 * (ne + 1)), "x");
            fz_in(v, sizeof(vlbe_real) * (size_t)(4 * (ne + 1)), "v");
            fz_out(Qc, (size_t)(4 * (ne + 1)), "Q");
            fz_out((kd & 1u) ? Kc : NULL, (size_t)(4 * (ne + 1) * VLBE_ALE_INV_BW), "K");
            fz_out((kd & 2u) ? Dc : NULL, (size_t)(4 * (ne + 1) * VLBE_ALE_INV_BW), "D");
            /* sys->H is documented scratch ("also the scratch of
               vlbe_ale_inv_sys_force"): work is not compared */
            fz_note("vlbe_ale_inv_sys_force(ne=%d)", ne);
            st = vlbe_ale_inv_sys_force(&sys, x, (kd & 8u) ? NULL : v, Qc, (kd & 1u) ? Kc : NULL,
                                        (kd & 2u) ? Dc : NULL);
        }
        break;
    }
    default: st = VLBE_OK; break;
    }
    fz_post(st);
    return 0;
}
#undef NE
#undef NX

/* fuzz_ale3.c -- libFuzzer harness of the 3D beam-shaft element with spin
   of ancf_ale.h (vlbe_ale3_*: material of a circle, init, force with K/D,
   mass, mass Jacobian, energy, point, strain, point force and torque)
   -- part of vlbe                                   SPDX-License-Identifier: MIT
   Input: flags byte (bit 0 non-finite reals), a material selector byte
   (bit 0: vlbe_ale3_mat_circle from 4 reals, else 11 reals), the element
   flags byte (NO_BEND, NO_DAMP, FIX_P1/2, NO_SPIN, NO_TWIST, and sometimes
   the planar-only CONSERVATIVE / INV_AXIAL: VLBE_EARG), Gauss orders nm, ns
   (byte % 11 - 1), operation, mode and K/D bytes, then the state: p1, L
   (any reals), slope scale (any real), positions, slopes, spin angles and
   the rates, then the operation's arguments.
   Asserts (fz_post): status OK => every output finite; otherwise every
   output and the element / material objects bitwise unchanged. */
#include "fuzz_util.h"
#include "../ancf_ale.h"

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size);
int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
    static vlbe_ale3_elem el;
    vlbe_ale3_mat mat;
    vlbe_real q[VLBE_ALE3_NQ], qd[VLBE_ALE3_NQ], a[VLBE_ALE3_NQ], Q[VLBE_ALE3_NQ],
        K[VLBE_ALE3_NQ * VLBE_ALE3_NQ], D[VLBE_ALE3_NQ * VLBE_ALE3_NQ], E[3], F[3], r[3], rp[3],
        th, eps, kap, phi, T, pp;
    unsigned sel, eflags, mode, op, kd, md;
    int nm, ns, nq, nb, s, k;
    vlbe_real p1, L, sc;
    vlbe_status st;
    fz_rd rd;
    fz_begin("ale3", &rd, data, size);
    sel = fz_u8(&rd);
    fz_snap_reset();
    if (sel & 1u) {
        const vlbe_real rho = fz_mod(&rd, 8000.0), Em = fz_mod(&rd, 2e11), G = fz_mod(&rd, 8e10),
                        rad = fz_real(&rd);
        fz_fill(&mat, sizeof mat);
        fz_snap(&mat, sizeof mat, "mat");
        fz_note("vlbe_ale3_mat_circle(%g, %g, %g, %g)", (double)rho, (double)Em, (double)G, (double)rad);
        st = vlbe_ale3_mat_circle(&mat, rho, Em, G, rad);
        if (st == VLBE_OK && !fz_skip("ale3-circle"))
            FUZZ_CHECK(fz_finite(&mat.rhoA, sizeof mat / sizeof(vlbe_real)),
                       "mat_circle OK but the material holds NaN/Inf");
        fz_post(st);
        if (st != VLBE_OK) return 0;
        mat.c_eps = fz_mod(&rd, 1e-3);
        mat.c_kap = fz_mod(&rd, 1e-3);
        mat.c_phi = fz_mod(&rd, 1e-3);
    } else {
        mat.rhoA = fz_mod(&rd, 4.0);
        mat.rhoI = fz_mod(&rd, 1.0);
        mat.EA = fz_mod(&rd, 100.0);
        mat.EJ = fz_mod(&rd, 4.0);
        mat.GI = fz_mod(&rd, 4.0);
        mat.c_eps = fz_mod(&rd, 1.0);
        mat.c_kap = fz_mod(&rd, 1.0);
        mat.c_phi = fz_mod(&rd, 1.0);
        mat.f[0] = fz_mod(&rd, 4.0);
        mat.f[1] = fz_mod(&rd, 4.0);
        mat.f[2] = fz_mod(&rd, 4.0);
    }
    eflags = fz_u8(&rd) & 255u;
    nm = fz_int(&rd, -1, 9);
    ns = fz_int(&rd, -1, 9);
    op = fz_u8(&rd) % 8u;
    mode = fz_u8(&rd) & (VLBE_ALE_NO_BEND | VLBE_ALE_NO_DAMP | VLBE_ALE_FIX_P1 | VLBE_ALE_FIX_P2 |
                         VLBE_ALE3_NO_SPIN | VLBE_ALE3_NO_TWIST);
    kd = fz_u8(&rd);

    fz_snap_reset();
    fz_fill(&el, sizeof el);
    fz_snap(&el, sizeof el, "el");
    fz_in(&mat, sizeof mat, "mat");
    fz_note("vlbe_ale3_elem_init(flags=%u, nm=%d, ns=%d)", eflags, nm, ns);
    st = vlbe_ale3_elem_init(&el, &mat, eflags, nm, ns);
    fz_post(st);
    if (st != VLBE_OK) return 0;

    /* the state in the layout of mode | flags */
    md = mode | eflags;
    nq = vlbe_ale3_nq(md);
    nb = nq / 2;
    p1 = fz_mod(&rd, 4.0);
    L = fz_real(&rd);
    sc = fz_real(&rd);
    for (s = 0; s < 2; ++s) {
        for (k = 0; k < 3; ++k) {
            q[s * nb + k] = fz_mod(&rd, 2.0) + (s ? L * fz_mod(&rd, 2.0) : VLBE_R(0.0));
            q[s * nb + 3 + k] = sc * fz_mod(&rd, 2.0);
        }
        if (nb == 8) q[s * nb + 6] = fz_mod(&rd, 4.0);
        q[s * nb + nb - 1] = s ? p1 + L : p1;
    }
    fz_mods(&rd, qd, nq, 4.0);
    fz_dump("q", q, nq);
    fz_dump("qd", qd, nq);

    fz_snap_reset();
    fz_in(&el, sizeof el, "el");
    fz_in(q, sizeof q, "q");
    fz_in(qd, sizeof qd, "qd");
    switch (op) {
    case 0:
        fz_out(Q, (size_t)nq, "Q");
        fz_out((kd & 1u) ? K : NULL, (size_t)(nq * nq), "K");
        fz_out((kd & 2u) ? D : NULL, (size_t)(nq * nq), "D");
        fz_note("vlbe_ale3_force(mode=%u, K=%d, D=%d)", mode, (int)(kd & 1u), (int)((kd >> 1) & 1u));
        st = vlbe_ale3_force(&el, mode, q, qd, Q, (kd & 1u) ? K : NULL, (kd & 2u) ? D : NULL);
        break;
    case 1:
        fz_out(K, (size_t)(nq * nq), "M");
        fz_note("vlbe_ale3_mass(mode=%u)", mode);
        st = vlbe_ale3_mass(&el, mode, q, K);
        break;
    case 2:
        fz_mods(&rd, a, nq, 4.0);
        fz_in(a, sizeof a, "a");
        fz_out(K, (size_t)(nq * nq), "Mq");
        fz_note("vlbe_ale3_mass_jac(mode=%u)", mode);
        st = vlbe_ale3_mass_jac(&el, mode, q, a, K);
        break;
    case 3:
        fz_out(E, 3, "E");
        fz_note("vlbe_ale3_energy(mode=%u)", mode);
        st = vlbe_ale3_energy(&el, mode, q, qd, E);
        break;
    case 4:
    case 5: /* point force (4) or torque (5): Q, K accumulate */
        pp = (kd & 4u) ? fz_real(&rd) : p1 + fz_mod(&rd, 1.0) * L;
        fz_mods(&rd, F, 3, 10.0);
        T = fz_mod(&rd, 10.0);
        fz_mods(&rd, Q, nq, 1.0);
        fz_mods(&rd, K, nq * nq, 1.0);
        fz_in(F, sizeof F, "F");
        fz_acc(Q, (size_t)nq, "Q");
        fz_acc((kd & 1u) ? K : NULL, (size_t)(nq * nq), "K");
        fz_note("vlbe_ale3_point_%s(mode=%u, pf=%g)", op == 4 ? "force" : "torque", md, (double)pp);
        st = op == 4 ? vlbe_ale3_point_force(md, q, pp, F, Q, (kd & 1u) ? K : NULL)
                     : vlbe_ale3_point_torque(md, q, pp, T, Q, (kd & 1u) ? K : NULL);
        break;
    default: /* point, strain at p */
        pp = (kd & 4u) ? fz_real(&rd) : p1 + fz_mod(&rd, 1.0) * L;
        fz_out(r, 3, "r");
        fz_out(rp, 3, "rp");
        fz_out(&th, 1, "th");
        fz_note("vlbe_ale3_point(mode=%u, p=%g)", md, (double)pp);
        st = vlbe_ale3_point(md, q, pp, r, (kd & 8u) ? NULL : rp, (kd & 16u) ? NULL : &th);
        fz_post(st);
        fz_snap_reset();
        fz_in(q, sizeof q, "q");
        fz_out(&eps, 1, "eps");
        fz_out(&kap, 1, "kap");
        fz_out(&phi, 1, "phi");
        fz_note("vlbe_ale3_strain(mode=%u, p=%g)", md, (double)pp);
        st = vlbe_ale3_strain(md, q, pp, &eps, (kd & 8u) ? NULL : &kap, (kd & 16u) ? NULL : &phi);
        break;
    }
    fz_post(st);
    return 0;
}

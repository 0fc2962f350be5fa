/* fuzz_cr2d.c -- libFuzzer harness of corot2d.h: element init, force with
   K/D, mass, mass Jacobian, energy, local coordinates, the floating-frame
   (*_ff) calls, the transition element (vlbe_cr2d_trans_*) and the sizes
   of vlbe_cr2d_beam_init            -- part of vlbe  SPDX-License-Identifier: MIT
   Input: flags byte (bit 0 non-finite reals), the material (6 reals), X1
   (2 moderate), the chord X2 - X1 (2 any reals: 1e-120 and 1e200), element
   flags, operation, mode and K/D bytes, q (positions near X plus a
   displacement, rotations), q', the operation's arguments (joint: exit C,
   axis angle; frame angle and rate; beam: ne, nfix and the fixed dofs).
   Asserts (fz_post): status OK => every output (and the element object
   after init) finite; otherwise outputs and objects bitwise unchanged;
   vlbe_cr2d_beam_init: VLBE_EARG unless 1 <= ne and 3 (ne + 1) fits in an
   int and every fixed dof is in [0, 3 (ne + 1)); on success n = 3 (ne +
   1). */
#include "fuzz_util.h"
#include "../corot2d.h"

/* every real of an element object (material, geometry, tables) finite */
static int cr_elem_finite(const vlbe_cr2d_elem *e)
{
    return fz_finite(&e->mat.EA, 6) && fz_finite(e->X, 4) && isfinite(e->L) && isfinite(e->a0) &&
           isfinite(e->c0) && isfinite(e->s0) && fz_finite(e->m_, 36) && fz_finite(e->k0_, 36) &&
           fz_finite(e->key_, 4);
}

/* starts the snapshots of the next call of a sequence: the const inputs
   (jt, fth, a: NULL when the operation has none) are taken again, the
   outputs of an earlier successful call are not (that call had the right to
   write them; the next call registers its own outputs) */
static void cr_next(const vlbe_cr2d_elem *el, const vlbe_real *q, const vlbe_real *qd,
                    const vlbe_cr2d_joint *jt, const vlbe_real *fth, const vlbe_real *a)
{
    fz_snap_reset();
    fz_in(el, sizeof *el, "el");
    fz_in(q, 6 * sizeof *q, "q");
    fz_in(qd, 6 * sizeof *qd, "qd");
    fz_in(jt, jt ? sizeof *jt : 0, "joint");
    fz_in(fth, 2 * sizeof *fth, "fth");
    fz_in(a, 6 * sizeof *a, "a");
}

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size);
int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
    vlbe_cr2d_elem el;
    vlbe_cr2d_mat mat;
    vlbe_cr2d_joint jt;
    vlbe_cr2d_beam bm;
    vlbe_cr2d_fix fix[4];
    vlbe_real X1[2], X2[2], dX[2], q[6], qd[6], a[6], Q[6], K[36], D[36], E[3], loc[6], fth[2];
    unsigned eflags, op, mode, kd;
    int k;
    vlbe_status st;
    fz_rd rd;
    fz_begin("cr2d", &rd, data, size);
    mat.EA = fz_mod(&rd, 100.0);
    mat.EI = fz_mod(&rd, 4.0);
    mat.rhoA = fz_mod(&rd, 4.0);
    mat.rhoI = fz_mod(&rd, 1.0);
    mat.ray_a = fz_mod(&rd, 1.0);
    mat.ray_b = fz_mod(&rd, 1.0);
    X1[0] = fz_mod(&rd, 4.0);
    X1[1] = fz_mod(&rd, 4.0);
    dX[0] = fz_real(&rd);
    dX[1] = fz_real(&rd);
    X2[0] = X1[0] + dX[0];
    X2[1] = X1[1] + dX[1];
    eflags = fz_u8(&rd) & 7u;
    op = fz_u8(&rd) % 9u;
    mode = fz_u8(&rd) & 7u;
    kd = fz_u8(&rd);
    fz_dump("mat", &mat.EA, 6);
    fz_dump("X1", X1, 2);
    fz_dump("X2", X2, 2);

    fz_snap_reset();
    fz_fill(&el, sizeof el);
    fz_snap(&el, sizeof el, "el");
    fz_in(&mat, sizeof mat, "mat");
    fz_note("vlbe_cr2d_elem_init(X2-X1=(%g, %g), flags=%u)", (double)dX[0], (double)dX[1], eflags);
    st = vlbe_cr2d_elem_init(&el, &mat, X1, X2, eflags);
    if (st == VLBE_OK && !fz_skip("cr2d-init"))
        FUZZ_CHECK(cr_elem_finite(&el), "elem_init OK but the element holds NaN/Inf");
    fz_post(st);
    if (st != VLBE_OK) return 0;

    /* state: reference positions + displacement (scaled by the length),
       rotations */
    for (k = 0; k < 2; ++k) {
        q[3 * k] = el.X[2 * k] + el.L * fz_mod(&rd, 0.5);
        q[3 * k + 1] = el.X[2 * k + 1] + el.L * fz_mod(&rd, 0.5);
        q[3 * k + 2] = fz_mod(&rd, 3.0);
    }
    fz_mods(&rd, qd, 6, 4.0);
    fz_dump("q", q, 6);
    fz_dump("qd", qd, 6);
    fz_snap_reset();
    fz_in(&el, sizeof el, "el");
    fz_in(q, sizeof q, "q");
    fz_in(qd, sizeof qd, "qd");
    if (op >= 4 && op <= 6) { /* a joint for the transition element */
        const vlbe_real ang = fz_mod(&rd, 4.0);
        jt.C[0] = q[0] + el.L * fz_mod(&rd, 1.0);
        jt.C[1] = q[1] + el.L * fz_mod(&rd, 1.0);
        jt.a[0] = (kd & 64u) ? fz_real(&rd) : vlbe_cos(ang);
        jt.a[1] = (kd & 64u) ? fz_real(&rd) : vlbe_sin(ang);
        fz_in(&jt, sizeof jt, "joint");
    }
    if (op == 7) { /* floating frame */
        fth[0] = fz_mod(&rd, 4.0);
        fth[1] = fz_mod(&rd, 4.0);
        fz_in(fth, sizeof fth, "fth");
    }
    switch (op) {
    case 0:
        fz_out(Q, 6, "Q");
        fz_out((kd & 1u) ? K : NULL, 36, "K");
        fz_out((kd & 2u) ? D : NULL, 36, "D");
        fz_note("vlbe_cr2d_force(mode=%u, K=%d, D=%d)", mode, (int)(kd & 1u), (int)((kd >> 1) & 1u));
        st = vlbe_cr2d_force(&el, mode, q, qd, Q, (kd & 1u) ? K : NULL, (kd & 2u) ? D : NULL);
        break;
    case 1:
        fz_out(K, 36, "M");
        fz_note("vlbe_cr2d_mass(mode=%u)", mode);
        st = vlbe_cr2d_mass(&el, mode, q, K);
        break;
    case 2:
        fz_mods(&rd, a, 6, 4.0);
        fz_in(a, sizeof a, "a");
        fz_out(K, 36, "Mq");
        fz_note("vlbe_cr2d_mass_jac(mode=%u)", mode);
        st = vlbe_cr2d_mass_jac(&el, mode, q, a, K);
        break;
    case 3:
        fz_out(E, 2, "E");
        fz_note("vlbe_cr2d_energy(mode=%u)", mode);
        st = vlbe_cr2d_energy(&el, mode, q, qd, E);
        fz_post(st);
        cr_next(&el, q, qd, NULL, NULL, NULL);
        fz_out(loc, 4, "loc");
        fz_note("vlbe_cr2d_local(mode=%u)", mode);
        st = vlbe_cr2d_local(&el, mode, q, loc);
        break;
    case 4:
        fz_out(Q, 6, "Q");
        fz_out((kd & 1u) ? K : NULL, 36, "K");
        fz_out((kd & 2u) ? D : NULL, 36, "D");
        fz_note("vlbe_cr2d_trans_force(mode=%u, K=%d, D=%d)", mode, (int)(kd & 1u), (int)((kd >> 1) & 1u));
        st = vlbe_cr2d_trans_force(&el, &jt, mode, q, qd, Q, (kd & 1u) ? K : NULL, (kd & 2u) ? D : NULL);
        break;
    case 5:
        fz_out(K, 36, "M");
        fz_mods(&rd, a, 6, 4.0);
        fz_in(a, sizeof a, "a");
        fz_note("vlbe_cr2d_trans_mass(mode=%u)", mode);
        st = vlbe_cr2d_trans_mass(&el, &jt, mode, q, K);
        fz_post(st);
        cr_next(&el, q, qd, &jt, NULL, a);
        fz_out(D, 36, "Mq");
        fz_note("vlbe_cr2d_trans_mass_jac(mode=%u)", mode);
        st = vlbe_cr2d_trans_mass_jac(&el, &jt, mode, q, a, D);
        break;
    case 6:
        fz_out(E, 2, "E");
        fz_note("vlbe_cr2d_trans_energy(mode=%u)", mode);
        st = vlbe_cr2d_trans_energy(&el, &jt, mode, q, qd, E);
        fz_post(st);
        cr_next(&el, q, qd, &jt, NULL, NULL);
        fz_out(loc, 6, "loc");
        fz_note("vlbe_cr2d_trans_local(mode=%u)", mode);
        st = vlbe_cr2d_trans_local(&el, &jt, mode, q, loc);
        break;
    case 7:
        fz_out(Q, 6, "Q");
        fz_out((kd & 1u) ? K : NULL, 36, "K");
        fz_out((kd & 2u) ? D : NULL, 36, "D");
        fz_note("vlbe_cr2d_force_ff(mode=%u)", mode | VLBE_CR2D_LINEAR);
        st = vlbe_cr2d_force_ff(&el, mode | ((kd & 4u) ? 0u : VLBE_CR2D_LINEAR), fth, q, qd, Q,
                                (kd & 1u) ? K : NULL, (kd & 2u) ? D : NULL);
        fz_post(st);
        cr_next(&el, q, qd, NULL, fth, NULL);
        fz_out(E, 2, "E");
        fz_note("vlbe_cr2d_energy_ff");
        st = vlbe_cr2d_energy_ff(&el, mode | ((kd & 4u) ? 0u : VLBE_CR2D_LINEAR), fth, q, qd, E);
        fz_post(st);
        cr_next(&el, q, qd, NULL, fth, NULL);
        fz_out(loc, 4, "loc");
        fz_note("vlbe_cr2d_local_ff");
        st = vlbe_cr2d_local_ff(&el, mode | ((kd & 4u) ? 0u : VLBE_CR2D_LINEAR), fth, q, loc);
        break;
    default: { /* beam sizes */
        const int ne = fz_size(&rd, 1, 8), nfix = fz_int(&rd, 0, 4);
        long long n;
        int ok = 1;
        memset(fix, 0, sizeof fix);
        for (k = 0; k < nfix; ++k) fix[k].dof = fz_index(&rd, 3 * 9);
        n = 3 * ((long long)ne + 1);
        if (ne < 1 || n > INT_MAX) ok = 0;
        for (k = 0; k < nfix; ++k)
            if (fix[k].dof < 0 || fix[k].dof >= n) ok = 0;
        fz_snap_reset();
        fz_fill(&bm, sizeof bm);
        fz_snap(&bm, sizeof bm, "beam");
        fz_in(fix, sizeof fix, "fix");
        fz_note("vlbe_cr2d_beam_init(ne=%d, nfix=%d)", ne, nfix);
        st = vlbe_cr2d_beam_init(&bm, &el, ne, nfix ? fix : NULL, nfix);
        if (!ok) FUZZ_CHECK(st == VLBE_EARG, "beam_init: out-of-range ne or dof not VLBE_EARG");
        else FUZZ_CHECK(st == VLBE_OK && bm.n == (int)n && bm.ne == ne, "beam_init: valid sizes refused or n wrong");
        break;
    }
    }
    fz_post(st);
    return 0;
}

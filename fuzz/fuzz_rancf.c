/* fuzz_rancf.c -- libFuzzer harness of rancf.h: rational basis, nodal <->
   Bezier conversions, curve point, homogeneous de Casteljau split,
   least-squares merge weights, element init / force / mass / energy,
   element split, circular arc   -- part of vlbe   SPDX-License-Identifier: MIT
   Input: flags byte (bit 0 non-finite reals), operation byte, dimension
   byte (d = byte % 5: 0 and 4 are out of range, VLBE_EARG), the weights
   w0..w3 (any reals: 1e300 next to 1e-300 makes the ratios overflow), a
   length / parameter real, then 4 d (or 3 (2 d + 1), or the element's 10)
   moderate reals and the operation's arguments.
   Asserts (fz_post): status OK => every output finite; otherwise every
   output (sentinel-filled) and the element object bitwise unchanged. */
#include "fuzz_util.h"
#include "../rancf.h"

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size);
int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
    static vlbe_rancf_elem el;
    vlbe_ale_mat mat;
    vlbe_real w[4], x[4 * VLBE_RANCF_DMAX], P[4 * VLBE_RANCF_DMAX], o[4 * VLBE_RANCF_DMAX],
        o2[4 * VLBE_RANCF_DMAX], wl[4], wr[4], kk[4], q[10], qd[10], Q[10], K[100], D[100],
        qh[5], qhd[5], c[2], l, na[7], nh[7], nb[7];
    vlbe_herm_ale hb;
    unsigned op, kd;
    int d, info, info0, nd;
    vlbe_status st;
    fz_rd rd;
    fz_begin("rancf", &rd, data, size);
    op = fz_u8(&rd) % 9u;
    d = (int)(fz_u8(&rd) % 5u);
    kd = fz_u8(&rd);
    fz_reals(&rd, w, 4);
    l = fz_real(&rd);
    nd = d >= 1 && d <= VLBE_RANCF_DMAX ? d : 1; /* array extent (d itself is passed) */
    fz_mods(&rd, x, 4 * nd, 4.0);
    fz_dump("w", w, 4);
    fz_dump("l", &l, 1);
    fz_dump("x", x, 4 * nd);
    fz_snap_reset();
    fz_in(w, sizeof w, "w");
    fz_in(x, sizeof x, "x");
    switch (op) {
    case 0:
        fz_out(P, (size_t)(4 * nd), "P");
        fz_note("vlbe_rancf_to_bezier(d=%d)", d);
        st = vlbe_rancf_to_bezier(d, w, l, x, P);
        break;
    case 1:
        fz_out(P, (size_t)(4 * nd), "x");
        fz_note("vlbe_rancf_from_bezier(d=%d)", d);
        st = vlbe_rancf_from_bezier(d, w, l, x, P);
        break;
    case 2:
        fz_out(P, (size_t)nd, "r");
        fz_note("vlbe_rancf_bezier_eval(d=%d, u=%g)", d, (double)l);
        st = vlbe_rancf_bezier_eval(d, w, x, l, P);
        break;
    case 3: /* split at u = l; any of the outputs may be NULL */
        fz_out((kd & 1u) ? NULL : wl, 4, "wl");
        fz_out((kd & 2u) ? NULL : o, (size_t)(4 * nd), "Pl");
        fz_out((kd & 4u) ? NULL : wr, 4, "wr");
        fz_out((kd & 8u) ? NULL : o2, (size_t)(4 * nd), "Pr");
        fz_note("vlbe_rancf_bezier_split(d=%d, u=%g)", d, (double)l);
        st = vlbe_rancf_bezier_split(d, w, x, l, (kd & 1u) ? NULL : wl, (kd & 2u) ? NULL : o,
                                     (kd & 4u) ? NULL : wr, (kd & 8u) ? NULL : o2);
        break;
    case 4: { /* merge: nodes a, h, b of 2 d + 1 reals (d = 2, 3; p last) */
        const int m = 2 * nd + 1;
        fz_mods(&rd, na, m, 4.0);
        fz_mods(&rd, nh, m, 4.0);
        fz_mods(&rd, nb, m, 4.0);
        if (kd & 16u) { /* ordered material coordinates, any spacing */
            na[m - 1] = fz_mod(&rd, 4.0);
            nh[m - 1] = na[m - 1] + vlbe_fabs(fz_real(&rd));
            nb[m - 1] = nh[m - 1] + vlbe_fabs(fz_real(&rd));
        }
        fz_in(na, sizeof na, "na");
        fz_in(nh, sizeof nh, "nh");
        fz_in(nb, sizeof nb, "nb");
        fz_out(kk, 4, "k");
        fz_fill(&info, sizeof info);
        info0 = info;
        fz_snap((kd & 32u) ? NULL : &info, sizeof info, "info");
        fz_note("vlbe_rancf_merge(d=%d)", d);
        st = vlbe_rancf_merge(d, na, nh, nb, kk, (kd & 32u) ? NULL : &info);
        if (st == VLBE_OK && !(kd & 32u)) FUZZ_CHECK(info == 0 || info == 1, "merge OK but info not 0/1");
        (void)info0;
        break;
    }
    case 5: { /* element init; then force / mass / energy / split */
        const unsigned sub = (kd >> 4) & 3u;
        const vlbe_real L = l;
        mat.rhoA = fz_mod(&rd, 4.0);
        mat.EA = fz_mod(&rd, 100.0);
        mat.EI = fz_mod(&rd, 4.0);
        mat.c_eps = fz_mod(&rd, 1.0);
        mat.c_kap = fz_mod(&rd, 1.0);
        mat.f[0] = fz_mod(&rd, 4.0);
        mat.f[1] = fz_mod(&rd, 4.0);
        fz_snap_reset();
        fz_in(w, sizeof w, "w");
        fz_in(&mat, sizeof mat, "mat");
        fz_fill(&el, sizeof el);
        fz_snap(&el, sizeof el, "el");
        fz_note("vlbe_rancf_elem_init(w)");
        st = vlbe_rancf_elem_init(&el, &mat, w, fz_u8(&rd) & 31u, 0, 0, 0);
        if (st == VLBE_OK && !fz_skip("rancf-init"))
            FUZZ_CHECK(fz_finite(el.k, 4), "elem_init OK but the weight ratios hold NaN/Inf");
        fz_post(st);
        if (st != VLBE_OK) return 0;
        q[4] = fz_mod(&rd, 2.0);
        q[9] = q[4] + L;
        q[0] = fz_mod(&rd, 2.0);
        q[1] = fz_mod(&rd, 2.0);
        q[5] = q[0] + L * fz_mod(&rd, 2.0);
        q[6] = q[1] + L * fz_mod(&rd, 2.0);
        q[2] = fz_mod(&rd, 2.0);
        q[3] = fz_mod(&rd, 2.0);
        q[7] = fz_mod(&rd, 2.0);
        q[8] = fz_mod(&rd, 2.0);
        fz_mods(&rd, qd, 10, 2.0);
        fz_dump("q", q, 10);
        fz_snap_reset();
        fz_in(&el, sizeof el, "el");
        fz_in(q, sizeof q, "q");
        fz_in(qd, sizeof qd, "qd");
        if (sub == 0) {
            fz_out(Q, 10, "Q");
            fz_out((kd & 1u) ? K : NULL, 100, "K");
            fz_out((kd & 2u) ? D : NULL, 100, "D");
            fz_note("vlbe_rancf_force(K=%d, D=%d)", (int)(kd & 1u), (int)((kd >> 1) & 1u));
            st = vlbe_rancf_force(&el, 0, q, qd, Q, (kd & 1u) ? K : NULL, (kd & 2u) ? D : NULL);
        } else if (sub == 1) {
            fz_out(K, 100, "M");
            fz_note("vlbe_rancf_mass");
            st = vlbe_rancf_mass(&el, 0, q, K);
        } else if (sub == 2) {
            fz_out(Q, 3, "E");
            fz_note("vlbe_rancf_energy");
            st = vlbe_rancf_energy(&el, 0, q, qd, Q);
        } else {
            const vlbe_real ph = (kd & 4u) ? fz_real(&rd) : q[4] + fz_mod(&rd, 1.0) * L;
            fz_out(qh, 5, "qh");
            fz_out((kd & 1u) ? qhd : NULL, 5, "qhd");
            fz_out(wl, 4, "wl");
            fz_out(wr, 4, "wr");
            fz_note("vlbe_rancf_split(ph=%g)", (double)ph);
            st = vlbe_rancf_split(&el, q, (kd & 1u) ? qd : NULL, ph, qh, (kd & 1u) ? qhd : NULL,
                                  wl, wr);
        }
        break;
    }
    case 6: { /* basis at p on [p1, p1 + l] */
        const vlbe_real p1 = fz_mod(&rd, 2.0), p = (kd & 4u) ? fz_real(&rd) : p1 + fz_mod(&rd, 1.0) * l;
        fz_fill(&hb, sizeof hb);
        fz_out(&hb.h[0][0][0], sizeof hb / sizeof(vlbe_real), "b");
        fz_note("vlbe_rancf_basis_eval(p=%g, p1=%g, L=%g)", (double)p, (double)p1, (double)l);
        st = vlbe_rancf_basis_eval(w, p, p1, p1 + l, (int)(kd % 4u), (int)((kd >> 2) % 3u), &hb);
        break;
    }
    default: { /* circular arc: centre, radius l, a0, theta */
        const vlbe_real a0 = fz_mod(&rd, 4.0), theta = fz_real(&rd);
        c[0] = x[0];
        c[1] = x[1];
        fz_out(wl, 4, "w");
        fz_out(o, 8, "x");
        fz_note("vlbe_rancf_arc(R=%g, a0=%g, theta=%g)", (double)l, (double)a0, (double)theta);
        st = vlbe_rancf_arc(c, l, a0, theta, wl, o);
        break;
    }
    }
    fz_post(st);
    return 0;
}

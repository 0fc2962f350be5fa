/* m4_rancf.c -- the rational ALE-RANCF element of rancf.h on the
   Cortex-M4F (make check-m4): weights {1, 0.8, 1.15, 1.05}, both material
   coordinates free, a bent and moving state with damping and gravity:
   M(q), Q with K and D, the energies {T, U, V}, and the basis at one
   point, printed (tests/m4/m4_out.h).
   -- part of vlbe                                  SPDX-License-Identifier: MIT */
#include "../../rancf.h"
#include "m4_out.h"

static vlbe_rancf_elem el; /* about 16 kB: static */
static vlbe_real M[100], Q[10], K[100], D[100], E[3];

int main(void)
{
    vlbe_ale_mat mat;
    static const vlbe_real w[4] = {VLBE_R(1.0), VLBE_R(0.8), VLBE_R(1.15), VLBE_R(1.05)};
    static const vlbe_real q[10] = {VLBE_R(0.0),  VLBE_R(0.0),  VLBE_R(0.98),  VLBE_R(0.25),
                                    VLBE_R(0.2),  VLBE_R(1.05), VLBE_R(0.3),   VLBE_R(0.9),
                                    VLBE_R(0.42), VLBE_R(1.3)};
    static const vlbe_real qd[10] = {VLBE_R(-0.1), VLBE_R(0.2),  VLBE_R(0.1),  VLBE_R(-0.05),
                                     VLBE_R(0.03), VLBE_R(0.3),  VLBE_R(0.15), VLBE_R(0.1),
                                     VLBE_R(-0.2), VLBE_R(0.01)};
    vlbe_herm_ale b;
    memset(&b, 0, sizeof b); /* entries beyond kmax, amax stay 0 */
    memset(&mat, 0, sizeof mat);
    mat.rhoA = VLBE_R(0.8);
    mat.EA = VLBE_R(1.0e4);
    mat.EI = VLBE_R(12.0);
    mat.c_eps = VLBE_R(5e-4);
    mat.c_kap = VLBE_R(1e-3);
    mat.f[1] = VLBE_R(-9.81) * mat.rhoA;
    if (m4_status("rancf_basis_eval",
                  vlbe_rancf_basis_eval(w, VLBE_R(0.6), VLBE_R(0.2), VLBE_R(1.3), 2, 2, &b)))
        return m4_exit();
    m4_vec("N", &b.h[0][0][0], (int)(sizeof b.h / sizeof b.h[0][0][0]));
    if (m4_status("rancf_elem_init", vlbe_rancf_elem_init(&el, &mat, w, 0, 0, 0, 0)))
        return m4_exit();
    m4_vec("k", el.k, 4);
    if (m4_status("rancf_mass", vlbe_rancf_mass(&el, 0, q, M))) return m4_exit();
    m4_vec("M", M, 100);
    if (m4_status("rancf_force", vlbe_rancf_force(&el, 0, q, qd, Q, K, D))) return m4_exit();
    m4_vec("Q", Q, 10);
    m4_vec("K", K, 100);
    m4_vec("D", D, 100);
    if (m4_status("rancf_energy", vlbe_rancf_energy(&el, 0, q, qd, E))) return m4_exit();
    m4_vec("E", E, 3);
    return m4_exit();
}

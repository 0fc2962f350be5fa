/* m4_ale3.c -- the 3D beam-shaft element (VLBSE) of ancf_ale.h on the
   Cortex-M4F (make check-m4): a steel shaft element of radius 5 mm, both
   material coordinates free, bent out of plane, twisted (spin angles 0.1
   and 0.35 rad) and spinning (40 and 41 rad/s), with Kelvin-Voigt damping
   and gravity: M(q), Q with K and D, the energies {T, U, V}, printed
   (tests/m4/m4_out.h).
   -- part of vlbe                                  SPDX-License-Identifier: MIT */
#include "../../ancf_ale.h"
#include "m4_out.h"

static vlbe_ale3_elem el;
static vlbe_real M[256], Q[16], K[256], D[256], E[3];

int main(void)
{
    vlbe_ale3_mat mat;
    /* q = [r1(3), r1'(3), th1, p1,  r2(3), r2'(3), th2, p2] */
    static const vlbe_real q[16] = {
        VLBE_R(0.0),  VLBE_R(0.0),   VLBE_R(0.0),  VLBE_R(0.995), VLBE_R(0.05),  VLBE_R(0.08),
        VLBE_R(0.1),  VLBE_R(0.2),   VLBE_R(0.79), VLBE_R(0.06),  VLBE_R(0.04),  VLBE_R(0.985),
        VLBE_R(0.12), VLBE_R(-0.09), VLBE_R(0.35), VLBE_R(1.0)};
    static const vlbe_real qd[16] = {
        VLBE_R(0.01), VLBE_R(0.2),  VLBE_R(-0.1), VLBE_R(0.0),  VLBE_R(0.3),  VLBE_R(-0.2),
        VLBE_R(40.0), VLBE_R(0.05), VLBE_R(0.02), VLBE_R(-0.3), VLBE_R(0.25), VLBE_R(0.01),
        VLBE_R(0.1),  VLBE_R(0.4),  VLBE_R(41.0), VLBE_R(-0.02)};
    if (m4_status("ale3_mat_circle",
                  vlbe_ale3_mat_circle(&mat, VLBE_R(7850.0), VLBE_R(2.1e11), VLBE_R(8.1e10),
                                       VLBE_R(0.005))))
        return m4_exit();
    mat.c_eps = VLBE_R(1e-4);
    mat.c_kap = VLBE_R(2e-4);
    mat.c_phi = VLBE_R(3e-4);
    mat.f[2] = VLBE_R(-9.81) * mat.rhoA;
    m4_val("rhoA", -1, mat.rhoA);
    m4_val("rhoI", -1, mat.rhoI);
    m4_val("EA", -1, mat.EA);
    m4_val("EJ", -1, mat.EJ);
    m4_val("GI", -1, mat.GI);
    if (m4_status("ale3_elem_init", vlbe_ale3_elem_init(&el, &mat, 0, 0, 0))) return m4_exit();
    m4_int("ale3_nq", vlbe_ale3_nq(0));
    if (m4_status("ale3_mass", vlbe_ale3_mass(&el, 0, q, M))) return m4_exit();
    m4_vec("M", M, 256);
    if (m4_status("ale3_force", vlbe_ale3_force(&el, 0, q, qd, Q, K, D))) return m4_exit();
    m4_vec("Q", Q, 16);
    m4_vec("K", K, 256);
    m4_vec("D", D, 256);
    if (m4_status("ale3_energy", vlbe_ale3_energy(&el, 0, q, qd, E))) return m4_exit();
    m4_vec("E", E, 3);
    return m4_exit();
}

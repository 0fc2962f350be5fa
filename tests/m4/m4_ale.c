/* m4_ale.c -- the planar ALE-ANCF element of ancf_ale.h on the Cortex-M4F
   (make check-m4): one element with both material coordinates free, bent
   (slopes at 0.2 and 0.5 rad, stretched 1 %), moving, with Kelvin-Voigt
   damping and gravity: M(q), Q with K = dQ/dq and D = dQ/dq', the energies
   {T, U, V}, printed (tests/m4/m4_out.h).
   -- part of vlbe                                  SPDX-License-Identifier: MIT */
#include "../../ancf_ale.h"
#include "m4_out.h"

static vlbe_ale_elem el; /* about 16 kB: static */
static vlbe_real M[100], Q[10], K[100], D[100], E[3];

int main(void)
{
    vlbe_ale_mat mat;
    /* q = [x1, y1, x1', y1', p1,  x2, y2, x2', y2', p2] */
    static const vlbe_real q[10] = {VLBE_R(0.0),  VLBE_R(0.0),   VLBE_R(0.98995), VLBE_R(0.20066),
                                    VLBE_R(0.1),  VLBE_R(0.95),  VLBE_R(0.25),    VLBE_R(0.86881),
                                    VLBE_R(0.47463), VLBE_R(1.1)};
    static const vlbe_real qd[10] = {VLBE_R(0.1),  VLBE_R(-0.2), VLBE_R(0.05), VLBE_R(0.3),
                                     VLBE_R(0.02), VLBE_R(0.4),  VLBE_R(-0.1), VLBE_R(-0.2),
                                     VLBE_R(0.1),  VLBE_R(-0.03)};
    memset(&mat, 0, sizeof mat);
    mat.rhoA = VLBE_R(1.2);
    mat.EA = VLBE_R(3.0e4);
    mat.EI = VLBE_R(40.0);
    mat.c_eps = VLBE_R(1e-3);
    mat.c_kap = VLBE_R(2e-3);
    mat.f[1] = VLBE_R(-9.81) * mat.rhoA;
    if (m4_status("ale_elem_init", vlbe_ale_elem_init(&el, &mat, 0, 0, 0, 0))) return m4_exit();
    if (m4_status("ale_mass", vlbe_ale_mass(&el, 0, q, M))) return m4_exit();
    m4_vec("M", M, 100);
    if (m4_status("ale_force", vlbe_ale_force(&el, 0, q, qd, Q, K, D))) return m4_exit();
    m4_vec("Q", Q, 10);
    m4_vec("K", K, 100);
    m4_vec("D", D, 100);
    if (m4_status("ale_energy", vlbe_ale_energy(&el, 0, q, qd, E))) return m4_exit();
    m4_vec("E", E, 3);
    return m4_exit();
}

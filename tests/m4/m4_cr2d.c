/* m4_cr2d.c -- the planar co-rotational beam element of corot2d.h on the
   Cortex-M4F (make check-m4): an element at 30 deg, displaced, rotated by
   about 0.5 rad as a whole and bent, moving, with rotary inertia and
   Rayleigh damping: Q with the consistent tangent K (the Hessian of the
   strain energy) and D, M(q), d(M a)/dq, the energies {T, U} and the local
   quantities {l, theta1, theta2, eps0}, printed (tests/m4/m4_out.h).
   -- part of vlbe                                  SPDX-License-Identifier: MIT */
#include "../../corot2d.h"
#include "m4_out.h"

static vlbe_cr2d_elem el;
static vlbe_real M[36], Mq[36], Q[6], K[36], D[36], E[2], loc[4];

int main(void)
{
    vlbe_cr2d_mat mat;
    static const vlbe_real X1[2] = {VLBE_R(0.0), VLBE_R(0.0)};
    static const vlbe_real X2[2] = {VLBE_R(0.8660254), VLBE_R(0.5)};
    /* q = [u1, v1, phi1, u2, v2, phi2] */
    static const vlbe_real q[6] = {VLBE_R(0.01), VLBE_R(-0.02), VLBE_R(0.55),
                                   VLBE_R(-0.35), VLBE_R(0.38), VLBE_R(0.42)};
    static const vlbe_real qd[6] = {VLBE_R(0.1), VLBE_R(0.05), VLBE_R(-0.3),
                                    VLBE_R(-0.2), VLBE_R(0.4), VLBE_R(0.6)};
    static const vlbe_real a[6] = {VLBE_R(1.0), VLBE_R(-2.0), VLBE_R(0.5),
                                   VLBE_R(0.3), VLBE_R(0.7), VLBE_R(-1.1)};
    memset(&mat, 0, sizeof mat);
    mat.EA = VLBE_R(2.0e5);
    mat.EI = VLBE_R(150.0);
    mat.rhoA = VLBE_R(2.7);
    mat.rhoI = VLBE_R(1e-3);
    mat.ray_a = VLBE_R(0.05);
    mat.ray_b = VLBE_R(1e-4);
    if (m4_status("cr2d_elem_init", vlbe_cr2d_elem_init(&el, &mat, X1, X2, 0))) return m4_exit();
    m4_val("L", -1, el.L);
    m4_val("a0", -1, el.a0);
    if (m4_status("cr2d_force", vlbe_cr2d_force(&el, 0, q, qd, Q, K, D))) return m4_exit();
    m4_vec("Q", Q, 6);
    m4_vec("K", K, 36);
    m4_vec("D", D, 36);
    if (m4_status("cr2d_mass", vlbe_cr2d_mass(&el, 0, q, M))) return m4_exit();
    m4_vec("M", M, 36);
    if (m4_status("cr2d_mass_jac", vlbe_cr2d_mass_jac(&el, 0, q, a, Mq))) return m4_exit();
    m4_vec("Mq", Mq, 36);
    if (m4_status("cr2d_energy", vlbe_cr2d_energy(&el, 0, q, qd, E))) return m4_exit();
    m4_vec("E", E, 2);
    if (m4_status("cr2d_local", vlbe_cr2d_local(&el, 0, q, loc))) return m4_exit();
    m4_vec("loc", loc, 4);
    return m4_exit();
}

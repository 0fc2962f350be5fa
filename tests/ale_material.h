/* ale_material.h -- the O(1) planar and 3D ALE-ANCF materials of the random tests,
   shared by the cmocka suites (through ale_fixtures.h) and the fuzz
   harnesses (no cmocka here).
   -- part of vlbe                                  SPDX-License-Identifier: MIT
   Include after ../ancf_ale.h. */
#ifndef VLBE_TEST_ALE_MATERIAL_H
#define VLBE_TEST_ALE_MATERIAL_H

/* Material of the random tests: every term O(1) so that no contribution
   hides below the rounding of another. */
static inline vlbe_ale_mat mat_std(void)
{
    vlbe_ale_mat m;
    m.rhoA = VLBE_R(1.3);
    m.EA = VLBE_R(5.0);
    m.EI = VLBE_R(0.7);
    m.c_eps = VLBE_R(0.15);
    m.c_kap = VLBE_R(0.25);
    m.f[0] = VLBE_R(0.4);
    m.f[1] = VLBE_R(-2.1);
    return m;
}

/* The 3D one (vlbe_ale3_mat): mat_std plus the spin inertia, the
   torsional stiffness, its damping and an out-of-plane load. */
static inline vlbe_ale3_mat mat3_std(void)
{
    vlbe_ale3_mat m;
    m.rhoA = VLBE_R(1.3);
    m.rhoI = VLBE_R(0.45);
    m.EA = VLBE_R(5.0);
    m.EJ = VLBE_R(0.7);
    m.GI = VLBE_R(0.9);
    m.c_eps = VLBE_R(0.15);
    m.c_kap = VLBE_R(0.25);
    m.c_phi = VLBE_R(0.2);
    m.f[0] = VLBE_R(0.4);
    m.f[1] = VLBE_R(-2.1);
    m.f[2] = VLBE_R(0.8);
    return m;
}

/* m3 takes the planar section m2 (rho A, EA, EI, the damping, the load in
   the x-y plane); its spin and torsion terms stay as they are. */
static inline void mat3_planar(vlbe_ale3_mat *m3, const vlbe_ale_mat *m2)
{
    m3->rhoA = m2->rhoA;
    m3->EA = m2->EA;
    m3->EJ = m2->EI;
    m3->c_eps = m2->c_eps;
    m3->c_kap = m2->c_kap;
    m3->f[0] = m2->f[0];
    m3->f[1] = m2->f[1];
    m3->f[2] = VLBE_R(0.0);
}

#endif /* VLBE_TEST_ALE_MATERIAL_H */

/* cr2d_fixtures.h -- what the corot2d suites share: the materials of the
   random tests, deformed states built from a prescribed deformation, the
   textbook matrices of the planar frame element typed from the textbook
   (independent of the tables in corot2d.h) and small double helpers.
   -- part of vlbe                                  SPDX-License-Identifier: MIT
   Include after test_util.h and ../corot2d.h. */
#ifndef VLBE_TEST_CR2D_FIXTURES_H
#define VLBE_TEST_CR2D_FIXTURES_H

#include "fixtures_common.h"

#include <string.h>

static const double CR_PI = 3.14159265358979323846;

/* -- materials ------------------------------------------------------------ */
/* O(1) material: at the O(1) states below every term (axial, bending,
   axial and lateral nonlinear inertia, rotary inertia, both Rayleigh parts)
   is of comparable size, so none hides below the rounding of another. */
static inline vlbe_cr2d_mat cr_mat_unit(void)
{
    vlbe_cr2d_mat m;
    m.EA = VLBE_R(40.0);
    m.EI = VLBE_R(1.5);
    m.rhoA = VLBE_R(1.3);
    m.rhoI = VLBE_R(0.15);
    m.ray_a = VLBE_R(0.3);
    m.ray_b = VLBE_R(0.02);
    return m;
}

/* Stiff material with the scales of a real beam: elastic stiffness EA/L
   ~ 1e6, stiffness-proportional damping beta EA/L ~ 1e3, inertia O(1),
   rotary inertia rhoI/rhoA = 1e-3 (radius of gyration 3 cm). */
static inline vlbe_cr2d_mat cr_mat_stiff(void)
{
    vlbe_cr2d_mat m;
    m.EA = VLBE_R(1.0e6);
    m.EI = VLBE_R(1.0e3);
    m.rhoA = VLBE_R(2.7);
    m.rhoI = VLBE_R(2.7e-3);
    m.ray_a = VLBE_R(0.5);
    m.ray_b = VLBE_R(1.0e-3);
    return m;
}

static inline void cr_elem_make(vlbe_cr2d_elem *el, const vlbe_cr2d_mat *m, double x1, double y1,
                                double x2, double y2, unsigned flags)
{
    vlbe_real X1[2], X2[2];
    X1[0] = (vlbe_real)x1;
    X1[1] = (vlbe_real)y1;
    X2[0] = (vlbe_real)x2;
    X2[1] = (vlbe_real)y2;
    assert_int_equal(vlbe_cr2d_elem_init(el, m, X1, X2, flags), VLBE_OK);
}

/* Element of length L at reference angle a0 whose node 1 sits at (x1, y1). */
static inline void cr_elem_polar(vlbe_cr2d_elem *el, const vlbe_cr2d_mat *m, double x1, double y1,
                                 double L, double a0, unsigned flags)
{
    cr_elem_make(el, m, x1, y1, x1 + L * cos(a0), y1 + L * sin(a0), flags);
}

/* -- states from a prescribed deformation ---------------------------------- */
/* A state with chord angle b, chord length l, deformation rotations th[j]
   and node 1 displaced by (t0, t1): node 2 at x1 + l (cos b, sin b), the
   cross-section rotations phi_j = b + th_j - a0 + 2 pi turns.  q in
   vlbe_real (rounded). */
static inline void cr_state_set(const vlbe_cr2d_elem *el, double b, double l, const double *th,
                                double t0, double t1, int turns, vlbe_real *q)
{
    const double X1 = (double)el->X[0], Y1 = (double)el->X[1];
    const double X2 = (double)el->X[2], Y2 = (double)el->X[3];
    const double a0 = atan2(Y2 - Y1, X2 - X1);
    const double x1 = X1 + t0, y1 = Y1 + t1;
    q[0] = (vlbe_real)t0;
    q[1] = (vlbe_real)t1;
    q[2] = (vlbe_real)(b + th[0] - a0 + 2.0 * CR_PI * turns);
    q[3] = (vlbe_real)(x1 + l * cos(b) - X2);
    q[4] = (vlbe_real)(y1 + l * sin(b) - Y2);
    q[5] = (vlbe_real)(b + th[1] - a0 + 2.0 * CR_PI * turns);
}

/* A random deformed state: chord at a random angle b, deformation
   rotations |th_j| <= thmax, uniform extension eps0 in [-epsmax, epsmax]
   (l chosen to give it), node 1 moved by up to 1 in x and y, cross-sections
   turned by `turns` full turns on top (turns = 2: phi ~ 13 rad), velocities
   uniform in [-vel, vel].  (The chord for a given eps0 uses (1/2L) int v'^2
   = (4 th1^2 - 2 th1 th2 + 4 th2^2)/60; the tests check the element's eps0
   against their own quadrature, not against this.)  Writes q, qd (qd may
   be NULL) and the prescribed
   deformation (l, th1, th2, eps0, b) to def (may be NULL). */
static inline void cr_state_rand(const vlbe_cr2d_elem *el, tu_rng *g, double thmax, double epsmax,
                                 int turns, double vel, vlbe_real *q, vlbe_real *qd, double *def)
{
    const double L = (double)el->L;
    const double b = CR_PI * tu_rng_uniform(g);
    double th[2], eps, l;
    double t0, t1;
    int i;
    th[0] = thmax * tu_rng_uniform(g);
    th[1] = thmax * tu_rng_uniform(g);
    eps = epsmax * tu_rng_uniform(g);
    l = L * (1.0 + eps - (4.0 * th[0] * th[0] - 2.0 * th[0] * th[1] + 4.0 * th[1] * th[1]) / 60.0);
    t0 = tu_rng_uniform(g);
    t1 = tu_rng_uniform(g);
    cr_state_set(el, b, l, th, t0, t1, turns, q);
    if (qd)
        for (i = 0; i < 6; ++i) qd[i] = (vlbe_real)(vel * tu_rng_uniform(g));
    if (def) {
        def[0] = l;
        def[1] = th[0];
        def[2] = th[1];
        def[3] = eps;
        def[4] = b;
    }
}

/* Chord angle, length and deformation rotations of q, in double, from the
   definitions (independent of the header): b = atan2 of the chord, theta_j
   = a0 + phi_j - b wrapped into [-pi, pi].  The turns are taken off phi in
   two parts, 2 pi = C1 + C2 with C1 = 6.28125 (8 bits: n C1 and phi - n C1
   exact), so the wrapped value is accurate to a few EPS of pi whatever the
   number of turns. */
static inline void cr_kin_ref(const vlbe_cr2d_elem *el, const vlbe_real *q, double *b, double *l,
                              double *th)
{
    const double X1 = (double)el->X[0], Y1 = (double)el->X[1];
    const double X2 = (double)el->X[2], Y2 = (double)el->X[3];
    const double a0 = atan2(Y2 - Y1, X2 - X1);
    const double dx = X2 + (double)q[3] - X1 - (double)q[0];
    const double dy = Y2 + (double)q[4] - Y1 - (double)q[1];
    int j;
    *b = atan2(dy, dx);
    *l = hypot(dx, dy);
    for (j = 0; j < 2; ++j) {
        const double C1 = 6.28125, C2 = 1.9353071795864769253e-3; /* 2 pi - C1 */
        const double x = a0 - *b, p = (double)q[2 + 3 * j];
        const double n = nearbyint((p + x) / (2.0 * CR_PI));
        th[j] = ((p - n * C1) - n * C2) + x;
    }
}

/* -- the rotation into a frame at angle b, 6x6 (u = T q) ------------------- */
static inline void cr_rot6(double b, double *T)
{
    const double c = cos(b), s = sin(b);
    int k, i;
    for (i = 0; i < 36; ++i) T[i] = 0.0;
    for (k = 0; k < 6; k += 3) {
        T[k * 6 + k] = c;
        T[k * 6 + k + 1] = s;
        T[(k + 1) * 6 + k] = -s;
        T[(k + 1) * 6 + k + 1] = c;
        T[(k + 2) * 6 + k + 2] = 1.0;
    }
}

/* G = T^T A T (all 6x6, double) */
static inline void cr_congr(const double *T, const double *A, double *G)
{
    double B[36];
    int i, j, k;
    for (i = 0; i < 6; ++i)
        for (j = 0; j < 6; ++j) {
            double s = 0.0;
            for (k = 0; k < 6; ++k) s += A[i * 6 + k] * T[k * 6 + j];
            B[i * 6 + j] = s;
        }
    for (i = 0; i < 6; ++i)
        for (j = 0; j < 6; ++j) {
            double s = 0.0;
            for (k = 0; k < 6; ++k) s += T[k * 6 + i] * B[k * 6 + j];
            G[i * 6 + j] = s;
        }
}

/* L = T A T^T: a global matrix seen in the frame (T^T A T with T^T) */
static inline void cr_to_frame(const double *T, const double *A, double *Lm)
{
    double Tt[36];
    int i, j;
    for (i = 0; i < 6; ++i)
        for (j = 0; j < 6; ++j) Tt[i * 6 + j] = T[j * 6 + i];
    cr_congr(Tt, A, Lm);
}
/* -- textbook matrices of the planar frame element (u1 v1 phi1 u2 v2 phi2) -- */
/* Przemieniecki, Theory of Matrix Structural Analysis (1968), or any FE text:
   the consistent mass (rhoA L/420 with the axial part rhoA L/6 [2 1; 1 2]),
   the rotary inertia of the Hermite slopes rhoI/(30 L) [36 3L -36 3L; ...],
   the stiffness EA/L, EI/L^3 [12 6L -12 6L; ...] and the geometric
   stiffness N/(30 L) [36 3L -36 3L; ...] (the same matrix as the rotary
   inertia).  Typed here from the books, not from corot2d.h. */
static inline void cr_textbook_mass(double rhoA, double rhoI, double L, double *M)
{
    const double a = rhoA * L / 420.0, r = rhoI / (30.0 * L), L2 = L * L;
    const double t[36] = {
        140 * a, 0, 0, 70 * a, 0, 0,
        0, 156 * a + 36 * r, 22 * L * a + 3 * L * r, 0, 54 * a - 36 * r, -13 * L * a + 3 * L * r,
        0, 22 * L * a + 3 * L * r, 4 * L2 * a + 4 * L2 * r, 0, 13 * L * a - 3 * L * r, -3 * L2 * a - L2 * r,
        70 * a, 0, 0, 140 * a, 0, 0,
        0, 54 * a - 36 * r, 13 * L * a - 3 * L * r, 0, 156 * a + 36 * r, -22 * L * a - 3 * L * r,
        0, -13 * L * a + 3 * L * r, -3 * L2 * a - L2 * r, 0, -22 * L * a - 3 * L * r, 4 * L2 * a + 4 * L2 * r};
    memcpy(M, t, sizeof t);
}

static inline void cr_textbook_stiffness(double EA, double EI, double L, double *K)
{
    const double a = EA / L, e = EI / (L * L * L), L2 = L * L;
    const double t[36] = {a, 0, 0, -a, 0, 0,
                          0, 12 * e, 6 * L * e, 0, -12 * e, 6 * L * e,
                          0, 6 * L * e, 4 * L2 * e, 0, -6 * L * e, 2 * L2 * e,
                          -a, 0, 0, a, 0, 0,
                          0, -12 * e, -6 * L * e, 0, 12 * e, -6 * L * e,
                          0, 6 * L * e, 2 * L2 * e, 0, -6 * L * e, 4 * L2 * e};
    memcpy(K, t, sizeof t);
}

static inline void cr_textbook_geometric(double N, double L, double *G)
{
    const double g = N / (30.0 * L), L2 = L * L;
    const double t[36] = {0, 0, 0, 0, 0, 0,
                          0, 36 * g, 3 * L * g, 0, -36 * g, 3 * L * g,
                          0, 3 * L * g, 4 * L2 * g, 0, -3 * L * g, -L2 * g,
                          0, 0, 0, 0, 0, 0,
                          0, -36 * g, -3 * L * g, 0, 36 * g, -3 * L * g,
                          0, 3 * L * g, -L2 * g, 0, -3 * L * g, 4 * L2 * g};
    memcpy(G, t, sizeof t);
}

/* -- small helpers ---------------------------------------------------------- */
static inline double cr_max_abs(int n, const vlbe_real *a)
{
    double m = 0.0;
    int i;
    for (i = 0; i < n; ++i) m = fmax(m, fabs((double)a[i]));
    return m;
}

static inline void cr_fill(int n, vlbe_real v, vlbe_real *a)
{
    int i;
    for (i = 0; i < n; ++i) a[i] = v;
}

static inline void cr_to_double(int n, const vlbe_real *a, double *d)
{
    int i;
    for (i = 0; i < n; ++i) d[i] = (double)a[i];
}


#endif /* VLBE_TEST_CR2D_FIXTURES_H */

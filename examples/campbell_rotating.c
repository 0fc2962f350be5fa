/* campbell_rotating.c -- Campbell diagram of a rotating cantilever: its
   in-plane (lag) and out-of-plane (flap) bending frequencies against the
   spin speed, from the linearisation of ANCF chains about the steady
   rotating state (vlbe_dae_linearize in the turning frame, integrators.h)
   and the gyroscopic eigenproblem (vlbe_eig_quad, vlbe.h), against the
   exact frequencies of the rotating Euler-Bernoulli beam (ex_cant_rot of
   scenes/ex_cant.h).  -- part of vlbe          SPDX-License-Identifier: MIT

   cc -O2 examples/campbell_rotating.c -lm && ./a.out [outdir]

   The model, the steady state, the linearisation and the sweep are
   scenes/campbell_rotating.h (shared with tests/test_modal.c); this file
   prints the tables, rows and charts.

   Beam: that of the spin-up scene (scenes/ex_spin.h): L = 10 m,
   EA = 2.8e7 N, EI = 1.4e4 N m^2, rhoA = 1.2 kg/m, no rotary inertia,
   clamped on the hub axis (position and slope held); first bending
   frequency at rest w0 = 1.8751^2 sqrt(EI / (rhoA L^4)) = 3.80 rad/s.
   Spin Om = 0 .. 13 rad/s about z, i.e. 0 .. 12 in the unit
   u = sqrt(EI / (rhoA L^4)) = 1.080 rad/s of the classical tables.

   Steady state.  In the frame turning with the hub the beam is at rest
   under its elastic forces and the centrifugal load -M G^2 q, where
   G = Om [e_z x] acts on every position and slope vector of q: the
   static solve (vlbe_dae_static) of the chain with that load added
   (continuation in Om from the straight beam).  In the inertial frame the
   same state moves with v = G q, q'' = G^2 q, and the multipliers are
   the same.
   Linearisation.  vlbe_dae_linearize about (q, G q, G^2 q, lambda) with
   the turning frame (vlbe_lin_frame: Om about z, the position and slope
   vectors of every node): M, D = 2 M G (Coriolis), K = K_t + M G^2 (the
   tangent stiffness with the centrifugal tension, and the centrifugal
   softening), reduced on the null space of the clamp.  Then
   (s^2 M + s D + K) x = 0 by vlbe_eig_quad with the shift sigma = -w0/2
   (shift-invert: the lowest |s| first); w = Im s.
   Models: the planar chain (in-plane modes only) and the 3D beam-shaft
   chain without its spin angle (VLBE_ALE3_NO_SPIN; the section is round
   and nothing twists), whose modes are told apart by their eigenvectors
   (flap: the z components carry most of the mode; lag: x and y).
   For contrast the LINEAR FLOATING FRAME: the same linearisation about the
   straight UNSTRESSED beam (no centrifugal tension, lambda = 0): lag
   w^2 = w0^2 - Om^2 (to the Coriolis coupling with the axial modes), zero
   at Om = w0 -- the divergence that ends the linear model's run in
   examples/spin_up.c -- while the nonlinear beam stiffens.

   Exact: the rotating uniform cantilever, w_lag^2 = w_flap^2 - Om^2 with
   the flap frequencies by shooting (ex_cant_rot; the classical 3.6816,
   4.1373, ... at Om = 1, 2, ...).  That theory is inextensible; the ANCF
   beam is not (EA L^2 / EI = 2e5; first axial mode 762 rad/s): its
   centrifugal stretch and the Coriolis coupling of the lag modes with the
   axial ones lower them, at Om = 10 rad/s the lag by 5.4e-4 relative and
   the flap by 5e-5, beside the discretisation error of 16 consistent-mass
   Hermite elements (1e-4, from above).  The rows with EA x 10, 100, 1000
   separate the two: the difference to the inextensible value falls as
   1/EA onto the discretisation error.

   Rows ROW|campbell rotating|<quantity>|<exact>|<ours>|<rel.err>|<cpu s>;
   with an output directory campbell_rotating.csv / .svg. */
#include "../scenes/campbell_rotating.h"
#include "../scenes/svgplot.h"

static void cr_row(const char *what, double exact, double ours, double cpu)
{
    svgp_compare_row(stdout, "campbell rotating", what, exact, ours, fabs(ours - exact) / exact,
                     cpu);
}

int main(int argc, char **argv)
{
    const char *dir = argc > 1 ? argv[1] : "out";
    const double u = cr_unit();
    static double Om[CR_NOM], ex[4][CR_NOM], l2[CR_NOM][CR_NW], f2[CR_NOM][CR_NW],
        l3[CR_NOM][CR_NW], f3[CR_NOM][CR_NW], lu[CR_NOM][CR_NW], fu[CR_NOM][CR_NW], reu[CR_NOM];
    static double col[12][CR_NOM];
    double cpu2 = 0, cpu3 = 0, cpuu = 0, cpue, w0;
    char what[160], path[512];
    int j, k, ne;
    clock_t t0;
    for (j = 0; j < CR_NOM; ++j) Om[j] = 0.5 * j;
    t0 = clock();
    for (j = 0; j < CR_NOM; ++j) { /* exact, physical units */
        ex[0][j] = u * ex_cant_rot(1, Om[j] / u, 0);
        ex[1][j] = u * ex_cant_rot(2, Om[j] / u, 0);
        ex[2][j] = u * ex_cant_rot(1, Om[j] / u, 1);
        ex[3][j] = u * ex_cant_rot(2, Om[j] / u, 1);
    }
    cpue = (double)(clock() - t0) / (double)CLOCKS_PER_SEC;
    w0 = ex[0][0];
    printf("Campbell diagram of a rotating cantilever (L = 10 m, EI = 1.4e4 N m^2, rhoA = 1.2 "
           "kg/m; w0 = %.6f rad/s, unit sqrt(EI/(rhoA L^4)) = %.6f rad/s)\n", w0, u);
    if (cr_sweep(16, 2, 1.0, 1, CR_NOM, Om, l2, f2, NULL, &cpu2) || cr_sweep(16, 3, 1.0, 1, CR_NOM, Om, l3, f3, NULL, &cpu3) ||
        cr_sweep(16, 2, 1.0, 0, CR_NOM, Om, lu, fu, reu, &cpuu)) {
        printf("campbell_rotating: a sweep failed\n");
        return 1;
    }
    printf("exact frequencies by shooting: %.3f s for %d roots\n", cpue, 4 * CR_NOM);
    printf("16 elements; CPU of a sweep of %d speeds (steady state, linearisation, eigen): "
           "planar %.3f s, 3D %.3f s, unstressed planar %.3f s\n", CR_NOM, cpu2, cpu3, cpuu);
    printf("  Om [rad/s]   flap1 exact / 3D      flap2 exact / 3D      lag1 exact / 3D / planar"
           "          lag2 exact / 3D / planar        lag1 unstressed\n");
    for (j = 0; j < CR_NOM; j += 2)
        printf("  %5.1f   %9.5f %9.5f   %9.5f %9.5f   %9.5f %9.5f %9.5f   %9.5f %9.5f %9.5f   %9.5f\n",
               Om[j], ex[0][j], f3[j][0], ex[1][j], f3[j][1], ex[2][j], l3[j][0], l2[j][0], ex[3][j],
               l3[j][1], l2[j][1], lu[j][0]);
    for (j = 0; j < CR_NOM; j += 8) {
        snprintf(what, sizeof what, "flap 1 [rad/s] at Om = %g rad/s (3D, 16 el.)", Om[j]);
        cr_row(what, ex[0][j], f3[j][0], cpu3 / CR_NOM);
        snprintf(what, sizeof what, "flap 2 [rad/s] at Om = %g rad/s (3D, 16 el.)", Om[j]);
        cr_row(what, ex[1][j], f3[j][1], cpu3 / CR_NOM);
        snprintf(what, sizeof what, "lag 1 [rad/s] at Om = %g rad/s (3D, 16 el.)", Om[j]);
        cr_row(what, ex[2][j], l3[j][0], cpu3 / CR_NOM);
        snprintf(what, sizeof what, "lag 1 [rad/s] at Om = %g rad/s (planar, 16 el.)", Om[j]);
        cr_row(what, ex[2][j], l2[j][0], cpu2 / CR_NOM);
    }
    j = CR_NOM - 1;
    snprintf(what, sizeof what, "flap 1 [rad/s] at Om = %g rad/s (3D, 16 el.)", Om[j]);
    cr_row(what, ex[0][j], f3[j][0], cpu3 / CR_NOM);
    snprintf(what, sizeof what, "lag 1 [rad/s] at Om = %g rad/s (planar, 16 el.)", Om[j]);
    cr_row(what, ex[2][j], l2[j][0], cpu2 / CR_NOM);
    for (j = 2; j <= 6; j += 4) {
        const double e = sqrt(w0 * w0 - Om[j] * Om[j]);
        snprintf(what, sizeof what,
                 "linear floating frame: lag 1 [rad/s] at Om = %g rad/s vs sqrt(w0^2 - Om^2)", Om[j]);
        cr_row(what, e, lu[j][0], cpuu / CR_NOM);
    }
    printf("mesh convergence at Om = 10 rad/s (3D; flap 1, lag 1; relative errors):\n");
    for (ne = 2; ne <= 16; ne *= 2) {
        double o = 10.0, l[1][CR_NW], f[1][CR_NW], cpu = 0;
        if (cr_sweep(ne, 3, 1.0, 1, 1, &o, l, f, NULL, &cpu)) return 1;
        printf("  %2d elements  flap1 %.9f (%.2e)  lag1 %.9f (%.2e)\n", ne, f[0][0],
               fabs(f[0][0] - ex[0][20]) / ex[0][20], l[0][0], fabs(l[0][0] - ex[2][20]) / ex[2][20]);
        snprintf(what, sizeof what, "flap 1 [rad/s] at Om = 10 rad/s, %d elements", ne);
        cr_row(what, ex[0][20], f[0][0], cpu);
    }
    printf("extensibility: lag 1 at Om = 10 rad/s (planar, 16 elements) against the "
           "inextensible exact %.9f rad/s:\n", ex[2][20]);
    for (k = 0; k < 4; ++k) {
        const double eaf = k == 0 ? 1.0 : k == 1 ? 10.0 : k == 2 ? 100.0 : 1000.0;
        double o = 10.0, l[1][CR_NW], f[1][CR_NW], cpu = 0;
        if (cr_sweep(16, 2, eaf, 1, 1, &o, l, f, NULL, &cpu)) return 1;
        printf("  EA x %6g  lag1 %.9f (%.2e)\n", eaf, l[0][0], fabs(l[0][0] - ex[2][20]) / ex[2][20]);
        snprintf(what, sizeof what, "lag 1 [rad/s] at Om = 10 rad/s, planar 16 el., EA x %g", eaf);
        cr_row(what, ex[2][20], l[0][0], cpu);
    }
    for (j = 1; j < CR_NOM && reu[j] <= 1e-3 * w0; ++j) {}
    if (j < CR_NOM)
        printf("linear floating frame: stable (max Re s = %.2e) up to Om = %g rad/s, unstable "
               "(max Re s = %.4f 1/s) from Om = %g rad/s; w0 = %.6f rad/s\n", reu[j - 1], Om[j - 1],
               reu[j], Om[j], w0);
    for (j = 0; j < CR_NOM; ++j) {
        col[0][j] = Om[j];
        for (k = 0; k < 4; ++k) col[1 + k][j] = ex[k][j];
        col[5][j] = f3[j][0];
        col[6][j] = f3[j][1];
        col[7][j] = l3[j][0];
        col[8][j] = l3[j][1];
        col[9][j] = l2[j][0];
        col[10][j] = l2[j][1];
        col[11][j] = lu[j][0];
    }
    {
        const double *cols[12];
        svgp_chart ch;
        static double y1[2] = {0, 13}, x1[2] = {0, 13}, X[2 * CR_NOM + 1], Y[5][2 * CR_NOM + 1];
        for (k = 0; k < 12; ++k) cols[k] = col[k];
        snprintf(path, sizeof path, "%s/campbell_rotating.csv", dir);
        if (svgp_csv_write(path,
                           "Om,flap1_exact,flap2_exact,lag1_exact,lag2_exact,flap1_3d,flap2_3d,"
                           "lag1_3d,lag2_3d,lag1_planar,lag2_planar,lag1_unstressed",
                           12, CR_NOM, cols))
            printf("# could not write %s\n", path);
        for (k = 0; k < 5; ++k) { /* modes 1 and 2 as one series, NaN between */
            static const int src[5][2] = {{1, 2}, {3, 4}, {5, 6}, {7, 8}, {9, 10}};
            for (j = 0; j < CR_NOM; ++j) {
                X[j] = X[CR_NOM + 1 + j] = Om[j];
                Y[k][j] = col[src[k][0]][j];
                Y[k][CR_NOM + 1 + j] = col[src[k][1]][j];
            }
            X[CR_NOM] = Y[k][CR_NOM] = NAN;
        }
        svgp_init(&ch, "Rotating cantilever: Campbell diagram (16 ANCF elements vs exact)",
                  "spin speed Om [rad/s]", "frequency [rad/s]", 0, 0);
        svgp_series(&ch, "flap 1, 2 exact", 2 * CR_NOM + 1, X, Y[0], 0);
        svgp_series(&ch, "lag 1, 2 exact (w^2 = w_flap^2 - Om^2)", 2 * CR_NOM + 1, X, Y[1],
                    SVGP_DASH);
        svgp_series(&ch, "flap, 3D beam-shaft", 2 * CR_NOM + 1, X, Y[2], SVGP_NOLINE);
        svgp_series(&ch, "lag, 3D beam-shaft", 2 * CR_NOM + 1, X, Y[3], SVGP_NOLINE);
        svgp_series(&ch, "lag, planar", 2 * CR_NOM + 1, X, Y[4], SVGP_NOLINE);
        svgp_series(&ch, "lag 1, linear floating frame (no stiffening)", 8, Om, col[11], SVGP_DOT);
        svgp_series(&ch, "w = Om (once per revolution)", 2, x1, y1, SVGP_DOT);
        ch.legend = SVGP_LEGEND_TL;
        svgp_xrange(&ch, 0, 13);
        svgp_yrange(&ch, 0, 60);
        snprintf(path, sizeof path, "%s/campbell_rotating.svg", dir);
        if (svgp_write_file(&ch, path)) printf("# could not write %s\n", path);
    }
    return 0;
}

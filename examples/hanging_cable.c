/* hanging_cable.c -- a uniform cable hanging under gravity, pinned at the
   top: its first three lateral frequencies against the Bessel closed form
   omega_k = (j0_k / 2) sqrt(g / L), with mesh convergence.
   -- part of vlbe                                  SPDX-License-Identifier: MIT

   cc -O2 -I. examples/hanging_cable.c -lm && ./a.out [outdir [N ...]]

   The model, the measurement and the physics corrections are in
   scenes/ex_cable.h (shared with tests/test_scenes_cable.c): L = 10 m,
   rhoA = 1 kg/m, EA = 1e7 N, EI = 1e-7 N m^2, g = 9.81, N Lagrangian
   ALE-ANCF elements, static equilibrium by vlbe_dae_static, then a start in
   the analytic k-th mode (lateral velocities, 10 um at the free end) and
   HHT-alpha (-0.05) at 200 steps per period over two periods; omega from
   the zero crossings of the projection on the analytic mode, HHT's known
   O((omega h)^2) frequency error removed.

   Printed per mesh (the element counts are the arguments after outdir;
   default 4 8 16 ... 1024) and mode: the measured omega, the closed form and
   the relative error; the same error less the stated first-order
   corrections (extension, bending: the error of the discretisation and of
   the measurement alone) and its rate between successive meshes; the
   dense eigen-analysis of the same model (up to EX_HC_EIG_MAX elements) as
   an independent check of the measurement; the clamped top against the
   pinned one.  Rows ROW|hanging|omega_k, N elements [rad/s]|closed form|
   ours|rel.err|cpu for `make demo`, and the same against the closed form
   with the stated corrections; out/hanging_cable_error.svg (the error
   less the corrections against the elements, log-log) and
   out/hanging_cable_modes.svg (the analytic mode shapes and the nodes of
   the eigenvectors at 16 elements). */
#include "../scenes/ex_cable.h"

#include <stdio.h>
#include <stdlib.h>

#define EX_HC_MAXN 16     /* meshes in one run, at most        */
#define EX_HC_EIG_MAX 128 /* dense eigen-analysis up to here   */
#define EX_HC_SHAPE_N 16  /* mesh of the mode-shape chart      */
#define EX_HC_PTS 201     /* points of an analytic mode shape  */

#include "../scenes/svgplot.h"

int main(int argc, char **argv)
{
    const char *dir = argc > 1 ? argv[1] : "out";
    int Ns[EX_HC_MAXN] = {4, 8, 16, 32, 64, 128, 256, 512, 1024}, nN = 9, i, k, rc = 0;
    static double err[EX_HC_MAXN][EX_CABLE_NMODES], xN[EX_HC_MAXN];
    static double ycol[EX_CABLE_NMODES][EX_HC_MAXN];
    static double zs[EX_HC_PTS], us[EX_CABLE_NMODES][EX_HC_PTS], zn[EX_HC_SHAPE_N + 1],
        un[EX_CABLE_NMODES][EX_HC_SHAPE_N + 1];
    double ext[EX_CABLE_NMODES], bend[EX_CABLE_NMODES], clamp[EX_CABLE_NMODES];
    ex_cable_cfg cfg;
    ex_cable_run run;
    char path[512], qty[200];
    if (argc > 2) {
        nN = 0;
        for (i = 2; i < argc && nN < EX_HC_MAXN; ++i) {
            const int n = atoi(argv[i]);
            if (n >= 1) Ns[nN++] = n;
        }
    }
    ex_cable_cfg_default(&cfg, 1);
    cfg.banded = 1; /* O(N) per step: the time histories of long cables */
    ex_cable_run_default(&run);
    printf("# hanging cable: L = %g m, g = %g m/s^2, rhoA = %g kg/m, EA = %g N (top strain %.3g), "
           "EI = %g N m^2, pinned top; Lagrangian ALE-ANCF elements, %s storage\n", cfg.L, cfg.g,
           cfg.rhoA, cfg.EA, cfg.rhoA * cfg.g * cfg.L / cfg.EA, cfg.EI,
           cfg.banded ? "banded" : "dense");
    printf("# measurement: start in the analytic mode (amplitude %g m at the free end), HHT-alpha "
           "%g, %d steps per period, %d periods; omega from the zero crossings of the projection "
           "on the analytic mode, HHT's frequency error c (omega h)^2, c = %.6f, removed "
           "(remainder 0.0085 (omega h)^4 = %.1e)\n", run.amp, run.alpha, run.steps_per_period,
           run.periods, ex_cable_hht_c(run.alpha),
           0.0085 * pow(2.0 * 3.14159265358979323846 / run.steps_per_period, 4.0));
    for (k = 1; k <= EX_CABLE_NMODES; ++k) {
        ex_cable_corrections(&cfg, k, &ext[k - 1], &bend[k - 1], &clamp[k - 1]);
        printf("# mode %d: closed form omega = (%.15g / 2) sqrt(g / L) = %.10f rad/s; first-order "
               "corrections: extension %+.3e, bending %+.3e (pinned); a clamp's boundary layer "
               "%+.3e\n", k, ex_cable_j0_zero(k), ex_cable_omega_exact(k, cfg.g, cfg.L),
               ext[k - 1], bend[k - 1], clamp[k - 1]);
    }
    printf("#\n# %4s | %s | %14s | %14s | %10s | %12s | %5s | %14s | %10s | %10s | %6s\n", "N", "k",
           "omega [rad/s]", "closed form", "rel.err", "err - corr.", "rate", "eig (dense)",
           "meas/eig-1", "clamp/pin-1", "cpu s");
    for (i = 0; i < nN; ++i) {
        ex_cable m, mc;
        vlbe_real *q, *qc;
        double om[EX_CABLE_NMODES], omc[EX_CABLE_NMODES];
        double shape[EX_CABLE_NMODES * (EX_HC_SHAPE_N + 1)];
        int have_eig = 0;
        ex_cable_cfg c = cfg;
        c.N = Ns[i];
        xN[i] = Ns[i];
        if (ex_cable_build(&m, &c)) {
            printf("# N = %d: the model could not be built\n", Ns[i]);
            return 1;
        }
        q = (vlbe_real *)malloc((size_t)m.ch.n * sizeof *q);
        if (!q) return 1;
        ex_cable_hanging(&m, q);
        if (ex_cable_static(&m, q) != VLBE_OK) {
            printf("# N = %d: no static equilibrium\n", Ns[i]);
            return 1;
        }
        if (Ns[i] <= EX_HC_EIG_MAX) { /* the dense twin of the model (the same q) */
            ex_cable md;
            c.banded = 0;
            if (ex_cable_build(&md, &c) == 0) {
                have_eig = ex_cable_eig(&md, q, EX_CABLE_NMODES, om,
                                        Ns[i] == EX_HC_SHAPE_N ? shape : NULL) == VLBE_OK;
                ex_cable_free(&md);
            }
            c.clamped = 1;
            if (have_eig && ex_cable_build(&mc, &c) == 0) {
                qc = (vlbe_real *)malloc((size_t)mc.ch.n * sizeof *qc);
                if (qc) ex_cable_hanging(&mc, qc);
                if (!qc || ex_cable_static(&mc, qc) != VLBE_OK ||
                    ex_cable_eig(&mc, qc, EX_CABLE_NMODES, omc, NULL) != VLBE_OK)
                    for (k = 0; k < EX_CABLE_NMODES; ++k) omc[k] = (double)NAN;
                free(qc);
                ex_cable_free(&mc);
            }
            if (Ns[i] == EX_HC_SHAPE_N && have_eig)
                for (k = 0; k < EX_CABLE_NMODES; ++k) {
                    int j;
                    for (j = 0; j <= EX_HC_SHAPE_N; ++j) {
                        zn[j] = cfg.L - (double)m.node[j].p;
                        un[k][j] = shape[k * (EX_HC_SHAPE_N + 1) + j];
                    }
                }
        }
        for (k = 1; k <= EX_CABLE_NMODES; ++k) {
            const ex_cable_freq_out r = ex_cable_freq(&m, q, k, &run);
            const double ex = ex_cable_omega_exact(k, cfg.g, cfg.L), e = r.omega / ex - 1.0;
            const double ec = e - ext[k - 1] - bend[k - 1];
            char rate[16] = "-";
            if (r.status != VLBE_OK) rc = 1;
            err[i][k - 1] = ec;
            ycol[k - 1][i] = fabs(ec);
            if (i > 0 && err[i - 1][k - 1] != 0.0 && ec != 0.0)
                snprintf(rate, sizeof rate, "%.2f", log(fabs(err[i - 1][k - 1] / ec)) /
                                                        log((double)Ns[i] / Ns[i - 1]));
            printf("# %4d | %d | %14.10f | %14.10f | %+10.3e | %+12.3e | %5s | ", Ns[i], k, r.omega,
                   ex, e, ec, rate);
            if (have_eig)
                printf("%14.10f | %+10.2e | %+10.2e | %6.2f\n", om[k - 1],
                       r.omega / om[k - 1] - 1.0, omc[k - 1] / om[k - 1] - 1.0, r.cpu);
            else
                printf("%14s | %10s | %10s | %6.2f\n", "-", "-", "-", r.cpu);
            if (r.status != VLBE_OK)
                printf("#        run stopped: %s after %ld steps\n", vlbe_status_str(r.status),
                       r.steps);
            snprintf(qty, sizeof qty, "omega_%d, %d elements [rad/s]", k, Ns[i]);
            svgp_compare_row(stdout, "hanging", qty, ex, r.omega, e, r.cpu);
            snprintf(qty, sizeof qty, "omega_%d, %d elements, against closed form x (1 + extension "
                     "+ bending) [rad/s]", k, Ns[i]);
            svgp_compare_row(stdout, "hanging", qty, ex * (1.0 + ext[k - 1] + bend[k - 1]),
                             r.omega, r.omega / (ex * (1.0 + ext[k - 1] + bend[k - 1])) - 1.0,
                             r.cpu);
        }
        free(q);
        ex_cable_free(&m);
    }
    printf("#\n# err - corr.: the relative error less the first-order extension and bending "
           "corrections, i.e. the discretisation and measurement error; its rate is the mesh "
           "convergence (cubic Hermite elements: eigenvalue errors O(h^6) asymptotically) down to "
           "the floor of the measurement, ~2e-9 (HHT's (omega h)^4 remainder, the crossings; "
           "meas/eig-1 shows it)\n");
    printf("# clamp/pin-1: the same model with the top slope held vertical.  Its continuum "
           "correction is l/(2L) = %.2e (l = sqrt(EI/T_top)); a mesh with L_e >> l cannot bend "
           "within l and bends the first element instead: an error O(L_e / L), halving with "
           "every refinement, far above the error of the pinned model\n", clamp[0]);

    { /* the charts */
        svgp_chart ce, cm;
        static const char *mname[EX_CABLE_NMODES] = {"mode 1", "mode 2", "mode 3"};
        static const char *nname[EX_CABLE_NMODES] = {"mode 1, eigenvector at 16 elements",
                                                     "mode 2, eigenvector at 16 elements",
                                                     "mode 3, eigenvector at 16 elements"};
        int j;
        svgp_init(&ce, "Hanging cable: |relative frequency error| less the extension and "
                  "bending corrections", "elements", "|omega / omega_closed - 1 - corrections|",
                  1, 1);
        for (k = 0; k < EX_CABLE_NMODES; ++k)
            svgp_series(&ce, mname[k], nN, xN, ycol[k], SVGP_MARKERS);
        snprintf(path, sizeof path, "%s/hanging_cable_error.svg", dir);
        if (svgp_write_file(&ce, path)) printf("# could not write %s\n", path);
        svgp_init(&cm, "Hanging cable: lateral mode shapes J0(2 omega_k sqrt(z/g))",
                  "z, distance from the free end [m]", "u / u(free end)", 0, 0);
        for (j = 0; j < EX_HC_PTS; ++j) {
            zs[j] = cfg.L * j / (EX_HC_PTS - 1);
            for (k = 0; k < EX_CABLE_NMODES; ++k)
                ex_cable_mode(ex_cable_omega_exact(k + 1, cfg.g, cfg.L), cfg.g, zs[j], &us[k][j],
                              NULL, NULL);
        }
        for (k = 0; k < EX_CABLE_NMODES; ++k) svgp_series(&cm, mname[k], EX_HC_PTS, zs, us[k], 0);
        for (i = 0; i < nN; ++i)
            if (Ns[i] == EX_HC_SHAPE_N && Ns[i] <= EX_HC_EIG_MAX)
                for (k = 0; k < EX_CABLE_NMODES; ++k)
                    svgp_series(&cm, nname[k], EX_HC_SHAPE_N + 1, zn, un[k],
                                SVGP_MARKERS | SVGP_NOLINE);
        svgp_xrange(&cm, 0.0, cfg.L);
        snprintf(path, sizeof path, "%s/hanging_cable_modes.svg", dir);
        if (svgp_write_file(&cm, path)) printf("# could not write %s\n", path);
    }
    return rc;
}

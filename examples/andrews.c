/* andrews.c -- Andrews' squeezing mechanism (seven bodies, index 3) with
   HHT-alpha, generalized-alpha and Newmark against the Test Set reference
   solution at t = 0.03 s -- part of vlbe            SPDX-License-Identifier: MIT
   build:  cc -O2 examples/andrews.c -lm           (from any directory)

   The problem, its start, the reference arrays and andr_run() are
   scenes/andrews.h, shared with the tests and benchmarks.

   Output: a table, then one comparison row per line for `make demo`:
     ROW|andrews|<quantity>|<published>|<computed>|<relative error>|<cpu seconds> */
#include "../scenes/andrews.h"

int main(void)
{
    enum { NMETH = 3, NH = 4, NTOL = 3, NROWS = NMETH * NH + 2 + 2 * NTOL };
    static const char *const name[NMETH] = {"HHT-a", "gen-a", "Newmark"};
    static const char *const label[NMETH] = {"HHT-alpha, alpha = -0.05",
                                             "generalized-alpha, rho_inf = 0.8",
                                             "Newmark trapezoidal (beta 1/4, gamma 1/2)"};
    static const long nsteps[NH] = {3000, 6000, 15000, 30000}; /* h = 1e-5 .. 1e-6 */
    static const double tols[NTOL] = {1e-6, 1e-8, 1e-10};
    andr_par p = andr_default();
    vlbe_dae sys;
    vlbe_real q0[ANDR_N], v0[ANDR_N], qdd[ANDR_N], lam[ANDR_M];
    vlbe_real w[512]; /* >= vlbe_dae_work_len(7, 6) = 341 */
    int iw[16], i, im, ih;
    char rows[NROWS][200];
    int nrows = 0;
    vlbe_status rc;
    vlbe_hht_params par;
    andr_result r;

    andr_setup(&sys, &p);
    andr_initial(q0, v0);
    if (vlbe_dae_work_len(ANDR_N, ANDR_M) > sizeof w / sizeof *w) return 1;
    printf("Andrews' squeezing mechanism (Hairer-Wanner II VII.7, Test Set 'andrews'), "
           "index 3, n = 7, m = 6, t in [0, %g] s\n\n",
           ANDR_T_END);
    rc = vlbe_dae_consistent_acc(&sys, VLBE_R(0.0), q0, v0, qdd, lam, NULL, w, sizeof w / sizeof *w,
                                 iw, sizeof iw / sizeof *iw);
    if (rc != VLBE_OK) {
        printf("consistent start failed: %s\n", vlbe_status_str(rc));
        return 1;
    }
    printf("consistent start (vlbe_dae_consistent_acc) vs Test Set:\n");
    for (i = 0; i < 2; ++i)
        printf("  q''_%d   %22.15e  %22.15e  rel %.1e\n", i + 1, (double)qdd[i], andr_qdd0()[i],
               fabs((double)qdd[i] - andr_qdd0()[i]) / fabs(andr_qdd0()[i]));
    for (i = 0; i < 2; ++i)
        printf("  lambda%d %22.15e  %22.15e  rel %.1e\n", i + 1, (double)lam[i], andr_lambda0()[i],
               fabs((double)lam[i] - andr_lambda0()[i]) / fabs(andr_lambda0()[i]));
    printf("\n");

    for (im = 0; im < NMETH; ++im) {
        printf("%s\n", label[im]);
        printf("  %-7s %-18s %-8s %-8s %-8s %-8s %-8s %6s %7s %4s %4s %7s %6s\n", "h [s]",
               "beta(0.03) [rad]", "rel.err", "max rel", "max rel", "lam1 rel", "max|g|", "steps",
               "newton", "jac", "LU", "force", "cpu");
        printf("  %-7s %-18s %-8s %-8s %-8s %-8s %-8s %6s %7s %4s %4s %7s %6s\n", "", "", "beta",
               "q", "q'", "", "[m]", "", "", "", "", "", "[s]");
        for (ih = 0; ih < NH; ++ih) {
            double h = ANDR_T_END / (double)nsteps[ih], ev = 0.0;
            andr_params_for(im, &par);
            if (andr_run(&par, nsteps[ih], &r) != VLBE_OK) {
                printf("  %-7.1e failed: %s after %ld steps\n", h, vlbe_status_str(r.status),
                       r.stats.steps);
                continue;
            }
            for (i = 0; i < ANDR_N; ++i) {
                double e = fabs(r.v[i] - andr_vref()[i]) / fabs(andr_vref()[i]);
                if (e > ev) ev = e;
            }
            printf("  %-7.1e %-18.14f %-8.1e %-8.1e %-8.1e %-8.1e %-8.1e %6ld %7ld %4ld %4ld %7ld "
                   "%6.3f\n",
                   h, r.q[0], r.rel_err[0], r.max_rel_err, ev,
                   fabs(r.lambda[0] - andr_lambda_ref()[0]) / fabs(andr_lambda_ref()[0]), r.max_c,
                   r.stats.steps, r.stats.newton_iters, r.stats.jac_evals, r.stats.lu_factors,
                   r.stats.force_calls, r.cpu);
            if (im < 2 || ih == NH - 1)
                sprintf(rows[nrows++], "ROW|andrews|beta(0.03) %s h=%.0e [rad]|%.16g|%.16g|%.1e|%.3f",
                        name[im], h, andr_qref()[0], r.q[0], r.rel_err[0], r.cpu);
            if (im < 2 && ih == NH - 1)
                sprintf(rows[nrows++], "ROW|andrews|max rel.err of 7 angles %s h=%.0e|-|%.2e|-|%.3f",
                        name[im], h, r.max_rel_err, r.cpu);
        }
        printf("\n");
    }
    printf("rel.err beta: of q1 against the Test Set reference 15.81077119629904; max rel q, q':\n"
           "the largest relative error of the seven angles and angular velocities at 0.03 s;\n"
           "lam1 rel: relative error of lambda_1 (reference 199.175..); max|g|: largest constraint\n"
           "residual over the run.  Newton: rtol 1e-12, atol 1e-14 (the defaults 1e-9 / 1e-11 stop\n"
           "the convergence near 1e-6, the error of 1e5 steps each within the Newton tolerance),\n"
           "modified Newton, analytic Jacobians.  Trapezoidal Newmark: positions converge, but\n"
           "the multipliers oscillate undamped (see lam1 rel).\n\n");

    /* variable-step, variable-order BDF on the GGL index-2 form */
    printf("BDF 1..5, variable step and order (GGL index-2 form), rtol = atol\n");
    printf("  %-7s %-18s %-8s %-8s %-8s %6s %4s %7s %4s %4s %7s %6s\n", "rtol", "beta(0.03) [rad]",
           "rel.err", "max rel", "max|g|", "steps", "rej", "newton", "jac", "LU", "force", "cpu");
    for (i = 0; i < NTOL; ++i) {
        if (andr_run_bdf(tols[i], &r) != VLBE_OK) {
            printf("  %-7.0e failed: %s after %ld steps\n", tols[i], vlbe_status_str(r.status),
                   r.stats.steps);
            continue;
        }
        printf("  %-7.0e %-18.14f %-8.1e %-8.1e %-8.1e %6ld %4ld %7ld %4ld %4ld %7ld %6.3f\n",
               tols[i], r.q[0], r.rel_err[0], r.max_rel_err, r.max_c, r.stats.steps,
               r.stats.rejected, r.stats.newton_iters, r.stats.jac_evals, r.stats.lu_factors,
               r.stats.force_calls, r.cpu);
        sprintf(rows[nrows++], "ROW|andrews|beta(0.03) BDF rtol=%.0e [rad]|%.16g|%.16g|%.1e|%.3f",
                tols[i], andr_qref()[0], r.q[0], r.rel_err[0], r.cpu);
        sprintf(rows[nrows++], "ROW|andrews|max rel.err of 7 angles BDF rtol=%.0e|-|%.2e|-|%.3f",
                tols[i], r.max_rel_err, r.cpu);
    }
    printf("\n");

    /* the same with finite-difference Jacobians: same answer, more force calls */
    andr_setup_fd(&sys, &p);
    andr_params_for(1, &par);
    if (andr_run_sys(&sys, &par, nsteps[NH - 1], &r) == VLBE_OK)
        printf("generalized-alpha, h = %.0e, finite-difference Jacobians: max rel q %.1e, "
               "newton %ld, jac %ld, LU %ld, force %ld, mass %ld, constr %ld, cpu %.3f s\n\n",
               ANDR_T_END / (double)nsteps[NH - 1], r.max_rel_err, r.stats.newton_iters,
               r.stats.jac_evals, r.stats.lu_factors, r.stats.force_calls, r.stats.mass_calls,
               r.stats.constr_calls, r.cpu);
    else
        printf("finite-difference Jacobians: failed: %s\n\n", vlbe_status_str(r.status));

    for (i = 0; i < nrows; ++i) printf("%s\n", rows[i]);
    return 0;
}

/* pendulum.c -- index-3 Cartesian pendulum with Newmark, HHT-alpha, BDF and
   generalized-alpha: period, constraint drift, multipliers -- part of vlbe
                                                   SPDX-License-Identifier: MIT
   build:  cc -O2 examples/pendulum.c -lm          (from any directory)

   The problem, its exact values, the period measurement and pend_run()
   are scenes/pendulum.h, shared with the tests and benchmarks.

   Output: a table, then one comparison row per line for `make demo`:
     ROW|pendulum|<quantity>|<published>|<computed>|<relative error>|<cpu seconds> */
#include "../scenes/pendulum.h"

int main(void)
{
    enum { NMETH = 3, NH = 4, NROWS = NMETH * NH + 3 };
    static const char *const name[NMETH] = {"HHT-a", "gen-a", "Newmark"};
    static const char *const label[NMETH] = {"HHT-alpha, alpha = -0.05",
                                             "generalized-alpha, rho_inf = 0.8",
                                             "Newmark trapezoidal (beta 1/4, gamma 1/2)"};
    static const double hs[NH] = {4e-3, 2e-3, 1e-3, 5e-4};
    const double t_end = 12.0; /* about 5 periods: 5 crossings, 4 full periods */
    double T_agm = pend_period_exact(PEND_L, PEND_G);
    int im, ih;
    char rows[NROWS][160];
    int nrows = 0;

    printf("Index-3 Cartesian pendulum: m = %g kg, L = %g m, g = %g m/s^2, "
           "released at rest from the horizontal, t in [0, %g] s\n",
           PEND_M, PEND_L, PEND_G, t_end);
    printf("exact period: AGM %.15f s, published %.12f s, relative difference %.1e\n", T_agm,
           PEND_T_PUBLISHED, fabs(T_agm - PEND_T_PUBLISHED) / PEND_T_PUBLISHED);
    printf("Newton: rtol = atol = 1e-12 (the multiplier error of an index-3 scheme is about\n"
           "the Newton tolerance / (beta h^2); the defaults 1e-9 would hide its h^2 convergence)\n\n");

    for (im = 0; im < NMETH; ++im) {
        double prev_err = 0.0;
        printf("%s\n", label[im]);
        printf("  %-7s %-15s %-8s %-5s %-8s %-8s %-8s %-8s %-8s %6s %7s %5s %7s\n", "h [s]",
               "period [s]", "rel.err", "ratio", "max|C|", "max|Cqv|", "max|dl|", "dl(t<1)",
               "dl(end)", "steps", "newton", "LU", "cpu [s]");
        for (ih = 0; ih < NH; ++ih) {
            vlbe_hht_params par;
            pend_result r;
            double err;
            if (im == 0) vlbe_hht_params_alpha(&par, VLBE_R(-0.05));
            else if (im == 1) vlbe_hht_params_genalpha(&par, VLBE_R(0.8));
            else vlbe_hht_params_newmark(&par, VLBE_R(0.25), VLBE_R(0.5));
#ifndef VLBE_USE_FLOAT
            par.rtol = par.atol = VLBE_R(1e-12);
#endif
            pend_run(&par, hs[ih], t_end, &r);
            err = fabs(r.period - T_agm) / T_agm;
            printf("  %-7g %-15.12f %-8.2e ", hs[ih], r.period, err);
            if (prev_err > 0.0 && r.status == VLBE_OK) printf("%-5.2f ", prev_err / err);
            else printf("%-5s ", "-");
            printf("%-8.1e %-8.1e %-8.1e %-8.1e ", r.max_c, r.max_cv, r.max_lam_err,
                   r.lam_err_early);
            if (r.status == VLBE_OK) printf("%-8.1e ", r.lam_err_late);
            else printf("%-8s ", "-");
            printf("%6ld %7ld %5ld %7.4f\n", r.stats.steps, r.stats.newton_iters,
                   r.stats.lu_factors, r.cpu);
            if (r.status != VLBE_OK)
                printf("          stopped at t = %.3f s: %s (period from the crossings before)\n",
                       r.t_reached, vlbe_status_str(r.status));
            prev_err = r.status == VLBE_OK ? err : 0.0;
            sprintf(rows[nrows++], "ROW|pendulum|period %s h=%g%s [s]|%.12f|%.12f|%.1e|%.4f",
                    name[im], hs[ih], r.status == VLBE_OK ? "" : " (failed)", PEND_T_PUBLISHED,
                    r.period,
                    fabs(r.period - PEND_T_PUBLISHED) / PEND_T_PUBLISHED, r.cpu);
        }
        printf("\n");
    }
    {
        static const double tols[3] = {1e-6, 1e-8, 1e-10};
        printf("BDF 1..5, variable step and order (GGL index-2 form), atol = rtol / 100\n");
        printf("  %-7s %-15s %-8s %-8s %-8s %-8s %6s %7s %5s %7s\n", "rtol", "period [s]",
               "rel.err", "max|C|", "max|Cqv|", "max|dl|", "steps", "newton", "LU", "cpu [s]");
        for (ih = 0; ih < 3; ++ih) {
            pend_result r;
            pend_run_bdf(tols[ih], t_end, &r);
            printf("  %-7g %-15.12f %-8.2e %-8.1e %-8.1e %-8.1e %6ld %7ld %5ld %7.4f\n", tols[ih],
                   r.period, fabs(r.period - T_agm) / T_agm, r.max_c, r.max_cv, r.max_lam_err,
                   r.stats.steps, r.stats.newton_iters, r.stats.lu_factors, r.cpu);
            if (r.status != VLBE_OK)
                printf("          stopped at t = %.3f s: %s\n", r.t_reached,
                       vlbe_status_str(r.status));
            if (nrows < NROWS)
                sprintf(rows[nrows++], "ROW|pendulum|period BDF rtol=%g%s [s]|%.12f|%.12f|%.1e|%.4f",
                        tols[ih], r.status == VLBE_OK ? "" : " (failed)", PEND_T_PUBLISHED,
                        r.period, fabs(r.period - PEND_T_PUBLISHED) / PEND_T_PUBLISHED, r.cpu);
        }
        printf("\n");
    }
    printf("rel.err: against the AGM period; ratio: error at the previous h over this one "
           "(4 for 2nd order).\n"
           "max|dl|: largest |lambda - (-3 m g y / L^2)| [N/m] over the run, dl(t<1) over t <= 1 s,\n"
           "dl(end) over the last second (3 m g / L = %.2f N/m at the bottom).  Trapezoidal\n"
           "Newmark has no damping of the multiplier mode (eigenvalue -1): its error grows until\n"
           "Newton fails (Cardona & Geradin 1989); HHT and generalized-alpha damp it.\n\n",
           3.0 * PEND_M * PEND_G / PEND_L);
    printf("ROW|pendulum|period AGM [s]|%.12f|%.15f|%.1e|0\n", PEND_T_PUBLISHED, T_agm,
           fabs(T_agm - PEND_T_PUBLISHED) / PEND_T_PUBLISHED);
    for (im = 0; im < nrows; ++im) printf("%s\n", rows[im]);
    return 0;
}

/* spin_up.c -- spin-up of a flexible cantilever on a hub (Simo & Vu-Quoc
   style, issue 7 scenes 1 and 2): the nonlinear co-rotational beam against
   the LINEAR element in the floating hub frame (no centrifugal stiffening),
   for final hub speeds W = 2, 4, 6, 10 rad/s.
   -- part of vlbe                                  SPDX-License-Identifier: MIT

   cc -O2 examples/spin_up.c -lm && ./a.out [outdir]

   L = 10 m, EA = 2.8e7 N, EI = 1.4e4 N m^2, rhoA = 1.2 kg/m, rhoI = 0; hub
   angle theta(t) = (W/Ts)[t^2/2 + (Ts/2pi)^2 (cos(2 pi t/Ts) - 1)] for t <=
   Ts = 15 s, W (t - Ts/2) after; run to 20 s.  8 elements, HHT alpha =
   -0.05, h = 5 ms (convergence in mesh and step printed below).  Model and
   run driver: examples/ex_spin.h.  The linear run stops with VLBE_EBOUND
   when the tip leaves |tip| <= L/10 = 1 m in the hub frame.

   No published table exists for this scene (the literature shows plots):
   the ROW lines carry '-' except for the steady axial tip extension after
   the spin-up, compared with the closed form of a rod under centrifugal
   load, u(L) = rhoA W^2 L^3 / (3 EA) (code_aster validation test
   V3.04.104, reference solution, eq. U_x(x) = rho w^2/(2E) (x L^2 - x^3/3)).
   Output: out/spin_up_w<W>.csv (t, axial and transverse tip of both
   models; the linear columns empty after its stop) and
   out/spin_up_w<W>.svg (transverse tip deflection, both models). */
#include "ex_spin.h"
#include "../bench/svgplot.h"

#include <stdio.h>

#define SP_NHIST 4096

/* tip history, every `every`-th step */
typedef struct sp_hist {
    long k, every;
    int n;
    double t[SP_NHIST], ax[SP_NHIST], tr[SP_NHIST];
} sp_hist;

static inline void sp_hist_obs(void *ctx, const sp_model *m, double t, const double *tip,
                               const vlbe_real *q, const vlbe_real *v)
{
    sp_hist *hh = (sp_hist *)ctx;
    (void)m;
    (void)q;
    (void)v;
    if (hh->k++ % hh->every == 0 && hh->n < SP_NHIST) {
        hh->t[hh->n] = t;
        hh->ax[hh->n] = tip[0];
        hh->tr[hh->n] = tip[1];
        ++hh->n;
    }
}

#ifndef VLBE_EXAMPLE_NO_MAIN

static void print_run(const char *name, const sp_cfg *c, const sp_out *o)
{
    printf("  %-9s %-14s %6.2f  %+.5e %+.5e  %+.5e %+.5e  %.3e %.3e  %6ld %6ld %5ld %7.3f\n", name,
           vlbe_status_str(o->status), o->t_stop, o->tip_Ts[0], o->tip_Ts[1], o->tip_end[0],
           o->tip_end[1], o->tip_max[0], o->tip_max[1], o->stats.steps, o->stats.newton_iters,
           o->stats.lu_factors, o->cpu);
    (void)c;
}

int main(int argc, char **argv)
{
    const char *dir = argc > 1 ? argv[1] : "out";
    static const double Ws[4] = {2.0, 4.0, 6.0, 10.0};
    static sp_model m;
    static sp_hist hist[2];
    int iw, im, ok = 1;
    sp_cfg c;
    sp_cfg_default(&c, 4.0, 0);
    printf("spin-up of a cantilever on a hub: L = %g m, EA = %g N, EI = %g N m^2, rhoA = %g "
           "kg/m, rhoI = 0; Ts = %g s, t_end = %g s\n",
           c.L, c.EA, c.EI, c.rhoA, c.Ts, c.t_end);
    printf("first bending frequency at rest omega_1 = %.4f rad/s; %d elements, h = %g s, HHT "
           "alpha = %g, bound |tip| <= %g m (hub frame)\n",
           sp_omega1(&c), c.ne, c.h, c.alpha, c.bound);
    printf("  %-9s %-14s %6s  %-25s  %-25s  %-19s  %6s %6s %5s %7s\n", "model", "status",
           "t_stop", "tip at Ts: axial, transv. [m]", "tip at end: axial, transv.",
           "max |axial|, |tr.|", "steps", "Newton", "LU", "cpu [s]");
    for (iw = 0; iw < 4; ++iw) {
        const double W = Ws[iw];
        sp_out out[2];
        svgp_chart ch;
        char path[512], title[128], q[160];
        static char names[2][64];
        FILE *csv;
        int k;
        printf("W = %g rad/s (%s omega_1)\n", W, W < sp_omega1(&c) ? "below" : "above");
        for (im = 0; im < 2; ++im) {
            sp_cfg_default(&c, W, im);
            memset(&hist[im], 0, sizeof hist[im]);
            hist[im].every = 10;
            sp_run(&m, &c, sp_hist_obs, &hist[im], &out[im]);
            print_run(im ? "linear" : "nonlinear", &c, &out[im]);
            if (out[im].status != VLBE_OK && !(im == 1 && out[im].status == VLBE_EBOUND)) ok = 0;
        }
        /* CSV: both models on the nonlinear run's time grid */
        snprintf(path, sizeof path, "%s/spin_up_w%g.csv", dir, W);
        csv = svgp_csv_open(path, "t,nonlinear_axial,nonlinear_transverse,linear_axial,"
                                  "linear_transverse");
        if (csv) {
            for (k = 0; k < hist[0].n; ++k) {
                double row[5];
                row[0] = hist[0].t[k];
                row[1] = hist[0].ax[k];
                row[2] = hist[0].tr[k];
                row[3] = k < hist[1].n ? hist[1].ax[k] : (double)NAN;
                row[4] = k < hist[1].n ? hist[1].tr[k] : (double)NAN;
                svgp_csv_row(csv, 5, row);
            }
            fclose(csv);
        }
        snprintf(title, sizeof title, "spin-up W = %g rad/s: transverse tip deflection (hub frame)",
                 W);
        svgp_init(&ch, title, "t [s]", "transverse tip deflection [m]", 0, 0);
        snprintf(names[0], sizeof names[0], "co-rotational (nonlinear)");
        snprintf(names[1], sizeof names[1], "linear, floating frame%s",
                 out[1].status == VLBE_EBOUND ? " (stopped at the bound)" : "");
        svgp_series(&ch, names[0], hist[0].n, hist[0].t, hist[0].tr, 0);
        svgp_series(&ch, names[1], hist[1].n, hist[1].t, hist[1].tr, 0);
        snprintf(path, sizeof path, "%s/spin_up_w%g.svg", dir, W);
        if (svgp_write_file(&ch, path)) printf("could not write %s\n", path);

        /* comparison rows */
        {
            const double uax = c.rhoA * W * W * c.L * c.L * c.L / (3.0 * c.EA);
            snprintf(q, sizeof q, "W=%g: nonlinear axial tip at t=20 s [m] (rod: rhoA W^2 L^3/3EA)",
                     W);
            svgp_compare_row(stdout, "spin-up", q, uax, out[0].tip_end[0],
                             out[0].tip_end[0] / uax - 1.0, out[0].cpu);
            snprintf(q, sizeof q, "W=%g: nonlinear transverse tip at t=15 s [m]", W);
            svgp_compare_row(stdout, "spin-up", q, NAN, out[0].tip_Ts[1], NAN, out[0].cpu);
            snprintf(q, sizeof q, "W=%g: nonlinear transverse tip at t=20 s [m]", W);
            svgp_compare_row(stdout, "spin-up", q, NAN, out[0].tip_end[1], NAN, out[0].cpu);
            snprintf(q, sizeof q, "W=%g: nonlinear max |transverse tip| [m]", W);
            svgp_compare_row(stdout, "spin-up", q, NAN, out[0].tip_max[1], NAN, out[0].cpu);
            if (out[1].status == VLBE_OK) {
                snprintf(q, sizeof q, "W=%g: linear (bounded) max |transverse tip| [m]", W);
                svgp_compare_row(stdout, "spin-up", q, NAN, out[1].tip_max[1], NAN, out[1].cpu);
            } else {
                snprintf(q, sizeof q, "W=%g: linear diverged: |tip| > %g m at t [s]", W, c.bound);
                svgp_compare_row(stdout, "spin-up", q, NAN, out[1].t_stop, NAN, out[1].cpu);
            }
        }
    }

    /* The linear model's divergence is more than a large deflection: with
       the bound at L (10 m, far beyond any linear theory) it still leaves,
       a few seconds after theta' passes omega_1, exponentially. */
    printf("\nlinear model, bound |tip| <= L = 10 m (exponential growth above omega_1):\n");
    for (iw = 0; iw < 4; ++iw) {
        sp_out o;
        double tc = NAN, g[3], t;
        sp_cfg_default(&c, Ws[iw], 1);
        c.bound = c.L;
        for (t = 0.0; t <= c.t_end; t += 1e-3) {
            sp_theta(&c, t, g);
            if (g[1] > sp_omega1(&c)) {
                tc = t;
                break;
            }
        }
        sp_run(&m, &c, NULL, NULL, &o);
        printf("  W = %4g: %-14s at t = %6.3f s; theta' > omega_1 from t = %6.3f s\n", Ws[iw],
               vlbe_status_str(o.status), o.t_stop, tc);
    }

    /* convergence of the nonlinear model in mesh and step against 16
       elements, h = 1.25 ms */
    printf("\nconvergence (nonlinear): |tip - tip_ref| at t = 15 s and 20 s, ref 16 el., h = "
           "1.25 ms\n");
    printf("  %4s %4s %8s  %-11s %-11s %-11s %-11s %7s\n", "W", "ne", "h [s]", "dtr(15)",
           "dtr(20)", "dax(20)", "dmax|tr|", "cpu [s]");
    for (iw = 1; iw < 4; iw += 2) {
        static const int nes[5] = {4, 8, 16, 8, 8};
        static const double hs[5] = {5e-3, 5e-3, 5e-3, 1e-2, 2.5e-3};
        sp_out ref, o;
        sp_cfg_default(&c, Ws[iw], 0);
        c.ne = 16;
        c.h = 1.25e-3;
        sp_run(&m, &c, NULL, NULL, &ref);
        if (ref.status != VLBE_OK) ok = 0;
        for (im = 0; im < 5; ++im) {
            sp_cfg_default(&c, Ws[iw], 0);
            c.ne = nes[im];
            c.h = hs[im];
            sp_run(&m, &c, NULL, NULL, &o);
            if (o.status != VLBE_OK) ok = 0;
            printf("  %4g %4d %8g  %.3e   %.3e   %.3e   %.3e   %7.3f\n", Ws[iw], c.ne, c.h,
                   fabs(o.tip_Ts[1] - ref.tip_Ts[1]), fabs(o.tip_end[1] - ref.tip_end[1]),
                   fabs(o.tip_end[0] - ref.tip_end[0]), fabs(o.tip_max[1] - ref.tip_max[1]),
                   o.cpu);
        }
        printf("  ref W = %g: tip(15) = (%+.6e, %+.6e), tip(20) = (%+.6e, %+.6e), max|tr| = "
               "%.6e; cpu %.3f s\n",
               Ws[iw], ref.tip_Ts[0], ref.tip_Ts[1], ref.tip_end[0], ref.tip_end[1],
               ref.tip_max[1], ref.cpu);
    }
    return ok ? 0 : 1;
}
#endif

/* spin_up.c -- spin-up of a flexible cantilever on a hub (Simo & Vu-Quoc
   style, rotating-beam scenes 1 and 2): the nonlinear co-rotational beam against
   the LINEAR element in the floating hub frame (no centrifugal stiffening),
   for final hub speeds W = 2, 4, 6, 10 rad/s.
   -- part of vlbe                                  SPDX-License-Identifier: MIT

   cc -O2 examples/spin_up.c -lm && ./a.out [outdir]

   The list of models and the comparison of two runs are
   scenes/spin_up.h (shared with the tests).

   L = 10 m, EA = 2.8e7 N, EI = 1.4e4 N m^2, rhoA = 1.2 kg/m, rhoI = 0; hub
   angle theta(t) = (W/Ts)[t^2/2 + (Ts/2pi)^2 (cos(2 pi t/Ts) - 1)] for t <=
   Ts = 15 s, W (t - Ts/2) after; run to 20 s.  8 elements, HHT alpha =
   -0.05, h = 5 ms (convergence in mesh and step printed below).  Model and
   run driver: scenes/ex_spin.h.  The linear run stops with VLBE_EBOUND
   when the tip leaves |tip| <= L/10 = 1 m in the hub frame.

   No published table exists for this scene (the literature shows plots):
   the ROW lines carry '-' except for the steady axial tip extension after
   the spin-up, compared with the closed form of a rod under centrifugal
   load, u(L) = rhoA W^2 L^3 / (3 EA) (code_aster validation test
   V3.04.104, reference solution, eq. U_x(x) = rho w^2/(2E) (x L^2 - x^3/3)).
   Output: out/spin_up_w<W>.csv (t, axial and transverse tip of both
   models; the linear columns empty after its stop) and
   out/spin_up_w<W>.svg (transverse tip deflection, both models). */
#include "../scenes/spin_up.h"
#include "../scenes/svgplot.h"

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
    static sp_hist hist[SP_NMODEL];
    int iw, im, k, ok = 1;
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
        sp_out out[SP_NMODEL];
        svgp_chart ch;
        char path[512], title[128], q[160];
        static char names[SP_NMODEL][64];
        FILE *csv;
        int ax;
        printf("W = %g rad/s (%s omega_1)\n", W, W < sp_omega1(&c) ? "below" : "above");
        for (im = 0; im < SP_NMODEL; ++im) {
            sp_cfg_default(&c, W, sp_models[im]);
            memset(&hist[im], 0, sizeof hist[im]);
            hist[im].every = 10;
            sp_run(&m, &c, sp_hist_obs, &hist[im], &out[im]);
            print_run(sp_model_name[im], &c, &out[im]);
            if (out[im].status != VLBE_OK &&
                !(sp_models[im] == SP_LINEAR && out[im].status == VLBE_EBOUND))
                ok = 0;
        }
        /* CSV: every model on the first run's time grid (all share h) */
        snprintf(path, sizeof path, "%s/spin_up_w%g.csv", dir, W);
        csv = svgp_csv_open(path, "t,cr_axial,cr_transverse,linear_axial,linear_transverse,"
                                  "ancf_axial,ancf_transverse");
        if (csv) {
            for (k = 0; k < hist[0].n; ++k) {
                double row[1 + 2 * SP_NMODEL];
                row[0] = hist[0].t[k];
                for (im = 0; im < SP_NMODEL; ++im) {
                    row[1 + 2 * im] = k < hist[im].n ? hist[im].ax[k] : (double)NAN;
                    row[2 + 2 * im] = k < hist[im].n ? hist[im].tr[k] : (double)NAN;
                }
                svgp_csv_row(csv, 1 + 2 * SP_NMODEL, row);
            }
            fclose(csv);
        }
        /* charts: transverse and axial tip deflection, all models */
        for (ax = 0; ax < 2; ++ax) {
            snprintf(title, sizeof title, "spin-up W = %g rad/s: %s tip deflection (hub frame)", W,
                     ax ? "axial" : "transverse");
            svgp_init(&ch, title, "t [s]", ax ? "axial tip deflection [m]"
                                              : "transverse tip deflection [m]", 0, 0);
            for (im = 0; im < SP_NMODEL; ++im) {
                snprintf(names[im], sizeof names[im], "%s%s", sp_model_label[im],
                         out[im].status == VLBE_EBOUND ? " (stopped at the bound)" : "");
                svgp_series(&ch, names[im], hist[im].n, hist[im].t, ax ? hist[im].ax : hist[im].tr,
                            0);
            }
            snprintf(path, sizeof path, "%s/spin_up_w%g%s.svg", dir, W, ax ? "_axial" : "");
            if (svgp_write_file(&ch, path)) printf("could not write %s\n", path);
        }

        /* comparison rows: the nonlinear models against the rod's axial
           extension and against each other */
        {
            const double uax = c.rhoA * W * W * c.L * c.L * c.L / (3.0 * c.EA);
            const sp_out *cr = &out[0], *lin = &out[1], *an = &out[2];
            for (im = 0; im < SP_NMODEL; im += 2) {
                snprintf(q, sizeof q, "W=%g: %s axial tip at t=20 s [m] (rod: rhoA W^2 L^3/3EA)", W,
                         sp_model_name[im]);
                svgp_compare_row(stdout, "spin-up", q, uax, out[im].tip_end[0],
                                 out[im].tip_end[0] / uax - 1.0, out[im].cpu);
            }
            snprintf(q, sizeof q, "W=%g: CR transverse tip at t=15 s [m]", W);
            svgp_compare_row(stdout, "spin-up", q, NAN, cr->tip_Ts[1], NAN, cr->cpu);
            snprintf(q, sizeof q, "W=%g: max abs. transverse tip [m], ANCF vs CR", W);
            svgp_compare_row(stdout, "spin-up", q, cr->tip_max[1], an->tip_max[1],
                             an->tip_max[1] / cr->tip_max[1] - 1.0, an->cpu);
            snprintf(q, sizeof q, "W=%g: max_t abs(ANCF - CR) / max abs. tr (0.5 s samples)", W);
            svgp_compare_row(stdout, "spin-up", q, NAN, sp_sample_diff(an, cr) / cr->tip_max[1],
                             NAN, an->cpu);
            if (lin->status == VLBE_OK) {
                snprintf(q, sizeof q, "W=%g: linear (bounded) max abs. transverse tip [m]", W);
                svgp_compare_row(stdout, "spin-up", q, NAN, lin->tip_max[1], NAN, lin->cpu);
            } else {
                snprintf(q, sizeof q, "W=%g: linear diverged: abs(tip) > %g m at t [s]", W, c.bound);
                svgp_compare_row(stdout, "spin-up", q, NAN, lin->t_stop, NAN, lin->cpu);
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

    /* convergence of the nonlinear models in mesh and step, each against
       its own run at 32 elements, h = 0.625 ms; then the two limits
       against each other.  They are different continua at the level of
       the axial strain eps_max = rhoA W^2 L^2 / (2 EA) (ANCF: Green strain
       and curvature per deformed length; CR: engineering strain and
       rotation gradient per reference length), so they agree to O(eps_max),
       not to round-off. */
    printf("\nconvergence (nonlinear models): max over the 0.5 s samples of |tip - tip_ref| / "
           "max |tr_ref|, ref = the same model at 32 elements, h = 0.625 ms\n");
    printf("  %4s %-5s %4s %9s  %-10s %-10s %7s\n", "W", "model", "ne", "h [s]", "transverse",
           "axial", "cpu [s]");
    for (iw = 2; iw < 4; ++iw) {
        static const int nes[5] = {8, 16, 32, 16, 16};
        static const double hs[5] = {1.25e-3, 1.25e-3, 1.25e-3, 5e-3, 2.5e-3};
        static sp_out ref[2];
        const double eps = c.rhoA * Ws[iw] * Ws[iw] * c.L * c.L / (2.0 * c.EA);
        for (im = 0; im < 2; ++im) {
            const int model = im ? SP_ANCF : SP_CR;
            sp_out o;
            sp_cfg_default(&c, Ws[iw], model);
            c.ne = 32;
            c.h = 6.25e-4;
            sp_run(&m, &c, NULL, NULL, &ref[im]);
            if (ref[im].status != VLBE_OK) ok = 0;
            for (k = 0; k < 5; ++k) {
                double dt = 0.0, da = 0.0;
                int j;
                sp_cfg_default(&c, Ws[iw], model);
                c.ne = nes[k];
                c.h = hs[k];
                sp_run(&m, &c, NULL, NULL, &o);
                if (o.status != VLBE_OK) ok = 0;
                for (j = 0; j < SP_NS; ++j) {
                    dt = fmax(dt, fabs(o.tip_s[j][1] - ref[im].tip_s[j][1]));
                    da = fmax(da, fabs(o.tip_s[j][0] - ref[im].tip_s[j][0]));
                }
                printf("  %4g %-5s %4d %9g  %.3e  %.3e  %7.3f\n", Ws[iw], im ? "ANCF" : "CR", c.ne,
                       c.h, dt / ref[im].tip_max[1], da / ref[im].tip_max[1], o.cpu);
            }
        }
        {
            const double d = sp_sample_diff(&ref[1], &ref[0]) / ref[0].tip_max[1];
            char q[160];
            printf("  W = %g: refs max|tr| CR %.6e, ANCF %.6e; ANCF - CR (32 el.): %.3e of max|tr| "
                   "= %.2f eps_max (eps_max = %.2e)\n",
                   Ws[iw], ref[0].tip_max[1], ref[1].tip_max[1], d, d / eps, eps);
            snprintf(q, sizeof q, "W=%g: max_t abs(ANCF - CR) / max abs. tr at 32 el. (eps_max %.1e)",
                     Ws[iw], eps);
            svgp_compare_row(stdout, "spin-up", q, NAN, d, NAN, ref[1].cpu);
        }
    }
    return ok ? 0 : 1;
}

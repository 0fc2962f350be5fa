/* spin_damping.c -- spin-up of a flexible cantilever on a hub (rotating-beam
   scene 3): internal damping computed from the deformation (Kelvin-Voigt on
   the strain rates, frame invariant) against damping on the absolute nodal
   velocities, Q_d = -(abs_a M + abs_b K0) v, for final hub speeds W = 2, 6,
   10 rad/s.  The planar ANCF beam of ancf_ale.h (SP_ANCF of ex_spin.h).
   -- part of vlbe                                  SPDX-License-Identifier: MIT

   cc -O2 examples/spin_damping.c -lm && ./a.out [outdir]

   The damping models, the runs and the references are
   scenes/spin_damping.h (shared with tests/test_spin_damping.c); this file
   prints the tables, rows and charts.

   Scene of spin_up.c: L = 10 m, EA = 2.8e7 N, EI = 1.4e4 N m^2, rhoA = 1.2
   kg/m; hub speed rising smoothly from 0 to W in Ts = 15 s, run to 20 s; 8
   elements, HHT alpha = -0.05, h = 5 ms.  Four damping models, all tuned
   to damp the first bending mode of the beam at rest by zeta = 2 %
   (omega_1 = 3.80 rad/s):
     undamped
     Kelvin-Voigt   c_kv = 2 zeta / omega_1 on axial strain and curvature
     abs. K0        abs_b = the same c: -c K0 v, K0 the stiffness of the
                    straight beam at rest (at rest the same damping matrix
                    as Kelvin-Voigt)
     abs. M         abs_a = 2 zeta omega_1: -abs_a M v
   Kelvin-Voigt damping sees strain rates only: a rigid rotation costs no
   power, and after the spin-up the beam settles to the undamped steady
   state (transverse tip 0 in the hub frame).  Absolute damping also brakes
   the rigid rotation:
     abs. M   at the steady speed W a point at radius x moves at W x, so the
              beam carries the drag q(x) = -abs_a rhoA W x per length
              (against the rotation), a steady load in the hub frame that
              the hub torque balances: a steady lag of the tip.  Reference:
              the static equilibrium of the beam in the hub frame under the
              drag and the centrifugal load rhoA W^2 r (both on the deformed
              beam), an extensible elastica solved by shooting below (no
              element in it).  Without centrifugal stiffening the linear
              cantilever under the triangular load q0 x / L, q0 = -abs_a
              rhoA W L, deflects by 11 q0 L^4 / (120 EI): the bound printed
              beside it (the tension rhoA W^2 (L^2 - x^2)/2 stiffens the
              beam and the spinning beam deflects less).
     abs. K0  K0 is fixed in space: a beam turned by theta moving rigidly
              at W has the axial (x) velocity -W x sin(theta), a strain
              rate of -W sin(theta) in K0's eyes: it dissipates abs_b EA L
              W^2 sin^2(theta) (tests/test_spin_damping.c), a braking
              torque abs_b EA L W sin^2(theta) on a rigid beam, 7e4 N m at
              theta = 0.29 rad, W = 0.3 rad/s, against a bending strength
              of 3 EI/L^2 = 420 N m per metre of tip deflection.  The beam
              is held back and folds long before the spin-up ends, at every
              W: the run stops when the tip leaves |tip| <= SD_BOUND in the
              hub frame, at a hub angle of about 0.29 rad whatever W (with
              the bound off the tip ends up behind the hub, up to 19 m from
              its place).
   Bound SD_BOUND = 2 m (L/5) instead of spin_up's L/10: the abs. M lag at
   W = 10 peaks at 1.25 m during the spin-up.

   No published numbers: the ROW lines compare the abs. M steady tip (axial
   and transverse) with the elastica reference and show the Kelvin-Voigt
   steady tip against 0.
   "Steady" is the mean over [Ts, t_end] (the residual vibration that the
   spin-up leaves, about 1e-3 m, averages out); the tip at t = 20 s and
   the residual amplitude (half the peak-to-peak over the window) are
   printed too, and the abs. M steady tip's convergence in mesh and step.
   Output: <outdir>/spin_damping_w<W>.csv (t, axial and transverse tip of
   each model, nan after a stop) and <outdir>/spin_damping_w<W>.svg
   (transverse tip, all models, and the abs. M reference). */
#include "../scenes/spin_damping.h"
#include "../scenes/svgplot.h"

static void print_run(int kind, const sp_out *o, const sd_rec *r)
{
    printf("  %-12s %-14s %6.2f  %+.4e %+.4e  %+.4e %.2e  %.3e  %6ld %6ld %7.3f\n",
           sd_kind_name(kind), vlbe_status_str(o->status), o->t_stop, o->tip_end[0],
           o->tip_end[1], sd_rec_mean(r), sd_rec_amp(r), o->tip_max[1], o->stats.steps,
           o->stats.newton_iters, o->cpu);
}

/* one ROW line "W=<W>: what"; the relative error where the reference is
   a nonzero number */
static void row(double W, const char *what, double ref, double ours, const sp_out *o)
{
    char q[192];
    snprintf(q, sizeof q, "W=%g: %s", W, what);
    svgp_compare_row(stdout, "spin damping", q, ref, ours,
                     isnan(ref) || ref == 0.0 ? (double)NAN : ours / ref - 1.0, o->cpu);
}

static void write_scene(const char *dir, double W, const sd_rec *rec, const sp_out *out,
                        double ref_tr, double t_end)
{
    static char names[SD_NKIND][96];
    static const char *const cols[SD_NKIND] = {"undamped", "kelvin_voigt", "abs_K0", "abs_M"};
    char path[512], title[160], head[512];
    double rx[2], ry[2];
    svgp_chart ch;
    FILE *csv;
    int k, j, len = 0;
    len += snprintf(head + len, sizeof head - (size_t)len, "t");
    for (j = 0; j < SD_NKIND; ++j)
        len += snprintf(head + len, sizeof head - (size_t)len, ",%s_axial,%s_transverse", cols[j],
                        cols[j]);
    /* the undamped run reaches t_end: its time grid is every run's */
    snprintf(path, sizeof path, "%s/spin_damping_w%g.csv", dir, W);
    csv = svgp_csv_open(path, head);
    if (csv) {
        for (k = 0; k < rec[0].h.n; ++k) {
            double row[1 + 2 * SD_NKIND];
            row[0] = rec[0].h.t[k];
            for (j = 0; j < SD_NKIND; ++j) {
                row[1 + 2 * j] = k < rec[j].h.n ? rec[j].h.ax[k] : (double)NAN;
                row[2 + 2 * j] = k < rec[j].h.n ? rec[j].h.tr[k] : (double)NAN;
            }
            svgp_csv_row(csv, 1 + 2 * SD_NKIND, row);
        }
        fclose(csv);
    } else
        printf("could not write %s\n", path);
    snprintf(title, sizeof title,
             "spin-up W = %g rad/s, damping 2%% of mode 1 at rest: transverse tip (hub frame)", W);
    svgp_init(&ch, title, "t [s]", "transverse tip deflection [m]", 0, 0);
    svgp_xrange(&ch, 0.0, t_end);
    ch.legend = SVGP_LEGEND_BR; /* below the steady tips, right of the abs. K0 stop */
    for (j = 0; j < SD_NKIND; ++j) {
        if (out[j].status == VLBE_EBOUND)
            snprintf(names[j], sizeof names[j], "%s (|tip| > %g m at t = %.2f s)",
                     sd_kind_name(j), SD_BOUND, out[j].t_stop);
        else
            snprintf(names[j], sizeof names[j], "%s", sd_kind_name(j));
        svgp_series(&ch, names[j], rec[j].h.n, rec[j].h.t, rec[j].h.tr, 0);
    }
    rx[0] = rec[0].t0;
    rx[1] = t_end;
    ry[0] = ry[1] = ref_tr;
    svgp_series(&ch, "abs. M: static reference (elastica)", 2, rx, ry, SVGP_DASH);
    snprintf(path, sizeof path, "%s/spin_damping_w%g.svg", dir, W);
    if (svgp_write_file(&ch, path)) printf("could not write %s\n", path);
}

int main(int argc, char **argv)
{
    const char *dir = argc > 1 ? argv[1] : "out";
    static const double Ws[3] = {2.0, 6.0, 10.0};
    static sp_model m;
    static sd_rec rec[SD_NKIND];
    int iw, k, ok = 1;
    sp_cfg c;
    sd_cfg(&c, 2.0, SD_UNDAMPED);
    printf("spin-up of a cantilever on a hub with internal damping: L = %g m, EA = %g N, EI = "
           "%g N m^2, rhoA = %g kg/m; Ts = %g s, t_end = %g s\n",
           c.L, c.EA, c.EI, c.rhoA, c.Ts, c.t_end);
    printf("ANCF, %d elements, h = %g s, HHT alpha = %g, bound |tip| <= %g m (hub frame); "
           "omega_1 = %.4f rad/s, zeta = %g at rest:\n",
           c.ne, c.h, c.alpha, SD_BOUND, sp_omega1(&c), SD_ZETA);
    printf("  c_kv = abs_b = 2 zeta/omega_1 = %.5f s, abs_a = 2 zeta omega_1 = %.5f 1/s\n",
           2.0 * SD_ZETA / sp_omega1(&c), 2.0 * SD_ZETA * sp_omega1(&c));
    printf("  steady = mean transverse tip over [Ts, t_end], amp = half its peak-to-peak there\n");
    printf("  %-12s %-14s %6s  %-23s  %-21s  %-9s  %6s %6s %7s\n", "damping", "status", "t_stop",
           "tip at end: ax., tr. [m]", "steady tr., amp [m]", "max|tr|", "steps", "Newton",
           "cpu [s]");
    for (iw = 0; iw < 3; ++iw) {
        const double W = Ws[iw];
        sp_out out[SD_NKIND];
        sd_ref rb;
        double ref[2] = {NAN, NAN}, lin, g[3], aa;
        printf("W = %g rad/s\n", W);
        for (k = 0; k < SD_NKIND; ++k) {
            sd_run(&m, W, k, 10, &rec[k], &out[k]);
            print_run(k, &out[k], &rec[k]);
            if (out[k].status != VLBE_OK && !(k == SD_ABS_K && out[k].status == VLBE_EBOUND))
                ok = 0;
        }
        sd_cfg(&c, W, SD_ABS_M);
        aa = c.abs_a;
        sd_ref_set(&rb, &c, W, aa);
        if (sd_ref_tip(&rb, SD_NS_REF, ref)) {
            printf("  reference: shooting did not converge\n");
            ok = 0;
        }
        lin = sd_lin_tip(&c, W, aa);
        printf("  abs. M reference (elastica, drag + centrifugal): tip (%+.5e, %+.5e) m; "
               "|steady tr. - ref| = %.2e m (%.3f%% of |ref|); no stiffening 11 q0 L^4/(120 "
               "EI) = %+.4f m\n",
               ref[0], ref[1], fabs(sd_rec_mean(&rec[SD_ABS_M]) - ref[1]),
               100.0 * fabs(sd_rec_mean(&rec[SD_ABS_M]) / ref[1] - 1.0), lin);
        sp_theta(&c, out[SD_ABS_K].t_stop, g);
        printf("  abs. K0 left the bound at t = %.3f s: hub angle %.3f rad, speed %.3f rad/s\n",
               out[SD_ABS_K].t_stop, g[0], g[1]);
        write_scene(dir, W, rec, out, ref[1], c.t_end);

        row(W, "abs. M steady transverse tip [m] (static elastica)", ref[1],
            sd_rec_mean(&rec[SD_ABS_M]), &out[SD_ABS_M]);
        row(W, "abs. M steady axial tip [m] (static elastica)", ref[0],
            sd_rec_mean_ax(&rec[SD_ABS_M]), &out[SD_ABS_M]);
        row(W, "abs. M max abs. transverse tip [m]", NAN, out[SD_ABS_M].tip_max[1],
            &out[SD_ABS_M]);
        row(W, "Kelvin-Voigt steady transverse tip [m] (0)", 0.0, sd_rec_mean(&rec[SD_KV]),
            &out[SD_KV]);
        row(W, "Kelvin-Voigt transverse tip at t=20 s [m]", NAN, out[SD_KV].tip_end[1],
            &out[SD_KV]);
        row(W, "Kelvin-Voigt max abs. transverse tip [m]", NAN, out[SD_KV].tip_max[1],
            &out[SD_KV]);
        row(W, "undamped steady transverse tip [m] (0)", 0.0, sd_rec_mean(&rec[SD_UNDAMPED]),
            &out[SD_UNDAMPED]);
        row(W, "abs. K0: tip leaves the bound (2 m) at t [s]", NAN, out[SD_ABS_K].t_stop,
            &out[SD_ABS_K]);
    }

    /* the abs. M steady tip in mesh and step (the error budget of
       tests/test_spin_damping.c) */
    printf("\nconvergence (abs. M): steady transverse and axial tip against the elastica\n");
    printf("  %4s %4s %8s  %-13s %-10s  %-13s %-10s  %7s\n", "W", "ne", "h [s]", "steady tr.",
           "rel. err", "steady ax.", "rel. err", "cpu [s]");
    for (iw = 1; iw < 3; ++iw) {
        static const int nes[4] = {4, 8, 16, 8};
        static const double hs[4] = {5e-3, 5e-3, 5e-3, 2.5e-3};
        sd_ref rb;
        double ref[2];
        sd_cfg(&c, Ws[iw], SD_ABS_M);
        sd_ref_set(&rb, &c, Ws[iw], c.abs_a);
        if (sd_ref_tip(&rb, SD_NS_REF, ref)) ok = 0;
        for (k = 0; k < 4; ++k) {
            sp_out o;
            sd_cfg(&c, Ws[iw], SD_ABS_M);
            c.ne = nes[k];
            c.h = hs[k];
            sd_rec_init(&rec[0], 1000000, c.Ts);
            sp_run(&m, &c, sd_rec_obs, &rec[0], &o);
            if (o.status != VLBE_OK) ok = 0;
            printf("  %4g %4d %8g  %+.6e %+.2e  %+.6e %+.2e  %7.3f\n", Ws[iw], c.ne, c.h,
                   sd_rec_mean(&rec[0]), sd_rec_mean(&rec[0]) / ref[1] - 1.0,
                   sd_rec_mean_ax(&rec[0]), sd_rec_mean_ax(&rec[0]) / ref[0] - 1.0, o.cpu);
        }
    }
    return ok ? 0 : 1;
}

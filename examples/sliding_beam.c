/* sliding_beam.c -- a beam sliding through a prismatic joint (Hsiao et al.,
   section 3, cases (a) and (b)), planar co-rotational elements of
   corot2d.h with the transition element at the joint.
   -- part of vlbe                                  SPDX-License-Identifier: MIT

   cc -O2 examples/sliding_beam.c -lm && ./a.out [outdir]

   The observer of the runs is scenes/sliding_beam.h (shared with
   tests/test_scenes_sliding.c and bench/bench_cr2d.c).

   Section A = 4.3434e-5 m^2, I = 1.059e-11 m^4, E = 68.96 GPa, rho =
   3144.3858 kg/m^3; 14 elements inside the joint and 10 outside at t = 0;
   dt = 1 ms, HHT alpha = -0.05 (the trapezoidal Newmark the paper names
   leaves the index-3 multiplier modes of the joint undamped and gets
   through only by sb_run's step halvings, at 8-27 times the CPU: see
   bench/wp_sliding.c); modal damping of eq. (56).
   (a) L = 0.762 m, L0 = 0.521 m, U_A = v0 t + a0 t^2/2, v0 = -0.03 m/s,
       a0 = -0.054 m/s^2 (retraction), 0 <= t <= 2.5 s;
   (b) L = 1.05 m, L0 = 0.35 m, the smooth deployment of eq. (55), c0 =
       0.7 m, t0 = 1.2 s, 0 <= t <= 3 s.
   At t = 0 the tip is deflected by 0.024 m by a static lateral tip force
   (removed at t = 0).  The model and its bookkeeping: scenes/ex_sbeam.h.

   The paper gives its results as plots only (Figs. 4, 5): the rows report
   what the plots show in numbers -- the periods of the tip oscillation
   between successive upward zero crossings, each against the first
   cantilever period 2 pi / omega_1(L_f) of the free length at the middle
   of that period (the quasi-static estimate a slowly sliding beam should
   follow), and the amplitudes. Output: out/sliding_beam_{a,b}.csv (t, tip
   x, tip y, free length, energy) and out/sliding_beam_tip.svg. */
#include "../scenes/sliding_beam.h"

int main(int argc, char **argv)
{
    const char *dir = argc > 1 ? argv[1] : "out";
    static const char cases[2] = {'a', 'b'};
    static double ts[2][4000], ys[2][4000];
    static sb_model m;
    svgp_chart ch;
    int ic, ok = 1;
    svgp_init(&ch, "sliding beam: tip deflection (Hsiao et al. cases a, b)", "t [s]",
              "tip deflection [m]", 0, 0);
    for (ic = 0; ic < 2; ++ic) {
        sb_cfg c;
        sb_obs o;
        sb_out out;
        char path[512], q[128];
        int k;
        sb_cfg_paper(&c, cases[ic]);
        memset(&o, 0, sizeof o);
        o.t = ts[ic];
        o.y = ys[ic];
        o.cap = 4000;
        snprintf(path, sizeof path, "%s/sliding_beam_%c.csv", dir, cases[ic]);
        o.csv = svgp_csv_open(path, "t,tip_x,tip_y,free_length,T,U");
        sb_run(&m, &c, sb_observe, &o, &out);
        if (o.csv) fclose(o.csv);
        printf("case (%c): L = %g m, L0 = %g m, %d + %d elements, h = %g s, HHT alpha %g\n",
               cases[ic], c.L, c.L0, c.n_in, c.n_out, c.h, c.alpha);
        if (out.status != VLBE_OK) {
            printf("  run failed: %s at t = %g (callback %d, element %d: %s)\n",
                   vlbe_status_str(out.status), o.tlast, out.stats.callback_rc, m.beam.err_elem,
                   vlbe_status_str(m.beam.err));
            ok = 0;
            continue;
        }
        printf("  static tip force %.6g N; %ld steps, %ld Newton, %ld LU, %d restarts "
               "(node crossings), largest projection at an entry %.2e m; cpu %.3f s\n",
               out.F0, out.stats.steps, out.stats.newton_iters, out.stats.lu_factors,
               out.restarts, m.proj_max, out.cpu);
        printf("  %-10s %-10s %-12s %-12s %-10s %-10s\n", "t_mid [s]", "L_f [m]", "period [s]",
               "2pi/w1 [s]", "ratio", "amp [m]");
        for (k = 1; k < o.ncross; ++k) {
            const double tm = 0.5 * (o.tcross[k] + o.tcross[k - 1]);
            const double T = o.tcross[k] - o.tcross[k - 1];
            double g[3], Lf, Tq;
            sb_ua(&c, tm, g);
            Lf = c.L0 + g[0];
            Tq = 2.0 * 3.14159265358979323846 / sb_omega(&c, 0, Lf);
            printf("  %-10.4f %-10.4f %-12.5f %-12.5f %-10.4f %-10.5f\n", tm, Lf, T, Tq, T / Tq,
                   o.amp[k]);
            if (k == 1 || k == o.ncross - 1) {
                snprintf(q, sizeof q, "case %c: period/cantilever period at t=%.2f s", cases[ic],
                         tm);
                svgp_compare_row(stdout, "sliding beam", q, 1.0, T / Tq, T / Tq - 1.0, out.cpu);
            }
        }
        snprintf(q, sizeof q, "case %c: wall time to t=%.1f s [s]", cases[ic], c.t_end);
        svgp_compare_row(stdout, "sliding beam", q, NAN, out.cpu, NAN, out.cpu);
        svgp_series(&ch, cases[ic] == 'a' ? "case (a): retraction" : "case (b): deployment",
                    (int)o.n, o.t, o.y, 0);
    }
    {
        char path[512];
        snprintf(path, sizeof path, "%s/sliding_beam_tip.svg", dir);
        if (svgp_write_file(&ch, path)) printf("could not write %s\n", path);
    }
    return ok ? 0 : 1;
}

/* winch.c -- a winch paying out a rope with a 10 kg end mass: the chain grows
   element by element at the winch (an ALE element with a prescribed
   material coordinate, split at 1.5 Lstd), the end mass follows the steady
   rope.                                            -- part of vlbe
                                                   SPDX-License-Identifier: MIT

   cc -O2 -I. examples/winch.c -lm && ./a.out [outdir [t_end [Lstd]]]

   The model, the run and the facts it is checked against are in
   scenes/ex_winch.h (shared with tests/test_scenes_cable.c): 10 m of rope
   (rhoA = 1 kg/m, EA = 1e6 N, no bending) hanging from the winch with a
   10 kg end mass, elements of Lstd = 0.5 m, paid out at V = 0.9 m/s,
   HHT-alpha -0.05 at h = 2 ms.  Here elements of Lstd = 0.1 m on the
   banded path (cfg.banded: O(N) per step) and t_end = 20 s: 18 m paid
   out, 100 -> 280 elements; t_end and Lstd are parameters.

   Printed: a table every t_end / 10 (elements against ne(l), end position
   against the steady rope, the stretch, the energy balance), the largest
   deviations over the run, and the same run started from the static rope
   (the end then oscillates about the steady state by the dynamic stretch
   rhoA V^2 / EA times the stretch, which the steady start removes).  Rows
   ROW|winch|...; out/winch_stretch.svg (the stretch of the rope, model and
   steady rope, against time) and out/winch_elements.svg (the elements
   against the paid-out length, model and ne(l)). */
#include "../scenes/ex_winch.h"

#include <stdio.h>
#include <stdlib.h>

#include "../scenes/svgplot.h"

int main(int argc, char **argv)
{
    const char *dir = argc > 1 ? argv[1] : "out";
    ex_winch_cfg c, cs;
    ex_winch_hist hi;
    ex_winch_out r, rs;
    svgp_chart ch1, ch2;
    char path[512], qty[200];
    double *d, *s_mod, *s_qs, *s_lin, mach2;
    int j, step, rc = 0;
    ex_winch_cfg_default(&c, argc > 2 ? atof(argv[2]) : 20.0);
    c.Lstd = argc > 3 ? atof(argv[3]) : 0.1;
    c.banded = 1; /* O(N) per step: hundreds of elements */
    ex_winch_cfg_capacity(&c);
    if (!(c.t_end > 0.0) || !(c.Lstd > 0.0)) return 1;
    if (ex_winch_hist_alloc(&hi, (int)(c.t_end / c.h) + 8)) return 1;
    printf("# winch: %g m of rope (rhoA %g kg/m, EA %g N, no bending) with a %g kg end mass, "
           "paid out at %g m/s for %g s; elements of %g m, the winch element split at 1.5 Lstd; "
           "HHT-alpha %g, h = %g s, %s storage\n", c.L0, c.rhoA, c.EA, c.mass, c.V, c.t_end,
           c.Lstd, c.alpha, c.h, c.banded ? "banded" : "dense");
    printf("# steady rope: tension = weight below under g_eff = g (1 - rhoA V^2 / EA) = %.9g "
           "m/s^2, every point at -lam(p0(t)) V\n", ex_winch_geff(&c));
    r = ex_winch_run(&c, &hi);
    if (r.status != VLBE_OK) rc = 1;
    printf("# %s at t = %.4f s; %ld steps, %ld Newton iterations, %ld LU, %d splits (%d -> %d "
           "elements); cpu %.3f s (splits and restarts %.3f s)\n", vlbe_status_str(r.status),
           r.t_stop, r.steps, r.newton, r.lu, r.splits, r.ne0, r.ne_end, r.cpu, r.cpu_split);
    printf("#\n# %7s | %8s | %9s | %13s | %13s | %10s | %11s | %10s | %10s\n", "t [s]",
           "paid [m]", "elements", "y end [m]", "steady [m]", "dy [m]", "stretch mm",
           "dv [m/s]", "dE / W");
    step = hi.n > 10 ? (hi.n - 1) / 10 : 1;
    for (j = 0; j < hi.n; j += step) {
        const double len = c.L0 + c.V * hi.t[j];
        printf("# %7.3f | %8.4f | %4.0f/%-4.0f | %13.9f | %13.9f | %+10.2e | %11.6f | %+10.2e | "
               "%+10.2e\n", hi.t[j], c.V * hi.t[j], hi.ne[j], hi.ne_pred[j], hi.y[j], hi.y_qs[j],
               hi.y[j] - hi.y_qs[j], -1e3 * (hi.y[j] + len), hi.v[j] - hi.v_qs[j],
               r.W_abs > 0.0 ? hi.dE[j] / r.W_abs : 0.0);
    }
    printf("# largest over the run: |y - y_qs| = %.3e m (the dynamic stretch (rhoA V^2 / EA) s at "
           "the end %.3e m), |v - v_qs| = %.3e m/s, |E - E0 - W| = %.3e J of int |P| dt = %.4g J, "
           "|mass - (m + rhoA l)| = %.3e kg; element count off ne(l) in %d steps (outside a "
           "split's step)\n", r.dy_max, c.rhoA * c.V * c.V / c.EA * -r.stretch_end, r.dv_max,
           r.dE_max, r.W_abs, r.dm_max, r.ne_bad);
    mach2 = c.rhoA * c.V * c.V / c.EA;
    cs = c;
    cs.steady = 0;
    rs = ex_winch_run(&cs, NULL);
    printf("# started from the static rope instead: |y - y_qs| = %.3e m, |v - v_qs| = %.3e m/s "
           "(%s): the axial mode the start excites, about the steady state by the dynamic "
           "stretch of the start, (rhoA V^2 / EA) s(0) = %.3e m\n", rs.dy_max, rs.dv_max,
           vlbe_status_str(rs.status), mach2 * -(hi.y_qs[0] + c.L0));
    {
        const double len = c.L0 + c.V * r.t_stop;
        const double lin = ex_winch_geff(&c) / c.EA * (c.mass * len + 0.5 * c.rhoA * len * len);
        const double yqs = hi.n > 0 ? hi.y_qs[hi.n - 1] : (double)NAN;
        const double y = hi.n > 0 ? hi.y[hi.n - 1] : (double)NAN;
        snprintf(qty, sizeof qty, "end mass after %.4g m paid out, steady rope [m]",
                 c.V * r.t_stop);
        svgp_compare_row(stdout, "winch", qty, yqs, y, fabs(y / yqs - 1.0), r.cpu);
        snprintf(qty, sizeof qty, "stretch of %.4g m of rope, (g_eff/EA)(m l + rhoA l^2/2) [mm]",
                 len);
        svgp_compare_row(stdout, "winch", qty, 1e3 * lin, -1e3 * (y + len),
                         fabs(-(y + len) / lin - 1.0), r.cpu);
        snprintf(qty, sizeof qty, "elements after %.4g m paid out, N0 + floor(d/Lstd + 1/2)",
                 c.V * r.t_stop);
        svgp_compare_row(stdout, "winch", qty, (double)ex_winch_ne(&c, c.V * r.t_stop),
                         (double)r.ne_end, (double)NAN, r.cpu);
        svgp_compare_row(stdout, "winch", "energy balance, largest abs(E - E0 - W) / int abs(P) dt",
                         (double)NAN,
                         r.W_abs > 0.0 ? r.dE_max / r.W_abs : (double)NAN, (double)NAN, r.cpu);
        svgp_compare_row(stdout, "winch", "largest abs(y_end - y_steady) over the run [m]",
                         (double)NAN, r.dy_max, (double)NAN, r.cpu);
    }
    /* charts */
    d = (double *)malloc(4 * (size_t)(hi.n > 0 ? hi.n : 1) * sizeof *d);
    if (!d) return 1;
    s_mod = d + hi.n;
    s_qs = d + 2 * hi.n;
    s_lin = d + 3 * hi.n;
    for (j = 0; j < hi.n; ++j) {
        const double len = c.L0 + c.V * hi.t[j];
        d[j] = c.V * hi.t[j];
        s_mod[j] = -1e3 * (hi.y[j] + len);
        s_qs[j] = -1e3 * (hi.y_qs[j] + len);
        s_lin[j] = 1e3 * ex_winch_geff(&c) / c.EA * (c.mass * len + 0.5 * c.rhoA * len * len);
    }
    svgp_init(&ch1, "Winch: stretch of the hanging rope", "t [s]", "stretch [mm]", 0, 0);
    svgp_series(&ch1, "model: -(y_end + L0 + V t)", hi.n, hi.t, s_mod, 0);
    svgp_series(&ch1, "steady rope, int (lam - 1) dp", hi.n, hi.t, s_qs, SVGP_DASH);
    svgp_series(&ch1, "(g_eff/EA)(m l + rhoA l^2/2)", hi.n, hi.t, s_lin, SVGP_DOT);
    ch1.legend = SVGP_LEGEND_TL;
    snprintf(path, sizeof path, "%s/winch_stretch.svg", dir);
    if (svgp_write_file(&ch1, path)) printf("# could not write %s\n", path);
    svgp_init(&ch2, "Winch: elements against the paid-out rope", "paid out [m]", "elements", 0, 0);
    svgp_series(&ch2, "model", hi.n, d, hi.ne, 0);
    svgp_series(&ch2, "N0 + floor(d / Lstd + 1/2)", hi.n, d, hi.ne_pred, SVGP_DASH);
    ch2.legend = SVGP_LEGEND_TL;
    snprintf(path, sizeof path, "%s/winch_elements.svg", dir);
    if (svgp_write_file(&ch2, path)) printf("# could not write %s\n", path);
    free(d);
    ex_winch_hist_free(&hi);
    return rc;
}

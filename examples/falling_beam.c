/* falling_beam.c -- falling cantilever with a sliding lumped mass
   (ale-rancf section 6.1, ALE-ANCF model) with the length control of its
   Figure 7.  -- part of vlbe                      SPDX-License-Identifier: MIT

   cc -O2 -I. examples/falling_beam.c -lm && ./a.out [outdir]

   Beam: L = 1 m, circular section r = 0.01 m, rho = 7200 kg/m^3,
   E = 20 MPa, no damping, gravity 9.81 m/s^2 (-y); left end clamped
   (position and slope direction), right end free.  Mass 0.8 kg, sliding
   without friction, starts 0.1 m from the clamp at 0.4 m/s along the beam.
   N elements of L_std = L/N: nodes at k L_std, the one nearest to 0.1 m
   replaced by the sliding node (free material coordinate, carrying the
   mass; one slope vector: the slope is continuous at a point mass, which
   is eq. (40)'s continuous case with the two slopes merged).  Elements
   next to the sliding node are ALE, all others Lagrangian (fixed p), as in
   the paper.  Length control keeps the elements behind the mass in
   [0.5, 1.5] L_std; after a change the integrator restarts from the mapped
   state (positions and velocities exact, accelerations consistent again).
   Ahead of the mass, at the free end, there is no node left to remove: the
   last element shrinks to nothing as the mass arrives, and its bending
   frequency grows like 1/L^2.  The run therefore ends when that element is
   shorter than 0.1 L_std, and the leaving time is p(t) extrapolated to
   p = L with p' and p'' (over the last 0.1 L_std, a few ms: the
   extrapolation error is far below the mesh error).

   Newton iterates may invert the short element behind the mass in a large
   step; the chain callbacks report that as "outside the domain" (a positive
   return value) and HHT halves the step (max_halvings = 8), see
   integrators.h.

   Both forms of the element are run: the paper's (virtual work of
   eqs. 17-19) and VLBE_ALE_CONSERVATIVE, which adds the flux of strain
   energy through the moving nodes.  The energy is tracked over the run:
   the drift within the steps (jumps taken out) and the jump at each merge
   (the merged cubic differs from the two pieces).

   The model and the run loop are examples/ex_slide.h (shared with the
   suspended beam of section 6.2).

   Output rows ROW|falling|..., out/falling_beam_<N>[_cons].csv (t, tip y,
   mass x, y, p, energy, arc length and its rate) and
   out/falling_beam_{tip,path}.svg. */
#include "ex_slide.h"

#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#define FB_NRUN 5

/* the scene: N elements, element flags (0 or VLBE_ALE_CONSERVATIVE), step h */
static inline void fb_cfg(ex_slide_cfg *c, int N, unsigned flags, double h)
{
    ex_slide_cfg_paper(c, N, EX_SLIDE_CLAMP_FREE, 0.8, 0.1, 0.4);
    c->flags = flags;
    c->h = h;
}

#ifndef VLBE_EXAMPLE_NO_MAIN
#include "../bench/svgplot.h"

int main(int argc, char **argv)
{
    const char *dir = argc > 1 ? argv[1] : "out";
    static const int Ns[FB_NRUN] = {5, 10, 20, 30, 40};
    static const double paper_motion[FB_NRUN] = {34.6, 58.3, 103.1, 192.4, 325.0};
    static const double paper_lc[FB_NRUN] = {3, 9, 18, 26, 35};
    static const char *form_name[2] = {"paper form", "conservative"};
    static char names[2][FB_NRUN][48];
    const double h = 1e-3;
    ex_slide_hist hist[2][FB_NRUN];
    char path[512], qty[200];
    svgp_chart ctip, cpath;
    int k, f, rc = 0;
    printf("# falling cantilever with a sliding mass (ale-rancf 6.1), ALE-ANCF, HHT-alpha -0.05, "
           "h = %g s, length control at 1.5 L_std; the run ends when the element ahead of the mass "
           "is shorter than 0.1 L_std, the leaving time is p(t) extrapolated to p = L with p', "
           "p''\n", h);
    printf("# paper form = the element of the paper (virtual work of eqs. 17-19); conservative = "
           "VLBE_ALE_CONSERVATIVE (adds the strain-energy flux through the moving nodes)\n");
    for (f = 0; f < 2; ++f) {
        for (k = 0; k < FB_NRUN; ++k) {
            ex_slide_cfg cfg;
            ex_slide_out r;
            ex_slide_hist *hi = &hist[f][k];
            fb_cfg(&cfg, Ns[k], f ? VLBE_ALE_CONSERVATIVE : 0u, h);
            if (ex_slide_hist_alloc(hi, (int)(cfg.t_end / h) + 16)) return 1;
            r = ex_slide_run(&cfg, hi);
            snprintf(path, sizeof path, "%s/falling_beam_%d%s.csv", dir, Ns[k], f ? "_cons" : "");
            if (ex_slide_hist_csv(hi, path)) printf("# could not write %s\n", path);
            printf("# %s, N = %d: %s, mass at p = %.4f m when the run stopped, leaves at t = %.4f s; "
                   "%ld steps (%ld rejected), %ld Newton iterations, %ld LU, %ld length-control "
                   "events; energy within the steps (jumps taken out) E - E0 in [%.3g, %.3g] J, "
                   "largest jump at a merge %.3g J, largest kinetic energy %.3g J; cpu %.3f s "
                   "(length control %.4f s)\n",
                   form_name[f], Ns[k], vlbe_status_str(r.status), r.p_stop, r.t_leave, r.steps,
                   r.rejected, r.newton, r.lu, r.lc_events, r.dE_loss, r.dE_gain, r.dE_lc, r.T_max,
                   r.cpu, r.cpu_lc);
            if (r.status != VLBE_OK || r.t_leave < 0) rc = 1;
            if (r.t_leave > 0)
                snprintf(qty, sizeof qty, "mass leaves the beam, %s, %d elements [s] (paper "
                         "0.6-0.7)", form_name[f], Ns[k]);
            else
                snprintf(qty, sizeof qty, "mass leaves the beam, %s, %d elements [s]: NOT REACHED, "
                         "%s at p = %.3f m", form_name[f], Ns[k], vlbe_status_str(r.status), r.p_stop);
            svgp_compare_row(stdout, "falling", qty, 0.65, r.t_leave > 0 ? r.t_leave : (double)NAN,
                             (double)NAN, r.cpu);
            if (f == 0) {
                snprintf(qty, sizeof qty, "length-control events, %d elements (paper Table 1 LC "
                         "times)", Ns[k]);
                svgp_compare_row(stdout, "falling", qty, paper_lc[k], (double)r.lc_events,
                                 fabs((double)r.lc_events - paper_lc[k]) / paper_lc[k], r.cpu);
                snprintf(qty, sizeof qty, "CPU time to the mass leaving, %d elements [s] (paper "
                         "Table 1 motion time)", Ns[k]);
                svgp_compare_row(stdout, "falling", qty, paper_motion[k], r.cpu, (double)NAN, r.cpu);
            }
            snprintf(qty, sizeof qty, "largest energy jump at a merge, %s, %d elements [J] (of "
                     "%.3g J peak kinetic)", form_name[f], Ns[k], r.T_max);
            svgp_compare_row(stdout, "falling", qty, (double)NAN, r.dE_lc, (double)NAN, r.cpu);
        }
    }
    svgp_init(&ctip, "Falling cantilever with a sliding mass (ale-rancf 6.1): free-end Y "
              "displacement", "t [s]", "Y of the free end [m]", 0, 0);
    svgp_init(&cpath, "Falling cantilever with a sliding mass (ale-rancf 6.1): trajectory of the "
              "mass", "X [m]", "Y [m]", 0, 0);
    for (f = 0; f < 2; ++f)
        for (k = 0; k < FB_NRUN; ++k) {
            const ex_slide_hist *hi = &hist[f][k];
            if (f == 1 && k != FB_NRUN - 1) continue; /* conservative: the finest mesh only */
            snprintf(names[f][k], sizeof names[f][k], "%d el%s", Ns[k], f ? ", conservative" : "");
            svgp_series(&ctip, names[f][k], hi->n, hi->t, hi->probe_y, f ? SVGP_DASH : 0);
            svgp_series(&cpath, names[f][k], hi->n, hi->mass_x, hi->mass_y, f ? SVGP_DASH : 0);
        }
    ctip.legend = SVGP_LEGEND_BL;
    cpath.legend = SVGP_LEGEND_TR;
    snprintf(path, sizeof path, "%s/falling_beam_tip.svg", dir);
    if (svgp_write_file(&ctip, path)) printf("# could not write %s\n", path);
    snprintf(path, sizeof path, "%s/falling_beam_path.svg", dir);
    if (svgp_write_file(&cpath, path)) printf("# could not write %s\n", path);
    for (f = 0; f < 2; ++f)
        for (k = 0; k < FB_NRUN; ++k) ex_slide_hist_free(&hist[f][k]);
    return rc;
}
#endif

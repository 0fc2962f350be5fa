/* falling_beam.c -- falling cantilever with a sliding lumped mass
   (ale-rancf section 6.1, ALE-ANCF and ALE-RANCF models) with the length
   control of its Figure 7.  -- part of vlbe                      SPDX-License-Identifier: MIT

   cc -O2 -I. examples/falling_beam.c -lm && ./a.out [outdir]

   The scene's configuration is scenes/falling_beam.h (shared with the
   tests and bench/bench_sliding.c).

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

   ALE-RANCF (ex_slide_cfg.rational, rancf.h), the paper's element form:
   unit weights at the start (the Hermite element bit for bit), length
   control splits exactly and gives merged elements the least-squares
   weights of eqs. 29-38.  Printed: the paper's Table 1 (motion CPU time =
   all - length control, length-control CPU time and events, both elements)
   and Table 2 (the weights k0, k1, k2 of every merged element: size,
   extremes, sigma of eq. 42) beside the paper's values, and the
   RANCF / ANCF motion-time ratio (paper ~1.6).  A rational run that ends
   with a status (Newton failure etc.) is printed as such, with the time
   and place it stopped: a measured outcome of the paper's method, not a
   failure of this program (the exit code is 1 only for ALE-ANCF failures
   and for statuses that are no dynamics outcome: EARG, EWORK, ECALLBACK).

   The model and the run loop are scenes/ex_slide.h (shared with the
   suspended beam of section 6.2).

   Output rows ROW|falling|..., out/falling_beam_<N>[_cons|_rancf].csv (t,
   tip y, mass x, y, p, energy, arc length and its rate),
   out/falling_beam_{tip,path}.svg (ALE-ANCF), out/falling_beam_rancf_
   {tip,path}.svg (ALE-RANCF, the finest ALE-ANCF dashed) and the paper's
   Figure 12: out/falling_beam_lc_{ancf,rancf}.svg, the 5-element beams
   just before and just after the first two length-control events (50
   material points per element), with the largest distance between the
   two curves at equal material coordinate printed. */
#include "../scenes/falling_beam.h"
#include "../scenes/svgplot.h"

#define FB_NFORM 3 /* ALE-ANCF paper form, ALE-ANCF conservative, ALE-RANCF */
#define FB_SHAPE_PTS 50 /* Figure 12: points per element */

/* largest |r_after(p) - r_before(p)| over the sampled points of event k */
static double fb_shape_change(const ex_slide_hist *hi, int k)
{
    const int n = hi->shape_pts;
    const double *s = hi->shape + (size_t)(4 * k * n);
    double d = 0.0;
    int j;
    for (j = 0; j < n; ++j) {
        const double dd = hypot(s[2 * n + j] - s[j], s[3 * n + j] - s[n + j]);
        if (dd > d) d = dd;
    }
    return d;
}

int main(int argc, char **argv)
{
    const char *dir = argc > 1 ? argv[1] : "out";
    static const int Ns[FB_NRUN] = {5, 10, 20, 30, 40};
    static const double paper_motion[FB_NRUN] = {34.6, 58.3, 103.1, 192.4, 325.0};
    static const double paper_rmotion[FB_NRUN] = {59.9, 97.1, 169.2, 292.4, 478.0};
    static const double paper_rlc[FB_NRUN] = {16.1, 69.1, 157.0, 238.3, 378.2};
    static const double paper_lc[FB_NRUN] = {3, 9, 18, 26, 35};
    /* Table 2: size of set, maximum, minimum, sigma */
    static const double paper_w[FB_NRUN][4] = {
        {6, 1.32, 0.44, 0.27}, {24, 1.18, 0.12, 0.29}, {57, 1.15, 0.73, 0.06},
        {81, 1.16, 0.95, 0.03}, {108, 1.07, 0.72, 0.04}};
    static const char *form_name[FB_NFORM] = {"ALE-ANCF paper form", "ALE-ANCF conservative",
                                              "ALE-RANCF"};
    static const char *suffix[FB_NFORM] = {"", "_cons", "_rancf"};
    static char names[FB_NFORM][FB_NRUN][48], snames[2][4][64], stitle[2][160];
    static ex_slide_out res[FB_NFORM][FB_NRUN];
    const double h = 1e-3;
    ex_slide_hist hist[FB_NFORM][FB_NRUN], shp[2];
    char path[512], qty[240];
    svgp_chart ctip, cpath, crtip, crpath, cshape[2];
    double ratio_sum = 0.0;
    int k, f, j, nratio = 0, rc = 0;
    printf("# falling cantilever with a sliding mass (ale-rancf 6.1), ALE-ANCF and ALE-RANCF, "
           "HHT-alpha -0.05, h = %g s, length control at 1.5 L_std; the run ends when the element "
           "ahead of the mass is shorter than 0.1 L_std, the leaving time is p(t) extrapolated to "
           "p = L with p', p''\n", h);
    printf("# ALE-ANCF paper form = the element of the paper (virtual work of eqs. 17-19); "
           "conservative = VLBE_ALE_CONSERVATIVE (adds the strain-energy flux through the moving "
           "nodes); ALE-RANCF = rancf.h, paper form, unit start weights, least-squares weights for "
           "merged elements (eqs. 29-38)\n");
    for (f = 0; f < FB_NFORM; ++f) {
        for (k = 0; k < FB_NRUN; ++k) {
            ex_slide_cfg cfg;
            ex_slide_out r;
            ex_slide_hist *hi = &hist[f][k];
            fb_cfg(&cfg, Ns[k], f == 1 ? VLBE_ALE_CONSERVATIVE : 0u, h);
            cfg.rational = f == 2;
            if (ex_slide_hist_alloc(hi, (int)(cfg.t_end / h) + 16)) return 1;
            r = res[f][k] = ex_slide_run(&cfg, hi);
            snprintf(path, sizeof path, "%s/falling_beam_%d%s.csv", dir, Ns[k], suffix[f]);
            if (ex_slide_hist_csv(hi, path)) printf("# could not write %s\n", path);
            printf("# %s, N = %d: %s at t = %.4f s, mass at p = %.4f m when the run stopped, "
                   "leaves at t = %.4f s; %ld steps (%ld rejected), %ld Newton iterations, %ld LU, "
                   "%ld length-control events; energy within the steps (jumps taken out) E - E0 "
                   "in [%.3g, %.3g] J, largest jump at a merge %.3g J, largest kinetic energy "
                   "%.3g J; cpu %.3f s (length control %.4f s)\n",
                   form_name[f], Ns[k], vlbe_status_str(r.status), r.t_stop, r.p_stop, r.t_leave,
                   r.steps, r.rejected, r.newton, r.lu, r.lc_events, r.dE_loss, r.dE_gain, r.dE_lc,
                   r.T_max, r.cpu, r.cpu_lc);
            if (f == 2)
                printf("#   weights made by length control: all %ld in [%.4g, %.4g] sigma %.4g; "
                       "merged %ld in [%.4g, %.4g] sigma %.4g; merges fallen back to unit "
                       "weights (eq. 38): %ld\n", r.wall.n, r.wall.kmin, r.wall.kmax,
                       ex_slide_sigma(&r.wall), r.wmerge.n, r.wmerge.kmin, r.wmerge.kmax,
                       ex_slide_sigma(&r.wmerge), r.merge_fallbacks);
            if (f < 2 ? r.status != VLBE_OK || r.t_leave < 0 : !fb_dynamic_status(r.status))
                rc = 1;
            if (r.t_leave > 0)
                snprintf(qty, sizeof qty, "mass leaves the beam, %s, %d elements [s] (paper "
                         "0.6-0.7)", form_name[f], Ns[k]);
            else
                snprintf(qty, sizeof qty, "mass leaves the beam, %s, %d elements [s]: NOT REACHED, "
                         "%s at t = %.4f s, p = %.3f m", form_name[f], Ns[k],
                         vlbe_status_str(r.status), r.t_stop, r.p_stop);
            svgp_compare_row(stdout, "falling", qty, 0.65, r.t_leave > 0 ? r.t_leave : (double)NAN,
                             (double)NAN, r.cpu);
            snprintf(qty, sizeof qty, "largest energy jump at a merge, %s, %d elements [J] (of "
                     "%.3g J peak kinetic)", form_name[f], Ns[k], r.T_max);
            svgp_compare_row(stdout, "falling", qty, (double)NAN, r.dE_lc, (double)NAN, r.cpu);
        }
    }

    /* Table 1 */
    printf("#\n# Table 1 (ale-rancf): CPU time [s] of the motion (all - length control) and of "
           "the length control, and the length-control events; ours (this machine) | paper. "
           "A rational run that stopped early is marked * (times up to the stop).\n");
    printf("# %3s | %21s | %21s | %11s | %11s | %21s | %9s | %11s | %12s\n", "N",
           "RANCF motion s (paper)", "RANCF LC s (paper)", "RANCF LC ev", "ANCF LC ev",
           "ANCF motion s (paper)", "ANCF LC s", "paper LC ev", "RANCF/ANCF");
    for (k = 0; k < FB_NRUN; ++k) {
        const ex_slide_out *a = &res[0][k], *r = &res[2][k];
        const double am = a->cpu - a->cpu_lc, rm = r->cpu - r->cpu_lc;
        const int ok = r->status == VLBE_OK && r->t_leave > 0;
        const double ratio = am > 0.0 ? rm / am : (double)NAN;
        if (ok && am > 0.0) {
            ratio_sum += ratio;
            nratio++;
        }
        printf("# %3d | %9.4f%s (%8.1f) | %9.4f (%9.1f) | %11ld | %11ld | %9.4f (%9.1f) | %9.4f | "
               "%11.0f | %11.2f%s\n", Ns[k], rm, ok ? " " : "*", paper_rmotion[k], r->cpu_lc,
               paper_rlc[k], r->lc_events, a->lc_events, am, paper_motion[k], a->cpu_lc,
               paper_lc[k], ratio, ok ? "" : "*");
        snprintf(qty, sizeof qty, "Table 1, ALE-RANCF motion CPU time, %d elements [s]%s", Ns[k],
                 ok ? "" : " (run stopped early)");
        svgp_compare_row(stdout, "falling", qty, paper_rmotion[k], rm, (double)NAN, r->cpu);
        snprintf(qty, sizeof qty, "Table 1, ALE-RANCF length-control CPU time, %d elements [s]",
                 Ns[k]);
        svgp_compare_row(stdout, "falling", qty, paper_rlc[k], r->cpu_lc, (double)NAN, r->cpu);
        snprintf(qty, sizeof qty, "Table 1, ALE-RANCF length-control events, %d elements%s",
                 Ns[k], ok ? "" : " (run stopped early)");
        svgp_compare_row(stdout, "falling", qty, paper_lc[k], (double)r->lc_events,
                         fabs((double)r->lc_events - paper_lc[k]) / paper_lc[k], r->cpu);
        snprintf(qty, sizeof qty, "Table 1, ALE-ANCF motion CPU time, %d elements [s]", Ns[k]);
        svgp_compare_row(stdout, "falling", qty, paper_motion[k], am, (double)NAN, a->cpu);
        snprintf(qty, sizeof qty, "Table 1, ALE-ANCF length-control CPU time, %d elements [s] "
                 "(paper: too short to measure)", Ns[k]);
        svgp_compare_row(stdout, "falling", qty, (double)NAN, a->cpu_lc, (double)NAN, a->cpu);
        snprintf(qty, sizeof qty, "Table 1, ALE-ANCF length-control events, %d elements", Ns[k]);
        svgp_compare_row(stdout, "falling", qty, paper_lc[k], (double)a->lc_events,
                         fabs((double)a->lc_events - paper_lc[k]) / paper_lc[k], a->cpu);
        snprintf(qty, sizeof qty, "Table 1, ALE-RANCF / ALE-ANCF motion-time ratio, %d elements%s",
                 Ns[k], ok ? "" : " (rational run stopped early)");
        svgp_compare_row(stdout, "falling", qty, paper_rmotion[k] / paper_motion[k], ratio,
                         ok ? fabs(ratio - paper_rmotion[k] / paper_motion[k]) /
                                  (paper_rmotion[k] / paper_motion[k])
                            : (double)NAN,
                         r->cpu + a->cpu);
    }
    printf("# mean RANCF / ANCF motion-time ratio over the completed rational runs (%d): %.2f "
           "(paper: about 1.6)\n", nratio, nratio ? ratio_sum / nratio : (double)NAN);
    svgp_compare_row(stdout, "falling", "mean ALE-RANCF / ALE-ANCF motion-time ratio (completed "
                     "runs)", 1.6, nratio ? ratio_sum / nratio : (double)NAN,
                     nratio ? fabs(ratio_sum / nratio - 1.6) / 1.6 : (double)NAN, (double)NAN);

    /* Table 2 */
    printf("#\n# Table 2 (ale-rancf): the weights k0, k1, k2 of every element made by a merge "
           "(eq. 33), ours | paper; sigma of eq. 42\n");
    printf("# %3s | %13s | %15s | %15s | %15s | %s\n", "N", "size (paper)", "max (paper)",
           "min (paper)", "sigma (paper)", "note");
    for (k = 0; k < FB_NRUN; ++k) {
        const ex_slide_out *r = &res[2][k];
        static const char *wq[4] = {"size of set", "maximum", "minimum", "deviation sigma"};
        double ours[4];
        const int ok = r->status == VLBE_OK && r->t_leave > 0;
        ours[0] = (double)r->wmerge.n;
        ours[1] = r->wmerge.kmax;
        ours[2] = r->wmerge.kmin;
        ours[3] = ex_slide_sigma(&r->wmerge);
        printf("# %3d | %5ld (%5.0f) | %6.3f (%6.2f) | %6.3f (%6.2f) | %6.3f (%6.2f) | %s\n",
               Ns[k], r->wmerge.n, paper_w[k][0], ours[1], paper_w[k][1], ours[2], paper_w[k][2],
               ours[3], paper_w[k][3], ok ? "left the beam" : "run stopped early: set up to the stop");
        for (j = 0; j < 4; ++j) {
            snprintf(qty, sizeof qty, "Table 2, weight set of merged elements, %s, %d elements%s",
                     wq[j], Ns[k], ok ? "" : " (rational run stopped early)");
            svgp_compare_row(stdout, "falling", qty, paper_w[k][j], ours[j],
                             fabs(ours[j] - paper_w[k][j]) / paper_w[k][j], r->cpu);
        }
    }

    /* Figure 12: 5 elements, before and after the first two length-control
       events (separate runs: the sampling would count in the times above) */
    for (f = 0; f < 2; ++f) {
        ex_slide_cfg cfg;
        ex_slide_out r;
        static const char *mname[2] = {"ALE-ANCF", "ALE-RANCF"};
        fb_cfg(&cfg, 5, 0u, h);
        cfg.rational = f;
        if (ex_slide_hist_alloc(&shp[f], (int)(cfg.t_end / h) + 16) ||
            ex_slide_hist_shapes(&shp[f], 2, FB_SHAPE_PTS * 5 + 1))
            return 1;
        r = ex_slide_run(&cfg, &shp[f]);
        snprintf(stitle[f], sizeof stitle[f], "Falling cantilever, 5 %s elements (ale-rancf "
                 "Figure 12): before and after the first two length-control events", mname[f]);
        svgp_init(&cshape[f], stitle[f], "X [m]", "Y [m]", 0, 0);
        for (k = 0; k < shp[f].shape_done; ++k) {
            const int n = shp[f].shape_pts;
            const double *s = shp[f].shape + (size_t)(4 * k * n);
            int kind = 0;
            for (j = 0; j < r.nev; ++j)
                if (r.ev[j].t == shp[f].shape_t[k]) kind = r.ev[j].changed;
            printf("# Figure 12, %s, event %d at t = %.4f s (%s): largest distance between the "
                   "beam before and after at equal material coordinate %.3g mm\n", mname[f], k + 1,
                   shp[f].shape_t[k], kind == 1 ? "split" : kind == 2 ? "split + merge" : "merge",
                   1e3 * fb_shape_change(&shp[f], k));
            snprintf(qty, sizeof qty, "Figure 12, %s, 5 elements, shape change at length-control "
                     "event %d (%s) [mm]", mname[f], k + 1,
                     kind == 1 ? "split" : kind == 2 ? "split + merge" : "merge");
            svgp_compare_row(stdout, "falling", qty, (double)NAN, 1e3 * fb_shape_change(&shp[f], k),
                             (double)NAN, r.cpu);
            snprintf(snames[f][2 * k], sizeof snames[f][2 * k], "before event %d, t = %.3f s",
                     k + 1, shp[f].shape_t[k]);
            snprintf(snames[f][2 * k + 1], sizeof snames[f][2 * k + 1], "after event %d", k + 1);
            svgp_series(&cshape[f], snames[f][2 * k], n, s, s + n, 0);
            svgp_series(&cshape[f], snames[f][2 * k + 1], n, s + 2 * n, s + 3 * n, SVGP_DASH);
        }
        cshape[f].legend = SVGP_LEGEND_BL;
        snprintf(path, sizeof path, "%s/falling_beam_lc_%s.svg", dir, f ? "rancf" : "ancf");
        if (svgp_write_file(&cshape[f], path)) printf("# could not write %s\n", path);
    }

    svgp_init(&ctip, "Falling cantilever with a sliding mass (ale-rancf 6.1), ALE-ANCF: free-end "
              "Y displacement", "t [s]", "Y of the free end [m]", 0, 0);
    svgp_init(&cpath, "Falling cantilever with a sliding mass (ale-rancf 6.1), ALE-ANCF: "
              "trajectory of the mass", "X [m]", "Y [m]", 0, 0);
    svgp_init(&crtip, "Falling cantilever with a sliding mass (ale-rancf 6.1), ALE-RANCF: free-end "
              "Y displacement", "t [s]", "Y of the free end [m]", 0, 0);
    svgp_init(&crpath, "Falling cantilever with a sliding mass (ale-rancf 6.1), ALE-RANCF: "
              "trajectory of the mass", "X [m]", "Y [m]", 0, 0);
    for (f = 0; f < FB_NFORM; ++f)
        for (k = 0; k < FB_NRUN; ++k) {
            const ex_slide_hist *hi = &hist[f][k];
            if (f == 1 && k != FB_NRUN - 1) continue; /* conservative: the finest mesh only */
            snprintf(names[f][k], sizeof names[f][k], "%d el%s", Ns[k],
                     f == 1 ? ", conservative" : "");
            if (f < 2) {
                svgp_series(&ctip, names[f][k], hi->n, hi->t, hi->probe_y, f ? SVGP_DASH : 0);
                svgp_series(&cpath, names[f][k], hi->n, hi->mass_x, hi->mass_y, f ? SVGP_DASH : 0);
            } else {
                if (res[2][k].status != VLBE_OK)
                    snprintf(names[f][k], sizeof names[f][k], "%d el (stopped t = %.3f s)", Ns[k],
                             res[2][k].t_stop);
                svgp_series(&crtip, names[f][k], hi->n, hi->t, hi->probe_y, 0);
                svgp_series(&crpath, names[f][k], hi->n, hi->mass_x, hi->mass_y, 0);
            }
        }
    snprintf(names[0][0], sizeof names[0][0], "ALE-ANCF %d el", Ns[FB_NRUN - 1]);
    svgp_series(&crtip, names[0][0], hist[0][FB_NRUN - 1].n, hist[0][FB_NRUN - 1].t,
                hist[0][FB_NRUN - 1].probe_y, SVGP_DASH);
    svgp_series(&crpath, names[0][0], hist[0][FB_NRUN - 1].n, hist[0][FB_NRUN - 1].mass_x,
                hist[0][FB_NRUN - 1].mass_y, SVGP_DASH);
    ctip.legend = crtip.legend = SVGP_LEGEND_BL;
    cpath.legend = crpath.legend = SVGP_LEGEND_TR;
    snprintf(path, sizeof path, "%s/falling_beam_tip.svg", dir);
    if (svgp_write_file(&ctip, path)) printf("# could not write %s\n", path);
    snprintf(path, sizeof path, "%s/falling_beam_path.svg", dir);
    if (svgp_write_file(&cpath, path)) printf("# could not write %s\n", path);
    snprintf(path, sizeof path, "%s/falling_beam_rancf_tip.svg", dir);
    if (svgp_write_file(&crtip, path)) printf("# could not write %s\n", path);
    snprintf(path, sizeof path, "%s/falling_beam_rancf_path.svg", dir);
    if (svgp_write_file(&crpath, path)) printf("# could not write %s\n", path);
    for (f = 0; f < FB_NFORM; ++f)
        for (k = 0; k < FB_NRUN; ++k) ex_slide_hist_free(&hist[f][k]);
    ex_slide_hist_free(&shp[0]);
    ex_slide_hist_free(&shp[1]);
    return rc;
}

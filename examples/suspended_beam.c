/* suspended_beam.c -- simply supported beam with a sliding 5 kg mass
   (ale-rancf section 6.2, ALE-ANCF and ALE-RANCF models, 3 elements) with the length
   control of its Figure 7.  -- part of vlbe        SPDX-License-Identifier: MIT

   cc -O2 -I. examples/suspended_beam.c -lm && ./a.out [outdir]

   The scene's configuration is scenes/suspended_beam.h (shared with
   tests/test_scenes_ale.c and bench/bench_sliding.c).

   The beam of section 6.1 (L = 1 m, r = 0.01 m, rho = 7200 kg/m^3,
   E = 20 MPa, no damping, gravity 9.81 m/s^2), pinned at both ends on a
   straight horizontal start; a 5 kg mass, released at rest 0.1 m from the
   left end, slides without friction.  Three elements of L_std = 1/3 m: the
   node at 1/3 m becomes the sliding node at p = 0.1 m (ex_slide.h).  The
   beam is far too soft to carry the mass in bending (static midspan sag of
   the beam alone 5 q L^4 / (384 EI) = 1.8 m): it hangs like a cable,
   stretched by the mass, and the mass swings back and forth about midspan.
   With three elements the length control fires at every crossing of
   p = L/2 (an element next to the mass then exceeds 1.5 L_std), each time
   one node inserted and one removed: a merge.

   What is shown (the paper's Figure 14): the beam's arc length and its
   rate (vlbe_ale_chain_length), the system energy T + U + V, and at each
   length-control event the jumps of energy and arc length that the merge
   makes (the split is exact: it makes none).  Between events the energy is
   conserved to integrator accuracy: HHT-alpha (alpha = -0.05) dissipates a
   little, and the dissipation falls with the step (shown at h and h/4).
   Both forms of the ALE-ANCF element are run: the paper's and
   VLBE_ALE_CONSERVATIVE (the strain-energy flux through moving nodes), and
   the ALE-RANCF element (ex_slide_cfg.rational, rancf.h; unit weights at
   the start, so the two models agree up to the first merge; a merged
   element gets the least-squares weights of eqs. 29-38).  The paper's
   claim (Figure 14): the merges of ALE-RANCF alter the shape less and
   excite smaller jumps and vibrations of length and energy than those of
   ALE-ANCF.  Measured here for every merge (an event that removes a node):
   the energy jump dE, the arc-length jump dlen, and the largest |rate of
   the arc length| in the 0.05 s after the merge (beside the same in the
   0.05 s before it: the swing of the mass alone); then the largest of
   each over the merges, model against model, with the verdict.

   Output rows ROW|suspended|..., out/suspended_beam[_cons|_rancf].csv (t,
   midspan y, mass x, y, p, energy, arc length, its rate) and
   out/suspended_beam_{length,energy,rate}.svg (all three). */
#include "../scenes/suspended_beam.h"
#include "../scenes/svgplot.h"

#define SB_NFORM 3   /* ALE-ANCF paper form, ALE-ANCF conservative, ALE-RANCF */
#define SB_WIN 0.05  /* s: the window after (and before) a merge */

int main(int argc, char **argv)
{
    const char *dir = argc > 1 ? argv[1] : "out";
    static const char *form_name[SB_NFORM] = {"ALE-ANCF paper form", "ALE-ANCF conservative",
                                              "ALE-RANCF"};
    static const char *suffix[SB_NFORM] = {"", "_cons", "_rancf"};
    static const double hs[2] = {1e-3, 2.5e-4};
    static const int fls[SB_NFORM] = {0, SVGP_DASH, SVGP_DOT};
    const double t_end = 2.0;
    ex_slide_hist hist[SB_NFORM];
    /* per form at h: largest |dE|, |dlen| over the merges, largest |rate|
       after a merge, and the merges counted */
    double mdE[SB_NFORM], mdl[SB_NFORM], mrate[SB_NFORM], fdE[SB_NFORM], fdl[SB_NFORM];
    int nmerge[SB_NFORM];
    char path[512], qty[240];
    svgp_chart cl, ce, cr;
    int f, j, k, rc = 0;
    printf("# suspended beam with a sliding 5 kg mass (ale-rancf 6.2), ALE-ANCF and ALE-RANCF, 3 "
           "elements, HHT-alpha -0.05, length control at 1.5 L_std, %g s\n", t_end);
    for (f = 0; f < SB_NFORM; ++f) {
        mdE[f] = mdl[f] = mrate[f] = 0.0;
        fdE[f] = fdl[f] = (double)NAN;
        nmerge[f] = 0;
        for (j = 0; j < 2; ++j) {
            ex_slide_cfg cfg;
            ex_slide_out r;
            double dmax = 0.0, lmax = 0.0;
            sb_cfg(&cfg, f == 1 ? VLBE_ALE_CONSERVATIVE : 0u, hs[j], t_end);
            cfg.rational = f == 2;
            if (j == 0 && ex_slide_hist_alloc(&hist[f], (int)(t_end / hs[j]) + 16)) return 1;
            r = ex_slide_run(&cfg, j == 0 ? &hist[f] : NULL);
            if (f < 2 ? r.status != VLBE_OK
                      : r.status == VLBE_EARG || r.status == VLBE_EWORK ||
                            r.status == VLBE_ECALLBACK)
                rc = 1;
            printf("# %s, h = %g s: %s at t = %.4f s; %ld steps (%ld rejected), %ld Newton "
                   "iterations, %ld LU, %ld length-control events; energy within the steps (jumps "
                   "taken out) E - E0 in [%.3g, %.3g] J, peak kinetic %.3g J; cpu %.3f s\n",
                   form_name[f], hs[j], vlbe_status_str(r.status), r.t_stop, r.steps, r.rejected,
                   r.newton, r.lu, r.lc_events, r.dE_loss, r.dE_gain, r.T_max, r.cpu);
            if (f == 2 && j == 0)
                printf("#   weights made by merges: %ld in [%.4g, %.4g], sigma %.4g; fallbacks to "
                       "unit weights %ld\n", r.wmerge.n, r.wmerge.kmin, r.wmerge.kmax,
                       ex_slide_sigma(&r.wmerge), r.merge_fallbacks);
            for (k = 0; k < r.nev; ++k) {
                const int merge = r.ev[k].changed >= 2;
                if (j == 0) {
                    const double ra = sb_rate_max(&hist[f], r.ev[k].t, r.ev[k].t + SB_WIN);
                    const double rb = sb_rate_max(&hist[f], r.ev[k].t - SB_WIN, r.ev[k].t);
                    printf("#   event %d at t = %.4f s (%s): energy jump %+.4g J, arc-length jump "
                           "%+.4g mm; largest |length rate| %.4g m/s in the %g s after (%.4g m/s "
                           "in the %g s before)\n", k + 1, r.ev[k].t, r.ev[k].changed == 2
                           ? "split + merge" : r.ev[k].changed == 3 ? "merge" : "split",
                           r.ev[k].dE, 1e3 * r.ev[k].dlen, ra, SB_WIN, rb, SB_WIN);
                    if (merge) {
                        if (nmerge[f]++ == 0) {
                            fdE[f] = r.ev[k].dE;
                            fdl[f] = r.ev[k].dlen;
                        }
                        if (fabs(r.ev[k].dE) > mdE[f]) mdE[f] = fabs(r.ev[k].dE);
                        if (fabs(r.ev[k].dlen) > mdl[f]) mdl[f] = fabs(r.ev[k].dlen);
                        if (ra > mrate[f]) mrate[f] = ra;
                    }
                }
                if (fabs(r.ev[k].dE) > dmax) dmax = fabs(r.ev[k].dE);
                if (fabs(r.ev[k].dlen) > lmax) lmax = fabs(r.ev[k].dlen);
            }
            snprintf(qty, sizeof qty, "energy drift within the steps (largest loss), %s, h = %g "
                     "[J]", form_name[f], hs[j]);
            svgp_compare_row(stdout, "suspended", qty, (double)NAN, -r.dE_loss, (double)NAN, r.cpu);
            snprintf(qty, sizeof qty, "energy gain within the steps (largest), %s, h = %g [J]",
                     form_name[f], hs[j]);
            svgp_compare_row(stdout, "suspended", qty, (double)NAN, r.dE_gain, (double)NAN, r.cpu);
            if (j == 0) {
                snprintf(qty, sizeof qty, "length-control events in %g s, %s%s", t_end,
                         form_name[f], r.status == VLBE_OK ? "" : " (run stopped early)");
                svgp_compare_row(stdout, "suspended", qty, (double)NAN, (double)r.lc_events,
                                 (double)NAN, r.cpu);
                snprintf(qty, sizeof qty, "largest energy jump at a merge, %s [J] (of %.3g J peak "
                         "kinetic)", form_name[f], r.T_max);
                svgp_compare_row(stdout, "suspended", qty, (double)NAN, dmax, (double)NAN, r.cpu);
                snprintf(qty, sizeof qty, "largest arc-length jump at a merge, %s [mm]",
                         form_name[f]);
                svgp_compare_row(stdout, "suspended", qty, (double)NAN, 1e3 * lmax, (double)NAN,
                                 r.cpu);
                snprintf(qty, sizeof qty, "largest |length rate| within %g s after a merge, %s "
                         "[m/s]", SB_WIN, form_name[f]);
                svgp_compare_row(stdout, "suspended", qty, (double)NAN, mrate[f], (double)NAN,
                                 r.cpu);
            }
        }
        snprintf(path, sizeof path, "%s/suspended_beam%s.csv", dir, suffix[f]);
        if (ex_slide_hist_csv(&hist[f], path)) printf("# could not write %s\n", path);
    }
    printf("#\n# merge jumps, h = %g s, %g s (the paper's claim: smaller with ALE-RANCF)\n", hs[0],
           t_end);
    printf("# %-22s | %6s | %12s | %13s | %24s\n", "model", "merges", "max |dE| J",
           "max |dlen| mm", "max |rate| after, m/s");
    for (f = 0; f < SB_NFORM; ++f)
        printf("# %-22s | %6d | %12.4g | %13.4g | %24.4g\n", form_name[f], nmerge[f], mdE[f],
               1e3 * mdl[f], mrate[f]);
    /* the first merge of the paper form and of ALE-RANCF: the same state
       before it (unit weights, the same element until then) */
    printf("# first merge, from the same state (ALE-RANCF with unit weights = ALE-ANCF paper form "
           "until then): energy jump %+.4g J vs %+.4g J, arc-length jump %+.4g mm vs %+.4g mm "
           "(ALE-RANCF vs ALE-ANCF)\n", fdE[2], fdE[0], 1e3 * fdl[2], 1e3 * fdl[0]);
    svgp_compare_row(stdout, "suspended", "first merge (same state before), |energy jump| "
                     "ALE-RANCF / ALE-ANCF paper form", (double)NAN, fabs(fdE[2] / fdE[0]),
                     (double)NAN, (double)NAN);
    svgp_compare_row(stdout, "suspended", "first merge (same state before), |arc-length jump| "
                     "ALE-RANCF / ALE-ANCF paper form", (double)NAN, fabs(fdl[2] / fdl[0]),
                     (double)NAN, (double)NAN);
    for (f = 0; f < 2; ++f) {
        static const char *what[3] = {"energy jump", "arc-length jump", "length rate after"};
        const double a[3] = {mdE[f], mdl[f], mrate[f]}, b[3] = {mdE[2], mdl[2], mrate[2]};
        for (k = 0; k < 3; ++k) {
            printf("# largest %s at a merge: ALE-RANCF %.4g vs %s %.4g: ALE-RANCF %s (ratio "
                   "%.3g)\n", what[k], b[k], form_name[f], a[k],
                   b[k] < a[k] ? "SMALLER" : "NOT smaller", a[k] > 0.0 ? b[k] / a[k] : (double)NAN);
            snprintf(qty, sizeof qty, "largest %s at a merge, ALE-RANCF / %s (paper: < 1)",
                     what[k], form_name[f]);
            svgp_compare_row(stdout, "suspended", qty, (double)NAN,
                             a[k] > 0.0 ? b[k] / a[k] : (double)NAN, (double)NAN, (double)NAN);
        }
    }
    svgp_init(&cl, "Suspended beam, sliding 5 kg mass (ale-rancf 6.2): arc length", "t [s]",
              "arc length of the beam [m]", 0, 0);
    svgp_init(&cr, "Suspended beam, sliding 5 kg mass (ale-rancf 6.2): rate of the arc length",
              "t [s]", "d(length)/dt [m/s]", 0, 0);
    svgp_init(&ce, "Suspended beam, sliding 5 kg mass (ale-rancf 6.2): energy T + U + V", "t [s]",
              "energy [J]", 0, 0);
    svgp_xrange(&cl, 0.0, t_end);
    svgp_xrange(&cr, 0.0, t_end);
    svgp_xrange(&ce, 0.0, t_end);
    ce.legend = SVGP_LEGEND_TL;
    for (f = 0; f < SB_NFORM; ++f) {
        svgp_series(&cl, form_name[f], hist[f].n, hist[f].t, hist[f].length, fls[f]);
        svgp_series(&cr, form_name[f], hist[f].n, hist[f].t, hist[f].rate, fls[f]);
        svgp_series(&ce, form_name[f], hist[f].n, hist[f].t, hist[f].energy, fls[f]);
    }
    snprintf(path, sizeof path, "%s/suspended_beam_length.svg", dir);
    if (svgp_write_file(&cl, path)) printf("# could not write %s\n", path);
    snprintf(path, sizeof path, "%s/suspended_beam_rate.svg", dir);
    if (svgp_write_file(&cr, path)) printf("# could not write %s\n", path);
    snprintf(path, sizeof path, "%s/suspended_beam_energy.svg", dir);
    if (svgp_write_file(&ce, path)) printf("# could not write %s\n", path);
    for (f = 0; f < SB_NFORM; ++f) ex_slide_hist_free(&hist[f]);
    return rc;
}

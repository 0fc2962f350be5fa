/* suspended_beam.c -- simply supported beam with a sliding 5 kg mass
   (ale-rancf section 6.2, ALE-ANCF model, 3 elements) with the length
   control of its Figure 7.  -- part of vlbe        SPDX-License-Identifier: MIT

   cc -O2 -I. examples/suspended_beam.c -lm && ./a.out [outdir]

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
   Both forms of the element are run: the paper's and
   VLBE_ALE_CONSERVATIVE (the strain-energy flux through moving nodes).

   Output rows ROW|suspended|..., out/suspended_beam[_cons].csv (t, midspan
   y, mass x, y, p, energy, arc length, its rate) and
   out/suspended_beam_{length,energy,rate}.svg. */
#include "ex_slide.h"

#include <stdio.h>
#include <stdlib.h>
#include <string.h>

/* the scene: element flags (0 or VLBE_ALE_CONSERVATIVE), step h, end time */
static inline void sb_cfg(ex_slide_cfg *c, unsigned flags, double h, double t_end)
{
    ex_slide_cfg_paper(c, 3, EX_SLIDE_PIN_PIN, 5.0, 0.1, 0.0);
    c->flags = flags;
    c->h = h;
    c->t_end = t_end;
}

#ifndef VLBE_EXAMPLE_NO_MAIN
#include "../bench/svgplot.h"

int main(int argc, char **argv)
{
    const char *dir = argc > 1 ? argv[1] : "out";
    static const char *form_name[2] = {"paper form", "conservative"};
    static const double hs[2] = {1e-3, 2.5e-4};
    const double t_end = 2.0;
    ex_slide_hist hist[2];
    char path[512], qty[200];
    svgp_chart cl, ce, cr;
    int f, j, k, rc = 0;
    printf("# suspended beam with a sliding 5 kg mass (ale-rancf 6.2), ALE-ANCF, 3 elements, "
           "HHT-alpha -0.05, length control at 1.5 L_std, %g s\n", t_end);
    for (f = 0; f < 2; ++f) {
        for (j = 0; j < 2; ++j) {
            ex_slide_cfg cfg;
            ex_slide_out r;
            double dmax = 0.0, lmax = 0.0;
            sb_cfg(&cfg, f ? VLBE_ALE_CONSERVATIVE : 0u, hs[j], t_end);
            if (j == 0 && ex_slide_hist_alloc(&hist[f], (int)(t_end / hs[j]) + 16)) return 1;
            r = ex_slide_run(&cfg, j == 0 ? &hist[f] : NULL);
            if (r.status != VLBE_OK) rc = 1;
            printf("# %s, h = %g s: %s at t = %.4f s; %ld steps (%ld rejected), %ld Newton "
                   "iterations, %ld LU, %ld length-control events; energy within the steps (jumps "
                   "taken out) E - E0 in [%.3g, %.3g] J, peak kinetic %.3g J; cpu %.3f s\n",
                   form_name[f], hs[j], vlbe_status_str(r.status), r.t_stop, r.steps, r.rejected,
                   r.newton, r.lu, r.lc_events, r.dE_loss, r.dE_gain, r.T_max, r.cpu);
            for (k = 0; k < r.nev; ++k) {
                if (j == 0)
                    printf("#   event %d at t = %.4f s (%s): energy jump %+.4g J, arc-length jump "
                           "%+.4g mm\n", k + 1, r.ev[k].t, r.ev[k].changed == 2 ? "split + merge"
                           : r.ev[k].changed == 3 ? "merge" : "split", r.ev[k].dE, 1e3 * r.ev[k].dlen);
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
                snprintf(qty, sizeof qty, "length-control events in %g s, %s", t_end, form_name[f]);
                svgp_compare_row(stdout, "suspended", qty, (double)NAN, (double)r.lc_events,
                                 (double)NAN, r.cpu);
                snprintf(qty, sizeof qty, "largest energy jump at a merge, %s [J] (of %.3g J peak "
                         "kinetic)", form_name[f], r.T_max);
                svgp_compare_row(stdout, "suspended", qty, (double)NAN, dmax, (double)NAN, r.cpu);
                snprintf(qty, sizeof qty, "largest arc-length jump at a merge, %s [mm]",
                         form_name[f]);
                svgp_compare_row(stdout, "suspended", qty, (double)NAN, 1e3 * lmax, (double)NAN,
                                 r.cpu);
            }
        }
        snprintf(path, sizeof path, "%s/suspended_beam%s.csv", dir, f ? "_cons" : "");
        if (ex_slide_hist_csv(&hist[f], path)) printf("# could not write %s\n", path);
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
    for (f = 0; f < 2; ++f) {
        const int fl = f ? SVGP_DASH : 0;
        svgp_series(&cl, form_name[f], hist[f].n, hist[f].t, hist[f].length, fl);
        svgp_series(&cr, form_name[f], hist[f].n, hist[f].t, hist[f].rate, fl);
        svgp_series(&ce, form_name[f], hist[f].n, hist[f].t, hist[f].energy, fl);
    }
    snprintf(path, sizeof path, "%s/suspended_beam_length.svg", dir);
    if (svgp_write_file(&cl, path)) printf("# could not write %s\n", path);
    snprintf(path, sizeof path, "%s/suspended_beam_rate.svg", dir);
    if (svgp_write_file(&cr, path)) printf("# could not write %s\n", path);
    snprintf(path, sizeof path, "%s/suspended_beam_energy.svg", dir);
    if (svgp_write_file(&ce, path)) printf("# could not write %s\n", path);
    for (f = 0; f < 2; ++f) ex_slide_hist_free(&hist[f]);
    return rc;
}
#endif

/* spinning_shaft.c -- VLBSE scene 4.3 (paper section 4.3): a simply
   supported shaft spinning at Omega under a constant-magnitude load P that
   travels along the axis at v and turns about it at omega (Katz 2001).
   Four 3D beam-shaft elements (ancf_ale.h, vlbe_ale3_*) in a chain whose
   third node follows the load, so every element changes length, against
   the exact modal series of eq. (59) (scenes/ex_katz.h).
   -- part of vlbe                                  SPDX-License-Identifier: MIT

   cc -O2 examples/spinning_shaft.c -lm && ./a.out [outdir]

   The scene's set-up, runs and error analysis are
   scenes/spinning_shaft.h (shared with the tests and bench/wp_shaft.c);
   this file prints the tables, rows and charts.

   Our reading of what the paper leaves implicit (Table 4 and the text):
     beta_1 = pi r_g / l = 0.02 with r_g = r/2 the radius of gyration of the
     solid circular section (r = 2 beta_1 l / pi = 12.7 mm);
     a = v / v_cr with v_cr = omega_1 l / pi the first critical load speed of
     the non-spinning Euler-Bernoulli beam, omega_1 = (pi/l)^2 sqrt(EJ/rhoA);
     k_omega = omega l / (2 pi v), turns of the load per traverse;
     U_s = P l^3 / (48 E J), the static midspan deflection under P at midspan.
   The load starts along X1 (U = U1 + i U2 = deflection in X1 + i X2).

   The model.  Nodes 0..ne, ne/2 elements of equal length on either side
   of the load node ne/2, whose material coordinate is the load's, p = v t
   (all prescribed through the chain's pfun: the ALE form of eq. (51); the
   paper's ne = 4); simple supports: r(0) = 0 (a spherical
   joint, eq. 50) and x = y = 0 at z = l, free along the axis
   (VLBE_ALE_CON_POS with a component mask).  Both ends held axially would
   add membrane tension ~ EA (U/l)^2, a nonlinear effect the linear
   eq. (59) does not have (0.6 % stiffening at U_s = l/1000).  The spin
   angle of node 0 is Omega t (VLBE_ALE_CON_SPIN), the others follow
   through the torsional stiffness; the load P (cos omega t, sin omega t,
   0) acts on the load node's position (eq. 45 at a node).

   Start.  As in the paper the shaft starts at rest: zero deflections and
   deflection rates.  The load cannot start exactly at the support (the
   elements left of it would have zero length): it starts at z0 l at
   t0 = z0 l / v, the nodes at their material points of the straight shaft
   (r_i = (0, 0, p_i), r_i' = (0, 0, 1), rates (0, 0, p_i') and (0, 0, 0),
   spin rate Omega), and stops at (1 - z0) l.  Starting at t0 instead of 0
   leaves out the exact state at t0, which grows as z0^2 (the load next to
   a support hardly bends the shaft): with z0 = 1e-3 (SS_Z0) its free
   vibration is below 4e-5 U_s, and the result does not depend on z0
   (tests/test_scenes_shaft.c bounds the difference; the table shows the
   4 elements from 1e-2 too).  Fine meshes at coarse steps need a larger
   margin, SS_Z0_COARSE (bench/wp_shaft.c: at z0 = 1e-3 Newton fails with
   8 and 16 elements at 125 to 500 steps per traverse; the iteration
   matrix's conditioning grows as the element length ratio cubed).

   Physics the element does not have.  Eq. (59) keeps the rotary inertia of
   the cross-sections in bending and the gyroscopic term -i 2 Omega rhoJ
   U_zzt; the beam-shaft element (an ANCF beam with a spin angle, eq. 27)
   has neither.  With beta_1 = 0.02 they change the exact response by
   O(beta^2) (ex_katz.h): the errors are reported against eq. (59) as
   written (the paper's) and against the same series without the rhoJ
   terms (the continuum the element discretizes).

   Where the error of the paper's mesh comes from.  The frozen mesh (the
   nodes held where they are when the load is at z) has bending
   frequencies above the exact (n pi / l)^2 sqrt(EJ / rhoA) of the simply
   supported shaft, by more as the load nears a support (ss_frozen_freq,
   printed); the phase error of modes 1 and 2 accumulates over the
   traverse.  The error history split at 6 cycles per traverse (ss_split)
   shows it: the part below (modes 1 and 2 vibrate at 1 and 4 cycles per
   traverse in case a = 0.5, at 0.67 and 2.7 in case a = 1.5) grows late
   in the traverse and dominates. */
#include "../scenes/spinning_shaft.h"
#include "../scenes/svgplot.h"

static ss_scene ss_main_scene;

/* histories of the 4-element run against the exact series (CSV and SVG) */
static void ss_plot(const ss_scene *s, int c, int nmodes, const char *dir)
{
    static double t[SS_NSAMP_MAX], y[8][SS_NSAMP_MAX];
    static const char *const lab[4] = {"load point U1/Us", "load point U2/Us", "midspan U1/Us",
                                       "midspan U2/Us"};
    static char names[8][64];
    const double us = ex_katz_us(&s->ref);
    char path[512], title[160];
    const double *cols[9];
    svgp_chart chart;
    int i, k;
    for (i = 0; i < s->ns; ++i) {
        double r[4];
        t[i] = s->ref.v * s->t[i] / s->ref.l; /* load position z / l */
        ex_katz_eval(&s->ref, nmodes, s->ref.v * s->t[i], s->t[i], &r[0], &r[1]);
        ex_katz_eval(&s->ref, nmodes, 0.5 * s->ref.l, s->t[i], &r[2], &r[3]);
        for (k = 0; k < 4; ++k) {
            y[2 * k][i] = s->u[k][i] / us;
            y[2 * k + 1][i] = r[k] / us;
        }
    }
    snprintf(title, sizeof title, "spinning shaft, a = %g, k_omega = %g: 4 ALE beam-shaft elements "
             "vs exact (eq. 59)", ss_case_a[c], ss_case_kw[c]);
    svgp_init(&chart, title, "load position z / l", "U / U_s", 0, 0);
    for (k = 0; k < 4; ++k) {
        snprintf(names[2 * k], sizeof names[0], "%s, 4 elements", lab[k]);
        snprintf(names[2 * k + 1], sizeof names[0], "%s, exact", lab[k]);
        svgp_series(&chart, names[2 * k], s->ns, t, y[2 * k], 0);
        svgp_series(&chart, names[2 * k + 1], s->ns, t, y[2 * k + 1], SVGP_DASH);
    }
    snprintf(path, sizeof path, "%s/spinning_shaft_case%d.svg", dir, c + 1);
    if (svgp_write_file(&chart, path)) printf("could not write %s\n", path);
    cols[0] = t;
    for (k = 0; k < 8; ++k) cols[1 + k] = y[k];
    snprintf(path, sizeof path, "%s/spinning_shaft_case%d.csv", dir, c + 1);
    if (svgp_csv_write(path, "z_over_l,load_U1_fe,load_U1_exact,load_U2_fe,load_U2_exact,"
                       "mid_U1_fe,mid_U1_exact,mid_U2_fe,mid_U2_exact", 9, s->ns, cols))
        printf("could not write %s\n", path);
}

/* one table row: the four largest errors (and where) */
static void ss_print_row(const char *lead, const ss_err *e)
{
    int k;
    printf("%s", lead);
    for (k = 0; k < 4; ++k) printf("  %+.4f (%.2f)", e->e[k], e->z[k]);
    printf("\n");
}

int main(int argc, char **argv)
{
    static const char *names[4] = {"load point U1/Us", "load point U2/Us", "midspan U1/Us",
                                   "midspan U2/Us"};
    static const double zf[7] = {0.5, 0.6, 0.7, 0.8, 0.9, 0.95, 0.99};
    static const struct { int ne, fixed; double z0; } runs[8] = {
        {4, 0, SS_Z0}, {4, 0, 1e-2}, {6, 0, SS_Z0}, {8, 0, SS_Z0},
        {16, 0, SS_Z0}, {4, 1, SS_Z0}, {8, 1, SS_Z0}, {16, 1, SS_Z0}};
    const char *outdir = argc > 1 ? argv[1] : "out";
    ss_scene *s = &ss_main_scene;
    int c, k, ir, i;
    printf("spinning shaft under a moving, turning load (vlbse section 4.3): ALE beam-shaft\n"
           "elements, the load on a node, the shaft starting at rest.  Largest\n"
           "(U - U_exact) / U_s over the traverse (load position z / l where it occurs);\n"
           "exact = eq. (59) [without its rhoJ terms], 30+ modes (series converged to 1e-6 U_s)\n");
    for (c = 0; c < 2; ++c) {
        const double a = ss_case_a[c], kw = ss_case_kw[c];
        ss_err err, err0, paper;
        ex_run_out out;
        int nm = 0;
        char lead[96], q[96];
        ex_katz ref;
        if (ex_katz_setup(&ref, SS_L, SS_BETA1, SS_E, SS_RHO, SS_OMEGA_SPIN, a, kw, 1.0, 1) ||
            ex_katz_modes_for(&ref, 1e-6, 400, &nm, NULL)) {
            printf("reference setup failed\n");
            return 1;
        }
        printf("\ncase a = %g, k_omega = %g: v = %.4f m/s, omega = %.3f rad/s, l/v = %.5f s, "
               "%d modes\n", a, kw, ref.v, ref.omega, ref.T, nm);
        printf("  mesh  el.  z0/l  steps  CPU [s]        load U1         load U2"
               "          mid U1          mid U2\n");
        for (ir = 0; ir < 8; ++ir) {
            const int ne = runs[ir].ne, fixed = runs[ir].fixed;
            const long nsteps = 4000;
            vlbe_status st = ss_run(s, a, kw, ne, fixed, runs[ir].z0, nsteps, -0.05, nm, &err,
                                    &err0, &out);
            if (st != VLBE_OK) {
                printf("  %2d elements: run failed: %s\n", ne, vlbe_status_str(st));
                return 1;
            }
            snprintf(lead, sizeof lead, "  %-6s %2d %5.0e %6ld %8.3f", fixed ? "fixed" : "moving",
                     ne, runs[ir].z0, out.stats.steps, out.cpu);
            ss_print_row(lead, &err);
            ss_print_row("  [without rhoJ]                  ", &err0);
            if (!fixed && (ne == 4 || ne == 6) && runs[ir].z0 == SS_Z0) {
                printf("   at the paper's z / l:         ");
                for (k = 0; k < 4; ++k)
                    printf("  %+.4f (%.2f)", ss_err_at(s, k, ss_paper_z[c][k]),
                           fmin(ss_paper_z[c][k], 1.0 - runs[ir].z0));
                printf("\n");
            }
            if ((!fixed && (ne == 4 || ne == 6) && runs[ir].z0 == SS_Z0) || (fixed && ne == 4))
                for (k = 0; k < 4; ++k) { /* rel. error only between errors of one sign */
                    const double p = ss_paper_err[c][k];
                    snprintf(q, sizeof q, "a=%g kw=%g largest err %s (%d%s el.)", a, kw, names[k],
                             ne, fixed ? " fixed" : "");
                    svgp_compare_row(stdout, "spinning shaft", q, p, err.e[k],
                                     err.e[k] * p > 0.0 ? err.e[k] / p - 1.0 : (double)NAN,
                                     out.cpu);
                }
            if (ne == 4 && !fixed && runs[ir].z0 == SS_Z0) {
                ss_plot(s, c, nm, outdir);
                printf("   split at %g cycles per traverse: largest |low| (z / l), largest "
                       "|high|\n                                ", SS_SPLIT_CYC);
                for (k = 0; k < 4; ++k) {
                    double lo, hi, zlo;
                    ss_split(s, k, SS_SPLIT_CYC, &lo, &hi, &zlo);
                    printf("  %.4f (%.2f) %.4f", lo, zlo, hi);
                }
                printf("\n");
            }
        }
        for (k = 0; k < 4; ++k) {
            paper.e[k] = ss_paper_err[c][k];
            paper.z[k] = ss_paper_z[c][k];
        }
        ss_print_row("  paper   4                       ", &paper);
    }
    printf("\nmoving: the paper's mesh, the load on the middle node (every element changes\n"
           "length); fixed: equal elements, the load a moving point force (eq. 45).  The load\n"
           "runs from z0 l to (1 - z0) l, the shaft starting at rest; the errors at the paper's\n"
           "positions at the nearest sample (at most 1e-3 l away; 1.00 l: the last one).\n"
           "[without rhoJ]: against the series without the rhoJ terms (the element's\n"
           "continuum).  z0 = 1e-2: the same start 10 times farther from the support.\n");

    printf("\nbending frequencies of the paper's mesh frozen with the load node at z (rel. to the\n"
           "exact (n pi / l)^2 sqrt(EJ / rhoA) of the simply supported shaft, %%)\n"
           "   z / l   4 el.: mode 1   mode 2   mode 3     6 el.: mode 1   mode 2   mode 3\n");
    for (i = 0; i < 7; ++i) {
        double w4[3], w6[3];
        if (ss_frozen_freq(s, 4, zf[i], 3, w4) || ss_frozen_freq(s, 6, zf[i], 3, w6)) {
            printf("frozen-mesh eigenproblem failed\n");
            return 1;
        }
        printf("   %5.2f  ", zf[i]);
        for (k = 0; k < 6; ++k) {
            const double wex = (double)((k % 3 + 1) * (k % 3 + 1)) * s->ref.w1; /* n^2 omega_1 */
            const double w = k < 3 ? w4[k] : w6[k - 3];
            printf("%s  %+7.3f", k == 3 ? "    " : "", 100.0 * (w / wex - 1.0));
        }
        printf("\n");
    }
    return 0;
}

/* moving_string.c -- axially moving string and beam between two supports
   (vlbse section 4.1, Table 1) with the planar ALE-ANCF element of
   ancf_ale.h in an Eulerian window: every node sits at a fixed place in
   space while the material flows through it (prescribed nodal material
   coordinates).  -- part of vlbe                  SPDX-License-Identifier: MIT

   cc -O2 -I. examples/moving_string.c -lm && ./a.out [outdir]

   The models, runs and references are scenes/moving_string.h (shared
   with the tests and bench/wp_moving.c); this file prints the tables, rows
   and charts.

   Table 1: l = 1 m, r = 0.005 m, rho = 2700 kg/m^3, E = 70 GPa, F = 1000 N,
   v0 = 40 m/s.  Free vibration from initial transverse velocities of the
   interior nodes (sin(pi x / l) profile, 0.1 mm/s: amplitude ~7e-7 m keeps
   the tension change from the vibration, and the frequency shift it
   causes, below 1e-8 relative).

   Our reading of the data (the paper leaves it implicit):
   - F is the physical tension.  The element's axial force is EA eps r' with
     the Green strain eps, so its magnitude is T = EA eps lam with the
     stretch lam = |r'| = sqrt(1 + 2 eps); vlbe_ale_prestretch solves T = F
     for eps.
   - v0 is the speed of the material in space, so every node's material
     coordinate moves at p' = -v0 / lam (p_i(t) = x_i / lam - v0 t / lam):
     vlbe_ale_chain_window sets the nodes so.
   - rhoA is the mass per unit unstretched length, so the stretched string
     carries rhoA / lam per metre.
   The linear transverse equation of that continuum is eq. (55) with
   rho A -> rhoA/lam and F -> T, whose first frequency is
        f1 = (c^2 - v0^2) / (2 l c),  c^2 = T lam / rhoA.
   With lam = 1 it is the paper's 22.6857 Hz; the prestretch (eps = 1.8e-4)
   raises it by 1.8e-4 relative.  We report our frequencies against both.

   The beam adds EI = E pi r^4 / 4 with pinned supports (the paper gives no
   exact value; its VLBE result is 32.2425 Hz with 4 elements).

   Frequency from the response: the transverse displacement of the middle
   node (x = l/2) over 0.5 s, its strongest line by a Blackman-Harris
   windowed DFT (scenes/ex_freq.h, exact to ~1e-7 here), integrated with
   generalized-alpha (rho_inf 0.9) at h and h/2 and extrapolated to h -> 0
   by Richardson (the scheme is second order: the period error is
   c (omega h)^2; the extrapolated value is accurate to O(h^4)).

   The 3D model (VLBSE scene 4.1 in 3D; `kind` MS_3D): the same window of
   3D beam-shaft elements (VLBSE, vlbe_ale3_* of ancf_ale.h) in a chain of
   vlbe_ale_chain_init3, nodes [r(3), r'(3), theta], the same prescribed
   p(t), supports holding all three components (VLBE_ALE_CON_POS), the
   straight start state along x and the initial velocities along y (or
   along z: MS_XZ, the string vibrating in the x-z plane).  Nothing drives
   the spin: theta(0) = theta'(0) = 0 and no force has a theta component at
   theta = 0, so theta stays 0 (measured: exactly 0), and the element, whose
   curvature vector is the planar signed curvature times the plane's
   normal, is the planar one in-plane.  The section adds rho I_p and G I_p
   (I_p = pi r^4 / 2; G = E / (2 (1 + nu)) with nu = 0.3, which Table 1 does
   not give: there is no twist); MS_NOSPIN drops the spin angle
   (VLBE_ALE3_NO_SPIN).  The runs report the 3D frequencies against eq.
   (56) and the paper's VLBSE values (22.6723 Hz string, 32.2097 Hz beam,
   4 elements), the same mesh convergence as the planar part, the CPU with
   and without the spin angle, and the reproduction of the planar history
   (ms_compare: same h, same integrator, every node's position at every
   step) in the x-y and the x-z plane.  Measured: axial positions equal to
   ~1e-15 m, the transverse ones to ~1e-11 of their amplitude (rounding
   times the Green strain's conditioning 1/eps = 5.5e3, accumulated over
   the run), out-of-plane positions, slopes and theta exactly 0, the x-z
   run the x-y one bit for bit, and without the spin angle the same
   history bit for bit (14-21 % less CPU, measured).  Frequencies from two
   histories that agree this well still differ by up to ~1e-8: the
   estimator's floor (the rounding of the DFT power near its flat peak).
   In float the spin
   chain does not start (VLBE_ESINGULAR: the spin angles' mass, r^2/2 =
   1.25e-5 of the translational one, is under the LU's pivot test n EPS
   max|A|); without the spin angle it runs (tests/test_scenes_moving3d.c).

   Output rows  ROW|moving|<quantity>|<published>|<computed>|<rel.err>|<cpu s>
   and, with an output directory, moving_string.csv / .svg (midpoint
   deflection over time). */
#include "../scenes/moving_string.h"
#include "../scenes/svgplot.h"

/* midpoint deflection histories of the 4-element string and beam */
static void ms_chart(const char *dir)
{
    vlbe_hht_params par;
    ms_obs o[2];
    double *t = NULL, *y[2] = {NULL, NULL};
    const double h = 1e-4, T = 0.25;
    char path[512];
    svgp_chart c;
    size_t k, n;
    int b;
    vlbe_hht_params_genalpha(&par, VLBE_R(0.9));
    memset(o, 0, sizeof o);
    for (b = 0; b < 2; ++b)
        if (ms_freq_run(4, b, h, T, &par, NULL, NULL, &o[b]) < 0) goto done;
    n = o[0].n < o[1].n ? o[0].n : o[1].n;
    t = (double *)malloc(n * sizeof *t);
    for (b = 0; b < 2; ++b) y[b] = (double *)malloc(n * sizeof *y[b]);
    if (!t || !y[0] || !y[1]) goto done;
    for (k = 0; k < n; ++k) {
        t[k] = (double)k * h;
        for (b = 0; b < 2; ++b) y[b][k] = 1e6 * o[b].y[k]; /* micrometres */
    }
    {
        const double *cols[3];
        cols[0] = t;
        cols[1] = y[0];
        cols[2] = y[1];
        snprintf(path, sizeof path, "%s/moving_string.csv", dir);
        if (svgp_csv_write(path, "t_s,string_mid_um,beam_mid_um", 3, (int)n, cols))
            printf("# could not write %s\n", path);
    }
    svgp_init(&c, "Axially moving string and beam (vlbse 4.1), 4 elements: midpoint deflection",
              "t [s]", "deflection [um]", 0, 0);
    svgp_series(&c, "string (EI = 0)", (int)n, t, y[0], 0);
    svgp_series(&c, "beam", (int)n, t, y[1], SVGP_DASH);
    snprintf(path, sizeof path, "%s/moving_string.svg", dir);
    if (svgp_write_file(&c, path)) printf("# could not write %s\n", path);
done:
    free(t);
    free(y[0]);
    free(y[1]);
    free(o[0].y);
    free(o[1].y);
}

/* The frequency table of one model family (kind3: 0 planar, MS_3D, MS_3D |
   MS_NOSPIN): string and beam on 4, 8, 16, 32 elements, ROW lines named
   with the prefix tag, against the exact value, eq. (56) as printed and
   the paper's 4-element values of its element (name, string, beam).
   f, cpu get the frequencies and CPU times [bend][mesh]. */
static void ms_table(const char *tag, int kind3, const char *name, double paper_s,
                     double paper_b, double h, double T, double f[2][4], double cpu[2][4])
{
    static const int nes[4] = {4, 8, 16, 32};
    const double fx = ms_f1_exact();
    char q[160];
    int k, b;
    for (b = 0; b < 2; ++b)
        for (k = 0; k < 4; ++k) f[b][k] = ms_freq(nes[k], kind3 | b, h, T, &cpu[b][k], NULL);
    for (k = 0; k < 4; ++k) {
        snprintf(q, sizeof q, "%sstring f1, %d elements, vs exact (prestretched) [Hz]", tag,
                 nes[k]);
        svgp_compare_row(stdout, "moving", q, fx, f[0][k], fabs(f[0][k] - fx) / fx, cpu[0][k]);
    }
    snprintf(q, sizeof q, "%sstring f1, 4 elements, vs paper %s [Hz]", tag, name);
    svgp_compare_row(stdout, "moving", q, paper_s, f[0][0], fabs(f[0][0] - paper_s) / paper_s,
                     cpu[0][0]);
    for (k = 0; k < 4; k += 3) {
        snprintf(q, sizeof q, "%sstring f1, %d elements, vs eq. (56) as printed [Hz]", tag,
                 nes[k]);
        svgp_compare_row(stdout, "moving", q, MS_F1_PAPER_EXACT, f[0][k],
                         fabs(f[0][k] - MS_F1_PAPER_EXACT) / MS_F1_PAPER_EXACT, cpu[0][k]);
    }
    snprintf(q, sizeof q, "%sbeam f1, 4 elements, vs paper %s [Hz]", tag, name);
    svgp_compare_row(stdout, "moving", q, paper_b, f[1][0], fabs(f[1][0] - paper_b) / paper_b,
                     cpu[1][0]);
    for (k = 1; k < 4; ++k) {
        snprintf(q, sizeof q, "%sbeam f1, %d elements, vs 32 elements [Hz]", tag, nes[k]);
        svgp_compare_row(stdout, "moving", q, k == 3 ? (double)NAN : f[1][3], f[1][k],
                         k == 3 ? (double)NAN : fabs(f[1][k] - f[1][3]) / f[1][3], cpu[1][k]);
    }
}

/* Campbell diagram of the window (16 elements): the lowest three
   frequencies of string and beam against the transport speed, up to the
   analytic divergence speed (string: c; beam: rho v^2 = T + EI pi^2/l^2,
   the first mode's stiffness gone; per length in space as in ms_galerkin:
   v_d^2 = (lam T + EI pi^2 / l^2) / rhoA), with the closed form of the string and
   the Galerkin series of the beam; ROW lines at v0 and near divergence. */
#define MS_NV 23
static void ms_campbell(const char *dir)
{
    static const double r[MS_NV] = {0,   .05, .1,  .15, .2,  .25, .3,  .35, .4,  .45, .5,  .55,
                                    .6,  .65, .7,  .75, .8,  .85, .9,  .95, .98, .99, .995};
    static double v[2][MS_NV], fe[2][3][MS_NV], fr[2][3][MS_NV], X[2][3 * MS_NV + 2],
        YE[2][3 * MS_NV + 2], YR[2][3 * MS_NV + 2], vd[2];
    const double PI = 3.14159265358979323846;
    double rhoA, EA, EI, eps, lam, c, cpu = 0, cpu_all = 0, f[3], g[3], vdm;
    char path[512], q[200];
    svgp_chart ch;
    int b, k, i;
    ms_section(&rhoA, &EA, &EI, &eps, &lam);
    c = sqrt(MS_F * lam / rhoA);
    vd[0] = c;
    vd[1] = sqrt((lam * MS_F + EI * PI * PI / (MS_L * MS_L)) / rhoA);
    for (b = 0; b < 2; ++b)
        for (i = 0; i < MS_NV; ++i) {
            v[b][i] = r[i] * vd[b];
            if (ms_eig(16, b, v[b][i], 3, f, NULL, &cpu) != VLBE_OK ||
                (b ? ms_galerkin(1, v[b][i], MS_GAL_MAX, 3, g) != VLBE_OK : 0)) {
                printf("# campbell: the analysis at %g m/s failed\n", v[b][i]);
                return;
            }
            cpu_all += cpu;
            for (k = 0; k < 3; ++k) {
                fe[b][k][i] = f[k];
                fr[b][k][i] = b ? g[k] : (k + 1) * (c * c - v[b][i] * v[b][i]) / (2.0 * MS_L * c);
            }
        }
    printf("# Campbell diagram, 16 elements, %d speeds each: %.3f s (linearisation and "
           "eigen-solve)\n#   v/v_d   string f1..f3 [Hz] (closed form)            beam f1..f3 "
           "[Hz] (Galerkin, 48 sine modes)\n", MS_NV, cpu_all);
    for (i = 0; i < MS_NV; i += 2)
        printf("#   %.3f  %8.4f %8.4f %8.4f (%8.4f)   %8.4f %8.4f %8.4f (%8.4f)\n", r[i],
               fe[0][0][i], fe[0][1][i], fe[0][2][i], fr[0][0][i], fe[1][0][i], fe[1][1][i],
               fe[1][2][i], fr[1][0][i]);
    for (b = 0; b < 2; ++b) {
        const char *nm = b ? "beam" : "string";
        for (i = 0; i < MS_NV; i += 10) {
            snprintf(q, sizeof q, "eigen route, %s f1 at %.0f %% of the divergence speed, "
                                  "16 elements, vs %s [Hz]", nm, 100.0 * r[i],
                     b ? "Galerkin series" : "closed form");
            svgp_compare_row(stdout, "moving", q, fr[b][0][i], fe[b][0][i],
                             fabs(fe[b][0][i] - fr[b][0][i]) / fr[b][0][i], cpu_all / (2 * MS_NV));
        }
        i = MS_NV - 1;
        snprintf(q, sizeof q, "eigen route, %s f1 at 99.5 %% of the divergence speed, 16 "
                              "elements, vs %s [Hz]", nm, b ? "Galerkin series" : "closed form");
        svgp_compare_row(stdout, "moving", q, fr[b][0][i], fe[b][0][i],
                         fabs(fe[b][0][i] - fr[b][0][i]) / fr[b][0][i], cpu_all / (2 * MS_NV));
        vdm = ms_divergence(16, b, 0.9 * vd[b], 1.1 * vd[b]);
        snprintf(q, sizeof q, "divergence speed of the %s (f1 -> 0), 16 elements, vs %s [m/s]",
                 nm, b ? "v^2 = (lam T + EI pi^2/l^2) / rhoA" : "c = sqrt(T lam / rhoA)");
        svgp_compare_row(stdout, "moving", q, vd[b], vdm, fabs(vdm - vd[b]) / vd[b], (double)NAN);
    }
    for (b = 0; b < 2; ++b) { /* three modes as one series each, NaN between */
        int j = 0;
        for (k = 0; k < 3; ++k) {
            for (i = 0; i < MS_NV; ++i, ++j) {
                X[b][j] = v[b][i];
                YE[b][j] = fe[b][k][i];
                YR[b][j] = fr[b][k][i];
            }
            if (k < 2) {
                X[b][j] = YE[b][j] = YR[b][j] = NAN;
                ++j;
            }
        }
    }
    {
        const double *cols[13];
        cols[0] = r;
        for (b = 0; b < 2; ++b) {
            cols[1 + 6 * b] = v[b];
            for (k = 0; k < 3; ++k) cols[2 + 6 * b + k] = fe[b][k];
            cols[5 + 6 * b] = fr[b][0];
            cols[6 + 6 * b] = fr[b][1];
        }
        snprintf(path, sizeof path, "%s/moving_campbell.csv", dir);
        if (svgp_csv_write(path,
                           "v_over_vd,v_string,f1_string,f2_string,f3_string,f1_string_exact,"
                           "f2_string_exact,v_beam,f1_beam,f2_beam,f3_beam,f1_beam_galerkin,"
                           "f2_beam_galerkin",
                           13, MS_NV, cols))
            printf("# could not write %s\n", path);
    }
    svgp_init(&ch, "Axially moving string and beam (vlbse 4.1): Campbell diagram, 16 elements",
              "transport speed v0 [m/s]", "frequency [Hz]", 0, 0);
    svgp_series(&ch, "string, closed form f_k = k (c^2 - v^2) / (2 l c)", 3 * MS_NV + 2, X[0],
                YR[0], 0);
    svgp_series(&ch, "string, eigen route", 3 * MS_NV + 2, X[0], YE[0], SVGP_NOLINE);
    svgp_series(&ch, "beam, Galerkin series (48 modes)", 3 * MS_NV + 2, X[1], YR[1], SVGP_DASH);
    svgp_series(&ch, "beam, eigen route", 3 * MS_NV + 2, X[1], YE[1], SVGP_NOLINE);
    {
        static double xs[2], xb[2], yv[2] = {0, 210};
        xs[0] = xs[1] = vd[0];
        xb[0] = xb[1] = vd[1];
        svgp_series(&ch, "divergence speed, string (v0 = c)", 2, xs, yv, SVGP_DOT);
        svgp_series(&ch, "divergence speed, beam", 2, xb, yv, SVGP_DOT);
    }
    svgp_xrange(&ch, 0, 85);
    svgp_yrange(&ch, 0, 210);
    snprintf(path, sizeof path, "%s/moving_campbell.svg", dir);
    if (svgp_write_file(&ch, path)) printf("# could not write %s\n", path);
}

/* ROW lines of ms_compare(4 elements) of model a against model b. */
static void ms_compare_rows(const char *what, int kind_a, int kind_b, double h, double T)
{
    ms_cmp c;
    char q[200];
    if (ms_compare(4, kind_a, kind_b, h, T, &c)) {
        printf("# %s: a run failed\n", what);
        return;
    }
    snprintf(q, sizeof q, "%s, 4 elements, %g s at h = %g: max abs dx over nodes and steps [m]",
             what, T, h);
    svgp_compare_row(stdout, "moving", q, 0.0, c.d[0], (double)NAN, c.cpu_a);
    snprintf(q, sizeof q, "%s: max abs d(transverse) / max abs transverse", what);
    svgp_compare_row(stdout, "moving", q, 0.0, c.d[1] / c.amax[1], (double)NAN, c.cpu_a);
    snprintf(q, sizeof q, "%s: max abs out-of-plane position or slope, max abs theta", what);
    printf("# %s: out-of-plane %.3g, theta %.3g over %lu samples\n", what, c.oop, c.th,
           (unsigned long)c.n);
    svgp_compare_row(stdout, "moving", q, 0.0, fmax(c.oop, c.th), (double)NAN, c.cpu_a);
    snprintf(q, sizeof q, "%s: f1 from this history (not extrapolated) [Hz]", what);
    svgp_compare_row(stdout, "moving", q, c.fb, c.fa, fabs(c.fa - c.fb) / c.fb, c.cpu_a);
}

int main(int argc, char **argv)
{
    static const int nes[4] = {4, 8, 16, 32};
    const char *dir = argc > 1 ? argv[1] : "out";
    const double fx = ms_f1_exact(), h = 2e-4, T = 0.5;
    double rhoA, EA, EI, eps, lam, f[2][4], cpu[2][4], f3[2][4], cpu3[2][4], f3n, cpu3n = 0;
    double cs = 0, cn = 0, cp = 0;
    char q[160];
    int k, b;
    ms_section(&rhoA, &EA, &EI, &eps, &lam);
    printf("# axially moving string/beam (vlbse 4.1), Eulerian window, prescribed p(t)\n"
           "# prestretch eps = %.6e (T = EA eps |r'| = F), exact f1 of this string %.6f Hz,\n"
           "# eq. (56) without prestretch %.6f Hz; frequencies from 0.5 s of response,\n"
           "# generalized-alpha rho 0.9, h = %g and h/2, Richardson to h -> 0\n",
           eps, fx, MS_F1_PAPER_EXACT, h);
    ms_table("", 0, "VLBE", MS_F1_PAPER_VLBE, MS_F1_PAPER_BEAM, h, T, f, cpu);
    printf("# 3D beam-shaft chain (VLBSE), theta = 0, no spin driving\n");
    ms_table("3D ", MS_3D, "VLBSE", MS_F1_PAPER_VLBSE, MS_F1_PAPER_BEAM3, h, T, f3, cpu3);
    printf("# 3D without the spin angle (VLBE_ALE3_NO_SPIN), 4 and 16 elements\n");
    for (b = 0; b < 2; ++b)
        for (k = 0; k < 4; k += 2) {
            f3n = ms_freq(nes[k], MS_3D | MS_NOSPIN | b, h, T, &cpu3n, NULL);
            snprintf(q, sizeof q, "3D %s f1 without spin angle, %d elements, vs with [Hz]",
                     b ? "beam" : "string", nes[k]);
            svgp_compare_row(stdout, "moving", q, f3[b][k], f3n, fabs(f3n - f3[b][k]) / f3[b][k],
                             cpu3n);
            cs += cpu3[b][k];
            cn += cpu3n;
            cp += cpu[b][k];
        }
    printf("# CPU of these 4 Richardson pairs: planar %.3f s, 3D with spin %.3f s, without "
           "%.3f s (-%.0f %%)\n",
           cp, cs, cn, 100.0 * (1.0 - cn / cs));
    printf("# 3D vs planar frequencies: equal up to the estimator's floor (~1e-8: the DFT\n"
           "# power's rounding near its flat peak); the histories agree to ~1e-11, below\n");
    for (b = 0; b < 2; ++b)
        for (k = 0; k < 4; ++k) {
            snprintf(q, sizeof q, "3D %s f1, %d elements, vs planar [Hz]", b ? "beam" : "string",
                     nes[k]);
            svgp_compare_row(stdout, "moving", q, f[b][k], f3[b][k],
                             fabs(f3[b][k] - f[b][k]) / f[b][k], cpu3[b][k]);
        }
    ms_compare_rows("3D vs planar string", MS_3D, 0, h, T);
    ms_compare_rows("3D vs planar beam", MS_3D | MS_BEND, MS_BEND, h, T);
    ms_compare_rows("3D without vs with spin angle string", MS_3D | MS_NOSPIN, MS_3D, h, T);
    ms_compare_rows("3D x-z vs x-y plane string", MS_3D | MS_XZ, MS_3D, h, T);
    ms_compare_rows("3D x-z vs x-y plane beam", MS_3D | MS_XZ | MS_BEND, MS_3D | MS_BEND, h, T);
    printf("# Table 1 by the eigen route (linearisation about the steady flow, vlbe_eig_quad),\n"
           "# 4 elements as the paper, against the paper and the time histories above\n");
    for (k = 0; k < 4; ++k) {
        const int d3 = k >= 2, bend = k & 1;
        const double paper = d3 ? (bend ? MS_F1_PAPER_BEAM3 : MS_F1_PAPER_VLBSE)
                                : (bend ? MS_F1_PAPER_BEAM : MS_F1_PAPER_VLBE);
        const double th = d3 ? f3[bend][0] : f[bend][0];
        double fe = 0, amax = 0, ce = 0;
        if (ms_eig(4, (d3 ? MS_3D : 0) | bend, MS_V0, 1, &fe, &amax, &ce) != VLBE_OK) {
            printf("# eigen route failed\n");
            continue;
        }
        snprintf(q, sizeof q, "eigen route: %s%s f1, 4 elements, vs paper %s [Hz]", d3 ? "3D " : "",
                 bend ? "beam" : "string", d3 ? "VLBSE" : "VLBE");
        svgp_compare_row(stdout, "moving", q, paper, fe, fabs(fe - paper) / paper, ce);
        snprintf(q, sizeof q, "eigen route: %s%s f1, 4 elements, vs the time history [Hz]",
                 d3 ? "3D " : "", bend ? "beam" : "string");
        svgp_compare_row(stdout, "moving", q, th, fe, fabs(fe - th) / th, ce);
        if (!bend) {
            snprintf(q, sizeof q, "eigen route: %sstring f1, 4 elements, vs exact (prestretched) "
                                  "[Hz]", d3 ? "3D " : "");
            svgp_compare_row(stdout, "moving", q, fx, fe, fabs(fe - fx) / fx, ce);
        }
        printf("# %s%s: steady state max |q''| = %.3g\n", d3 ? "3D " : "", bend ? "beam" : "string",
               amax);
    }
    ms_campbell(dir);
    ms_chart(dir);
    return 0;
}

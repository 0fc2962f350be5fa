/* moving_string.c -- axially moving string and beam between two supports
   (vlbse section 4.1, Table 1) with the planar ALE-ANCF element of
   ancf_ale.h in an Eulerian window: every node sits at a fixed place in
   space while the material flows through it (prescribed nodal material
   coordinates).  -- part of vlbe                  SPDX-License-Identifier: MIT

   cc -O2 -I. examples/moving_string.c -lm && ./a.out [outdir]

   Table 1: l = 1 m, r = 0.005 m, rho = 2700 kg/m^3, E = 70 GPa, F = 1000 N,
   v0 = 40 m/s.  Free vibration from initial transverse velocities of the
   interior nodes (sin(pi x / l) profile, 0.1 mm/s: amplitude ~7e-7 m keeps
   the tension change from the vibration, and the frequency shift it
   causes, below 1e-8 relative).

   Our reading of the data (the paper leaves it implicit):
   - F is the physical tension.  The element's axial force is EA eps r' with
     the Green strain eps, so its magnitude is T = EA eps lam with the
     stretch lam = |r'| = sqrt(1 + 2 eps); we solve T = F for eps.
   - v0 is the speed of the material in space, so every node's material
     coordinate moves at p' = -v0 / lam (p_i(t) = x_i / lam - v0 t / lam).
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
   windowed DFT (examples/ex_freq.h, exact to ~1e-7 here), integrated with
   generalized-alpha (rho_inf 0.9) at h and h/2 and extrapolated to h -> 0
   by Richardson (the scheme is second order: the period error is
   c (omega h)^2; the extrapolated value is accurate to O(h^4)).

   Output rows  ROW|moving|<quantity>|<published>|<computed>|<rel.err>|<cpu s>
   and, with an output directory, moving_string.csv / .svg (midpoint
   deflection over time). */
#include "../ancf_ale.h"
#include "ex_ale.h"
#include "ex_freq.h"
#include "ex_run.h"

#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#define MS_L 1.0
#define MS_R 0.005
#define MS_RHO 2700.0
#define MS_E 70e9
#define MS_F 1000.0
#define MS_V0 40.0
#define MS_F1_PAPER_EXACT 22.6857  /* eq. (56), as printed               */
#define MS_F1_PAPER_VLBE 22.6786   /* VLBE, 4 elements (string)          */
#define MS_F1_PAPER_VLBSE 22.6723  /* VLBSE, 4 elements (string)         */
#define MS_F1_PAPER_BEAM 32.2425   /* VLBE, 4 elements (beam)            */
#define MS_NE_MAX 64

typedef struct ms_model {
    vlbe_ale_mat mat;
    vlbe_ale_elem el;
    vlbe_ale_node node[MS_NE_MAX + 1];
    vlbe_ale_con con[2];
    vlbe_ale_chain ch;
    vlbe_dae sys;
    double lam, eps, T; /* prestretch and tension */
    int ne, bend;
} ms_model;

/* Section and prestretch: T = EA eps sqrt(1 + 2 eps) = F. */
static inline void ms_section(double *rhoA, double *EA, double *EI, double *eps, double *lam)
{
    const double PI = 3.14159265358979323846, A = PI * MS_R * MS_R;
    double e = 0.0;
    int k;
    *rhoA = MS_RHO * A;
    *EA = MS_E * A;
    *EI = MS_E * PI * MS_R * MS_R * MS_R * MS_R / 4.0;
    for (k = 0; k < 50; ++k) e = MS_F / (*EA * sqrt(1.0 + 2.0 * e));
    *eps = e;
    *lam = sqrt(1.0 + 2.0 * e);
}

/* The exact first frequency of the prestretched moving string (see top). */
static inline double ms_f1_exact(void)
{
    double rhoA, EA, EI, eps, lam, c;
    ms_section(&rhoA, &EA, &EI, &eps, &lam);
    c = sqrt(MS_F * lam / rhoA);
    return (c * c - MS_V0 * MS_V0) / (2.0 * MS_L * c);
}

/* Builds the window of ne elements; q0, v0 (size m->ch.n) get the straight
   prestretched state with the initial transverse velocities. */
static inline int ms_build(ms_model *m, int ne, int bend, vlbe_real *q0, vlbe_real *v0)
{
    const double PI = 3.14159265358979323846;
    double rhoA, EA, EI;
    vlbe_real r0[2] = {0, 0}, dir[2];
    vlbe_ale_con c;
    int i;
    if (ne < 2 || ne > MS_NE_MAX) return -1;
    memset(m, 0, sizeof *m);
    ms_section(&rhoA, &EA, &EI, &m->eps, &m->lam);
    m->T = MS_F;
    m->ne = ne;
    m->bend = bend;
    m->mat.rhoA = (vlbe_real)rhoA;
    m->mat.EA = (vlbe_real)EA;
    m->mat.EI = (vlbe_real)EI;
    if (vlbe_ale_elem_init(&m->el, &m->mat, (bend ? 0u : VLBE_ALE_NO_BEND) | VLBE_ALE_NO_DAMP, 0, 0,
                           0))
        return -1;
    for (i = 0; i <= ne; ++i) {
        vlbe_ale_node *nd = &m->node[i];
        nd->pmode = VLBE_ALE_PPRESCRIBED;
        nd->p = (vlbe_real)(MS_L * i / ne / m->lam);
        nd->pd = (vlbe_real)(-MS_V0 / m->lam);
    }
    if (vlbe_ale_chain_init(&m->ch, &m->el, m->node, ne + 1, MS_NE_MAX + 1, m->con, 2)) return -1;
    memset(&c, 0, sizeof c);
    c.type = VLBE_ALE_CON_POS; /* supports: positions fixed (pinned) */
    c.node = 0;
    vlbe_ale_chain_add(&m->ch, &c);
    c.node = ne;
    c.v[0] = (vlbe_real)MS_L;
    vlbe_ale_chain_add(&m->ch, &c);
    if (vlbe_ale_chain_layout(&m->ch)) return -1;
    ex_ale_wire(&m->sys, &m->ch);
    if (q0) {
        dir[0] = (vlbe_real)m->lam;
        dir[1] = 0;
        vlbe_ale_chain_straight(&m->ch, r0, dir, q0);
    }
    if (v0) {
        for (i = 0; i < m->ch.n; ++i) v0[i] = 0;
        for (i = 1; i < ne; ++i) v0[m->node[i].ofs + 1] = (vlbe_real)(1e-4 * sin(PI * i / ne));
    }
    return 0;
}

typedef struct ms_obs {
    int idx;        /* coordinate observed (y of the middle node) */
    size_t n, cap;
    double *y;
} ms_obs;

static inline vlbe_status ms_observe(void *ctx, double t, const vlbe_real *q, const vlbe_real *v,
                                     const vlbe_real *lam)
{
    ms_obs *o = (ms_obs *)ctx;
    (void)t, (void)v, (void)lam;
    if (o->n < o->cap) o->y[o->n++] = (double)q[o->idx];
    return VLBE_OK;
}

/* One run: first frequency from the response of ne elements with step h
   over t_end (HHT family par); *cpu gets the run time, *stats the counters.
   Returns the frequency, or -1 on failure. */
static inline double ms_freq_run(int ne, int bend, double h, double t_end,
                                 const vlbe_hht_params *par, double *cpu, vlbe_dae_stats *stats,
                                 ms_obs *keep)
{
    ms_model *m = (ms_model *)malloc(sizeof *m);
    vlbe_real *q0 = NULL, *v0 = NULL;
    double f = -1.0, *w = NULL;
    ex_method meth;
    ex_run_out out;
    ms_obs o;
    memset(&o, 0, sizeof o);
    memset(&meth, 0, sizeof meth);
    if (!m) return -1.0;
    q0 = (vlbe_real *)malloc(4 * (MS_NE_MAX + 1) * sizeof *q0);
    v0 = (vlbe_real *)malloc(4 * (MS_NE_MAX + 1) * sizeof *v0);
    o.cap = (size_t)(t_end / h + 2.5);
    o.y = (double *)malloc(o.cap * sizeof *o.y);
    w = (double *)malloc(o.cap * sizeof *w);
    if (q0 && v0 && o.y && w && ms_build(m, ne, bend, q0, v0) == 0) {
        o.idx = m->node[ne / 2].ofs + 1;
        meth.hht = par;
        meth.h = h;
        if (ex_run(&m->sys, &meth, q0, v0, t_end, ms_observe, &o, NULL, NULL, NULL, &out) ==
            VLBE_OK)
            f = ex_peak_freq(o.y, o.n, h, bend ? 20.0 : 12.0, bend ? 45.0 : 33.0, w);
        if (cpu) *cpu = out.cpu;
        if (stats) *stats = out.stats;
    }
    if (keep && f > 0) {
        *keep = o;
        o.y = NULL;
    }
    free(o.y);
    free(w);
    free(q0);
    free(v0);
    free(m);
    return f;
}

/* Richardson-extrapolated frequency from steps h and h/2. */
static inline double ms_freq(int ne, int bend, double h, double t_end, double *cpu,
                             vlbe_dae_stats *st)
{
    vlbe_hht_params par;
    double c1 = 0, c2 = 0, f1, f2;
    vlbe_hht_params_genalpha(&par, VLBE_R(0.9));
    f1 = ms_freq_run(ne, bend, h, t_end, &par, &c1, NULL, NULL);
    f2 = ms_freq_run(ne, bend, 0.5 * h, t_end, &par, &c2, st, NULL);
    if (cpu) *cpu = c1 + c2;
    if (f1 < 0 || f2 < 0) return -1.0;
    return f2 + (f2 - f1) / 3.0;
}

#ifndef VLBE_EXAMPLE_NO_MAIN
#include "../bench/svgplot.h"

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

int main(int argc, char **argv)
{
    const char *dir = argc > 1 ? argv[1] : "out";
    static const int nes[4] = {4, 8, 16, 32};
    const double fx = ms_f1_exact(), h = 2e-4, T = 0.5;
    double rhoA, EA, EI, eps, lam, f[2][4], cpu[2][4];
    char q[128];
    int k, b;
    ms_section(&rhoA, &EA, &EI, &eps, &lam);
    printf("# axially moving string/beam (vlbse 4.1), Eulerian window, prescribed p(t)\n"
           "# prestretch eps = %.6e (T = EA eps |r'| = F), exact f1 of this string %.6f Hz,\n"
           "# eq. (56) without prestretch %.6f Hz; frequencies from 0.5 s of response,\n"
           "# generalized-alpha rho 0.9, h = %g and h/2, Richardson to h -> 0\n",
           eps, fx, MS_F1_PAPER_EXACT, h);
    for (b = 0; b < 2; ++b)
        for (k = 0; k < 4; ++k) f[b][k] = ms_freq(nes[k], b, h, T, &cpu[b][k], NULL);
    for (k = 0; k < 4; ++k) {
        snprintf(q, sizeof q, "string f1, %d elements, vs exact (prestretched) [Hz]", nes[k]);
        svgp_compare_row(stdout, "moving", q, fx, f[0][k], fabs(f[0][k] - fx) / fx, cpu[0][k]);
    }
    svgp_compare_row(stdout, "moving", "string f1, 4 elements, vs paper VLBE [Hz]", MS_F1_PAPER_VLBE,
                     f[0][0], fabs(f[0][0] - MS_F1_PAPER_VLBE) / MS_F1_PAPER_VLBE, cpu[0][0]);
    svgp_compare_row(stdout, "moving", "string f1, 4 elements, vs eq. (56) as printed [Hz]",
                     MS_F1_PAPER_EXACT, f[0][0],
                     fabs(f[0][0] - MS_F1_PAPER_EXACT) / MS_F1_PAPER_EXACT, cpu[0][0]);
    svgp_compare_row(stdout, "moving", "string f1, 32 elements, vs eq. (56) as printed [Hz]",
                     MS_F1_PAPER_EXACT, f[0][3],
                     fabs(f[0][3] - MS_F1_PAPER_EXACT) / MS_F1_PAPER_EXACT, cpu[0][3]);
    svgp_compare_row(stdout, "moving", "beam f1, 4 elements, vs paper VLBE [Hz]", MS_F1_PAPER_BEAM,
                     f[1][0], fabs(f[1][0] - MS_F1_PAPER_BEAM) / MS_F1_PAPER_BEAM, cpu[1][0]);
    for (k = 1; k < 4; ++k) {
        snprintf(q, sizeof q, "beam f1, %d elements, vs 32 elements [Hz]", nes[k]);
        svgp_compare_row(stdout, "moving", q, k == 3 ? (double)NAN : f[1][3], f[1][k],
                         k == 3 ? (double)NAN : fabs(f[1][k] - f[1][3]) / f[1][3], cpu[1][k]);
    }
    ms_chart(dir);
    return 0;
}
#endif

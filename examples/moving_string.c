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
   windowed DFT (examples/ex_freq.h, exact to ~1e-7 here), integrated with
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
#define MS_F1_PAPER_BEAM3 32.2097  /* VLBSE, 4 elements (beam)           */
#define MS_NU 0.3                  /* Poisson's ratio for G (twist only)  */
#define MS_NE_MAX 64
#define MS_NQ_NODE 8               /* coordinates per node, at most (3D: r, r', theta, p) */

/* Model kinds (the `kind` argument; 0 and 1 are the planar string, beam). */
#define MS_BEND 1   /* the beam (EI); otherwise the string                 */
#define MS_3D 2     /* 3D beam-shaft chain (VLBSE) instead of the planar one */
#define MS_NOSPIN 4 /* 3D: without the spin angle (VLBE_ALE3_NO_SPIN)      */
#define MS_XZ 8     /* 3D: vibration in the x-z plane (else x-y)           */
#define MS_BAND 16  /* banded matrices (vlbe_ale_chain_band) and the
                       integrators' banded path; else dense             */

typedef struct ms_model {
    vlbe_ale_mat mat;
    vlbe_ale_elem el;
    vlbe_ale3_elem el3;
    vlbe_ale_node node[MS_NE_MAX + 1];
    vlbe_ale_con con[2];
    vlbe_ale_chain ch;
    vlbe_dae sys;
    int order[MS_NQ_NODE * (MS_NE_MAX + 1) + 6]; /* MS_BAND: the augmented order */
    double lam, eps, T; /* prestretch and tension */
    int ne, bend, kind;
    int tr;             /* component of the transverse motion: 1 (y) or 2 (z) */
} ms_model;

/* Section and prestretch: T = EA eps sqrt(1 + 2 eps) = F (vlbe_ale_prestretch). */
static inline void ms_section(double *rhoA, double *EA, double *EI, double *eps, double *lam)
{
    const double PI = 3.14159265358979323846, A = PI * MS_R * MS_R;
    vlbe_real e = 0, l = 1;
    *rhoA = MS_RHO * A;
    *EA = MS_E * A;
    *EI = MS_E * PI * MS_R * MS_R * MS_R * MS_R / 4.0;
    (void)vlbe_ale_prestretch((vlbe_real)*EA, (vlbe_real)MS_F, &e, &l); /* EA > 0, F > 0: VLBE_OK */
    *eps = (double)e;
    *lam = (double)l;
}

/* The exact first frequency of the prestretched moving string (see top). */
static inline double ms_f1_exact(void)
{
    double rhoA, EA, EI, eps, lam, c;
    ms_section(&rhoA, &EA, &EI, &eps, &lam);
    c = sqrt(MS_F * lam / rhoA);
    return (c * c - MS_V0 * MS_V0) / (2.0 * MS_L * c);
}

/* Builds the window of ne elements of the given kind (MS_*); q0, v0 (size
   m->ch.n, at most MS_NQ_NODE (ne + 1)) get the straight prestretched state
   with the initial transverse velocities. */
static inline int ms_build(ms_model *m, int ne, int kind, vlbe_real *q0, vlbe_real *v0)
{
    const double PI = 3.14159265358979323846;
    const int d3 = (kind & MS_3D) != 0;
    const unsigned flags = ((kind & MS_BEND) ? 0u : VLBE_ALE_NO_BEND) | VLBE_ALE_NO_DAMP;
    double rhoA, EA, EI;
    vlbe_real r0[3] = {0, 0, 0}, dir[3] = {0, 0, 0}, s[MS_NE_MAX + 1];
    vlbe_ale_con c;
    int i;
    if (ne < 2 || ne > MS_NE_MAX || kind < 0 || kind > 31 || (!d3 && (kind & ~MS_BAND) > 1))
        return -1;
    memset(m, 0, sizeof *m);
    ms_section(&rhoA, &EA, &EI, &m->eps, &m->lam);
    m->T = MS_F;
    m->ne = ne;
    m->bend = kind & MS_BEND;
    m->kind = kind;
    m->tr = (kind & MS_XZ) ? 2 : 1;
    m->mat.rhoA = (vlbe_real)rhoA;
    m->mat.EA = (vlbe_real)EA;
    m->mat.EI = (vlbe_real)EI;
    if (d3) {
        const double Ip = 2.0 * EI / MS_E; /* polar: pi r^4 / 2 */
        vlbe_ale3_mat m3;
        memset(&m3, 0, sizeof m3);
        m3.rhoA = m->mat.rhoA;
        m3.EA = m->mat.EA;
        m3.EJ = m->mat.EI;
        m3.rhoI = (vlbe_real)(MS_RHO * Ip);
        m3.GI = (vlbe_real)(MS_E / (2.0 * (1.0 + MS_NU)) * Ip);
        if (vlbe_ale3_elem_init(&m->el3, &m3, flags | ((kind & MS_NOSPIN) ? VLBE_ALE3_NO_SPIN : 0u),
                                0, 0))
            return -1;
    } else if (vlbe_ale_elem_init(&m->el, &m->mat, flags, 0, 0, 0)) {
        return -1;
    }
    if ((d3 ? vlbe_ale_chain_init3(&m->ch, &m->el3, m->node, ne + 1, MS_NE_MAX + 1, m->con, 2)
            : vlbe_ale_chain_init(&m->ch, &m->el, m->node, ne + 1, MS_NE_MAX + 1, m->con, 2)))
        return -1;
    /* the window: nodes at x_i = l i / ne, the material flowing through at
       v0 with the stretch lam (p_i = (x_i - v0 t) / lam) */
    for (i = 0; i <= ne; ++i) s[i] = (vlbe_real)(MS_L * i / ne);
    if (vlbe_ale_chain_window(&m->ch, s, (vlbe_real)m->lam, (vlbe_real)MS_V0)) return -1;
    memset(&c, 0, sizeof c);
    c.type = VLBE_ALE_CON_POS; /* supports: positions fixed (pinned; 3D: all 3 components) */
    c.node = 0;
    vlbe_ale_chain_add(&m->ch, &c);
    c.node = ne;
    c.r[0] = (vlbe_real)MS_L;
    vlbe_ale_chain_add(&m->ch, &c);
    if (vlbe_ale_chain_layout(&m->ch)) return -1;
    if ((kind & MS_BAND) &&
        ex_ale_band(&m->ch, m->order, (int)(sizeof m->order / sizeof m->order[0])))
        return -1;
    if (vlbe_ale_chain_dae(&m->ch, &m->sys)) return -1;
    if (q0) {
        dir[0] = (vlbe_real)m->lam;
        vlbe_ale_chain_straight(&m->ch, r0, dir, q0); /* theta = 0 */
    }
    if (v0) {
        for (i = 0; i < m->ch.n; ++i) v0[i] = 0;
        for (i = 1; i < ne; ++i) v0[m->node[i].ofs + m->tr] = (vlbe_real)(1e-4 * sin(PI * i / ne));
    }
    return 0;
}

/* Samples of one run: the transverse displacement of the middle node (y),
   and with `all` set by the caller before the run (ms_freq_run's keep)
   every node's position in the frame of the vibration plane, r[3 (s nn +
   i) + k] at sample s, node i: k = 0 axial, 1 transverse in the plane of
   vibration, 2 out of that plane (0 in a planar chain), and the largest
   |out-of-plane| position or slope and |theta| (3D) over the run. */
typedef struct ms_obs {
    int idx;        /* coordinate observed (transverse, middle node) */
    size_t n, cap;
    double *y;
    int all;        /* in: record r, oop, th                         */
    const ms_model *m;
    double *r;
    double oop, th;
} ms_obs;

static inline vlbe_status ms_observe(void *ctx, double t, const vlbe_real *q, const vlbe_real *v,
                                     const vlbe_real *lam)
{
    ms_obs *o = (ms_obs *)ctx;
    (void)t, (void)v, (void)lam;
    if (o->n >= o->cap) return VLBE_OK;
    if (o->r) {
        const ms_model *m = o->m;
        const int d = m->ch.d, nn = m->ne + 1, tr = m->tr, oo = 3 - tr;
        int i;
        for (i = 0; i < nn; ++i) {
            const int a = m->node[i].ofs;
            double *ri = o->r + 3 * (o->n * (size_t)nn + (size_t)i);
            ri[0] = (double)q[a];
            ri[1] = (double)q[a + tr];
            ri[2] = d == 3 ? (double)q[a + oo] : 0.0;
            if (d == 3) {
                o->oop = fmax(o->oop, fmax(fabs(ri[2]), fabs((double)q[a + 3 + oo])));
                if (m->ch.spin) o->th = fmax(o->th, fabs((double)q[a + 6]));
            }
        }
    }
    o->y[o->n++] = (double)q[o->idx];
    return VLBE_OK;
}

/* One run: first frequency from the response of ne elements of the given
   kind (MS_*; 0 string, 1 beam) with step h over t_end (HHT family par);
   *cpu gets the run time, *stats the counters, *keep (if not NULL, zeroed
   by the caller, keep->all set for the whole history) the samples.
   Returns the frequency, or -1 on failure. */
static inline double ms_freq_run(int ne, int kind, double h, double t_end,
                                 const vlbe_hht_params *par, double *cpu, vlbe_dae_stats *stats,
                                 ms_obs *keep)
{
    const int bend = kind & MS_BEND;
    ms_model *m = (ms_model *)malloc(sizeof *m);
    vlbe_real *q0 = NULL, *v0 = NULL;
    double f = -1.0, *w = NULL;
    ex_method meth;
    ex_run_out out;
    ms_obs o;
    memset(&o, 0, sizeof o);
    memset(&meth, 0, sizeof meth);
    if (!m) return -1.0;
    q0 = (vlbe_real *)malloc(MS_NQ_NODE * (MS_NE_MAX + 1) * sizeof *q0);
    v0 = (vlbe_real *)malloc(MS_NQ_NODE * (MS_NE_MAX + 1) * sizeof *v0);
    o.cap = (size_t)(t_end / h + 2.5);
    o.y = (double *)malloc(o.cap * sizeof *o.y);
    w = (double *)malloc(o.cap * sizeof *w);
    if (keep && keep->all) {
        o.r = (double *)malloc(3 * (size_t)(ne + 1) * o.cap * sizeof *o.r);
        if (!o.r) o.cap = 0; /* nothing to record into: fail below */
    }
    if (q0 && v0 && o.y && w && o.cap && ms_build(m, ne, kind, q0, v0) == 0) {
        o.idx = m->node[ne / 2].ofs + m->tr;
        o.m = m;
        meth.hht = par;
        meth.h = h;
        if (ex_run(&m->sys, &meth, q0, v0, t_end, ms_observe, &o, NULL, NULL, NULL, &out) ==
            VLBE_OK)
            f = ex_peak_freq(o.y, o.n, h, bend ? 20.0 : 12.0, bend ? 45.0 : 33.0, w);
        if (cpu) *cpu = out.cpu;
        if (stats) *stats = out.stats;
    }
    o.m = NULL; /* freed below */
    if (keep && f > 0) {
        o.all = keep->all;
        *keep = o;
        o.y = NULL;
        o.r = NULL;
    }
    free(o.y);
    free(o.r);
    free(w);
    free(q0);
    free(v0);
    free(m);
    return f;
}

/* Richardson-extrapolated frequency from steps h and h/2. */
static inline double ms_freq(int ne, int kind, double h, double t_end, double *cpu,
                             vlbe_dae_stats *st)
{
    vlbe_hht_params par;
    double c1 = 0, c2 = 0, f1, f2;
    vlbe_hht_params_genalpha(&par, VLBE_R(0.9));
    f1 = ms_freq_run(ne, kind, h, t_end, &par, &c1, NULL, NULL);
    f2 = ms_freq_run(ne, kind, 0.5 * h, t_end, &par, &c2, st, NULL);
    if (cpu) *cpu = c1 + c2;
    if (f1 < 0 || f2 < 0) return -1.0;
    return f2 + (f2 - f1) / 3.0;
}

/* Two models of one scene, same ne, h, t_end and integrator (generalized-
   alpha rho 0.9), sample by sample: d[k] = max |r_a - r_b| over the nodes
   and samples per component (axial, transverse, out of plane; see ms_obs),
   amax[k] = max |r_b|, oop and th of run a, both frequencies, CPU times. */
typedef struct ms_cmp {
    double d[3], amax[3];
    double oop, th;
    double fa, fb, cpu_a, cpu_b;
    size_t n;
} ms_cmp;

static inline int ms_compare(int ne, int kind_a, int kind_b, double h, double t_end, ms_cmp *c)
{
    vlbe_hht_params par;
    ms_obs a, b;
    size_t s;
    int rc = -1, k;
    memset(c, 0, sizeof *c);
    memset(&a, 0, sizeof a);
    memset(&b, 0, sizeof b);
    a.all = b.all = 1;
    vlbe_hht_params_genalpha(&par, VLBE_R(0.9));
    c->fa = ms_freq_run(ne, kind_a, h, t_end, &par, &c->cpu_a, NULL, &a);
    c->fb = ms_freq_run(ne, kind_b, h, t_end, &par, &c->cpu_b, NULL, &b);
    if (c->fa > 0 && c->fb > 0 && a.n == b.n) {
        c->n = a.n;
        for (s = 0; s < 3 * (size_t)(ne + 1) * a.n; ++s) {
            k = (int)(s % 3);
            c->d[k] = fmax(c->d[k], fabs(a.r[s] - b.r[s]));
            c->amax[k] = fmax(c->amax[k], fabs(b.r[s]));
        }
        c->oop = a.oop;
        c->th = a.th;
        rc = 0;
    }
    free(a.y);
    free(a.r);
    free(b.y);
    free(b.r);
    return rc;
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
    ms_chart(dir);
    return 0;
}
#endif

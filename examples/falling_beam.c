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
   the paper.  Length control keeps every element in [0.5, 1.5] L_std;
   after a change the integrator restarts from the mapped state (positions
   and velocities exact, accelerations consistent again).  The run ends
   when the element ahead of the mass is shorter than 1e-3 L_std: the mass
   leaves the beam at the free end (the paper: between 0.6 s and 0.7 s); the
   time is extrapolated linearly to p = L.

   Output rows ROW|falling|... and out/falling_beam_<N>.csv (t, tip y,
   mass x, y, p).

   STATUS (work in progress): with 5 and 10 elements the mass reaches the
   last element and leaves at 0.57 s and 0.51 s (the paper: 0.6-0.7 s);
   with 20-40 elements Newton diverges (an iterate inverts the element
   behind the mass) at p = 0.86-0.92 m, t ~ 0.48 s, ~3 m/s sliding speed.
   Under investigation; the rows say so. */
#include "../ancf_ale.h"
#include "ex_ale.h"
#include "ex_run.h"

#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#define FB_L 1.0
#define FB_R 0.01
#define FB_RHO 7200.0
#define FB_E 20e6
#define FB_G 9.81
#define FB_MASS 0.8
#define FB_P0 0.1
#define FB_V0 0.4
#define FB_NMAX 64

typedef struct fb_result {
    vlbe_status status;
    double t_leave;   /* time the mass leaves the beam (extrapolated), -1 if not */
    double cpu, cpu_lc;
    long steps, lc_events, newton, lu;
    double tip_y_end; /* tip deflection at the end of the run */
    double p_stop;    /* material coordinate of the mass when the run stopped */
} fb_result;

typedef struct fb_model {
    vlbe_ale_mat mat;
    vlbe_ale_elem el;
    vlbe_ale_node node[FB_NMAX + 2];
    vlbe_ale_con con[2];
    vlbe_ale_chain ch;
    vlbe_dae sys;
    int slider;
    double Lstd;
} fb_model;

static inline void fb_wire(fb_model *m) { ex_ale_wire(&m->sys, &m->ch); }

static inline int fb_build(fb_model *m, int N, vlbe_real *q0, vlbe_real *v0)
{
    const double PI = 3.14159265358979323846, A = PI * FB_R * FB_R;
    vlbe_real r0[2] = {0, 0}, dir[2] = {1, 0};
    vlbe_ale_con c;
    int i, ks;
    if (N < 2 || N > FB_NMAX) return -1;
    memset(m, 0, sizeof *m);
    m->mat.rhoA = (vlbe_real)(FB_RHO * A);
    m->mat.EA = (vlbe_real)(FB_E * A);
    m->mat.EI = (vlbe_real)(FB_E * PI * FB_R * FB_R * FB_R * FB_R / 4.0);
    m->mat.f[1] = (vlbe_real)(-FB_G * FB_RHO * A);
    if (vlbe_ale_elem_init(&m->el, &m->mat, VLBE_ALE_NO_DAMP, 0, 0, 0)) return -1;
    m->Lstd = FB_L / N;
    ks = (int)floor(FB_P0 / m->Lstd + 0.5);
    if (ks < 1) ks = 1;
    for (i = 0; i <= N; ++i) {
        m->node[i].pmode = VLBE_ALE_PFIXED;
        m->node[i].p = (vlbe_real)(i * m->Lstd);
    }
    m->node[ks].pmode = VLBE_ALE_PFREE;
    m->node[ks].p = (vlbe_real)FB_P0;
    m->node[ks].mass = (vlbe_real)FB_MASS;
    m->slider = ks;
    if (vlbe_ale_chain_init(&m->ch, &m->el, m->node, N + 1, FB_NMAX + 2, m->con, 2)) return -1;
    m->ch.g[1] = (vlbe_real)-FB_G;
    memset(&c, 0, sizeof c);
    c.type = VLBE_ALE_CON_POS; /* clamp: position ... */
    vlbe_ale_chain_add(&m->ch, &c);
    c.type = VLBE_ALE_CON_SLOPE_DIR; /* ... and slope direction (1, 0) */
    c.v[0] = 1;
    vlbe_ale_chain_add(&m->ch, &c);
    if (vlbe_ale_chain_layout(&m->ch)) return -1;
    fb_wire(m);
    vlbe_ale_chain_straight(&m->ch, r0, dir, q0);
    for (i = 0; i < m->ch.n; ++i) v0[i] = 0;
    /* the mass slides at 0.4 m/s over the resting beam: p' = 0.4, r' = p' r'(p) */
    v0[m->node[ks].ofs] = (vlbe_real)FB_V0;
    v0[m->node[ks].ofs + 4] = (vlbe_real)FB_V0;
    return 0;
}

/* Runs N elements with HHT step h up to the mass leaving (or t_end);
   csv: optional file for the histories. */
static inline fb_result fb_run(int N, double h, double t_end, FILE *csv)
{
    fb_result res;
    fb_model *m = (fb_model *)malloc(sizeof *m);
    const int nmax = 5 * (FB_NMAX + 2);
    vlbe_real *q = (vlbe_real *)malloc((size_t)(4 * nmax) * sizeof *q);
    vlbe_real *v = q ? q + nmax : NULL, *qn = q ? q + 2 * nmax : NULL, *vn = q ? q + 3 * nmax : NULL;
    vlbe_hht_params par;
    vlbe_hht st;
    size_t lw = vlbe_hht_work_len(nmax, 2), liw = vlbe_hht_iwork_len(nmax, 2);
    vlbe_real *w = (vlbe_real *)malloc(lw * sizeof *w);
    int *iw = (int *)malloc(liw * sizeof *iw);
    double t = 0.0;
    clock_t c0 = clock();
    memset(&res, 0, sizeof res);
    res.t_leave = -1.0;
    res.status = VLBE_EWORK;
    if (!m || !q || !w || !iw || fb_build(m, N, q, v)) goto done;
    vlbe_hht_params_hht(&par, VLBE_R(-0.05));
    par.max_halvings = 8;
    res.status = vlbe_hht_init(&st, &m->sys, &par, 0, q, v, w, lw, iw, liw);
    while (res.status == VLBE_OK && t < t_end) {
        const int ps = m->node[m->slider].ofs + 4;
        double ps_now, Lahead;
        int changed = 0;
        if ((res.status = vlbe_hht_step(&st, (vlbe_real)h)) != VLBE_OK) {
            /* the element ahead of the mass, the last one, collapsed inside
               a Newton iteration: the mass is at the free end */
            res.p_stop = (double)st.q[ps];
            if (res.status == VLBE_ECALLBACK && m->ch.err == VLBE_ELENGTH &&
                m->slider + 1 == m->ch.nn - 1 && st.v[ps] > 0) {
                res.t_leave = t + (FB_L - res.p_stop) / (double)st.v[ps];
                res.status = VLBE_OK;
            }
            break;
        }
        t = (double)st.t;
        res.steps++;
        ps_now = (double)st.q[ps];
        if (csv) {
            vlbe_real tip[2];
            const double ty = vlbe_ale_chain_point(&m->ch, st.t, st.q, (vlbe_real)FB_L, tip, NULL)
                                  ? (double)NAN
                                  : (double)tip[1];
            fprintf(csv, "%.6f,%.9g,%.9g,%.9g,%.9g\n", t, ty,
                    (double)st.q[m->node[m->slider].ofs], (double)st.q[m->node[m->slider].ofs + 1],
                    ps_now);
        }
        Lahead = (double)m->node[m->slider + 1].p - ps_now;
        if (m->slider + 1 == m->ch.nn - 1 && Lahead < 1e-3 * m->Lstd) {
            /* linear extrapolation of p(t) to the end of the beam */
            res.p_stop = ps_now;
            res.t_leave = st.v[ps] > 0 ? t + (FB_L - ps_now) / (double)st.v[ps] : t;
            break;
        }
        {
            clock_t c1 = clock();
            vlbe_vec_copy(m->ch.n, st.q, q);
            vlbe_vec_copy(m->ch.n, st.v, v);
            res.status = vlbe_ale_chain_length_control(&m->ch, &m->slider, (vlbe_real)m->Lstd,
                                                       st.t, q, v, qn, vn, &changed);
            if (res.status == VLBE_OK && changed) {
                /* the counters of st restart with it: bank them first */
                res.newton += st.stats.newton_iters;
                res.lu += st.stats.lu_factors;
                fb_wire(m);
                res.lc_events++;
                res.status = vlbe_hht_init(&st, &m->sys, &par, (vlbe_real)t, qn, vn, w, lw, iw, liw);
            }
            res.cpu_lc += (double)(clock() - c1) / CLOCKS_PER_SEC;
        }
    }
    if (res.status == VLBE_OK || res.steps > 0) {
        vlbe_real tip[2];
        res.newton += st.stats.newton_iters;
        res.lu += st.stats.lu_factors;
        if (vlbe_ale_chain_point(&m->ch, st.t, st.q, (vlbe_real)FB_L, tip, NULL) == VLBE_OK)
            res.tip_y_end = (double)tip[1];
    }
done:
    res.cpu = (double)(clock() - c0) / CLOCKS_PER_SEC;
    free(m);
    free(q);
    free(w);
    free(iw);
    return res;
}

#ifndef VLBE_EXAMPLE_NO_MAIN
#include "../bench/svgplot.h"

int main(int argc, char **argv)
{
    const char *dir = argc > 1 ? argv[1] : "out";
    static const int Ns[5] = {5, 10, 20, 30, 40};
    static const double paper_motion[5] = {34.6, 58.3, 103.1, 192.4, 325.0};
    const double h = 1e-3;
    char path[512], qty[160];
    int k;
    printf("# falling cantilever with a sliding mass (ale-rancf 6.1), ALE-ANCF, HHT-alpha -0.05, "
           "h = %g s, length control at 1.5 L_std\n", h);
    for (k = 0; k < 5; ++k) {
        FILE *f;
        fb_result r;
        snprintf(path, sizeof path, "%s/falling_beam_%d.csv", dir, Ns[k]);
        f = fopen(path, "w");
        if (f) fprintf(f, "t_s,tip_y_m,mass_x_m,mass_y_m,mass_p_m\n");
        r = fb_run(Ns[k], h, 1.0, f);
        if (f) fclose(f);
        printf("# N = %d: status %s, run stopped with the mass at p = %.4f m, leaves at t = %.4f s "
               "(extrapolated), %ld steps, %ld Newton iterations, %ld LU, %ld length-control "
               "events, cpu %.3f s (length control %.4f s)\n",
               Ns[k], vlbe_status_str(r.status), r.p_stop, r.t_leave, r.steps, r.newton, r.lu,
               r.lc_events, r.cpu, r.cpu_lc);
        if (r.t_leave > 0)
            snprintf(qty, sizeof qty, "mass leaves the beam, %d elements [s] (paper 0.6-0.7)",
                     Ns[k]);
        else
            snprintf(qty, sizeof qty, "mass leaves the beam, %d elements [s]: NOT REACHED, %s at "
                     "p = %.3f m", Ns[k], vlbe_status_str(r.status), r.p_stop);
        svgp_compare_row(stdout, "falling", qty, 0.65, r.t_leave > 0 ? r.t_leave : (double)NAN,
                         (double)NAN, r.cpu);
        snprintf(qty, sizeof qty, "wall time to the mass leaving, %d elements [s] (paper Table 1 "
                 "motion time)", Ns[k]);
        svgp_compare_row(stdout, "falling", qty, paper_motion[k], r.cpu, (double)NAN, r.cpu);
    }
    return 0;
}
#endif

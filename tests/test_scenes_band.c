/* test_scenes_band.c -- every paper scene with chains or beams, dense and
   banded (vlbe_dae.storage = VLBE_DAE_BANDED through the scenes' band
   switches): the two runs must agree to rounding.
   -- part of vlbe                                  SPDX-License-Identifier: MIT
   cc -std=c99 -Wall -Wextra -Wpedantic ... -O2 tests/test_scenes_band.c -lcmocka -lm

   Each test runs a shortened scene (a fraction of the paper's time span,
   a small mesh) twice, dense and banded, from the same start, and
   compares what the scene records: the states of every step (or the
   scene's own outputs), relative to their amplitude.

   The bound.  The callbacks fill the same entries in both storages (the
   element sums are the same; band assembly is checked entry by entry in
   test_chain_ale.c, test_cr2d_band.c), so the two runs differ only where
   the linear algebra rounds differently: the band LU eliminates in the
   augmented order (constraint rows between the coordinates) with its own
   pivot choices, the products with M and C_q run over bands, and missing
   Jacobians are differenced over column groups.  A linear solve with LU
   and partial pivoting is backward stable; two factorizations of one
   matrix give solutions that differ by about kappa EPS of the solution,
   kappa the condition the pivots meet.  In these beams the spread of the
   stiffness is that of an element's axial over its bending stiffness,
   (EA / Le) / (EI / Le^3) = EA Le^2 / EI (a rounding EPS of an axial
   force, relative, is kappa EPS of a bending one): kappa = EA Le^2 / EI
   with the longest element Le of the run (prestressed strings: 1 / eps
   of the prestretch, test_scenes_moving3d.c).  Newton corrects the
   increments, and while both runs take the same decisions (the counters
   of steps, rejections, Newton iterations and factorizations equal) the
   iterates differ by such roundings only; each step adds at most kappa
   EPS of the state, and a stable integrator carries the differences on
   without amplifying them beyond linear growth: over N steps
        |x_band - x_dense| <= N kappa EPS max|x|.
   Where a convergence test flips (one more Newton iteration in one run)
   the state moves by less than the Newton tolerance, rtol |x| + atol,
   which is added per flip.  The differences sit far below these bounds
   (most scenes agree bit for bit: the pivots and the sums happen to be
   the same); each is printed beside its bound with VLBE_TEST_REPORT=1.
   The largest in double, the co-rotational sliding beam of case (a),
   is 9.0e3 (m~:sbeam_a) EPS of max|q| against a bound of 2.5e6 EPS; the
   ANCF spin-up's 36 (m~:spin_gauss) EPS against 1.6e6 EPS.  The
   counters are asserted equal in double (no decision flipped); in float
   they are not (its roundings sit at the Newton tolerances and decisions
   flip), and the bound, N kappa FLT_EPSILON, is loose there (0.2 of the
   state in the spin-up; the runs agree to a few 1e-5).

   Tests (dbl -O2: 1-2 s; valgrind under 2 min)
     spin_ancf       ex_spin.h, ANCF beam of 8 elements, W = 6 rad/s with a
                     4 s spin-up, 2.5 s: the three force routes (Gauss,
                     element and system invariants), Kelvin-Voigt damping,
                     absolute damping -abs_a M v and -abs_b K0 v (the
                     latter 0.3 s: it folds the beam, spin_damping.c)
     spin_bdf        the same beam with BDF (order 2, rtol 1e-6), compared
                     at its output times
     spin_cr         the co-rotational beam (nonlinear; with Rayleigh
                     damping) and the LINEAR element in the hub frame (W =
                     2): vlbe_cr2d_beam_band
     slide           ex_slide.h with length control (the chain re-layouts,
                     the workspace is that of the largest chain): the
                     falling beam (5 elements to the mass leaving; 20
                     elements, 0.25 s, ALE-ANCF and ALE-RANCF), the
                     suspended beam (3 elements, 0.3 s), the semicircle
                     (8 rational arcs, 0.2 s)
     moving          moving_string.c (MS_BAND), 4 elements, 0.1 s: planar
                     string and beam, 3D beam, 3D string without the spin
                     angle; histories and the frequencies of them
     torsion         shaft_torsion.c (st_history_run), 4 elements, 10 ms
     shaft           spinning_shaft.c (ss_band), case a = 0.5, 4 elements,
                     500 steps over the traverse
     sliding_beam    ex_sbeam.h (sb_cfg.band): case (a) 0.2 s, case (b)
                     0.45 s with 4 restarts at node crossings (the re-layout
                     keeps the beam banded)
     xcheck_ale      ex_xcheck.h's ALE-ANCF model of the sliding beam
                     (sb_cfg.band), 10 elements, 0.1 s, static start and
                     impulse included
     rollup          corot_static.c (cs_band): the static roll-up, 8
                     elements, 8 load steps (vlbe_dae_static banded)
   Float: the shortened runs that run in float with dense matrices run
   here too (ANCF spin-up, sliding mass, moving string, torsion, roll-up
   with the float section of test_scenes_cr2d.c); the others skip with the
   reason. */
#include "test_util.h"

#include "../scenes/spin_up.h"
#include "../scenes/falling_beam.h"
#include "../scenes/semicircle.h"
#include "../scenes/moving_string.h"
#include "../scenes/shaft_torsion.h"
#include "../scenes/spinning_shaft.h"
#include "../scenes/ex_xcheck.h"
#include "../scenes/corot_static.h"

#define EPS ((double)VLBE_EPS)
#define IS_FLOAT ((double)VLBE_EPS > 1e-10)

/* kappa of the header: axial over bending stiffness of an element */
static double kappa_beam(double EA, double EI, double Le) { return EA * Le * Le / EI; }

/* One comparison: d = max |banded - dense| over what is compared, amp its
   max |dense|, tol the bound relative to amp; printed, measured (key, in
   EPS of amp), asserted. */
static void check(const char *name, const char *key, double d, double amp, double tol)
{
    assert_true(amp > 0.0);
    tu_report(name, d / amp, tol);
    tu_measured(key, d / amp / EPS);
    ASSERT_CLOSE(d, 0.0, 0.0, tol * amp);
}

/* The counters of the two runs (double only, see the header): equal but
   newton_iters, which may differ by `flips` (constraint calls are not
   compared: the banded path differences missing constraint Jacobians by
   column groups, fewer calls). */
static void counters(const char *what, const vlbe_dae_stats *a, const vlbe_dae_stats *b, long flips)
{
    if (tu_report_on())
        print_message("    %s: steps %ld/%ld, rejected %ld/%ld, Newton %ld/%ld, LU %ld/%ld\n", what,
                      a->steps, b->steps, a->rejected, b->rejected, a->newton_iters,
                      b->newton_iters, a->lu_factors, b->lu_factors);
    if (IS_FLOAT) return;
    assert_int_equal(a->steps, b->steps);
    assert_int_equal(a->rejected, b->rejected);
    assert_int_equal(a->newton_fails, b->newton_fails);
    assert_int_equal(a->jac_evals, b->jac_evals);
    assert_int_equal(a->lu_factors, b->lu_factors);
    assert_true(labs(a->newton_iters - b->newton_iters) <= flips);
    if (flips == 0) {
        assert_int_equal(a->newton_iters, b->newton_iters);
        assert_int_equal(a->lu_solves, b->lu_solves);
        assert_int_equal(a->force_calls, b->force_calls);
        assert_int_equal(a->mass_calls, b->mass_calls);
    }
}

/* -- a history of states: q (n <= HMAX_N) after every accepted step ------ */
#define HMAX_N 200
typedef struct hist {
    int n, len, cap;
    double *x;
} hist;

static void hist_init(hist *h, int cap)
{
    memset(h, 0, sizeof *h);
    h->cap = cap;
    h->x = (double *)calloc((size_t)cap * HMAX_N, sizeof *h->x);
    assert_non_null(h->x);
}

static void hist_add(hist *h, int n, const vlbe_real *q)
{
    int i;
    assert_true(n <= HMAX_N);
    assert_true(h->len < h->cap);
    if (h->len == 0) h->n = n;
    assert_int_equal(n, h->n);
    for (i = 0; i < n; ++i) h->x[(size_t)h->len * (size_t)n + (size_t)i] = (double)q[i];
    h->len++;
}

/* max |b - a| and max |a| over the histories (same length, same n) */
static void hist_cmp(const hist *a, const hist *b, double *d, double *amp)
{
    size_t k;
    assert_int_equal(a->len, b->len);
    assert_int_equal(a->n, b->n);
    *d = *amp = 0.0;
    for (k = 0; k < (size_t)a->len * (size_t)a->n; ++k) {
        *d = fmax(*d, fabs(b->x[k] - a->x[k]));
        *amp = fmax(*amp, fabs(a->x[k]));
    }
}

static void hist_free(hist *h)
{
    free(h->x);
    memset(h, 0, sizeof *h);
}

/* ======================================================================= */
/* spin-up (scenes/ex_spin.h; spin_up.c, spin_damping.c)                  */
/* ======================================================================= */
static sp_model g_sp;

static void sp_hist_add(void *ctx, const sp_model *m, double t, const double *tip,
                        const vlbe_real *q, const vlbe_real *v)
{
    (void)t, (void)tip, (void)v;
    hist_add((hist *)ctx, m->n, q);
}

/* The scene shortened: 8 elements, W with a 4 s spin-up, run 2.5 s (HHT
   at the scene's h = 5 ms: 500 steps), no bound. */
static void spin_cfg(sp_cfg *c, double W, int model)
{
    sp_cfg_default(c, W, model);
    c->ne = 8;
    c->Ts = 4.0;
    c->t_end = 2.5;
    c->bound = 0.0;
}

/* Dense and banded runs of c; HHT: every step's q, BDF: the tip at its
   output times (a BDF run's step sizes are continuous functions of its
   error estimates, which the two runs round differently: the steps land
   at different times in between, on the same output times). */
static void spin_case(const char *what, const char *key, sp_cfg c)
{
    /* the beam of the scene: EA = 2.8e7 N, EI = 1.4e4 N m^2, Le = L / ne */
    const double kappa = kappa_beam(c.EA, c.EI, c.L / c.ne);
    hist a, b;
    sp_out oa, ob;
    double d = 0.0, amp = 0.0, steps;
    char name[96];
    int k;
    hist_init(&a, 600);
    hist_init(&b, 600);
    c.band = 0;
    sp_run(&g_sp, &c, c.bdf_rtol > 0.0 ? NULL : sp_hist_add, &a, &oa);
    c.band = 1;
    sp_run(&g_sp, &c, c.bdf_rtol > 0.0 ? NULL : sp_hist_add, &b, &ob);
    assert_int_equal(oa.status, VLBE_OK);
    assert_int_equal(ob.status, VLBE_OK);
    if (c.bdf_rtol > 0.0) {
        for (k = 0; k < SP_NS && SP_DTS * (k + 1) <= c.t_end + 1e-9; ++k) {
            d = fmax(d, hypot(ob.tip_s[k][0] - oa.tip_s[k][0], ob.tip_s[k][1] - oa.tip_s[k][1]));
            amp = fmax(amp, hypot(oa.tip_s[k][0], oa.tip_s[k][1]));
        }
    } else {
        hist_cmp(&a, &b, &d, &amp);
    }
    steps = (double)oa.stats.steps;
    snprintf(name, sizeof name, "spin %s: max |dq| / max |q|", what);
    check(name, key, d, amp, steps * kappa * EPS);
    counters(what, &oa.stats, &ob.stats, 0);
    hist_free(&a);
    hist_free(&b);
}

static void test_spin_ancf(void **state)
{
    sp_cfg c;
    (void)state;
    spin_cfg(&c, 6.0, SP_ANCF);
    spin_case("ancf gauss", "spin_gauss", c);
    c.inv = SP_INV_ELEM;
    spin_case("ancf element invariants", "spin_inv_elem", c);
    c.inv = SP_INV_SYS;
    spin_case("ancf system invariants", "spin_inv_sys", c);
    c.inv = SP_GAUSS;
    c.c_kv = 2.0 * 0.02 / sp_omega1(&c); /* spin_damping.c: zeta = 2 % */
    spin_case("ancf Kelvin-Voigt", "spin_kv", c);
    c.c_kv = 0.0;
    c.abs_a = 2.0 * 0.02 * sp_omega1(&c);
    spin_case("ancf abs. M", "spin_abs_m", c);
    c.abs_a = 0.0;
    c.abs_b = 2.0 * 0.02 / sp_omega1(&c);
    c.t_end = 0.3;
    spin_case("ancf abs. K0", "spin_abs_k0", c);
}

static void test_spin_bdf(void **state)
{
    sp_cfg c;
    (void)state;
    if (IS_FLOAT) TU_SKIP("float: the ANCF spin-up with BDF stops with VLBE_ESTEP, dense too");
    spin_cfg(&c, 6.0, SP_ANCF);
    c.bdf_rtol = 1e-6;
    c.bdf_max_order = 2;
    spin_case("ancf BDF", "spin_bdf", c);
}

static void test_spin_cr(void **state)
{
    sp_cfg c;
    (void)state;
    spin_cfg(&c, 6.0, SP_CR);
    spin_case("cr", "spin_cr", c);
    c.ray_b = 1e-3;
    spin_case("cr Rayleigh", "spin_cr_ray", c);
    spin_cfg(&c, 2.0, SP_LINEAR);
    spin_case("linear", "spin_linear", c);
}

/* ======================================================================= */
/* sliding mass with length control (scenes/ex_slide.h)                   */
/* ======================================================================= */
/* kappa of the scene's beam: its section, the longest element the length
   control lets through (1.5 L_std) */
static double slide_kappa(const ex_slide_cfg *c)
{
    const double PI = 3.14159265358979323846, L = c->R > 0.0 ? PI * c->R : c->L;
    const double EA = c->E * PI * c->r * c->r, EI = c->E * PI * pow(c->r, 4.0) / 4.0;
    return kappa_beam(EA, EI, 1.5 * L / c->N);
}

static void slide_case(const char *what, const char *key, ex_slide_cfg c)
{
    ex_slide_hist ha, hb;
    ex_slide_out oa, ob;
    const double kappa = slide_kappa(&c);
    double tol;
    /* the recorded columns (the length's rate is left out: a sum of
       products larger than itself) */
    const char *col[6] = {"probe y", "mass x", "mass y", "mass p", "energy", "arc length"};
    double *ca[6], *cb[6];
    char name[128], k2[64];
    int j, k;
    assert_int_equal(ex_slide_hist_alloc(&ha, (int)(c.t_end / c.h) + 16), 0);
    assert_int_equal(ex_slide_hist_alloc(&hb, (int)(c.t_end / c.h) + 16), 0);
    c.band = 0;
    oa = ex_slide_run(&c, &ha);
    c.band = 1;
    ob = ex_slide_run(&c, &hb);
    assert_int_equal(oa.status, VLBE_OK);
    assert_int_equal(ob.status, VLBE_OK);
    assert_true(oa.lc_events > 0); /* the window goes through the re-layout */
    tol = (double)oa.steps * kappa * EPS;
    if (tu_report_on())
        print_message("    %s: steps %ld/%ld, Newton %ld/%ld, LU %ld/%ld, rejected %ld/%ld, "
                      "length-control events %ld/%ld\n",
                      what, oa.steps, ob.steps, oa.newton, ob.newton, oa.lu, ob.lu, oa.rejected,
                      ob.rejected, oa.lc_events, ob.lc_events);
    assert_int_equal(ha.n, hb.n);
    ca[0] = ha.probe_y, ca[1] = ha.mass_x, ca[2] = ha.mass_y;
    ca[3] = ha.mass_p, ca[4] = ha.energy, ca[5] = ha.length;
    cb[0] = hb.probe_y, cb[1] = hb.mass_x, cb[2] = hb.mass_y;
    cb[3] = hb.mass_p, cb[4] = hb.energy, cb[5] = hb.length;
    for (j = 0; j < 6; ++j) {
        double d = 0.0, amp = 0.0;
        for (k = 0; k < ha.n; ++k) {
            d = fmax(d, fabs(cb[j][k] - ca[j][k]));
            amp = fmax(amp, fabs(ca[j][k]));
        }
        snprintf(name, sizeof name, "%s: %s", what, col[j]);
        snprintf(k2, sizeof k2, "%s_%d", key, j);
        check(name, k2, d, amp, tol);
    }
    if (c.support == EX_SLIDE_CLAMP_FREE && oa.t_leave > 0.0) {
        snprintf(name, sizeof name, "%s: leaving time", what);
        snprintf(k2, sizeof k2, "%s_leave", key);
        check(name, k2, fabs(ob.t_leave - oa.t_leave), oa.t_leave, tol);
    }
    if (!IS_FLOAT) { /* the same decisions: the same events at the same steps */
        assert_int_equal(oa.lc_events, ob.lc_events);
        assert_int_equal(oa.nev, ob.nev);
        for (k = 0; k < oa.nev; ++k)
            assert_true(oa.ev[k].t == ob.ev[k].t && oa.ev[k].changed == ob.ev[k].changed);
        assert_int_equal(oa.steps, ob.steps);
        assert_int_equal(oa.newton, ob.newton);
        assert_int_equal(oa.lu, ob.lu);
        assert_int_equal(oa.rejected, ob.rejected);
    }
    ex_slide_hist_free(&ha);
    ex_slide_hist_free(&hb);
}

static void test_slide(void **state)
{
    ex_slide_cfg c;
    (void)state;
    fb_cfg(&c, 5, 0u, 1e-3); /* falling_beam.c: to the mass leaving */
    slide_case("falling beam", "fb5", c);
    fb_cfg(&c, 20, 0u, 1e-3);
    c.t_end = 0.25;
    slide_case("falling beam 20", "fb20", c);
    c.rational = 1;
    slide_case("falling beam 20 rational", "fb20r", c);
    /* suspended_beam.c's scene (its sb_cfg, whose name ex_sbeam.h takes) */
    ex_slide_cfg_paper(&c, 3, EX_SLIDE_PIN_PIN, 5.0, 0.1, 0.0);
    c.t_end = 0.3;
    slide_case("suspended beam", "susp", c);
    sc_cfg(&c, 8, 1, 1e-3);
    c.t_end = 0.2;
    slide_case("semicircle", "semi", c);
}

/* ======================================================================= */
/* moving string and beam (examples/moving_string.c)                        */
/* ======================================================================= */
static void ms_case(const char *what, const char *key, int kind)
{
    const double h = 2e-4, T = 0.1;
    vlbe_hht_params par;
    ms_obs a, b;
    vlbe_dae_stats sa, sb;
    double rhoA, EA, EI, eps, lam, kappa, fa, fb, tol, d[2] = {0, 0}, amp[2] = {0, 0};
    char name[128], k2[64];
    size_t s;
    memset(&a, 0, sizeof a);
    memset(&b, 0, sizeof b);
    a.all = b.all = 1;
    ms_section(&rhoA, &EA, &EI, &eps, &lam);
    kappa = fmax(1.0 / eps, (kind & MS_BEND) ? kappa_beam(EA, EI, MS_L / 4.0) : 0.0);
    vlbe_hht_params_genalpha(&par, VLBE_R(0.9));
    fa = ms_freq_run(4, kind, h, T, &par, NULL, &sa, &a);
    fb = ms_freq_run(4, kind | MS_BAND, h, T, &par, NULL, &sb, &b);
    assert_true(fa > 0.0 && fb > 0.0);
    assert_true(a.n == b.n && a.n > 0);
    for (s = 0; s < 3 * 5 * a.n; ++s)
        if (s % 3 < 2) {
            d[s % 3] = fmax(d[s % 3], fabs(b.r[s] - a.r[s]));
            amp[s % 3] = fmax(amp[s % 3], fabs(a.r[s]));
        }
    tol = (double)sa.steps * kappa * EPS;
    snprintf(name, sizeof name, "moving %s: axial", what);
    snprintf(k2, sizeof k2, "%s_ax", key);
    check(name, k2, d[0], amp[0], tol);
    snprintf(name, sizeof name, "moving %s: transverse", what);
    snprintf(k2, sizeof k2, "%s_tr", key);
    check(name, k2, d[1], amp[1], tol);
    /* the frequency of two histories that agree to tol: a phase drift of
       tol over the record's 2 pi f T radians, plus the estimator's floor
       1e-7 (test_scenes_moving3d.c) */
    snprintf(name, sizeof name, "moving %s: f1", what);
    snprintf(k2, sizeof k2, "%s_f", key);
    check(name, k2, fabs(fb - fa), fa, 1e-7 + tol / (2.0 * 3.14159265358979323846 * fa * T));
    counters(what, &sa, &sb, 0);
    free(a.y), free(a.r), free(b.y), free(b.r);
}

static void test_moving(void **state)
{
    (void)state;
    ms_case("string", "ms_string", 0);
    ms_case("beam", "ms_beam", MS_BEND);
    ms_case("3D beam", "ms_beam3", MS_3D | MS_BEND);
    ms_case("3D string without spin", "ms_string3", MS_3D | MS_NOSPIN);
}

/* ======================================================================= */
/* free torsion of a shaft (examples/shaft_torsion.c)                       */
/* ======================================================================= */
static void test_torsion(void **state)
{
    /* 4 elements of l/4, r = 5 mm: EA Le^2 / EI = 4 Le^2 / r^2 */
    const double kappa = 4.0 * (ST_L / 4.0) * (ST_L / 4.0) / (ST_R * ST_R);
    st_hist a, b;
    double d = 0, amp = 0;
    size_t k;
    (void)state;
    assert_int_equal(st_history_run(4, ST_DT, 10, 0.01, 0, &a), VLBE_OK);
    assert_int_equal(st_history_run(4, ST_DT, 10, 0.01, 1, &b), VLBE_OK);
    assert_true(a.n == b.n && a.n > 0);
    for (k = 0; k < a.n; ++k) {
        d = fmax(d, fabs(b.y[k] - a.y[k]));
        amp = fmax(amp, fabs(a.y[k]));
    }
    check("torsion: free-end twist", "torsion", d, amp, (double)a.stats.steps * kappa * EPS);
    counters("torsion", &a.stats, &b.stats, 0);
    free(a.y);
    free(b.y);
}

/* ======================================================================= */
/* spinning shaft under a travelling load (examples/spinning_shaft.c)       */
/* ======================================================================= */
static ss_scene g_ssa, g_ssb;

static void test_shaft(void **state)
{
    vlbe_real q0[SS_NE_MAX * 8 + 8], v0[SS_NE_MAX * 8 + 8];
    ss_err ea, eb;
    ex_run_out oa, ob;
    double d = 0, amp = 0, kappa;
    int i, k;
    (void)state;
    if (IS_FLOAT)
        TU_SKIP("float: the scene's HHT Newton iteration fails, dense too (test_scenes_shaft.c)");
    assert_int_equal(ss_run(&g_ssa, 0.5, 1.0, 4, 0, SS_Z0, 500, -0.05, 30, &ea, NULL, &oa),
                     VLBE_OK);
    assert_int_equal(ss_setup(&g_ssb, 0.5, 1.0, 4, 0, SS_Z0, q0, v0), 0);
    assert_int_equal(ss_band(&g_ssb), 0);
    assert_int_equal(g_ssb.sys.storage, VLBE_DAE_BANDED);
    assert_int_equal(ss_integrate(&g_ssb, q0, v0, 500, -0.05, 30, &eb, NULL, &ob), VLBE_OK);
    assert_int_equal(g_ssa.ns, g_ssb.ns);
    for (k = 0; k < 4; ++k)
        for (i = 0; i < g_ssa.ns; ++i) {
            d = fmax(d, fabs(g_ssb.u[k][i] - g_ssa.u[k][i]));
            amp = fmax(amp, fabs(g_ssa.u[k][i]));
        }
    /* the elements stretch up to half the shaft: Le <= l / 2 */
    kappa = 4.0 * (0.5 * SS_L) * (0.5 * SS_L) / (g_ssa.ref.r * g_ssa.ref.r);
    check("shaft: load point and midspan", "shaft", d, amp, (double)oa.stats.steps * kappa * EPS);
    counters("shaft", &oa.stats, &ob.stats, 0);
}

/* ======================================================================= */
/* sliding beam, co-rotational (ex_sbeam.h) and ALE-ANCF (ex_xcheck.h)      */
/* ======================================================================= */
static sb_model g_sb;

static void sb_hist_obs(void *ctx, const sb_model *m, double t, const vlbe_real *q,
                        const vlbe_real *v)
{
    (void)t, (void)v;
    hist_add((hist *)ctx, m->n, q);
}

/* kappa of the paper's section with elements of length Le */
static double sb_kappa(const sb_cfg *c, double Le) { return kappa_beam(c->A, c->I, Le); }

static void sbeam_case(const char *what, const char *key, char which, double T, long flips)
{
    sb_cfg c;
    sb_out oa, ob;
    hist a, b;
    double d, amp, Le, rtol;
    vlbe_hht_params par;
    char name[96];
    sb_cfg_paper(&c, which);
    c.t_end = T;
    Le = fmax((c.L - c.L0) / c.n_in, c.L0 / c.n_out);
    hist_init(&a, 600);
    hist_init(&b, 600);
    sb_run(&g_sb, &c, sb_hist_obs, &a, &oa);
    c.band = 1;
    sb_run(&g_sb, &c, sb_hist_obs, &b, &ob);
    assert_int_equal(oa.status, VLBE_OK);
    assert_int_equal(ob.status, VLBE_OK);
    assert_int_equal(oa.restarts, ob.restarts);
    hist_cmp(&a, &b, &d, &amp);
    ex_hht_pick(&par, c.alpha, c.rho_inf);
    rtol = (double)par.rtol + (double)par.atol / amp; /* a flipped Newton test (header) */
    snprintf(name, sizeof name, "sliding beam %s: max |dq| / max |q|", what);
    check(name, key, d, amp, (double)oa.stats.steps * sb_kappa(&c, Le) * EPS + (double)flips * rtol);
    counters(what, &oa.stats, &ob.stats, flips);
    hist_free(&a);
    hist_free(&b);
}

static void test_sliding_beam(void **state)
{
    (void)state;
    if (IS_FLOAT)
        TU_SKIP("float: the static start is singular (VLBE_ESINGULAR), dense too "
                "(test_scenes_sliding.c)");
    sbeam_case("(a)", "sbeam_a", 'a', 0.2, 0);
    /* (b): one Newton convergence test decides at its threshold (an
       increment within rounding of atol + rtol |x|): one more iteration in
       one of the runs */
    sbeam_case("(b)", "sbeam_b", 'b', 0.45, 1);
}

static void test_xcheck_ale(void **state)
{
    sb_cfg c;
    xc_hist a, b;
    xc_ale_out oa, ob;
    double d = 0, amp = 0, tol;
    int k;
    (void)state;
    if (IS_FLOAT)
        TU_SKIP("float: the static start is singular, dense too (test_sliding_xcheck.c)");
    sb_cfg_paper(&c, 'a');
    c.t_end = 0.1;
    assert_int_equal(xc_hist_alloc(&a, 1000), 0);
    assert_int_equal(xc_hist_alloc(&b, 1000), 0);
    oa = xc_ale_run(&c, 10, XC_START_IMPULSE, &a);
    c.band = 1;
    ob = xc_ale_run(&c, 10, XC_START_IMPULSE, &b);
    assert_int_equal(oa.status, VLBE_OK);
    assert_int_equal(ob.status, VLBE_OK);
    assert_int_equal(a.n, b.n);
    for (k = 0; k < a.n; ++k) {
        d = fmax(d, fabs(b.y[k] - a.y[k]));
        amp = fmax(amp, fabs(a.y[k]));
    }
    /* elements of at most L / 10 (the outside part is shorter than L) */
    tol = (double)oa.steps * sb_kappa(&c, c.L / 10.0) * EPS;
    check("xcheck ALE: tip", "xc_tip", d, amp, tol);
    check("xcheck ALE: static tip force", "xc_f0", fabs(ob.F0 - oa.F0), oa.F0, tol);
    if (tu_report_on())
        print_message("    xcheck: steps %ld/%ld, Newton %ld/%ld, LU %ld/%ld\n", oa.steps, ob.steps,
                      oa.newton, ob.newton, oa.lu, ob.lu);
    /* one Newton test decides within rounding of its threshold (the
       band's pivot order is not the dense one): one iteration and one
       refreshed matrix more or less in one run (681/680 and 682/681
       measured), at an iterate already converged to rounding (the tip
       agrees to 2.6e-15 m, far inside tol) */
    assert_int_equal(oa.steps, ob.steps);
    assert_true(labs(oa.newton - ob.newton) <= 1);
    assert_true(labs(oa.lu - ob.lu) <= 1);
    assert_int_equal(oa.rejected, ob.rejected);
    xc_hist_free(&a);
    xc_hist_free(&b);
}

/* ======================================================================= */
/* co-rotational roll-up, static (examples/corot_static.c)                  */
/* ======================================================================= */
static cs_model g_cs;

/* the model and the solver's parameters of test_scenes_cr2d.c's roll-up:
   the scene's (float: a softer section, the increment test at 1e-4; the
   reasons there) */
static int rollup_model(cs_model *m, int N, double *EA)
{
#ifdef VLBE_USE_FLOAT
    *EA = 1200.0 * cs_EI() / (CS_L * CS_L);
#else
    *EA = cs_EA();
#endif
    return cs_build_sec(m, N, 0u, *EA, cs_EI(), cs_rhoA());
}

static void test_rollup(void **state)
{
    enum { NE = 8, NSTEP = 8 };
    static vlbe_real qa[(NSTEP + 1) * 3 * (NE + 1)], qb[(NSTEP + 1) * 3 * (NE + 1)];
    vlbe_static_params par;
    vlbe_dae_stats sa, sb;
    double d = 0, amp = 0, EA = 0.0;
    size_t k;
    (void)state;
    vlbe_static_params_default(&par);
    par.max_halvings = 0;
#ifdef VLBE_USE_FLOAT
    par.rtol = par.atol = VLBE_R(1e-4);
#endif
    memset(&sa, 0, sizeof sa);
    memset(&sb, 0, sizeof sb);
    assert_int_equal(rollup_model(&g_cs, NE, &EA), 0);
    assert_int_equal(cs_rollup(&g_cs, NSTEP, &par, qa, &sa), VLBE_OK);
    assert_int_equal(rollup_model(&g_cs, NE, &EA), 0);
    assert_int_equal(cs_band(&g_cs), 0);
    assert_int_equal(g_cs.sys.storage, VLBE_DAE_BANDED);
    assert_int_equal(cs_rollup(&g_cs, NSTEP, &par, qb, &sb), VLBE_OK);
    for (k = 0; k < sizeof qa / sizeof qa[0]; ++k) {
        d = fmax(d, fabs((double)qb[k] - (double)qa[k]));
        amp = fmax(amp, fabs((double)qa[k]));
    }
    /* each load step solved to rounding from the previous one: N = NSTEP */
    check("rollup: every node, every load step", "rollup", d, amp,
          NSTEP * kappa_beam(EA, cs_EI(), CS_L / NE) * EPS);
    counters("rollup", &sa, &sb, 0);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_spin_ancf),    cmocka_unit_test(test_spin_bdf),
        cmocka_unit_test(test_spin_cr),
        cmocka_unit_test(test_slide),        cmocka_unit_test(test_moving),
        cmocka_unit_test(test_torsion),      cmocka_unit_test(test_shaft),
        cmocka_unit_test(test_sliding_beam), cmocka_unit_test(test_xcheck_ale),
        cmocka_unit_test(test_rollup),
    };
    return cmocka_run_group_tests_name("scenes_band", tests, NULL, NULL);
}

/* corot_static.c -- static checks of the planar co-rotational Euler beam of
   corot2d.h (Hsiao et al.): a cantilever rolled up into a circle by an end
   moment, the cantilever's natural frequencies from the linearised system
   at rest, and zero deformation force under rigid rotation of any number
   of turns.  -- part of vlbe                      SPDX-License-Identifier: MIT

   cc -O2 examples/corot_static.c -lm && ./a.out [outdir]

   The model and the three checks are scenes/corot_static.h (shared with
   the tests); this file prints the tables, rows and charts.

   Section of the paper's sliding beam (its section 5): A = 4.3434e-5 m^2,
   I = 1.059e-11 m^4, E = 68.96 GPa, rho = 3144.3858 kg/m^3 (EA = 2.995e6 N,
   EI = 0.7303 N m^2, rhoA = 0.13657 kg/m), rotary inertia rhoI = 0; a
   cantilever of L = 1 m along x, clamped at node 0 by the prescribed
   coordinates u = v = phi = 0 (vlbe_cr2d_fix), N equal elements.

   (a) Roll-up.  A moment M = lambda 2 pi EI / L on the tip's phi (beam.P,
   load factor beam.load = lambda) in NSTEP equal load steps, each solved
   by vlbe_dae_static (integrators.h) from the previous solution.  Exact
   (inextensible Euler beam, pure moment: zero axial force, constant
   curvature k = M / EI = 2 pi lambda / L): the arc r(s) = (sin ks, 1 -
   cos ks) / k, phi(s) = k s; at lambda = 1 the tip is back at the root
   with phi = 2 pi.
   The discrete solution in closed form (by hand from eq. 7 and eqs.
   16-17, used as a second reference): the free tip carries no force, so
   every element has zero axial force, EA eps0 = 0, no shear (g1 + g2 = 0
   in eqs. 16-17) and the end moment M = EI/L_e (2 theta1 + 4 theta2):
   theta2 = -theta1 = a/2 with a = k L_e exactly (the Hermite cubic holds a
   constant curvature), so the node rotations are exact, phi_i = i a.
   eps0 = 0 with eq. 7 fixes the chord, l = L_e (1 - a^2/24), so the nodes
   lie on a circle of radius
        R_d = l / (2 sin(a/2)) = R (1 - a^4/1920 + O(a^6)),   R = 1/k,
   at their exact angles: node i at R_d (sin(i a), 1 - cos(i a)).  The
   position error is (R - R_d) 2 sin(k s / 2): FOURTH order in the element
   length, not second: the quadratic term of eps0 (the int v'^2 of eq. 7)
   shortens the chord by exactly the a^2/24 that an arc's chord has.
   (An element with eps0 = (l - L)/L alone keeps l = L_e and has R_d = R
   (1 + a^2/24): second order.)  At lambda = 1 (N a = 2 pi) the polygon
   closes: the tip returns to the root to rounding for every N.
   The LINEAR element (VLBE_CR2D_LINEAR) for contrast: the tip deflects by
   M L^2 / (2 EI) = pi L laterally and does not move axially.

   (b) Natural frequencies of the cantilever from the linearised system at
   rest: K0 = -dQ/dq (vlbe_cr2d_beam_force_jac at q = 0, q' = 0) and M
   (vlbe_cr2d_beam_mass), the clamped coordinates removed, K0 x = w^2 M x
   (vlbe_eig_gsym of vlbe.h).  Bending modes against Euler-Bernoulli,
   w = (beta L)^2 sqrt(EI / (rhoA L^4)), beta L the roots of
   1 + cos(bL) cosh(bL) = 0 (computed here by Newton to full precision;
   1.8751, 4.6941, 7.8548 to five digits); the first axial mode against
   the rod, w = (pi/2) sqrt(EA / (rhoA L^2)).  At rest the frame is the
   reference frame and the axial and bending coordinates decouple: a mode
   is axial when its u components carry most of its M-norm.  The
   consistent-mass Hermite element converges as h^4 in frequency (from
   above: Rayleigh-Ritz), the linear axial element as h^2.
   Reduction: the eigenproblem is solved by shift-invert with sigma = 0
   (vlbe_eig_gsym: Jacobi on L^-1 M L^-T, K0 = L L^T, eigenvalues mu =
   1/w^2), so that the low modes are the LARGE eigenvalues of the reduced
   matrix.  Solved with a shift far below the spectrum instead (sigma =
   -max K0_ii / M_ii, what makes K0 - sigma M safely positive definite
   without knowing the spectrum, like the direct form K0 x = w^2 M x) the
   rounding is relative to |sigma|, of the order of the highest (axial)
   mode, 1e9 .. 1e11 times the fundamental's w^2 = 66: the last column of
   the table printed below shows w1's error of that form, off the shift-
   invert one by 1.5e-8 at N = 8 and 1.3e-6 at N = 64 (rounding-limited
   from N = 8 on).  The N = 64 w1
   is rounding-limited even with sigma = 0 (its h^4 error, 5e-10, is about
   the reduction's rounding).

   (c) Rigid rotation: the beam turned about a point by psi from -2 to +6
   turns (phi = psi, unbounded): Q is rounding.  Reported as the largest
   force component over EA (the strain that force would need) and the
   largest moment over EI / L_e (the deformation rotation it would need).

   Output rows ROW|corot static|..., a convergence table, out/corot_static_
   shapes.svg (deformed shapes at several load factors, 8 elements, and the
   exact arcs), out/corot_static_conv.svg (errors against N, log-log) and
   the CSV files corot_static_shapes.csv, corot_static_conv.csv. */
#include "../scenes/corot_static.h"
#include "../scenes/svgplot.h"

#define CS_NN 5      /* N = 4, 8, 16, 32, 64 */
#define CS_NSTEP 16  /* load steps of the roll-up */
#define CS_NLEV 4    /* load factors compared: 1/4, 1/2, 3/4, 1 */

static double cs_cpu(clock_t c0) { return (double)(clock() - c0) / (double)CLOCKS_PER_SEC; }

/* observed order between N and 2N: log2(e(N) / e(2N)) */
static double cs_order(double e1, double e2)
{
    return e1 > 0.0 && e2 > 0.0 ? log(e1 / e2) / log(2.0) : (double)NAN;
}

/* The deformed shapes of the 8-element beam at lambda = k / CS_NSTEP for
   the k in ks, drawn along each element's cubic (chord frame, lateral
   deflection L_e (N2 theta1 + N4 theta2) of eqs. 8-9 scaled by l / L_e:
   the element's own shape), with the exact arcs; SVG + CSV. */
static void cs_shapes(const char *dir, const cs_model *m, const vlbe_real *qh)
{
    enum { NK = 5, SUB = 8 };
    static const int ks[NK] = {2, 4, 8, 12, 16};
    static char names[NK][48];
    static double xs[NK][CS_NE_MAX * SUB + 1], ys[NK][CS_NE_MAX * SUB + 1];
    static double xa[NK * 130], ya[NK * 130]; /* the exact arcs, NaN between them */
    const int ne = m->ne, npt = ne * SUB + 1;
    char path[512];
    svgp_chart c;
    FILE *f;
    int j, e, s;
    snprintf(path, sizeof path, "%s/corot_static_shapes.csv", dir);
    f = svgp_csv_open(path, "lambda,node,x_m,y_m,phi_rad,x_exact_m,y_exact_m");
    for (j = 0; j < NK; ++j) {
        const vlbe_real *q = qh + (size_t)ks[j] * (size_t)m->n;
        const double lam = (double)ks[j] / CS_NSTEP, k = 2.0 * CS_PI * lam / CS_L;
        for (e = 0; e < ne; ++e) {
            vlbe_real loc[4];
            const vlbe_real *qe = q + 3 * e;
            const double X1 = CS_L * e / ne, X2 = CS_L * (e + 1) / ne, Le = X2 - X1;
            const double x1 = X1 + (double)qe[0], y1 = (double)qe[1];
            const double x2 = X2 + (double)qe[3], y2 = (double)qe[4];
            const double l = hypot(x2 - x1, y2 - y1), cb = (x2 - x1) / l, sb = (y2 - y1) / l;
            if (vlbe_cr2d_local(&m->el[e], 0u, qe, loc)) return;
            for (s = (e == 0 ? 0 : 1); s <= SUB; ++s) {
                const double xi = (double)s / SUB;
                const double N2 = xi * (1.0 - xi) * (1.0 - xi), N4 = xi * xi * (xi - 1.0);
                const double vloc = Le * (N2 * (double)loc[1] + N4 * (double)loc[2]) * l / Le;
                const int p = e * SUB + s;
                xs[j][p] = x1 + xi * l * cb - vloc * sb;
                ys[j][p] = y1 + xi * l * sb + vloc * cb;
            }
        }
        for (s = 0; s <= 128; ++s)
            cs_arc_exact(k, CS_L * s / 128.0, &xa[130 * j + s], &ya[130 * j + s]);
        xa[130 * j + 129] = ya[130 * j + 129] = (double)NAN;
        if (f)
            for (e = 0; e <= ne; ++e) {
                double row[7];
                row[0] = lam;
                row[1] = e;
                row[2] = CS_L * e / ne + (double)q[3 * e];
                row[3] = (double)q[3 * e + 1];
                row[4] = (double)q[3 * e + 2];
                cs_arc_exact(k, CS_L * e / ne, &row[5], &row[6]);
                svgp_csv_row(f, 7, row);
            }
    }
    if (!f || fclose(f) != 0) printf("# could not write %s\n", path);
    svgp_init(&c, "Co-rotational cantilever, end moment lambda 2 pi EI/L, 8 elements",
              "x [m]", "y [m]", 0, 0);
    for (j = 0; j < NK; ++j) {
        snprintf(names[j], sizeof names[j], "lambda = %g", (double)ks[j] / CS_NSTEP);
        svgp_series(&c, names[j], npt, xs[j], ys[j], SVGP_SOLID);
    }
    svgp_series(&c, "exact arcs", NK * 130, xa, ya, SVGP_DOT);
    /* equal scales: the plot area is 696 x 394 px */
    svgp_xrange(&c, -0.42, -0.42 + 0.85 * 696.0 / 394.0);
    svgp_yrange(&c, -0.1, 0.75);
    c.legend = SVGP_LEGEND_TL;
    snprintf(path, sizeof path, "%s/corot_static_shapes.svg", dir);
    if (svgp_write_file(&c, path)) printf("# could not write %s\n", path);
}

int main(int argc, char **argv)
{
    const char *dir = argc > 1 ? argv[1] : "out";
    static const int Ns[CS_NN] = {4, 8, 16, 32, 64};
    static const double ref5[3] = {1.8751, 4.6941, 7.8548};
    static cs_arc_err err[CS_NN][CS_NLEV];
    static double cpu_roll[CS_NN], wb[2][CS_NN][3], wa[CS_NN], cpu_eig[CS_NN];
    static double rel_b[CS_NN][3], rel_a[CS_NN];
    static double xN[CS_NN], cy[6][CS_NN];
    static vlbe_dae_stats sts[CS_NN];
    const double EI = cs_EI(), EA = cs_EA(), rA = cs_rhoA();
    const double wax = 0.5 * CS_PI * sqrt(EA / rA) / CS_L;
    double bl[3], wex[3], lin_v = 0, lin_u = 0, lin_phi = 0, cpu_lin = 0;
    char qty[200], path[512];
    int i, j, k, rc = 0;
    cs_model *m = (cs_model *)malloc(sizeof *m);
    vlbe_real *qh = (vlbe_real *)malloc((size_t)(CS_NSTEP + 1) * 3 * (CS_NE_MAX + 1) * sizeof *qh);
    if (!m || !qh) return 1;
    printf("# co-rotational beam (corot2d.h), static checks: cantilever L = %g m, EA = %.6g N, "
           "EI = %.6g N m^2, rhoA = %.6g kg/m (the paper's section), clamped at x = 0\n",
           CS_L, EA, EI, rA);

    /* (a) roll-up */
    printf("# (a) roll-up: tip moment lambda 2 pi EI/L in %d load steps, vlbe_dae_static from the "
           "previous solution; exact: circle of radius L/(2 pi lambda); discrete closed form: "
           "nodes at exact angles on radius R_d = L_e (1 - a^2/24)/(2 sin(a/2))\n", CS_NSTEP);
    printf("#  N  lambda  tip err/L      node err/L     pred. tip err  |disc - closed| "
           "rot err [rad]\n");
    for (i = 0; i < CS_NN; ++i) {
        clock_t c0 = clock();
        vlbe_status st;
        memset(&sts[i], 0, sizeof sts[i]);
        if (cs_build(m, Ns[i], 0u)) return 1;
        st = cs_rollup(m, CS_NSTEP, NULL, qh, &sts[i]);
        cpu_roll[i] = cs_cpu(c0);
        if (st != VLBE_OK) {
            printf("# roll-up, N = %d: %s\n", Ns[i], vlbe_status_str(st));
            rc = 1;
            continue;
        }
        for (j = 0; j < CS_NLEV; ++j) {
            const int ks = (j + 1) * CS_NSTEP / CS_NLEV;
            err[i][j] = cs_arc_errors(m, qh + (size_t)ks * (size_t)m->n, (double)(j + 1) / CS_NLEV);
            printf("# %3d  %5.3f  %.6e  %.6e  %.6e  %.3e      %.3e\n", Ns[i],
                   (double)(j + 1) / CS_NLEV, err[i][j].tip, err[i][j].node, err[i][j].tip_pred,
                   err[i][j].disc, err[i][j].rot);
        }
        printf("#      %ld Newton iterations in %d load steps, %ld LU, cpu %.4f s\n",
               sts[i].newton_iters, CS_NSTEP, sts[i].lu_factors, cpu_roll[i]);
        if (Ns[i] == 8) cs_shapes(dir, m, qh);
    }
    printf("# observed order of the tip error (log2 of the ratio N -> 2N):\n#  lambda");
    for (i = 0; i + 1 < CS_NN; ++i) printf("   %2d->%-2d", Ns[i], Ns[i + 1]);
    printf("\n");
    for (j = 0; j < CS_NLEV - 1; ++j) {
        printf("#  %5.3f ", (double)(j + 1) / CS_NLEV);
        for (i = 0; i + 1 < CS_NN; ++i)
            printf("  %7.3f", cs_order(err[i][j].tip, err[i + 1][j].tip));
        printf("\n");
    }
    for (i = 0; i < CS_NN; ++i) {
        snprintf(qty, sizeof qty, "roll-up lambda = 1, %d el.: tip-to-root distance / L", Ns[i]);
        svgp_compare_row(stdout, "corot static", qty, 0.0, err[i][CS_NLEV - 1].tip, (double)NAN,
                         cpu_roll[i]);
    }
    for (i = 0; i < CS_NN; i += 2) {
        snprintf(qty, sizeof qty, "roll-up lambda = 1, %d el.: tip rotation [rad]", Ns[i]);
        svgp_compare_row(stdout, "corot static", qty, 2.0 * CS_PI, err[i][CS_NLEV - 1].phitip,
                         err[i][CS_NLEV - 1].rot / (2.0 * CS_PI), cpu_roll[i]);
    }
    for (i = 0; i < CS_NN; ++i) {
        snprintf(qty, sizeof qty, "roll-up lambda = 1/2, %d el.: tip y = 2L/pi [m]", Ns[i]);
        svgp_compare_row(stdout, "corot static", qty, 2.0 * CS_L / CS_PI, err[i][1].ytip,
                         fabs(err[i][1].ytip - 2.0 * CS_L / CS_PI) / (2.0 * CS_L / CS_PI),
                         cpu_roll[i]);
    }
    snprintf(qty, sizeof qty, "roll-up lambda = 1/2: order of the tip error, %d -> %d el.", Ns[2],
             Ns[3]);
    svgp_compare_row(stdout, "corot static", qty, 4.0, cs_order(err[2][1].tip, err[3][1].tip),
                     fabs(cs_order(err[2][1].tip, err[3][1].tip) - 4.0) / 4.0, (double)NAN);
    /* the linear element */
    {
        clock_t c0 = clock();
        if (cs_build(m, 8, VLBE_CR2D_LINEAR) == 0 && cs_rollup(m, 1, NULL, qh, NULL) == VLBE_OK) {
            const vlbe_real *q = qh + m->n;
            lin_u = (double)q[3 * 8];
            lin_v = (double)q[3 * 8 + 1];
            lin_phi = (double)q[3 * 8 + 2];
        } else
            rc = 1;
        cpu_lin = cs_cpu(c0);
        printf("# LINEAR element, 8 el., lambda = 1 (one step): tip u = %.3e m, v = %.12f m "
               "(M L^2/(2 EI) = pi L = %.12f), phi = %.12f (2 pi = %.12f): the tip stays at "
               "x = L, %.4f L from the root where the rolled-up beam returns\n",
               lin_u, lin_v, CS_PI * CS_L, lin_phi, 2.0 * CS_PI, hypot(CS_L + lin_u, lin_v) / CS_L);
        svgp_compare_row(stdout, "corot static", "LINEAR element, lambda = 1: tip deflection, "
                         "M L^2/(2 EI) [m]", CS_PI * CS_L, lin_v,
                         fabs(lin_v - CS_PI * CS_L) / (CS_PI * CS_L), cpu_lin);
        svgp_compare_row(stdout, "corot static", "LINEAR element, lambda = 1: tip-to-root "
                         "distance / L (exact 0)", 0.0, hypot(CS_L + lin_u, lin_v) / CS_L,
                         (double)NAN, cpu_lin);
    }

    /* (b) frequencies */
    for (k = 0; k < 3; ++k) {
        bl[k] = ex_cant_root(k + 1);
        wex[k] = bl[k] * bl[k] * sqrt(EI / (rA * CS_L * CS_L * CS_L * CS_L));
    }
    printf("# (b) cantilever frequencies, K0 x = w^2 M x at rest (clamped coordinates removed), "
           "solved by shift-invert, sigma = 0; "
           "beta L = %.12f %.12f %.12f (1 + cos cosh = 0; to five digits %.4f %.4f %.4f); exact "
           "w = %.9g %.9g %.9g rad/s, first axial w = %.9g rad/s\n",
           bl[0], bl[1], bl[2], ref5[0], ref5[1], ref5[2], wex[0], wex[1], wex[2], wax);
    printf("#  N   rel. error of w1        w2              w3              axial w1     "
           "(w1 with sigma = -max K0_ii/M_ii)\n");
    for (i = 0; i < CS_NN; ++i) {
        clock_t c0 = clock();
        vlbe_status st = cs_freqs(Ns[i], 1, 3, wb[0][i], &wa[i]);
        cpu_eig[i] = cs_cpu(c0);
        if (st == VLBE_OK) st = cs_freqs(Ns[i], 0, 3, wb[1][i], NULL);
        if (st != VLBE_OK) {
            printf("# frequencies, N = %d: %s\n", Ns[i], vlbe_status_str(st));
            rc = 1;
            continue;
        }
        for (k = 0; k < 3; ++k) rel_b[i][k] = (wb[0][i][k] - wex[k]) / wex[k];
        rel_a[i] = (wa[i] - wax) / wax;
        printf("# %3d   %+.6e  %+.6e  %+.6e  %+.6e  (%+.6e)\n", Ns[i], rel_b[i][0], rel_b[i][1],
               rel_b[i][2], rel_a[i], (wb[1][i][0] - wex[0]) / wex[0]);
    }
    printf("# observed orders (N -> 2N):\n");
    for (k = 0; k < 4; ++k) {
        printf("#  %s", k < 3 ? (k == 0 ? "bending w1" : k == 1 ? "bending w2" : "bending w3")
                              : "axial w1  ");
        for (i = 0; i + 1 < CS_NN; ++i)
            printf("  %7.3f", k < 3 ? cs_order(rel_b[i][k], rel_b[i + 1][k])
                                    : cs_order(rel_a[i], rel_a[i + 1]));
        printf("\n");
    }
    printf("#  (w1 at %d elements is rounding-limited: the reduction's error in w^2, about 6e-10, "
           "exceeds its h^4 error; see the top of corot_static.c)\n", Ns[CS_NN - 1]);
    for (i = 0; i < CS_NN; i += 3)
        for (k = 0; k < 3; ++k) {
            snprintf(qty, sizeof qty, "cantilever bending w%d, %d el. [rad/s]", k + 1, Ns[i]);
            svgp_compare_row(stdout, "corot static", qty, wex[k], wb[0][i][k], fabs(rel_b[i][k]),
                             cpu_eig[i]);
        }
    snprintf(qty, sizeof qty, "cantilever w1: order of the error, %d -> %d el.", Ns[0], Ns[1]);
    svgp_compare_row(stdout, "corot static", qty, 4.0, cs_order(rel_b[0][0], rel_b[1][0]),
                     fabs(cs_order(rel_b[0][0], rel_b[1][0]) - 4.0) / 4.0, (double)NAN);
    snprintf(qty, sizeof qty, "cantilever w3: order of the error, %d -> %d el.", Ns[1], Ns[2]);
    svgp_compare_row(stdout, "corot static", qty, 4.0, cs_order(rel_b[1][2], rel_b[2][2]),
                     fabs(cs_order(rel_b[1][2], rel_b[2][2]) - 4.0) / 4.0, (double)NAN);
    snprintf(qty, sizeof qty, "cantilever first axial w, %d el. [rad/s]", Ns[2]);
    svgp_compare_row(stdout, "corot static", qty, wax, wa[2], fabs(rel_a[2]), cpu_eig[2]);

    /* (c) rigid rotation */
    {
        static const double cpt[2] = {0.3, -0.2};
        double fm, mm, fl, ml;
        clock_t c0 = clock();
        if (cs_rigid(16, 0u, -4.0 * CS_PI, 0.05, 1006, cpt, &fm, &mm)) rc = 1;
        if (cs_rigid(16, VLBE_CR2D_LINEAR, -4.0 * CS_PI, 0.05, 1006, cpt, &fl, &ml)) rc = 1;
        printf("# (c) rigid rotation of the 16-element beam about (0.3, -0.2) m by psi in "
               "[-4 pi, 12 pi] (1006 angles, phi = psi): max |Q_force|/EA = %.3e, "
               "max |Q_moment| L_e/EI = %.3e (EPS = %.3e); LINEAR element: %.3e, %.3e\n",
               fm, mm, (double)VLBE_EPS, fl, ml);
        svgp_compare_row(stdout, "corot static", "rigid rotation up to 6 turns: max abs Q / EA "
                         "(forces)", 0.0, fm, (double)NAN, cs_cpu(c0));
        svgp_compare_row(stdout, "corot static", "rigid rotation up to 6 turns: max abs Q L_e / EI "
                         "(moments)", 0.0, mm, (double)NAN, cs_cpu(c0));
    }

    /* convergence chart and CSV */
    for (i = 0; i < CS_NN; ++i) {
        xN[i] = Ns[i];
        cy[0][i] = err[i][0].tip;
        cy[1][i] = err[i][1].tip;
        cy[2][i] = err[i][2].tip;
        cy[3][i] = fabs(rel_b[i][0]);
        cy[4][i] = fabs(rel_b[i][2]);
        cy[5][i] = fabs(rel_a[i]);
    }
    {
        const double *cols[7];
        svgp_chart c;
        cols[0] = xN;
        for (k = 0; k < 6; ++k) cols[k + 1] = cy[k];
        snprintf(path, sizeof path, "%s/corot_static_conv.csv", dir);
        if (svgp_csv_write(path, "N,tip_err_lambda_0.25,tip_err_lambda_0.5,tip_err_lambda_0.75,"
                           "w1_rel_err,w3_rel_err,axial_w1_rel_err", 7, CS_NN, cols))
            printf("# could not write %s\n", path);
        svgp_init(&c, "Co-rotational beam: discretisation errors against the number of elements",
                  "elements N", "error", 1, 1);
        svgp_series(&c, "roll-up tip / L, lambda = 1/4", CS_NN, xN, cy[0], SVGP_MARKERS);
        svgp_series(&c, "roll-up tip / L, lambda = 1/2", CS_NN, xN, cy[1], SVGP_MARKERS);
        svgp_series(&c, "roll-up tip / L, lambda = 3/4", CS_NN, xN, cy[2], SVGP_MARKERS);
        svgp_series(&c, "bending w1, relative", CS_NN, xN, cy[3], SVGP_MARKERS | SVGP_DASH);
        svgp_series(&c, "bending w3, relative", CS_NN, xN, cy[4], SVGP_MARKERS | SVGP_DASH);
        svgp_series(&c, "axial w1, relative", CS_NN, xN, cy[5], SVGP_MARKERS | SVGP_DOT);
        c.legend = SVGP_LEGEND_BL;
        snprintf(path, sizeof path, "%s/corot_static_conv.svg", dir);
        if (svgp_write_file(&c, path)) printf("# could not write %s\n", path);
    }
    free(qh);
    free(m);
    return rc;
}

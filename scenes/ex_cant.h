/* ex_cant.h -- closed forms of the clamped-free Euler-Bernoulli beam that
   the examples and their tests compare against: the roots of the
   frequency equation 1 + cos(bL) cosh(bL) = 0.
   -- part of vlbe                                  SPDX-License-Identifier: MIT */
#ifndef VLBE_EX_CANT_H
#define VLBE_EX_CANT_H

#include <math.h>

/* The n-th root b_n L (n = 1, 2, ...) of 1 + cos x cosh x = 0, written as
   cos x + 1/cosh x = 0 (well scaled for large x), Newton from 1.875 for
   n = 1 and from the asymptote (2n - 1) pi/2 otherwise; full double
   precision (1.87510407, 4.69409113, 7.85475744, ...).  omega_n =
   (b_n L)^2 sqrt(EI / (rhoA L^4)). */
static inline double ex_cant_root(int n)
{
    double x = n == 1 ? 1.875 : (2.0 * n - 1.0) * 3.14159265358979323846 / 2.0;
    int it;
    for (it = 0; it < 60; ++it) {
        const double ch = cosh(x);
        const double f = cos(x) + 1.0 / ch, fp = -sin(x) - tanh(x) / ch;
        const double dx = f / fp;
        x -= dx;
        if (fabs(dx) <= 1e-16 * x) break;
    }
    return x;
}

/* The first four roots as ex_cant_root gives them (for hot paths that
   should not iterate; tests/test_scenes_cr2d.c checks the two agree). */
static const double ex_cant_b[4] = {1.8751040687119611, 4.694091132974175, 7.8547574382376126,
                                    10.995540734875467};

/* The rotating uniform cantilever (Euler-Bernoulli, clamped on the axis,
   no hub radius, inextensible): in units EI = rhoA = L = 1, spin speed Om,
   the centrifugal tension T(x) = Om^2 (1 - x^2)/2 and the mode equations
        flap (out of the plane of rotation):  w'''' - (T w')' = w^2 w,
        lag  (in the plane):                  v'''' - (T v')' - Om^2 v = w^2 v,
   so that w_lag^2 = w_flap^2 - Om^2 exactly (the lag equation is the flap
   one with w^2 + Om^2 for w^2).  The n-th root w of
        D(w) = y1''(1) y2'''(1) - y2''(1) y1'''(1) = 0,
   y1, y2 the solutions with y(0) = y'(0) = 0 and (y'', y''') = (1, 0),
   (0, 1) (clamp at x = 0; free tip: moment y'' and shear y''' - T y'
   vanish, T(1) = 0), by shooting: classical Runge-Kutta with EX_CANT_RK
   steps on [0, 1], a scan in w by factors 1.05 from 0.5 counting sign
   changes of D, then bisection to the last bit.  At Om = 0 the roots are
   ex_cant_root(n)^2; flap mode 1 at Om = 1, 2, 3 is the classical 3.6816,
   4.1373, 4.7973 (Wright, Smith, Thresher, Wang, J. Appl. Mech. 49 (1982)
   197-202).  Returns the nondimensional w (physical: w sqrt(EI / (rhoA
   L^4)), with Om scaled the same way), -1 if fewer than n roots lie below
   w = 500. */
#define EX_CANT_RK 2000

static inline double ex_cant__rot_det(double w2, double Om, int lag)
{
    const double h = 1.0 / EX_CANT_RK, O2 = Om * Om, k = lag ? w2 + O2 : w2;
    double y[2][4] = {{0, 0, 1, 0}, {0, 0, 0, 1}};
    int c, i, s;
    for (c = 0; c < 2; ++c)
        for (s = 0; s < EX_CANT_RK; ++s) {
            const double x0 = s * h;
            double st[4][4], yt[4];
            for (i = 0; i < 4; ++i) yt[i] = y[c][i];
            for (i = 0; i < 4; ++i) { /* stage i at x0 + (0, h/2, h/2, h)[i] */
                const double x = x0 + (i == 0 ? 0.0 : i == 3 ? h : 0.5 * h);
                const double T = 0.5 * O2 * (1.0 - x * x), Tp = -O2 * x;
                double *d = st[i];
                int j;
                d[0] = yt[1];
                d[1] = yt[2];
                d[2] = yt[3];
                d[3] = Tp * yt[1] + T * yt[2] + k * yt[0];
                if (i < 3)
                    for (j = 0; j < 4; ++j) yt[j] = y[c][j] + (i == 2 ? h : 0.5 * h) * d[j];
            }
            for (i = 0; i < 4; ++i)
                y[c][i] += h / 6.0 * (st[0][i] + 2.0 * st[1][i] + 2.0 * st[2][i] + st[3][i]);
        }
    return y[0][2] * y[1][3] - y[1][2] * y[0][3];
}

static inline double ex_cant_rot(int n, double Om, int lag)
{
    double w = 0.5, d0 = ex_cant__rot_det(w * w, Om, lag), lo = 0, hi = 0, dlo = 0;
    int found = 0, it;
    if (n < 1) return -1.0;
    while (found < n) {
        const double w1 = w * 1.05, d1 = ex_cant__rot_det(w1 * w1, Om, lag);
        if (w1 > 500.0) return -1.0;
        if ((d0 < 0) != (d1 < 0) && ++found == n) {
            lo = w;
            hi = w1;
            dlo = d0;
        }
        w = w1;
        d0 = d1;
    }
    for (it = 0; it < 200 && hi - lo > 2e-16 * hi; ++it) {
        const double mid = 0.5 * (lo + hi), dm = ex_cant__rot_det(mid * mid, Om, lag);
        if ((dm < 0) == (dlo < 0)) {
            lo = mid;
            dlo = dm;
        } else {
            hi = mid;
        }
    }
    return 0.5 * (lo + hi);
}

#endif /* VLBE_EX_CANT_H */

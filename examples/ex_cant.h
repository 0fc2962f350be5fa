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

#endif /* VLBE_EX_CANT_H */

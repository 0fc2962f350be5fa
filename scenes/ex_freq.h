/* ex_freq.h -- frequency of the strongest spectral line of a sampled
   response, for the vibration scenes of the examples.
   -- part of vlbe                                  SPDX-License-Identifier: MIT

   ex_peak_freq(y, n, dt, f_lo, f_hi) returns the frequency in [f_lo, f_hi]
   that maximises |sum_k w_k (y_k - mean) exp(-2 pi i f k dt)| with w the
   4-term Blackman-Harris window (sidelobes below -92 dB, so a neighbouring
   mode of similar amplitude more than 4/(n dt) away moves the peak by a
   negligible amount).  The maximum is bracketed on a grid of 1/(8 n dt)
   and refined by golden-section search to 1e-10 relative.  On a pure
   sinusoid of 10 or more periods the estimate is exact to ~1e-9 relative
   (tests/test_scenes_ale.c checks it on synthetic signals). */
#ifndef VLBE_EX_FREQ_H
#define VLBE_EX_FREQ_H

#include <math.h>
#include <stddef.h>

/* |DFT|^2 of the (already windowed) samples x at frequency f */
static inline double ex__dft_pow(const double *x, size_t n, double dt, double f)
{
    const double PI = 3.14159265358979323846;
    double c = 0.0, s = 0.0, wr = cos(2.0 * PI * f * dt), wi = -sin(2.0 * PI * f * dt);
    double er = 1.0, ei = 0.0; /* exp(-2 pi i f k dt) by recurrence */
    size_t k;
    for (k = 0; k < n; ++k) {
        double t;
        c += x[k] * er;
        s += x[k] * ei;
        t = er * wr - ei * wi;
        ei = er * wi + ei * wr;
        er = t;
        if ((k & 255u) == 255u) { /* renormalise |e| = 1 against rounding drift */
            double a = 1.0 / sqrt(er * er + ei * ei);
            er *= a;
            ei *= a;
        }
    }
    return c * c + s * s;
}

/* w: workspace of n doubles; y is not modified. */
static inline double ex_peak_freq(const double *y, size_t n, double dt, double f_lo, double f_hi,
                                  double *w)
{
    const double PI = 3.14159265358979323846, gr = 0.6180339887498949;
    double mean = 0.0, df, f, best = -1.0, fbest = f_lo, a, b, x1, x2, p1, p2;
    size_t k;
    if (n < 8 || !(f_hi > f_lo)) return 0.0;
    for (k = 0; k < n; ++k) mean += y[k];
    mean /= (double)n;
    for (k = 0; k < n; ++k) {
        double x = 2.0 * PI * (double)k / (double)(n - 1);
        w[k] = (0.35875 - 0.48829 * cos(x) + 0.14128 * cos(2.0 * x) - 0.01168 * cos(3.0 * x)) *
               (y[k] - mean);
    }
    df = 1.0 / (8.0 * (double)n * dt);
    for (f = f_lo; f <= f_hi; f += df) {
        double pw = ex__dft_pow(w, n, dt, f);
        if (pw > best) best = pw, fbest = f;
    }
    a = fbest - df > f_lo ? fbest - df : f_lo;
    b = fbest + df < f_hi ? fbest + df : f_hi;
    x1 = b - gr * (b - a);
    x2 = a + gr * (b - a);
    p1 = ex__dft_pow(w, n, dt, x1);
    p2 = ex__dft_pow(w, n, dt, x2);
    while (b - a > 1e-10 * fabs(fbest)) {
        if (p1 > p2) {
            b = x2, x2 = x1, p2 = p1;
            x1 = b - gr * (b - a);
            p1 = ex__dft_pow(w, n, dt, x1);
        } else {
            a = x1, x1 = x2, p1 = p2;
            x2 = a + gr * (b - a);
            p2 = ex__dft_pow(w, n, dt, x2);
        }
    }
    return 0.5 * (a + b);
}

#endif /* VLBE_EX_FREQ_H */

/* ex_katz.h -- exact modal-series reference for the spinning simply
   supported shaft under an axially moving, rotating point load (Katz 2001;
   VLBSE scene 4.3: paper section 4.3, eqs. 59-63, Table 4).
   -- part of vlbe                                  SPDX-License-Identifier: MIT

   Reference code for the examples and tests: plain double (not vlbe_real),
   <math.h> only, no complex.h (complex numbers are explicit real pairs), no
   allocation, no printing.  Include it as the other scene headers, relative
   to the file: #include "../scenes/ex_katz.h" from examples/ or tests/; it
   compiles as C99 and as C++.

   ex_katz k;
   double u1, u2, T, us;
   int N;
   if (ex_katz_setup(&k, 1.0, 0.02, 206e9, 7700.0, 1.0, 0.5, 1.0, 1.0, 1) != 0) ...
   T = ex_katz_traverse_time(&k);                      l / v
   us = ex_katz_us(&k);                                U_s = P l^3 / (48 E J)
   ex_katz_modes_for(&k, 1e-5, 1000, &N, NULL);        modes for 1e-5 U_s
   ex_katz_eval(&k, N, k.v * t, t, &u1, &u2);          U1, U2 under the load
                                                       (0 <= t <= T)

   Model.  z in [0, l] along the shaft (X3), U = U1 + i U2 the deflection of
   the axis in X1 (real part) and X2 (imaginary part).  Eq. 59:
       EJ U_zzzz + rhoA U_tt - rhoJ [U_zztt - i 2 Omega U_zzt]
           = P delta(z - v t) e^{i omega t}                          (59, 60)
   with J = A r_g^2.  The load is P along X1 at t = 0 and turns at omega
   from X1 towards X2 (X1 component P cos(omega t), X2 component
   P sin(omega t)).  Simply supported ends (U = U_zz = 0 at z = 0, l), zero
   initial deflection and velocity.  Modes sin(k_n z), k_n = n pi / l.
   Insert U = sum_n w_n(t) sin(k_n z): U_zz -> -k_n^2 w_n, so the bracket
   becomes -rhoJ [-k_n^2 w_n'' + i 2 Omega k_n^2 w_n']
   = +rhoJ k_n^2 w_n'' - i 2 Omega rhoJ k_n^2 w_n'.  Multiply by sin(k_n z),
   integrate over [0, l] (int sin^2 = l/2, delta picks sin(k_n v t)) and
   divide by rhoA l / 2:
       a_n w'' - i b_n w' + c_n w = F0 sin(theta_n t) e^{i omega t}     (M)
       a_n = 1 + beta_n^2,  b_n = 2 Omega beta_n^2,  c_n = w0_n^2,
       beta_n = k_n r_g,  w0_n^2 = EJ k_n^4 / rhoA,  theta_n = k_n v,
       F0 = 2 P / (rhoA l),  w_n(0) = w_n'(0) = 0.
   Signs: the rotary inertia adds to the mass (+beta_n^2 w''); the
   gyroscopic term enters as -i 2 Omega beta_n^2 w'.  With w = e^{i s t}
   the homogeneous equation is
       D_n(s) = -a_n s^2 + b_n s + c_n = -a_n (s - s1)(s - s2) = 0,
   two real roots s1 > 0 > s2 (c_n > 0), s1 + s2 = b_n / a_n, s1 s2 =
   -c_n / a_n: for Omega > 0 the forward whirl s1 is faster than the
   backward whirl |s2| (the paper's omega_n1 > 0, omega_n2 < 0).
   rot = 0 drops the rhoJ terms (beta_n = 0 in (M) only; r_g still sets the
   section): the Euler-Bernoulli shaft, on which the spin has no effect,
   s1,2 = +-w0_n.  vlbe's ANCF beam with a spin angle has no rotary
   inertia of bending and discretizes this rot = 0 model.  On the paper's
   cases the two models differ by up to 1.4e-3 U_s (a = 0.5) and 4.4e-4 U_s
   (a = 1.5) (max over the traverse at the load and at midspan, both
   components): 3.5 and 1.1 beta1^2, O(beta1^2) (tests/test_katz.c).

   Exact solution of (M).  Write the forcing as F0 (e^{i(omega+theta)t} -
   e^{i(omega-theta)t}) / (2i).  Let E_t[x0, x1, x2] be the second divided
   difference of y -> e^{i y t} at the nodes x0, x1, x2.  Since
   a (d/dt - i s1)(d/dt - i s2) e^{i y t} = D_n(y) e^{i y t}, the function
   -E_t[x, s1, s2] / a has the e^{i x t} part e^{i x t} / D_n(x) (the
   particular solution) plus a homogeneous part, and it and its t
   derivative vanish at t = 0 (divided differences of 1 and of i y).  So
       w_n(t) = (i F0 / (2 a_n)) (E_t[omega+theta_n, s1, s2]
                                  - E_t[omega-theta_n, s1, s2]).
   Expanded in partial fractions this is eqs. 62-63 of the paper with
   r1 = omega + theta_n, r2 = theta_n - omega, omega_n1 = s1, omega_n2 = s2
   (the printed '.' between the terms of eq. 63 are minus signs: U2 has the
   signs +, -, +, - on its cos(s1 t), cos(s2 t), cos(r1 t), cos(r2 t) terms);
   tests/test_katz.c checks the two forms against each other.
   Resonance (a forcing frequency omega +- theta_n equal to s1 or s2) needs
   no special case and never divides by zero: the first difference
       E_t[x0, x1] = i t e^{i (x0+x1) t / 2} sinc((x1 - x0) t / 2)
   is exact and smooth through x0 = x1 (the confluent limit gives the
   secular term t e^{i s t}), and E_t[x, s1, s2] divides only by the larger
   of |x - s1|, |x - s2|, which is >= (s1 - s2) / 2 > 0.  So the functions
   below have no resonant failure; near and at resonance the accuracy is
   that of any other case.

   Non-dimensional parameters (OUR reading; the paper refers to Katz 2001
   and leaves them implicit):
       beta1 = pi r_g / l   (given: 0.02), so r_g = beta1 l / pi, r = 2 r_g
                            (solid circular section), A = pi r^2,
                            J = pi r^4 / 4 = A r_g^2
       v_cr = omega_1 l / pi, omega_1 = (pi/l)^2 sqrt(EJ / rhoA): the first
                            critical speed of the load (the first mode's
                            theta_1 equals the Euler-Bernoulli, non-spinning
                            omega_1); a = v / v_cr
       k_omega = omega l / (2 pi v): load rotations per traverse
       U_s = P l^3 / (48 E J): static midspan deflection under P at midspan
   Table 4: l = 1 m, beta1 = 0.02, E = 206e9 Pa, rho = 7700 kg/m^3,
   Omega = 1 rad/s; cases (a, k_omega) = (0.5, 1) and (1.5, 0.5); one
   traverse t in [0, l / v].  With these, omega_1 = 324.99 rad/s,
   v_cr = 103.45 m/s.  U/U_s is independent of P, and for rot = 0 of
   beta1 (and Omega) too.

   Reference values (N = 30 modes; 240 modes change them by < 1e-5),
   max over the traverse of |U1| / U_s, |U2| / U_s (at load position z/l):
                       at the load                    at midspan
     a    k_omega rot  |U1|    (z/l)  |U2|    (z/l)   |U1|    (z/l)  |U2|    (z/l)
     0.5  1       1    1.28008 (0.70) 1.07315 (0.53)  1.67540 (0.77) 2.10304 (1)
     0.5  1       0    1.28046 (0.70) 1.07328 (0.53)  1.67564 (0.77) 2.10343 (1)
     1.5  0.5     1    0.24423 (0.69) 0.47056 (0.79)  0.26425 (0.77) 0.83122 (1)
     1.5  0.5     0    0.24442 (0.69) 0.47080 (0.79)  0.26422 (0.77) 0.83145 (1)
   (for a = 0.5, k_omega = 1 the load turns at omega = 2 a k_omega
   omega_1 = omega_1: the forcing frequencies omega +- theta_1 are 1.5 and
   0.5 omega_1.)

   Conventions.  Results are deflections in metres (divide by
   ex_katz_us for U/U_s).  The series is valid for 0 <= t <= T = l / v
   (after that the load has left the shaft); ex_katz_eval refuses t and z
   outside [0, T] and [0, l] beyond a rounding slack of 1e-12 relative (so
   z = v t at t = T passes).  ex_katz_mode is the exact solution of (M) for
   any t.

   Accuracy.  Each mode is exact up to rounding; the phases s t are formed
   in double, so a mode carries an error of a few EPS (1 + |s| t) times the
   amplitudes of its exponentials (|s| t <= 5e3 for 30 modes on the paper's
   cases).  Measured against eqs. 62-63 summed in long double: 2e-15 U_s
   (30 modes, both cases, both rot).  The truncated series differs from
   the full one by the tail: for large n the particular part of mode n is
   quasi-static, of size (96 / pi^4) U_s / n^4 at most, the free
   vibration about (96 / pi^4) U_s a / n^5, so the tail after N modes is
   about 0.33 U_s / N^3 at the load point and about half of that at
   midspan (even modes vanish there).  ex_katz_modes_for measures it: the
   largest |U_N - U_2N| / U_s over EX_KATZ_NGRID + 1 equally spaced times
   of the traverse, at z = v t and z = l / 2, both components.  Measured, both
   cases and both rot (the tail is the quasi-static one, max at the load):
       (a, k_omega) = (0.5, 1), (1.5, 0.5)   N = 30 modes for 1e-5:
       |U_30 - U_60| = 9.25e-6 / 9.32e-6 U_s (N = 29: 1.02e-5 / 1.03e-5)
       (rot = 1; rot = 0 within 3e-8 U_s of these)
   On a grid of 20000 intervals |U_30 - U_60| is 9.29e-6 / 9.33e-6 U_s, and
   against 240 modes (nearly the whole tail, which is ~8/7 of U_N - U_2N)
   9.75e-6 / 9.79e-6 U_s: 30 modes converge the series to 1e-5 U_s in
   both senses.  (A 201-point grid misses the peaks: it accepts N = 29.)

   Status: 0, or EX_KATZ_EARG: a non-finite or out-of-range argument
   (setup: l, beta1, E, rho, a not > 0, any argument not finite, or a
   derived value that over- or underflows; eval: nmodes < 1, z outside
   [0, l] or t outside [0, l / v] (with the slack above), or NaN; mode:
   n < 1 or t not finite; modes_for: tol not > 0, nmax < 1, U_s = 0).
   ex_katz_modes_for returns EX_KATZ_ENOCONV if nmax modes do not reach tol.
   Outputs are written only on success.

   API
     int    ex_katz_setup(k, l, beta1, E, rho, Omega, a, k_omega, P, rot)
     double ex_katz_us(k)                      U_s
     double ex_katz_traverse_time(k)           l / v
     int    ex_katz_mode(k, n, t, wr, wi)      w_n(t) = wr + i wi of (M)
     int    ex_katz_eval(k, nmodes, z, t, u1, u2)   U1, U2: modes 1..nmodes
     double ex_katz_conv_err(k, N)             max |U_N - U_2N| / U_s (grid)
     int    ex_katz_modes_for(k, tol, nmax, nmodes, err)  smallest N with
                                               ex_katz_conv_err(k, N) <= tol

   References
     R. Katz, The dynamic response of a rotating shaft subject to an
       axially moving and rotating load, J. Sound Vib. 246 (2001) 757-775
       (as cited by the paper; not at hand: eqs. 59-63 are read from the
       paper ../shared/papers/vlbse-spinning-variable-length-beam.txt,
       section 4.3: eq. 59 (the PDE), eqs. 60-61 (load, U = U1 + i U2),
       eqs. 62-63 (the modal series), Table 4 (parameters)).
     L. Fryba, Vibration of solids and structures under moving loads,
       3rd ed., Telford 1999, ch. 1 (the non-spinning, non-rotating load:
       w_n = F0 (sin theta t - (theta/w0) sin w0 t) / (w0^2 - theta^2)).
     C. de Boor, Divided differences, Surveys in Approximation Theory 1
       (2005) 46-69 (divided differences of exponentials, confluent nodes). */
#ifndef VLBE_EX_KATZ_H
#define VLBE_EX_KATZ_H

#include <math.h>
#include <string.h>

#define EX_KATZ_EARG 1    /* bad argument */
#define EX_KATZ_ENOCONV 2 /* ex_katz_modes_for: nmax modes are not enough */
#define EX_KATZ_NGRID 997 /* time intervals of the convergence grid (prime: the
                             grid points z = v t do not fall on nodes of sin(n pi z / l)) */

typedef struct ex_katz {
    /* inputs */
    double l, beta1, E, rho, Omega, a, kw, P;
    int rot; /* 1: eq. 59 (rotary inertia, gyroscopic term); 0: without the rhoJ terms */
    /* derived */
    double rg, r, A, J, EJ, rhoA; /* section */
    double w1, vcr;               /* omega_1, v_cr */
    double v, omega, T;           /* load speed, load spin rate, traverse time l / v */
    double Us, F0;                /* U_s, 2 P / (rhoA l) */
} ex_katz;

static inline int ex__katz_finite(double x) { return x == x && fabs(x) <= 1.79e308; }

static inline int ex_katz_setup(ex_katz *k, double l, double beta1, double E, double rho,
                                double Omega, double a, double kw, double P, int rot)
{
    const double PI = 3.14159265358979323846;
    ex_katz s;
    memset(&s, 0, sizeof s); /* padding too: *k compares bytewise (tests) */
    if (!k || !ex__katz_finite(l) || !ex__katz_finite(beta1) || !ex__katz_finite(E) ||
        !ex__katz_finite(rho) || !ex__katz_finite(Omega) || !ex__katz_finite(a) ||
        !ex__katz_finite(kw) || !ex__katz_finite(P) || !(l > 0.0) || !(beta1 > 0.0) ||
        !(E > 0.0) || !(rho > 0.0) || !(a > 0.0))
        return EX_KATZ_EARG;
    s.l = l, s.beta1 = beta1, s.E = E, s.rho = rho, s.Omega = Omega, s.a = a, s.kw = kw;
    s.P = P, s.rot = rot ? 1 : 0;
    s.rg = beta1 * l / PI;
    s.r = 2.0 * s.rg;
    s.A = PI * s.r * s.r;
    s.J = s.A * s.rg * s.rg; /* = pi r^4 / 4 */
    s.EJ = E * s.J;
    s.rhoA = rho * s.A;
    s.w1 = (PI / l) * (PI / l) * sqrt(s.EJ / s.rhoA);
    s.vcr = s.w1 * l / PI;
    s.v = a * s.vcr;
    s.omega = 2.0 * PI * s.v * kw / l;
    s.T = l / s.v;
    s.Us = P * l * l * l / (48.0 * s.EJ);
    s.F0 = 2.0 * P / (s.rhoA * l);
    if (!ex__katz_finite(s.T) || !ex__katz_finite(s.omega) || !ex__katz_finite(s.F0) ||
        !ex__katz_finite(s.Us) || !(s.EJ > 0.0) || !(s.rhoA > 0.0) || !(s.T > 0.0))
        return EX_KATZ_EARG; /* under- or overflow of the derived values */
    *k = s;
    return 0;
}

static inline double ex_katz_us(const ex_katz *k) { return k->Us; }
static inline double ex_katz_traverse_time(const ex_katz *k) { return k->T; }

/* E_t[x0, x1] = (e^{i x1 t} - e^{i x0 t}) / (x1 - x0)
   = i t e^{i m t} sinc(h t / 2), m = (x0 + x1)/2, h = x1 - x0 */
static inline void ex__katz_dd1(double x0, double x1, double t, double *re, double *im)
{
    double m = 0.5 * (x0 + x1), y = 0.5 * (x1 - x0) * t, sc = y != 0.0 ? sin(y) / y : 1.0;
    double ph = m * t;
    *re = -t * sc * sin(ph);
    *im = t * sc * cos(ph);
}

/* E_t[x, s1, s2] given d12 = E_t[s1, s2]; divides by the larger of
   |x - s1|, |x - s2| (>= (s1 - s2)/2) */
static inline void ex__katz_dd2(double x, double s1, double s2, double t, double d12r,
                                double d12i, double *re, double *im)
{
    double dr, di, den;
    if (fabs(x - s2) >= fabs(x - s1)) { /* (E[x, s1] - E[s1, s2]) / (x - s2) */
        ex__katz_dd1(x, s1, t, &dr, &di);
        den = x - s2;
    } else { /* (E[x, s2] - E[s2, s1]) / (x - s1) */
        ex__katz_dd1(x, s2, t, &dr, &di);
        den = x - s1;
    }
    *re = (dr - d12r) / den;
    *im = (di - d12i) / den;
}

/* the modal coordinate w_n(t) = *wr + i *wi of (M), exact for any t */
static inline int ex_katz_mode(const ex_katz *k, int n, double t, double *wr, double *wi)
{
    const double PI = 3.14159265358979323846;
    double kn, b2, an, bn, cn, q, s1, s2, th, d12r, d12i, er, ei, fr, fi, g;
    if (n < 1 || !ex__katz_finite(t)) return EX_KATZ_EARG;
    kn = (double)n * PI / k->l;
    b2 = k->rot ? (kn * k->rg) * (kn * k->rg) : 0.0;
    an = 1.0 + b2;
    bn = 2.0 * k->Omega * b2;
    cn = k->EJ * (kn * kn) * (kn * kn) / k->rhoA;
    /* roots of a s^2 - b s - c = 0 without cancellation */
    q = 0.5 * bn + (bn >= 0.0 ? 1.0 : -1.0) * sqrt(0.25 * bn * bn + an * cn);
    if (q > 0.0) s1 = q / an, s2 = -cn / q;
    else s2 = q / an, s1 = -cn / q;
    th = kn * k->v;
    ex__katz_dd1(s1, s2, t, &d12r, &d12i);
    ex__katz_dd2(k->omega + th, s1, s2, t, d12r, d12i, &er, &ei);
    ex__katz_dd2(k->omega - th, s1, s2, t, d12r, d12i, &fr, &fi);
    /* w = (i F0 / (2 a)) (E+ - E-) */
    g = k->F0 / (2.0 * an);
    *wr = -g * (ei - fi);
    *wi = g * (er - fr);
    return 0;
}

/* U1 + i U2 summed over modes n0..n1 at (z, t), unchecked */
static inline void ex__katz_sum(const ex_katz *k, int n0, int n1, double z, double t, double *u1,
                                double *u2)
{
    const double PI = 3.14159265358979323846;
    double s_1 = 0.0, s_2 = 0.0, wr, wi, sn;
    int n;
    for (n = n0; n <= n1; ++n) {
        if (ex_katz_mode(k, n, t, &wr, &wi) != 0) continue; /* n >= 1: not taken */
        sn = sin((double)n * PI * z / k->l);
        s_1 += wr * sn;
        s_2 += wi * sn;
    }
    *u1 = s_1;
    *u2 = s_2;
}

/* deflections U1, U2 (metres) at z, t from modes 1..nmodes */
static inline int ex_katz_eval(const ex_katz *k, int nmodes, double z, double t, double *u1,
                               double *u2)
{
    const double slack = 1.0 + 1e-12;
    if (nmodes < 1 || !(z >= 0.0 && z <= k->l * slack) || !(t >= 0.0 && t <= k->T * slack))
        return EX_KATZ_EARG;
    ex__katz_sum(k, 1, nmodes, z, t, u1, u2);
    return 0;
}

/* max |U_N - U_2N| / U_s (both components) over t_j = j T / EX_KATZ_NGRID,
   j = 0..EX_KATZ_NGRID, at the load point z = v t_j and at midspan */
static inline double ex_katz_conv_err(const ex_katz *k, int N)
{
    double worst = 0.0, t, z, d1, d2;
    int j, p;
    if (N < 1) return HUGE_VAL;
    for (j = 0; j <= EX_KATZ_NGRID; ++j) {
        t = k->T * (double)j / (double)EX_KATZ_NGRID;
        for (p = 0; p < 2; ++p) {
            z = p ? 0.5 * k->l : k->v * t;
            ex__katz_sum(k, N + 1, 2 * N, z, t, &d1, &d2);
            if (fabs(d1) > worst) worst = fabs(d1);
            if (fabs(d2) > worst) worst = fabs(d2);
        }
    }
    return worst / fabs(k->Us);
}

/* smallest N <= nmax with ex_katz_conv_err(k, N) <= tol; *err (may be
   NULL) gets its error.  EX_KATZ_ENOCONV (nothing written) if none. */
static inline int ex_katz_modes_for(const ex_katz *k, double tol, int nmax, int *nmodes,
                                    double *err)
{
    double e;
    int N;
    if (!(tol > 0.0) || nmax < 1 || !nmodes || !(fabs(k->Us) > 0.0)) return EX_KATZ_EARG;
    for (N = 1; N <= nmax; ++N) {
        e = ex_katz_conv_err(k, N);
        if (e <= tol) {
            *nmodes = N;
            if (err) *err = e;
            return 0;
        }
    }
    return EX_KATZ_ENOCONV;
}

#endif /* VLBE_EX_KATZ_H */

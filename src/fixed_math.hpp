// libm's functions for the setups, as fixed sequences of IEEE double operations (+, -, *, /,
// sqrt: correctly rounded everywhere; the library is built with -ffp-contract=off), with
// double-double steps where the rounding would cost more than a fraction of an ulp. Every CPU
// and compiler then gives the same bits, which libm does not: glibc's x86-64 sin, cos, exp,
// log, pow... take another path where the CPU has FMA (measured: a sampler's table changed),
// and AArch64's is another build. The setups and the reference's eval_angle and coef_exact
// call these, never libm, so that the deterministic mode's kernels are the same bits
// everywhere (docs/accuracy.md). Each is within 1 ulp of the exact value, measured against
// MPFR on random inputs (tests/test_fixed_math.cpp: at most 0.75 ulp); sin and cos for
// |x| < 2^20. Special values are C's, but for a NaN's payload.
#pragma once

namespace kutlog::detail::fixed {

double sin(double x);
double cos(double x);
double asin(double x);
double acos(double x);
double atan2(double y, double x);
double expm1(double x);
double log(double x);
double log1p(double x);
double pow(double x, double y);
double hypot(double x, double y);

// cos(pi m / d), pi m / d taken to 106 bits: the Chebyshev nodes of the fits.
long double cos_pi_times(int m, int d);

}  // namespace kutlog::detail::fixed

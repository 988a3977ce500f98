// A certified bound on the error of a lobe kernel (kutlog/lobe.hpp's LobeKernel), for the
// setup of src/lobe.cpp: instead of checking a fit against the reference at thousands of
// points, bound every error it can have, over every float t of the support, from the fit's
// own error and the roundings of the arithmetic that will run it.
//
// The support w = 1 - t in [0, w_max] is cut into pieces; on each, the bound takes every term
// at its worst (the powers of |s| and w at the piece's far end, the lobe's value at its ends),
// so it holds for every t of the piece:
//   approximation:  |q(w) - p(s)| <= the Chebyshev tail of the fit (src/polynomial_fit.hpp);
//   coefficients:   each rounded to the kernel's precision;
//   Horner's rule:  a running bound, one rounding per multiply and per add (unfused; a fused
//                   multiply-add has only the add's, so one bound covers both);
//   inputs:         w = 1 - t and s = center_t - t in float, exact where Sterbenz's lemma
//                   holds, else rounded;
//   the final ops:  scale - w q (or scale_f + (scale_lo - w q)), the rounding to float, the
//                   clamp to [0, scale_f].
// For the base_power form (B^k: in double lanes, or in float or double on the scalar path), the
// base's error reaches F multiplied by k B^(k-1). q's terms add up as PieceBudget, which the
// scalar pieces (src/scalar_pieces.hpp) share.
#pragma once

#include <algorithm>
#include <bit>
#include <cmath>
#include <cstdint>
#include <span>
#include <vector>

#include "kutlog/detail/float_ulp.hpp"
#include "kutlog/lobe.hpp"
#include "fixed_math.hpp"
#include "polynomial_fit.hpp"

namespace kutlog::detail {

// The lobe's shape against w = 1 - t, and 1 - shape without cancellation:
// theta = acos(1 - w) = 2 asin(sqrt(w / 2)), 1 - cos^k(u) = -expm1(k log1p(-2 sin^2(u/2))).
struct LobeShape {
  double c;
  int k;
  double theta(double w) const { return 2 * fixed::asin(std::sqrt(0.5 * w)); }
  double base(double w) const { return fixed::cos(c * theta(w)); }
  double one_minus_power(double w, int power) const {
    const double half_sine = fixed::sin(0.5 * c * theta(w));
    return -fixed::expm1(power * fixed::log1p(-2 * half_sine * half_sine));
  }
};

// The lobe at the ends of the pieces of its support: w ascending from 0 to w_max, the base
// B = cos(c theta) and F = B^k decreasing; the epicenter (F >= 0.6) is w <= w_epicenter.
struct LobeProfile {
  std::vector<double> w, base, value;
  double w_epicenter;
};
// Pieces of the support. More tighten the bound where the lobe's value changes within one
// (the epicenter's ulp is taken at a piece's lowest value), at more setup time: the setup
// certifies on kProfilePieces, and again on kFineProfilePieces a kernel that missed by little.
inline constexpr int kProfilePieces = 32, kFineProfilePieces = 128;
LobeProfile lobe_profile(const LobeShape& shape, double w_max, int pieces = kProfilePieces);

// A polynomial fit of q(w) = (1 - B^power) / w (power k: the polynomial form; 1: the base of
// the base_power form): its exact monomials and a bound on |q - p| over the support.
struct QuotientFit {
  std::vector<Real> monomials;  // unscaled, in s = center_t - t (polynomial) or in w
  double approximation_error;   // on the unscaled q
};

inline constexpr double kFloatUnit = 0x1p-24, kDoubleUnit = 0x1p-53;  // unit roundoffs
// Where the ulp bound applies: F >= 0.6 (kutlog/lobe.hpp).
inline constexpr double kEpicenter = 0.6;

// The error of rounding a value of magnitude at most m: half an ulp in float (half of unit m
// to unit m, by where m sits in its binade), unit m in double, whose underflow adds half the
// smallest subnormal float.
struct Rounding {
  bool to_float;
  double operator()(double magnitude) const {
    return to_float ? 0.5 * ulp_of_float(magnitude) : kDoubleUnit * magnitude + 0x1p-150;
  }
};

struct Interval {
  double lo, hi;
  double magnitude() const { return std::max(-lo, hi); }
};
inline Interval times(Interval a, Interval b) {
  const double p1 = a.lo * b.lo, p2 = a.lo * b.hi, p3 = a.hi * b.lo, p4 = a.hi * b.hi;
  return {std::min(std::min(p1, p2), std::min(p3, p4)),
          std::max(std::max(p1, p2), std::max(p3, p4))};
}

// Horner's rule for sum c_i x^i (c's last the highest) with x in an interval, each operation
// rounded: bounds on the magnitude of the exact value and on the error of the computed one
// against it. The exact partial sums are carried as intervals, so each rounding is bounded by
// the ulp of what it rounds there. A fused multiply-add rounds once, else the product rounds
// too: the unfused bound covers both, and any mix of them.
struct HornerBound {
  double magnitude, error;
  double lowest;  // of the exact value
};
HornerBound horner_bound(std::span<const double> c, Interval x, Rounding round,
                         bool product_rounded);

// The worst errors of a kernel over the support, in the units of the contract: |out - scale F|
// relative to scale, and in ulps of the float scale F where F >= 0.6 (0 if no such t). For
// the polynomial form in float lanes, not compensated: a lower bound on the q the kernel
// computes, over the support (what src/lobe.cpp needs to drop the clamp at the peak).
struct CertifiedError {
  double abs_error;
  double epicenter_ulp;
  double lowest_q = -INFINITY;

  // Takes one piece's bound on |out - scale F|: relative to the scale and, where the piece lies
  // in the epicenter (lowest_output > 0: scale F at least that there), in ulps of that output.
  void take_piece(double error, double scale, double lowest_output) {
    abs_error = std::max(abs_error, error / scale);
    if (lowest_output > 0)
      epicenter_ulp = std::max(epicenter_ulp, error / ulp_of_float(lowest_output));
  }
};

// The error budget of a certified kernel on one piece of its support (the array kernels'
// certified_error and the scalar pieces' ScalarPiecesFitter): what its polynomial computes
// against the exact function, each term at its worst over the piece. The output's own
// operations and rounding to float (Rounding{true}) come on top, by the kernel's form.
struct PieceBudget {
  double approximation;    // the fit's truncation (and aliasing), times the scale
  double coefficients;     // each coefficient's rounding to the kernel's type, at |x|^i
  double range_shift = 0;  // the constant term moved to keep the output within its range
  double evaluation;       // Horner's rule's (or Estrin's scheme's) roundings
  double input;            // the variable's own error, through the polynomial's slope
  double total() const { return approximation + coefficients + range_shift + evaluation + input; }
};

// The monomials are exact to long double's precision, not better: each counts as off by this.
inline constexpr Real kMonomialRelativeError = 0x1p-60L;
// PieceBudget::coefficients: sum |stored_i - exact_i| x_magnitude^i over the coefficients.
inline double coefficient_rounding(std::span<const Real> exact, std::span<const double> stored,
                                   double x_magnitude) {
  double error = 0, x_power = 1;
  for (std::size_t i = 0; i < stored.size(); ++i, x_power *= x_magnitude)
    error += double(std::fabs(Real(stored[i]) - exact[i]) +
                    kMonomialRelativeError * std::fabs(exact[i])) * x_power;
  return error;
}

// kernel: a kernel of either form, its coefficients set from fit.monomials (times scale in
// the polynomial form); scale: the exact scale (coef or 1) that kernel.scale_f rounds.
// Stops at the first piece past `limit` (then only that the error exceeds it is known).
CertifiedError certified_error(const detail::LobeKernel& kernel, detail::Arithmetic arithmetic,
                               const QuotientFit& fit, double scale, const LobeProfile& profile,
                               const CertifiedError& limit = {INFINITY, INFINITY});

}  // namespace kutlog::detail

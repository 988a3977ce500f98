#include "lobe_bound.hpp"

#include <algorithm>
#include <array>
#include <bit>
#include <cmath>
#include <numbers>
#include <span>

namespace kutlog::detail {
namespace {

// The monomials are exact to long double's precision, not better: each counts as off by this.
constexpr double kMonomialRelativeError = 0x1p-60;
// Where the ulp bound applies: F >= 0.6 (kutlog/lobe.hpp).
constexpr double kEpicenter = 0.6;

using Coefficients = std::array<double, detail::LobeKernel::kMaxDegree + 1>;

// The same bounds for Estrin's scheme as the scalar path runs it (LobeKernel::with_q): the
// sum of c[first + i] x^i over i < count is the lowest bit_floor(count - 1) terms plus
// x^(bit_floor(count - 1)) times the rest, x's powers by repeated squaring.
struct Evaluated {
  Interval exact;  // where the exact value lies
  double error;    // of the computed value against it
};
using Powers = std::array<Evaluated, std::bit_width(unsigned(detail::LobeKernel::kMaxDegree))>;
Evaluated estrin_node(const Coefficients& c, int first, int count, const Powers& powers,
                      Rounding round, bool product_rounded) {
  if (count == 1) return {{c[first], c[first]}, 0};
  const int low = int(std::bit_floor(unsigned(count - 1)));
  const Evaluated a = estrin_node(c, first, low, powers, round, product_rounded);
  const Evaluated b = estrin_node(c, first + low, count - low, powers, round, product_rounded);
  const Evaluated& power = powers[std::size_t(std::countr_zero(unsigned(low)))];
  const Interval product = times(power.exact, b.exact);
  // |P B - p b| <= |P - p| |B| + |p| |B - b|, P and B the computed factors.
  double error = power.error * (b.exact.magnitude() + b.error) + power.exact.magnitude() * b.error;
  if (product_rounded) error += round(product.magnitude() + error);
  const Interval sum{a.exact.lo + product.lo, a.exact.hi + product.hi};
  error += a.error;
  return {sum, error + round(sum.magnitude() + error)};
}
HornerBound estrin_bound(const Coefficients& c, int degree, Interval x, Rounding round,
                         bool product_rounded) {
  Powers powers{};  // x^(2^j), as far as the degree needs
  powers[0] = {x, 0};
  for (std::size_t j = 1; (1 << j) <= degree; ++j) {
    const Evaluated& p = powers[j - 1];
    const double error = p.error * (2 * p.exact.magnitude() + p.error);
    const Interval square = times(p.exact, p.exact);
    powers[j] = {square, error + round(square.magnitude() + error)};
  }
  const Evaluated q = estrin_node(c, 0, degree + 1, powers, round, product_rounded);
  return {q.exact.magnitude(), q.error, q.exact.lo};
}

}  // namespace

HornerBound horner_bound(std::span<const double> c, Interval x, Rounding round,
                         bool product_rounded) {
  const double x_magnitude = x.magnitude();
  Interval partial{c.back(), c.back()};
  double error = 0;
  for (std::size_t i = c.size() - 1; i-- > 0;) {
    const Interval product = times(partial, x);
    double before_sum = error * x_magnitude;
    if (product_rounded) before_sum += round(product.magnitude() + before_sum);
    partial = {product.lo + c[i], product.hi + c[i]};
    error = before_sum + round(partial.magnitude() + before_sum);
  }
  return {partial.magnitude(), error, partial.lo};
}

LobeProfile lobe_profile(const LobeShape& shape, double w_max, int pieces) {
  // Half the pieces on the epicenter, which ends at a piece's end: its ulp bound is tighter.
  // Past pi/2 (wide lobes, c < 1) the whole support is epicenter: sin^2 must not wrap around.
  const double x_epicenter =
      std::min(std::acos(std::pow(kEpicenter, 1.0 / shape.k)) / shape.c, std::numbers::pi / 2);
  // Rounded up: every t where F >= 0.6 is inside.
  const double w_epicenter =
      std::min(w_max, 2 * std::pow(std::sin(0.5 * x_epicenter), 2) * (1 + 0x1p-40));
  LobeProfile profile;
  profile.w_epicenter = w_epicenter;
  const auto add = [&](double w) {
    const double base = std::max(0.0, shape.base(w));
    profile.w.push_back(w);
    profile.base.push_back(base);
    profile.value.push_back(std::pow(base, shape.k));
  };
  for (int j = 0; j < pieces / 2; ++j) add(w_epicenter * j / (pieces / 2));
  for (int j = 0; j <= pieces / 2; ++j) add(w_epicenter + (w_max - w_epicenter) * j / (pieces / 2));
  return profile;
}

CertifiedError certified_error(const detail::LobeKernel& kernel, detail::Arithmetic arithmetic,
                               const QuotientFit& fit, double scale, const LobeProfile& profile,
                               const CertifiedError& limit) {
  const bool polynomial = kernel.form == detail::LobeKernel::Form::polynomial;
  // In float: the polynomial form in SIMD lanes, or either form in the scalar path where the
  // kernel says so (SIMD lanes run the base_power form in double).
  const bool in_float =
      arithmetic == detail::Arithmetic::scalar ? kernel.scalar_in_float : polynomial;
  // The scalar path's multiply-adds are fused or not as the caller's flags decide: the
  // unfused bound covers both.
  const bool product_rounded = arithmetic != detail::Arithmetic::fused || !in_float;
  const double unit = in_float ? kFloatUnit : kDoubleUnit;
  const Rounding round{in_float};
  const int degree = kernel.degree;
  const double coefficient_scale = polynomial ? scale : 1.0;
  Coefficients stored{}, rounding{};
  for (int i = 0; i <= degree; ++i) {
    const Real exact = coefficient_scale * fit.monomials[i];
    stored[i] = in_float ? double(kernel.q_f[i]) : kernel.q_d[i];
    rounding[i] = double(std::fabs(Real(stored[i]) - exact)) +
                  kMonomialRelativeError * double(std::fabs(exact));
  }
  // s = center_t - t = w - w_center (polynomial form), else the variable is w itself. In
  // float, center_t - t is exact where Sterbenz's lemma holds: for every t of the support
  // when center_t >= 1/2 and its lowest t >= center_t / 2; 1 - t is exact for t >= 1/2.
  const double w_center = polynomial ? 1.0 - double(kernel.center_t) : 0.0;
  const bool s_rounded = in_float && !(kernel.center_t >= 0.5f &&
                                       2 * (1 - profile.w.back()) >= double(kernel.center_t));
  const bool split_scale = in_float && kernel.scale_lo != 0;
  const bool compensated = in_float && kernel.compensated;
  if (compensated && (arithmetic != detail::Arithmetic::fused || degree == 0))
    return {INFINITY, INFINITY};
  Coefficients above_constant{};  // r's: c_1 .. c_degree
  for (int i = 1; i <= degree; ++i) above_constant[i - 1] = stored[i];
  const double stored_scale =
      in_float ? double(kernel.scale_f) + double(kernel.scale_lo) : kernel.scale_d;
  // Clamping to scale_f moves an output by at most the distance of scale_f below scale.
  const double clamp_error = std::max(0.0, scale - double(kernel.scale_f));

  const bool bounds_q = polynomial && in_float && !compensated;  // lowest_q's kernels
  CertifiedError worst{0, 0, bounds_q ? INFINITY : -INFINITY};
  for (std::size_t j = 0; j + 1 < profile.w.size(); ++j) {
    const double w_hi = profile.w[j + 1];
    // The variable's range on the piece (widened by its rounding, if rounded).
    const double widening = s_rounded ? 2 * unit : 0;
    const double x_lo = profile.w[j] - w_center, x_hi = w_hi - w_center;
    const Interval x{x_lo - widening * std::fabs(x_lo), x_hi + widening * std::fabs(x_hi)};
    const double sigma = x.magnitude();
    // Horner's rule in full, or down to r, q = c_0 + s r, with the last step exact; the
    // scalar path runs Estrin's scheme.
    const HornerBound horner =
        compensated ? horner_bound(std::span(above_constant).first(std::size_t(degree)), x,
                                   round, false)
        : arithmetic == detail::Arithmetic::scalar
            ? estrin_bound(stored, degree, x, round, product_rounded)
            : horner_bound(std::span(stored).first(std::size_t(degree) + 1), x, round,
                           product_rounded);
    double coefficient_error = 0, slope = 0, sigma_power = 1;  // slope: sum i |c_i| sigma^i
    for (int i = 0; i <= degree; ++i, sigma_power *= sigma) {
      coefficient_error += rounding[i] * sigma_power;
      if (s_rounded) slope += i * std::fabs(stored[i]) * sigma_power;  // only then needed
    }
    // A rounded s moves p(s) by at most sum |c_i| sigma^i ((1 + unit)^i - 1).
    const double input_error = s_rounded ? 1.001 * unit * slope : 0;
    double evaluation_error = horner.error, q_magnitude = horner.magnitude + horner.error;
    // The exact partial sums' intervals are computed in double, off by a few of its units.
    if (bounds_q)
      worst.lowest_q = std::min(worst.lowest_q, horner.lowest - horner.error - input_error -
                                                    0x1p-40 * horner.magnitude);
    double lo_magnitude = 0;  // of q_lo, compensated
    if (compensated) {
      // s r = hi + lo exactly (two_product), c_0 + hi = q_hi + e exactly (two_sum),
      // q_lo = e + lo rounded once.
      const double product = sigma * q_magnitude * (1 + unit);
      q_magnitude = std::fabs(stored[0]) + product;
      lo_magnitude = 0.5 * (ulp_of_float(q_magnitude) + ulp_of_float(product));
      evaluation_error = sigma * horner.error + round(lo_magnitude);
    }
    const double q_error = coefficient_scale * fit.approximation_error + coefficient_error +
                           evaluation_error + input_error;
    q_magnitude += input_error;
    const double exact_hi = scale * profile.value[j];  // F decreases with w
    double error;  // before the rounding to float
    if (polynomial) {
      const double w_rounding = in_float && w_hi > 0.5 ? unit * w_hi : 0;
      const double w_q = (w_hi + w_rounding) * q_magnitude;
      error = w_hi * q_error + w_rounding * q_magnitude + (product_rounded ? round(w_q) : 0) +
              std::fabs(stored_scale - scale);
      if (compensated)  // scale_lo - w q_lo, then - w q_hi
        error += round(std::fabs(kernel.scale_lo) + w_hi * lo_magnitude) +
                 round(std::fabs(kernel.scale_lo) + w_q + w_hi * lo_magnitude);
      else if (split_scale)
        error += round(std::fabs(kernel.scale_lo) + w_q);  // scale_lo - w q
      if (!in_float) error += round(exact_hi + error);  // the double subtraction
    } else {
      // B = 1 - w q, B^k by squaring (at most 13 products for k <= 64), times the stored
      // scale; in float, w = 1 - t is rounded below t = 1/2.
      const double w_rounding = in_float && w_hi > 0.5 ? unit * w_hi : 0;
      const double w_q = (w_hi + w_rounding) * q_magnitude;
      const double base_error =
          w_hi * q_error + w_rounding * q_magnitude + unit * (w_q + 1 + w_q);
      const double base_hi = profile.base[j] + base_error;
      const double power_hi = detail::integer_power(base_hi, kernel.k - 1);
      error = scale * (kernel.k * power_hi * base_error + 14 * unit * power_hi * base_hi) +
              (unit * scale + std::fabs(stored_scale - scale)) * power_hi * base_hi;
    }
    error += 0.5 * ulp_of_float(exact_hi + error);
    error = std::max(error, clamp_error) * (1 + 0x1p-40);  // and this computation's own roundings
    if (std::isnan(error)) error = INFINITY;  // coefficients that overflow float
    worst.abs_error = std::max(worst.abs_error, error / scale);
    if (profile.w[j + 1] <= profile.w_epicenter) {
      const double lowest = scale * std::max(kEpicenter, profile.value[j + 1]);
      worst.epicenter_ulp = std::max(worst.epicenter_ulp, error / ulp_of_float(lowest));
    }
    if (worst.abs_error > limit.abs_error || worst.epicenter_ulp > limit.epicenter_ulp) break;
  }
  return worst;
}

}  // namespace kutlog::detail

#include "lobe_bound.hpp"

#include <algorithm>
#include <array>
#include <bit>
#include <cmath>
#include <numbers>
#include <span>

#include "kutlog/detail/integer_power.hpp"

namespace kutlog::detail {
namespace {

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

// A kernel's error budget on each piece of the support, for the arithmetic that runs it.
class KernelBudget {
 public:
  KernelBudget(const detail::LobeKernel& kernel, detail::Arithmetic arithmetic,
               const QuotientFit& fit, double scale, const LobeProfile& profile);
  // In the compensated form (only with FMA, on a degree of at least 1).
  bool compensated() const { return compensated_; }
  // Whether the budget bounds the q computed from below (CertifiedError::lowest_q).
  bool bounds_q() const { return polynomial_ && in_float_ && !compensated_; }
  // The bound on |out - scale F| over piece j (to profile.w[j + 1]); lowers worst.lowest_q.
  double piece_error(std::size_t j, CertifiedError& worst) const;

 private:
  // What the kernel computes for q on a piece: its budget, |q| and, compensated, |q_lo|.
  struct Quotient {
    PieceBudget budget;
    double magnitude, lo_magnitude;
  };
  Interval variable_range(std::size_t j) const;
  Quotient quotient(Interval x, CertifiedError& worst) const;
  double polynomial_output(double w_hi, double exact_hi, const Quotient& q) const;
  double base_power_output(std::size_t j, const Quotient& q) const;

  const detail::LobeKernel& kernel_;
  detail::Arithmetic arithmetic_;
  const LobeProfile& profile_;
  double scale_, approximation_error_;
  bool polynomial_, in_float_, product_rounded_, s_rounded_, split_scale_, compensated_;
  double unit_;
  Rounding round_;
  int degree_;
  double coefficient_scale_, w_center_, stored_scale_, clamp_error_;
  std::array<Real, detail::LobeKernel::kMaxDegree + 1> exact_{};
  Coefficients stored_{};
  Coefficients above_constant_{};  // r's: c_1 .. c_degree
};

KernelBudget::KernelBudget(const detail::LobeKernel& kernel, detail::Arithmetic arithmetic,
                           const QuotientFit& fit, double scale, const LobeProfile& profile)
    : kernel_(kernel), arithmetic_(arithmetic), profile_(profile), scale_(scale),
      approximation_error_(fit.approximation_error),
      polynomial_(kernel.form == detail::LobeKernel::Form::polynomial),
      // In float: the polynomial form in SIMD lanes, or either form in the scalar path where
      // the kernel says so (SIMD lanes run the base_power form in double).
      in_float_(arithmetic == detail::Arithmetic::scalar ? kernel.scalar_in_float : polynomial_),
      // The scalar path's multiply-adds are fused or not as the caller's flags decide: the
      // unfused bound covers both.
      product_rounded_(arithmetic != detail::Arithmetic::fused || !in_float_),
      unit_(in_float_ ? kFloatUnit : kDoubleUnit), round_{in_float_}, degree_(kernel.degree),
      coefficient_scale_(polynomial_ ? scale : 1.0) {
  for (int i = 0; i <= degree_; ++i) {
    exact_[std::size_t(i)] = coefficient_scale_ * fit.monomials[std::size_t(i)];
    stored_[std::size_t(i)] = in_float_ ? double(kernel.q_f[i]) : kernel.q_d[i];
  }
  for (int i = 1; i <= degree_; ++i) above_constant_[std::size_t(i - 1)] = stored_[std::size_t(i)];
  // s = center_t - t = w - w_center (polynomial form), else the variable is w itself. In
  // float, center_t - t is exact where Sterbenz's lemma holds: for every t of the support
  // when center_t >= 1/2 and its lowest t >= center_t / 2; 1 - t is exact for t >= 1/2.
  w_center_ = polynomial_ ? 1.0 - double(kernel.center_t) : 0.0;
  s_rounded_ = in_float_ && !(kernel.center_t >= 0.5f &&
                              2 * (1 - profile.w.back()) >= double(kernel.center_t));
  split_scale_ = in_float_ && kernel.scale_lo != 0;
  compensated_ = in_float_ && kernel.compensated;
  stored_scale_ = in_float_ ? double(kernel.scale_f) + double(kernel.scale_lo) : kernel.scale_d;
  // Clamping to scale_f moves an output by at most the distance of scale_f below scale.
  clamp_error_ = std::max(0.0, scale - double(kernel.scale_f));
}

// The variable's range on piece j (widened by its rounding, if rounded).
Interval KernelBudget::variable_range(std::size_t j) const {
  const double widening = s_rounded_ ? 2 * unit_ : 0;
  const double x_lo = profile_.w[j] - w_center_, x_hi = profile_.w[j + 1] - w_center_;
  return {x_lo - widening * std::fabs(x_lo), x_hi + widening * std::fabs(x_hi)};
}

KernelBudget::Quotient KernelBudget::quotient(Interval x, CertifiedError& worst) const {
  const double sigma = x.magnitude();
  const auto degree = std::size_t(degree_);
  // Horner's rule in full, or down to r, q = c_0 + s r, with the last step exact; the
  // scalar path runs Estrin's scheme.
  const HornerBound horner =
      compensated_ ? horner_bound(std::span(above_constant_).first(degree), x, round_, false)
      : arithmetic_ == detail::Arithmetic::scalar
          ? estrin_bound(stored_, degree_, x, round_, product_rounded_)
          : horner_bound(std::span(stored_).first(degree + 1), x, round_, product_rounded_);
  double slope = 0, sigma_power = 1;  // sum i |c_i| sigma^i, only needed for a rounded s
  for (std::size_t i = 0; s_rounded_ && i <= degree; ++i, sigma_power *= sigma)
    slope += double(i) * std::fabs(stored_[i]) * sigma_power;
  Quotient q{{coefficient_scale_ * approximation_error_,
              coefficient_rounding(std::span(exact_).first(degree + 1),
                                   std::span(stored_).first(degree + 1), sigma),
              0, horner.error,
              // A rounded s moves p(s) by at most sum |c_i| sigma^i ((1 + unit)^i - 1).
              s_rounded_ ? 1.001 * unit_ * slope : 0},
             horner.magnitude + horner.error, 0};
  // The exact partial sums' intervals are computed in double, off by a few of its units.
  if (bounds_q())
    worst.lowest_q = std::min(worst.lowest_q, horner.lowest - horner.error - q.budget.input -
                                                  0x1p-40 * horner.magnitude);
  if (compensated_) {
    // s r = hi + lo exactly (two_product), c_0 + hi = q_hi + e exactly (two_sum),
    // q_lo = e + lo rounded once.
    const double product = sigma * q.magnitude * (1 + unit_);
    q.magnitude = std::fabs(stored_[0]) + product;
    q.lo_magnitude = 0.5 * (ulp_of_float(q.magnitude) + ulp_of_float(product));
    q.budget.evaluation = sigma * horner.error + round_(q.lo_magnitude);
  }
  q.magnitude += q.budget.input;
  return q;
}

// scale - w q, or scale_f + (scale_lo - w q), before the rounding to float.
double KernelBudget::polynomial_output(double w_hi, double exact_hi, const Quotient& q) const {
  const double w_rounding = in_float_ && w_hi > 0.5 ? unit_ * w_hi : 0;
  const double w_q = (w_hi + w_rounding) * q.magnitude;
  double error = w_hi * q.budget.total() + w_rounding * q.magnitude +
                 (product_rounded_ ? round_(w_q) : 0) + std::fabs(stored_scale_ - scale_);
  const double scale_lo = std::fabs(kernel_.scale_lo);
  if (compensated_)  // scale_lo - w q_lo, then - w q_hi
    error += round_(scale_lo + w_hi * q.lo_magnitude) +
             round_(scale_lo + w_q + w_hi * q.lo_magnitude);
  else if (split_scale_)
    error += round_(scale_lo + w_q);  // scale_lo - w q
  if (!in_float_) error += round_(exact_hi + error);  // the double subtraction
  return error;
}

// B = 1 - w q, B^k by squaring (at most 13 products for k <= 64), times the stored scale; in
// float, w = 1 - t is rounded below t = 1/2. Before the rounding to float.
double KernelBudget::base_power_output(std::size_t j, const Quotient& q) const {
  const double w_hi = profile_.w[j + 1];
  const double w_rounding = in_float_ && w_hi > 0.5 ? unit_ * w_hi : 0;
  const double w_q = (w_hi + w_rounding) * q.magnitude;
  const double base_error =
      w_hi * q.budget.total() + w_rounding * q.magnitude + unit_ * (w_q + 1 + w_q);
  const double base_hi = profile_.base[j] + base_error;
  const double power_hi = detail::integer_power(base_hi, kernel_.k - 1);
  return scale_ * (kernel_.k * power_hi * base_error + 14 * unit_ * power_hi * base_hi) +
         (unit_ * scale_ + std::fabs(stored_scale_ - scale_)) * power_hi * base_hi;
}

double KernelBudget::piece_error(std::size_t j, CertifiedError& worst) const {
  const Quotient q = quotient(variable_range(j), worst);
  const double exact_hi = scale_ * profile_.value[j];  // F decreases with w
  double error = polynomial_ ? polynomial_output(profile_.w[j + 1], exact_hi, q)
                             : base_power_output(j, q);
  error += Rounding{true}(exact_hi + error);
  error = std::max(error, clamp_error_) * (1 + 0x1p-40);  // and this computation's own roundings
  if (std::isnan(error)) error = INFINITY;  // coefficients that overflow float
  return error;
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
      std::min(fixed::acos(fixed::pow(kEpicenter, 1.0 / shape.k)) / shape.c, std::numbers::pi / 2);
  // Rounded up: every t where F >= 0.6 is inside.
  const double w_epicenter =
      std::min(w_max, 2 * fixed::pow(fixed::sin(0.5 * x_epicenter), 2) * (1 + 0x1p-40));
  LobeProfile profile;
  profile.w_epicenter = w_epicenter;
  const auto add = [&](double w) {
    const double base = std::max(0.0, shape.base(w));
    profile.w.push_back(w);
    profile.base.push_back(base);
    profile.value.push_back(fixed::pow(base, shape.k));
  };
  for (int j = 0; j < pieces / 2; ++j) add(w_epicenter * j / (pieces / 2));
  for (int j = 0; j <= pieces / 2; ++j) add(w_epicenter + (w_max - w_epicenter) * j / (pieces / 2));
  return profile;
}

CertifiedError certified_error(const detail::LobeKernel& kernel, detail::Arithmetic arithmetic,
                               const QuotientFit& fit, double scale, const LobeProfile& profile,
                               const CertifiedError& limit) {
  const KernelBudget budget(kernel, arithmetic, fit, scale, profile);
  if (budget.compensated() && (arithmetic != detail::Arithmetic::fused || kernel.degree == 0))
    return {INFINITY, INFINITY};
  CertifiedError worst{0, 0, budget.bounds_q() ? INFINITY : -INFINITY};
  for (std::size_t j = 0; j + 1 < profile.w.size(); ++j) {
    const double error = budget.piece_error(j, worst);
    const bool in_epicenter = profile.w[j + 1] <= profile.w_epicenter;
    worst.take_piece(error, scale,
                     in_epicenter ? scale * std::max(kEpicenter, profile.value[j + 1]) : 0);
    if (worst.abs_error > limit.abs_error || worst.epicenter_ulp > limit.epicenter_ulp) break;
  }
  return worst;
}

}  // namespace kutlog::detail

// Setup of a Lobe: the per-material polynomial fits behind the kernels of kutlog/simd/lobe.hpp,
// each accepted only when a certified bound on its error over every float of the support
// (src/lobe_bound.hpp), for the arithmetic that will run it, is within its variant's promise.
#include "kutlog/lobe.hpp"

#include <algorithm>
#include <array>
#include <cstdio>
#include <bit>
#include <cmath>
#include <functional>
#include <limits>
#include <optional>
#include <span>
#include <stdexcept>
#include <string>
#include <vector>

#include "kutlog/reference.hpp"
#include "arch/kernel_table.hpp"
#include "cpu_features.hpp"
#include "epicenter_check.hpp"
#include "fixed_math.hpp"
#include "lobe_bound.hpp"
#include "lobe_cut.hpp"
#include "lobe_setup_hook.hpp"
#include "polynomial_fit.hpp"
#include "scalar_pieces.hpp"
#include "scalar_kernel.hpp"

namespace kutlog {
using detail::Real;
namespace fixed = detail::fixed;

#if defined(__ELF__)
// Weak: the array path links it (src/dispatch.cpp), and only then are a Lobe's fused kernels
// fitted (docs/design.md, "Footprint"); the unfused ones, which the deterministic mode runs
// everywhere, always are. Elsewhere than ELF every Lobe fits all.
namespace detail {
[[gnu::weak]] decltype(fused_epicenter_loops) fused_epicenter_loops;
}  // namespace detail
#endif

namespace {

constexpr double kPi = std::numbers::pi;

// What a variant promises (kutlog/lobe.hpp), which the certified bound must meet: the error
// relative to the scale (coef when normalized), and in ulps of the value returned where
// F >= 0.6 (infinite: no promise).
using Target = detail::CertifiedError;
constexpr Target kPreciseTarget{0x1p-22, 2.0};
constexpr Target kFastTarget{0x1p-16, std::numeric_limits<double>::infinity()};

// q(w) = (1 - B^power) / w on [0, w_max] as a Chebyshev series, with the monomials of its
// truncations by degree in powers of w - w_center, computed when first asked for.
class QuotientSeries {
 public:
  QuotientSeries(const detail::LobeShape& shape, int power, double w_max) : w_max_(w_max) {
    const auto q = [&shape, power](Real w) {
      return Real(shape.one_minus_power(double(w), power)) / w;  // nodes are inside: w > 0
    };
    // Enough nodes that the last coefficients are down to the noise of the values (doubles,
    // a few ulps each): the series has then converged, and what interpolation aliased is
    // below them. Else no degree is certain.
    for (int nodes = 32; nodes <= 128 && !converged_; nodes *= 2) {
      series_ = detail::chebyshev_interpolant(q, 0, w_max, nodes);
      converged_ = series_.converged(kValueNoise * 2);
    }
    // Each degree's truncation error, asked for many times.
    for (int degree = 0; degree < int(series_.coefficients.size()); ++degree)
      truncation_errors_.push_back(series_.truncation_error(degree, kValueNoise));
  }

  // The fit of this degree about w_center with its bound, if the series converged.
  std::optional<detail::QuotientFit> fit(int degree, double w_center) {
    if (!converged_ || degree >= int(series_.coefficients.size())) return std::nullopt;
    auto cached = std::find_if(monomials_.begin(), monomials_.end(), [&](const Monomials& m) {
      return m.degree == degree && m.w_center == w_center;
    });
    if (cached == monomials_.end())
      cached = monomials_.insert(monomials_.end(),
                                 {degree, w_center, series_.monomials(degree, w_center)});
    return detail::QuotientFit{cached->monomials, truncation_error(degree)};
  }
  double truncation_error(int degree) const {
    return std::size_t(degree) < truncation_errors_.size()
               ? truncation_errors_[std::size_t(degree)]
               : series_.truncation_error(degree, kValueNoise);
  }
  bool converged() const { return converged_; }
  // The fit of the lowest degree whose truncation is below 2^-40 of the peak (w_max q), or of
  // the highest degree the series has: a reference for src/epicenter_check.hpp.
  std::optional<detail::QuotientFit> reference_fit(double w_center) {
    if (!converged_) return std::nullopt;
    int degree = 1;
    while (degree + 1 < int(series_.coefficients.size()) &&
           truncation_error(degree) * w_max_ > 0x1p-40)
      ++degree;
    return fit(degree, w_center);
  }

 private:
  // The relative noise of q's values (doubles), times the interpolant's Lebesgue constant.
  static constexpr Real kValueNoise = 0x1p-45L;
  struct Monomials {
    int degree;
    double w_center;
    std::vector<Real> monomials;
  };
  double w_max_;
  detail::ChebyshevSeries series_;
  std::vector<Monomials> monomials_;
  std::vector<double> truncation_errors_;  // by degree
  bool converged_ = false;
};

// Multiplications of B^k by squaring (k = 5: B^2, B^4, B^4 B).
int power_cost(int k) { return std::bit_width(unsigned(k)) + std::popcount(unsigned(k)) - 2; }

// Within this factor of the target on the support's pieces, a bound is tried again on finer
// pieces (src/lobe_bound.hpp; unfused float lanes at k = 5, n = 100 and 1000: 2^-21.9 on
// the pieces, 2^-22 on the finer ones).
constexpr double kNearMiss = 1.25;

// The support in pieces (detail::kProfilePieces), and a lazy finer cut for a second pass.
struct Profiles {
  const detail::LobeProfile& coarse;
  const std::function<const detail::LobeProfile&()>& fine;
};

// A SIMD kernel whose bound meets the absolute promise and the epicenter's within this factor
// is run on every float of its epicenter: the epicenter bound overstates the worst error by up
// to 3.8 times (docs/accuracy.md), and a wider gate (up to 8) admitted no lower degree on the
// grid and 200 random lobes, only more runs.
constexpr double kRunEpicenterWithin = 3;

// Whether a kernel meets the target: by its certified bound (on the finer pieces too, if
// `finer` and it missed by little) or, for a SIMD kernel, by running it on every float of the
// epicenter (src/epicenter_check.hpp). If it does, its certified bound.
std::optional<detail::CertifiedError> meets(const detail::LobeKernel& kernel,
                                            detail::Arithmetic arithmetic,
                                            const detail::QuotientFit& fit, double scale,
                                            const Profiles& profiles, bool finer,
                                            const Target& target, QuotientSeries* series_to_run) {
  const Target limit{target.abs_error,
                     (series_to_run ? kRunEpicenterWithin : 1) * target.epicenter_ulp};
  const auto misses = [&](const detail::CertifiedError& bound, double factor) {
    return bound.abs_error > factor * limit.abs_error ||
           bound.epicenter_ulp > factor * limit.epicenter_ulp;
  };
  detail::CertifiedError certified =
      detail::certified_error(kernel, arithmetic, fit, scale, profiles.coarse, limit);
  if (finer && misses(certified, 1) && !misses(certified, kNearMiss))
    certified = detail::certified_error(kernel, arithmetic, fit, scale, profiles.fine(), limit);
  if (misses(certified, 1)) return std::nullopt;
  if (certified.epicenter_ulp <= target.epicenter_ulp) return certified;
  const std::optional<detail::QuotientFit> reference =
      series_to_run->reference_fit(1 - double(kernel.center_t));
  if (!reference) return std::nullopt;
  const std::optional<double> measured =
      detail::measured_epicenter_ulp(kernel, arithmetic, *reference, scale,
                                     profiles.coarse.w_epicenter, target.epicenter_ulp);
  if (measured && *measured <= target.epicenter_ulp) return certified;
  return std::nullopt;
}

// Drops a float polynomial kernel's clamp to [0, scale_f] where its certified bound proves the
// output within without it (LobeKernel::clamped), raising its cut as that proof needs.
//   Peak: w = 1 - min(t, 1) >= 0 and a computed q >= 0 make w q >= 0, so scale_f - w q rounds
//   to at most scale_f, and scale_lo - w q to at most scale_lo, then scale_f + (.) to at most
//   scale_f + scale_lo rounded, which must be scale_f.
//   Zero: the output is within E scale of scale F, so it is >= 0 where F >= E. The cut moves
//   up to the last float where F < E (1 + 2^-16) (the margin outweighs this computation's
//   roundings), at most the promise: there 0 is within it, and the certificate grows to cover it.
void drop_clamp_if_proven(detail::LobeKernel& kernel, detail::CertifiedError& certified,
                          const detail::LobeShape& shape, const Target& target) {
  const double zero_limit = certified.abs_error * (1 + 0x1p-16);
  // scale_f + scale_lo is exact in double.
  if (kernel.compensated || !(certified.lowest_q > 0) ||
      float(double(kernel.scale_f) + double(kernel.scale_lo)) != kernel.scale_f ||
      zero_limit * (1 + 0x1p-16) > target.abs_error)
    return;
  const double angle = fixed::acos(fixed::pow(zero_limit, 1.0 / shape.k)) / shape.c;  // F = limit
  if (angle < kPi / 2) {
    const double half_sine = fixed::sin(0.5 * angle);
    const float t_zero = detail::float_at_or_below_cut(1 - 2 * half_sine * half_sine);
    kernel.t_cut = std::max(kernel.t_cut, t_zero);
    certified.abs_error = std::max(certified.abs_error, zero_limit * (1 + 0x1p-16));
  }
  kernel.clamped = false;
}

// Where q's powers are centered, tried in this order at each degree: at the cut-off, then
// nearer the peak, where q's error weighs on the 2 ulps of the epicenter. A center below 1/2
// is raised to 1/2 where s = center_t - t is then exact (src/lobe_bound.cpp).
constexpr std::array kCenterFractions{1.0, 0.85, 0.7};  // of w_max, below t = 1
std::vector<float> center_candidates(double w_max) {
  std::vector<float> centers;
  const auto add = [&](float center) {
    if (std::find(centers.begin(), centers.end(), center) == centers.end())
      centers.push_back(center);
  };
  for (double fraction : kCenterFractions) {
    const float center = float(1 - fraction * w_max);
    add(center);
    if (center < 0.5f && 2 * (1 - w_max) >= 0.5) add(0.5f);
  }
  return centers;
}

// A kernel with the bound its setup certified.
struct CertifiedKernel {
  detail::LobeKernel kernel;
  detail::CertifiedError certified;
};

// F = scale - w q(s), q in powers of s = center_t - t, first the distance to the cut-off
// (center_t ~ cos(gran)): near the cut-off, where scale - w q cancels, s p(s) vanishes and
// only q's constant term is rounded; near t = 1 the errors of q are multiplied by w, small
// there, unless |s| is large there too (wide lobes): then the center moves up. The lowest
// degree that meets the target, if one does, at any center: first in the plain form (one
// multiply-add per degree), its bound certified or its epicenter run; else, with FMA, in the
// compensated form, about ten operations more.
std::optional<CertifiedKernel> fit_polynomial(detail::LobeKernel kernel, QuotientSeries& series,
                                         const detail::LobeShape& shape, double w_max,
                                         double scale, const Profiles& profiles,
                                         const Target& target, detail::Arithmetic arithmetic) {
  kernel.form = detail::LobeKernel::Form::polynomial;
  const float scale_lo = float(scale - double(kernel.scale_f));
  const std::vector<float> centers = center_candidates(w_max);
  // A pass on the support's pieces, then one on finer pieces for the kernels that missed by
  // little, before the compensated form.
  for (auto [compensated, finer] : {std::pair{false, false}, std::pair{false, true},
                                    std::pair{true, false}, std::pair{true, true}}) {
    if (compensated && arithmetic != detail::Arithmetic::fused) break;
    kernel.compensated = compensated;
    // Up to the degrees the array loops unroll; past them, base_power.
    for (int degree = 1;
         degree <= detail::LobeArrayKernels::kMaxArrayUnrolledDegree && series.converged();
         ++degree) {
      // The approximation alone must leave room: w_max q's truncation error at least.
      if (series.truncation_error(degree) * w_max > target.abs_error) continue;
      kernel.degree = degree;
      for (float center_t : centers) {
        kernel.center_t = center_t;
        kernel.center_d = double(center_t);
        const detail::QuotientFit fit = *series.fit(degree, 1 - double(center_t));
        for (int i = 0; i <= degree; ++i) {
          kernel.q_d[i] = double(scale * fit.monomials[i]);
          kernel.q_f[i] = float(kernel.q_d[i]);
        }
        // The scale whole, else split (scale_f + (scale_lo - w q): one more rounding, of a term
        // smaller than the output, against scale_f's whole rounding error in a lower binade).
        // SIMD kernels of either may be run over the epicenter: the whole scale saves an add
        // per batch, worth a second run.
        const bool split =
            arithmetic != detail::Arithmetic::scalar && (compensated || scale_lo != 0);
        QuotientSeries* series_to_run =
            !compensated && arithmetic != detail::Arithmetic::scalar ? &series : nullptr;
        kernel.scale_lo = 0;
        std::optional<detail::CertifiedError> certified;
        if (!compensated)
          certified =
              meets(kernel, arithmetic, fit, scale, profiles, finer, target, series_to_run);
        if (!certified && split) {
          kernel.scale_lo = scale_lo;
          certified =
              meets(kernel, arithmetic, fit, scale, profiles, finer, target, series_to_run);
        }
        if (certified) {
          if (arithmetic != detail::Arithmetic::scalar)
            drop_clamp_if_proven(kernel, *certified, shape, target);
          return CertifiedKernel{kernel, *certified};
        }
      }
      // Once the fit's own error is negligible, a higher degree only adds roundings.
      if (series.truncation_error(degree) * w_max < 0x1p-8 * target.abs_error) break;
    }
  }
  return std::nullopt;
}

// B^k, B = cos(c theta) = 1 - w q(w), which converges for every lobe: in double lanes, or on
// the scalar path in double or, where kernel.scalar_in_float, in float.
std::optional<CertifiedKernel> fit_base_power(detail::LobeKernel kernel, QuotientSeries& series,
                                              double w_max, double scale, const Profiles& profiles,
                                              const Target& target, detail::Arithmetic arithmetic) {
  kernel.form = detail::LobeKernel::Form::base_power;
  // Unfused (the deterministic mode's), every degree with the coefficients rounded to float
  // first: fits in the long double of x86-64 and of AArch64 differ near 2^-44 of a coefficient,
  // in double's last bits, and round to the same float but where one lies that near a float's
  // midpoint. Then in double, if no degree certifies so.
  for (const bool in_float_precision : {arithmetic == detail::Arithmetic::unfused, false}) {
    for (int degree = 1; degree <= detail::LobeKernel::kMaxDegree; ++degree) {
      // A base off by e puts F off by about k e near t = 1: a fit far from the target is
      // skipped.
      if (series.converged() && series.truncation_error(degree) * w_max > target.abs_error)
        continue;
      const std::optional<detail::QuotientFit> fit = series.fit(degree, 0);
      if (!fit) break;
      kernel.degree = degree;
      kernel.q_d.fill(0);
      kernel.q_f.fill(0);
      for (int i = 0; i <= degree; ++i) {
        kernel.q_f[i] = float(double(fit->monomials[i]));
        kernel.q_d[i] = in_float_precision ? double(kernel.q_f[i]) : double(fit->monomials[i]);
      }
      if (const auto certified =
              meets(kernel, arithmetic, *fit, scale, profiles, false, target, nullptr))
        return CertifiedKernel{kernel, *certified};
      // Once the fit's own error is negligible, a higher degree only adds roundings: in float
      // (the scalar path's, or float coefficients) the try ends there (it fails for the precise
      // variant, whose setup it would slow).
      if ((kernel.scalar_in_float || in_float_precision) && series.converged() &&
          series.truncation_error(degree) * w_max < 0x1p-8 * target.abs_error)
        break;
    }
    if (!in_float_precision) break;
  }
  return std::nullopt;
}

// The kernel for one variant and one arithmetic: in SIMD lanes the polynomial form if it
// meets the target (float lanes, fastest), else base_power (double lanes); in the scalar path
// (where its pieces were not certified) the polynomial form in float if its bound meets the
// target (the fast variant, mostly: a third faster than in double, n = 1000), else both forms
// in double, whichever takes fewer operations.
CertifiedKernel fit_kernel(const ref::KutlogLobe& reference, float t_cut,
                      const detail::LobeShape& shape, QuotientSeries& polynomial_series,
                      const std::function<QuotientSeries&()>& base_series, double w_max,
                      double scale, const Profiles& profiles, const Target& target,
                      detail::Arithmetic arithmetic) {
  detail::LobeKernel kernel;
  kernel.t_cut = t_cut;
  kernel.scale_f = float(scale);
  kernel.scale_d = scale;
  kernel.k = reference.k();
  // No float below 1 on the support (n from about 1e7 up, by k and Q): F is the peak at
  // t >= 1 and 0 below, which q = 0 gives exactly. A fit there divides by the support's width
  // and overflows float (and 0 * inf at t = 1 is NaN).
  if (kernel.t_cut == std::nextafter(1.0f, 0.0f)) return {kernel, target};
  // Beyond the same steps of q and 1 - w q, the base costs the power, the scale and a switch
  // on k: in the scalar path (Estrin's scheme) a polynomial of up to that many degrees more
  // runs as fast as the base, in float as in double (n = 1000, k = 5: degree 8 in double
  // takes a tenth longer than a base of degree 3).
  const int base_overhead = power_cost(kernel.k) + 1;
  if (arithmetic == detail::Arithmetic::scalar) {
    // In float where a form's bound allows, the cheaper form (a third faster than double).
    detail::LobeKernel in_float = kernel;
    in_float.scalar_in_float = true;
    std::optional<CertifiedKernel> polynomial = fit_polynomial(
        in_float, polynomial_series, shape, w_max, scale, profiles, target, arithmetic);
    if (polynomial && polynomial->kernel.degree > detail::LobeKernel::kMaxScalarUnrolledDegree)
      polynomial.reset();
    const std::optional<CertifiedKernel> base =
        fit_base_power(in_float, base_series(), w_max, scale, profiles, target, arithmetic);
    if (polynomial && (!base || polynomial->kernel.degree <= base->kernel.degree + base_overhead))
      return *polynomial;
    if (base) return *base;
  }
  const std::optional<CertifiedKernel> polynomial =
      fit_polynomial(kernel, polynomial_series, shape, w_max, scale, profiles, target, arithmetic);
  if (polynomial &&
      (arithmetic != detail::Arithmetic::scalar || polynomial->kernel.degree < 1 + base_overhead))
    return *polynomial;
  const std::optional<CertifiedKernel> base =
      fit_base_power(kernel, base_series(), w_max, scale, profiles, target, arithmetic);
  if (polynomial && (!base || polynomial->kernel.degree <= base->kernel.degree + base_overhead))
    return *polynomial;
  if (base) return *base;
  // Not seen on any lobe tried (tests/test_lobe.cpp: the grid and random lobes; seen there with
  // the targets made unreachable, src/lobe_setup_hook.hpp); a kernel whose bound misses is
  // never kept.
  throw std::runtime_error("kutlog: no kernel of Lobe(n = " + std::to_string(reference.n()) +
                           ", k = " + std::to_string(reference.k()) + ", Q = " +
                           std::to_string(reference.Q()) + ") meets the bound of its variant");
}

// The arithmetics whose kernels a Lobe fits: the fused ones only where the program links the
// array path, which alone runs them.
std::span<const detail::Arithmetic> fitted_arithmetics() {
  static constexpr detail::Arithmetic kAll[] = {
      detail::Arithmetic::fused, detail::Arithmetic::unfused, detail::Arithmetic::scalar};
#if defined(__ELF__)
  if (&detail::fused_epicenter_loops == nullptr) return std::span(kAll).last(2);
#endif
  return kAll;
}

// A variant's promise, times the tests' factor (src/lobe_setup_hook.hpp).
Target target_of(Variant variant) {
  const Target& promised = variant == Variant::fast ? kFastTarget : kPreciseTarget;
  const double factor = detail::lobe_target_factor_for_tests.load(std::memory_order_relaxed);
  return {promised.abs_error * factor, promised.epicenter_ulp * factor};
}

// The scalar path's pieces, if certified, with their certificate.
template <class Pieces>
bool keep_pieces(std::optional<detail::ScalarPiecesFitter::Fitted<Pieces>> fitted,
                 Pieces& pieces, detail::KernelCertificate& certificate) {
  if (!fitted) return false;
  pieces = std::move(fitted->pieces);
  certificate = {fitted->certified.abs_error, fitted->certified.epicenter_ulp};
  return true;
}

[[noreturn]] void throw_coef_overflow(double n, int k, double Q, double coef) {
  // coef grows like n for large n: the largest n whose coef fits a float, from coef at 1e30.
  constexpr double kLargeN = 1e30;
  const double n_limit =
      kLargeN * (std::numeric_limits<float>::max() / ref::coef_exact(kLargeN, k, Q));
  char message[320];
  std::snprintf(message, sizeof message,
                "kutlog: Lobe(n = %g, k = %d, Q = %g): n is out of range: its exact coef %g "
                "exceeds FLT_MAX; for k = %d and Q = %g, n must be at most about %.3g "
                "(coef <= FLT_MAX: normalized kernels compute in float)",
                n, k, Q, coef, k, Q, n_limit);
  throw std::invalid_argument(message);
}

}  // namespace

Lobe::Lobe(double n, int k, double Q) : n_(n), Q_(Q), k_(k) {
  const ref::KutlogLobe reference(n, k, Q);  // validates
  c_ = reference.c();
  cutoff_angle_ = reference.cutoff_angle();
  coef_exact_ = reference.coef_exact();
  if (!(coef_exact_ <= std::numeric_limits<float>::max()))
    throw_coef_overflow(n, k, Q, coef_exact_);
  detail::require_runnable_arch();
  const double limit = reference.integration_limit();
  const double half_sine = fixed::sin(0.5 * limit);
  const double w_max = 2 * half_sine * half_sine;  // 1 - cos(min(gran, pi/2))
  // F = 0 for t <= cos(gran), and below the horizon (t <= 0) when gran > pi/2.
  t_cut_ = detail::float_at_or_below_cut(cutoff_angle_ >= kPi / 2 ? 0.0 : fixed::cos(cutoff_angle_));
  const detail::LobeShape shape{c_, k_};
  const detail::LobeProfile profile = detail::lobe_profile(shape, w_max);
  std::optional<detail::LobeProfile> fine;
  const std::function<const detail::LobeProfile&()> fine_profile =
      [&]() -> const detail::LobeProfile& {
    if (!fine) fine = detail::lobe_profile(shape, w_max, detail::kFineProfilePieces);
    return *fine;
  };
  const Profiles profiles{profile, fine_profile};
  QuotientSeries polynomial_series(shape, k_, w_max);
  std::optional<QuotientSeries> base;
  const std::function<QuotientSeries&()> base_series = [&]() -> QuotientSeries& {
    if (!base) base.emplace(shape, 1, w_max);
    return *base;
  };
  detail::ScalarPiecesFitter pieces_fitter(shape, t_cut_);
  for (Variant variant : {Variant::precise, Variant::fast})
    for (Normalization normalization : {Normalization::none, Normalization::exact_coef})
      for (detail::Arithmetic arithmetic : fitted_arithmetics()) {
        const Target target = target_of(variant);
        const int index = kernel_index(variant, normalization, arithmetic);
        const double scale = normalization == Normalization::exact_coef ? coef_exact_ : 1.0;
        // The scalar path: the pieces if certified (the faster form), else a kernel.
        if (arithmetic == detail::Arithmetic::scalar &&
            (variant == Variant::fast
                 ? keep_pieces(pieces_fitter.fit<detail::FastScalarPieces>(scale, target),
                               fast_pieces_[int(normalization)], certificates_[index])
                 : keep_pieces(pieces_fitter.fit<detail::ScalarPieces>(scale, target),
                               precise_pieces_[int(normalization)], certificates_[index]))) {
          kernels_[index].t_cut = t_cut_;
          continue;
        }
        const CertifiedKernel fitted =
            fit_kernel(reference, t_cut_, shape, polynomial_series, base_series, w_max, scale,
                       profiles, target, arithmetic);
        kernels_[index] = fitted.kernel;
        certificates_[index] = {fitted.certified.abs_error, fitted.certified.epicenter_ulp};
        array_slots_[index] = std::uint8_t(detail::LobeArrayKernels::slot_of(kernels_[index]));
      }
}

float detail::evaluate_scalar_kernel(const LobeKernel& kernel, float t) noexcept {
  return kernel.evaluate(t);
}
float Lobe::eval_by_kernel(float t, Variant variant, Normalization normalization) const noexcept {
  return detail::evaluate_scalar_kernel(
      kernels_[kernel_index(variant, normalization, detail::Arithmetic::scalar)], t);
}

}  // namespace kutlog

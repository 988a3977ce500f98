#include "epicenter_check.hpp"

#include <algorithm>
#include <bit>
#include <cmath>
#include <cstdint>
#include <vector>

#include "arch/kernel_table.hpp"

namespace kutlog::detail {
namespace {

constexpr double kDoubleUnit = 0x1p-53;
// The reference is evaluated eight floats at a time, so that the compiler keeps eight
// independent Horner chains in flight (one chain alone waits on each multiply-add).
constexpr int kChains = 8;

}  // namespace

std::optional<double> measured_epicenter_ulp(const LobeKernel& kernel, Arithmetic arithmetic,
                                             const QuotientFit& reference, double scale,
                                             double w_epicenter) {
  const LobeArrayKernels* kernels = lobe_array_kernels_for(arithmetic);
  if (!kernels || kernel.form != LobeKernel::Form::polynomial) return std::nullopt;
  // Every float t of [1 - w_epicenter, 1], 1 first (t above 1 gives t = 1's output).
  const float t_lowest = float(1 - w_epicenter);
  const long count = long(std::bit_cast<std::uint32_t>(1.0f)) -
                     long(std::bit_cast<std::uint32_t>(t_lowest)) + 1;
  if (count > kMaxCheckedEpicenterFloats) return std::nullopt;
  std::vector<float> t(count), out(count);
  for (long i = 0; i < count; ++i)
    t[i] = std::bit_cast<float>(std::bit_cast<std::uint32_t>(1.0f) - std::uint32_t(i));
  kernels->of(kernel)(kernel, t.data(), out.data(), std::size_t(count));

  // scale (1 - w p(s)) in double: s = center_t - t and w = 1 - t are exact (floats of one
  // binade or two), the coefficients off by half a unit each, Horner's rule by one unit per
  // operation of sum |c_i| sigma^i; the truncation by the fit's bound; the subtraction by one.
  const int degree = int(reference.monomials.size()) - 1;
  std::vector<double> c(degree + 1);
  for (int i = 0; i <= degree; ++i) c[i] = double(scale * reference.monomials[i]);
  const double sigma = 1.0 - double(kernel.center_t);  // |s| <= 1 - center_t on the epicenter
  double absolute_sum = 0, sigma_power = 1;
  for (int i = 0; i <= degree; ++i, sigma_power *= sigma)
    absolute_sum += std::fabs(c[i]) * sigma_power;
  const double reference_error = w_epicenter * (scale * reference.approximation_error +
                                                (2 * degree + 3) * kDoubleUnit * absolute_sum) +
                                 2 * kDoubleUnit * scale;

  double worst = 0;
  for (long first = 0; first < count; first += kChains) {
    double s[kChains], w[kChains], q[kChains];
    const int lanes = int(std::min<long>(kChains, count - first));
    for (int j = 0; j < kChains; ++j) {
      const double t_j = t[first + std::min(j, lanes - 1)];
      s[j] = double(kernel.center_t) - t_j;
      w[j] = 1.0 - t_j;
      q[j] = c[degree];
    }
    for (int i = degree; i-- > 0;)
      for (int j = 0; j < kChains; ++j) q[j] = q[j] * s[j] + c[i];
    for (int j = 0; j < lanes; ++j) {
      const double exact = scale - w[j] * q[j];
      // The ulp of the smallest value the exact one can be.
      const double ulp = ulp_of_float(exact - reference_error);
      const double error = std::fabs(double(out[first + j]) - exact) + reference_error;
      worst = std::max(worst, error / ulp);
    }
  }
  return worst;
}

}  // namespace kutlog::detail

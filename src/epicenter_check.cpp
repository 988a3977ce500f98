#include "epicenter_check.hpp"

#include <algorithm>
#include <bit>
#include <cmath>
#include <cstdint>
#include <vector>

#include "arch/kernel_table.hpp"

namespace kutlog::detail {

#if defined(__ELF__)
// Weak: the array path links it (src/dispatch.cpp); without it no fused kernel is fitted.
[[gnu::weak]] decltype(fused_epicenter_loops) fused_epicenter_loops;
#endif

namespace {

// Floats a chunk: t and the kernel's outputs, 32 KiB.
constexpr long kChunk = 4096;

}  // namespace

std::optional<double> measured_epicenter_ulp(const detail::LobeKernel& kernel,
                                             detail::Arithmetic arithmetic,
                                             const QuotientFit& reference, double scale,
                                             double w_epicenter, double limit) {
  if (kernel.form != detail::LobeKernel::Form::polynomial) return std::nullopt;
  const std::optional<EpicenterLoops> loops =
      arithmetic == Arithmetic::unfused ? unfused_epicenter_loops()
      : arithmetic == Arithmetic::fused && &fused_epicenter_loops
          ? fused_epicenter_loops(kernel)
          : std::nullopt;
  if (!loops) return std::nullopt;
  // Every float t of [1 - w_epicenter, 1], 1 first (t above 1 gives t = 1's output).
  const float t_lowest = float(1 - w_epicenter);
  const long count = long(std::bit_cast<std::uint32_t>(1.0f)) -
                     long(std::bit_cast<std::uint32_t>(t_lowest)) + 1;
  if (count > max_checked_epicenter_floats(arithmetic)) return std::nullopt;

  // scale (1 - w p(s)) in double: s = center_t - t and w = 1 - t are exact (floats of one
  // binade or two), the coefficients off by half a unit each, Horner's rule by one unit per
  // operation of sum |c_i| sigma^i; the truncation by the fit's bound; the subtraction by one.
  const int degree = int(reference.monomials.size()) - 1;
  std::vector<double> c(degree + 1);
  for (int i = 0; i <= degree; ++i) c[i] = double(scale * reference.monomials[i]);
  // |s| on the epicenter, whose ends are w = 0 and w_epicenter
  const double w_center = 1.0 - double(kernel.center_t);
  const double sigma = std::max(w_center, std::fabs(w_epicenter - w_center));
  double absolute_sum = 0, sigma_power = 1;
  for (int i = 0; i <= degree; ++i, sigma_power *= sigma)
    absolute_sum += std::fabs(c[i]) * sigma_power;
  const EpicenterReference exact{
      c.data(), degree, double(kernel.center_t), scale,
      w_epicenter * (scale * reference.approximation_error +
                     (2 * degree + 3) * kDoubleUnit * absolute_sum) +
          2 * kDoubleUnit * scale};

  // In chunks that stay in L1, the reference on the best arch's double lanes; every 16th
  // float first.
  std::vector<float> t(std::size_t(std::min<long>(count, kChunk))), out(t.size());
  double worst = 0;
  for (const long stride : {16L, 1L}) {
    for (long first = 0; first < count; first += kChunk * stride) {
      const std::size_t size =
          std::size_t(std::min<long>(kChunk, (count - first + stride - 1) / stride));
      const std::uint32_t first_bits = std::bit_cast<std::uint32_t>(1.0f) - std::uint32_t(first);
      for (std::size_t i = 0; i < size; ++i)
        t[i] = std::bit_cast<float>(first_bits - std::uint32_t(stride * long(i)));
      loops->lobe(kernel, t.data(), out.data(), size);
      worst = std::max(worst, loops->worst_ulp(exact, t.data(), out.data(), size));
      if (worst > limit) return worst;
    }
  }
  return worst;
}

}  // namespace kutlog::detail

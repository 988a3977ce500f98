// The epicenter check's sweep (src/epicenter_check.cpp) in double lanes: every float t of an
// epicenter against the reference scale - (1 - t) p(center - t), on the best arch whatever
// arithmetic the kernel checked has (the reference's error bound holds fused or not).
#pragma once

#include <cstddef>
#include <cstdint>

#include "arch/kernel_table.hpp"
#include "kutlog/simd/float_ops.hpp"
#include "kutlog/simd/xsimd.hpp"

namespace kutlog::detail {

// The error of `out` at t in ulps of the float binade of the exact value, the reference's own
// error bound added: (|out - exact| + error) / ulp(exact - error). 1 / ulp from the exponent
// bits: 2^(23 - e) has biased exponent 2069 - (e + 1023), and is at most 2^149 (the float
// subnormals' ulp is 2^-149).
template <class Arch>
[[gnu::always_inline]] inline xsimd::batch<double, Arch> epicenter_ulps(
    const EpicenterReference& reference, xsimd::batch<double, Arch> t,
    xsimd::batch<double, Arch> out) {
  using D = xsimd::batch<double, Arch>;
  using I = xsimd::batch<std::int64_t, Arch>;
  const D s = D(reference.center) - t, w = D(1.0) - t;
  D p(reference.coefficients[reference.degree]);
  for (int i = reference.degree; i-- > 0;) p = simd::mul_add(p, s, D(reference.coefficients[i]));
  const D exact = D(reference.scale) - w * p;
  constexpr std::int64_t kExponentBits = std::int64_t(0x7ff) << 52;
  constexpr std::int64_t kInverseBias = std::int64_t(2069) << 52;
  const I exponent = xsimd::bitwise_cast<I>(exact - D(reference.error)) & I(kExponentBits);
  const D inverse_ulp =
      xsimd::min(xsimd::bitwise_cast<D>(I(kInverseBias) - exponent), D(0x1p149));
  return (xsimd::abs(out - exact) + D(reference.error)) * inverse_ulp;
}

// The largest of epicenter_ulps over the floats t and the kernel's outputs there.
template <class Arch>
double epicenter_worst_ulp(const EpicenterReference& reference, const float* t, const float* out,
                           std::size_t count) {
  using F = xsimd::batch<float, Arch>;
  using D = xsimd::batch<double, Arch>;
  D worst(0.0);
  const auto add = [&](F t_batch, F out_batch) {
    const simd::Pair<D> ts = simd::widen(t_batch), outs = simd::widen(out_batch);
    worst = xsimd::max(worst, epicenter_ulps<Arch>(reference, ts.hi, outs.hi));
    worst = xsimd::max(worst, epicenter_ulps<Arch>(reference, ts.lo, outs.lo));
  };
  std::size_t i = 0;
  for (; i + F::size <= count; i += F::size)
    add(F::load_unaligned(t + i), F::load_unaligned(out + i));
  if (i < count) {  // the tail, its last float repeated: the largest is unchanged
    alignas(64) float t_tail[F::size], out_tail[F::size];
    for (std::size_t j = 0; j < F::size; ++j) {
      const std::size_t k = i + j < count ? i + j : count - 1;
      t_tail[j] = t[k], out_tail[j] = out[k];
    }
    add(F::load_aligned(t_tail), F::load_aligned(out_tail));
  }
  alignas(64) double lanes[D::size];
  worst.store_aligned(lanes);
  double largest = 0;
  for (double lane : lanes) largest = lane > largest ? lane : largest;
  return largest;
}

}  // namespace kutlog::detail

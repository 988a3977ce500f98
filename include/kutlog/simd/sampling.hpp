// kutlog/simd/sampling.hpp: the F_kutlog lobe sampler of kutlog/sampling.hpp as a template on
// xsimd batches of float, for users who inline it. The contract and the data rule are
// kutlog/sampling.hpp's.
#pragma once

#include <cstdint>

#include "kutlog/sampling.hpp"
#include "kutlog/simd/lobe.hpp"
#include "kutlog/simd/math.hpp"
#include "kutlog/simd/xsimd.hpp"

namespace kutlog::simd {

template <class Arch>
struct SampleBatch {
  floats<Arch> x, y, z, pdf;
};

namespace detail {
inline constexpr float kLargestBelowOne = 0x1.fffffep-1f;
inline constexpr float kLargestBelowHalfPi = 1.57079625f;  // cos of it is > 0

// sin and cos of theta in [0, pi/2], each ending in one rounding (as cos_halfpi_u10).
template <class Arch>
inline Pair<floats<Arch>> sin_cos_halfpi(floats<Arch> theta) {
  using F = floats<Arch>;
  const Reduced<Arch> reduced = reduce_half_pi(theta);
  const F u = reduced.r_hi * reduced.r_hi;
  const F sin_r = sin_reduced(reduced.r_hi, reduced.r_lo, u);
  const F cos_r = cos_reduced(reduced.r_hi, reduced.r_lo, u);
  // theta = n pi/2 + r, n in {0, 1}: sin(pi/2 + r) = cos r, cos(pi/2 + r) = -sin r.
  const auto first_half = reduced.n == F(0.0f);
  return {xsimd::select(first_half, sin_r, cos_r), xsimd::select(first_half, cos_r, -sin_r)};
}

// sin and cos of the azimuth 2 pi u, u in [0, 1): 4u = q + f exactly, q an integer in 0..4,
// |f| <= 1/2, so 2 pi u = q pi/2 + r with r = f pi/2 formed to twice float precision.
template <class Arch>
inline Pair<floats<Arch>> sin_cos_turn(floats<Arch> u) {
  using F = floats<Arch>;
  const F four_u = u * F(4.0f), quadrant = xsimd::nearbyint(four_u), f = four_u - quadrant;
  const Pair<F> r = two_product(f, F(constants::kHalfPiHi));
  const F r_lo = mul_add(f, F(constants::kHalfPiLo), r.lo);
  const F square = r.hi * r.hi;
  const F sin_r = sin_reduced(r.hi, r_lo, square), cos_r = cos_reduced(r.hi, r_lo, square);
  // Quadrant 1: (cos, sin) = (-sin r, cos r); 2: (-cos r, -sin r); 3: (sin r, -cos r); 4 = 0.
  const auto odd = (quadrant == F(1.0f)) | (quadrant == F(3.0f));
  const F negative_cos = xsimd::select((quadrant == F(1.0f)) | (quadrant == F(2.0f)), F(-0.0f),
                                       F(0.0f));
  const F negative_sin = xsimd::select((quadrant == F(2.0f)) | (quadrant == F(3.0f)), F(-0.0f),
                                       F(0.0f));
  return {xsimd::select(odd, cos_r, sin_r) ^ negative_sin,
          xsimd::select(odd, sin_r, cos_r) ^ negative_cos};
}

// u in [0, 1): below 0 (and NaN) to 0, from 1 up to the largest float below 1.
template <class Arch>
inline floats<Arch> unit_interval(floats<Arch> u) {
  using F = floats<Arch>;
  return xsimd::select(u > F(0.0f), xsimd::min(u, F(kLargestBelowOne)), F(0.0f));
}
}  // namespace detail

// A SamplerKernel with its constants broadcast once, for loops over many batches.
template <class Arch>
class PreparedSampler {
 public:
  using F = floats<Arch>;
  using I = ints<Arch>;

  explicit PreparedSampler(const SamplerKernel& kernel)
      : kernel_(kernel), c_(kernel.c), limit_(kernel.limit), peak_(kernel.density_scale) {}

  // The polar angle theta(u1) of the fitted inverse CDF, in [0, limit]; u1 in [0, 1).
  F polar_angle(F u1) const {
    using K = SamplerKernel;
    static_assert(K::kBandsPerBinade == 8, "the band is the top 3 bits of w's mantissa");
    const auto lower = u1 <= F(0.5f);
    const F w = F(1.0f) - u1;  // exact for u1 >= 1/2
    // w's exponent field and top 3 mantissa bits: s = (e + 127) * 8 + band, so that
    // K::upper_cell(e, band) = kLowerCells + (125 - (e + 127)) * 8 + band.
    const I s = xsimd::bitwise_cast<I>(w) >> 20;
    const I upper = I(K::kLowerCells + 125 * K::kBandsPerBinade) - s + ((s & I(7)) << 1);
    const I cell = xsimd::to_int(
        xsimd::select(lower, xsimd::min(u1 * F(2 * K::kLowerCells), F(K::kLowerCells - 1)),
                      xsimd::to_float(upper)));
    const F x = xsimd::select(lower, u1, w) - F::gather(kernel_.center.data(), cell);
    const float* row = kernel_.coefficients.data() + kernel_.degree * K::kCells;
    F p = F::gather(row, cell);
    for (int j = kernel_.degree; j-- > 0;) {
      row -= K::kCells;
      p = mul_add(p, x, F::gather(row, cell));
    }
    const F theta = xsimd::select(lower, xsimd::sqrt(u1) * p, p);
    return xsimd::min(xsimd::max(theta, F(0.0f)), limit_);
  }

  SampleBatch<Arch> operator()(F u1, F u2) const {
    const F theta = polar_angle(detail::unit_interval(u1));
    const auto [sin_theta, cos_theta] = detail::sin_cos_halfpi(theta);
    const auto [sin_phi, cos_phi] = detail::sin_cos_turn(detail::unit_interval(u2));
    const F lobe = detail::integer_power(
        cos_halfpi_u10(xsimd::min(c_ * theta, F(detail::kLargestBelowHalfPi))), kernel_.k);
    const F density = kernel_.cosine_weighted ? peak_ * lobe * cos_theta : peak_ * lobe;
    const auto valid = (u1 == u1) & (u2 == u2);
    const F nan(std::numeric_limits<float>::quiet_NaN());
    return {xsimd::select(valid, sin_theta * cos_phi, nan),
            xsimd::select(valid, sin_theta * sin_phi, nan), xsimd::select(valid, cos_theta, nan),
            xsimd::select(valid, detail::clamp_zero_to(density, peak_), nan)};
  }

 private:
  const SamplerKernel& kernel_;
  F c_, limit_, peak_;
};

}  // namespace kutlog::simd

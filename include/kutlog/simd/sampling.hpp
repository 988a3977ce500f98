// kutlog/simd/sampling.hpp: kutlog/sampling.hpp's lobe sampler on xsimd float batches, and its
// one-sample path in double (on the arch for its FMA); the contract is kutlog/sampling.hpp's.
#pragma once

#include <cmath>
#include <cstdint>
#include <limits>

#include "kutlog/detail/integer_power.hpp"
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

// sin and cos of |r| <= pi/4 by the cores of cos_u10 without its compensated last steps: a few
// float roundings, which the sampler's bounds allow, at half the cost.
template <class Arch>
inline Pair<floats<Arch>> sin_cos_quarter_pi(floats<Arch> r) {
  using F = floats<Arch>;
  const F u = r * r;
  return {mul_add(r * u, horner(u, constants::kSin), r),
          mul_add(u * u, horner(u, constants::kCos), neg_mul_add(F(0.5f), u, F(1.0f)))};
}

// sin and cos of theta in [0, pi/2]: above pi/4 through rho = pi/2 - theta, formed exactly
// (Sterbenz) but for the low part of pi/2.
template <class Arch>
inline Pair<floats<Arch>> sin_cos_halfpi(floats<Arch> theta) {
  using F = floats<Arch>;
  const auto upper = theta > F(0.78539819f);
  const F rho = (F(constants::kHalfPiHi) - theta) + F(constants::kHalfPiLo);
  const auto [sin_r, cos_r] = sin_cos_quarter_pi(xsimd::select(upper, rho, theta));
  return {xsimd::select(upper, cos_r, sin_r), xsimd::select(upper, sin_r, cos_r)};
}

// sin and cos of the azimuth 2 pi u, u in [0, 1): 4u = q + f exactly, q an integer in 0..4,
// |f| <= 1/2, so 2 pi u = q pi/2 + r, r = f pi/2.
template <class Arch>
inline Pair<floats<Arch>> sin_cos_turn(floats<Arch> u) {
  using F = floats<Arch>;
  const F four_u = u * F(4.0f), quadrant = xsimd::nearbyint(four_u);
  const auto [sin_r, cos_r] = sin_cos_quarter_pi((four_u - quadrant) * F(constants::kHalfPiHi));
  // Quadrant 1: (cos, sin) = (-sin r, cos r); 2: (-cos r, -sin r); 3: (sin r, -cos r); 4 = 0.
  const auto odd = (quadrant == F(1.0f)) | (quadrant == F(3.0f));
  const F negative_cos = xsimd::select((quadrant == F(1.0f)) | (quadrant == F(2.0f)), F(-0.0f),
                                       F(0.0f));
  const F negative_sin = xsimd::select((quadrant == F(2.0f)) | (quadrant == F(3.0f)), F(-0.0f),
                                       F(0.0f));
  return {xsimd::select(odd, cos_r, sin_r) ^ negative_sin,
          xsimd::select(odd, sin_r, cos_r) ^ negative_cos};
}

// The cell of u1 in [0, 1) in the layout `cells` (kutlog/sampling.hpp's SamplerCells), and
// u1's position x in it.
template <class Arch>
struct CellPosition {
  ints<Arch> cell;
  floats<Arch> x;
  xsimd::batch_bool<float, Arch> lower;
};
template <SamplerCells cells, class Arch>
inline CellPosition<Arch> locate(floats<Arch> u1) {
  using F = floats<Arch>;
  using I = ints<Arch>;
  const auto lower = u1 <= F(0.5f);
  // Lower cells: 2 L u1 = cell + 1/2 + x exactly.
  const F scaled = u1 * F(2 * cells.lower_cells);
  const F lower_cell = xsimd::min(xsimd::floor(scaled), F(cells.lower_cells - 1));
  // Upper cells by the bits of w = 1 - u1 (exact): exponent and top band_bits give the cell,
  // the other mantissa bits, as a float in [1, 2), 1.5 + x.
  constexpr int kFractionBits = 23 - cells.band_bits;
  const I bits = xsimd::bitwise_cast<I>(F(1.0f) - u1);
  const I s = bits >> kFractionBits;
  const I upper_cell =
      I(cells.lower_cells + 125 * cells.bands()) - s + ((s & I(cells.bands() - 1)) << 1);
  const I fraction = (bits & I((1 << kFractionBits) - 1)) << cells.band_bits;
  const F upper_x = xsimd::bitwise_cast<F>(fraction | I(0x3f800000)) - F(1.5f);
  return {xsimd::select(xsimd::bool_cast(lower), xsimd::to_int(lower_cell), upper_cell),
          xsimd::select(lower, (scaled - lower_cell) - F(0.5f), upper_x), lower};
}

// Horner's rule over coefficient rows (row j at coefficients + j * stride), each lane's
// coefficients looked up by its cell with `lookup(row, cell)`.
template <class Arch, class Lookup>
inline floats<Arch> cell_polynomial(const float* coefficients, int degree, int stride,
                                    const CellPosition<Arch>& at, Lookup lookup) {
  const float* row = coefficients + degree * stride;
  floats<Arch> p = lookup(row, at.cell);
  for (int j = degree; j-- > 0;) {
    row -= stride;
    p = mul_add(p, at.x, lookup(row, at.cell));
  }
  return p;
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
      : kernel_(kernel), half_c_(0.5f * kernel.c), limit_(kernel.limit),
        peak_(kernel.density_scale) {}

  // The polar angle theta(u1) of the fitted inverse CDF, in [0, limit]. AVX-512 permutes the
  // coarse table (one instruction, not 16 loads); AVX2 gathers with its own instruction.
  F polar_angle(F u1) const {
    using K = SamplerKernel;
    F p;
    xsimd::batch_bool<float, Arch> lower;
#if XSIMD_WITH_AVX512F
    if constexpr (arch_of<Arch, xsimd::avx512f>) {
      const detail::CellPosition<Arch> at = detail::locate<K::kCoarse>(u1);
      p = detail::cell_polynomial(kernel_.coarse.data(), kernel_.coarse_degree, K::kCoarseStride,
                                  at, [](const float* row, I cell) -> F {
                                    return _mm512_permutex2var_ps(_mm512_loadu_ps(row), cell,
                                                                  _mm512_loadu_ps(row + 16));
                                  });
      lower = at.lower;
    } else
#endif
    {
      const detail::CellPosition<Arch> at = detail::locate<K::kFine>(u1);
      p = detail::cell_polynomial(kernel_.fine.data(), kernel_.fine_degree, K::kFine.count(), at,
                                  [](const float* row, I cell) -> F {
#if XSIMD_WITH_AVX2
                                    if constexpr (arch_of<Arch, xsimd::avx2>)
                                      return _mm256_i32gather_ps(row, cell, sizeof(float));
                                    else
#endif
                                      return F::gather(row, cell);
                                  });
      lower = at.lower;
    }
    const F theta = xsimd::select(lower, xsimd::sqrt(u1) * p, p);
    return xsimd::min(xsimd::max(theta, F(0.0f)), limit_);
  }

  SampleBatch<Arch> operator()(F u1, F u2) const {
    const F theta = polar_angle(detail::unit_interval(u1));
    const auto [sin_theta, cos_theta] = detail::sin_cos_halfpi(theta);
    const auto [sin_phi, cos_phi] = detail::sin_cos_turn(detail::unit_interval(u2));
    // F = cos^k(c theta), cos(c theta) = 1 - 2 sin^2(c theta / 2), c theta in [0, pi/2].
    const F half_angle = half_c_ * theta;
    const F sin_half = detail::sin_cos_quarter_pi(half_angle).hi;
    const F base = neg_mul_add(F(2.0f) * sin_half, sin_half, F(1.0f));
    const F lobe = kutlog::detail::integer_power(base, kernel_.k);
    const F density = kernel_.cosine_weighted ? peak_ * lobe * cos_theta : peak_ * lobe;
    const auto valid = (u1 == u1) & (u2 == u2);
    const F nan(std::numeric_limits<float>::quiet_NaN());
    return {xsimd::select(valid, sin_theta * cos_phi, nan),
            xsimd::select(valid, sin_theta * sin_phi, nan), xsimd::select(valid, cos_theta, nan),
            xsimd::select(valid, detail::clamp_zero_to(density, peak_), nan)};
  }

 private:
  const SamplerKernel& kernel_;
  F half_c_, limit_, peak_;
};

// PreparedSampler's steps for one (u1, u2) in double, a path tracer's one direction per bounce.
// The arch brings its FMA, shortening the chain of multiply-adds; helpers are templates on it,
// so each arch's TU compiles its own.
namespace one_sample {

struct SinCos {
  double sin, cos;
};

inline constexpr double kHalfPi = 1.5707963267948966;

template <class Arch>
inline double mul_add(double a, double b, double c) {
  if constexpr (has_fused_fma<Arch>)
    return std::fma(a, b, c);
  else
    return a * b + c;
}

// c[0] + c[1] u + c[2] u^2 + c[3] u^3 in pairs (Estrin's scheme): two steps deep, not three.
template <class Arch>
inline double pairwise_cubic(double u, const std::array<float, 4>& c) {
  const auto at = [&](std::size_t i) { return double(c[i]); };
  return mul_add<Arch>(u * u, mul_add<Arch>(at(3), u, at(2)), mul_add<Arch>(at(1), u, at(0)));
}

// sin and cos of |r| <= pi/4 by kutlog's cores: within 2^-27; the bounds allow 2^-21 of G.
template <class Arch>
inline SinCos sin_cos_quarter_pi(double r) {
  const double u = r * r;
  return {mul_add<Arch>(r * u, pairwise_cubic<Arch>(u, constants::kSin), r),
          mul_add<Arch>(u * u, pairwise_cubic<Arch>(u, constants::kCos), 1 - 0.5 * u)};
}

// sin and cos of theta in [0, pi/2]: above pi/4 by those of pi/2 - theta. Selects, not
// branches: a wide lobe's angles fall on both sides at random.
template <class Arch>
inline SinCos sin_cos_half_pi(double theta) {
  const bool upper = theta > 0.5 * kHalfPi;
  const SinCos r = sin_cos_quarter_pi<Arch>(upper ? kHalfPi - theta : theta);
  return {upper ? r.cos : r.sin, upper ? r.sin : r.cos};
}

// sin and cos of the azimuth 2 pi u: 4u = q + f exactly, (sin, cos)(f pi/2) turned by q pi/2
// with looked-up 0 and +-1: exact products, no branch on a random quadrant.
template <class Arch>
inline SinCos sin_cos_turn(float u) {
  static constexpr double kQuadrantSin[4] = {0, 1, 0, -1}, kQuadrantCos[4] = {1, 0, -1, 0};
  const double four_u = 4.0 * double(u);
  const int quadrant = int(four_u + 0.5);
  const SinCos r = sin_cos_quarter_pi<Arch>((four_u - quadrant) * kHalfPi);
  const double s = kQuadrantSin[quadrant & 3], c = kQuadrantCos[quadrant & 3];
  return {s * r.cos + c * r.sin, c * r.cos - s * r.sin};
}

// u in [0, 1): below 0 to 0, from 1 up to the largest float below 1 (NaN is the caller's).
template <class Arch>
inline float unit_interval(float u) {
  return u > 0 ? std::min(u, detail::kLargestBelowOne) : 0.0f;
}

// The polar angle theta(u1) of the fitted inverse CDF (the fine table), in [0, limit].
template <class Arch>
inline double polar_angle(const SamplerKernel& kernel, float u1) {
  using K = SamplerKernel;
  // Both sides' cells are found and one is selected: u1 falls on either side at random.
  const bool lower = u1 <= 0.5f;
  const SamplerCells::Position below = K::kFine.position<Arch>(true, double(u1)),
                               above = K::kFine.position<Arch>(false, 1.0 - double(u1));
  const int cell = lower ? below.cell : above.cell;
  const double x = lower ? below.x : above.x;
  constexpr int kStride = K::kFine.count();
  const float* coefficient = kernel.fine.data() + kernel.fine_degree * kStride + cell;
  double p = double(*coefficient);
  for (int j = kernel.fine_degree; j-- > 0;)
    p = mul_add<Arch>(p, x, double(*(coefficient -= kStride)));
  return std::clamp((lower ? std::sqrt(double(u1)) : 1.0) * p, 0.0, double(kernel.limit));
}

template <class Arch>
inline SampledDirection sample(const SamplerKernel& kernel, float u1, float u2) {
  if (std::isnan(u1) || std::isnan(u2)) {
    constexpr float kNaN = std::numeric_limits<float>::quiet_NaN();
    return {kNaN, kNaN, kNaN, kNaN};
  }
  const double theta = polar_angle<Arch>(kernel, unit_interval<Arch>(u1));
  const SinCos polar = sin_cos_half_pi<Arch>(theta);
  const SinCos azimuth = sin_cos_turn<Arch>(unit_interval<Arch>(u2));
  // F = cos^k(c theta) with cos(c theta) = 1 - 2 sin^2(c theta / 2), c theta in [0, pi/2].
  const double sin_half = sin_cos_quarter_pi<Arch>(0.5 * double(kernel.c) * theta).sin;
  const double lobe = kutlog::detail::integer_power<Arch>(1 - 2 * sin_half * sin_half, kernel.k);
  const double density =
      double(kernel.density_scale) * lobe * (kernel.cosine_weighted ? polar.cos : 1);
  return {float(polar.sin * azimuth.cos), float(polar.sin * azimuth.sin), float(polar.cos),
          std::clamp(float(density), 0.0f, kernel.density_scale)};
}

}  // namespace one_sample

}  // namespace kutlog::simd

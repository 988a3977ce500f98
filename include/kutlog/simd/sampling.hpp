// kutlog/simd/sampling.hpp: kutlog/sampling.hpp's lobe sampler on xsimd float batches, and its
// one-sample path in float scalars (on the arch for its FMA); the contract is
// kutlog/sampling.hpp's.
#pragma once

#include <algorithm>
#include <bit>
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
  const I upper_cell = I(cells.upper_cell_offset()) - s + ((s & I(cells.bands() - 1)) << 1);
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

// One (u1, u2) per call, a path tracer's one direction per bounce, in float scalars with no
// branch on the random numbers: the setup's per-cell fits of sin(theta/2) and of the pdf
// (SamplerKernel::one_sample) leave two square roots and the azimuth's sine and cosine.
// Templates on the arch, which brings its FMA: each arch's TU compiles its own.
namespace one_sample {

struct SinCos {
  float sin, cos;
};

template <class Arch>
inline float mul_add(float a, float b, float c) {
  if constexpr (has_fused_fma<Arch>)
    return std::fma(a, b, c);
  else
    return a * b + c;
}

// c[0] + c[1] x + ... + c[4] x^4 in pairs (Estrin's scheme): three steps deep, not four.
// Always the full degree: a fit of lower degree has zeros above it, cheaper than a branch.
template <class Arch>
inline float quartic(const float* c, float x) {
  static_assert(SamplerKernel::kOneSampleDegree == 4);
  const float square = x * x;
  const float high = mul_add<Arch>(c[4], square, mul_add<Arch>(c[3], x, c[2]));
  return mul_add<Arch>(square, high, mul_add<Arch>(c[1], x, c[0]));
}

// sin and cos of |r| <= pi/4 by the cores of kutlog's sin and cos, as the arrays'.
template <class Arch>
inline SinCos sin_cos_quarter_pi(float r) {
  const float u = r * r;
  const auto core = [u](const std::array<float, 4>& c) {
    return mul_add<Arch>(u * u, mul_add<Arch>(c[3], u, c[2]), mul_add<Arch>(c[1], u, c[0]));
  };
  return {mul_add<Arch>(r * u, core(constants::kSin), r),
          mul_add<Arch>(u * u, core(constants::kCos), mul_add<Arch>(-0.5f, u, 1.0f))};
}

// sin and cos of the azimuth 2 pi u, u in [0, 1): 4u = q + f exactly, (sin, cos)(f pi/2)
// turned by q pi/2 with looked-up 0 and +-1: exact products, no branch on a random quadrant.
template <class Arch>
inline SinCos sin_cos_turn(float u) {
  static constexpr float kQuadrantSin[4] = {0, 1, 0, -1}, kQuadrantCos[4] = {1, 0, -1, 0};
  // 4u + 1.5 2^23 rounds 4u to an integer q in its low mantissa bits; f = 4u - q exactly.
  constexpr float kRounder = 0x1.8p23f;
  const float four_u = 4.0f * u, rounded = four_u + kRounder;
  const unsigned quadrant = std::bit_cast<std::uint32_t>(rounded) & 3u;
  const SinCos r = sin_cos_quarter_pi<Arch>((four_u - (rounded - kRounder)) * constants::kHalfPiHi);
  const float s = kQuadrantSin[quadrant], c = kQuadrantCos[quadrant];
  return {s * r.cos + c * r.sin, c * r.cos - s * r.sin};
}

// u in [0, 1): below 0 to 0, from 1 up to the largest float below 1 (NaN is the caller's).
inline float unit_interval(float u) { return std::min(u > 0 ? u : 0.0f, detail::kLargestBelowOne); }

// u1's row of SamplerKernel::one_sample and its x there, from the bits of w = 1 - u1 alone
// (kOneSample has no lower cells: no branch or select on which half u1 falls in, at random).
// Below 1/2, w is u1's complement rounded, which moves x by at most 2^-21; at u1 = 0, w is
// the largest float below 1, the last cell's edge.
struct Row {
  const float* coefficients;
  float x;
};
inline Row row_of(const SamplerKernel& kernel, float u1) {
  constexpr SamplerCells kCells = SamplerKernel::kOneSample;
  static_assert(kCells.lower_cells == 0 && kCells.top_exponent == -1);
  constexpr int kFractionBits = 23 - kCells.band_bits;
  const auto bits = std::bit_cast<std::uint32_t>(std::min(1.0f - u1, detail::kLargestBelowOne));
  const int s = int(bits >> kFractionBits);
  const int cell = kCells.upper_cell_offset() - s + ((s & (kCells.bands() - 1)) << 1);
  const float x =
      std::bit_cast<float>(((bits & ((1u << kFractionBits) - 1)) << kCells.band_bits) |
                           0x3f800000u) - 1.5f;
  return {kernel.one_sample.data() + cell * SamplerKernel::kOneSampleStride, x};
}

template <class Arch>
inline SampledDirection sample(const SamplerKernel& kernel, float u1, float u2) {
  if (std::isnan(u1) || std::isnan(u2)) {
    constexpr float kNaN = std::numeric_limits<float>::quiet_NaN();
    return {kNaN, kNaN, kNaN, kNaN};
  }
  u1 = unit_interval(u1);
  const Row row = row_of(kernel, u1);
  const float fitted = quartic<Arch>(row.coefficients, row.x);
  const float pdf = quartic<Arch>(row.coefficients + SamplerKernel::kOneSampleDegree + 1, row.x);
  // The fit's weight sqrt(min(2 u1, 1)), exactly 1 above 1/2; the min on the bits (u1 >= 0
  // orders them as the values), which GCC keeps a cmov where a float min became a branch.
  const float weight = std::sqrt(std::bit_cast<float>(
      std::min(std::bit_cast<std::uint32_t>(u1 + u1), std::bit_cast<std::uint32_t>(1.0f))));
  // s = sin(theta/2): cos(theta) = 1 - 2 s^2, sin(theta) = 2 s cos(theta/2).
  const float s = std::clamp(weight * fitted, 0.0f, kernel.half_sine_limit);
  const float cos_theta = mul_add<Arch>(-2.0f * s, s, 1.0f);
  const float sin_theta = (s + s) * std::sqrt(mul_add<Arch>(-s, s, 1.0f));
  const SinCos azimuth = sin_cos_turn<Arch>(unit_interval(u2));
  return {sin_theta * azimuth.cos, sin_theta * azimuth.sin, cos_theta,
          std::clamp(pdf, 0.0f, kernel.density_scale)};
}

}  // namespace one_sample

}  // namespace kutlog::simd

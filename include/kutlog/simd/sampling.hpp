// kutlog/simd/sampling.hpp: kutlog/sampling.hpp's lobe sampler on xsimd float batches, and its
// one-sample path in float scalars (on the arch for its FMA); the contract is
// kutlog/sampling.hpp's.
#pragma once

#include "kutlog/api.hpp"  // below C++20 its #error, and this header is empty
#if KUTLOG_HAS_CXX20

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
// float roundings, which the sampler's bounds allow, at half the cost. kMayFuse as mul_add's.
template <bool kMayFuse = true, class Arch>
inline Pair<floats<Arch>> sin_cos_quarter_pi(floats<Arch> r) {
  using F = floats<Arch>;
  const F u = r * r;
  return {mul_add<kMayFuse>(r * u, horner<kMayFuse>(u, constants::kSin), r),
          mul_add<kMayFuse>(u * u, horner<kMayFuse>(u, constants::kCos),
                            neg_mul_add<kMayFuse>(F(0.5f), u, F(1.0f)))};
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
// |f| <= 1/2, so 2 pi u = q pi/2 + r, r = f pi/2. 4u + 1.5 2^23 rounds 4u to q and holds it
// in its low mantissa bits, so the quadrant's swap and signs are bit operations.
template <bool kMayFuse = true, class Arch>
inline Pair<floats<Arch>> sin_cos_turn(floats<Arch> u) {
  using F = floats<Arch>;
  using I = ints<Arch>;
  constexpr float kRounder = 0x1.8p23f;
  const F four_u = u * F(4.0f), rounded = four_u + F(kRounder);
  const auto [sin_r, cos_r] =
      sin_cos_quarter_pi<kMayFuse>((four_u - (rounded - F(kRounder))) * F(constants::kHalfPiHi));
  // Quadrant q: (sin, cos) = (s, c), (c, -s), (-s, -c), (-c, s): swapped where q is odd, sin
  // negated where bit 1 of q is set, cos where bit 1 of q + 1 is (bit 1 moved to the sign).
  const I q = xsimd::bitwise_cast<I>(rounded), odd = q << 31;
  const I sin_sign = (q << 30) & I(std::numeric_limits<int>::min());
  const I cos_sign = sin_sign ^ odd;  // bit 1 of q + 1 is bit 1 of q flipped where q is odd
  // The swap where q is odd, by bits: x ^ ((sin ^ cos) & mask) is the other where mask is all
  // ones (GCC makes two blends five instructions).
  const F swap = (sin_r ^ cos_r) & xsimd::bitwise_cast<F>(odd >> 31);
  return {sin_r ^ (swap ^ xsimd::bitwise_cast<F>(sin_sign)),
          cos_r ^ (swap ^ xsimd::bitwise_cast<F>(cos_sign))};
}

// The band cell of w in [2^-24, 1) in the layout `cells` (kutlog::detail::SamplerCells)
// from its bits: the exponent and the top band_bits give the cell, the other mantissa bits,
// as a float in [1, 2), 1.5 + x.
template <class Arch>
struct BandPosition {
  ints<Arch> cell;
  floats<Arch> x;
};
template <kutlog::detail::SamplerCells cells, class Arch>
inline BandPosition<Arch> band_position(floats<Arch> w) {
  using F = floats<Arch>;
  using I = ints<Arch>;
  constexpr int kFractionBits = 23 - cells.band_bits;
  const I bits = xsimd::bitwise_cast<I>(w);
  const I s = bits >> kFractionBits;
  const I fraction = (bits & I((1 << kFractionBits) - 1)) << cells.band_bits;
  return {I(cells.upper_cell_offset()) - s + ((s & I(cells.bands() - 1)) << 1),
          xsimd::bitwise_cast<F>(fraction | I(0x3f800000)) - F(1.5f)};
}

// The cell of u1 in [0, 1) in the layout `cells` (kutlog::detail::SamplerCells), and
// u1's position x in it.
template <class Arch>
struct CellPosition {
  ints<Arch> cell;
  floats<Arch> x;
  xsimd::batch_bool<float, Arch> lower;
};
template <kutlog::detail::SamplerCells cells, class Arch>
inline CellPosition<Arch> locate(floats<Arch> u1) {
  using F = floats<Arch>;
  const auto lower = u1 <= F(0.5f);
  // Lower cells: 2 L u1 = cell + 1/2 + x exactly.
  const F scaled = u1 * F(2 * cells.lower_cells);
  const F lower_cell = xsimd::min(xsimd::floor(scaled), F(cells.lower_cells - 1));
  // Upper cells by the bits of w = 1 - u1 (exact).
  const BandPosition<Arch> upper = band_position<cells>(F(1.0f) - u1);
  return {xsimd::select(xsimd::bool_cast(lower), xsimd::to_int(lower_cell), upper.cell),
          xsimd::select(lower, (scaled - lower_cell) - F(0.5f), upper.x), lower};
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

// u in [0, 1): below 0 to 0, from 1 up to the largest float below 1. NaN gives 0 on x86 and
// NaN elsewhere: the callers NaN its outputs (nan_where_unordered) and index nothing by it.
template <class Arch>
inline floats<Arch> unit_interval(floats<Arch> u) {
  using F = floats<Arch>;
  return xsimd::min(xsimd::max(u, F(0.0f)), F(kLargestBelowOne));
}

// The sample, NaN in every output where u1 or u2 is NaN. With SSE and AVX, an OR with the
// all-ones lanes (a NaN) of one unordered compare: GCC makes each select there a compare and
// an AND or a three-uop blend.
template <class Arch>
inline SampleBatch<Arch> nan_where_unordered(floats<Arch> u1, floats<Arch> u2,
                                             SampleBatch<Arch> s) {
  return {ops::nan_where_unordered(u1, u2, s.x, Arch{}),
          ops::nan_where_unordered(u1, u2, s.y, Arch{}),
          ops::nan_where_unordered(u1, u2, s.z, Arch{}),
          ops::nan_where_unordered(u1, u2, s.pdf, Arch{})};
}
}  // namespace detail

// A SamplerKernel with its constants broadcast once, for loops over many batches. On AVX-512,
// kDoublePower raises the lobe's base to the k-th power in double lanes: the loop chooses
// it once (double_power_needed), not each batch. kDeterministic (Variant::deterministic) reads
// rows on every arch, its multiply-adds unfused and its NaN the same: the same bits everywhere.
template <class Arch, bool kDoublePower = false, bool kDeterministic = false>
class PreparedSampler {
  static constexpr bool kMayFuse = !kDeterministic;

 public:
  // In float, the base's rounding (2^-24 near 1) and each squaring's grow k-fold in F, within
  // the pdf bound up to this k (the grid and random lobes measure it).
  static constexpr int kFloatPowerMaxK = 5;
  // Whether this arch's batches draw theta from the coarse fit, and so raise the lobe to a
  // power (AVX-512's path; the others read rows).
  static constexpr bool kRaisesPower =
      !kDeterministic && ops::samples_by_polar_angle<Arch>(Arch{});
  static bool double_power_needed(const kutlog::detail::SamplerKernel& kernel) {
    return kRaisesPower && kernel.k > kFloatPowerMaxK;
  }

  using F = floats<Arch>;
  using I = ints<Arch>;

  explicit PreparedSampler(const kutlog::detail::SamplerKernel& kernel)
      : kernel_(kernel), half_c_(0.5f * kernel.c), limit_(kernel.limit),
        peak_(kernel.density_scale) {}

  // The polar angle theta(u1) of the coarse fit of the inverse CDF, in [0, limit], each
  // coefficient looked up by the arch's lookup of 32 cells.
  F polar_angle(F u1) const requires(kRaisesPower) {
    using K = kutlog::detail::SamplerKernel;
    const detail::CellPosition<Arch> at = detail::locate<K::kCoarse>(u1);
    const F p = detail::cell_polynomial(
        kernel_.coarse.data(), kernel_.coarse_degree, K::kCoarseStride, at,
        [](const float* row, I cell) -> F { return ops::coarse_coefficient(row, cell, Arch{}); });
    const F theta = xsimd::select(at.lower, xsimd::sqrt(u1) * p, p);
    return xsimd::min(xsimd::max(theta, F(0.0f)), limit_);
  }

  // Theta from the coarse fit, then its sine and cosine, and the pdf from c theta.
  SampleBatch<Arch> from_polar_angle(F u1, F u2) const requires(kRaisesPower) {
    const F theta = polar_angle(detail::unit_interval(u1));
    const auto [sin_theta, cos_theta] = detail::sin_cos_halfpi(theta);
    const F lobe = lobe_power(detail::sin_cos_quarter_pi(half_c_ * theta).hi);
    const F density = kernel_.cosine_weighted ? peak_ * lobe * cos_theta : peak_ * lobe;
    return finish(u1, u2, sin_theta, cos_theta, density);
  }

  // F = cos^k(c theta) = (1 - 2 s^2)^k, s = sin(c theta / 2), c theta in [0, pi/2]; in double
  // lanes, rounded once, where kDoublePower.
  F lobe_power(F sin_half) const requires(kRaisesPower) {
    if constexpr (!kDoublePower) {
      return kutlog::detail::integer_power(neg_mul_add(F(2.0f) * sin_half, sin_half, F(1.0f)),
                                           kernel_.k);
    } else {
      using D = doubles<Arch>;
      const auto power = [this](D s) {
        return kutlog::detail::integer_power(neg_mul_add(D(2.0) * s, s, D(1.0)), kernel_.k);
      };
      const Pair<D> halves = widen(sin_half);
      return narrow(power(halves.hi), power(halves.lo));
    }
  }

  // The other archs: the cell's row of SamplerKernel::rows (the one-sample call's), the
  // haversine q = sin^2(theta/2) (over its scale) and the pdf from its two cubics, then
  // cos(theta) = 1 - 2 q and sin(theta) = 2 sqrt(q (1 - q)): no sine of theta and no power.
  SampleBatch<Arch> from_rows(F u1, F u2) const {
    using K = kutlog::detail::SamplerKernel;
    static_assert(K::kRowCells.lower_cells == 0 && K::kRowCells.top_exponent == -1);
    const F u = detail::unit_interval(u1);
    // w = 1 - u rounded below 1/2 (x moves by at most 2^-21); u = 0 gives the last cell's edge.
    const detail::BandPosition<Arch> at = detail::band_position<K::kRowCells>(
        xsimd::min(F(1.0f) - u, F(detail::kLargestBelowOne)));
    const F x = at.x;
    // A NaN u1 leaves any bits in w (not on x86): its cell, clamped as unsigned, reads a row.
    using U = xsimd::batch<std::uint32_t, Arch>;
    const U last_cell(std::uint32_t(K::kRowCells.count() - 1));
    const std::array<F, K::kRowStride> c = row_coefficients(
        xsimd::bitwise_cast<I>(xsimd::min(xsimd::bitwise_cast<U>(at.cell), last_cell)));
    const F square = x * x;
    const auto cubic = [&](std::size_t first) {
      return mul_add<kMayFuse>(square, mul_add<kMayFuse>(c[first + 3], x, c[first + 2]),
                               mul_add<kMayFuse>(c[first + 1], x, c[first]));
    };
    static_assert(K::kRowDegree == 3 && K::kRowStride == 8);
    const F weight = xsimd::min(u + u, F(1.0f));  // exactly 1 above 1/2
    const F scaled = xsimd::min(xsimd::max(weight * cubic(0), F(0.0f)),
                                F(kernel_.haversine_limit));
    const F q = F(kernel_.haversine_scale) * scaled;
    return finish(u1, u2,
                  F(kernel_.sine_scale) * xsimd::sqrt(neg_mul_add<kMayFuse>(q, scaled, scaled)),
                  neg_mul_add<kMayFuse>(F(2.0f), q, F(1.0f)), cubic(4));
  }

  SampleBatch<Arch> operator()(F u1, F u2) const {
    if constexpr (kRaisesPower) return from_polar_angle(u1, u2);
    else return from_rows(u1, u2);
  }

 private:
  // The direction from theta's sine and cosine and the azimuth 2 pi u2; the pdf clamped to
  // [0, peak]; NaN in every output where u1 or u2 is NaN.
  SampleBatch<Arch> finish(F u1, F u2, F sin_theta, F cos_theta, F density) const {
    const auto [sin_phi, cos_phi] = detail::sin_cos_turn<kMayFuse>(detail::unit_interval(u2));
    const SampleBatch<Arch> sample{sin_theta * cos_phi, sin_theta * sin_phi, cos_theta,
                                   detail::clamp_zero_to(density, peak_)};
    if constexpr (kDeterministic) {  // the quiet NaN, where SSE and AVX set every bit
      const auto ordered = (u1 == u1) & (u2 == u2);
      const F nan(std::numeric_limits<float>::quiet_NaN());
      return {xsimd::select(ordered, sample.x, nan), xsimd::select(ordered, sample.y, nan),
              xsimd::select(ordered, sample.z, nan), xsimd::select(ordered, sample.pdf, nan)};
    }
    return detail::nan_where_unordered(u1, u2, sample);
  }

  // Each lane's row of SamplerKernel::rows, transposed: coefficient j of every lane in batch
  // j. Whole-row loads and shuffles, where gathers cost a load per lane and coefficient.
  std::array<F, kutlog::detail::SamplerKernel::kRowStride> row_coefficients(I cell) const {
    constexpr std::size_t N = F::size;
    constexpr int kRowBytes = kutlog::detail::SamplerKernel::kRowStride * int(sizeof(float));
    // Byte offsets, unsigned: each lane's address is then one add, with no sign extension.
    alignas(64) std::uint32_t offsets[N];
    (cell * I(kRowBytes)).store_aligned(reinterpret_cast<std::int32_t*>(offsets));
#if defined(__GNUC__)
    // Read back from memory: GCC would extract each lane instead (vpextrd, two uops each), 10%
    // slower over the whole AVX2 batch than one store and a load per lane.
    asm volatile("" : "+m"(offsets));
#endif
    const auto row = [&](std::size_t lane) {
      return reinterpret_cast<const float*>(
          reinterpret_cast<const char*>(kernel_.rows.data()) + offsets[lane]);
    };
    static_assert(kutlog::detail::SamplerKernel::kRowStride == 8);
    return ops::transpose_rows<Arch>(row, Arch{});
  }

  const kutlog::detail::SamplerKernel& kernel_;
  F half_c_, limit_, peak_;
};

// One (u1, u2) per call, a path tracer's one direction per bounce, in float scalars with no
// branch on the random numbers: the setup's per-cell fits of sin^2(theta/2) and of the pdf
// (SamplerKernel::rows) leave one square root and the azimuth's sine and cosine.
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

// c[0] + c[1] x + c[2] x^2 + c[3] x^3 in pairs (Estrin's scheme): two steps deep, not three.
// Always the full degree: a fit of lower degree has zeros above it, cheaper than a branch.
template <class Arch>
inline float cubic(const float* c, float x) {
  static_assert(kutlog::detail::SamplerKernel::kRowDegree == 3);
  return mul_add<Arch>(x * x, mul_add<Arch>(c[3], x, c[2]), mul_add<Arch>(c[1], x, c[0]));
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

// u1's row of SamplerKernel::rows and its x there, from the bits of w = 1 - u1 alone
// (kRowCells has no lower cells: no branch or select on which half u1 falls in, at random).
// Below 1/2, w is u1's complement rounded, which moves x by at most 2^-21; at u1 = 0, w is
// the largest float below 1, the last cell's edge.
struct Row {
  const float* coefficients;
  float x;
};
inline Row row_of(const kutlog::detail::SamplerKernel& kernel, float u1) {
  constexpr kutlog::detail::SamplerCells kCells = kutlog::detail::SamplerKernel::kRowCells;
  static_assert(kCells.lower_cells == 0 && kCells.top_exponent == -1);
  constexpr int kFractionBits = 23 - kCells.band_bits;
  const auto bits = std::bit_cast<std::uint32_t>(std::min(1.0f - u1, detail::kLargestBelowOne));
  const int s = int(bits >> kFractionBits);
  const int cell = kCells.upper_cell_offset() - s + ((s & (kCells.bands() - 1)) << 1);
  const float x =
      std::bit_cast<float>(((bits & ((1u << kFractionBits) - 1)) << kCells.band_bits) |
                           0x3f800000u) - 1.5f;
  return {kernel.rows.data() + cell * kutlog::detail::SamplerKernel::kRowStride, x};
}

template <class Arch>
inline SampledDirection sample(const kutlog::detail::SamplerKernel& kernel, float u1, float u2) {
  if (std::isnan(u1) || std::isnan(u2)) {
    constexpr float kNaN = std::numeric_limits<float>::quiet_NaN();
    return {kNaN, kNaN, kNaN, kNaN};
  }
  u1 = unit_interval(u1);
  const Row row = row_of(kernel, u1);
  const float fitted = cubic<Arch>(row.coefficients, row.x);
  const float pdf =
      cubic<Arch>(row.coefficients + kutlog::detail::SamplerKernel::kRowDegree + 1, row.x);
  // The fit's weight min(2 u1, 1), exactly 1 above 1/2; the min on the bits (u1 >= 0 orders
  // them as the values), which GCC keeps a cmov where a float min became a branch.
  const float weight = std::bit_cast<float>(
      std::min(std::bit_cast<std::uint32_t>(u1 + u1), std::bit_cast<std::uint32_t>(1.0f)));
  // q = sin^2(theta/2): cos(theta) = 1 - 2 q, sin(theta) = 2 sqrt(q (1 - q)).
  const float scaled = std::clamp(weight * fitted, 0.0f, kernel.haversine_limit);
  const float q = kernel.haversine_scale * scaled;
  const float cos_theta = mul_add<Arch>(-2.0f, q, 1.0f);
  const float sin_theta = kernel.sine_scale * std::sqrt(mul_add<Arch>(-q, scaled, scaled));
  const SinCos azimuth = sin_cos_turn<Arch>(unit_interval(u2));
  return {sin_theta * azimuth.cos, sin_theta * azimuth.sin, cos_theta,
          std::clamp(pdf, 0.0f, kernel.density_scale)};
}

}  // namespace one_sample

}  // namespace kutlog::simd

#endif  // KUTLOG_HAS_CXX20

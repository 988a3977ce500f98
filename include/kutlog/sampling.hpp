// kutlog/sampling.hpp: importance sampling of the normalized F_kutlog lobe, in SIMD, for one
// material: arrays of uniform numbers in, directions and their pdf out; or one sample per call.
//
//   const kutlog::LobeSampler sampler(n, k, Q, kutlog::LobeUse::microfacet);  // once
//   sampler.sample(u1, u2, {x, y, z, pdf}, count);                            // per batch
//   const kutlog::SampledDirection d = sampler.sample(u1, u2);               // per bounce
//
// The two uses of kutlog/sampling_reference.hpp (the spec): microfacet half vectors wm with
// pdf D(wm) cos(theta_m), in the frame whose z is the normal; phong directions with pdf
// F(R.w) / (2 pi J), in the frame whose z is the mirror direction R. Rotating into the shading
// frame and reflecting are the caller's (ref::KutlogMicrofacet::reflect says how).
//
// How it is fast: the setup fits the polar angle's inverse CDF, theta(u1), once per material
// (milliseconds: about 3 on an AMD EPYC; no allocation per call), as piecewise polynomials in
// variables that make it smooth: theta = sqrt(u1) P(u1) on u1 <= 1/2 (cdf ~ theta^2 near the
// peak), and theta = P(1 - u1) on 1/2 < u1 < 1 in cells of each binade of 1 - u1 (1 - cdf
// vanishes as a power of the distance to the cut-off), each fit checked against
// ref::PolarAngleDistribution::inverse_cdf at setup. A batch then looks its cells'
// coefficients up, runs Horner's rule, and takes the sines and cosines of theta, of the
// azimuth 2 pi u2 and of c theta (for F) from the polynomial cores of kutlog's sin and cos
// (kutlog/simd/math.hpp): no pow.
//
// Contract, on every arch (kutlog/accuracy.hpp has the numbers, tests/test_lobe_sampler.cpp
// asserts them): with theta the angle of the returned direction from z,
//   |theta - inverse_cdf(u1)| <= kSamplerBound.theta_error * G, G the lobe's support
//     (KutlogLobe::integration_limit(): gran, or pi/2 for n < k);
//   |pdf - pdf_ref(direction)| <= kSamplerBound.pdf_error * peak, peak = the pdf at theta = 0,
//     pdf_ref the reference's solid-angle density of the returned direction;
//   the azimuth within kSamplerBound.phi_error (radians) of 2 pi u2;
//   0 <= pdf <= peak, |direction| = 1 within a few float roundings, z >= 0.
// Data rule: u1 and u2 are taken in [0, 1); a value below 0 counts as 0, one at or above 1 as
// the largest float below 1; NaN in either gives NaN in every output of that sample. Any
// count, any alignment; outputs must not overlap the inputs. Thread-safe (const).
//
// Domain: n finite > 0, k integer in [1, 64], Q in (0, 1) (std::invalid_argument naming the
// parameter otherwise), and the peak pdf must fit a float (n up to about 10^37, by k and Q;
// std::invalid_argument naming n beyond).
#pragma once

#include <algorithm>
#include <array>
#include <bit>
#include <cstddef>
#include <cstdint>
#include <type_traits>

#include "kutlog/api.hpp"
#include "kutlog/sampling_reference.hpp"

KUTLOG_API_BEGIN
namespace kutlog {

using ref::LobeUse;

// How u1 is cut into cells: lower_cells of width 1/(2 lower_cells) over [0, 1/2], then, for
// u1 > 1/2, by w = 1 - u1 (exact in float), 2^band_bits bands of each binade [2^e, 2^(e+1)) of
// w, e = -2 down to -24 (1 - u1 >= 2^-24 for a float u1 < 1). Each cell has its own variable
// x in [-1/2, 1/2]: u1 = (cell + 1/2 + x) / (2 lower_cells) in a lower cell, where theta is
// sqrt(u1) times the cell's polynomial in x; w = 2^e (1 + (band + 1/2 + x) / 2^band_bits) in
// an upper one, where theta is the polynomial.
struct SamplerCells {
  static constexpr int kUpperBinades = 23;
  int lower_cells, band_bits;
  constexpr int bands() const { return 1 << band_bits; }
  constexpr int count() const { return lower_cells + kUpperBinades * bands(); }
  // The cell of u1 > 1/2 whose w lies in band `band` of binade 2^exponent.
  constexpr int upper_cell(int exponent, int band) const {
    return lower_cells + (-2 - exponent) * bands() + band;
  }
  // The cell of argument = u1 <= 1/2 (lower) or of argument = w = 1 - u1 in [2^-24, 1/2), and
  // the argument's x in it, in double: for the setup and the one-sample path (the SIMD kernels
  // find the same from a float's bits). A template on the caller's arch, as kutlog/simd/'s
  // helpers are: each arch's copy, compiled with its flags, is a symbol of its own.
  struct Position {
    int cell;
    double x;
  };
  template <class Arch = void>
  Position position(bool lower, double argument) const {
    if (lower) {
      const double scaled = argument * (2 * lower_cells);
      const int cell = std::min(int(scaled), lower_cells - 1);
      return {cell, scaled - cell - 0.5};
    }
    constexpr std::uint64_t kMantissaBits = (std::uint64_t(1) << 52) - 1;
    const auto bits = std::bit_cast<std::uint64_t>(argument);
    // w = 2^exponent m, m in [1, 2); (m - 1) bands() = band + 1/2 + x.
    const int exponent = int(bits >> 52) - 1023;
    const double banded =
        (std::bit_cast<double>((bits & kMantissaBits) | std::bit_cast<std::uint64_t>(1.0)) - 1) *
        bands();
    const int band = std::min(int(banded), bands() - 1);
    return {upper_cell(exponent, band), banded - band - 0.5};
  }
};

// What a sampling kernel needs of one material, precomputed: plain data, for
// kutlog/simd/sampling.hpp. The inverse CDF is fitted twice, in two tables an arch chooses
// between by what a lookup costs it: `fine`, 400 cells of low degree (cubics), read with
// gathers; `coarse`, 31 cells of higher degree, which AVX-512 holds in two registers per
// coefficient and reads with one permute (vpermi2ps) instead of a gather.
struct SamplerKernel {
  static constexpr SamplerCells kFine{32, 4}, kCoarse{8, 0};
  static constexpr int kFineMaxDegree = 5, kCoarseMaxDegree = 12;
  static constexpr int kCoarseStride = 32;  // two registers of 16 floats per coefficient

  int fine_degree = 0, coarse_degree = 0;  // of every cell's polynomial
  int k = 1;
  bool cosine_weighted = true;  // microfacet: the pdf has the factor cos(theta)
  float c = 1;
  float limit = 0;          // G rounded down to a float
  float density_scale = 0;  // the pdf at theta = 0, the peak
  // Coefficient j of cell i at [j * stride + i] (stride kFine.count(), kCoarseStride):
  // coefficient-major, so that a batch looks coefficient j of its lanes' cells up in one row.
  std::array<float, kFine.count() * (kFineMaxDegree + 1)> fine{};
  std::array<float, kCoarseStride*(kCoarseMaxDegree + 1)> coarse{};
};

// Where the sampler writes: four arrays of count floats each.
struct DirectionSamples {
  float* x;
  float* y;
  float* z;
  float* pdf;  // over solid angle
};

// One direction and its pdf (over solid angle).
struct SampledDirection {
  float x, y, z, pdf;
};

class LobeSampler {
 public:
  // The parameters in Lobe's order, then the use. Throws std::invalid_argument naming the
  // parameter and its range (see Domain above).
  LobeSampler(double n, int k, double Q, LobeUse use);
  template <class N, class K, class Anchor>
    requires(!std::is_integral_v<K>)
  LobeSampler(N, K, Anchor, LobeUse) = delete;

  double n() const { return n_; }
  int k() const { return kernel_.k; }
  double Q() const { return Q_; }
  LobeUse use() const { return use_; }
  // The support G of the polar angle.
  double limit() const { return limit_; }
  // The largest |theta_fit - inverse_cdf| / G the setup saw at its check points, with either
  // fit evaluated in double: what the polynomials contribute to the contract's theta_error.
  double fit_error() const { return fit_error_; }
  const SamplerKernel& kernel() const { return kernel_; }

  // For i < count: a direction from (u1[i], u2[i]) and its pdf, into out.x[i] ... out.pdf[i].
  void sample(const float* u1, const float* u2, DirectionSamples out, std::size_t count) const;

  // One direction from (u1, u2) and its pdf: a path tracer's one sample per bounce. Scalar
  // code in double precision, each output rounded once to float, dispatched to the arch's
  // build for its fused multiply-add (out of line: the caller's flags do not reach it): the
  // contract and the data rule above, asserted per arch by the same tests. For many samples
  // at once the array call is faster (docs/benchmarks.md, the sampling table).
  SampledDirection sample(float u1, float u2) const;
  // Floats only, as the arrays' inputs are: a double u1 just below 1 would round to 1 without
  // a word. Convert explicitly, sample(float(u1), float(u2)).
  template <class U1, class U2>
    requires(!std::is_same_v<U1, float> || !std::is_same_v<U2, float>)
  SampledDirection sample(U1, U2) const = delete;

 private:
  double n_, Q_, limit_, fit_error_;
  LobeUse use_;
  SamplerKernel kernel_;
};

}  // namespace kutlog
KUTLOG_API_END

// kutlog/sampling.hpp: importance sampling of the normalized F_kutlog lobe for one material,
// in SIMD arrays or one sample per call; the reference is kutlog/sampling_reference.hpp.
// Contract (bounds in kSamplerBound, kutlog/accuracy.hpp), data rule and method:
// docs/api-notes.md. Domain as Lobe's, and the peak pdf must fit a float (n up to ~10^37).
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

// How u1 is cut into cells: halves of [0, 1/2], then bands of each binade of 1 - u1.
struct SamplerCells {
  static constexpr int kUpperBinades = 23;
  int lower_cells, band_bits;
  constexpr int bands() const { return 1 << band_bits; }
  constexpr int count() const { return lower_cells + kUpperBinades * bands(); }
  constexpr int upper_cell(int exponent, int band) const {
    return lower_cells + (-2 - exponent) * bands() + band;
  }
  // The cell of u1 <= 1/2 (lower) or of w = 1 - u1, and x in it (the setup, one sample).
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
    const int exponent = int(bits >> 52) - 1023;
    const double banded =
        (std::bit_cast<double>((bits & kMantissaBits) | std::bit_cast<std::uint64_t>(1.0)) - 1) *
        bands();
    const int band = std::min(int(banded), bands() - 1);
    return {upper_cell(exponent, band), banded - band - 0.5};
  }
};

// What the sampling kernels need of one material: the inverse CDF fitted for gathers (fine)
// and for AVX-512's two-register permutes (coarse).
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
  // Coefficient j of cell i at [j * stride + i]: one row per coefficient.
  std::array<float, kFine.count() * (kFineMaxDegree + 1)> fine{};
  std::array<float, kCoarseStride*(kCoarseMaxDegree + 1)> coarse{};
};

struct DirectionSamples {
  float* x;
  float* y;
  float* z;
  float* pdf;  // over solid angle
};

struct SampledDirection {
  float x, y, z, pdf;
};

class LobeSampler {
 public:
  // std::invalid_argument naming the parameter and its range; std::runtime_error if the CPU
  // runs no compiled arch.
  LobeSampler(double n, int k, double Q, LobeUse use);
  template <class N, class K, class Anchor>
    requires(!std::is_integral_v<K>)
  LobeSampler(N, K, Anchor, LobeUse) = delete;

  double n() const { return n_; }
  int k() const { return kernel_.k; }
  double Q() const { return Q_; }
  LobeUse use() const { return use_; }
  double limit() const { return limit_; }
  // The largest |theta_fit - inverse_cdf| / G seen at setup.
  double fit_error() const { return fit_error_; }
  const SamplerKernel& kernel() const { return kernel_; }

  void sample(const float* u1, const float* u2, DirectionSamples out,
              std::size_t count) const noexcept;

  // One sample, in double rounded once, with the arrays' contract.
  SampledDirection sample(float u1, float u2) const noexcept;
  // Floats only: a double u1 just below 1 would round to 1 without a word.
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

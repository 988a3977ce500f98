// kutlog/detail/sampler_kernel.hpp: what LobeSampler's kernels need of one material, filled
// by its setup (src/sampling.cpp) and read by kutlog/simd/sampling.hpp.
#pragma once

#include "kutlog/api.hpp"  // below C++20 its #error, and this header is empty
#if KUTLOG_HAS_CXX20

#include <algorithm>
#include <array>
#include <bit>
#include <cstdint>

KUTLOG_API_BEGIN
namespace kutlog::detail {

// How u1 is cut into cells: lower_cells cells of width 1 / (2 lower_cells) over [0, 1/2], then,
// for u1 > 1/2, by w = 1 - u1 (exact in float), 2^band_bits bands of each binade [2^e, 2^(e+1))
// of w, e = top_exponent (-2) down to -24 (w >= 2^-24 for a float u1 < 1). With no lower cells
// and top_exponent -1 (the one-sample table's layout), the bands of w's top binade are even
// cells of u1 in (0, 1/2], and every cell is found from the bits of w alone. Each cell has its
// own variable x in [-1/2, 1/2]: u1 = (cell + 1/2 + x) / (2 lower_cells) in a lower cell, where
// theta is sqrt(u1) times the cell's polynomial in x; w = 2^e (1 + (band + 1/2 + x) / 2^band_bits)
// in an upper one, where theta is the polynomial.
struct SamplerCells {
  static constexpr int kLowestExponent = -24;
  int lower_cells, band_bits, top_exponent = -2;
  constexpr int bands() const { return 1 << band_bits; }
  constexpr int binades() const { return top_exponent - kLowestExponent + 1; }
  constexpr int count() const { return lower_cells + binades() * bands(); }
  constexpr int upper_cell(int exponent, int band) const {
    return lower_cells + (top_exponent - exponent) * bands() + band;
  }
  // upper_cell from the top bits s = (biased exponent << band_bits) | band of a float w.
  constexpr int upper_cell_offset() const { return lower_cells + (127 + top_exponent) * bands(); }
  // The cell of argument = u1 <= 1/2 (lower) or of argument = w = 1 - u1 in
  // [2^-24, 2^(top_exponent + 1)), and the argument's x in it, in double: for the setup (the SIMD
  // kernels and the one-sample call find the same from a float's bits).
  struct Position {
    int cell;
    double x;
  };
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

// What a LobeSampler's kernels need of one material, plain data in two tables an arch chooses
// between by what a lookup costs it: `coarse`, the inverse CDF in 31 cells of high degree, which
// AVX-512 holds in two registers per coefficient and reads with one permute (vpermi2ps) instead
// of a gather; `rows`, per cell of kRowCells (384, all found from the bits of 1 - u1), the
// haversine sin^2(theta/2) and the pdf of the direction it gives as two cubics in 8 floats,
// which leave no sine of theta or power to evaluate: the one-sample call reads them, the other
// archs load them whole and transpose.
struct SamplerKernel {
  static constexpr SamplerCells kCoarse{8, 0}, kRowCells{0, 4, -1};
  static constexpr int kCoarseMaxDegree = 12;
  static constexpr int kCoarseStride = 32;  // two registers of 16 floats per coefficient
  // A cell's row: sin^2(theta/2) / (haversine_scale min(2 u1, 1)), then the pdf, cubics (zeros
  // above a lower degree); 8 floats, half a cache line, that SIMD loads whole and transposes.
  static constexpr int kRowDegree = 3, kRowStride = 2 * (kRowDegree + 1);

  int coarse_degree = 0;  // of every cell's polynomial
  int k = 1;
  bool cosine_weighted = true;  // microfacet: the pdf has the factor cos(theta)
  float c = 1;
  float limit = 0;          // G rounded down to a float
  float density_scale = 0;  // the pdf at theta = 0, the peak
  // The rows hold the haversine over haversine_scale, a power of 4 at or above sin^2(G / 2):
  // for the narrowest lobes sin^2(theta/2) is below the smallest normal float, its quotient
  // is not. sine_scale = 2 sqrt(haversine_scale), exact.
  float haversine_scale = 1, sine_scale = 2;
  float haversine_limit = 0;  // sin^2(G / 2) / haversine_scale, rounded down
  // Coefficient j of cell i at [j * kCoarseStride + i]: one row per coefficient.
  std::array<float, kCoarseStride*(kCoarseMaxDegree + 1)> coarse{};
  alignas(32) std::array<float, kRowCells.count() * kRowStride> rows{};
};

}  // namespace kutlog::detail
KUTLOG_API_END

#endif  // KUTLOG_HAS_CXX20

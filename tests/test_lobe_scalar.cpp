// The per-fragment path, Lobe::eval(float t) and PerLaneLobe::eval(float t, float n), against
// the same bounds and hard contract as the arrays. CMake builds this file twice: with the
// compiler's default flags (kutlog-test-lobe-scalar) and with FMA and -ffp-contract=fast
// (kutlog-test-lobe-scalar-fma), as a user might: the contract must hold under both.
// Estrin's scheme (kutlog/lobe.hpp) seen failing on planted bugs (2026-12-03): one squaring of
// x too few in the unrolled tree fails AccuracyGridEvery97thFloat and RandomLobesWithinBounds;
// x for x^(2^j) in the level-by-level loop (degree above 12) fails RandomLobesDensely.
#include <gtest/gtest.h>

#include <bit>
#include <cfloat>
#include <cstdint>
#include <cmath>
#include <limits>
#include <vector>

#include "kutlog/dispatch.hpp"
#include "kutlog/inspect.hpp"
#include "lobe_accuracy.hpp"

namespace kutlog {
namespace {

// Compiled here, with this binary's flags.
void evaluate_scalar_here(const Lobe& lobe, Variant variant, Normalization normalization,
                          const float* t, float* out, std::size_t count) {
  for (std::size_t i = 0; i < count; ++i) out[i] = lobe.eval(t[i], variant, normalization);
}
void evaluate_per_lane_scalar_here(const PerLaneLobe& lobe, Variant variant,
                                   Normalization normalization, const float* t, const float* n,
                                   float* out, std::size_t count) {
  for (std::size_t i = 0; i < count; ++i) out[i] = lobe.eval(t[i], n[i], variant, normalization);
}

TEST(LobeScalar, AccuracyGridEvery97thFloat) { expect_grid_within_bounds(97, evaluate_scalar_here); }

TEST(LobeScalar, RandomLobesWithinBoundsAndBetweenZeroAndPeak) {
  expect_random_lobes_within_bounds(12, 2026, 0x1p18, 0x1p21, evaluate_scalar_here);
}

TEST(LobeScalar, PerLaneMaterialsWithinBoundsAndBetweenZeroAndPeak) {
  // Not asserted to reach the bound: in double, the scalar path has only the fits' error,
  // about half the arrays' (whose float roundings the measured bound is; test_lobe.cpp).
  unsigned seed = 17;
  for (const PerLaneCase& c : per_lane_materials(40, 2026))
    for (Variant variant : tools::kLobeVariants)
      expect_per_lane_within_bounds(c, seed++, 8192, variant, evaluate_per_lane_scalar_here);
}

TEST(LobeScalar, PerLanePeaksAreCoefExactWithoutBias) {
  expect_per_lane_peaks_unbiased(evaluate_per_lane_scalar_here);
}

// The data rule, the same as the arrays': the peak at t >= 1, 0 at and below the cut and for
// t <= 0, NaN for NaN; the scalar and the array path agree on each of these exactly.
TEST(LobeScalar, DataRuleAsTheArrays) {
  constexpr float kNaN = std::numeric_limits<float>::quiet_NaN();
  for (const LobeCase& c : {LobeCase{100, 3, 0.5}, LobeCase{3, 5, 0.2}, LobeCase{3e7, 1, 0.5}}) {
    const Lobe lobe(c.n, c.k, c.Q);
    const float cut = lobe.cutoff_angle() >= ref::pi / 2 ? 0.0f : float(std::cos(lobe.cutoff_angle()));
    const std::vector<float> t = {1.0f, 1.0000001f, 2.0f, INFINITY, std::nextafter(cut, -1.0f),
                                  -0.0f, -0.5f, -1.0f, -1.0000001f, -2.0f, -FLT_MAX,
                                  -INFINITY, kNaN};
    for (Variant variant : tools::kLobeVariants)
      for (Normalization normalization : tools::kLobeNormalizations) {
        const float peak = normalization == Normalization::none ? 1.0f : float(lobe.coef_exact());
        for (int i = 0; i < 4; ++i) EXPECT_EQ(lobe.eval(t[i], variant, normalization), peak);
        for (std::size_t i = 4; i + 1 < t.size(); ++i)
          EXPECT_EQ(lobe.eval(t[i], variant, normalization), 0.0f) << "t = " << t[i];
        EXPECT_TRUE(std::isnan(lobe.eval(kNaN, variant, normalization)));
      }
  }
  const PerLaneLobe per_lane(10, 1000, 3, 0.5);
  EXPECT_EQ(per_lane.eval(1.5f, 100.0f), 1.0f);
  EXPECT_EQ(per_lane.eval(-0.2f, 100.0f), 0.0f);
  EXPECT_TRUE(std::isnan(per_lane.eval(kNaN, 100.0f)));
  EXPECT_TRUE(std::isnan(per_lane.eval(0.999f, kNaN)));
  EXPECT_TRUE(std::isnan(per_lane.eval(-1.0f, kNaN)));
  EXPECT_EQ(per_lane.eval(0.999f, 1e6f), per_lane.eval(0.999f, 1000.0f));  // clamped to n_max
}

// Variant::deterministic's one fragment, called from code built with this binary's flags (a
// caller's FMA and -ffp-contract=fast, or -ffast-math), gives the bits of every arch's arrays:
// it runs out of line, compiled with the library's flags. Every 257th float of [-0.1, 1.01],
// NaNs, zeros, subnormals and infinities.
TEST(LobeScalar, DeterministicIsTheArraysBitsWhateverTheCallersFlags) {
  std::vector<float> t;
  for (std::uint32_t bits = std::bit_cast<std::uint32_t>(1.01f); bits >= 257; bits -= 257)
    t.push_back(std::bit_cast<float>(bits));
  for (std::uint32_t bits = 0x80000000u; bits <= std::bit_cast<std::uint32_t>(-0.1f); bits += 257)
    t.push_back(std::bit_cast<float>(bits));
  for (std::uint32_t bits : {0x7fc00000u, 0xffc12345u, 0x7f800001u, 0x00000001u, 0x80000001u,
                             0x007fffffu, 0x00000000u, 0x80000000u, 0x7f800000u, 0xff800000u})
    t.push_back(std::bit_cast<float>(bits));
  std::vector<float> one(t.size()), arrays(t.size());
  for (const LobeCase& c : {LobeCase{1000, 3, 0.5}, LobeCase{0.7, 2, 0.3}, LobeCase{20, 40, 0.8}})
    for (Normalization normalization : tools::kLobeNormalizations) {
      const Lobe lobe(c.n, c.k, c.Q);
      for (std::size_t i = 0; i < t.size(); ++i)
        one[i] = lobe.eval(t[i], Variant::deterministic, normalization);
      for (Arch arch : supported_archs()) {
        const inspect::ScopedArch forced(arch);
        lobe.eval(t.data(), arrays.data(), t.size(), Variant::deterministic, normalization);
        for (std::size_t i = 0; i < t.size(); ++i)
          ASSERT_EQ(std::bit_cast<std::uint32_t>(one[i]), std::bit_cast<std::uint32_t>(arrays[i]))
              << arch_name(arch) << ", " << testing::PrintToString(c) << ", t bits 0x" << std::hex
              << std::bit_cast<std::uint32_t>(t[i]);
      }
    }
}

// t_cut(), the bound a caller's own branch tests: the largest float at or below the cosine of
// the cut-off (0 past pi/2), where every kernel, scalar or array, returns 0, as at the 16
// floats below it.
TEST(LobeScalar, TCutIsTheLastFloatEveryPathZeroes) {
  std::vector<LobeCase> lobes = accuracy_grid();
  for (const LobeCase& c : random_lobes(40, 99)) lobes.push_back(c);
  for (const LobeCase& c : lobes) {
    const Lobe lobe(c.n, c.k, c.Q);
    const double cut = lobe.cutoff_angle() >= ref::pi / 2 ? 0.0 : std::cos(lobe.cutoff_angle());
    float expected = float(cut);
    if (double(expected) > cut) expected = std::nextafter(expected, -1.0f);
    ASSERT_EQ(lobe.t_cut(), expected) << "n = " << c.n << ", k = " << c.k << ", Q = " << c.Q;
    std::vector<float> t{lobe.t_cut()};
    while (t.size() < 17) t.push_back(std::nextafter(t.back(), -1.0f));
    std::vector<float> out(t.size());
    for (Variant variant : tools::kLobeVariants)
      for (Normalization normalization : tools::kLobeNormalizations) {
        if (variant != Variant::deterministic)  // its SIMD kernel's cut may be raised
          EXPECT_EQ(
              inspect::kernel(lobe, variant, normalization, inspect::Arithmetic::scalar).t_cut,
              lobe.t_cut());
        lobe.eval(t.data(), out.data(), t.size(), variant, normalization);
        for (std::size_t i = 0; i < t.size(); ++i) {
          EXPECT_EQ(lobe.eval(t[i], variant, normalization), 0.0f) << "t = " << t[i];
          EXPECT_EQ(out[i], 0.0f) << "t = " << t[i];
        }
      }
  }
}

// The pieces, the scalar path's faster form, where materials usually are: every grid lobe with
// n >= 10 and k <= 5, each variant and normalization. Elsewhere the setup may fall back to the
// kernel of Arithmetic::scalar (a lobe cut at the horizon, whose floats just above t = 0 would
// reach the zero piece); the sweeps above cover both.
TEST(LobeScalar, PiecesOnTheUsualMaterials) {
  for (double n : {10.0, 100.0, 1000.0, 10000.0})
    for (int k = 1; k <= 5; ++k)
      for (double Q : {0.1, 0.5, 0.9}) {
        const Lobe lobe(n, k, Q);
        for (Normalization normalization : tools::kLobeNormalizations) {
          EXPECT_FALSE(inspect::precise_pieces(lobe, normalization).table.empty())
              << "n = " << n << ", k = " << k << ", Q = " << Q;
          EXPECT_FALSE(inspect::fast_pieces(lobe, normalization).table.empty())
              << "n = " << n << ", k = " << k << ", Q = " << Q;
        }
      }
  const Lobe horizon(1.5, 3, 0.5);
  EXPECT_EQ(horizon.t_cut(), 0.0f);
  EXPECT_TRUE(inspect::precise_pieces(horizon, Normalization::none).table.empty());
}

// Every float of each support on the grid (sampled below the cut), and random lobes densely
// (labelled `exhaustive`).
TEST(LobeScalarExhaustive, AccuracyGridEveryFloat) {
  expect_grid_within_bounds_everywhere(evaluate_scalar_here);
}
TEST(LobeScalarExhaustive, RandomLobesDensely) {
  expect_random_lobes_densely_within_bounds(evaluate_scalar_here);
}

}  // namespace
}  // namespace kutlog

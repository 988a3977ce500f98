// The stream API (kutlog/shade.hpp) per arch: Blinn and Phong cosines from SoA vectors against
// the scalar reference, masks, any count and offset, nothing written outside the output.
#include <gtest/gtest.h>

#include <algorithm>
#include <bit>
#include <cmath>
#include <random>
#include <tuple>
#include <vector>

#include "kutlog/accuracy.hpp"
#include "kutlog/dispatch.hpp"
#include "kutlog/inspect.hpp"
#include "kutlog/reference.hpp"
#include "cosine_error.hpp"
#include "kutlog/lobe.hpp"
#include "kutlog/shade.hpp"
#include "test_archs.hpp"

namespace kutlog {
namespace {

struct Scene {
  std::vector<float> nx, ny, nz, lx, ly, lz, vx, vy, vz;
  Vectors normal() const { return {nx.data(), ny.data(), nz.data()}; }
  Vectors light() const { return {lx.data(), ly.data(), lz.data()}; }
  Vectors viewer() const { return {vx.data(), vy.data(), vz.data()}; }
  ref::Vec3 at(const std::vector<float>& x, const std::vector<float>& y,
               const std::vector<float>& z, std::size_t i) const {
    return {x[i], y[i], z[i]};
  }
};

// Unit normals near +z, lights and viewers over the upper hemisphere, so that many highlights
// are hit and many missed.
Scene random_scene(std::size_t count, unsigned seed) {
  std::mt19937 engine(seed);
  std::normal_distribution<float> gaussian;
  Scene scene;
  const auto unit = [&](std::vector<float>& x, std::vector<float>& y, std::vector<float>& z,
                        float spread) {
    float a = spread * gaussian(engine), b = spread * gaussian(engine), c = std::fabs(gaussian(engine)) + 0.2f;
    const float length = std::sqrt(a * a + b * b + c * c);
    x.push_back(a / length), y.push_back(b / length), z.push_back(c / length);
  };
  for (std::size_t i = 0; i < count; ++i) {
    unit(scene.nx, scene.ny, scene.nz, 0.05f);
    unit(scene.lx, scene.ly, scene.lz, 0.6f);
    unit(scene.vx, scene.vy, scene.vz, 0.6f);
  }
  return scene;
}

class ShadePerArch : public testing::TestWithParam<Arch> {
 protected:
  inspect::ScopedArch forced{GetParam()};
};

// out = coef F(t) max(N.L, 0) with t and N.L the kernel's float cosines: each within its
// derived error (cosine_error.hpp) of the exact cosine of the same float vectors (computed in
// double). F is non-decreasing in t, so coef F over the window [t - dt, t + dt] lies between
// its ends; the lobe kernel adds its bound (kLobeBounds, relative to coef), and the product
// rounds once (half an ulp, or half the smallest subnormal).
struct Window {
  double lo, hi;
};
Window expected_window(const ref::KutlogLobe& reference, double coef, double t, double dt,
                       double n_dot_l) {
  const double bound = kLobeBounds[0].max_abs_error() * coef;  // precise
  const double f_lo = coef * reference.eval(t - dt) - bound;
  const double f_hi = coef * reference.eval(t + dt) + bound;
  const double l_lo = std::max(0.0, n_dot_l - test::kNDotLError);
  const double l_hi = std::max(0.0, n_dot_l + test::kNDotLError);
  double lo = std::min({f_lo * l_lo, f_lo * l_hi, f_hi * l_lo, f_hi * l_hi});
  double hi = std::max({f_lo * l_lo, f_lo * l_hi, f_hi * l_lo, f_hi * l_hi});
  lo -= std::fabs(lo) * test::kFloatUnitRoundoff + 0x1p-150;
  hi += std::fabs(hi) * test::kFloatUnitRoundoff + 0x1p-150;
  return {lo, hi};
}

TEST_P(ShadePerArch, BlinnAndPhongMatchTheReference) {
  for (const double n : {100.0, 1000.0}) {
    const Lobe lobe(n, 3, 0.5);
    const ref::KutlogLobe reference(n, 3, 0.5);
    const double coef = reference.coef_exact();
    const double t_cut = std::cos(reference.cutoff_angle());
    const Scene scene = random_scene(4099, 1);
    std::vector<float> out(4099);
    for (Reflection reflection : {Reflection::blinn, Reflection::phong}) {
      ShadeOptions options;
      options.reflection = reflection;
      options.normalization = Normalization::exact_coef;
      shade(lobe, scene.normal(), scene.light(), scene.viewer(), out.data(), out.size(), nullptr,
            options);
      const double dt = reflection == Reflection::blinn ? test::kBlinnCosineError
                                                        : test::kPhongCosineError;
      int lit = 0, dark = 0;
      for (std::size_t i = 0; i < out.size(); ++i) {
        const ref::Vec3 N = scene.at(scene.nx, scene.ny, scene.nz, i),
                        L = scene.at(scene.lx, scene.ly, scene.lz, i),
                        V = scene.at(scene.vx, scene.vy, scene.vz, i);
        const double t = reflection == Reflection::blinn ? ref::blinn_cosine(N, L, V)
                                                         : ref::phong_cosine(N, L, V);
        const double n_dot_l = N.x * L.x + N.y * L.y + N.z * L.z;
        const Window window = expected_window(reference, coef, t, dt, n_dot_l);
        EXPECT_GE(out[i], window.lo) << "n " << n << " lane " << i << " t " << t;
        EXPECT_LE(out[i], window.hi) << "n " << n << " lane " << i << " t " << t;
        // Away from the cut (the float cut-off, rounded, is within 2^-23 of cos(gran)) and
        // from N.L = 0, the reference is 0 and so must the output be, exactly.
        if (t + dt + 0x1p-23 < t_cut || n_dot_l + test::kNDotLError < 0) {
          EXPECT_EQ(out[i], 0.0f) << "n " << n << " lane " << i << " t " << t;
          ++dark;
        }
        lit += out[i] > 0;
      }
      // The scene hits and misses the highlight: both cases are exercised (lit: 30 lanes and
      // more of the 4099 at n = 1000, Phong, where the lobe is narrowest).
      EXPECT_GT(lit, 20) << "n " << n;
      EXPECT_GT(dark, 100) << "n " << n;
    }
  }
}

// The kernels' float cosines, computed here as kutlog/simd/shade.hpp computes them: each
// multiply-add fused (one rounding) on an arch with FMA, else a product and a sum (this file
// is compiled with -ffp-contract=off, so that the compiler fuses none of them).
struct FloatCosines {
  bool fused;
  float mul_add(float a, float b, float c) const { return fused ? std::fma(a, b, c) : a * b + c; }
  float dot(ref::Vec3 a, ref::Vec3 b) const {
    return mul_add(float(a.x), float(b.x), mul_add(float(a.y), float(b.y), float(a.z) * float(b.z)));
  }
  float blinn(ref::Vec3 n, ref::Vec3 l, ref::Vec3 v) const {
    const ref::Vec3 sum{float(l.x) + float(v.x), float(l.y) + float(v.y), float(l.z) + float(v.z)};
    const float length_squared = dot(sum, sum);
    return length_squared == 0 ? 0.0f : dot(n, sum) / std::sqrt(length_squared);
  }
  float phong(ref::Vec3 n, ref::Vec3 l, ref::Vec3 v) const {
    const float n_dot_l = dot(n, l), twice = n_dot_l + n_dot_l;
    return fused ? std::fma(twice, dot(n, v), -dot(l, v)) : twice * dot(n, v) - dot(l, v);
  }
};

// The vector forms give, bit for bit, the lobe's eval of their own float cosine times
// max(N.L, 0): what BlinnAndPhongMatchTheReference bounds only within the cosines' error,
// about 10^3 times the lobe's bound at the shoulder of a narrow lobe.
TEST_P(ShadePerArch, VectorsGiveEvalOfTheirFloatCosinesExactly) {
  const Scene scene = random_scene(4099, 4);
  constexpr std::size_t kCount = 4099;
  std::vector<float> out(kCount), t(kCount), n_dot_l(kCount), evaluated(kCount);
  for (const auto& [n, k, Q] : {std::tuple{1000.0, 3, 0.5}, std::tuple{100.0, 5, 0.3}}) {
    const Lobe lobe(n, k, Q);
    lobe.eval(t.data(), evaluated.data(), 1);  // the active arch's loops, from here on
    const FloatCosines cosines{detail::Inspector::active_loops().load()->fused_fma};
    for (Reflection reflection : {Reflection::blinn, Reflection::phong}) {
      ShadeOptions options;
      options.reflection = reflection;
      options.normalization = Normalization::exact_coef;
      shade(lobe, scene.normal(), scene.light(), scene.viewer(), out.data(), kCount, nullptr,
            options);
      int lit = 0;
      for (std::size_t i = 0; i < kCount; ++i) {
        const ref::Vec3 N = scene.at(scene.nx, scene.ny, scene.nz, i),
                        L = scene.at(scene.lx, scene.ly, scene.lz, i),
                        V = scene.at(scene.vx, scene.vy, scene.vz, i);
        t[i] = reflection == Reflection::blinn ? cosines.blinn(N, L, V) : cosines.phong(N, L, V);
        n_dot_l[i] = cosines.dot(N, L);
      }
      lobe.eval(t.data(), evaluated.data(), kCount, Variant::precise, Normalization::exact_coef);
      for (std::size_t i = 0; i < kCount; ++i) {
        const float expected = evaluated[i] * std::max(0.0f, n_dot_l[i]);
        lit += expected > 0;
        ASSERT_EQ(std::bit_cast<std::uint32_t>(out[i]), std::bit_cast<std::uint32_t>(expected))
            << "n " << n << ", lane " << i << ", t " << t[i] << ": " << out[i] << " against "
            << expected;
      }
      EXPECT_GT(lit, 20) << "n " << n;
    }
  }
}

TEST_P(ShadePerArch, MaskKeepsUnselectedLanesAndTailsStayInside) {
  const Lobe lobe(50, 2, 0.5);
  const Scene scene = random_scene(80, 2);
  std::vector<float> t(80), n_dot_l(80);
  for (std::size_t i = 0; i < 80; ++i) t[i] = 1.0f - 0.001f * float(i), n_dot_l[i] = 0.5f;
  for (std::size_t count = 0; count <= 70; ++count)
    for (std::size_t offset = 0; offset < 4; ++offset) {
      std::vector<std::uint8_t> mask(count + offset);
      for (std::size_t i = 0; i < mask.size(); ++i) mask[i] = (i * 7) % 3 != 0;
      std::vector<float> buffer(count + 40, -3.0f), unmasked(count + 40, -3.0f);
      float* out = buffer.data() + 16;
      shade(lobe, t.data() + offset, n_dot_l.data() + offset, out, count, mask.data() + offset);
      shade(lobe, t.data() + offset, n_dot_l.data() + offset, unmasked.data() + 16, count);
      for (std::size_t i = 0; i < buffer.size(); ++i) {
        const bool inside = i >= 16 && i < 16 + count;
        if (inside && mask[offset + i - 16]) ASSERT_EQ(buffer[i], unmasked[i]) << i;
        else ASSERT_EQ(buffer[i], -3.0f) << "count " << count << " index " << i;
      }
      // Vectors, with the same mask: unselected lanes untouched.
      std::vector<float> shaded(count + 40, -5.0f);
      const auto shift = [&](Vectors v) { return Vectors{v.x + offset, v.y + offset, v.z + offset}; };
      shade(lobe, shift(scene.normal()), shift(scene.light()), shift(scene.viewer()),
            shaded.data() + 16, count, mask.data() + offset);
      for (std::size_t i = 0; i < shaded.size(); ++i) {
        const bool selected = i >= 16 && i < 16 + count && mask[offset + i - 16];
        if (!selected) ASSERT_EQ(shaded[i], -5.0f) << "count " << count << " index " << i;
      }
    }
}

TEST_P(ShadePerArch, OppositeLightAndViewerAndNaN) {
  const Lobe lobe(20, 1, 0.5);
  const float nx[] = {0, 0, 0}, ny[] = {0, 0, 0}, nz[] = {1, 1, 1};
  const float lx[] = {0.6f, NAN, 0.6f}, ly[] = {0, 0, 0}, lz[] = {0.8f, 0.8f, 0.8f};
  const float vx[] = {-0.6f, 0, NAN}, vy[] = {0, 0, 0}, vz[] = {-0.8f, 1, 1};
  float out[3];
  for (Reflection reflection : {Reflection::blinn, Reflection::phong}) {
    ShadeOptions options;
    options.reflection = reflection;
    shade(lobe, {nx, ny, nz}, {lx, ly, lz}, {vx, vy, vz}, out, 3, nullptr, options);
    if (reflection == Reflection::blinn) EXPECT_EQ(out[0], 0.0f);  // L + V = 0: no half vector
    EXPECT_TRUE(std::isnan(out[1]));
    EXPECT_TRUE(std::isnan(out[2]));  // Blinn: a NaN length of L + V, not "L + V = 0"
    // The same through the single-vector form (which forms Blinn's H once, in double), and an
    // infinite component, which gives NaN too.
    const float inf = INFINITY;
    const Direction lights[] = {{lx[0], ly[0], lz[0]}, {lx[1], ly[1], lz[1]}, {lx[2], ly[2], lz[2]},
                                {inf, 0.0f, 0.8f}};
    const Direction viewers[] = {{vx[0], vy[0], vz[0]}, {vx[1], vy[1], vz[1]},
                                 {vx[2], vy[2], vz[2]}, {0.0f, 0.0f, 1.0f}};
    for (int i = 0; i < 4; ++i) {
      float single = -1.0f;
      shade(lobe, {nx, ny, nz}, lights[i], viewers[i], &single, 1, nullptr, options);
      if (i == 0) {
        if (reflection == Reflection::blinn) EXPECT_EQ(single, 0.0f);
      } else {
        EXPECT_TRUE(std::isnan(single)) << "case " << i << ": " << single;
      }
    }
  }
}

// One directional light and a fixed viewer as single vectors, with and without the N.L factor.
// Phong: the same values as the SoA overload given those vectors in every lane, bit for bit.
// Blinn, whose half vector this form computes once (in double): within the reference's window
// of its tighter cosine error (kBlinnHalfVectorCosineError). Without N.L, the cosine form gives
// exactly the lobe's eval.
TEST_P(ShadePerArch, DirectionsAndOptionalNDotLAgreeWithTheArrays) {
  const Lobe lobe(300, 3, 0.4);
  Scene scene = random_scene(157, 3);
  const Direction to_light{scene.lx[0], scene.ly[0], scene.lz[0]},
      to_viewer{scene.vx[0], scene.vy[0], scene.vz[0]};
  std::fill(scene.lx.begin(), scene.lx.end(), to_light.x);
  std::fill(scene.ly.begin(), scene.ly.end(), to_light.y);
  std::fill(scene.lz.begin(), scene.lz.end(), to_light.z);
  std::fill(scene.vx.begin(), scene.vx.end(), to_viewer.x);
  std::fill(scene.vy.begin(), scene.vy.end(), to_viewer.y);
  std::fill(scene.vz.begin(), scene.vz.end(), to_viewer.z);
  // Normals spread around the highlight, so that some lanes are lit.
  for (std::size_t i = 0; i < scene.nx.size(); ++i) {
    const float hx = to_light.x + to_viewer.x, hy = to_light.y + to_viewer.y,
                hz = to_light.z + to_viewer.z, length = std::sqrt(hx * hx + hy * hy + hz * hz);
    const float wobble = 0.002f * float(i % 13) - 0.012f;
    const float nx = hx / length + wobble, ny = hy / length - wobble, nz = hz / length;
    const float n_length = std::sqrt(nx * nx + ny * ny + nz * nz);
    scene.nx[i] = nx / n_length, scene.ny[i] = ny / n_length, scene.nz[i] = nz / n_length;
  }
  const ref::KutlogLobe reference(300, 3, 0.4);
  std::vector<float> arrays(157), directions(157);
  int lit = 0;
  for (Reflection reflection : {Reflection::blinn, Reflection::phong})
    for (bool times_n_dot_l : {true, false}) {
      ShadeOptions options;
      options.reflection = reflection;
      options.times_n_dot_l = times_n_dot_l;
      shade(lobe, scene.normal(), scene.light(), scene.viewer(), arrays.data(), 157, nullptr, options);
      shade(lobe, scene.normal(), to_light, to_viewer, directions.data(), 157, nullptr, options);
      for (std::size_t i = 0; i < 157; ++i) {
        lit += directions[i] > 0;
        if (reflection == Reflection::phong) {
          ASSERT_EQ(std::bit_cast<std::uint32_t>(arrays[i]),
                    std::bit_cast<std::uint32_t>(directions[i]))
              << "lane " << i;
          continue;
        }
        const ref::Vec3 N = scene.at(scene.nx, scene.ny, scene.nz, i),
                        L{to_light.x, to_light.y, to_light.z},
                        V{to_viewer.x, to_viewer.y, to_viewer.z};
        const double n_dot_l = times_n_dot_l ? N.x * L.x + N.y * L.y + N.z * L.z : 1.0;
        const Window window = expected_window(reference, 1.0, ref::blinn_cosine(N, L, V),
                                              test::kBlinnHalfVectorCosineError, n_dot_l);
        ASSERT_GE(directions[i], window.lo) << "lane " << i << ", N.L factor " << times_n_dot_l;
        ASSERT_LE(directions[i], window.hi) << "lane " << i << ", N.L factor " << times_n_dot_l;
      }
    }
  EXPECT_GT(lit, 200);
  std::vector<float> t(157), from_cosines(157), evaluated(157);
  for (std::size_t i = 0; i < 157; ++i) t[i] = 1.0f - 0.0005f * float(i);
  ShadeOptions bare;
  bare.times_n_dot_l = false;
  shade(lobe, t.data(), nullptr, from_cosines.data(), 157, nullptr, bare);
  lobe.eval(t.data(), evaluated.data(), 157);
  for (std::size_t i = 0; i < 157; ++i) ASSERT_EQ(from_cosines[i], evaluated[i]) << "t = " << t[i];
}

// Every shade form runs the lobe by the loop Lobe::eval runs for its kernel (a loop per degree,
// finish and clamp), a chunk of 256 lanes at a time. Over lobes whose kernels take different
// loops, both variants and normalizations, and counts across chunk ends, under a mask, the
// cosine form gives eval's output times max(N.L, 0), bit for bit, where the mask selects, and
// leaves the other lanes as they were; and that output is within the lobe's bound of the scalar
// reference's scale F(t) max(N.L, 0), the product rounded once (eval and shade both run the
// table's loop: another loop in its slot would pass the first check). (The vector forms'
// chunks: BlinnAndPhongMatchTheReference, 4099 lanes.)
TEST_P(ShadePerArch, CosinesGiveEvalTimesNDotLAcrossChunksAndKernels) {
  std::mt19937 engine(7);
  std::uniform_real_distribution<float> cosine(-0.2f, 1.05f), n_l(-0.5f, 1.0f);
  std::uniform_real_distribution<double> unit(0, 1);
  constexpr std::size_t kMost = 1100;
  std::vector<float> t(kMost), n_dot_l(kMost), evaluated(kMost), out(kMost);
  std::vector<double> in_support(kMost);
  std::vector<std::uint8_t> mask(kMost);
  // The mask in runs of 16 lanes selected, unselected and mixed: whole batches of each kind on
  // every arch.
  for (std::size_t i = 0; i < kMost; ++i) {
    t[i] = cosine(engine), n_dot_l[i] = n_l(engine), in_support[i] = unit(engine);
    mask[i] = i / 16 % 3 == 0 || (i / 16 % 3 == 2 && (i * 5) % 7 < 4);
  }
  t[3] = NAN, n_dot_l[6] = NAN, t[680] = 1.5f;  // all three selected
  // Their kernels (on AVX2 and SSE4.1) run unrolled without the clamp, plain and split (n =
  // 1000), compensated (2, 2, 0.1 normalized), in double lanes (2, 6, 0.1 normalized) and as
  // the clamped constant of a support with no float below 1 (n = 10^8).
  for (const auto& [n, k, Q] : {std::tuple{1000.0, 3, 0.5}, std::tuple{1000.0, 5, 0.5},
                                std::tuple{2.0, 2, 0.1}, std::tuple{2.0, 6, 0.1},
                                std::tuple{1e8, 1, 0.1}, std::tuple{2e5, 12, 0.7}})
    for (Variant variant : {Variant::precise, Variant::fast})
      for (Normalization normalization : {Normalization::none, Normalization::exact_coef}) {
        const Lobe lobe(n, k, Q);
        const ref::KutlogLobe reference(n, k, Q);
        const double scale =
            normalization == Normalization::none ? 1.0 : reference.coef_exact();
        const double bound =
            kLobeBounds[variant == Variant::fast ? 1 : 0].max_abs_error() * scale;
        // The odd lanes over the lobe's support, which few of [-0.2, 1.05] reach when narrow.
        const double cut = std::cos(std::min(reference.cutoff_angle(), ref::pi / 2));
        for (std::size_t i = 1; i < kMost; i += 2) t[i] = float(cut + (1 - cut) * in_support[i]);
        t[3] = NAN;
        ShadeOptions options;
        options.variant = variant;
        options.normalization = normalization;
        lobe.eval(t.data(), evaluated.data(), kMost, variant, normalization);
        for (std::size_t count : {std::size_t(255), std::size_t(256), std::size_t(257), kMost}) {
          std::fill(out.begin(), out.end(), -7.0f);
          shade(lobe, t.data(), n_dot_l.data(), out.data(), count, mask.data(), options);
          for (std::size_t i = 0; i < kMost; ++i) {
            const float expected =
                !(i < count && mask[i]) ? -7.0f
                : std::isnan(n_dot_l[i]) ? NAN
                                         : evaluated[i] * std::max(0.0f, n_dot_l[i]);
            if (std::isnan(expected)) {
              ASSERT_TRUE(std::isnan(out[i])) << "lane " << i;
              continue;
            }
            ASSERT_EQ(std::bit_cast<std::uint32_t>(out[i]), std::bit_cast<std::uint32_t>(expected))
                << "n " << n << " k " << k << " count " << count << " lane " << i;
            if (count != kMost || !mask[i]) continue;
            const double f = scale * reference.eval(t[i]), lit = std::max(0.0f, n_dot_l[i]);
            ASSERT_LE(std::fabs(out[i] - f * lit),
                      (bound + test::kFloatUnitRoundoff * (f + bound)) * lit + 0x1p-150)
                << "n " << n << " k " << k << " Q " << Q << " variant " << int(variant)
                << " normalization " << int(normalization) << " lane " << i << " t " << t[i];
          }
        }
      }
}

INSTANTIATE_TEST_SUITE_P(Arch, ShadePerArch, testing::ValuesIn(supported_archs()), arch_test_name);

}  // namespace
}  // namespace kutlog

// The stream API (kutlog/shade.hpp) per arch: Blinn and Phong cosines from SoA vectors against
// the scalar reference, masks, any count and offset, nothing written outside the output.
#include <gtest/gtest.h>

#include <cmath>
#include <random>
#include <vector>

#include "kutlog/accuracy.hpp"
#include "kutlog/dispatch.hpp"
#include "kutlog/reference.hpp"
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
  ScopedArch forced{GetParam()};
};

TEST_P(ShadePerArch, BlinnAndPhongMatchTheReference) {
  const Lobe lobe(100, 3, 0.5);
  const ref::KutlogLobe reference(100, 3, 0.5);
  const Scene scene = random_scene(4099, 1);
  std::vector<float> out(4099);
  for (Reflection reflection : {Reflection::blinn, Reflection::phong}) {
    ShadeOptions options;
    options.reflection = reflection;
    shade(lobe, scene.normal(), scene.light(), scene.viewer(), out.data(), out.size(), nullptr,
          options);
    int lit = 0;
    for (std::size_t i = 0; i < out.size(); ++i) {
      const ref::Vec3 n = scene.at(scene.nx, scene.ny, scene.nz, i),
                      l = scene.at(scene.lx, scene.ly, scene.lz, i),
                      v = scene.at(scene.vx, scene.vy, scene.vz, i);
      const double t = reflection == Reflection::blinn ? ref::blinn_cosine(n, l, v)
                                                       : ref::phong_cosine(n, l, v);
      const double n_dot_l = std::max(0.0, n.x * l.x + n.y * l.y + n.z * l.z);
      const double expected = reference.coef_exact() * reference.eval(t) * n_dot_l;
      // The float cosine is within a few ulps of the double one; near t = 1 the lobe's slope
      // turns that into at most ~1e-4 of the peak.
      EXPECT_NEAR(out[i], expected, 2e-4 * reference.coef_exact()) << "lane " << i;
      lit += expected > 0;
    }
    EXPECT_GT(lit, 100);
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
  }
}

INSTANTIATE_TEST_SUITE_P(Arch, ShadePerArch, testing::ValuesIn(supported_archs()), arch_test_name);

}  // namespace
}  // namespace kutlog

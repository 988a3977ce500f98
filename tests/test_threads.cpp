// Thread safety as the headers promise it. A scene loader builds its materials on many threads
// at once (Lobe, PerLaneLobe, LobeSampler: their setups share caches), and shaders use one
// const material from many threads. Every result must equal the one computed on one thread.
// ctest runs these natively (quick), and scripts/test.sh again under ThreadSanitizer
// (build-tsan), where a data race fails the run even when the results happen to agree.
//
// Its first run under ThreadSanitizer (2026-12-03) found a data race: the dispatch published
// its table pointer with relaxed ordering (src/dispatch.cpp), so a thread could read the table
// through it without seeing it filled; now release and acquire. Seen to fail again on a planted
// bug: the Chebyshev fits' cosine cache (src/polynomial_fit.cpp) made static instead of
// thread_local, where natively the results still agreed.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <latch>
#include <random>
#include <thread>
#include <vector>

#include "kutlog/lobe.hpp"
#include "kutlog/sampling.hpp"
#include "kutlog/shade.hpp"

namespace kutlog {
namespace {

constexpr int kThreads = 4;

struct Material {
  double n;
  int k;
  double Q;
};

// Random materials over the whole domain (as the setup benchmark draws them), narrow and wide.
std::vector<Material> random_materials(int count) {
  std::mt19937 engine(2026);
  std::uniform_real_distribution<double> unit(0, 1);
  std::vector<Material> materials;
  for (int i = 0; i < count; ++i) {
    const double n = std::exp(std::log(0.5) + unit(engine) * std::log(2e6));
    materials.push_back({n, 1 + int(unit(engine) * 64) % 64, 0.01 + 0.98 * unit(engine)});
  }
  return materials;
}

// Cosines over [-0.2, 1.1]: past the cut-off, the support and above 1.
std::vector<float> cosines() {
  std::vector<float> t(1000);
  for (std::size_t i = 0; i < t.size(); ++i) t[i] = -0.2f + 1.3f * float(i) / float(t.size());
  return t;
}

// Everything one material computes, from fixed inputs: the lobe's every variant and
// normalization, array and scalar, the per-lane lobe, and the sampler's directions.
std::vector<float> outputs_of(const Material& material) {
  const std::vector<float> t = cosines();
  std::vector<float> result, out(t.size());
  const Lobe lobe(material.n, material.k, material.Q);
  for (Variant variant : {Variant::precise, Variant::fast}) {
    lobe.eval(t.data(), out.data(), t.size(), variant);
    result.insert(result.end(), out.begin(), out.end());
    for (float cosine : t) result.push_back(lobe.eval(cosine, variant));
  }
  const double n_min = std::max(material.n, double(material.k));
  const PerLaneLobe per_lane(n_min, 4 * n_min, material.k, material.Q);
  const std::vector<float> n(t.size(), float(2 * n_min));
  per_lane.eval(t.data(), n.data(), out.data(), t.size());
  result.insert(result.end(), out.begin(), out.end());
  const LobeSampler sampler(material.n, material.k, material.Q, LobeUse::microfacet);
  std::vector<float> u1(t.size()), u2(t.size()), x(t.size()), y(t.size()), z(t.size()),
      pdf(t.size());
  for (std::size_t i = 0; i < t.size(); ++i)
    u1[i] = float(i) / float(t.size()), u2[i] = float((i * 7) % t.size()) / float(t.size());
  sampler.sample(u1.data(), u2.data(), {x.data(), y.data(), z.data(), pdf.data()}, t.size());
  for (const std::vector<float>* samples : {&x, &y, &z, &pdf})
    result.insert(result.end(), samples->begin(), samples->end());
  return result;
}

// Bitwise equality of two output vectors (no NaN among them: every input is in range).
void expect_same_bits(const std::vector<float>& expected, const std::vector<float>& actual,
                      const std::string& what) {
  ASSERT_EQ(expected.size(), actual.size()) << what;
  for (std::size_t i = 0; i < expected.size(); ++i)
    ASSERT_EQ(expected[i], actual[i]) << what << ", output " << i;
}

// Materials built on several threads at once, each thread in its own order, give what they
// give when built alone. The concurrent builds come first, so that the setup's caches are
// filled by threads racing to it (this test is the first of its process under
// ThreadSanitizer).
TEST(Threads, MaterialsBuiltConcurrentlyEqualThoseBuiltAlone) {
  const std::vector<Material> materials = random_materials(12);
  std::vector<std::vector<std::vector<float>>> concurrent(
      kThreads, std::vector<std::vector<float>>(materials.size()));
  std::latch start(kThreads);
  std::vector<std::thread> threads;
  for (int thread = 0; thread < kThreads; ++thread)
    threads.emplace_back([&, thread] {
      start.arrive_and_wait();
      for (std::size_t j = 0; j < materials.size(); ++j) {
        const std::size_t m = (j + std::size_t(thread) * 5) % materials.size();
        concurrent[std::size_t(thread)][m] = outputs_of(materials[m]);
      }
    });
  for (std::thread& thread : threads) thread.join();
  std::vector<std::vector<float>> alone;
  for (const Material& material : materials) alone.push_back(outputs_of(material));
  for (std::size_t thread = 0; thread < kThreads; ++thread)
    for (std::size_t m = 0; m < materials.size(); ++m)
      expect_same_bits(alone[m], concurrent[thread][m],
                       "thread " + std::to_string(thread) + ", material " + std::to_string(m));
}

// One const material used by several threads at once: the array and scalar lobe, the stream
// API and the sampler give every thread the single-threaded answer.
TEST(Threads, SharedMaterialGivesEveryThreadTheSameAnswer) {
  const Lobe lobe(1000, 3, 0.5);
  const LobeSampler sampler(1000, 3, 0.5, LobeUse::phong);
  const std::vector<float> t = cosines();
  const std::size_t count = t.size();
  std::vector<float> nx(count), ny(count), nz(count), u(count);
  for (std::size_t i = 0; i < count; ++i) {
    const float angle = 0.3f * float(i) / float(count);
    nx[i] = std::sin(angle), ny[i] = 0, nz[i] = std::cos(angle);
    u[i] = float(i) / float(count);
  }
  const Direction light{0.0f, 0.6f, 0.8f}, viewer{0.0f, -0.6f, 0.8f};
  ShadeOptions normalized;
  normalized.normalization = Normalization::exact_coef;
  const auto compute = [&] {
    std::vector<float> result(7 * count);
    float* const out = result.data();
    lobe.eval(t.data(), out, count, Variant::precise, Normalization::exact_coef);
    for (std::size_t i = 0; i < count; ++i) out[count + i] = lobe.eval(t[i], Variant::fast);
    shade(lobe, {nx.data(), ny.data(), nz.data()}, light, viewer, out + 2 * count, count,
          nullptr, normalized);
    sampler.sample(u.data(), t.data(),
                   {out + 3 * count, out + 4 * count, out + 5 * count, out + 6 * count}, count);
    return result;
  };
  const std::vector<float> alone = compute();
  std::vector<std::vector<float>> concurrent(kThreads);
  std::latch start(kThreads);
  std::vector<std::thread> threads;
  for (int thread = 0; thread < kThreads; ++thread)
    threads.emplace_back([&, thread] {
      start.arrive_and_wait();
      for (int repeat = 0; repeat < 20; ++repeat) concurrent[std::size_t(thread)] = compute();
    });
  for (std::thread& thread : threads) thread.join();
  for (std::size_t thread = 0; thread < kThreads; ++thread)
    expect_same_bits(alone, concurrent[thread], "thread " + std::to_string(thread));
}

}  // namespace
}  // namespace kutlog

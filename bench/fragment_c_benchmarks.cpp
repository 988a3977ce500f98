// fragment/scalar_kutlog_c[_fast]: the per-fragment rows of kutlog_eval, its loop compiled as C
// (bench/fragment_c.c) on a lobe of the C API, at the inputs of the C++ rows; and
// fragment/material_*: where a renderer keeps the lobe of each material.
#include <cmath>
#include <memory>
#include <random>

#include "fragment_benchmarks.hpp"
#include "fragment_c.h"
#include "kutlog/kutlog.h"

namespace kutlog::bench {

void register_c_fragment_benchmarks(double n, int k, const std::string& at,
                                    const std::vector<float>& cosines) {
  kutlog_lobe* created = nullptr;
  if (kutlog_lobe_create(n, k, kLobeAnchor, &created, nullptr) != KUTLOG_OK) return;
  const std::shared_ptr<kutlog_lobe> lobe(created, kutlog_lobe_destroy);
  kutlog_fragment precise;
  kutlog_fast_fragment fast;
  kutlog_lobe_fragment(lobe.get(), KUTLOG_UNNORMALIZED, &precise, nullptr);
  kutlog_lobe_fast_fragment(lobe.get(), KUTLOG_UNNORMALIZED, &fast, nullptr);
  benchmark::RegisterBenchmark(("fragment/scalar_kutlog_c" + at).c_str(),
                               // lobe too: the fragment points into it
                               [lobe, precise, cosines](benchmark::State& state) {
    time_loop(state, [&](const float* t, float* out, std::size_t count) {
      kutlog_bench_c_eval(&precise, t, out, count);
    }, cosines);
  });
  benchmark::RegisterBenchmark(("fragment/scalar_kutlog_c_fast" + at).c_str(),
                               [lobe, fast, cosines](benchmark::State& state) {
    time_loop(state, [&](const float* t, float* out, std::size_t count) {
      kutlog_bench_c_eval_fast(&fast, t, out, count);
    }, cosines);
  });
}

namespace {

// A renderer's material as it might hold its specular lobe: the Lobe itself (4.6 KB), a pointer
// to it, the C API's 32-byte fragment handle, or powf's exponent.
struct MaterialWithLobe {
  float albedo[3];
  Lobe lobe;
};
struct MaterialWithPointer {
  float albedo[3];
  const Lobe* lobe;
};
struct MaterialWithFragment {
  float albedo[3];
  kutlog_fragment lobe;
};
struct MaterialWithExponent {
  float albedo[3];
  float n;
};

// Each material's n, log-uniform over [50, 2000].
double material_exponent(int material, int materials) {
  return 50 * std::pow(40.0, double(material) / double(materials - 1));
}

// out[i] = albedo N.L + F(N.H) of fragment i's material, materials in random order.
template <class Material, class Specular>
void register_material_row(const std::string& name, std::vector<Material> materials,
                           Specular specular) {
  std::mt19937 random(7);
  std::uniform_int_distribution<int> pick(0, int(materials.size()) - 1);
  std::uniform_real_distribution<float> cosine(0.95f, 1.0f);
  std::vector<int> material(kArrayLength);
  std::vector<float> t(kArrayLength);
  for (std::size_t i = 0; i < kArrayLength; ++i) material[i] = pick(random), t[i] = cosine(random);
  benchmark::RegisterBenchmark(name.c_str(), [=](benchmark::State& state) {
    time_loop(state, [&](const float* x, float* out, std::size_t count) {
      for (std::size_t i = 0; i < count; ++i) {
        const Material& m = materials[std::size_t(material[i])];
        out[i] = m.albedo[0] * 0.5f + specular(m, x[i]);
      }
    }, t);
  });
}

}  // namespace

void register_material_benchmarks() {
  for (const int count : {16, 256}) {
    const std::string at = "/materials:" + std::to_string(count);
    std::vector<Lobe> lobes;
    std::vector<std::shared_ptr<kutlog_lobe>> handles;
    std::vector<MaterialWithLobe> by_value;
    std::vector<MaterialWithFragment> with_fragment(static_cast<std::size_t>(count));
    std::vector<MaterialWithExponent> with_exponent;
    lobes.reserve(std::size_t(count));
    for (int m = 0; m < count; ++m) {
      const double n = material_exponent(m, count);
      lobes.emplace_back(n, 3, kLobeAnchor);
      by_value.push_back({{0.5f, 0.4f, 0.3f}, lobes.back()});
      with_exponent.push_back({{0.5f, 0.4f, 0.3f}, float(n)});
      kutlog_lobe* created = nullptr;
      kutlog_lobe_create(n, 3, kLobeAnchor, &created, nullptr);
      handles.emplace_back(created, kutlog_lobe_destroy);
      with_fragment[std::size_t(m)].albedo[0] = 0.5f;
      kutlog_lobe_fragment(created, KUTLOG_UNNORMALIZED, &with_fragment[std::size_t(m)].lobe,
                           nullptr);
    }
    const auto kept_lobes = std::make_shared<const std::vector<Lobe>>(std::move(lobes));
    std::vector<MaterialWithPointer> by_pointer;
    for (const Lobe& lobe : *kept_lobes) by_pointer.push_back({{0.5f, 0.4f, 0.3f}, &lobe});
    register_material_row("fragment/material_lobe" + at, by_value,
                          [](const MaterialWithLobe& m, float t) { return m.lobe.eval(t); });
    register_material_row("fragment/material_lobe_pointer" + at, by_pointer,
                          [kept_lobes](const MaterialWithPointer& m, float t) {
                            return m.lobe->eval(t);
                          });
    register_material_row("fragment/material_fragment_handle" + at, with_fragment,
                          [handles](const MaterialWithFragment& m, float t) {
                            return kutlog_eval(&m.lobe, t);
                          });
    register_material_row("fragment/material_powf" + at, with_exponent,
                          [](const MaterialWithExponent& m, float t) {
                            return powf(std::max(t, 0.0f), m.n);
                          });
  }
}

}  // namespace kutlog::bench

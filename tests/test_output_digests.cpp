// Every public kernel's outputs on a fixed set of inputs, hashed per arch and compared with the
// digests in tests/data/output-digests-<platform>-<compiler>.txt: a refactor that moves code
// must leave every bit where it was. After a change meant to alter outputs, record them anew:
//   KUTLOG_RECORD_DIGESTS=1 build/tests/kutlog-test-output-digests
// (and build-portable's binary for the portable arch); the test then rewrites its entries.
#include <gtest/gtest.h>

#include <bit>
#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <fstream>
#include <functional>
#include <limits>
#include <map>
#include <sstream>
#include <string>
#include <tuple>
#include <vector>

#include "kutlog/baselines.hpp"
#include "kutlog/detail/math_functions.hpp"
#include "kutlog/dispatch.hpp"
#include "kutlog/lobe.hpp"
#include "kutlog/math.hpp"
#include "kutlog/sampling.hpp"
#include "kutlog/shade.hpp"
#include "recorded_data.hpp"

namespace kutlog {
namespace {

// Per compiler: clang-14 and GCC 12 round a few kernels differently (6 of 337 outputs on
// x86-64), so each has its own record; one without a record skips.
std::string digest_file() { return recorded_data_file("output-digests", true); }

// FNV-1a over the bits of each float, NaN payloads included.
std::uint64_t digest(const std::vector<float>& values) {
  std::uint64_t hash = 0xcbf29ce484222325u;
  for (float value : values) {
    std::uint32_t bits = std::bit_cast<std::uint32_t>(value);
    for (int byte = 0; byte < 4; ++byte, bits >>= 8) {
      hash ^= bits & 0xffu;
      hash *= 0x100000001b3u;
    }
  }
  return hash;
}

// A fixed stream of floats in [lo, hi], from a 64-bit LCG (the same on every platform).
std::vector<float> spread(float lo, float hi, std::size_t count, std::uint64_t seed) {
  std::vector<float> values(count);
  for (std::size_t i = 0; i < count; ++i) {
    seed = seed * 6364136223846793005u + 1442695040888963407u;
    const double unit = double(seed >> 11) * 0x1p-53;
    values[i] = float(lo + (double(hi) - lo) * unit);
  }
  return values;
}

// The data rule's inputs: both zeros, subnormals, 1 and past it, infinities, NaN payloads.
std::vector<float> specials() {
  constexpr float inf = std::numeric_limits<float>::infinity();
  return {0.0f,   -0.0f, 0x1p-149f, -0x1p-149f, 0x1p-126f, 1.0f, 0x1.000002p0f, 2.0f,  -1.0f,
          inf,    -inf,  std::bit_cast<float>(0x7fc00000u), std::bit_cast<float>(0xfff278d6u),
          0.5f,   0.999f};
}

// t over [0, 1] denser near the peak, then the specials: 4096 + 15 values, an odd count that
// leaves every arch a partial batch.
std::vector<float> cosines(std::uint64_t seed) {
  std::vector<float> t = spread(0.0f, 1.0f, 2048, seed);
  const std::vector<float> near_peak = spread(0.95f, 1.0f, 2048, seed + 1);
  t.insert(t.end(), near_peak.begin(), near_peak.end());
  const std::vector<float> rule = specials();
  t.insert(t.end(), rule.begin(), rule.end());
  return t;
}

using Outputs = std::map<std::string, std::uint64_t>;

struct LobeParameters {
  double n;
  int k;
  double Q;
};
constexpr LobeParameters kLobes[] = {{1, 1, 0.5},     {10, 3, 0.5},  {32, 3, 0.5},
                                     {100, 2, 0.9},   {1000, 1, 0.5}, {1000, 3, 0.5},
                                     {1000, 5, 0.3},  {3000, 1, 0.5}, {50, 5, 0.5},
                                     {1e5, 4, 0.7},   {2, 16, 0.5},  {200, 64, 0.1}};
constexpr Variant kVariants[] = {Variant::precise, Variant::fast};
constexpr Normalization kNormalizations[] = {Normalization::none, Normalization::exact_coef};

std::string lobe_name(const LobeParameters& lobe, Variant variant, Normalization normalization) {
  std::ostringstream name;
  name << "n" << lobe.n << "_k" << lobe.k << "_Q" << lobe.Q
       << (variant == Variant::fast ? "_fast" : "_precise")
       << (normalization == Normalization::exact_coef ? "_coef" : "");
  return name.str();
}

// Unit vectors, fixed.
struct UnitVectors {
  std::vector<float> x, y, z;
  Vectors view() const { return {x.data(), y.data(), z.data()}; }
};
UnitVectors unit_vectors(std::size_t count, std::uint64_t seed, float min_z) {
  UnitVectors v{spread(-1, 1, count, seed), spread(-1, 1, count, seed + 1),
                spread(min_z, 1, count, seed + 2)};
  for (std::size_t i = 0; i < count; ++i) {
    const double length = std::sqrt(double(v.x[i]) * v.x[i] + double(v.y[i]) * v.y[i] +
                                     double(v.z[i]) * v.z[i]);
    v.x[i] = float(v.x[i] / length);
    v.y[i] = float(v.y[i] / length);
    v.z[i] = float(v.z[i] / length);
  }
  return v;
}

void record_math(Outputs& outputs) {
  const std::size_t count = 4099;
  std::vector<float> out(count);
  auto inputs = [&](float lo, float hi, std::uint64_t seed) {
    std::vector<float> x = spread(lo, hi, count - specials().size(), seed);
    const std::vector<float> rule = specials();
    x.insert(x.end(), rule.begin(), rule.end());
    return x;
  };
#define KUTLOG_DIGEST_UNARY(function, kernel, promised, x86, arm, domain, lo, hi, ...) \
  {                                                                                  \
    const std::vector<float> x = inputs(lo, hi, 1);                                  \
    math::kernel(x.data(), out.data(), x.size());                                    \
    outputs["math/" #kernel] = digest(out);                                          \
  }
#define KUTLOG_DIGEST_BINARY(function, kernel, promised, x86, arm, domain, lo, hi, ...) \
  {                                                                                   \
    const std::vector<float> x = inputs(0, 1, 2), y = inputs(0, 4000, 3);             \
    math::kernel(x.data(), y.data(), out.data(), x.size());                           \
    outputs["math/" #kernel] = digest(out);                                           \
    math::kernel(x.data(), 1000.0f, out.data(), x.size());                            \
    outputs["math/" #kernel "_scalar_y"] = digest(out);                               \
  }
  KUTLOG_UNARY_MATH_FUNCTIONS(KUTLOG_DIGEST_UNARY)
  KUTLOG_BINARY_MATH_FUNCTIONS(KUTLOG_DIGEST_BINARY)
#undef KUTLOG_DIGEST_UNARY
#undef KUTLOG_DIGEST_BINARY
}

void record_lobes(Outputs& outputs, bool scalar) {
  const std::vector<float> t = cosines(7);
  std::vector<float> out(t.size());
  for (const LobeParameters& parameters : kLobes) {
    const Lobe lobe(parameters.n, parameters.k, parameters.Q);
    for (Variant variant : kVariants)
      for (Normalization normalization : kNormalizations) {
        if (scalar)
          for (std::size_t i = 0; i < t.size(); ++i)
            out[i] = lobe.eval(t[i], variant, normalization);
        else
          lobe.eval(t.data(), out.data(), t.size(), variant, normalization);
        outputs["lobe/" + lobe_name(parameters, variant, normalization)] = digest(out);
      }
  }
  const PerLaneLobe per_lane(10, 2000, 3, 0.5);
  std::vector<float> n = spread(1, 3000, t.size(), 11);
  n.back() = std::numeric_limits<float>::quiet_NaN();
  for (Variant variant : kVariants)
    for (Normalization normalization : kNormalizations) {
      if (scalar)
        for (std::size_t i = 0; i < t.size(); ++i)
          out[i] = per_lane.eval(t[i], n[i], variant, normalization);
      else
        per_lane.eval(t.data(), n.data(), out.data(), t.size(), variant, normalization);
      outputs["per_lane/" + lobe_name({10, 3, 0.5}, variant, normalization)] = digest(out);
    }
}

void record_shade(Outputs& outputs) {
  const std::size_t count = 1027;
  const UnitVectors normal = unit_vectors(count, 21, -0.2f), light = unit_vectors(count, 31, 0),
                    viewer = unit_vectors(count, 41, 0);
  const std::vector<float> t = cosines(51), n_dot_l = spread(-0.2f, 1, t.size(), 61);
  std::vector<std::uint8_t> mask(count);
  for (std::size_t i = 0; i < count; ++i) mask[i] = std::uint8_t(i % 3 != 0);
  const Lobe lobe(300, 3, 0.5);
  for (Reflection reflection : {Reflection::blinn, Reflection::phong})
    for (bool times_n_dot_l : {true, false})
      for (bool masked : {false, true}) {
        const ShadeOptions options{Variant::precise, Normalization::exact_coef, reflection,
                                   times_n_dot_l};
        const std::string name = std::string(reflection == Reflection::blinn ? "blinn" : "phong") +
                                 (times_n_dot_l ? "_nl" : "") + (masked ? "_masked" : "");
        const std::uint8_t* lanes = masked ? mask.data() : nullptr;
        std::vector<float> out(count, -1.0f);
        shade(lobe, normal.view(), light.view(), viewer.view(), out.data(), count, lanes, options);
        outputs["shade/vectors_" + name] = digest(out);
        out.assign(count, -1.0f);
        shade(lobe, normal.view(), Direction{0.3f, 0.4f, 0.866f}, Direction{-0.2f, 0.1f, 0.97f},
              out.data(), count, lanes, options);
        outputs["shade/directions_" + name] = digest(out);
        std::vector<float> out_t(t.size(), -1.0f);
        shade(lobe, t.data(), n_dot_l.data(), out_t.data(), std::min(t.size(), count), lanes,
              options);
        outputs["shade/cosines_" + name] = digest(out_t);
      }
}

void record_sampler(Outputs& outputs, bool scalar) {
  const std::size_t count = 4097;
  std::vector<float> u1 = spread(0, 1, count, 71), u2 = spread(0, 1, count, 81);
  u1[0] = 0;
  u1[1] = std::nextafter(1.0f, 0.0f);
  u1[2] = 0x1p-149f;
  for (const auto& [n, k, Q, use, name] :
       {std::tuple{100.0, 3, 0.5, LobeUse::microfacet, "microfacet_n100_k3"},
        std::tuple{1000.0, 1, 0.5, LobeUse::phong, "phong_n1000_k1"},
        std::tuple{10.0, 5, 0.3, LobeUse::microfacet, "microfacet_n10_k5"}}) {
    const LobeSampler sampler(n, k, Q, use);
    std::vector<float> x(count), y(count), z(count), pdf(count);
    if (scalar)
      for (std::size_t i = 0; i < count; ++i) {
        const SampledDirection d = sampler.sample(u1[i], u2[i]);
        x[i] = d.x, y[i] = d.y, z[i] = d.z, pdf[i] = d.pdf;
      }
    else
      sampler.sample(u1.data(), u2.data(), {x.data(), y.data(), z.data(), pdf.data()}, count);
    x.insert(x.end(), y.begin(), y.end());
    x.insert(x.end(), z.begin(), z.end());
    x.insert(x.end(), pdf.begin(), pdf.end());
    outputs[std::string(scalar ? "sample_one/" : "sample/") + name] = digest(x);
  }
}

void record_baselines(Outputs& outputs) {
  const std::vector<float> t = cosines(91);
  std::vector<float> out(t.size());
  for (Variant variant : kVariants) {
    const std::string name = variant == Variant::fast ? "fast" : "precise";
    PowerPoly(1000, variant, 2.5).eval(t.data(), out.data(), t.size());
    outputs["baseline/power_poly_" + name] = digest(out);
    std::vector<float> n = spread(50, 2000, t.size(), 101);
    PerLanePowerPoly(50, 2000, variant, Normalization::exact_coef)
        .eval(t.data(), n.data(), out.data(), t.size());
    outputs["baseline/per_lane_power_poly_" + name] = digest(out);
  }
  blinn_phong_xsimd(t.data(), out.data(), t.size(), 1000, 2.5f);
  outputs["baseline/blinn_phong_xsimd"] = digest(out);
  blinn_phong_u10(t.data(), out.data(), t.size(), 1000, 2.5f);
  outputs["baseline/blinn_phong_u10"] = digest(out);
  schlick(t.data(), out.data(), t.size(), 1000);
  outputs["baseline/schlick"] = digest(out);
}

// Every entry of one arch's functions (the one-sample call among them: it runs the arch's
// build), or the inline scalar paths (arch "scalar").
Outputs record(const std::string& arch) {
  Outputs outputs;
  if (arch == "scalar") {
    record_lobes(outputs, true);
    return outputs;
  }
  force_arch(arch);
  record_math(outputs);
  record_lobes(outputs, false);
  record_shade(outputs);
  record_sampler(outputs, false);
  record_sampler(outputs, true);
  record_baselines(outputs);
  reset_arch();
  return outputs;
}

// "arch key digest" per line.
std::map<std::string, Outputs> read_digests() {
  std::map<std::string, Outputs> digests;
  std::ifstream file(digest_file());
  std::string arch, key, hex;
  while (file >> arch >> key >> hex) digests[arch][key] = std::stoull(hex, nullptr, 16);
  return digests;
}

void write_digests(const std::map<std::string, Outputs>& digests) {
  std::ofstream file(digest_file());
  for (const auto& [arch, outputs] : digests)
    for (const auto& [key, value] : outputs)
      file << arch << ' ' << key << ' ' << std::hex << value << std::dec << '\n';
}

std::vector<std::string> archs_to_check() {
  std::vector<std::string> archs{"scalar"};
  for (Arch arch : supported_archs()) archs.emplace_back(arch_name(arch));
  return archs;
}

TEST(OutputDigests, EveryKernelGivesTheRecordedBits) {
  std::map<std::string, Outputs> recorded = read_digests();
  if (std::getenv("KUTLOG_RECORD_DIGESTS")) {
    for (const std::string& arch : archs_to_check()) recorded[arch] = record(arch);
    write_digests(recorded);
    GTEST_SKIP() << "recorded " << digest_file();
  }
  if (recorded.empty())
    GTEST_SKIP() << "no digests recorded for " << kPlatformName << " built by " << kCompilerName;
  for (const std::string& arch : archs_to_check()) {
    if (!recorded.count(arch)) {
      ADD_FAILURE() << "no digests of arch " << arch << " in " << digest_file()
                    << "; record them (the comment atop this file says how)";
      continue;
    }
    const Outputs outputs = record(arch);
    EXPECT_EQ(outputs.size(), recorded[arch].size()) << arch << ": a kernel added or dropped";
    for (const auto& [key, value] : outputs) {
      const auto found = recorded[arch].find(key);
      if (found == recorded[arch].end())
        ADD_FAILURE() << arch << " " << key << ": not recorded";
      else
        EXPECT_EQ(value, found->second) << arch << " " << key << ": the outputs changed";
    }
  }
}

}  // namespace
}  // namespace kutlog

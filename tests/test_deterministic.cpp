// Variant::deterministic's promise (kutlog/lobe.hpp): every output the same bits on every arch
// and every call shape. In process, every arch this CPU runs and the scalar path (the portable
// arch's instance) compute the same outputs; across CPUs, a digest of them is compared with
// tests/data/deterministic-digests.txt, recorded on x86-64 with GCC and checked by the aarch64
// stage under qemu, the portable stage and clang's sanitize stage, and again under a libm that
// takes its paths for CPUs without FMA (deterministic.libm_without_fma). After a change
// meant to alter these bits:
//   KUTLOG_RECORD_DETERMINISTIC=1 build/tests/kutlog-test-deterministic --gtest_filter=*Digest*
#include <gtest/gtest.h>

#include <algorithm>
#include <bit>
#include <cfloat>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <fstream>
#include <limits>
#include <map>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#if defined(__SSE__)
#include <xmmintrin.h>
#endif
#if defined(__x86_64__) && defined(__GLIBC__) && __has_include(<sys/platform/x86.h>)
#include <sys/platform/x86.h>
#define KUTLOG_GLIBC_CPU_FEATURES 1
#endif

#include "kutlog/dispatch.hpp"
#include "kutlog/inspect.hpp"
#include "kutlog/lobe.hpp"
#include "kutlog/sampling.hpp"
#include "kutlog/shade.hpp"
#include "common/pathtrace.hpp"
#include "lobe_accuracy.hpp"

namespace kutlog {
namespace {

constexpr Variant kDeterministic = Variant::deterministic;

// One file for every platform and compiler: GCC 12 and clang-14 give the same record.
std::string digest_file() { return std::string(KUTLOG_TEST_DATA_DIR) + "/deterministic-digests.txt"; }

// FNV-1a over each float's bits, NaN payloads included.
struct Digest {
  std::uint64_t value = 0xcbf29ce484222325u;
  void add(const float* values, std::size_t count) {
    for (std::size_t i = 0; i < count; ++i) {
      value ^= std::bit_cast<std::uint32_t>(values[i]);
      value *= 0x100000001b3u;
    }
  }
};

// A grid of 40 lobes: k in {1, 2, 5, 20}, Q in {0.1, 0.5}, n from below k (cut at the horizon)
// to 10^5; and 8 off it (random_lobes' own: n near k, n < k, k up to 64).
constexpr std::size_t kGridLobes = 40;
const std::vector<LobeCase>& deterministic_lobes() {
  static const std::vector<LobeCase> lobes = [] {
    std::vector<LobeCase> all;
    for (int k : {1, 2, 5, 20})
      for (double Q : {0.1, 0.5})
        for (double n : {0.5 * k, k + 1.0, 100.0, 3000.0, 1e5}) all.push_back({n, k, Q});
    for (const LobeCase& c : random_lobes(8, 5309)) all.push_back(c);
    return all;
  }();
  return lobes;
}

// The data rule's inputs: NaNs of either sign, quiet and signaling, with payloads; both zeros,
// subnormals, 1 and past it, infinities; the cut and the floats about it.
std::vector<float> special_inputs(const Lobe& lobe) {
  constexpr float inf = std::numeric_limits<float>::infinity();
  std::vector<float> t = {0.0f,       -0.0f,         0x1p-149f,   -0x1p-149f, 0x1.fffffcp-127f,
                          0x1p-126f,  1.0f,          0x1.000002p0f, 2.0f,      -1.0f,
                          inf,        -inf,          FLT_MAX,     -FLT_MAX,   0.5f};
  for (std::uint32_t nan : {0x7fc00000u, 0xffc00000u, 0x7fc12345u, 0xfff278d6u, 0x7f800001u,
                            0xff812345u, 0x7fbfffffu})
    t.push_back(std::bit_cast<float>(nan));
  float below = lobe.t_cut(), above = lobe.t_cut();
  t.push_back(below);
  for (int i = 0; i < 8; ++i)
    t.push_back(below = std::nextafter(below, -1.0f)), t.push_back(above = std::nextafter(above, 2.0f));
  return t;
}

// Every `stride`-th float of [0, 1] from 1 down, then the special inputs: the digest's inputs
// (an odd count: every arch ends on a partial batch).
std::vector<float> digest_inputs(const Lobe& lobe, std::uint32_t stride) {
  std::vector<float> t;
  for (std::uint32_t bits = std::bit_cast<std::uint32_t>(1.0f);; bits -= stride) {
    t.push_back(std::bit_cast<float>(bits));
    if (bits < stride) break;
  }
  for (float special : special_inputs(lobe)) t.push_back(special);
  if (t.size() % 2 == 0) t.push_back(0.25f);
  return t;
}

// The archs this CPU runs, each as a forced arch.
std::vector<Arch> archs() { return supported_archs(); }

// Asserts that `values` are `expected`'s bits, naming the first that is not (and its input,
// where `inputs` has one per value).
void expect_same_bits(const std::vector<float>& expected, const std::vector<float>& values,
                      const std::vector<float>& inputs, const std::string& what) {
  ASSERT_EQ(expected.size(), values.size()) << what;
  if (std::memcmp(expected.data(), values.data(), expected.size() * sizeof(float)) == 0) return;
  for (std::size_t i = 0; i < expected.size(); ++i)
    if (std::bit_cast<std::uint32_t>(expected[i]) != std::bit_cast<std::uint32_t>(values[i])) {
      const float input = i < inputs.size() ? inputs[i] : std::numeric_limits<float>::quiet_NaN();
      ADD_FAILURE() << what << ": output " << i << ", input " << input << " (0x" << std::hex
                    << std::bit_cast<std::uint32_t>(input) << ") gives 0x"
                    << std::bit_cast<std::uint32_t>(values[i]) << ", expected 0x"
                    << std::bit_cast<std::uint32_t>(expected[i]);
      return;
    }
}

// A lobe's outputs on t by one arch's arrays, and by its other call shapes (one fragment at a
// time, the stream API on given cosines), each asserted to be the arrays' bits.
std::vector<float> lobe_outputs(const Lobe& lobe, Normalization normalization,
                                const std::vector<float>& t, Arch arch, bool scalar_path) {
  const inspect::ScopedArch forced(arch);
  std::vector<float> out(t.size()), shaded(t.size());
  lobe.eval(t.data(), out.data(), t.size(), kDeterministic, normalization);
  shade(lobe, t.data(), nullptr, shaded.data(), t.size(), nullptr,
        {kDeterministic, normalization, Reflection::blinn, false});
  const std::string name = std::string(arch_name(arch)) + " " + testing::PrintToString(lobe.n()) +
                           " " + std::to_string(lobe.k()) + " " + std::to_string(lobe.Q());
  expect_same_bits(out, shaded, t, name + ": shade against eval");
  if (scalar_path) {
    std::vector<float> one(t.size());
    for (std::size_t i = 0; i < t.size(); ++i) one[i] = lobe.eval(t[i], kDeterministic, normalization);
    expect_same_bits(out, one, t, name + ": eval(t) against the arrays");
  }
  return out;
}

// A 64-bit LCG: the same stream on every platform, where the standard distributions are not.
struct FixedStream {
  std::uint64_t state;
  std::uint64_t next() { return state = state * 6364136223846793005u + 1442695040888963407u; }
};

// Unit vectors from a FixedStream: x, y, z uniform in [-1, 1] normalized in double, each
// rounded once.
struct UnitVectors {
  std::vector<float> x, y, z;
  UnitVectors(std::size_t count, std::uint64_t seed, bool upper) {
    FixedStream stream{seed};
    const auto unit = [&] { return double(stream.next() >> 11) * 0x1p-52 - 1.0; };
    for (std::size_t i = 0; i < count; ++i) {
      const double a = unit(), b = unit(), c = upper ? std::fabs(unit()) + 0.05 : unit();
      const double length = std::sqrt(a * a + b * b + c * c);
      x.push_back(float(a / length)), y.push_back(float(b / length)), z.push_back(float(c / length));
    }
  }
  Vectors view() const { return {x.data(), y.data(), z.data()}; }
};

// shade's outputs of every form, reflection and normalization over fixed vectors, by one arch.
std::vector<float> shade_outputs(const Lobe& lobe, Arch arch) {
  const inspect::ScopedArch forced(arch);
  constexpr std::size_t kCount = 4099;
  const UnitVectors normal(kCount, 11, true), light(kCount, 12, true), viewer(kCount, 13, true);
  // Viewers near the mirror direction of the light, where the lobe is not 0.
  UnitVectors near = normal;
  for (std::size_t i = 0; i < kCount; ++i) {
    const double d = 2.0 * (double(normal.x[i]) * light.x[i] + double(normal.y[i]) * light.y[i] +
                            double(normal.z[i]) * light.z[i]);
    const double rx = d * normal.x[i] - light.x[i] + 0.01 * (viewer.x[i]),
                 ry = d * normal.y[i] - light.y[i] + 0.01 * (viewer.y[i]),
                 rz = d * normal.z[i] - light.z[i] + 0.01 * (viewer.z[i]);
    const double length = std::sqrt(rx * rx + ry * ry + rz * rz);
    near.x[i] = float(rx / length), near.y[i] = float(ry / length), near.z[i] = float(rz / length);
  }
  const Direction sun{0.48f, 0.6f, 0.64f}, eye{-0.36f, 0.48f, 0.8f};
  std::vector<float> all, out(kCount);
  for (Reflection reflection : {Reflection::blinn, Reflection::phong})
    for (Normalization normalization : {Normalization::none, Normalization::exact_coef})
      for (bool times_n_dot_l : {true, false}) {
        const ShadeOptions options{kDeterministic, normalization, reflection, times_n_dot_l};
        shade(lobe, normal.view(), light.view(), near.view(), out.data(), kCount, nullptr, options);
        all.insert(all.end(), out.begin(), out.end());
        shade(lobe, normal.view(), sun, eye, out.data(), kCount, nullptr, options);
        all.insert(all.end(), out.begin(), out.end());
      }
  return all;
}

// PerLaneLobe's outputs over (t, n) pairs by one arch's arrays, its one fragment asserted equal.
std::vector<float> per_lane_outputs(const PerLaneLobe& lobe, const std::vector<float>& t,
                                    const std::vector<float>& n, Arch arch) {
  const inspect::ScopedArch forced(arch);
  std::vector<float> all, out(t.size()), one(t.size());
  for (Normalization normalization : {Normalization::none, Normalization::exact_coef}) {
    lobe.eval(t.data(), n.data(), out.data(), t.size(), kDeterministic, normalization);
    for (std::size_t i = 0; i < t.size(); ++i)
      one[i] = lobe.eval(t[i], n[i], kDeterministic, normalization);
    expect_same_bits(out, one, t, std::string(arch_name(arch)) + ": per-lane eval(t, n)");
    all.insert(all.end(), out.begin(), out.end());
  }
  return all;
}

// A sampler's 2^18 samples and the data rule's (u1, u2) by one arch's arrays, its one-sample
// call asserted equal: x, y, z and pdf of each in turn.
std::vector<float> sampler_outputs(const LobeSampler& sampler, Arch arch) {
  const inspect::ScopedArch forced(arch);
  std::vector<float> u1, u2;
  FixedStream stream{77};
  for (int i = 0; i < 1 << 18; ++i) {
    const std::uint64_t bits = stream.next();
    u1.push_back(float(bits >> 40) * 0x1p-24f);
    u2.push_back(float((bits >> 16) & 0xffffffu) * 0x1p-24f);
  }
  constexpr float inf = std::numeric_limits<float>::infinity();
  for (float special : {0.0f, -0.0f, 0x1p-149f, 0x1p-60f, 0.5f, 0x1.fffffep-1f, 1.0f, 2.0f, -1.0f,
                        inf, -inf, std::bit_cast<float>(0x7fc00000u),
                        std::bit_cast<float>(0xff812345u)})
    for (float other : {0.0f, 0.3f, 0x1.fffffep-1f, std::bit_cast<float>(0x7fc12345u)})
      u1.push_back(special), u2.push_back(other), u1.push_back(other), u2.push_back(special);
  const std::size_t count = u1.size();
  std::vector<float> x(count), y(count), z(count), pdf(count), one(4 * count), all;
  sampler.sample(u1.data(), u2.data(), {x.data(), y.data(), z.data(), pdf.data()}, count,
                 kDeterministic);
  for (const std::vector<float>* output : {&x, &y, &z, &pdf})
    all.insert(all.end(), output->begin(), output->end());
  for (std::size_t i = 0; i < count; ++i) {
    const SampledDirection d = sampler.sample(u1[i], u2[i], kDeterministic);
    one[i] = d.x, one[count + i] = d.y, one[2 * count + i] = d.z, one[3 * count + i] = d.pdf;
  }
  std::vector<float> inputs(u1);
  for (int copy = 0; copy < 3; ++copy) inputs.insert(inputs.end(), u1.begin(), u1.end());
  expect_same_bits(all, one, inputs, std::string(arch_name(arch)) + ": one sample per call");
  return all;
}

// A double's bits as two floats', for the digests.
void push_bits(std::vector<float>& values, double value) {
  const std::uint64_t bits = std::bit_cast<std::uint64_t>(value);
  values.push_back(std::bit_cast<float>(std::uint32_t(bits)));
  values.push_back(std::bit_cast<float>(std::uint32_t(bits >> 32)));
}

// The deterministic kernels the setup fits for 400 random lobes, as the bits of their fields
// (the setup fits in long double, 64 bits of mantissa on x86-64 and 113 on AArch64: its kernels
// must round to the same floats). Parameters from integer bits only, the same on every
// platform: n = m 2^e over [2^-1, 2^20], k in 1..64 (1..5 for the first 100), Q in (0.01, 0.99).
std::vector<float> kernels_of_random_lobes() {
  std::vector<float> fields;
  FixedStream stream{2026};
  const auto next = [&] { return stream.next() >> 11; };
  for (int i = 0; i < 400; ++i) {
    // One draw per statement: the order of a call's arguments differs by platform.
    const double mantissa = 1.0 + double(next() & 0xfffff) * 0x1p-20;
    const double n = std::ldexp(mantissa, int(next() % 21) - 1);
    const int k = i < 100 ? 1 + i % 5 : 1 + int(next() % 64);
    const double Q = 0.01 + 0.98 * double(next() & 0xffffff) * 0x1p-24;
    const Lobe lobe(n, k, Q);
    for (Normalization normalization : {Normalization::none, Normalization::exact_coef}) {
      const inspect::LobeKernel& kernel =
          inspect::kernel(lobe, kDeterministic, normalization, inspect::Arithmetic::unfused);
      for (float field : {float(kernel.form), float(kernel.degree), float(kernel.k), kernel.t_cut,
                          kernel.center_t, kernel.scale_f, kernel.scale_lo, float(kernel.clamped)})
        fields.push_back(field);
      push_bits(fields, kernel.scale_d);
      for (int j = 0; j <= kernel.degree; ++j)
        push_bits(fields, kernel.form == inspect::LobeKernel::Form::base_power
                              ? kernel.q_d[std::size_t(j)]
                              : double(kernel.q_f[std::size_t(j)]));
    }
  }
  return fields;
}

// Every output of every path, by name, for the digest: each arch's must be the first arch's.
std::map<std::string, std::uint64_t> current_digests() {
  std::map<std::string, std::uint64_t> digests;
  const auto record = [&](const std::string& name, const std::vector<float>& values,
                          const std::vector<float>& inputs, std::vector<float>* first) {
    if (first->empty()) {
      *first = values;
      Digest digest;
      digest.add(values.data(), values.size());
      digests[name] = digest.value;
    } else {
      expect_same_bits(*first, values, inputs, name);
    }
  };
  std::vector<float> no_first;
  record("kernels of 400 random lobes", kernels_of_random_lobes(), {}, &no_first);
  for (const LobeCase& c : deterministic_lobes()) {
    const Lobe lobe(c.n, c.k, c.Q);
    const std::vector<float> t = digest_inputs(lobe, 4099);
    const std::string name = "lobe n=" + testing::PrintToString(c.n) + " k=" + std::to_string(c.k) +
                             " Q=" + testing::PrintToString(c.Q);
    for (Normalization normalization : {Normalization::none, Normalization::exact_coef}) {
      std::vector<float> first;
      for (Arch arch : archs())
        record(name + (normalization == Normalization::none ? "" : " coef"),
               lobe_outputs(lobe, normalization, t, arch, arch == archs().front()), t, &first);
    }
    std::vector<float> first;
    for (Arch arch : archs()) record(name + " shade", shade_outputs(lobe, arch), {}, &first);
  }
  for (const auto& [n, k, use] : {std::tuple{1000.0, 3, LobeUse::microfacet},
                                  std::tuple{30.0, 1, LobeUse::phong},
                                  std::tuple{3.0, 8, LobeUse::microfacet},
                                  std::tuple{1e5, 40, LobeUse::phong}}) {
    const LobeSampler sampler(n, k, 0.5, use);
    std::vector<float> first;
    for (Arch arch : archs())
      record("sampler n=" + testing::PrintToString(n) + " k=" + std::to_string(k) +
                 (use == LobeUse::phong ? " phong" : " microfacet"),
             sampler_outputs(sampler, arch), {}, &first);
  }
  // The path tracer's image (kutlog-pathtrace), rendered in the deterministic mode: its pixels'
  // doubles as pairs of floats' bits.
  const pathtrace::Material material(1000, 3, 0.5, kDeterministic);
  const pathtrace::Environment sky = pathtrace::Environment::sky();
  std::vector<float> first_image;
  for (Arch arch : archs()) {
    const inspect::ScopedArch forced(arch);
    const pathtrace::Image image =
        pathtrace::render({material, sky, 32, 24}, pathtrace::Sampler::lobe, 3, {4}, 1)[0];
    std::vector<float> bits;
    for (const pathtrace::Rgb& pixel : image.pixels)
      for (double channel : {pixel.r, pixel.g, pixel.b}) push_bits(bits, channel);
    record("pathtrace image", bits, {}, &first_image);
  }
  const std::vector<float> t = digest_inputs(Lobe(100, 3, 0.5), 65521);
  std::vector<float> n(t.size());
  for (std::size_t i = 0; i < n.size(); ++i) n[i] = 30.0f * std::pow(100.0f, float(i % 997) / 996);
  for (const auto& [n_min, n_max, k] : {std::tuple{30.0, 3000.0, 3}, std::tuple{2.0, 50.0, 1},
                                        std::tuple{100.0, 1e5, 5}}) {
    const PerLaneLobe lobe(n_min, n_max, k, 0.5);
    std::vector<float> first;
    for (Arch arch : archs())
      record("per_lane n_min=" + testing::PrintToString(n_min) + " k=" + std::to_string(k),
             per_lane_outputs(lobe, t, n, arch), t, &first);
  }
  return digests;
}

std::map<std::string, std::uint64_t> read_digests() {
  std::map<std::string, std::uint64_t> digests;
  std::ifstream file(digest_file());
  std::string line;
  while (std::getline(file, line)) {
    const std::size_t space = line.rfind(' ');
    if (space != std::string::npos)
      digests[line.substr(0, space)] = std::strtoull(line.c_str() + space + 1, nullptr, 16);
  }
  return digests;
}

// Every arch and call shape in process, and the digest against the record of every platform.
TEST(Deterministic, DigestOfEveryPathAndArchMatchesTheRecord) {
  const std::map<std::string, std::uint64_t> current = current_digests();
  if (std::getenv("KUTLOG_RECORD_DETERMINISTIC")) {
    std::FILE* file = std::fopen(digest_file().c_str(), "w");
    ASSERT_NE(file, nullptr) << digest_file();
    for (const auto& [name, digest] : current)
      std::fprintf(file, "%s %016llx\n", name.c_str(), static_cast<unsigned long long>(digest));
    std::fclose(file);
    GTEST_SKIP() << "recorded " << digest_file();
  }
  const std::map<std::string, std::uint64_t> recorded = read_digests();
  ASSERT_FALSE(recorded.empty()) << "no record: " << digest_file();
  for (const auto& [name, digest] : current) {
    const auto found = recorded.find(name);
    if (found == recorded.end()) {
      ADD_FAILURE() << name << ": not in the record " << digest_file()
                    << "; record it anew (the file's header says how)";
      continue;
    }
    EXPECT_EQ(digest, found->second)
        << name << ": the deterministic bits differ from the record (" << digest_file()
        << "), made on another CPU or before a change; its header says how to record it";
  }
  EXPECT_EQ(current.size(), recorded.size()) << "stale entries in " << digest_file();
}

#if defined(KUTLOG_GLIBC_CPU_FEATURES)
// deterministic.libm_without_fma runs the digest with GLIBC_TUNABLES hiding FMA and
// AVX2 from glibc, which then computes sin, cos, exp, log, pow... by its paths for CPUs without
// them, as on an older x86 node (libm's results differ between the two; the setups call their
// own, src/fixed_math.hpp). This checks that glibc took the tunable.
TEST(Deterministic, GlibcTookTheTunableThatHidesFma) {
  if (!std::getenv("KUTLOG_EXPECT_LIBM_WITHOUT_FMA")) GTEST_SKIP() << "not under the tunable";
  EXPECT_FALSE(CPU_FEATURE_ACTIVE(FMA));
  EXPECT_FALSE(CPU_FEATURE_ACTIVE(AVX2));
}
#endif

#if defined(__SSE__)
// The promise assumes no flush of subnormals (docs/accuracy.md): under x86's FTZ and DAZ (set
// at start by a program linked with -ffast-math) only outputs at a subnormal t (a lobe cut at
// the horizon is not 0 there) or below 2^-126 change (a 0 may come out -0: a tiny negative
// value flushed before the clamp).
TEST(Deterministic, FlushingSubnormalsChangesOnlyTheirOutputs) {
  int changed = 0;
  for (const LobeCase& c : deterministic_lobes()) {
    const Lobe lobe(c.n, c.k, c.Q);
    std::vector<float> t = digest_inputs(lobe, 4099);
    for (std::uint32_t bits = 1; bits < 0x00800000u; bits += 0x1001) t.push_back(std::bit_cast<float>(bits));
    for (Normalization normalization : {Normalization::none, Normalization::exact_coef}) {
      std::vector<float> plain, flushed;
      for (Arch arch : archs()) {
        plain = lobe_outputs(lobe, normalization, t, arch, false);
        const unsigned csr = _mm_getcsr();
        _mm_setcsr(csr | 0x8040);  // FTZ, DAZ
        flushed = lobe_outputs(lobe, normalization, t, arch, false);
        _mm_setcsr(csr);
        for (std::size_t i = 0; i < t.size(); ++i) {
          if (std::bit_cast<std::uint32_t>(plain[i]) == std::bit_cast<std::uint32_t>(flushed[i]))
            continue;
          ++changed;
          EXPECT_TRUE(std::fpclassify(t[i]) == FP_SUBNORMAL || std::fabs(plain[i]) < FLT_MIN)
              << arch_name(arch) << " " << testing::PrintToString(c) << ": t = " << t[i]
              << " gives " << plain[i] << ", flushed " << flushed[i];
        }
      }
    }
  }
  EXPECT_GT(changed, 0) << "FTZ and DAZ changed nothing: the test no longer sees them";
}
#endif

// Every float of [0, 1], each lobe of the grid and both normalizations: every arch this CPU
// runs gives the first one's bits (where it runs two or more).
class DeterministicEveryFloat : public testing::TestWithParam<LobeCase> {};

TEST_P(DeterministicEveryFloat, EveryArchGivesTheSameBits) {
  const std::vector<Arch> all = archs();
  if (all.size() < 2) GTEST_SKIP() << "one arch on this CPU: the digest compares it";
  const Lobe lobe(GetParam().n, GetParam().k, GetParam().Q);
  constexpr std::uint32_t kChunk = 1 << 16;
  std::vector<float> t(kChunk), first(kChunk), out(kChunk);
  std::vector<detail::LobeArrayKernels const*> loops;
  for (Arch arch : all) {
    const inspect::ScopedArch forced(arch);
    float probe = 1;
    lobe.eval(&probe, &probe, 1);
    loops.push_back(detail::Inspector::active_loops().load());
  }
  for (Normalization normalization : {Normalization::none, Normalization::exact_coef})
    for (std::uint32_t top = std::bit_cast<std::uint32_t>(1.0f) + 1; top > 0;) {
      const std::uint32_t size = std::min(top, kChunk);
      for (std::uint32_t i = 0; i < size; ++i) t[i] = std::bit_cast<float>(top - 1 - i);
      top -= size;
      for (std::size_t a = 0; a < all.size(); ++a) {
        detail::Inspector::active_loops().store(loops[a]);
        lobe.eval(t.data(), (a == 0 ? first : out).data(), size, kDeterministic, normalization);
        if (a > 0 && std::memcmp(first.data(), out.data(), size * sizeof(float)) != 0) {
          expect_same_bits(std::vector<float>(first.begin(), first.begin() + size),
                           std::vector<float>(out.begin(), out.begin() + size),
                           std::vector<float>(t.begin(), t.begin() + size),
                           std::string(arch_name(all[a])) + " against " +
                               std::string(arch_name(all[0])));
          reset_arch();
          return;
        }
      }
    }
  reset_arch();
}

INSTANTIATE_TEST_SUITE_P(Grid, DeterministicEveryFloat,
                         testing::ValuesIn(deterministic_lobes().begin(),
                                           deterministic_lobes().begin() + kGridLobes));

}  // namespace
}  // namespace kutlog

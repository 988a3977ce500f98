// The C API (kutlog/kutlog.h) against the C++ API it wraps: the same bits from every call, the
// C++ exceptions' messages as error codes, and the documented rule for NULL handles, NULL
// arrays, huge counts and enums out of range. tests/c_api_from_c.c checks the header as C.
#include "kutlog/kutlog.h"

#include <gtest/gtest.h>

#include <bit>
#include <cmath>
#include <cstdint>
#include <limits>
#include <memory>
#include <random>
#include <stdexcept>
#include <string>
#include <vector>

#include "kutlog/dispatch.hpp"
#include "kutlog/inspect.hpp"
#include "kutlog/lobe.hpp"
#include "kutlog/math.hpp"
#include "kutlog/sampling.hpp"
#include "kutlog/shade.hpp"

namespace kutlog {
namespace {

constexpr float kSentinel = -12345.0f;

struct LobeDeleter {
  void operator()(kutlog_lobe* lobe) const { kutlog_lobe_destroy(lobe); }
};
using LobeHandle = std::unique_ptr<kutlog_lobe, LobeDeleter>;

LobeHandle make_lobe(double n, int k, double Q) {
  kutlog_lobe* lobe = nullptr;
  kutlog_error error{};
  EXPECT_EQ(kutlog_lobe_create(n, k, Q, &lobe, &error), KUTLOG_OK) << error.message;
  return LobeHandle(lobe);
}

// Inputs that cover the data rule: the lobe's inside and cut, signed zeros, t > 1, NaN.
std::vector<float> cosines(float t_cut) {
  std::vector<float> t = {0.0f, -0.0f, 1.0f, 1.0000001f, 2.0f, -1.0f, -1.5f, t_cut,
                          std::nextafter(t_cut, 1.0f), std::numeric_limits<float>::quiet_NaN(),
                          std::numeric_limits<float>::infinity(),
                          -std::numeric_limits<float>::infinity()};
  std::mt19937 random(49);
  std::uniform_real_distribution<float> inside(t_cut, 1.0f), anywhere(-1.0f, 1.0f);
  for (int i = 0; i < 20000; ++i) t.push_back(i % 2 ? inside(random) : anywhere(random));
  return t;
}

void expect_same_bits(float expected, float actual, float t) {
  EXPECT_EQ(std::bit_cast<std::uint32_t>(expected), std::bit_cast<std::uint32_t>(actual))
      << "t = " << t << ": " << expected << " against " << actual;
}

// The C fragment's inline eval, precise and fast, gives Lobe::eval's bits: pieces where
// certified, else the kernel out of line (the horizon-cut lobe n = 2, and k = 40).
TEST(CApi, FragmentEvalIsLobeEvalBitForBit) {
  for (const auto [n, k, Q] : {std::tuple{1000.0, 3, 0.5}, std::tuple{50.0, 5, 0.2},
                               std::tuple{2.0, 3, 0.5}, std::tuple{3000.0, 40, 0.9}}) {
    const Lobe lobe(n, k, Q);
    const LobeHandle handle = make_lobe(n, k, Q);
    for (const Normalization normalization : {Normalization::none, Normalization::exact_coef}) {
      kutlog_fragment precise;
      kutlog_fast_fragment fast;
      const auto c_normalization = kutlog_normalization(normalization);
      ASSERT_EQ(kutlog_lobe_fragment(handle.get(), c_normalization, &precise, nullptr), KUTLOG_OK);
      ASSERT_EQ(kutlog_lobe_fast_fragment(handle.get(), c_normalization, &fast, nullptr),
                KUTLOG_OK);
      EXPECT_EQ(precise.pieces == nullptr,
                inspect::precise_pieces(lobe, normalization).table.empty());
      EXPECT_EQ(precise.t_cut, lobe.t_cut());
      for (const float t : cosines(lobe.t_cut())) {
        expect_same_bits(lobe.eval(t, Variant::precise, normalization), kutlog_eval(&precise, t),
                         t);
        expect_same_bits(lobe.eval(t, Variant::fast, normalization), kutlog_eval_fast(&fast, t),
                         t);
      }
    }
  }
  EXPECT_EQ(sizeof(kutlog_fragment), 32u);
  EXPECT_EQ(sizeof(kutlog_fast_fragment), 32u);
}

// Each array call gives the C++ call's bits.
TEST(CApi, ArraysAreTheCppArrays) {
  const Lobe lobe(300, 3, 0.5);
  const LobeHandle handle = make_lobe(300, 3, 0.5);
  const std::vector<float> t = cosines(lobe.t_cut());
  const std::size_t count = t.size();
  std::vector<float> expected(count), actual(count);
  for (const Variant variant : {Variant::precise, Variant::fast}) {
    lobe.eval(t.data(), expected.data(), count, variant, Normalization::exact_coef);
    ASSERT_EQ(kutlog_lobe_eval_array(handle.get(), t.data(), actual.data(), count,
                                     kutlog_variant(variant), KUTLOG_EXACT_COEF, nullptr),
              KUTLOG_OK);
    for (std::size_t i = 0; i < count; ++i) expect_same_bits(expected[i], actual[i], t[i]);
  }
  std::vector<float> n(count);
  for (std::size_t i = 0; i < count; ++i) n[i] = 100.0f + float(i % 900);
  const PerLaneLobe per_lane(100, 1000, 3, 0.5);
  kutlog_per_lane_lobe* c_per_lane = nullptr;
  ASSERT_EQ(kutlog_per_lane_lobe_create(100, 1000, 3, 0.5, &c_per_lane, nullptr), KUTLOG_OK);
  per_lane.eval(t.data(), n.data(), expected.data(), count);
  ASSERT_EQ(kutlog_per_lane_lobe_eval_array(c_per_lane, t.data(), n.data(), actual.data(), count,
                                            KUTLOG_PRECISE, KUTLOG_UNNORMALIZED, nullptr),
            KUTLOG_OK);
  for (std::size_t i = 0; i < count; ++i) {
    expect_same_bits(expected[i], actual[i], t[i]);
    expect_same_bits(per_lane.eval(t[i], n[i]),
                     kutlog_per_lane_lobe_eval(c_per_lane, t[i], n[i], KUTLOG_PRECISE,
                                               KUTLOG_UNNORMALIZED),
                     t[i]);
  }
  kutlog_per_lane_lobe_destroy(c_per_lane);
  math::pow_u10(t.data(), 50.0f, expected.data(), count);
  ASSERT_EQ(kutlog_pow_u10_scalar_y(t.data(), 50.0f, actual.data(), count, nullptr), KUTLOG_OK);
  for (std::size_t i = 0; i < count; ++i) expect_same_bits(expected[i], actual[i], t[i]);
  math::acos_u10(t.data(), expected.data(), count);
  ASSERT_EQ(kutlog_acos_u10(t.data(), actual.data(), count, nullptr), KUTLOG_OK);
  for (std::size_t i = 0; i < count; ++i) expect_same_bits(expected[i], actual[i], t[i]);
}

// The three shade calls and both sample calls give the C++ bits.
TEST(CApi, ShadeAndSampleAreTheCppCalls) {
  const Lobe lobe(100, 3, 0.5);
  const LobeHandle handle = make_lobe(100, 3, 0.5);
  constexpr std::size_t kCount = 1000;
  std::mt19937 random(50);
  std::uniform_real_distribution<float> unit(0.0f, 1.0f);
  std::vector<float> nx(kCount), ny(kCount), nz(kCount), u1(kCount), u2(kCount);
  for (std::size_t i = 0; i < kCount; ++i) {
    const float phi = 6.2831853f * unit(random), z = unit(random), r = std::sqrt(1 - z * z);
    nx[i] = r * std::cos(phi), ny[i] = r * std::sin(phi), nz[i] = z;
    u1[i] = unit(random), u2[i] = unit(random);
  }
  std::vector<std::uint8_t> mask(kCount);
  for (std::size_t i = 0; i < kCount; ++i) mask[i] = std::uint8_t(i % 3 != 0);
  std::vector<float> expected(kCount, 7.0f), actual(kCount, 7.0f);
  const kutlog_shade_options options{KUTLOG_FAST, KUTLOG_EXACT_COEF, KUTLOG_REFLECT_PHONG, 1};
  shade(lobe, {nx.data(), ny.data(), nz.data()}, Direction{0, 0.6f, 0.8f}, Direction{0, 0, 1},
        expected.data(), kCount, mask.data(),
        {Variant::fast, Normalization::exact_coef, Reflection::phong, true});
  ASSERT_EQ(kutlog_shade_directional(handle.get(), {nx.data(), ny.data(), nz.data()},
                                     {0, 0.6f, 0.8f}, {0, 0, 1}, actual.data(), kCount,
                                     mask.data(), &options, nullptr),
            KUTLOG_OK);
  for (std::size_t i = 0; i < kCount; ++i) expect_same_bits(expected[i], actual[i], nx[i]);
  shade(lobe, {nx.data(), ny.data(), nz.data()}, {ny.data(), nz.data(), nx.data()},
        {nz.data(), nx.data(), ny.data()}, expected.data(), kCount);
  ASSERT_EQ(kutlog_shade(handle.get(), {nx.data(), ny.data(), nz.data()},
                         {ny.data(), nz.data(), nx.data()}, {nz.data(), nx.data(), ny.data()},
                         actual.data(), kCount, nullptr, nullptr, nullptr),
            KUTLOG_OK);
  for (std::size_t i = 0; i < kCount; ++i) expect_same_bits(expected[i], actual[i], nx[i]);
  shade(lobe, nz.data(), ny.data(), expected.data(), kCount);
  ASSERT_EQ(kutlog_shade_cosines(handle.get(), nz.data(), ny.data(), actual.data(), kCount,
                                 nullptr, nullptr, nullptr),
            KUTLOG_OK);
  for (std::size_t i = 0; i < kCount; ++i) expect_same_bits(expected[i], actual[i], nz[i]);

  const LobeSampler sampler(100, 3, 0.5, LobeUse::phong);
  kutlog_sampler* c_sampler = nullptr;
  ASSERT_EQ(kutlog_sampler_create(100, 3, 0.5, KUTLOG_USE_PHONG, &c_sampler, nullptr), KUTLOG_OK);
  std::vector<float> x(kCount), y(kCount), z(kCount), pdf(kCount);
  std::vector<float> cpp_x(kCount), cpp_y(kCount), cpp_z(kCount);
  for (const Variant variant : {Variant::precise, Variant::deterministic}) {
    sampler.sample(u1.data(), u2.data(),
                   {cpp_x.data(), cpp_y.data(), cpp_z.data(), expected.data()}, kCount, variant);
    ASSERT_EQ(kutlog_sampler_sample_array(c_sampler, u1.data(), u2.data(), x.data(), y.data(),
                                          z.data(), pdf.data(), kCount, kutlog_variant(variant),
                                          nullptr),
              KUTLOG_OK);
    for (std::size_t i = 0; i < kCount; ++i) {
      expect_same_bits(cpp_x[i], x[i], u1[i]);
      expect_same_bits(cpp_y[i], y[i], u1[i]);
      expect_same_bits(cpp_z[i], z[i], u1[i]);
      expect_same_bits(expected[i], pdf[i], u1[i]);
      const SampledDirection one = sampler.sample(u1[i], u2[i], variant);
      const kutlog_sample c_one =
          kutlog_sampler_sample(c_sampler, u1[i], u2[i], kutlog_variant(variant));
      expect_same_bits(one.z, c_one.z, u1[i]);
      expect_same_bits(one.pdf, c_one.pdf, u1[i]);
    }
  }
  kutlog_sampler_destroy(c_sampler);
}

// Each invalid parameter: the C++ exception's message, its code, and no handle.
TEST(CApi, InvalidParametersGiveTheCppMessage) {
  const auto cpp_message = [](auto construct) {
    try {
      construct();
    } catch (const std::invalid_argument& exception) {
      return std::string(exception.what());
    }
    return std::string("no exception");
  };
  struct Invalid {
    double n;
    int k;
    double Q;
    const char* parameter;
  };
  for (const Invalid& invalid : {Invalid{0.0, 3, 0.5, "n = "}, Invalid{100.0, 0, 0.5, "k = "},
                                 Invalid{100.0, 3, 1.0, "Q = "},
                                 Invalid{1e300, 3, 0.5, "n is out of range"}}) {
    const double n = invalid.n, Q = invalid.Q;  // captured below: not structured bindings
    const int k = invalid.k;
    const char* const parameter = invalid.parameter;
    kutlog_error error{};
    kutlog_lobe* lobe = reinterpret_cast<kutlog_lobe*>(&error);  // overwritten with NULL
    EXPECT_EQ(kutlog_lobe_create(n, k, Q, &lobe, &error), KUTLOG_INVALID_ARGUMENT);
    EXPECT_EQ(lobe, nullptr);
    EXPECT_EQ(error.code, KUTLOG_INVALID_ARGUMENT);
    EXPECT_EQ(std::string(error.message), cpp_message([&] { Lobe(n, k, Q); }));
    EXPECT_NE(std::string(error.message).find(parameter), std::string::npos) << error.message;
    kutlog_sampler* sampler = nullptr;
    if (std::string(parameter) != "n is out of range") {
      EXPECT_EQ(kutlog_sampler_create(n, k, Q, KUTLOG_USE_MICROFACET, &sampler, &error),
                KUTLOG_INVALID_ARGUMENT);
      EXPECT_EQ(sampler, nullptr);
      EXPECT_EQ(std::string(error.message),
                cpp_message([&] { LobeSampler(n, k, Q, LobeUse::microfacet); }));
    }
    // Without an error struct: the code alone.
    EXPECT_EQ(kutlog_lobe_create(n, k, Q, &lobe, nullptr), KUTLOG_INVALID_ARGUMENT);
  }
  kutlog_error error{};
  kutlog_per_lane_lobe* per_lane = nullptr;
  EXPECT_EQ(kutlog_per_lane_lobe_create(1000, 100, 3, 0.5, &per_lane, &error),
            KUTLOG_INVALID_ARGUMENT);
  EXPECT_EQ(std::string(error.message), cpp_message([] { PerLaneLobe(1000, 100, 3, 0.5); }));
  EXPECT_EQ(kutlog_lobe_create(100, 3, 0.5, nullptr, &error), KUTLOG_INVALID_ARGUMENT);
  EXPECT_NE(std::string(error.message).find("address is NULL"), std::string::npos)
      << error.message;
  kutlog_sampler* sampler = nullptr;
  EXPECT_EQ(kutlog_sampler_create(100, 3, 0.5, kutlog_lobe_use(2), &sampler, &error),
            KUTLOG_INVALID_ARGUMENT);
  EXPECT_NE(std::string(error.message).find("use = 2 is out of range"), std::string::npos)
      << error.message;
  EXPECT_EQ(sampler, nullptr);
}

// The pointer and count rule: count 0 takes NULL; NULL with a count, a count past
// KUTLOG_MAX_COUNT, a NULL handle or an enum out of range is refused, naming it, and nothing is
// written.
TEST(CApi, NullsCountsAndEnumsFollowTheRule) {
  const LobeHandle lobe = make_lobe(100, 3, 0.5);
  std::vector<float> t(16, 0.5f), out(16, kSentinel);
  kutlog_error error{};
  const auto refused = [&](kutlog_status status, const std::string& named) {
    EXPECT_EQ(status, KUTLOG_INVALID_ARGUMENT);
    EXPECT_EQ(error.code, KUTLOG_INVALID_ARGUMENT);
    EXPECT_NE(std::string(error.message).find(named), std::string::npos) << error.message;
    for (const float value : out) EXPECT_EQ(value, kSentinel);
  };
  EXPECT_EQ(kutlog_lobe_eval_array(lobe.get(), nullptr, nullptr, 0, KUTLOG_PRECISE,
                                   KUTLOG_UNNORMALIZED, &error),
            KUTLOG_OK);
  EXPECT_EQ(error.code, KUTLOG_OK);
  EXPECT_EQ(kutlog_acos_u10(nullptr, nullptr, 0, &error), KUTLOG_OK);
  refused(kutlog_lobe_eval_array(lobe.get(), nullptr, out.data(), 16, KUTLOG_PRECISE,
                                 KUTLOG_UNNORMALIZED, &error),
          "t is NULL with count = 16");
  refused(kutlog_lobe_eval_array(lobe.get(), t.data(), out.data(), KUTLOG_MAX_COUNT + 1u,
                                 KUTLOG_PRECISE, KUTLOG_UNNORMALIZED, &error),
          "count = " + std::to_string(KUTLOG_MAX_COUNT + 1u) + " is out of range");
  refused(kutlog_lobe_eval_array(lobe.get(), t.data(), out.data(), SIZE_MAX, KUTLOG_PRECISE,
                                 KUTLOG_UNNORMALIZED, &error),
          "count = ");
  refused(kutlog_lobe_eval_array(nullptr, t.data(), out.data(), 16, KUTLOG_PRECISE,
                                 KUTLOG_UNNORMALIZED, &error),
          "lobe is NULL");
  refused(kutlog_lobe_eval_array(lobe.get(), t.data(), out.data(), 16, kutlog_variant(3),
                                 KUTLOG_UNNORMALIZED, &error),
          "variant = 3 is out of range");
  refused(kutlog_lobe_eval_array(lobe.get(), t.data(), out.data(), 16, KUTLOG_PRECISE,
                                 kutlog_normalization(-1), &error),
          "normalization = -1 is out of range");
  refused(kutlog_pow_u10(t.data(), nullptr, out.data(), 16, &error), "y is NULL");
  refused(kutlog_shade_cosines(lobe.get(), t.data(), nullptr, out.data(), 16, nullptr, nullptr,
                               &error),
          "n_dot_l is NULL");
  const kutlog_shade_options bad_reflection{KUTLOG_PRECISE, KUTLOG_UNNORMALIZED,
                                            kutlog_reflection(7), 1};
  refused(kutlog_shade_cosines(lobe.get(), t.data(), t.data(), out.data(), 16, nullptr,
                               &bad_reflection, &error),
          "options->reflection = 7");
  refused(kutlog_shade(lobe.get(), {t.data(), t.data(), t.data()}, {t.data(), nullptr, t.data()},
                       {t.data(), t.data(), t.data()}, out.data(), 16, nullptr, nullptr, &error),
          "to_light.y is NULL");
  std::vector<float> x(16), y(16), z(16);
  refused(kutlog_sampler_sample_array(nullptr, t.data(), t.data(), x.data(), y.data(), z.data(),
                                      out.data(), 16, KUTLOG_PRECISE, &error),
          "sampler is NULL");
  kutlog_fragment fragment;
  refused(kutlog_lobe_fragment(nullptr, KUTLOG_UNNORMALIZED, &fragment, &error), "lobe is NULL");
  refused(kutlog_lobe_fragment(lobe.get(), KUTLOG_UNNORMALIZED, nullptr, &error),
          "fragment is NULL");
  refused(kutlog_force_arch(nullptr, &error), "name is NULL");
  // The shade calls without n_dot_l where it is not read.
  const kutlog_shade_options alone{KUTLOG_PRECISE, KUTLOG_UNNORMALIZED, KUTLOG_REFLECT_BLINN, 0};
  EXPECT_EQ(kutlog_shade_cosines(lobe.get(), t.data(), nullptr, out.data(), 16, nullptr, &alone,
                                 &error),
            KUTLOG_OK);
}

// Values from NULL handles: NaN; a fragment never filled by a lobe (zeroed): NaN; destroying
// NULL: nothing.
TEST(CApi, NullHandlesGiveNaN) {
  EXPECT_TRUE(std::isnan(kutlog_lobe_coef_exact(nullptr)));
  EXPECT_TRUE(std::isnan(kutlog_lobe_t_cut(nullptr)));
  EXPECT_TRUE(std::isnan(kutlog_per_lane_lobe_eval(nullptr, 0.5f, 10, KUTLOG_PRECISE,
                                                   KUTLOG_UNNORMALIZED)));
  const kutlog_sample sample = kutlog_sampler_sample(nullptr, 0.5f, 0.5f, KUTLOG_PRECISE);
  EXPECT_TRUE(std::isnan(sample.x) && std::isnan(sample.y) && std::isnan(sample.z) &&
              std::isnan(sample.pdf));
  // A variant or normalization out of range, where the call returns a value: NaN too.
  const LobeHandle lobe = make_lobe(100, 3, 0.5);
  EXPECT_TRUE(std::isnan(kutlog_lobe_eval(lobe.get(), 0.5f, kutlog_variant(3),
                                          KUTLOG_UNNORMALIZED)));
  EXPECT_TRUE(std::isnan(kutlog_lobe_eval(lobe.get(), 0.5f, KUTLOG_DETERMINISTIC,
                                          kutlog_normalization(2))));
  EXPECT_FALSE(std::isnan(kutlog_lobe_eval(lobe.get(), 0.99f, KUTLOG_DETERMINISTIC,
                                           KUTLOG_UNNORMALIZED)));
  kutlog_sampler* sampler = nullptr;
  ASSERT_EQ(kutlog_sampler_create(100, 3, 0.5, KUTLOG_USE_PHONG, &sampler, nullptr), KUTLOG_OK);
  EXPECT_TRUE(std::isnan(kutlog_sampler_sample(sampler, 0.5f, 0.5f, kutlog_variant(-1)).pdf));
  EXPECT_FALSE(std::isnan(kutlog_sampler_sample(sampler, 0.5f, 0.5f, KUTLOG_DETERMINISTIC).pdf));
  kutlog_sampler_destroy(sampler);
  const kutlog_fragment zeroed{};
  EXPECT_TRUE(std::isnan(kutlog_eval(&zeroed, 0.5f)));
  const kutlog_fast_fragment zeroed_fast{};
  EXPECT_TRUE(std::isnan(kutlog_eval_fast(&zeroed_fast, 0.5f)));
  kutlog_lobe_destroy(nullptr);
  kutlog_per_lane_lobe_destroy(nullptr);
  kutlog_sampler_destroy(nullptr);
}

// The arch calls: C++'s names and messages.
TEST(CApi, ArchQueryAndForce) {
  kutlog_error error{};
  ASSERT_NE(kutlog_active_arch(&error), nullptr) << error.message;
  EXPECT_EQ(std::string(kutlog_active_arch(nullptr)), std::string(arch_name(active_arch())));
  EXPECT_EQ(kutlog_force_arch("mmx", &error), KUTLOG_INVALID_ARGUMENT);
  EXPECT_NE(std::string(error.message).find("unknown arch 'mmx'"), std::string::npos)
      << error.message;
  for (const Arch arch : kCompiledArchs) {
    const std::string name(arch_name(arch));
    EXPECT_EQ(kutlog_force_arch(name.c_str(), &error),
              arch_supported(arch) ? KUTLOG_OK : KUTLOG_UNSUPPORTED)
        << name << ": " << error.message;
    if (arch_supported(arch)) EXPECT_EQ(std::string(kutlog_active_arch(nullptr)), name);
  }
  kutlog_reset_arch();
  EXPECT_EQ(std::string(kutlog_active_arch(nullptr)), std::string(arch_name(active_arch())));
}

}  // namespace
}  // namespace kutlog

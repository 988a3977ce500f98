// kutlog/accuracy.hpp: the one table of accuracy bounds (SLEEF's model): the promise in each
// name, the measured maximum per platform; the tests assert both. How each column was
// measured: kMeasurements and docs/accuracy.md.
#pragma once

#include <optional>
#include <string_view>

#include "kutlog/api.hpp"
#include "kutlog/archs.hpp"
#include "kutlog/detail/math_functions.hpp"

KUTLOG_API_BEGIN
namespace kutlog {

// The platforms with a measured column, over the archs the registry has for each.
enum class Platform { x86_64, aarch64 };
inline constexpr Platform kPlatform =
#if defined(__aarch64__)
    Platform::aarch64;
#else
    Platform::x86_64;
#endif

struct PerPlatform {
  double x86_64, aarch64;
  constexpr double on(Platform platform) const {
    return platform == Platform::aarch64 ? aarch64 : x86_64;
  }
};

struct Measurement {
  Platform platform;
  std::string_view archs;
  std::string_view sweep;  // "exhaustive" (every float) or "sampled"
  std::string_view inputs;
  std::string_view command;
};
inline constexpr Measurement kMeasurements[] = {
    {Platform::x86_64, KUTLOG_ARCH_NAMES_X86_64, "exhaustive",
     "every float of each math kernel's domain, every float t of each lobe's support (below)",
     "kutlog-ulp --arch all --summary; ctest --test-dir build -L exhaustive"},
    {Platform::aarch64, KUTLOG_ARCH_NAMES_AARCH64, "sampled",
     "under qemu-aarch64 (KUTLOG_SWEEP_SAMPLES=2^24): 2^24 floats evenly spread over each "
     "math kernel's domain plus every float of its hardest ranges (tests/test_math_exhaustive.cpp); "
     "2^24 floats of t shared among the lobes of each sweep, over their supports and as many over "
     "their epicenters (tests/lobe_accuracy.hpp)",
     "KUTLOG_JOBS=1 GTEST_OUTPUT=xml:$PWD/build-aarch64/measured/ bash scripts/test-aarch64.sh "
     "-L exhaustive; "
     "python3 scripts/measured-bounds.py build-aarch64/measured"},
};

struct AccuracyBound {
  std::string_view kernel;  // the name in kutlog::simd and kutlog::math
  std::string_view function;
  std::string_view variant;  // "precise" or "fast"
  double promised_ulp;
  PerPlatform measured_ulp;
  std::string_view domain;
  // The floats the exhaustive sweep covers.
  float sweep_lo, sweep_hi;
  constexpr double max_ulp() const { return measured_ulp.on(kPlatform); }
};

// One row per kernel of kutlog/detail/math_functions.hpp.
inline constexpr AccuracyBound kAccuracyBounds[] = {
#define KUTLOG_ACCURACY_BOUND(function, kernel, promised, x86_64, aarch64, domain, lo, hi, ...) \
  {#kernel, #function, "precise", promised, {x86_64, aarch64}, domain, lo, hi},
    KUTLOG_MATH_FUNCTIONS(KUTLOG_ACCURACY_BOUND)
#undef KUTLOG_ACCURACY_BOUND
};

// The lobe kernels: abs error |out - scale F| / scale everywhere, ulps of scale F where F >= 0.6
// (docs/accuracy.md, "Lobe contract").
struct LobeBound {
  std::string_view variant;
  double promised_abs_error;
  PerPlatform measured_abs_error;
  double promised_epicenter_ulp;  // 0: no promise
  PerPlatform measured_epicenter_ulp;  // 0: not asserted
  constexpr double max_abs_error() const { return measured_abs_error.on(kPlatform); }
  constexpr double max_epicenter_ulp() const { return measured_epicenter_ulp.on(kPlatform); }
};
inline constexpr LobeBound kLobeBounds[] = {
    {"precise", 0x1p-22, {0x1p-22, 0x1p-22}, 2.0, {2.0, 2.0}},
    {"fast", 0x1p-16, {0x1p-16, 0x1p-16}, 0.0, {0.0, 0.0}},
    // PerLaneLobe: the epicenter bound is measured (4.63 ULP), not promised.
    {"per_lane", 0x1p-20, {0x1p-21, 0x1p-21}, 0.0, {5.0, 5.0}},
    {"per_lane_fast", 0x1p-16, {0x1p-17, 0x1p-17}, 0.0, {0.0, 0.0}},
};
// PerLaneLobe's normalized peak against coef_exact(n), relative: precise, and fast (its coef
// fitted to the fast variant's 2^-19).
inline constexpr double kPerLanePeakError = 0x1.8p-22;
inline constexpr double kPerLaneFastPeakError = 0x1p-18;

// The lobe sampler: theta_error in units of the support G, pdf_error relative to the peak
// pdf, phi_error in radians (docs/api-notes.md).
struct SamplerBound {
  double theta_error, pdf_error, phi_error;
};
inline constexpr SamplerBound kSamplerBound = {0x1p-21, 0x1p-21, 0x1.cp-23};

// The baselines: Schlick's four roundings (4 ULP); xsimd::pow within 5e-6 of the peak.
inline constexpr double kSchlickMaxUlp = 4.0;
inline constexpr double kBlinnPhongXsimdMaxAbsError = 5e-6;

// The bound of a kernel by function name ("acos", ...) and variant, if kutlog has one.
constexpr std::optional<AccuracyBound> find_accuracy_bound(std::string_view function,
                                                           std::string_view variant = "precise") {
  for (const AccuracyBound& bound : kAccuracyBounds)
    if (bound.function == function && bound.variant == variant) return bound;
  return std::nullopt;
}

}  // namespace kutlog
KUTLOG_API_END

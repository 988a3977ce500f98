// kutlog/accuracy.hpp: the one table of accuracy bounds of kutlog's kernels (SLEEF's model):
// the promise in each kernel's name (_u10: 1.0 ULP), and the maximal error measured on each
// platform over its archs, rounded up; the lobes' columns likewise (their aarch64 bounds are the
// x86 ones, which the sampled sweeps stay within). The tests assert both the promise and this
// platform's measured bound, so that neither can drift from the code; README's accuracy table
// is printed from here by kutlog-ulp --summary. How each column was measured: kMeasurements and
// docs/accuracy.md.
#pragma once

#include "kutlog/api.hpp"  // below C++20 its #error, and this header is empty
#if KUTLOG_HAS_CXX20

#include <optional>
#include <string_view>

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

// One value per platform; on() picks one.
struct PerPlatform {
  double x86_64, aarch64;
  constexpr double on(Platform platform) const {
    return platform == Platform::aarch64 ? aarch64 : x86_64;
  }
};

// How a platform's column was measured: the archs, the sweep (every float or a sample), its
// inputs, and the command that reruns it.
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

// A math kernel's row: promised_ulp, the contract in its name; measured_ulp, the maximum measured
// per platform, rounded up, max_ulp() that of the platform compiled for; the domain the bound
// holds on, as text; the floats the exhaustive sweep covers.
struct AccuracyBound {
  std::string_view kernel;  // the name in kutlog::simd and kutlog::math
  std::string_view function;
  std::string_view variant;  // "precise" or "fast"
  double promised_ulp;
  PerPlatform measured_ulp;
  std::string_view domain;
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

// The lobe kernels (kutlog/lobe.hpp), in the units of the value returned, out, against the exact
// scale F (scale = coef_exact when normalized, else 1): abs error |out - scale F| / scale,
// relative to the peak, everywhere; epicenter ulp, |out - scale F| in ulps of the float scale F,
// where F >= 0.6; and always 0 <= out <= peak (1, or the float coef: the output at t = 1), NaN
// for NaN (docs/accuracy.md, "Lobe contract"). Lobe's rows measured (tests/test_lobe.cpp, ctest
// -L exhaustive) on every arch of the platform over every float t of each lobe's support, and
// below its cut (where out must be an exact 0) every 61st float plus every float within 2^16 of
// the cut and of 0 (tools/common/lobe_errors.hpp), on the grid n in {k+1, 10, 100, 1000, 10000},
// k in 1..5, Q in {0.1, 0.5, 0.9}, and on random lobes (n log-uniform in [0.5, 10^6] and near k,
// k in 1..64, Q in [0.01, 0.99]), every float of each epicenter up to 2^24 of them, 2^21 of each
// support; on aarch64 sampled (kMeasurements).
struct LobeBound {
  std::string_view variant;
  double promised_abs_error;
  PerPlatform measured_abs_error;
  double promised_epicenter_ulp;  // 0: no promise
  PerPlatform measured_epicenter_ulp;  // 0: not asserted
  constexpr double max_abs_error() const { return measured_abs_error.on(kPlatform); }
  constexpr double max_epicenter_ulp() const { return measured_epicenter_ulp.on(kPlatform); }
};
// Lobe's variants, then PerLaneLobe's.
inline constexpr LobeBound kLobeBounds[] = {
    {"precise", 0x1p-22, {0x1p-22, 0x1p-22}, 2.0, {2.0, 2.0}},
    {"fast", 0x1p-16, {0x1p-16, 0x1p-16}, 0.0, {0.0, 0.0}},
    // PerLaneLobe, on random (t, n) lanes of the materials of tests/lobe_accuracy.hpp: a grid,
    // extremes, and random k in 1..64, Q from 10^-6 to 1 - 5 10^-7, n_min log-uniform in
    // [k, 10^30], n_max up to 10^12 n_min and FLT_MAX. The epicenter bound is what was measured
    // (4.63 ULP, from c^2, theta^2, the base and coef, each fitted within 2^-23, and at k = 2 to 5
    // the power's own roundings in float), not a promise.
    {"per_lane", 0x1p-20, {0x1p-21, 0x1p-21}, 0.0, {5.0, 5.0}},
    // Variant::fast, on the same lanes: 2^-18.2 measured (every fit within 2^-19, the power in
    // float), asserted within 2^-17.
    {"per_lane_fast", 0x1p-16, {0x1p-17, 0x1p-17}, 0.0, {0.0, 0.0}},
};
// PerLaneLobe's normalized peak, its output at t = 1, against coef_exact(n), relative: from
// coef's fit within 2^-23 and the float product n K(y) (measured 2^-22.08 on SSE4.1, 2^-22.32
// with FMA). The peak bounds every output of the lane, so this keeps out <= coef (1 + it).
inline constexpr double kPerLanePeakError = 0x1.8p-22;
// The same for Variant::fast, whose coef is fitted within 2^-19 (measured 2^-19.04 with FMA).
inline constexpr double kPerLaneFastPeakError = 0x1p-18;

// The lobe sampler (kutlog/sampling.hpp), on every arch, measured by
// tests/test_lobe_sampler.cpp over dense u1 sweeps (2^14 evenly spaced, tiny ones, the 4096
// floats below 1) on the grid n in {k+1, 10, 100, 1000, 10^4}, k in {1, 3, 5},
// Q in {0.1, 0.5, 0.9}, both uses, and on random lobes (n log-uniform in [0.5, 10^6], k in
// 1..64, Q in [0.01, 0.99]):
//   theta_error: |theta - inverse_cdf(u1)| / G, theta the angle of the returned direction from
//     z, G the lobe's support. Absolute in units of G, not ULP: the density varies on the scale
//     G, so an error of e G moves each sample by at most e of the lobe's width, what a
//     chi-square test at any resolution of the lobe sees (and near theta = 0, where the ULP of
//     theta shrinks, the density's own scale does not).
//   pdf_error: |pdf - pdf_ref(direction)| / peak, pdf_ref the reference's solid-angle density
//     of the returned direction, peak the pdf at theta = 0.
//   phi_error: the angle between the returned direction's (x, y) and (cos, sin)(2 pi u2), in
//     radians (measured 1.24e-7 on AVX-512's batches, 1.26e-7 on the other archs and one per
//     call: the float roundings of the azimuth's sin and cos cores).
struct SamplerBound {
  double theta_error, pdf_error, phi_error;
};
inline constexpr SamplerBound kSamplerBound = {0x1p-21, 0x1p-21, 0x1.cp-23};

// The baselines of kutlog/baselines.hpp, which are not kutlog's kernels. Schlick's
// t / (n - n t + t) rounds four times (three with FMA), each by half an ulp at most: within
// 4 ULP (the fuzz target found 2.35 on SSE4.1 at n = 1e5; tests/test_lobe.cpp sees 2 at most on
// its grid).
inline constexpr double kSchlickMaxUlp = 4.0;
// scale t^n with xsimd::pow (67 to 86 ULP at large n, and subnormal results flushed to 0): within
// 5e-6 of the peak, relative to scale, as measured.
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

#endif  // KUTLOG_HAS_CXX20

// kutlog/accuracy.hpp: the one table of accuracy bounds of kutlog's kernels (SLEEF's model).
//
// `promised_ulp` is the contract in the kernel's name (_u10: 1.0 ULP). `max_ulp` is the
// maximal error measured over every float of `domain` on every arch (kutlog-ulp --arch all),
// rounded up: the tests assert both, so neither can drift from the code. README's accuracy
// table is printed from here by kutlog-ulp --bounds.
#pragma once

#include <optional>
#include <string_view>

namespace kutlog {

struct AccuracyBound {
  std::string_view kernel;  // the name in kutlog::simd and kutlog::math
  std::string_view function;
  std::string_view variant;  // "precise" or "fast"
  double promised_ulp;
  double max_ulp;
  std::string_view domain;
};

inline constexpr AccuracyBound kAccuracyBounds[] = {
    {"acos_u10", "acos", "precise", 1.0, 0.65, "[-1, 1]"},
    {"cos_u10", "cos", "precise", 1.0, 0.81, "[-pi, pi]"},
    {"cos_halfpi_u10", "cos_halfpi", "precise", 1.0, 0.81, "[0, pi/2]"},
    {"exp_u10", "exp", "precise", 1.0, 0.51, "[-104, 89] (0 or inf beyond)"},
    {"log_u10", "log", "precise", 1.0, 0.67, "(0, inf)"},
    {"pow_u10", "pow", "precise", 1.0, 0.54,
     "x in (0, 2^8], y in {1, 2, 5, 10, 50, 100, 500, 1000, 5000}; 10^7 random (x, y)"},
};

// The lobe kernels of kutlog::Lobe (kutlog/lobe.hpp): promised and measured, over every float
// t in [-1, 1] on the grid n in {k+1, 10, 100, 1000, 10000}, k in 1..5, Q in {0.1, 0.5, 0.9},
// every arch, F and coef * F (the latter relative to coef).
struct LobeBound {
  std::string_view variant;
  double promised_abs_error, max_abs_error;
  double promised_epicenter_ulp, max_epicenter_ulp;  // where F >= 0.6; 0: no promise
};
inline constexpr LobeBound kLobeBounds[] = {
    {"precise", 0x1p-22, 0x1p-22, 2.0, 2.0},
    {"fast", 0x1p-16, 0x1p-16, 0.0, 0.0},
    // kutlog::PerLaneLobe, on random (t, n), n in [k + 1, 10^4] (tests/test_lobe.cpp); the
    // epicenter bound is what was measured (B^k amplifies B's error k times), not a promise.
    {"per_lane", 0x1p-20, 0x1p-20, 0.0, 8.0},
};

// The baselines of kutlog/lobe.hpp, which are not kutlog's kernels. Schlick's t / (n - n t + t)
// rounds four times (three with FMA), each by half an ulp at most: within 4 ULP (the fuzz
// target found 2.35 on SSE4.1 at n = 1e5; tests/test_lobe.cpp sees 2 at most on its grid).
// scale * t^n with xsimd::pow (67 to 86 ULP at large n, and subnormal results flushed to 0):
// within 5e-6 of the peak, relative to scale, as measured.
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

// Accuracy of the lobe kernels of a kutlog::Lobe against the scalar reference, over the floats
// t in [-1, 1], shared by kutlog-ulp and the tests.
#pragma once

#include <array>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <limits>

#include "kutlog/accuracy.hpp"
#include "kutlog/lobe.hpp"

namespace kutlog::tools {

// PerLaneLobe's promise for its normalized peak against coef_exact(n) (kutlog/accuracy.hpp).
constexpr double per_lane_peak_bound(Variant variant) {
  return variant == Variant::fast ? kPerLaneFastPeakError : kPerLanePeakError;
}

// Errors of the value returned, out, against the exact scale * F (scale = coef when
// normalized, else 1): kutlog/accuracy.hpp's units.
struct LobeErrors {
  double max_abs_error = 0;      // |out - scale F| / scale: relative to the peak
  double max_epicenter_ulp = 0;  // |out - scale F| in ulps of the float scale F, where F >= 0.6
  float worst_abs_input = std::numeric_limits<float>::quiet_NaN();
  float worst_ulp_input = std::numeric_limits<float>::quiet_NaN();
  // The hard contract 0 <= out <= peak (the output at t = 1), over every non-NaN output.
  float min_output = std::numeric_limits<float>::infinity();
  float max_output = -std::numeric_limits<float>::infinity();
  float min_output_input = std::numeric_limits<float>::quiet_NaN();
  float max_output_input = std::numeric_limits<float>::quiet_NaN();
  // Where F = 0 (at and below the cut-off) the output must be an exact 0: the largest |out|
  // there (NaN counts as infinite), and where.
  float max_where_zero = 0;
  float max_where_zero_input = std::numeric_limits<float>::quiet_NaN();
  std::uint64_t inputs = 0;

  // Records one output; NaN errors count as the worst.
  void add(float t, float out, double scale, double expected);
  void merge(const LobeErrors& other);
};

// |out - scale F| / scale, the error relative to the peak. NaN stays NaN.
inline double lobe_abs_error(float out, double scale, double expected) {
  return std::fabs(double(out) - scale * expected) / scale;
}

// The kernels in the order variant x normalization: precise, precise * coef, fast, fast * coef,
// deterministic, deterministic * coef.
inline constexpr Variant kLobeVariants[] = {Variant::precise, Variant::fast,
                                            Variant::deterministic};
inline constexpr Normalization kLobeNormalizations[] = {Normalization::none,
                                                        Normalization::exact_coef};
// The variants with kernels of their own: deterministic runs precise's unfused ones.
inline constexpr Variant kFittedVariants[] = {Variant::precise, Variant::fast};
inline constexpr std::size_t kLobeKernels = std::size(kLobeVariants) * std::size(kLobeNormalizations);
using LobeKernelErrors = std::array<LobeErrors, kLobeKernels>;
// The bound of kutlog/accuracy.hpp a variant promises: deterministic promises precise's.
inline const LobeBound& lobe_bound_of(Variant variant) {
  return kLobeBounds[variant == Variant::fast ? 1 : 0];
}

// Which floats t a sweep takes: every `support_stride`-th float of the support (t above the
// cut) outside the epicenter, every `epicenter_stride`-th inside it (F >= 0.6); 1: every float.
// Below the cut, where the reference is 0 and the kernels decide by one comparison: every
// `below_cut_stride`-th float (by default every (61 support_stride)-th) plus every float
// within 2^16 of the cut and of 0. There the kernels must give exactly 0. And every float
// within 2^16 / support_stride (at least 2^10) above the cut and below 1, where the output
// meets 0 and the peak, and within 2^12 of each SIMD kernel's own cut (the clamps there are
// dropped where the setup proves them needless, the cut raised: kutlog/lobe.hpp).
struct LobeSweep {
  std::uint32_t support_stride = 1, epicenter_stride = 1;
  std::uint32_t below_cut_stride = 61 * support_stride;
};

// How a lobe's kernel is called on `count` floats: the array functions (dispatched to the
// active arch) or, in the tests, the scalar per-fragment eval compiled with the test's flags.
using LobeEvaluator = void (*)(const Lobe& lobe, Variant variant, Normalization normalization,
                               const float* t, float* out, std::size_t count);
void evaluate_array(const Lobe& lobe, Variant variant, Normalization normalization,
                    const float* t, float* out, std::size_t count);

// The floats of the sweep through `evaluate`, against the reference (computed once, for the
// kernels of kLobeVariants).
LobeKernelErrors measure_lobe(const Lobe& lobe, LobeSweep sweep = {},
                                       LobeEvaluator evaluate = evaluate_array,
                                       unsigned threads = 0);

// The float t where the reference lobe falls to 0.6, the epicenter's edge (0 when it is
// beyond the horizon).
double epicenter_edge(const Lobe& lobe);

}  // namespace kutlog::tools

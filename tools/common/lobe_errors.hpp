// Accuracy of the lobe kernels of a kutlog::Lobe against the scalar reference, over the floats
// t in [-1, 1], shared by kutlog-ulp and the tests.
#pragma once

#include <array>
#include <cmath>
#include <cstdint>
#include <limits>

#include "kutlog/lobe.hpp"

namespace kutlog::tools {

// Normalized results are measured relative to coef: e = |out / scale - F| (scale = coef when
// normalized, else 1).
struct LobeErrors {
  double max_abs_error = 0;      // e
  double max_epicenter_ulp = 0;  // e in ulps of F (float), where F >= 0.6
  float worst_abs_input = std::numeric_limits<float>::quiet_NaN();
  float worst_ulp_input = std::numeric_limits<float>::quiet_NaN();
  std::uint64_t inputs = 0;
};

// One output of a lobe kernel against the reference F: |out / scale - F|, and that error in ulps
// of the float F (its binade's ulp), the unit of the epicenter bound. NaN errors stay NaN.
inline double lobe_abs_error(float out, double scale, double expected) {
  return std::fabs(double(out) / scale - expected);
}
inline double epicenter_ulps(double abs_error, double expected) {
  return abs_error / std::ldexp(1.0, std::ilogb(expected) - 23);
}

// The kernels in the order variant x normalization: precise, precise * coef, fast, fast * coef.
inline constexpr Variant kLobeVariants[] = {Variant::precise, Variant::fast};
inline constexpr Normalization kLobeNormalizations[] = {Normalization::none,
                                                        Normalization::exact_coef};

// The floats t in [-1, 1] through lobe.eval on the active arch, against the reference
// (computed once, for the four kernels): every `stride`-th float of the support (t above the
// cut; stride 1: every float), and below it, where the reference is 0 and the kernels decide
// by one comparison, every (61 stride)-th float plus every float within 2^16 of the cut and of
// 0. There the kernels must give exactly 0.
std::array<LobeErrors, 4> measure_lobe(const Lobe& lobe, std::uint32_t stride = 1,
                                       unsigned threads = 0);

}  // namespace kutlog::tools

// The deterministic mode's scalar side (Variant::deterministic, kutlog/lobe.hpp): Lobe's one
// fragment, and the run of an unfused kernel's epicenter at setup (src/epicenter_check.hpp), by
// the loops every arch runs in that mode, instantiated here on the portable arch
// (kutlog/simd/detail/portable.hpp) with the baseline flags: no dispatch table, and the bits
// of every arch's deterministic loops (tests/test_deterministic.cpp). PerLaneLobe's one
// fragment does the same in src/per_lane_lobe.cpp.
#include "arch/epicenter_loops.hpp"
#include "arch/lobe_loops.hpp"
#include "epicenter_check.hpp"
#include "kutlog/lobe.hpp"

namespace kutlog {

namespace {
using Portable = simd::portable;

// The portable arch's deterministic loop for any unfused kernel: its degree in a loop (the
// same operations as an unrolled slot's), clamped (where the setup dropped a kernel's clamp it
// proved the output within it: the same bits).
using DeterministicLobe = simd::PreparedLobe<Portable, -1, simd::LobeFinish::any, true, true>;
constexpr detail::LobeArrayKernel kDeterministicLoop =
    &detail::kutlog_lobe_loop<Portable, -1, simd::LobeFinish::any, true, true>;
}  // namespace

float Lobe::eval_deterministic(float t, Normalization normalization) const noexcept {
  const detail::LobeKernel& kernel =
      kernels_[kernel_index(Variant::deterministic, normalization, detail::Arithmetic::unfused)];
  // The loop's kernel on t in every lane: the loop's partial batch costs as much again.
  return DeterministicLobe(kernel)(simd::floats<Portable>(t)).get(0);
}

detail::EpicenterLoops detail::unfused_epicenter_loops() {
  return {kDeterministicLoop, &epicenter_worst_ulp<Portable>};
}

}  // namespace kutlog

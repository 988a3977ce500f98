// kutlog/detail/lobe_dispatch.hpp: the per-arch tables of lobe loops that Lobe's inline array
// eval reads (filled by src/arch/lobe_loops.hpp; the active one is Lobe::active_loops_, set by
// src/dispatch.cpp).
#pragma once

#include "kutlog/api.hpp"  // below C++20 its #error, and this header is empty
#if KUTLOG_HAS_CXX20

#include <atomic>
#include <cstddef>

#include "kutlog/detail/lobe_kernel.hpp"

KUTLOG_API_BEGIN
namespace kutlog {

namespace detail {
// One array loop of a lobe kernel: out[i] = F(t[i]) over count floats.
using LobeArrayKernel = void (*)(const LobeKernel&, const float*, float*, std::size_t);
// One arch's lobe loops, by slot: for the polynomial form of each degree up to
// kMaxArrayUnrolledDegree, one per finish (plain, split, compensated: simd::LobeFinish), then plain
// and split without the clamp (LobeKernel::clamped; compensated kernels keep it), unrolled and
// testing no flag; in the last slot, one for any kernel. A Lobe computes its kernels' slots at
// setup, so that a call picks its loop with one load. FMA-less archs are never given a
// compensated kernel: Lobe keeps those for Arithmetic::fused. deterministic_by_slot, the same
// slots for Variant::deterministic, runs unfused kernels unfused (on FMA-less archs, the same
// loops). Filled per arch by src/arch/lobe_loops.hpp; here because Lobe's array eval reads it
// inline.
struct LobeArrayKernels {
  static constexpr int kMaxArrayUnrolledDegree = 16;
  static constexpr int kSlotsPerDegree = 5;
  static constexpr int kSlots = kSlotsPerDegree * (kMaxArrayUnrolledDegree + 1) + 1;
  bool fused_fma;  // which of a Lobe's kernels this arch runs
  LobeArrayKernel by_slot[kSlots];
  LobeArrayKernel deterministic_by_slot[kSlots];
  static constexpr int slot_of(const LobeKernel& kernel) {
    if (kernel.form != LobeKernel::Form::polynomial || kernel.degree > kMaxArrayUnrolledDegree)
      return kSlots - 1;
    const int finish = kernel.compensated ? 2 : kernel.scale_lo != 0 ? 1 : 0;
    return kSlotsPerDegree * kernel.degree + (kernel.clamped || finish == 2 ? finish : 3 + finish);
  }
  LobeArrayKernel of(const LobeKernel& kernel, bool deterministic) const {
    return (deterministic ? deterministic_by_slot : by_slot)[slot_of(kernel)];
  }
};
}  // namespace detail

}  // namespace kutlog
KUTLOG_API_END

#endif  // KUTLOG_HAS_CXX20

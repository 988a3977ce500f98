// The kernels of one arch as a table of function pointers; src/dispatch.cpp picks the table.
#pragma once

#include <cstddef>

#include "kutlog/dispatch.hpp"
#include "kutlog/lobe.hpp"
#include "kutlog/sampling.hpp"
#include "kutlog/shade.hpp"

namespace kutlog::detail {

using UnaryArrayKernel = void (*)(const float*, float*, std::size_t);
using BinaryArrayKernel = void (*)(const float*, const float*, float*, std::size_t);
using BinaryScalarArrayKernel = void (*)(const float*, float, float*, std::size_t);

using LobeArrayKernel = void (*)(const LobeKernel&, const float*, float*, std::size_t);
// The lobe's array loops, by slot: for the polynomial form of each degree up to
// kMaxUnrolledDegree, one per finish (plain, split, compensated: simd::LobeFinish), then
// plain and split without the clamp (LobeKernel::clamped; compensated kernels keep it),
// unrolled and testing no flag; in the last slot, one for any kernel. A Lobe computes its
// kernels' slots at setup, so that a call picks its loop with one load. (FMA-less archs are
// never given a compensated kernel: Lobe keeps those for Arithmetic::fused.)
struct LobeArrayKernels {
  static constexpr int kMaxUnrolledDegree = 16;
  static constexpr int kSlotsPerDegree = 5;
  static constexpr int kSlots = kSlotsPerDegree * (kMaxUnrolledDegree + 1) + 1;
  LobeArrayKernel by_slot[kSlots];
  static constexpr int slot_of(const LobeKernel& kernel) {
    if (kernel.form != LobeKernel::Form::polynomial || kernel.degree > kMaxUnrolledDegree)
      return kSlots - 1;
    const int finish = kernel.compensated ? 2 : kernel.scale_lo != 0 ? 1 : 0;
    return kSlotsPerDegree * kernel.degree + (kernel.clamped || finish == 2 ? finish : 3 + finish);
  }
  LobeArrayKernel of(const LobeKernel& kernel) const { return by_slot[slot_of(kernel)]; }
};
using PowerLobeArrayKernel = void (*)(const float*, float n, float scale, float*, std::size_t);

using ShadeVectorsKernel = void (*)(const LobeKernel&, const ShadeOptions&, Vectors, Vectors,
                                    Vectors, float*, std::size_t, const std::uint8_t*);
using ShadeDirectionsKernel = void (*)(const LobeKernel&, const ShadeOptions&, Vectors, Direction,
                                       Direction, float*, std::size_t, const std::uint8_t*);
using ShadeCosinesKernel = void (*)(const LobeKernel&, const ShadeOptions&, const float*,
                                    const float*, float*, std::size_t, const std::uint8_t*);

using PerLaneArrayKernel = void (*)(const PerLaneKernel&, bool normalized, const float*,
                                    const float*, float*, std::size_t);

using SampleArrayKernel = void (*)(const SamplerKernel&, const float* u1, const float* u2,
                                   DirectionSamples, std::size_t);
using SampleOneKernel = SampledDirection (*)(const SamplerKernel&, float u1, float u2);

struct KernelTable {
  bool fused_fma;  // which of a Lobe's kernels this arch runs
  UnaryArrayKernel acos_u10, cos_u10, cos_halfpi_u10, exp_u10, log_u10;
  BinaryArrayKernel pow_u10;
  BinaryScalarArrayKernel pow_scalar_u10;
  LobeArrayKernels kutlog_lobe;
  PerLaneArrayKernel kutlog_per_lane;
  PowerLobeArrayKernel blinn_phong_xsimd, blinn_phong_u10;
  BinaryScalarArrayKernel schlick;
  ShadeVectorsKernel shade_vectors;
  ShadeDirectionsKernel shade_directions;
  ShadeCosinesKernel shade_cosines;
  SampleArrayKernel sample_lobe;
  SampleOneKernel sample_one;
};

// The table of one arch: specialized by src/arch/kernels.cpp, which CMake compiles once per
// arch of the registry with only that arch's flags.
template <Arch arch>
const KernelTable& kernel_table();

}  // namespace kutlog::detail

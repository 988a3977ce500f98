// The kernels of one arch as a table of function pointers; src/dispatch.cpp picks the table.
#pragma once

#include <cstddef>

#include "kutlog/dispatch.hpp"
#include "kutlog/detail/math_functions.hpp"
#include "kutlog/lobe.hpp"
#include "kutlog/sampling.hpp"
#include "kutlog/shade.hpp"

namespace kutlog::detail {

using UnaryArrayKernel = void (*)(const float*, float*, std::size_t);
using BinaryArrayKernel = void (*)(const float*, const float*, float*, std::size_t);
using BinaryScalarArrayKernel = void (*)(const float*, float, float*, std::size_t);

using PowerLobeArrayKernel = void (*)(const float*, float n, float scale, float*, std::size_t);

using ShadeVectorsKernel = void (*)(const detail::LobeKernel&, const ShadeOptions&, Vectors, Vectors,
                                    Vectors, float*, std::size_t, const std::uint8_t*);
using ShadeDirectionsKernel = void (*)(const detail::LobeKernel&, const ShadeOptions&, Vectors, Direction,
                                       Direction, float*, std::size_t, const std::uint8_t*);
using ShadeCosinesKernel = void (*)(const detail::LobeKernel&, const ShadeOptions&, const float*,
                                    const float*, float*, std::size_t, const std::uint8_t*);

using PowerPolyArrayKernel = void (*)(const detail::PowerPolyKernel&, const float*, float*, std::size_t);
using PerLanePowerPolyArrayKernel = void (*)(const detail::PerLanePowerPolyKernel&, const float*,
                                             const float*, float*, std::size_t);

using PerLaneArrayKernel = void (*)(const detail::PerLaneKernel&, bool normalized, const float*,
                                    const float*, float*, std::size_t);

using SampleArrayKernel = void (*)(const detail::SamplerKernel&, const float* u1, const float* u2,
                                   DirectionSamples, std::size_t);
using SampleOneKernel = SampledDirection (*)(const detail::SamplerKernel&, float u1, float u2);

// The reference of src/epicenter_check.hpp's sweep: scale - (1 - t) p(center - t), p's
// coefficients c[0..degree] in double, and the bound on its own error.
struct EpicenterReference {
  const double* coefficients;
  int degree;
  double center, scale, error;
};
using EpicenterSweepKernel = double (*)(const EpicenterReference&, const float* t,
                                        const float* out, std::size_t);

// A LobeArrayKernels first (its fused_fma: which of a Lobe's kernels this arch runs), so that
// the active table is what detail::active_lobe_loops points to (kutlog/lobe.hpp).
struct KernelTable : LobeArrayKernels {
#define KUTLOG_UNARY_SLOT(function, kernel, ...) UnaryArrayKernel kernel;
#define KUTLOG_BINARY_SLOTS(function, kernel, ...) \
  BinaryArrayKernel kernel;                       \
  BinaryScalarArrayKernel kernel##_scalar;
  KUTLOG_UNARY_MATH_FUNCTIONS(KUTLOG_UNARY_SLOT)
  KUTLOG_BINARY_MATH_FUNCTIONS(KUTLOG_BINARY_SLOTS)
#undef KUTLOG_UNARY_SLOT
#undef KUTLOG_BINARY_SLOTS
  PerLaneArrayKernel kutlog_per_lane;
  PowerLobeArrayKernel blinn_phong_xsimd, blinn_phong_u10;
  PowerPolyArrayKernel power_poly;
  PerLanePowerPolyArrayKernel per_lane_power_poly;
  BinaryScalarArrayKernel schlick;
  ShadeVectorsKernel shade_vectors;
  ShadeDirectionsKernel shade_directions;
  ShadeCosinesKernel shade_cosines;
  SampleArrayKernel sample_lobe;
  SampleOneKernel sample_one;
  EpicenterSweepKernel epicenter_worst_ulp;
  // Whether simd::mul_add rounds once on this arch, as measured (tests/test_cpu_features.cpp).
  bool (*mul_add_rounds_once)();
};

// The table of one arch: specialized by src/arch/kernels.cpp, which CMake compiles once per
// arch of the registry with only that arch's flags.
template <Arch arch>
const KernelTable& kernel_table();

}  // namespace kutlog::detail

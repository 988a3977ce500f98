// The kernels of one arch as a table of function pointers; src/dispatch.cpp picks the table.
#pragma once

#include <cstddef>
#include <cstdint>
#include <type_traits>

#include "kutlog/dispatch.hpp"
#include "kutlog/detail/math_functions.hpp"
#include "kutlog/lobe.hpp"
#include "kutlog/sampling.hpp"
#include "kutlog/shade.hpp"

namespace kutlog::detail {

using UnaryArrayKernel = void (*)(const float*, float*, std::size_t);
using BinaryArrayKernel = void (*)(const float*, const float*, float*, std::size_t);
using BinaryScalarArrayKernel = void (*)(const float*, float, float*, std::size_t);

// The reference of src/epicenter_check.hpp's sweep: scale - (1 - t) p(center - t), p's
// coefficients c[0..degree] in double, and the bound on its own error.
struct EpicenterReference {
  const double* coefficients;
  int degree;
  double center, scale, error;
};

// The one list of dispatched entries past the math kernels (whose list is
// kutlog/detail/math_functions.hpp) and the lobes' slots (LobeArrayKernels):
// X(entry, loop, signature), the loop a function template on the xsimd arch in src/arch/ of
// that signature. The table's field, its fill per arch and the call through
// active_table().entry all come from here (docs/design.md, "Dispatch").
#define KUTLOG_ARRAY_ENTRIES(X)                                                                   \
  X(per_lane_lobe, per_lane_array,                                                               \
    void(const PerLaneKernel&, bool normalized, bool deterministic, const float* t,             \
         const float* n, float* out, std::size_t count))                                         \
  X(blinn_phong_xsimd, blinn_phong_xsimd_array,                                                  \
    void(const float* t, float n, float scale, float* out, std::size_t count))                  \
  X(blinn_phong_u10, blinn_phong_u10_array,                                                      \
    void(const float* t, float n, float scale, float* out, std::size_t count))                  \
  X(schlick, schlick_array, void(const float* t, float n, float* out, std::size_t count))       \
  X(power_poly, power_poly_array,                                                                \
    void(const PowerPolyKernel&, const float* t, float* out, std::size_t count))                \
  X(per_lane_power_poly, per_lane_power_poly_array,                                              \
    void(const PerLanePowerPolyKernel&, const float* t, const float* n, float* out,             \
         std::size_t count))                                                                     \
  X(shade_vectors, shade_vectors_array,                                                          \
    void(const LobeKernel&, const ShadeOptions&, Vectors, Vectors, Vectors, float*, std::size_t, \
         const std::uint8_t*))                                                                   \
  X(shade_directions, shade_directions_array,                                                    \
    void(const LobeKernel&, const ShadeOptions&, Vectors, Direction, Direction, float*,          \
         std::size_t, const std::uint8_t*))                                                      \
  X(shade_cosines, shade_cosines_array,                                                          \
    void(const LobeKernel&, const ShadeOptions&, const float*, const float*, float*,            \
         std::size_t, const std::uint8_t*))                                                      \
  X(sample_lobe, sample_lobe_array,                                                              \
    void(const SamplerKernel&, bool deterministic, const float* u1, const float* u2,           \
         DirectionSamples, std::size_t count))                                                   \
  X(sample_one, sample_one, SampledDirection(const SamplerKernel&, float u1, float u2))         \
  X(epicenter_worst_ulp, epicenter_worst_ulp,                                                    \
    double(const EpicenterReference&, const float* t, const float* out, std::size_t count))     \
  /* Whether simd::mul_add rounds once on this arch, as measured (test_cpu_features.cpp). */   \
  X(mul_add_rounds_once, mul_add_rounds_once, bool())

// A LobeArrayKernels first (its fused_fma: which of a Lobe's kernels this arch runs), so that
// the active table is what Lobe::active_loops_ points to (kutlog/lobe.hpp).
struct KernelTable : LobeArrayKernels {
#define KUTLOG_UNARY_SLOT(function, kernel, ...) UnaryArrayKernel kernel;
#define KUTLOG_BINARY_SLOTS(function, kernel, ...) \
  BinaryArrayKernel kernel;                       \
  BinaryScalarArrayKernel kernel##_scalar;
#define KUTLOG_ENTRY_SLOT(entry, loop, signature) std::add_pointer_t<signature> entry;
  KUTLOG_UNARY_MATH_FUNCTIONS(KUTLOG_UNARY_SLOT)
  KUTLOG_BINARY_MATH_FUNCTIONS(KUTLOG_BINARY_SLOTS)
  KUTLOG_ARRAY_ENTRIES(KUTLOG_ENTRY_SLOT)
#undef KUTLOG_UNARY_SLOT
#undef KUTLOG_BINARY_SLOTS
#undef KUTLOG_ENTRY_SLOT
};

// The table of one arch: specialized by src/arch/kernels.cpp, which CMake compiles once per
// arch of the registry with only that arch's flags.
template <Arch arch>
const KernelTable& kernel_table();

}  // namespace kutlog::detail

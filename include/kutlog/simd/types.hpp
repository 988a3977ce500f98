// kutlog/simd/types.hpp: the batch types the kernels and the per-arch files of
// kutlog/simd/arch/ share.
#pragma once

#include "kutlog/api.hpp"  // below C++20 its #error, and this header is empty
#if KUTLOG_HAS_CXX20

#include <cstdint>
#include <type_traits>

#include "kutlog/archs.hpp"
#include "kutlog/simd/xsimd.hpp"

namespace kutlog::simd {

// The batches of float, double and int32 lanes of an xsimd arch.
template <class Arch>
using floats = xsimd::batch<float, Arch>;
template <class Arch>
using doubles = xsimd::batch<double, Arch>;
template <class Arch>
using ints = xsimd::batch<std::int32_t, Arch>;

// True when mul_add (kutlog/simd/float_ops.hpp) is one fused instruction (one rounding) for
// this arch, as the arch registry's FUSED_FMA field says (cmake/KutlogArchs.cmake) for the
// entry whose xsimd type Arch is or derives from; elsewhere two roundings, and the kernels
// take the FMA-free paths.
template <class Arch>
inline constexpr bool has_fused_fma = false
#define KUTLOG_FUSED_FMA_OF(id, name, xsimd_arch, cpu_features, fused_fma) \
  || (fused_fma && std::is_base_of_v<xsimd_arch, Arch>)
    KUTLOG_ARCHS(KUTLOG_FUSED_FMA_OF);
#undef KUTLOG_FUSED_FMA_OF

// A value held as an unevaluated sum hi + lo, |lo| <= ulp(hi) / 2.
template <class Batch>
struct Pair {
  Batch hi, lo;
  // By value, into registers: with the aggregate's member-wise copy GCC 12 left a dead store
  // of each half to the stack in the loops, and realigned the stack of every call for them.
  Pair(Batch high, Batch low) : hi(high), lo(low) {}
};

}  // namespace kutlog::simd

#endif  // KUTLOG_HAS_CXX20

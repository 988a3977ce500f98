// kutlog/simd/arch.hpp: the xsimd arch type of each kutlog::Arch (from the arch registry), for
// code that instantiates the kernels of kutlog/simd/ once per arch as the library does.
#pragma once

#include "kutlog/api.hpp"  // below C++20 its #error, and this header is empty
#if KUTLOG_HAS_CXX20

#include "kutlog/dispatch.hpp"
#include "kutlog/simd/xsimd.hpp"

namespace kutlog::simd {

template <Arch arch>
struct XsimdArchOf;
#define KUTLOG_XSIMD_ARCH_OF(id, name, xsimd_arch_type, ...)          \
  template <>                                                          \
  struct XsimdArchOf<Arch::id> {                                       \
    using type = xsimd_arch_type;                                      \
  };
KUTLOG_ARCHS(KUTLOG_XSIMD_ARCH_OF)
#undef KUTLOG_XSIMD_ARCH_OF

// xsimd_arch<Arch::avx2> is xsimd::fma3<xsimd::avx2>.
template <Arch arch>
using xsimd_arch = typename XsimdArchOf<arch>::type;

}  // namespace kutlog::simd

#endif  // KUTLOG_HAS_CXX20

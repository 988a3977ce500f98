// kutlog/simd/arch/portable.hpp: what the kernels do their own way on the portable arch
// (kutlog::simd::portable, defined in kutlog/simd/detail/portable.hpp), as overloads on its
// tag (kutlog/simd/arch/avx512.hpp says how): 4 float lanes, 2 double lanes.
#pragma once

#include "kutlog/api.hpp"  // below C++20 its #error, and this header is empty
#if KUTLOG_HAS_CXX20

#include <cstddef>

#include "kutlog/simd/types.hpp"

namespace kutlog::simd::ops {

using portable_tag = xsimd::kernel::requires_arch<portable>;

// Lane by lane, each conversion correctly rounded.
template <class Arch>
inline Pair<doubles<Arch>> widen(floats<Arch> x, portable_tag) {
  constexpr std::size_t half = doubles<Arch>::size;
  typename doubles<Arch>::register_type low, high;
  for (std::size_t i = 0; i < half; ++i)
    low[i] = double(x.data[i]), high[i] = double(x.data[half + i]);
  return {doubles<Arch>(low), doubles<Arch>(high)};
}
template <class Arch>
inline floats<Arch> narrow(doubles<Arch> low, doubles<Arch> high, portable_tag) {
  constexpr std::size_t half = doubles<Arch>::size;
  typename floats<Arch>::register_type v;
  for (std::size_t i = 0; i < half; ++i)
    v[i] = float(low.data[i]), v[half + i] = float(high.data[i]);
  return v;
}

}  // namespace kutlog::simd::ops

#endif  // KUTLOG_HAS_CXX20

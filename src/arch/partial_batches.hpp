// The first `count` lanes of an array as a batch, and their store, without touching memory
// past them: the tail of every array loop, each arch's way (kutlog/simd/arch/): AVX-512 under
// a lane mask, AVX2 loads under one and stores by halves, SSE4.1 by halves, the others
// through a local buffer.
#pragma once

#include <cstddef>

#include "kutlog/simd/float_ops.hpp"

namespace kutlog::detail {

template <class Arch>
using floats_of = xsimd::batch<float, Arch>;

// The first `count` (< N; AVX-512's also N, and every arch's but SSE4.1's 0) lanes of an
// array, `padding` in the others.
template <class Arch>
inline floats_of<Arch> load_partial(const float* in, std::size_t count, float padding) {
  return simd::ops::load_partial<Arch>(in, count, padding, Arch{});
}
template <class Arch>
inline void store_partial(float* out, floats_of<Arch> value, std::size_t count) {
  simd::ops::store_partial<Arch>(out, value, count, Arch{});
}

}  // namespace kutlog::detail

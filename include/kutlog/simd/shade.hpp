// kutlog/simd/shade.hpp: the cosines of the stream API (kutlog/shade.hpp) on batches, and the
// per-arch pieces of masked streams that xsimd 8.1 lacks (a byte mask as a batch_bool, a
// store that leaves masked lanes alone).
#pragma once

#include "kutlog/api.hpp"  // below C++20 its #error, and this header is empty
#if KUTLOG_HAS_CXX20

#include <cstdint>

#include "kutlog/simd/float_ops.hpp"
#include "kutlog/simd/xsimd.hpp"

namespace kutlog::simd {

template <class Arch>
struct Vector3 {
  floats<Arch> x, y, z;
};

// kMayFuse as mul_add's (false: Variant::deterministic).
template <bool kMayFuse = true, class Arch>
inline floats<Arch> dot(const Vector3<Arch>& a, const Vector3<Arch>& b) {
  return mul_add<kMayFuse>(a.x, b.x, mul_add<kMayFuse>(a.y, b.y, a.z * b.z));
}

// N.H with H = (L + V) / |L + V|; 0 where L + V = 0 (or |L + V|^2 underflows). Tested as
// == 0, not !(> 0), so that a NaN in L or V stays NaN.
template <bool kMayFuse = true, class Arch>
inline floats<Arch> blinn_cosine(const Vector3<Arch>& normal, const Vector3<Arch>& to_light,
                                 const Vector3<Arch>& to_viewer) {
  using F = floats<Arch>;
  const Vector3<Arch> sum{to_light.x + to_viewer.x, to_light.y + to_viewer.y,
                          to_light.z + to_viewer.z};
  const F length_squared = dot<kMayFuse>(sum, sum);
  return zero_where(length_squared == F(0.0f),
                    dot<kMayFuse>(normal, sum) / xsimd::sqrt(length_squared));
}

// R.V with R = 2 (N.L) N - L, from N.L.
template <bool kMayFuse = true, class Arch>
inline floats<Arch> phong_cosine(const Vector3<Arch>& normal, const Vector3<Arch>& to_light,
                                 const Vector3<Arch>& to_viewer, floats<Arch> n_dot_l) {
  return mul_sub<kMayFuse>(n_dot_l + n_dot_l, dot<kMayFuse>(normal, to_viewer),
                           dot<kMayFuse>(to_light, to_viewer));
}

// mask[0 .. size) != 0 as a batch_bool (reads exactly size bytes).
template <class Arch>
inline xsimd::batch_bool<float, Arch> load_mask(const std::uint8_t* mask) {
  return ops::load_mask<Arch>(mask, Arch{});
}

// Stores value where selected; elsewhere memory keeps its contents (AVX2 and AVX-512 do not
// write those lanes; the others write back what they read).
template <class Arch>
inline void store_selected(float* out, floats<Arch> value,
                           xsimd::batch_bool<float, Arch> selected) {
  ops::store_selected(out, value, selected, Arch{});
}

}  // namespace kutlog::simd

#endif  // KUTLOG_HAS_CXX20

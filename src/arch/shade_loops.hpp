// shade() over arrays: the lobe's cosine per fragment, the lobe by its array loop, times N.L,
// a chunk at a time.
#pragma once

#include <cmath>
#include <cstddef>
#include <cstdint>

#include "arch/array_loops.hpp"
#include "arch/lobe_loops.hpp"
#include "kutlog/shade.hpp"
#include "kutlog/simd/shade.hpp"

namespace kutlog::detail {

// The shade forms run a chunk at a time: the chunk's cosines t (and N.L) into local buffers,
// unless the caller gave them; F(t) by the array loop of the kernel's slot, the one
// Lobe::eval runs (degree unrolled, finish fixed, clamp dropped where proven needless); then
// F, times max(N.L, 0) if asked, stored where mask selects. The buffers stay in L1. (One loop
// per form and slot instead would compile each form 86 times per arch.)
constexpr std::size_t kShadeChunk = 256;

// Where a chunk's t and N.L are (N.L only read when options.times_n_dot_l): the given arrays
// or the buffers cosines(begin, size, t_buffer, n_dot_l_buffer) filled.
struct ChunkCosines {
  const float* t;
  const float* n_dot_l;
};
template <class Arch, class Cosines>
void shade_in_chunks(const LobeKernel& kernel, const ShadeOptions& options,
                     const Cosines& cosines, float* out, std::size_t count,
                     const std::uint8_t* mask) {
  using F = floats_of<Arch>;
  static constexpr LobeArrayKernels kLobeLoops = lobe_array_kernels<Arch>();
  const LobeArrayKernel lobe_loop =
      kLobeLoops.of(kernel, options.variant == Variant::deterministic);
  alignas(64) float t_buffer[kShadeChunk], n_dot_l_buffer[kShadeChunk], lobe[kShadeChunk];
  for (std::size_t begin = 0; begin < count; begin += kShadeChunk) {
    const std::size_t size = count - begin < kShadeChunk ? count - begin : kShadeChunk;
    const ChunkCosines chunk = cosines(begin, size, t_buffer, n_dot_l_buffer);
    lobe_loop(kernel, chunk.t, lobe, size);
    const std::uint8_t* lanes = mask ? mask + begin : nullptr;
    if (options.times_n_dot_l)
      map_masked<Arch, 2>([](F f, F n_l) { return f * xsimd::max(F(0.0f), n_l); },
                          {lobe, chunk.n_dot_l}, out + begin, size, lanes);
    else
      map_masked<Arch, 1>([](F f) { return f; }, {lobe}, out + begin, size, lanes);
  }
}

// The cosine the lobe takes, by options.reflection: N.H (Blinn) or R.V (Phong). kMayFuse
// false in the deterministic mode, as every dot product of this file.
template <bool kMayFuse, class Arch>
inline floats_of<Arch> lobe_cosine(const ShadeOptions& options, const simd::Vector3<Arch>& n,
                                   const simd::Vector3<Arch>& l, const simd::Vector3<Arch>& v) {
  return options.reflection == Reflection::blinn
             ? simd::blinn_cosine<kMayFuse>(n, l, v)
             : simd::phong_cosine<kMayFuse>(n, l, v, simd::dot<kMayFuse>(n, l));
}

// Each form below runs its cosines fused where the arch has FMA, or unfused in the
// deterministic mode: one instance of each kMayFuse, picked by the table's entries further on.
template <class Arch, bool kMayFuse>
void shade_vectors_as(const LobeKernel& kernel, const ShadeOptions& options, Vectors normal,
                      Vectors to_light, Vectors to_viewer, float* out, std::size_t count,
                      const std::uint8_t* mask) {
  using F = floats_of<Arch>;
  const auto cosines = [&](std::size_t begin, std::size_t size, float* t, float* n_dot_l) {
    const float *nx = normal.x + begin, *ny = normal.y + begin, *nz = normal.z + begin,
                *lx = to_light.x + begin, *ly = to_light.y + begin, *lz = to_light.z + begin;
    map_arrays<Arch, 9>(
        [&](F n_x, F n_y, F n_z, F l_x, F l_y, F l_z, F v_x, F v_y, F v_z) {
          return lobe_cosine<kMayFuse, Arch>(options, {n_x, n_y, n_z}, {l_x, l_y, l_z},
                                             {v_x, v_y, v_z});
        },
        {nx, ny, nz, lx, ly, lz, to_viewer.x + begin, to_viewer.y + begin, to_viewer.z + begin},
        t, size);
    if (options.times_n_dot_l)
      map_arrays<Arch, 6>([](F n_x, F n_y, F n_z, F l_x, F l_y, F l_z) {
        return simd::dot<kMayFuse, Arch>({n_x, n_y, n_z}, {l_x, l_y, l_z});
      }, {nx, ny, nz, lx, ly, lz}, n_dot_l, size);
    return ChunkCosines{t, n_dot_l};
  };
  shade_in_chunks<Arch>(kernel, options, cosines, out, count, mask);
}

// Blinn's half vector of one light and one viewer, H = (L + V) / |L + V|, in double and rounded
// once per component: the zero vector where L + V = 0 (N.H = 0, as blinn_cosine gives there),
// NaN where L or V has a NaN or an infinity. A template, as everything here, though it does not
// depend on the arch (std::sqrt of a double is the compiler's instruction or libm's call).
template <class Arch>
Direction half_vector(Direction to_light, Direction to_viewer) {
  const double x = double(to_light.x) + double(to_viewer.x),
               y = double(to_light.y) + double(to_viewer.y),
               z = double(to_light.z) + double(to_viewer.z);
  const double length = std::sqrt(x * x + y * y + z * z);
  if (length == 0) return {0.0f, 0.0f, 0.0f};
  return {float(x / length), float(y / length), float(z / length)};
}

// One light and one viewer for every lane: Blinn's H is formed once per call, so that a lane
// computes N.H alone (blinn_cosine per lane took a square root and a division per batch), and
// closer to the exact cosine: 4 units of float rounding against 8.5 (tests/cosine_error.hpp).
template <class Arch, bool kMayFuse>
void shade_directions_as(const LobeKernel& kernel, const ShadeOptions& options, Vectors normal,
                         Direction to_light, Direction to_viewer, float* out, std::size_t count,
                         const std::uint8_t* mask) {
  using F = floats_of<Arch>;
  const simd::Vector3<Arch> l{F(to_light.x), F(to_light.y), F(to_light.z)},
      v{F(to_viewer.x), F(to_viewer.y), F(to_viewer.z)};
  const Direction half = half_vector<Arch>(to_light, to_viewer);
  const simd::Vector3<Arch> h{F(half.x), F(half.y), F(half.z)};
  const bool blinn = options.reflection == Reflection::blinn;
  const auto cosines = [&](std::size_t begin, std::size_t size, float* t, float* n_dot_l) {
    const float* const n[3] = {normal.x + begin, normal.y + begin, normal.z + begin};
    if (blinn)
      map_arrays<Arch, 3>(
          [&](F n_x, F n_y, F n_z) { return simd::dot<kMayFuse, Arch>({n_x, n_y, n_z}, h); }, n,
          t, size);
    else
      map_arrays<Arch, 3>(
          [&](F n_x, F n_y, F n_z) {
            return lobe_cosine<kMayFuse, Arch>(options, {n_x, n_y, n_z}, l, v);
          },
          n, t, size);
    if (options.times_n_dot_l)
      map_arrays<Arch, 3>(
          [&](F n_x, F n_y, F n_z) { return simd::dot<kMayFuse, Arch>({n_x, n_y, n_z}, l); }, n,
          n_dot_l, size);
    return ChunkCosines{t, n_dot_l};
  };
  shade_in_chunks<Arch>(kernel, options, cosines, out, count, mask);
}

template <class Arch>
void shade_cosines_array(const LobeKernel& kernel, const ShadeOptions& options, const float* t,
                         const float* n_dot_l, float* out, std::size_t count,
                         const std::uint8_t* mask) {
  const auto given = [&](std::size_t begin, std::size_t, float*, float*) {
    return ChunkCosines{t + begin, options.times_n_dot_l ? n_dot_l + begin : nullptr};
  };
  shade_in_chunks<Arch>(kernel, options, given, out, count, mask);
}

// The entries of the kernel table: the cosines unfused in the deterministic mode (on FMA-less
// archs, the one instance).
template <class Arch>
void shade_vectors_array(const LobeKernel& kernel, const ShadeOptions& options, Vectors normal,
                         Vectors to_light, Vectors to_viewer, float* out, std::size_t count,
                         const std::uint8_t* mask) {
  if constexpr (simd::has_fused_fma<Arch>)
    if (options.variant == Variant::deterministic)
      return shade_vectors_as<Arch, false>(kernel, options, normal, to_light, to_viewer, out,
                                           count, mask);
  shade_vectors_as<Arch, true>(kernel, options, normal, to_light, to_viewer, out, count, mask);
}
template <class Arch>
void shade_directions_array(const LobeKernel& kernel, const ShadeOptions& options, Vectors normal,
                            Direction to_light, Direction to_viewer, float* out,
                            std::size_t count, const std::uint8_t* mask) {
  if constexpr (simd::has_fused_fma<Arch>)
    if (options.variant == Variant::deterministic)
      return shade_directions_as<Arch, false>(kernel, options, normal, to_light, to_viewer,
                                              out, count, mask);
  shade_directions_as<Arch, true>(kernel, options, normal, to_light, to_viewer, out, count, mask);
}

}  // namespace kutlog::detail

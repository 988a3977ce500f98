// The loops that apply a batch kernel over arrays: plain (map_arrays) and under a coverage
// mask (map_masked), each with its tail as a partial batch.
#pragma once

#include <cstddef>
#include <cstdint>
#include <utility>

#include "arch/partial_batches.hpp"
#include "kutlog/simd/shade.hpp"

namespace kutlog::detail {

// Applies `kernel` to batches of `count` floats from each input array; the tail as a partial
// batch padded with `padding` (a value inside every kernel's domain). Inlined into its caller,
// so that what the kernel captures by reference is seen not to alias the output: out of line
// (GCC 12's choice for some), a loop recomputed its kernel's constants per batch.
template <class Arch, std::size_t Inputs, class Kernel>
[[gnu::always_inline]] inline void map_arrays(const Kernel& kernel,
                                              const float* const (&inputs)[Inputs], float* out,
                                              std::size_t count, float padding = 0.5f) {
  using F = xsimd::batch<float, Arch>;
  constexpr std::size_t N = F::size;
  const auto apply = [&](const auto& load) {
    return [&]<std::size_t... input>(std::index_sequence<input...>) {
      return kernel(load(input)...);
    }(std::make_index_sequence<Inputs>());
  };
  std::size_t i = 0;
  for (; i + N <= count; i += N)
    apply([&](std::size_t input) { return F::load_unaligned(inputs[input] + i); })
        .store_unaligned(out + i);
  if (i == count) return;
  const std::size_t tail = count - i;
  const F value = apply([&](std::size_t input) {
    return load_partial<Arch>(inputs[input] + i, tail, padding);
  });
  store_partial<Arch>(out + i, value, tail);
}

// The stream loop: kernel(inputs...) on batches of Inputs arrays, stored where mask (if any)
// selects; the tail as a partial batch, as in map_arrays.
template <class Arch, std::size_t Inputs, class Kernel>
inline void map_masked(const Kernel& kernel, const float* const (&inputs)[Inputs], float* out,
                       std::size_t count, const std::uint8_t* mask) {
  using F = xsimd::batch<float, Arch>;
  constexpr std::size_t N = F::size;
  // A batch no lane of which is selected is skipped, one whose every lane is stored whole: a
  // rasterizer's coverage is mostly such batches, and AVX2's lane-masked store is microcoded
  // on AMD.
  const auto run = [&](const float* const (&sources)[Inputs], std::size_t at, float* target,
                       const std::uint8_t* lanes) {
    const auto value = [&] {
      return [&]<std::size_t... input>(std::index_sequence<input...>) {
        return kernel(F::load_unaligned(sources[input] + at)...);
      }(std::make_index_sequence<Inputs>());
    };
    if (!lanes) return value().store_unaligned(target);
    const auto selected = simd::load_mask<Arch>(lanes);
    if (xsimd::all(selected)) value().store_unaligned(target);
    else if (xsimd::any(selected)) simd::store_selected(target, value(), selected);
  };
  std::size_t i = 0;
  for (; i + N <= count; i += N) run(inputs, i, out + i, mask ? mask + i : nullptr);
  if (i == count) return;
  // The tail: a partial batch, merged with what out holds where the mask leaves it.
  const std::size_t tail = count - i;
  const F value = [&]<std::size_t... input>(std::index_sequence<input...>) {
    return kernel(load_partial<Arch>(inputs[input] + i, tail, 0.0f)...);
  }(std::make_index_sequence<Inputs>());
  if (!mask) return store_partial<Arch>(out + i, value, tail);
  std::uint8_t lanes[N] = {};
  for (std::size_t j = 0; j < tail; ++j) lanes[j] = mask[i + j];
  const F kept = load_partial<Arch>(out + i, tail, 0.0f);
  store_partial<Arch>(out + i, xsimd::select(simd::load_mask<Arch>(lanes), value, kept), tail);
}

}  // namespace kutlog::detail

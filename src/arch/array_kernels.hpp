// The array loops around the batch kernels, instantiated once per arch by src/arch/<arch>.cpp.
// Everything here is a template on the xsimd arch, so no copy compiled with one arch's flags
// can stand in for another's; it calls nothing from the standard library for that reason.
#pragma once

#include <cstddef>
#include <xsimd/xsimd.hpp>

#include "arch/kernel_table.hpp"
#include "kutlog/simd/math.hpp"

namespace kutlog::detail {

// Applies `kernel` to batches of `count` floats from each input array. The tail goes through
// an aligned local buffer padded with `padding` (a value inside every kernel's domain), so no
// load or store leaves the arrays.
template <class Arch, int Inputs, class Kernel>
inline void map_arrays(Kernel kernel, const float* const (&inputs)[Inputs], float* out,
                       std::size_t count, float padding = 0.5f) {
  using F = xsimd::batch<float, Arch>;
  constexpr std::size_t N = F::size;
  std::size_t i = 0;
  const auto load = [&](int input) { return F::load_unaligned(inputs[input] + i); };
  for (; i + N <= count; i += N) {
    if constexpr (Inputs == 1) kernel(load(0)).store_unaligned(out + i);
    if constexpr (Inputs == 2) kernel(load(0), load(1)).store_unaligned(out + i);
  }
  if (i == count) return;
  alignas(64) float buffer[Inputs][N];
  const std::size_t tail = count - i;
  for (int input = 0; input < Inputs; ++input)
    for (std::size_t j = 0; j < N; ++j) buffer[input][j] = j < tail ? inputs[input][i + j] : padding;
  alignas(64) float result[N];
  if constexpr (Inputs == 1) kernel(F::load_aligned(buffer[0])).store_aligned(result);
  if constexpr (Inputs == 2)
    kernel(F::load_aligned(buffer[0]), F::load_aligned(buffer[1])).store_aligned(result);
  for (std::size_t j = 0; j < tail; ++j) out[i + j] = result[j];
}

template <class Arch>
KernelTable make_kernel_table() {
  using F = xsimd::batch<float, Arch>;
  KernelTable table{};
  table.acos_u10 = [](const float* x, float* out, std::size_t count) {
    map_arrays<Arch, 1>([](F v) { return simd::acos_u10(v); }, {x}, out, count);
  };
  table.cos_u10 = [](const float* x, float* out, std::size_t count) {
    map_arrays<Arch, 1>([](F v) { return simd::cos_u10(v); }, {x}, out, count);
  };
  table.cos_halfpi_u10 = [](const float* x, float* out, std::size_t count) {
    map_arrays<Arch, 1>([](F v) { return simd::cos_halfpi_u10(v); }, {x}, out, count);
  };
  table.exp_u10 = [](const float* x, float* out, std::size_t count) {
    map_arrays<Arch, 1>([](F v) { return simd::exp_u10(v); }, {x}, out, count);
  };
  table.log_u10 = [](const float* x, float* out, std::size_t count) {
    map_arrays<Arch, 1>([](F v) { return simd::log_u10(v); }, {x}, out, count);
  };
  table.pow_u10 = [](const float* x, const float* y, float* out, std::size_t count) {
    map_arrays<Arch, 2>([](F a, F b) { return simd::pow_u10(a, b); }, {x, y}, out, count);
  };
  table.pow_scalar_u10 = [](const float* x, float y, float* out, std::size_t count) {
    const F exponent(y);
    map_arrays<Arch, 1>([exponent](F a) { return simd::pow_u10(a, exponent); }, {x}, out,
                        count);
  };
  return table;
}

}  // namespace kutlog::detail

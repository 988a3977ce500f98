// The lobe sampler over arrays.
#pragma once

#include <cstddef>

#include "arch/partial_batches.hpp"
#include "kutlog/sampling.hpp"
#include "kutlog/simd/sampling.hpp"

namespace kutlog::detail {

// The sampler over arrays: four outputs per pair of inputs, the tail as a partial batch.
template <class Arch, class Sampler>
void sample_lobe_batches(const Sampler& sampler, const float* u1, const float* u2,
                         DirectionSamples out, std::size_t count) {
  using F = floats_of<Arch>;
  constexpr std::size_t N = F::size;
  std::size_t i = 0;
  for (; i + N <= count; i += N) {
    const simd::SampleBatch<Arch> sample = sampler(F::load_unaligned(u1 + i), F::load_unaligned(u2 + i));
    sample.x.store_unaligned(out.x + i);
    sample.y.store_unaligned(out.y + i);
    sample.z.store_unaligned(out.z + i);
    sample.pdf.store_unaligned(out.pdf + i);
  }
  if (i == count) return;
  const std::size_t tail = count - i;
  const simd::SampleBatch<Arch> sample = sampler(load_partial<Arch>(u1 + i, tail, 0.5f),
                                                 load_partial<Arch>(u2 + i, tail, 0.5f));
  store_partial<Arch>(out.x + i, sample.x, tail);
  store_partial<Arch>(out.y + i, sample.y, tail);
  store_partial<Arch>(out.z + i, sample.z, tail);
  store_partial<Arch>(out.pdf + i, sample.pdf, tail);
}

// deterministic: Variant::deterministic's rows, unfused, its NaN the quiet one.
template <class Arch>
void sample_lobe_array(const SamplerKernel& kernel, bool deterministic, const float* u1,
                       const float* u2, DirectionSamples out, std::size_t count) {
  if (deterministic)
    return sample_lobe_batches<Arch>(simd::PreparedSampler<Arch, false, true>(kernel), u1, u2,
                                     out, count);
  if constexpr (simd::PreparedSampler<Arch>::kRaisesPower)
    if (simd::PreparedSampler<Arch>::double_power_needed(kernel))
      return sample_lobe_batches<Arch>(simd::PreparedSampler<Arch, true>(kernel), u1, u2, out,
                                       count);
  sample_lobe_batches<Arch>(simd::PreparedSampler<Arch>(kernel), u1, u2, out, count);
}

// One sample, scalar float code compiled with this arch's flags (its fused multiply-add).
template <class Arch>
SampledDirection sample_one(const SamplerKernel& kernel, float u1, float u2) {
  return simd::one_sample::sample<Arch>(kernel, u1, u2);
}

}  // namespace kutlog::detail

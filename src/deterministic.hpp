// The deterministic mode's one sample (Variant::deterministic, kutlog/sampling.hpp): the arrays'
// rows code on one lane of the portable arch, compiled in src/sampling.cpp with the baseline
// flags, as Lobe's one fragment is in src/deterministic.cpp.
#pragma once

#include "kutlog/sampling.hpp"

namespace kutlog::detail {
SampledDirection deterministic_sample(const SamplerKernel& kernel, float u1, float u2) noexcept;
}  // namespace kutlog::detail

// The names the tools, tests and benchmarks print for kutlog's option enums.
#pragma once

#include <string_view>

#include "kutlog/lobe.hpp"
#include "kutlog/sampling_reference.hpp"

namespace kutlog {

constexpr std::string_view variant_name(Variant variant) {
  return variant == Variant::precise ? "precise"
         : variant == Variant::fast  ? "fast"
                                     : "deterministic";
}
constexpr std::string_view normalization_name(Normalization normalization) {
  return normalization == Normalization::none ? "none" : "exact_coef";
}
constexpr std::string_view use_name(ref::LobeUse use) {
  return use == ref::LobeUse::microfacet ? "microfacet" : "phong";
}

}  // namespace kutlog

// The kutlog/simd/ kernels and xsimd::pow for AVX-512, instantiated (simd_*_first.cpp).
#pragma once

#include <kutlog/inspect.hpp>

namespace kutlog_consumer {
template <class Arch>
xsimd::batch<float, Arch> lobe_and_pow(const kutlog::inspect::LobeKernel& kernel,
                                       xsimd::batch<float, Arch> t) {
  return kutlog::simd::kutlog_lobe<Arch>(t, kernel) + kutlog::simd::blinn_phong_xsimd<Arch>(t, t) +
         kutlog::simd::blinn_phong_u10<Arch>(t, t);
}
template xsimd::batch<float, xsimd::avx512bw> lobe_and_pow(const kutlog::inspect::LobeKernel&,
                                                          xsimd::batch<float, xsimd::avx512bw>);
}  // namespace kutlog_consumer

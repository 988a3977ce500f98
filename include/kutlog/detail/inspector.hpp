// kutlog/detail/inspector.hpp: detail::Inspector, the one friend of the public classes, which
// reads what their setup fitted: for kutlog/inspect.hpp, the C API and the library's dispatch.
// Unlike kutlog/inspect.hpp it links no array path: the C API's scalar calls use it alone.
#pragma once

#include "kutlog/api.hpp"  // below C++20 its #error, and this header is empty
#if KUTLOG_HAS_CXX20

#include <atomic>

#include "kutlog/detail/lobe_dispatch.hpp"
#include "kutlog/detail/lobe_kernel.hpp"
#include "kutlog/detail/sampler_kernel.hpp"
#include "kutlog/lobe.hpp"
#include "kutlog/sampling.hpp"

namespace kutlog::detail {
struct Inspector {
  static const LobeKernel& kernel(const Lobe& lobe, int index) { return lobe.kernels_[index]; }
  static const KernelCertificate& certificate(const Lobe& lobe, int index) {
    return lobe.certificates_[index];
  }
  static int index(Variant variant, Normalization normalization, Arithmetic arithmetic) {
    return Lobe::kernel_index(variant, normalization, arithmetic);
  }
  static const ScalarPieces& precise_pieces(const Lobe& lobe, Normalization normalization) {
    return lobe.precise_pieces_[int(normalization)];
  }
  static const FastScalarPieces& fast_pieces(const Lobe& lobe, Normalization normalization) {
    return lobe.fast_pieces_[int(normalization)];
  }
  static double c(const Lobe& lobe) { return lobe.c_; }
  static const PerLaneKernel& kernel(const PerLaneLobe& lobe, Variant variant) {
    return lobe.kernels_[int(variant == Variant::fast)];
  }
  static const SamplerKernel& kernel(const LobeSampler& sampler) { return sampler.kernel_; }
  static double limit(const LobeSampler& sampler) { return sampler.limit_; }
  static double fit_error(const LobeSampler& sampler) { return sampler.fit_error_; }
  static std::atomic<const LobeArrayKernels*>& active_loops() { return Lobe::active_loops_; }
};
}  // namespace kutlog::detail

#endif  // KUTLOG_HAS_CXX20

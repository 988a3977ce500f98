// The math and sampling benchmarks of one arch. CMake compiles this file once per entry of the arch
// registry (cmake/KutlogArchs.cmake), with only that arch's flags and KUTLOG_ARCH_ID set to its
// id, as it does the library's kernels.
#include "kutlog/simd/arch.hpp"
#include "math_benchmarks.hpp"
#include "sampling_benchmarks.hpp"

#ifndef KUTLOG_ARCH_ID
#error "compiled once per arch by CMake, with KUTLOG_ARCH_ID=<id of cmake/KutlogArchs.cmake>"
#endif

namespace kutlog::bench {

template <>
void register_math_benchmarks_of<Arch::KUTLOG_ARCH_ID>() {
  register_math_benchmarks<simd::xsimd_arch<Arch::KUTLOG_ARCH_ID>>(
      std::string(arch_name(Arch::KUTLOG_ARCH_ID)));
  register_sampling_benchmarks<simd::xsimd_arch<Arch::KUTLOG_ARCH_ID>>(Arch::KUTLOG_ARCH_ID);
}

}  // namespace kutlog::bench

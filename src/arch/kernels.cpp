// The kernels of one arch. CMake compiles this file once per entry of the arch registry
// (cmake/KutlogArchs.cmake), each time with only that arch's flags and KUTLOG_ARCH_ID set to
// its id; every kernel is a template on the xsimd arch, so no copy compiled for one arch can be
// the one the linker keeps for another.
#include "arch/array_kernels.hpp"
#include "kutlog/simd/arch.hpp"

#ifndef KUTLOG_ARCH_ID
#error "compiled once per arch by CMake, with KUTLOG_ARCH_ID=<id of cmake/KutlogArchs.cmake>"
#endif

namespace kutlog::detail {

template <>
const KernelTable& kernel_table<Arch::KUTLOG_ARCH_ID>() {
  static const KernelTable table = make_kernel_table<simd::xsimd_arch<Arch::KUTLOG_ARCH_ID>>();
  return table;
}

}  // namespace kutlog::detail

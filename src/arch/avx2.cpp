// The kernels compiled for one arch; CMake gives this file only that arch's flags.
#include "arch/array_kernels.hpp"

namespace kutlog::detail {

const KernelTable& kernel_table_avx2() {
  static const KernelTable table = make_kernel_table<xsimd::fma3<xsimd::avx2>>();
  return table;
}

}  // namespace kutlog::detail

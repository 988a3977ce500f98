// The kernels compiled for one arch; CMake gives this file only that arch's flags.
#include "arch/array_kernels.hpp"

namespace kutlog::detail {

const KernelTable& kernel_table_avx512() {
  static const KernelTable table = make_kernel_table<xsimd::avx512bw>();
  return table;
}

}  // namespace kutlog::detail

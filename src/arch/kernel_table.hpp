// The kernels of one arch as a table of function pointers; src/dispatch.cpp picks the table.
#pragma once

#include <cstddef>

namespace kutlog::detail {

using UnaryArrayKernel = void (*)(const float*, float*, std::size_t);
using BinaryArrayKernel = void (*)(const float*, const float*, float*, std::size_t);
using BinaryScalarArrayKernel = void (*)(const float*, float, float*, std::size_t);

struct KernelTable {
  UnaryArrayKernel acos_u10, cos_u10, cos_halfpi_u10, exp_u10, log_u10;
  BinaryArrayKernel pow_u10;
  BinaryScalarArrayKernel pow_scalar_u10;
};

// One per arch translation unit (src/arch/<arch>.cpp), compiled with that arch's flags.
const KernelTable& kernel_table_sse4_1();
const KernelTable& kernel_table_avx2();
const KernelTable& kernel_table_avx512();

}  // namespace kutlog::detail

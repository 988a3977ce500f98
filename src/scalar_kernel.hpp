// LobeKernel::evaluate out of line (src/lobe.cpp): the one copy of that code, which Lobe::eval
// (where its pieces are not certified) and the C API's kutlog_eval call. Not exported.
#pragma once

#include "kutlog/detail/lobe_kernel.hpp"

namespace kutlog::detail {
float evaluate_scalar_kernel(const LobeKernel& kernel, float t) noexcept;
}  // namespace kutlog::detail

// The lobe kernels' arithmetic in scalar code, for the setup's acceptance (src/lobe.cpp) and
// for the test that compares it with the kernels bit for bit (tests/test_lobe.cpp).
#pragma once

#include "kutlog/lobe.hpp"

namespace kutlog::detail {

// What PreparedLobe (kutlog/simd/lobe.hpp) returns for t, computed with the same operations
// in the same order and with the same roundings: fused multiply-adds (AVX2, AVX-512) or a
// multiply and an add (SSE4.1). Compiled without FMA contraction, like the kernels.
float simulate_lobe_kernel(const LobeKernel& kernel, bool fused, float t);

}  // namespace kutlog::detail

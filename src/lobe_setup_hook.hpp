// A test's way into Lobe's setup (src/lobe.cpp): the targets its kernels must meet, times this
// factor (1 in use). A test sets it far below 1, so that no fit can meet its target, to see
// the setup refuse the material rather than keep a kernel whose bound misses.
#pragma once

#include <atomic>

namespace kutlog::detail {

inline std::atomic<double> lobe_target_factor_for_tests{1.0};

}  // namespace kutlog::detail
